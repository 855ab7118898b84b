//! The SVG document reader against an independent renderer: every file of a corpus of real
//! SVG files (icon sets from the npm registry, Inkscape's and LibreOffice Draw's exports, edge
//! cases; `tests/data/svg_corpus/README.md`) is either read as a viewer shows it — the outline
//! the library reads, filled by its rule and stroked by its stroke, inks the pixels resvg inks
//! for the file itself — or refused with a message naming the element at fault.
//!
//! Independent of the library: resvg renders the file; the map from the root `viewBox` to the
//! viewport is written here from SVG 1.1 §7.8 (not taken from the library); the library's
//! outline is drawn by tiny-skia (resvg's rasteriser) from its points alone.
#![cfg(feature = "svg")]

use resvg::tiny_skia;
use resvg::usvg;
use splinelab::input::svg_document::{drawn_paths, DrawnPath, FillRule, LineCap, LineJoin};
use std::path::{Path, PathBuf};

/// The pixels of the longer side of a rendering.
const PIXELS: f32 = 400.0;
/// How far (pixels) an inked pixel of one rendering may lie from an inked pixel of the other.
const SLACK: i64 = 2;

fn corpus() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/svg_corpus");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    files.sort();
    files
}

/// The files refused, each with a part of its message.
const REFUSED: &[(&str, &str)] = &[
    // the first viewport's `slice` cuts its rectangle
    (
        "edge-aspect-ratio.svg",
        "the viewport of a nested <svg>, <symbol> or marker cuts the drawn outline",
    ),
    // the inner viewport cuts the orange rectangle
    (
        "edge-nested-svg.svg",
        "the viewport of a nested <svg>, <symbol> or marker cuts the drawn outline",
    ),
    // a circle clips a square
    (
        "edge-not-rendered.svg",
        "line 19, column 3: <rect>: the clip path \"clip\" cuts",
    ),
    // a rectangle clips a disc (Inkscape's Object ▸ Clip ▸ Set)
    (
        "inkscape-boolean-ops.svg",
        "<ellipse id=\"photo\">: the clip path \"clipPath27\" cuts the drawn outline",
    ),
];

/// The root viewBox → viewport map `(sx, sy, tx, ty)` of SVG 1.1 §7.8, from the root's
/// attributes and the viewport size resvg uses.
fn view_box_map(doc: &usvg::roxmltree::Document, size: usvg::Size) -> (f64, f64, f64, f64) {
    let root = doc.root_element();
    let (w, h) = (f64::from(size.width()), f64::from(size.height()));
    let Some(vb) = root.attribute("viewBox") else {
        return (1.0, 1.0, 0.0, 0.0);
    };
    let v: Vec<f64> = vb
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|s| !s.is_empty())
        .map(|s| s.parse().unwrap())
        .collect();
    let (x, y, vw, vh) = (v[0], v[1], v[2], v[3]);
    let par = root.attribute("preserveAspectRatio").unwrap_or("xMidYMid");
    let mut words = par.split_whitespace();
    let align = words.next().unwrap_or("xMidYMid");
    let slice = words.next() == Some("slice");
    let (mut sx, mut sy) = (w / vw, h / vh);
    let (mut ax, mut ay) = (0.0, 0.0);
    if align != "none" {
        let s = if slice { sx.max(sy) } else { sx.min(sy) };
        (sx, sy) = (s, s);
        let fx = match &align[..4] {
            "xMid" => 0.5,
            "xMax" => 1.0,
            _ => 0.0,
        };
        let fy = match &align[4..] {
            "YMid" => 0.5,
            "YMax" => 1.0,
            _ => 0.0,
        };
        ax = fx * (w - vw * s);
        ay = fy * (h - vh * s);
    }
    (sx, sy, ax - x * sx, ay - y * sy)
}

/// A boolean image: which pixels are inked (alpha above `threshold`).
fn inked(pixmap: &tiny_skia::Pixmap, threshold: u8) -> Vec<bool> {
    pixmap
        .pixels()
        .iter()
        .map(|p| p.alpha() > threshold)
        .collect()
}

/// The count of pixels inked in `a` with no pixel inked in `b` within `SLACK` pixels.
fn misses(a: &[bool], b: &[bool], w: i64, h: i64) -> usize {
    let mut count = 0;
    for y in 0..h {
        for x in 0..w {
            if !a[(y * w + x) as usize] {
                continue;
            }
            let near = (-SLACK..=SLACK).any(|dy| {
                (-SLACK..=SLACK).any(|dx| {
                    let (u, v) = (x + dx, y + dy);
                    u >= 0 && v >= 0 && u < w && v < h && b[(v * w + u) as usize]
                })
            });
            if !near {
                count += 1;
            }
        }
    }
    count
}

/// The library's outline drawn by tiny-skia in the pixel frame `to_pixel`.
fn draw_outline(
    paths: &[DrawnPath],
    to_pixel: &dyn Fn(f64, f64) -> (f32, f32),
    scale: f64,
    pixmap: &mut tiny_skia::Pixmap,
) {
    let paint = tiny_skia::Paint::default();
    for p in paths {
        let mut pb = tiny_skia::PathBuilder::new();
        for c in &p.contours {
            for (k, q) in c.points.iter().enumerate() {
                let (x, y) = to_pixel(q.x, q.y);
                if k == 0 {
                    pb.move_to(x, y);
                } else {
                    pb.line_to(x, y);
                }
            }
            if c.closed {
                pb.close();
            }
        }
        let Some(path) = pb.finish() else { continue };
        if let Some(rule) = p.fill {
            let rule = match rule {
                FillRule::NonZero => tiny_skia::FillRule::Winding,
                FillRule::EvenOdd => tiny_skia::FillRule::EvenOdd,
            };
            pixmap.fill_path(&path, &paint, rule, tiny_skia::Transform::identity(), None);
        }
        if let Some(s) = &p.stroke {
            let stroke = tiny_skia::Stroke {
                width: (s.width * scale) as f32,
                miter_limit: s.miter_limit as f32,
                line_cap: match s.cap {
                    LineCap::Butt => tiny_skia::LineCap::Butt,
                    LineCap::Round => tiny_skia::LineCap::Round,
                    LineCap::Square => tiny_skia::LineCap::Square,
                },
                line_join: match s.join {
                    LineJoin::Miter => tiny_skia::LineJoin::Miter,
                    LineJoin::MiterClip => tiny_skia::LineJoin::MiterClip,
                    LineJoin::Round => tiny_skia::LineJoin::Round,
                    LineJoin::Bevel => tiny_skia::LineJoin::Bevel,
                },
                dash: s.dashes.as_ref().and_then(|d| {
                    tiny_skia::StrokeDash::new(d.iter().map(|&x| (x * scale) as f32).collect(), 0.0)
                }),
            };
            pixmap.stroke_path(
                &path,
                &paint,
                &stroke,
                tiny_skia::Transform::identity(),
                None,
            );
        }
    }
}

/// Reads `file` with the library and compares its outline with resvg's rendering of the file:
/// `Ok((pixels inked by resvg, misses one way, misses the other way))` or the library's error.
fn compare(file: &Path) -> Result<(usize, usize, usize), String> {
    let text = std::fs::read_to_string(file).unwrap();
    let options = usvg::roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    let doc = usvg::roxmltree::Document::parse_with_options(&text, options).unwrap();
    let tree = usvg::Tree::from_xmltree(&doc, &usvg::Options::default()).unwrap();
    let size = tree.size();
    let k = PIXELS / size.width().max(size.height());
    let (w, h) = (
        (size.width() * k).ceil() as u32,
        (size.height() * k).ceil() as u32,
    );
    let mut theirs = tiny_skia::Pixmap::new(w, h).unwrap();
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(k, k),
        &mut theirs.as_mut(),
    );

    let (sx, sy, tx, ty) = view_box_map(&doc, size);
    let user = sx.max(sy).max(1e-300);
    // the flattening well below a pixel
    let tolerance = 0.05 / (f64::from(k) * user);
    let paths = drawn_paths(&text, tolerance).map_err(|e| e.to_string())?;
    let k = f64::from(k);
    // user units, y up → viewport → pixels
    let to_pixel = |x: f64, y: f64| (((sx * x + tx) * k) as f32, ((sy * -y + ty) * k) as f32);
    let mut ours = tiny_skia::Pixmap::new(w, h).unwrap();
    draw_outline(&paths, &to_pixel, k * (sx * sy).sqrt(), &mut ours);
    let (a, b) = (inked(&theirs, 127), inked(&ours, 127));
    let (w, h) = (i64::from(w), i64::from(h));
    Ok((
        a.iter().filter(|&&x| x).count(),
        misses(&a, &b, w, h),
        misses(&b, &a, w, h),
    ))
}

#[test]
fn every_corpus_file_is_read_as_resvg_draws_it_or_refused_by_name() {
    let mut failures = Vec::new();
    let files = corpus();
    assert!(files.len() >= 40, "the corpus has {} files", files.len());
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        let expected = REFUSED.iter().find(|(f, _)| *f == name);
        match (compare(file), expected) {
            (Ok((inked, one, other)), None) => {
                println!("{name}: {inked} pixels inked; {one} drawn by resvg only, {other} by the library only");
                if inked < 500 || one > 0 || other > 0 {
                    failures.push(format!("{name}: {inked} inked, misses {one} / {other}"));
                }
            }
            (Err(e), Some((_, part))) => {
                println!("{name}: refused: {e}");
                if !e.contains(part) {
                    failures.push(format!("{name}: refused with {e:?}, expected {part:?}"));
                }
            }
            (Ok(_), Some((_, part))) => {
                failures.push(format!("{name}: read, expected a refusal naming {part:?}"))
            }
            (Err(e), None) => failures.push(format!("{name}: refused: {e}")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
