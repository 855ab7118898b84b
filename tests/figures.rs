//! Every figure renders headless into a temporary folder: PNG of the stated size, not blank,
//! anti-aliased, and an SVG beside it; the public drawing API draws a user's own surface,
//! partition and curve; bad output folders give a typed error.

#![cfg(feature = "report")]

use nalgebra::{Vector2, Vector3};
use plotters::prelude::{BitMapBackend, IntoDrawingArea, RGBColor};
use splinelab::num_dual::DualNum;
use splinelab::report::draw::{self, Plot2d, Plot3d};
use splinelab::report::figure::{Drawing, Figure};
use splinelab::report::plot2d::{Figure2d, Panel, Series, Style};
use splinelab::report::render3d::{Figure3d, Marker, Scene, View};
use splinelab::report::style::FIGURE_SIZE;
use splinelab::report::{self, Error};
use splinelab::study::hermite_error::convergence;
use splinelab::{
    BSplineBasis, BSplineCurve, FnSurface, HermiteSurface, KnotVector, Partition, Rect,
};

/// Minimum share of coloured pixels. Axes, grid panels, text and background are grey, black
/// or white; surfaces, vectors and data series are coloured. An axes-only 3-D chart has none
/// (see `an_axes_only_chart_fails_the_ink_check`), the sparsest real figure about 1.7 %.
const MIN_INK: f64 = 0.01;

/// The same for plane figures (curves on axes), where a single curve of width 3 inks under
/// 1 %: an axes-only plane chart has none (`an_empty_plane_chart_fails_the_ink_check`), the
/// sparsest real one about 0.4 % (`fig-seed004-cross-sinusoid`, whose Angular panel is a
/// refusal: points and shape only).
const MIN_INK_PLANE: f64 = 0.003;

/// A pixel is coloured when its channels differ by more than this.
const CHROMA: u8 = 40;

fn ink(pixels: impl Iterator<Item = [u8; 3]>) -> f64 {
    let (mut total, mut inked) = (0usize, 0usize);
    for p in pixels {
        total += 1;
        let (hi, lo) = (p.iter().max().unwrap_or(&0), p.iter().min().unwrap_or(&0));
        if hi - lo > CHROMA {
            inked += 1;
        }
    }
    inked as f64 / total.max(1) as f64
}

fn pixels(rgb: &[u8]) -> impl Iterator<Item = [u8; 3]> + '_ {
    rgb.chunks(3).map(|c| [c[0], c[1], c[2]])
}

fn is_plane(f: &Figure) -> bool {
    matches!(f.drawing, Drawing::Plane(_))
}

#[test]
fn an_axes_only_chart_fails_the_ink_check() {
    // Control: the same renderer with nothing but two black points sets the axes.
    let mut scene = Scene::default();
    for at in [Vector3::zeros(), Vector3::new(3.0, 3.0, 1.0)] {
        scene.markers.push(Marker {
            at,
            color: RGBColor(0, 0, 0),
            radius: 1,
        });
    }
    let fig = Figure::from(Figure3d {
        title: "axes only".into(),
        scene,
        view: View::default(),
    });
    let share = ink(pixels(&fig.to_rgb().expect("draws")));
    assert!(
        share < MIN_INK / 10.0,
        "axes-only chart counts as inked: {share:.4}"
    );
}

#[test]
fn an_empty_plane_chart_fails_the_ink_check() {
    // Control: a plane figure whose only series is two black points setting the axes.
    let fig = Figure::from(Figure2d::new(
        "axes only",
        vec![Panel::new("empty", "x", "y").with(
            Series::line("corners", vec![(0.0, 0.0), (1.0, 1.0)], RGBColor(0, 0, 0))
                .styled(Style::Points(1)),
        )],
        (1, 1),
    ));
    let share = ink(pixels(&fig.to_rgb().expect("draws")));
    assert!(
        share < MIN_INK_PLANE / 10.0,
        "axes-only plane chart counts as inked: {share:.5}"
    );
}

#[test]
fn every_figure_renders_png_and_svg() {
    let dir = tempfile::tempdir().expect("tempdir");
    for out in report::outputs().filter(|o| o.is_figure()) {
        if out.id == "fig-table-i" {
            // its search is Table I's: tests/choice.rs renders it once (the_table_i_outputs_build)
            continue;
        }
        let paths = out
            .write(dir.path())
            .unwrap_or_else(|e| panic!("{} renders: {e}", out.id));
        let png = dir.path().join(format!("figures/{}.png", out.id));
        let svg = dir.path().join(format!("figures/{}.svg", out.id));
        assert_eq!(paths, vec![png.clone(), svg.clone()]);
        let img = image::open(&png).expect("PNG decodes").to_rgb8();
        let fig = report::figure(out.id).expect("builds");
        assert_eq!(img.dimensions(), fig.size(), "{} size", out.id);
        let share = ink(img.pixels().map(|p| p.0));
        let plane = is_plane(&fig);
        let min = if plane { MIN_INK_PLANE } else { MIN_INK };
        assert!(
            share > min,
            "{} is nearly blank: {share:.4} of pixels inked, minimum {min}",
            out.id
        );
        let text = std::fs::read_to_string(&svg).expect("SVG");
        assert!(
            text.starts_with("<svg") && text.trim_end().ends_with("</svg>"),
            "{}",
            out.id
        );
    }
}

fn plain_bitmap(fig: &Figure) -> Vec<u8> {
    let (w, h) = FIGURE_SIZE;
    let mut plain = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut plain, FIGURE_SIZE).into_drawing_area();
        fig.render(&root).expect("renders");
        root.present().expect("presents");
    }
    plain
}

#[test]
fn png_edges_are_anti_aliased() {
    // A large black dot on white. Plotters' bitmap backend blends only the ends of each
    // horizontal span of a filled circle (and rounds polygon corners to whole pixels), so
    // its rim has fewer grey levels; drawn three times larger and averaged down, the rim
    // takes more pixels and levels. The text and axes are the same with and without the dot, so the pixels that
    // differ are the dot's.
    let axes = || {
        Plot2d::new("dot", "x", "y").with(
            Series::line("", vec![(0.0, 0.0), (1.0, 1.0)], RGBColor(255, 255, 255)).unlabeled(),
        )
    };
    let with_dot = axes()
        .with(
            Series::line("dot", vec![(0.5, 0.5)], RGBColor(0, 0, 0))
                .styled(Style::Points(60))
                .unlabeled(),
        )
        .figure();
    let without = axes().figure();
    let smooth = rim_levels(
        &with_dot.to_rgb().expect("draws"),
        &without.to_rgb().expect("draws"),
    );
    let plain = rim_levels(&plain_bitmap(&with_dot), &plain_bitmap(&without));
    assert!(
        smooth.1 > 8,
        "supersampled rim has only {} grey levels",
        smooth.1
    );
    // Measured: 318 rim pixels in 28 levels vs 268 in 21 — plotters already blends span
    // ends, so the gain is modest but strict; a broken supersampler gives equal counts.
    assert!(
        smooth.0 > plain.0 + plain.0 / 10 && smooth.1 > plain.1,
        "rim pixels: supersampled {} vs plain {} (levels {} vs {})",
        smooth.0,
        plain.0,
        smooth.1,
        plain.1
    );
}

/// The pixels where a drawing and its control differ with an intermediate value (the rim of
/// a shape drawn in black on white): their count and their number of distinct levels.
fn rim_levels(with: &[u8], without: &[u8]) -> (usize, usize) {
    let mut levels = std::collections::BTreeSet::new();
    let mut count = 0;
    for (a, b) in with.chunks(3).zip(without.chunks(3)) {
        if a != b && (20..235).contains(&a[0]) && a[0] == a[1] && a[1] == a[2] {
            count += 1;
            levels.insert(a[0] / 8);
        }
    }
    (count, levels.len())
}

/// Rows and columns spanned by coloured pixels.
fn inked_box(rgb: &[u8], (w, _h): (u32, u32)) -> (usize, usize, usize, usize) {
    let (mut x0, mut x1, mut y0, mut y1) = (usize::MAX, 0, usize::MAX, 0);
    for (k, p) in pixels(rgb).enumerate() {
        let (hi, lo) = (p.iter().max().unwrap_or(&0), p.iter().min().unwrap_or(&0));
        if hi - lo > CHROMA {
            let (x, y) = (k % w as usize, k / w as usize);
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
    }
    (x0, x1, y0, y1)
}

#[test]
fn a_3d_view_fills_the_canvas() {
    // A flat square seen from above used to take half the height; the fit scales it up.
    let flat = FnSurface::new(|s, t| Vector3::new(s, t, s * 0.0 + 0.1));
    let fig = Plot3d::new("flat")
        .surface_colored(&flat, &Rect::unit(), 10, RGBColor(0, 114, 178), 1.0)
        .expect("draws")
        .figure();
    let (x0, x1, y0, y1) = inked_box(&fig.to_rgb().expect("draws"), FIGURE_SIZE);
    let (w, h) = FIGURE_SIZE;
    let share_w = (x1 - x0) as f64 / w as f64;
    let share_h = (y1 - y0) as f64 / h as f64;
    assert!(
        share_w > 0.6 || share_h > 0.6,
        "the surface spans {share_w:.2} of the width and {share_h:.2} of the height"
    );
}

/// Issue 27: a 3-D figure is as tall as its fitted scene — no blank band under the plot —
/// and the colour bar's name reads upwards beside the bar, level with its middle.
#[test]
fn a_3d_figure_has_no_blank_band_and_its_colour_bar_is_named_beside_it() {
    let torus = splinelab::Torus::default();
    let fig = Plot3d::new("torus")
        .surface(&torus, &Rect::new(0.0, 7.0, 0.0, 7.0), 30)
        .expect("draws")
        .figure();
    let (w, h) = fig.size();
    assert_eq!(w, FIGURE_SIZE.0);
    assert!(h < FIGURE_SIZE.1, "a wide scene trims the height: {h}");
    let rgb = fig.to_rgb().expect("draws");
    // the last row with anything drawn (tick labels are black, the box grey)
    let inked_rows: Vec<usize> = pixels(&rgb)
        .enumerate()
        .filter(|(_, p)| p.iter().any(|&c| c < 200))
        .map(|(k, _)| k / w as usize)
        .collect();
    let last = *inked_rows.iter().max().expect("ink");
    assert!(
        h as usize - last < 70,
        "{} blank rows under the plot of a {h}-pixel figure",
        h as usize - last
    );
    let svg = fig.to_svg().expect("svg");
    let name = svg.find("height z").expect("the bar is named");
    let tag = &svg[svg[..name].rfind("<text").expect("in a text element")..name];
    assert!(tag.contains("rotate(270"), "the name reads upwards: {tag}");
    // beside the bar: within the bar strip on the right, at mid-height
    let attr = |key: &str| -> f64 {
        let at = tag.find(&format!(" {key}=\"")).expect("attribute") + key.len() + 3;
        tag[at..]
            .split('"')
            .next()
            .expect("value")
            .parse()
            .expect("number")
    };
    assert!(attr("x") > 0.9 * w as f64, "x = {}", attr("x"));
    assert!(
        (attr("y") - h as f64 / 2.0).abs() < 0.15 * h as f64,
        "y = {} of {h}",
        attr("y")
    );
}

/// `fitted_height` on scenes that cannot be fitted or barely fit: empty, a NaN or infinite
/// point, coordinates at the scene limit and beyond, a flat line, the smallest figure —
/// always a height between half the figure and the whole, never a panic.
#[test]
fn fitted_heights_of_bad_scenes_stay_within_the_figure() {
    use splinelab::report::render3d::{fitted_height, SCENE_LIMIT};
    let marker = |at: Vector3<f64>| Marker {
        at,
        color: RGBColor(0, 0, 0),
        radius: 3,
    };
    let scenes: Vec<Scene> = [
        vec![],
        vec![Vector3::new(f64::NAN, 0.0, 0.0)],
        vec![Vector3::repeat(f64::INFINITY), Vector3::zeros()],
        vec![Vector3::repeat(-SCENE_LIMIT), Vector3::repeat(SCENE_LIMIT)],
        vec![Vector3::repeat(f64::MAX), Vector3::zeros()],
        vec![Vector3::zeros(), Vector3::new(1.0, 0.0, 0.0)],
        vec![Vector3::zeros(); 3],
    ]
    .into_iter()
    .map(|points| Scene {
        markers: points.into_iter().map(marker).collect(),
        ..Scene::default()
    })
    .collect();
    for scene in &scenes {
        for size in [(64, 64), FIGURE_SIZE, (4000, 300)] {
            let h = fitted_height("bad", scene, View::default(), size);
            assert!(
                h >= size.1 / 2 && h <= size.1,
                "{size:?} → {h} for {:?}",
                scene.markers.iter().map(|m| m.at).collect::<Vec<_>>()
            );
        }
    }
}

#[test]
fn a_users_surface_and_partition_are_drawn_and_studied() {
    // The "Try it" path of the notebooks: a closure with sin/exp on hyper-dual numbers, a
    // partition of one's own, the spline figure, the error map, the convergence plot and
    // the tables.
    let bump = FnSurface::new(|s, t| Vector3::new(s, t, (s * 2.0).sin() * (-t * t).exp()));
    let u = Partition::try_new(vec![0.0, 0.3, 1.0, 1.5]).expect("partition");
    let v = Partition::try_new(vec![0.0, 0.5, 1.0]).expect("partition");
    let spline = HermiteSurface::try_from_surface(&bump, u, v).expect("spline");
    let rect = Rect::new(0.0, 1.5, 0.0, 1.0);
    let figures = [
        Plot3d::new("my surface")
            .surface(&bump, &rect, 20)
            .expect("surface")
            .corners(&bump, &rect)
            .derivatives(&bump, &rect)
            .figure(),
        Plot3d::new("my spline")
            .spline(&spline)
            .expect("spline")
            .figure(),
        draw::error_map(&bump, &spline, 41).expect("error map"),
        draw::convergence(
            &convergence(&bump, &rect, &[1, 2, 4, 8], 9).expect("study"),
            "my convergence",
        ),
    ];
    for fig in &figures {
        let share = ink(pixels(&fig.to_rgb().expect("draws")));
        let min = if is_plane(fig) {
            MIN_INK_PLANE
        } else {
            MIN_INK
        };
        assert!(share > min, "{} nearly blank: {share:.4}", fig.title());
        assert!(fig.to_svg().expect("svg").contains(fig.title()));
    }
    let tab = report::table::tabulation(&bump, &rect, 5, 4).expect("tabulation");
    assert_eq!(tab.df.height(), 20);
    assert_eq!(tab.df.width(), 14);
    // the partials columns are the exact derivatives of the closure
    let z_s = tab.df.column("z_s").expect("z_s").f64().expect("f64")[7].expect("value");
    let (s, t) = (1.5 * (7 / 4) as f64 / 4.0, (7 % 4) as f64 / 3.0);
    let exact = 2.0 * (2.0 * s).cos() * (-t * t).exp();
    assert!((z_s - exact).abs() < 1e-13, "{z_s} vs {exact}");
    let rows = convergence(&bump, &rect, &[1, 2, 4], 9).expect("study");
    let conv = report::table::convergence("mine", "my study", &rows).expect("table");
    assert_eq!(conv.df.height(), 9);
    assert!(conv.to_html().expect("html").contains("<table>"));
    assert!(report::table::markdown(&conv.df)
        .expect("md")
        .contains("| n |"));
}

#[test]
fn curves_bases_and_series_are_drawn_from_data() {
    let knots = KnotVector::open_uniform(3, 6, 0.0, 1.0).expect("knots");
    let basis = BSplineBasis::try_new(knots, 3).expect("basis");
    let points: Vec<Vector2<f64>> = (0..6)
        .map(|i| Vector2::new(i as f64, ((i * 7) % 5) as f64))
        .collect();
    let curve = BSplineCurve::try_new(basis.clone(), points.clone()).expect("curve");
    let figs = [
        Plot2d::new("curve", "x", "y")
            .control_polygon("polygon", &points)
            .curve("curve", &curve)
            .expect("curve")
            .tangents(&curve, &[0.2, 0.5], 0.1)
            .equal()
            .figure(),
        draw::bases(&basis, "bases"),
        draw::series(
            "log series",
            "n",
            "e",
            &[(
                "e = n⁻²",
                (1..20).map(|n| (n as f64, (n as f64).powi(-2))).collect(),
            )],
            (true, true),
        ),
    ];
    for fig in &figs {
        let share = ink(pixels(&fig.to_rgb().expect("draws")));
        assert!(
            share > MIN_INK_PLANE,
            "{} nearly blank: {share:.4}",
            fig.title()
        );
    }
    // a space curve with its control polygon, points and tangent arrows
    let helix: Vec<Vector3<f64>> = (0..8)
        .map(|i| {
            let a = i as f64 * 0.9;
            Vector3::new(a.cos(), a.sin(), 0.3 * a)
        })
        .collect();
    let knots = KnotVector::open_uniform(3, helix.len(), 0.0, 1.0).expect("knots");
    let basis = BSplineBasis::try_new(knots, 3).expect("basis");
    let space = BSplineCurve::try_new(basis, helix.clone()).expect("curve");
    let fig = Plot3d::new("a space curve")
        .polyline(&helix, RGBColor(120, 120, 120), "control polygon")
        .points(&helix, RGBColor(0, 114, 178), "control points")
        .curve(&space, RGBColor(213, 94, 0), "cubic B-spline")
        .expect("curve")
        .tangents(&space, &[0.2, 0.5, 0.8], 0.3)
        .figure();
    let share = ink(pixels(&fig.to_rgb().expect("draws")));
    assert!(
        share > MIN_INK_PLANE,
        "space curve nearly blank: {share:.4}"
    );
}

#[test]
fn unwritable_figure_folder_is_a_typed_error() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("plain-file");
    std::fs::write(&file, "x").expect("write");
    let fig = report::figure("fig2-torus").expect("builds");
    let err = fig
        .save(&file, "fig2-torus")
        .expect_err("a file is not a folder");
    assert!(matches!(err, Error::Io { .. }), "{err}");
}

#[test]
fn output_ids_are_unique_and_found() {
    let ids: Vec<&str> = report::outputs().map(|o| o.id).collect();
    let mut sorted = ids.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), ids.len(), "repeated id");
    for id in ids {
        assert_eq!(report::find(id).expect("found").id, id);
    }
    assert!(matches!(report::find("fig9"), Err(Error::UnknownId { .. })));
    assert!(matches!(
        report::figure("t6-spline-error"),
        Err(Error::UnknownId { .. })
    ));
}

#[test]
fn notebook_svg_is_the_same_drawing() {
    let svg = report::figure("fig-convergence")
        .expect("builds")
        .to_svg()
        .expect("svg");
    assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(80)]);
    assert!(svg.contains("Convergence"), "title missing");
}

#[test]
fn surfaces_written_for_dual_numbers_only_are_accepted() {
    // A closure generic over the number type compiles against the re-exported num-dual.
    fn saddle<D: DualNum<Primitive = f64> + Copy>(s: D, t: D) -> Vector3<D> {
        Vector3::new(s, t, s * s - t * t)
    }
    let f = FnSurface::new(saddle);
    let fig = draw::error_map(
        &f,
        &HermiteSurface::uniform(&f, &Rect::unit(), 2, 2).expect("spline"),
        21,
    )
    .expect("map");
    assert!(fig.to_svg().expect("svg").contains("2×2"));
}

#[test]
fn the_notebooks_try_it_helpers_hold_their_claims() {
    // 05: C¹ across the seams of a user's uneven partition, read from each side's own patch
    let torus = splinelab::Torus::default();
    let u = Partition::try_new(vec![0.0, 0.2, 0.7, 1.0]).expect("partition");
    let v = Partition::try_new(vec![0.0, 0.4, 1.0]).expect("partition");
    let spline = HermiteSurface::try_from_surface(&torus, u, v).expect("spline");
    let seams = report::table::seam_continuity(&spline, 11).expect("seams");
    assert_eq!(seams.df.height(), 2 + 1, "two u-seams and one v-seam");
    let col = |name: &str| -> Vec<f64> {
        let c = seams.df.column(name).expect("column");
        c.f64()
            .expect("f64")
            .iter()
            .map(|v| v.expect("value"))
            .collect()
    };
    for ((jx, jd), size) in col("max_jump_X")
        .into_iter()
        .zip(col("max_jump_cross_derivative"))
        .zip(col("max_cross_derivative"))
    {
        assert!(
            jx < 1e-14 && jd < 1e-13 * size.max(1.0),
            "jumps {jx:e}, {jd:e}"
        );
        assert!(
            size > 0.1,
            "the cross derivative is not trivially zero: {size}"
        );
    }
    // a control: a surface spline is not C¹ against a *different* partition's patch widths,
    // so the scaling matters — the unscaled local derivatives differ across an uneven seam
    let l = splinelab::SurfaceDerivatives::partials(&spline.patch(0, 0), 1.0, 0.5);
    let r = splinelab::SurfaceDerivatives::partials(&spline.patch(1, 0), 0.0, 0.5);
    assert!((l.ds - r.ds).amax() > 0.1, "unscaled X_s should jump");
    // 06: an error study over the user's cases, one row per case and coordinate
    let study =
        report::table::error_study(&torus, &Rect::unit(), &[(2, 2), (3, 3)], 15).expect("study");
    assert_eq!(study.df.height(), 6);
    // 08: de Casteljau for the user's points
    let pts = [
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 3.0),
        Vector2::new(3.0, 3.5),
        Vector2::new(5.0, 0.5),
    ];
    let fig = draw::de_casteljau(&pts, &[0.2, 0.5, 0.8], "mine").expect("figure");
    assert!(ink(pixels(&fig.to_rgb().expect("draws"))) > MIN_INK_PLANE);
    assert!(draw::de_casteljau(&[], &[0.5], "none").is_err());
}

#[test]
fn seed004_letters_and_method_comparisons_from_the_users_points() {
    use splinelab::seeds::letters::letter_a;
    use splinelab::{CubicEnd, Method};
    for version in 1..=4 {
        let l = letter_a(version).expect("letter");
        assert_eq!(l.contours.len(), 2, "{}: outer contour and counter", l.name);
        for c in &l.contours {
            assert!(c.points.len() >= 4, "{}", l.name);
            assert!(
                c.points.windows(2).all(|w| w[0] != w[1]),
                "{}: repeated points",
                l.name
            );
            assert_eq!(
                c.outline.first(),
                c.outline.last(),
                "{}: outline closed",
                l.name
            );
            // the marked list holds every on-curve point, in order, and the controls between
            let on: Vec<_> = c.marked.iter().filter(|m| m.1).map(|m| m.0).collect();
            assert_eq!(on, c.points, "{}", l.name);
            assert_eq!(
                c.marked.iter().any(|m| !m.1),
                version != 3,
                "{}: off-curve controls",
                l.name
            );
            // every on-curve point lies on the outline
            for p in &c.points {
                let d = c
                    .outline
                    .iter()
                    .map(|q| (q - p).norm())
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    d <= 1e-12,
                    "{}: point {p:?} off the outline by {d:e}",
                    l.name
                );
            }
        }
    }
    assert!(letter_a(5).is_err());
    assert!(matches!(
        splinelab::report::seed004::figures::shape_column(9),
        Err(Error::UnknownId { .. })
    ));
    // any user's points, any methods
    let mine: Vec<Vector2<f64>> = (0..7)
        .map(|k| Vector2::new(k as f64, (k as f64).sqrt()))
        .collect();
    let fig = draw::methods(
        "mine",
        &mine,
        &[
            (Method::Angular, mine.clone(), false),
            (
                Method::Cubic {
                    end: CubicEnd::Relaxed,
                },
                mine.clone(),
                false,
            ),
        ],
        (1, 2),
    )
    .expect("draws");
    assert!(fig.to_svg().expect("svg").contains("Angular — 7 points"));
    // points through which the method has no smooth curve: a panel that says so, not a
    // failed figure; a bad request (too few points) stays an error
    let turn = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 1.0), (4.0, 3.0)]
        .map(|(x, y)| Vector2::new(x, y))
        .to_vec();
    let refused = draw::methods(
        "bad",
        &turn,
        &[(Method::Angular, turn.clone(), false)],
        (1, 1),
    )
    .expect("draws the refusal");
    let svg = refused.to_svg().expect("svg");
    assert!(
        svg.contains("refused") && svg.contains("no G¹ Angular piece"),
        "{svg}"
    );
    assert!(draw::methods(
        "bad",
        &mine,
        &[(Method::Angular, mine[..2].to_vec(), false)],
        (1, 1)
    )
    .is_err());
}

/// Issue 23, classes 1 and 2: data at the ends of the `f64` range, marks and layouts of any
/// size, and a figure's size — each drawn (or refused) at once. On the earlier code the
/// ±`f64::MAX` plot never returned from `to_svg` (the padding overflowed to ±∞ and the tick
/// search did not end).
#[test]
fn extreme_data_and_sizes_draw_or_are_refused_at_once() {
    let started = std::time::Instant::now();
    let m = f64::MAX;
    let data: Vec<Vec<(f64, f64)>> = vec![
        vec![(-m, -m), (m, m)],
        vec![(-m, 0.0), (m, 1.0), (0.0, -m)],
        vec![(1e-300, 1e-300), (2e-300, 3e-300)],
        vec![(1e15, 1.0), (1e15 + 0.125, 1.0)],
        vec![(f64::NAN, 1.0), (f64::INFINITY, -f64::INFINITY), (0.0, 0.0)],
        vec![(5e-324, -5e-324)],
        vec![],
    ];
    for points in data {
        for fixed in [
            None,
            Some((0.0, 1.0)),
            Some((f64::NAN, 2.0)),
            Some((1.0, -1.0)),
            Some((-m, m)),
        ] {
            let mut panel = Panel::new("extreme", "x", "y")
                .with(Series::line("line", points.clone(), RGBColor(0, 0, 0)).width(u32::MAX))
                .with(
                    Series::line("marks", points.clone(), RGBColor(200, 0, 0))
                        .styled(Style::Points(u32::MAX)),
                )
                .with(
                    Series::line("crosses", points.clone(), RGBColor(0, 0, 200))
                        .styled(Style::Crosses(u32::MAX)),
                )
                .note(m, -m, "far")
                .equal();
            if let Some((lo, hi)) = fixed {
                panel = panel.x_range(lo, hi).y_range(lo, hi);
            }
            for log in [false, true] {
                let fig = Figure::new(Drawing::Plane(Figure2d::new(
                    "extreme",
                    vec![panel.clone().log(log, log)],
                    (1, 1),
                )));
                let svg = fig.to_svg().expect("an extreme plot draws");
                assert!(svg.contains("<svg"));
                fig.clone()
                    .with_size(200, 150)
                    .to_rgb()
                    .expect("and rasterises");
            }
        }
    }
    // layouts with no cell or too many are typed errors, not a panic or a huge allocation
    for layout in [(0, 1), (1, 0), (usize::MAX, usize::MAX), (1 << 20, 1 << 20)] {
        let fig = Figure::new(Drawing::Plane(Figure2d::new("layout", vec![], layout)));
        assert!(
            matches!(fig.to_svg(), Err(Error::Figure { .. })),
            "{layout:?}"
        );
    }
    // the size goes through with_size, which clamps it; to_rgb's buffer follows
    let fig =
        Figure::new(Drawing::Plane(Figure2d::new("size", vec![], (1, 1)))).with_size(u32::MAX, 1);
    assert_eq!(fig.size(), (splinelab::report::figure::MAX_SIDE, 64));
    // a 3-D scene with far, non-finite and huge marks, and a zoom beyond reason
    let mut scene = Scene::default();
    for at in [
        Vector3::new(m, -m, 0.0),
        Vector3::new(f64::NAN, 0.0, 1.0),
        Vector3::new(0.0, 1.0, 2.0),
    ] {
        scene.markers.push(Marker {
            at,
            color: RGBColor(0, 0, 0),
            radius: u32::MAX,
        });
    }
    let view = View {
        yaw: f64::NAN,
        pitch: f64::INFINITY,
        scale: 1e300,
    };
    let far = Figure::new(Drawing::Scene(Figure3d {
        title: "far".into(),
        scene: scene.clone(),
        view,
    }));
    assert!(matches!(far.to_svg(), Err(Error::Figure { .. })));
    scene.markers.remove(0);
    let near = Figure::new(Drawing::Scene(Figure3d {
        title: "near".into(),
        scene,
        view,
    }));
    near.to_svg().expect("a finite scene draws");
    near.with_size(160, 120).to_rgb().expect("and rasterises");
    assert!(
        started.elapsed() < std::time::Duration::from_secs(60),
        "{:?}",
        started.elapsed()
    );
}

/// The animations are GIFs of their frames: as many frames as asked, of the frames' size,
/// looping; de Casteljau's last frame has traced the whole curve, to the last control point.
#[test]
fn animations_are_gifs_of_their_frames() {
    use image::AnimationDecoder;
    use splinelab::report::animation;
    let points = [
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 3.0),
        Vector2::new(4.0, 3.0),
        Vector2::new(5.0, 0.0),
    ];
    let anim = animation::de_casteljau(&points, 6, "de Casteljau").unwrap();
    assert_eq!(anim.frames().len(), 6);
    let gif = anim.to_gif().unwrap();
    let decoder = image::codecs::gif::GifDecoder::new(std::io::Cursor::new(&gif)).unwrap();
    let frames = decoder.into_frames().collect_frames().unwrap();
    assert_eq!(frames.len(), 6);
    assert!(frames.iter().all(|f| f.buffer().dimensions() == (640, 500)));
    // the frames differ: the construction moves with u
    assert_ne!(frames[0].buffer().as_raw(), frames[5].buffer().as_raw());
    // a later frame stores only what changed: what did not change (the legend, at the bottom)
    // is still shown, as in the first frame, and is not blank
    let bottom = |f: &image::Frame| {
        let b = f.buffer();
        (b.height() - 60..b.height())
            .flat_map(|y| (0..b.width()).map(move |x| (x, y)))
            .map(|(x, y)| b.get_pixel(x, y).0)
            .collect::<Vec<_>>()
    };
    assert_eq!(bottom(&frames[0]), bottom(&frames[5]));
    assert!(
        bottom(&frames[5]).iter().any(|p| p[0] < 128),
        "the legend is blank"
    );
    let window = splinelab::blending::window::WindowCurve::printed_bspline(&points).unwrap();
    let slide = animation::sliding_window(&window, &points, 2, "window").unwrap();
    assert_eq!(slide.frames().len(), 2 * window.segments() + 1);
    eprintln!("GIF bytes: de Casteljau {} (6 frames)", gif.len());
}
