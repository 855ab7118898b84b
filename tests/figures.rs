//! Every figure renders headless into a temporary folder: PNG of the stated size, not blank,
//! and an SVG beside it; bad output folders give a typed error.

use nalgebra::Vector3;
use plotters::prelude::{BitMapBackend, IntoDrawingArea, RGBColor, WHITE};
use splinelab::report::figures::FigureId;
use splinelab::report::output::write_figure;
use splinelab::report::plot2d::{Figure2d, Panel, Series, Style};
use splinelab::report::render3d::{draw_scene, Marker, Scene, View};
use splinelab::report::style::{ensure_font, FIGURE_SIZE};
use splinelab::Error;

/// Minimum share of coloured pixels. Axes, grid panels, text and background are grey, black
/// or white; surfaces, vectors and data series are coloured. An axes-only 3-D chart has none
/// (see `an_axes_only_chart_fails_the_ink_check`), the sparsest real figure about 1.7 %.
const MIN_INK: f64 = 0.01;

/// The same for plane figures (curves on axes), where a single curve of width 3 inks under
/// 1 %: an axes-only plane chart has none (`an_empty_plane_chart_fails_the_ink_check`), the
/// sparsest real one about 0.8 %.
const MIN_INK_PLANE: f64 = 0.004;

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

fn render_to_buffer(
    draw: impl FnOnce(&plotters::drawing::DrawingArea<BitMapBackend, plotters::coord::Shift>),
) -> Vec<u8> {
    let (w, h) = FIGURE_SIZE;
    let mut buffer = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, FIGURE_SIZE).into_drawing_area();
        draw(&root);
        root.present().expect("presents");
    }
    buffer
}

#[test]
fn an_axes_only_chart_fails_the_ink_check() {
    // Control: the same renderer with nothing but two black points sets the axes.
    ensure_font().expect("font");
    let buffer = render_to_buffer(|root| {
        root.fill(&WHITE).expect("fill");
        let mut scene = Scene::default();
        for at in [Vector3::zeros(), Vector3::new(3.0, 3.0, 1.0)] {
            scene.markers.push(Marker {
                at,
                color: RGBColor(0, 0, 0),
                radius: 1,
            });
        }
        draw_scene(root, "axes only", &scene, View::default()).expect("draws");
    });
    let share = ink(buffer.chunks(3).map(|c| [c[0], c[1], c[2]]));
    assert!(
        share < MIN_INK / 10.0,
        "axes-only chart counts as inked: {share:.4}"
    );
}

#[test]
fn an_empty_plane_chart_fails_the_ink_check() {
    // Control: a plane figure whose only series is two black points setting the axes.
    ensure_font().expect("font");
    let figure = Figure2d::new(
        "axes only",
        vec![Panel::new("empty", "x", "y").with(
            Series::line("corners", vec![(0.0, 0.0), (1.0, 1.0)], RGBColor(0, 0, 0))
                .styled(Style::Points(1)),
        )],
        (1, 1),
    );
    let buffer = render_to_buffer(|root| {
        root.fill(&WHITE).expect("fill");
        figure.draw(root).expect("draws");
    });
    let share = ink(buffer.chunks(3).map(|c| [c[0], c[1], c[2]]));
    assert!(
        share < MIN_INK_PLANE / 10.0,
        "axes-only plane chart counts as inked: {share:.5}"
    );
}

#[test]
fn every_figure_renders_png_and_svg() {
    let dir = tempfile::tempdir().expect("tempdir");
    for fig in FigureId::ALL {
        let paths = write_figure(fig, dir.path()).expect("figure renders");
        let png = dir.path().join(format!("figures/{}.png", fig.id()));
        let svg = dir.path().join(format!("figures/{}.svg", fig.id()));
        assert_eq!(paths, vec![png.clone(), svg.clone()]);
        let img = image::open(&png).expect("PNG decodes").to_rgb8();
        assert_eq!(img.dimensions(), FIGURE_SIZE, "{} size", fig.id());
        let share = ink(img.pixels().map(|p| p.0));
        let min = if fig.is_plane() {
            MIN_INK_PLANE
        } else {
            MIN_INK
        };
        assert!(
            share > min,
            "{} is nearly blank: {:.4} of pixels inked, minimum {min}",
            fig.id(),
            share
        );
        let text = std::fs::read_to_string(&svg).expect("SVG");
        assert!(
            text.starts_with("<svg") && text.trim_end().ends_with("</svg>"),
            "{}",
            fig.id()
        );
    }
}

#[test]
fn figures_render_into_any_backend() {
    // The same function draws into an in-memory bitmap (as notebooks draw into SVG strings).
    let buffer = render_to_buffer(|root| FigureId::NinePatches.render(root).expect("renders"));
    let share = ink(buffer.chunks(3).map(|c| [c[0], c[1], c[2]]));
    assert!(share > MIN_INK, "in-memory render nearly blank: {share:.3}");
}

#[test]
fn unwritable_figure_folder_is_a_typed_error() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("plain-file");
    std::fs::write(&file, "x").expect("write");
    let err = write_figure(FigureId::Torus, &file).expect_err("a file is not a folder");
    assert!(matches!(err, Error::Io { .. }), "{err:?}");
}

#[test]
fn figure_ids_round_trip() {
    for fig in FigureId::ALL {
        assert_eq!(FigureId::from_id(fig.id()), Some(fig));
    }
    assert_eq!(FigureId::from_id("fig9"), None);
}

#[test]
fn notebook_svg_is_the_same_drawing() {
    let svg = splinelab::report::notebook::figure_svg(FigureId::Convergence).expect("svg");
    assert!(
        svg.0.starts_with("<svg"),
        "{}",
        &svg.0[..svg.0.len().min(80)]
    );
    assert!(svg.0.contains("Convergence"), "title missing");
}
