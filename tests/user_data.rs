//! A user's own data through the seeds' methods (issue 29): `report::user`'s fit, fewest and
//! surface, the outline readers by file kind, and the exported curve drawn by an independent
//! SVG renderer (resvg) compared with the library's own sampling, both ways.
#![cfg(feature = "report")]

use nalgebra::Vector2;
use splinelab::input::{Columns, Contour};
use splinelab::interp::choice::{simplified, Family, Target};
use splinelab::report::export::PlyEncoding;
use splinelab::report::user::fewest;
use splinelab::report::user::fit::{Fit, FormulaStyle};
use splinelab::report::user::outline::{read_outline, FileKind, ReadOptions};
use splinelab::report::user::surface::{BuiltIn, MeshFormat, PartitionSpec, SurfaceMesh};
use splinelab::study::outline::{default_options, fewest, Tolerance};
use splinelab::study::table_i::{shape_names, shape_outline};
use splinelab::{CubicEnd, Error, Method, ParametricCurve};
use std::path::Path;

type V = Vector2<f64>;

fn blob() -> Vec<V> {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/examples/points.csv"
    ))
    .unwrap();
    splinelab::input::points_from_csv::<2>(&text, &Columns::First).unwrap()
}

fn methods() -> Vec<Method> {
    vec![
        Method::Angular,
        Method::Cardinal { a: 0.5 },
        Method::Cubic {
            end: CubicEnd::Relaxed,
        },
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        Method::BSpline { order: 4 },
        Method::Linear,
    ]
}

#[test]
fn a_fit_interpolates_its_points_and_its_samples_read_back() {
    let points = blob();
    for method in methods() {
        for closed in [false, true] {
            let fit = Fit::try_new(&points, method, closed).unwrap();
            let csv = fit.samples_csv(8).unwrap();
            let rows: Vec<Vec<f64>> = csv
                .lines()
                .skip(1)
                .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
                .collect();
            let breaks = fit.curve.breaks();
            assert_eq!(rows.len(), (breaks.len() - 1) * 8 + 1);
            for r in &rows {
                // every sample is the curve's point, to the bit
                let p = fit.curve.point(r[0]);
                assert_eq!((p.x, p.y), (r[1], r[2]));
            }
            if matches!(method, Method::BSpline { .. }) {
                // clamped: the curve starts on its first control point
                assert!((fit.curve.point(breaks[0]) - points[0]).norm() < 1e-12);
                continue;
            }
            // an interpolating method passes through every point drawn (but an open Angular or
            // cardinal spline's first and last, its guides)
            let mut drawn = fit.drawn_points();
            if !closed && matches!(method, Method::Angular | Method::Cardinal { .. }) {
                drawn = drawn[1..drawn.len() - 1].to_vec();
            }
            let hits = drawn
                .iter()
                .filter(|q| {
                    breaks
                        .iter()
                        .any(|&t| (fit.curve.point(t) - **q).norm() < 1e-12)
                })
                .count();
            assert_eq!(hits, drawn.len(), "{method:?} closed {closed}");
        }
    }
}

#[test]
fn formulas_name_every_piece_and_hold_on_it() {
    let fit = Fit::try_new(
        &blob(),
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        true,
    )
    .unwrap();
    let pieces = fit.curve.breaks().len() - 1;
    let plain = fit.formulas(FormulaStyle::Plain).unwrap();
    assert_eq!(plain.matches("piece ").count(), pieces);
    assert_eq!(plain.matches("x(u) = ").count(), pieces);
    let latex = fit.formulas(FormulaStyle::Latex).unwrap();
    assert_eq!(latex.matches("\\begin{align*}").count(), pieces);
    // the printed numbers are those of the traced formulas, which equal the curve
    for w in fit.curve.breaks().windows(2) {
        let t = 0.3 * w[0] + 0.7 * w[1];
        let f = splinelab::symbolic::curve_formulas_local(&fit.curve, t).unwrap();
        let u = t - f.origin.unwrap();
        let p = fit.curve.point(t);
        assert!((f.point[0].eval(&[u]) - p.x).abs() < 1e-12);
        assert!((f.point[1].eval(&[u]) - p.y).abs() < 1e-12);
        assert!(plain.contains(&f.point[0].plain()));
    }
}

#[test]
fn bad_fits_are_typed_errors() {
    let pts = blob();
    assert!(matches!(
        Fit::try_new(&pts[..1], Method::Linear, false).map_err(core),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(Fit::try_new(&pts, Method::Cardinal { a: f64::NAN }, false).is_err());
    assert!(Fit::try_new(&pts, Method::BSpline { order: 99 }, false).is_err());
    let fit = Fit::try_new(&pts, Method::Linear, false).unwrap();
    assert!(matches!(
        fit.samples(1).map_err(core),
        Err(Error::TooFewSamples { .. })
    ));
    assert!(matches!(
        fit.samples(usize::MAX).map_err(core),
        Err(Error::TooLarge { .. })
    ));
    assert!(fit.bezier(0.0).is_err());
}

fn core(e: splinelab::report::Error) -> Error {
    match e {
        splinelab::report::Error::Core(e) => e,
        other => panic!("not a core error: {other}"),
    }
}

/// The curve's SVG document rendered by resvg, `scale` pixels a unit: (pixmap, a map from the
/// curve's coordinates to pixels).
fn render(svg: &str, scale: f32) -> (resvg::tiny_skia::Pixmap, impl Fn(V) -> (f64, f64)) {
    let tree = resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default()).unwrap();
    let size = tree.size();
    let (w, h) = (
        (size.width() * scale).ceil() as u32,
        (size.height() * scale).ceil() as u32,
    );
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    // the document's own numbers: viewBox origin and the y flip's offset
    let number_after = |key: &str| -> Vec<f64> {
        let at = svg.find(key).unwrap() + key.len();
        svg[at..]
            .split(['"', ')'])
            .next()
            .unwrap()
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let view = number_after("viewBox=\"");
    let matrix = number_after("matrix(");
    let (vx, vy, f) = (view[0], view[1], matrix[5]);
    let k = f64::from(scale);
    (pixmap, move |p: V| ((p.x - vx) * k, (f - p.y - vy) * k))
}

#[test]
fn the_svg_path_drawn_by_resvg_is_the_curve_sampled_by_the_library() {
    let points = blob();
    for (method, closed) in [
        (
            Method::Cubic {
                end: CubicEnd::Cyclic,
            },
            true,
        ),
        (Method::Cardinal { a: 0.5 }, false),
        (Method::Angular, true),
        (Method::BSpline { order: 5 }, false),
    ] {
        let fit = Fit::try_new(&points, method, closed).unwrap();
        let segments = fit.bezier(1e-5).unwrap();
        let width = 0.01;
        let svg = splinelab::report::export::svg_document(&segments, width).unwrap();
        let scale = 160.0;
        let (pixmap, to_pixel) = render(&svg, scale);
        let samples: Vec<(f64, f64)> = fit
            .samples(256)
            .unwrap()
            .into_iter()
            .map(|(_, p)| to_pixel(p))
            .collect();
        let inked = |x: i64, y: i64| {
            pixmap
                .pixel(x as u32, y as u32)
                .is_some_and(|c| c.alpha() > 0)
        };
        // 1. every sample of the library's curve lies on the renderer's stroke (within a pixel)
        for &(x, y) in &samples {
            let near = (-1..=1)
                .any(|dx| (-1..=1).any(|dy| inked(x.round() as i64 + dx, y.round() as i64 + dy)));
            assert!(
                near,
                "{method:?}: the sample at pixel ({x:.1}, {y:.1}) is not drawn"
            );
        }
        // 2. every pixel the renderer inks lies within the stroke of the sampled polyline
        let reach = 0.5 * width * f64::from(scale) + 1.5;
        let mut inked_count = 0;
        for py in 0..pixmap.height() {
            for px in 0..pixmap.width() {
                if pixmap.pixel(px, py).is_none_or(|c| c.alpha() < 64) {
                    continue;
                }
                inked_count += 1;
                let c = V::new(f64::from(px) + 0.5, f64::from(py) + 0.5);
                let d = samples
                    .windows(2)
                    .map(|w| {
                        splinelab::metrics::curve::segment_distance(
                            c,
                            V::new(w[0].0, w[0].1),
                            V::new(w[1].0, w[1].1),
                        )
                    })
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    d <= reach,
                    "{method:?}: pixel ({px}, {py}) is {d:.2} px off the curve"
                );
            }
        }
        assert!(
            inked_count > 1000,
            "{method:?}: only {inked_count} pixels drawn"
        );
    }
}

fn square(n: usize) -> Vec<V> {
    let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)];
    let mut points = Vec::new();
    for w in corners.windows(2) {
        let (a, b) = (V::new(w[0].0, w[0].1), V::new(w[1].0, w[1].1));
        points.extend((0..n).map(|k| a + (b - a) * (k as f64 / n as f64)));
    }
    points.push(points[0]);
    points
}

#[test]
fn fewest_on_an_outline_and_its_table_and_figures() {
    let outline = [Contour {
        points: square(40),
        closed: true,
    }];
    let seen = std::sync::atomic::AtomicUsize::new(0);
    let found = fewest(
        &outline,
        Tolerance::Fraction(0.01),
        &[Family::Linear, Family::Cardinal],
        &default_options(),
        &|p| {
            assert!(p.done <= p.total && p.total == 2);
            seen.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        },
    )
    .unwrap();
    assert_eq!(seen.into_inner(), 2);
    assert_eq!(found.methods[0].counted(), 5);
    assert!(found.methods.iter().all(|m| m.within_tolerance()));
    assert!((found.tolerance - 0.01).abs() < 1e-15);
    let table = fewest::table("square-fewest", &found).unwrap();
    let md = table.to_markdown().unwrap();
    assert!(md.contains("| linear | 5 |"), "{md}");
    assert_eq!(fewest::figures(&found).unwrap().len(), 2);
    // bad requests
    assert!(fewest(
        &[],
        Tolerance::default(),
        &[Family::Linear],
        &default_options(),
        &|_| {}
    )
    .is_err());
    assert!(fewest(
        &outline,
        Tolerance::Absolute(-1.0),
        &[Family::Linear],
        &default_options(),
        &|_| {}
    )
    .is_err());
    assert!(fewest(
        &outline,
        Tolerance::default(),
        &[],
        &default_options(),
        &|_| {}
    )
    .is_err());
}

#[test]
fn tolerances_parse_as_percentages_or_distances() {
    assert_eq!(
        "1%".parse::<Tolerance>().unwrap(),
        Tolerance::Fraction(0.01)
    );
    assert_eq!(
        " 0.5 % ".parse::<Tolerance>().unwrap(),
        Tolerance::Fraction(0.005)
    );
    assert_eq!(
        "0.05".parse::<Tolerance>().unwrap(),
        Tolerance::Absolute(0.05)
    );
    for bad in ["", "%", "abc", "-1%", "0", "nan", "inf%", "1e999"] {
        assert!(bad.parse::<Tolerance>().is_err(), "{bad:?}");
    }
}

#[test]
fn the_paper_shapes_as_outlines_name_every_shape() {
    for (column, name) in shape_names() {
        let a = shape_outline(column).unwrap();
        let b = shape_outline(&name).unwrap();
        assert_eq!(a, b);
        assert!(a.points.len() > 2000);
    }
    let err = shape_outline("heart").unwrap_err().to_string();
    assert!(
        err.contains("ellipse-0.7") && err.contains("Ellisse 1"),
        "{err}"
    );
}

#[test]
fn the_simplification_stays_within_its_distance() {
    // a dense wiggly spiral: every vertex within epsilon of the simplified polyline
    let points: Vec<V> = (0..20_000)
        .map(|i| {
            let t = i as f64 * 0.002;
            V::new(t.cos() * (1.0 + 0.1 * t), t.sin() * (1.0 + 0.1 * t))
                + V::new(0.0, 0.003 * (37.0 * t).sin())
        })
        .collect();
    for eps in [1e-2, 1e-3, 1e-5] {
        let s = simplified(&points, eps);
        assert_eq!(
            (s[0], s[s.len() - 1]),
            (points[0], points[points.len() - 1])
        );
        assert!(s.len() < points.len());
        let tree = splinelab::metrics::curve::SegmentTree::new(&s).unwrap();
        assert!(tree.farthest(&points).0 <= eps * (1.0 + 1e-12), "eps {eps}");
    }
    // collinear runs are capped, never one segment for a million points
    let line: Vec<V> = (0..1000).map(|i| V::new(i as f64, 0.0)).collect();
    assert!(simplified(&line, 0.1).len() >= 1000 / 64);
}

#[test]
fn a_dense_outline_is_searched_coarsely_and_measured_exactly() {
    let dense = square(3000);
    assert!(dense.len() > splinelab::interp::choice::COARSE_ABOVE);
    let target = Target::polyline(&dense, true, 0.01).unwrap();
    let found = fewest(
        &[Contour {
            points: dense,
            closed: true,
        }],
        Tolerance::Absolute(0.01),
        &[Family::Cubic],
        &default_options(),
        &|_| {},
    )
    .unwrap();
    let choice = &found.methods[0].contours[0].search.choice;
    // the answer's measure is the exact one, on every vertex
    let exact = target.measure(&choice.method, &choice.points).unwrap();
    assert_eq!(choice.measure, exact);
    assert!(choice.within_tolerance && exact.distances.hausdorff() <= 0.01);
}

fn write_temp(dir: &Path, name: &str, text: &[u8]) -> std::path::PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn outlines_are_read_by_their_file_kind() {
    let dir = tempfile::tempdir().unwrap();
    let csv = write_temp(dir.path(), "a.csv", b"x;y\n0;0\n1;0\n1;1\n0;0\n");
    let c = read_outline(&csv, &ReadOptions::default()).unwrap();
    assert!(c[0].closed, "the last point is the first");
    let open = ReadOptions {
        closed: Some(false),
        ..ReadOptions::default()
    };
    assert!(!read_outline(&csv, &open).unwrap()[0].closed);
    let svg = write_temp(
        dir.path(),
        "a.svg",
        b"<svg xmlns='http://www.w3.org/2000/svg'><!-- <path d='M 9 9 H 1'/> --><path id='p' d='M 0 0 L 10 0 L 10 5 Z'/></svg>",
    );
    let c = read_outline(&svg, &ReadOptions::default()).unwrap();
    assert_eq!(c.len(), 1, "the comment's path is not read");
    // y turned up
    assert_eq!(c[0].points[2], V::new(10.0, -5.0));
    let path = write_temp(dir.path(), "a.path", b"M 0 0 Q 5 10 10 0 Z");
    let c = read_outline(&path, &ReadOptions::default()).unwrap();
    assert!(c[0].points.len() > 10, "the quadratic is flattened densely");
    // a loop whose segment ends all meet in one point: its size from its curves (the chords'
    // is 0), so it is flattened within a small part of it (issue 46)
    let d = b"M 0 0 C 10 10 -10 10 0 0 Z";
    let path = write_temp(dir.path(), "loop.path", d);
    let c = read_outline(&path, &ReadOptions::default()).unwrap();
    let reach = c[0].points.iter().map(|p| p.y.abs()).fold(0.0, f64::max);
    assert!(
        (reach - 7.5).abs() < 0.01,
        "the loop reaches |y| = 7.5: {reach}"
    );
    assert!(c[0].points.len() > 20, "{} points", c[0].points.len());
    let font = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/fonts/DejaVuSans.ttf"
    ));
    let with_glyph = ReadOptions {
        glyph: Some('o'),
        ..ReadOptions::default()
    };
    assert_eq!(read_outline(font, &with_glyph).unwrap().len(), 2);
    // refusals
    assert!(read_outline(font, &ReadOptions::default())
        .unwrap_err()
        .to_string()
        .contains("--glyph"));
    assert!(FileKind::of(Path::new("a.docx")).is_err());
    let bad = write_temp(
        dir.path(),
        "b.svg",
        b"<svg xmlns='http://www.w3.org/2000/svg'>\n  <path d='M 0 0 L 1 x'/>\n</svg>",
    );
    let err = read_outline(&bad, &ReadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(err.contains("line 2, column"), "{err}");
    let none = write_temp(
        dir.path(),
        "c.svg",
        b"<svg xmlns='http://www.w3.org/2000/svg'><rect/></svg>",
    );
    assert!(read_outline(&none, &ReadOptions::default()).is_err());
    let unterminated = write_temp(
        dir.path(),
        "d.svg",
        b"<svg xmlns='http://www.w3.org/2000/svg'><path d='M 0 0 L 1 1",
    );
    assert!(read_outline(&unterminated, &ReadOptions::default()).is_err());
    let binary = write_temp(dir.path(), "e.csv", &[0xff, 0xfe, 0, 1, 2]);
    let err = read_outline(&binary, &ReadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(err.contains("not UTF-8"), "{err}");
    assert!(read_outline(&dir.path().join("missing.csv"), &ReadOptions::default()).is_err());
}

#[test]
fn a_surface_on_a_users_partition_is_a_mesh_in_every_format() {
    let torus = BuiltIn::Torus {
        major: 2.0,
        minor: 1.0,
    };
    let (s, t) = "4x3"
        .parse::<PartitionSpec>()
        .unwrap()
        .partitions(&torus)
        .unwrap();
    let made = SurfaceMesh::try_new(&torus, s, t, 4).unwrap();
    assert_eq!(made.mesh.positions().len(), 17 * 13);
    // the vertices are the spline's points, which interpolate the torus at the nodes
    let exact = splinelab::Torus::new(2.0, 1.0);
    use splinelab::SurfaceDerivatives;
    let p = made.mesh.positions()[4 * 13 + 4];
    let (s0, t0) = (std::f64::consts::TAU / 4.0, std::f64::consts::TAU / 3.0);
    assert!((p - exact.partials(s0, t0).point).norm() < 1e-14);
    for (name, ascii) in [
        ("a.obj", false),
        ("a.ply", true),
        ("a.ply", false),
        ("a.STL", false),
    ] {
        let format = MeshFormat::of_path(Path::new(name), ascii).unwrap();
        assert!(!format.encode(&made.mesh).unwrap().is_empty());
    }
    assert_eq!(
        MeshFormat::of_path(Path::new("x.ply"), true).unwrap(),
        MeshFormat::Ply(PlyEncoding::Ascii)
    );
    assert!(MeshFormat::of_path(Path::new("x.gltf"), false).is_err());
    // explicit nodes, the sphere's poles included
    let sphere = BuiltIn::Sphere { radius: 2.0 };
    let spec = PartitionSpec::Nodes(
        vec![0.0, 2.0, 4.0, std::f64::consts::TAU],
        vec![
            -std::f64::consts::FRAC_PI_2,
            0.0,
            std::f64::consts::FRAC_PI_2,
        ],
    );
    let (s, t) = spec.partitions(&sphere).unwrap();
    let made = SurfaceMesh::try_new(&sphere, s, t, 3).unwrap();
    assert!(made
        .mesh
        .normals()
        .iter()
        .all(|n| (n.norm() - 1.0).abs() < 1e-12));
    // refusals
    for bad in ["", "4", "4x", "x4", "0x3", "ax3", "4x3x2", "-1x2"] {
        let parsed = bad.parse::<PartitionSpec>();
        assert!(
            parsed.is_err() || parsed.unwrap().partitions(&torus).is_err(),
            "{bad:?}"
        );
    }
    let (s, t) = "2x2"
        .parse::<PartitionSpec>()
        .unwrap()
        .partitions(&BuiltIn::Exp)
        .unwrap();
    assert!(SurfaceMesh::try_new(&BuiltIn::Exp, s.clone(), t.clone(), 0).is_err());
    assert!(SurfaceMesh::try_new(&BuiltIn::Exp, s.clone(), t.clone(), usize::MAX).is_err());
    assert!(SurfaceMesh::try_new(
        &BuiltIn::Torus {
            major: 1.0,
            minor: f64::NAN
        },
        s.clone(),
        t.clone(),
        2
    )
    .is_err());
    assert!(SurfaceMesh::try_new(&BuiltIn::Sphere { radius: -1.0 }, s, t, 2).is_err());
    assert!(PartitionSpec::Nodes(vec![0.0, 0.0], vec![0.0, 1.0])
        .partitions(&BuiltIn::Exp)
        .is_err());
}

/// A ring stored the usual way, its first point repeated at its end, is that ring: every
/// method's closed curve equals the one through the points without the repeat, and the fit
/// says it dropped it; a real coincidence is named by its indices.
#[test]
fn a_closed_rings_repeated_first_point_is_dropped_and_coincidences_are_named() {
    use splinelab::report::user::fit::Fit;
    use splinelab::{CubicEnd, Method};
    let ring: Vec<V> = [(0.0, 0.0), (2.0, 0.0), (2.5, 1.5), (1.0, 2.0), (-0.5, 1.0)]
        .iter()
        .map(|&(x, y)| V::new(x, y))
        .collect();
    let mut stored = ring.clone();
    stored.push(ring[0]);
    for method in [
        Method::Angular,
        Method::Cardinal { a: 0.5 },
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        Method::BSpline { order: 4 },
        Method::Linear,
    ] {
        let a = Fit::try_new(&stored, method, true).unwrap();
        let b = Fit::try_new(&ring, method, true).unwrap();
        assert_eq!(a.curve, b.curve, "{method:?}");
        assert!(a.dropped_ring_repeat() && !b.dropped_ring_repeat());
        // open, the repeat is a point of the curve
        let open = Fit::try_new(&stored, method, false).unwrap();
        assert!(!open.dropped_ring_repeat());
    }
    // a real coincidence: points 2 and 3 (from 0)
    let mut dup = ring.clone();
    dup.insert(3, ring[2]);
    let err = Fit::try_new(&dup, Method::Linear, true)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("point 3 coincides with point 2 (indices from 0)"),
        "{err}"
    );
    // a ring stored with two repeats: named as such
    let mut twice = stored.clone();
    twice.push(ring[0]);
    let err = Fit::try_new(&twice, Method::Linear, true)
        .unwrap_err()
        .to_string();
    assert!(err.contains("point 6 coincides with point 5"), "{err}");
    // the shipped coastline is such a ring
    let coast = splinelab::report::user::outline::read_points(
        Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/data/sicily-coastline.csv"
        )),
        &Default::default(),
    )
    .unwrap();
    assert_eq!(coast.first(), coast.last());
    let fit = Fit::try_new(
        &coast,
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        true,
    )
    .unwrap();
    assert!(fit.dropped_ring_repeat());
}

/// The size limit holds while reading: a link to a device that reads without end is refused
/// after `max + 1` bytes; an SVG document whose extent overflows is refused.
#[test]
fn limits_hold_while_reading_and_writing() {
    use splinelab::report::user::outline::read_bytes_within;
    let dir = tempfile::tempdir().unwrap();
    let zero = dir.path().join("zero.csv");
    std::os::unix::fs::symlink("/dev/zero", &zero).unwrap();
    let err = read_bytes_within(&zero, 1 << 20).unwrap_err().to_string();
    assert!(err.contains("more than the 1048576 bytes read"), "{err}");
    let small = write_temp(dir.path(), "small.csv", b"0,0\n1,1\n");
    assert_eq!(read_bytes_within(&small, 8).unwrap().len(), 8);
    assert!(read_bytes_within(&small, 7).is_err());
    // control points ±1.7e308 apart: the viewBox's width overflows
    let far = [[
        V::new(-1.7e308, 0.0),
        V::new(-1e308, 1.0),
        V::new(1e308, 1.0),
        V::new(1.7e308, 0.0),
    ]];
    let err = splinelab::report::export::svg_document(&far, 1.0)
        .unwrap_err()
        .to_string();
    assert!(err.contains("viewBox"), "{err}");
}

/// Curves out join where they should: consecutive Bézier segments share their end points
/// exactly, a closed curve's path is one subpath closed by `Z`, and its data points are
/// written as they are (no ulp off), for every method, open and closed.
#[test]
fn bezier_segments_join_exactly() {
    let pts: Vec<V> = [
        (0.1, 0.0),
        (1.3, 0.2),
        (2.2, 1.7),
        (1.1, 2.9),
        (-0.3, 2.1),
        (-0.7, 0.9),
    ]
    .iter()
    .map(|&(x, y)| V::new(x, y))
    .collect();
    for method in [
        Method::Angular,
        Method::Cardinal { a: 0.3 },
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        Method::BSpline { order: 5 },
        Method::Linear,
    ] {
        for closed in [false, true] {
            let fit = Fit::try_new(&pts, method, closed).unwrap();
            let segments = fit.bezier(1e-6).unwrap();
            for w in segments.windows(2) {
                assert_eq!(w[0][3], w[1][0], "{method:?} closed={closed}");
            }
            let d = splinelab::report::export::svg_path(&segments);
            assert_eq!(d.matches('M').count(), 1, "{method:?} closed={closed}: {d}");
            assert_eq!(d.ends_with('Z'), closed, "{method:?} closed={closed}");
            // the interpolating methods pass through their points: written exactly
            if !matches!(method, Method::BSpline { .. }) {
                let first = segments[0][0];
                assert_eq!(first, fit.curve.point(fit.curve.domain().0));
            }
        }
    }
}

/// `fit --contour K`'s reader (issue 46): one contour of a `contour,x,y` file; refused by name
/// for column indices (the contour column is found by its name), a contour with no row, a
/// file without the column, and a non-finite coordinate.
#[test]
fn one_contour_of_an_answer_file_is_read() {
    use splinelab::input::Columns;
    use splinelab::report::user::outline::read_contour_points;
    let dir = tempfile::tempdir().unwrap();
    let file = write_temp(
        dir.path(),
        "a.csv",
        b"contour,x,y\n1,0,0\n1,1,0\n2,5,5\n2,6,5\n2,6,6\n",
    );
    let two = read_contour_points(&file, &Columns::First, 2).unwrap();
    assert_eq!(two, [V::new(5.0, 5.0), V::new(6.0, 5.0), V::new(6.0, 6.0)]);
    let named = Columns::Names(vec!["x".into(), "y".into()]);
    assert_eq!(read_contour_points(&file, &named, 1).unwrap().len(), 2);
    let refusals = [
        read_contour_points(&file, &Columns::Indices(vec![1, 2]), 1),
        read_contour_points(&file, &Columns::First, 3),
        read_contour_points(
            &write_temp(dir.path(), "b.csv", b"x,y\n0,0\n"),
            &Columns::First,
            1,
        ),
        read_contour_points(
            &write_temp(dir.path(), "c.csv", b"contour,x,y\n1,nan,0\n1,1,inf\n"),
            &Columns::First,
            1,
        ),
    ];
    for (k, r) in refusals.iter().enumerate() {
        assert!(r.is_err(), "case {k}: {r:?}");
    }
    assert!(refusals[0]
        .as_ref()
        .unwrap_err()
        .to_string()
        .contains("by name"));
    assert!(refusals[1]
        .as_ref()
        .unwrap_err()
        .to_string()
        .contains("contour"));
}
