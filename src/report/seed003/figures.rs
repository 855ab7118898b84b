//! Figures of seed 003, the lecture notes on curves (de Casteljau, blending functions,
//! OpenGL evaluators, the sliding bicubic surface).

use crate::bezier::bernstein::bernstein_sum;
use crate::bezier::de_casteljau::de_casteljau;
use crate::blending::functions::{lagrange4, uniform_bspline4};
use crate::blending::opengl::{opengl_polyline, LastGroup};
use crate::blending::window::WindowCurve;
use crate::domain::linspace;
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::plot2d::{
    sampled, trace, xy, Figure2d, Panel, Series, Style, INK as BLACK, SAMPLES,
};
use crate::report::style::LINE_PALETTE as C;
use crate::seeds::seed003 as data;
use nalgebra::Vector2;
use plotters::prelude::{RGBColor, SeriesLabelPosition};

/// Seed 003: de Casteljau's construction at `u = 0.3, 0.5, 0.7`, a thin call of
/// [`crate::report::draw::de_casteljau`].
pub fn de_casteljau_figure() -> Result<Figure> {
    let points = data::CASTELJAU_POINTS.map(|(x, y)| Vector2::new(x, y));
    crate::report::draw::de_casteljau(
        &points,
        &data::CASTELJAU_U,
        "de Casteljau: repeated linear interpolation",
    )
}

/// Seed 003: the Lagrange and uniform cubic B-spline blending functions (fixed by the notes:
/// nothing to choose).
///
/// # Errors
/// Never in practice.
pub fn blending_functions() -> Result<Figure> {
    let mut lag = Panel::new("Lagrange, nodes u = −1, 0, 1, 2", "u", "B_i(u)")
        .legend_at(SeriesLabelPosition::UpperMiddle);
    let mut bsp = Panel::new("uniform cubic B-spline, u ∈ [0, 1]", "u", "b_i(u)")
        .legend_at(SeriesLabelPosition::UpperMiddle)
        .y_range(-0.05, 0.8);
    for (i, &color) in C.iter().take(4).enumerate() {
        lag = lag.with(Series::line(
            format!("B{}", i + 1),
            sampled(-1.0, 2.0, |u| (u, lagrange4(u)[i])),
            color,
        ));
        bsp = bsp.with(Series::line(
            format!("b{i}"),
            sampled(0.0, 1.0, |u| (u, uniform_bspline4(u)[i])),
            color,
        ));
    }
    Ok(Figure::from(Figure2d::new(
        "Cubic blending functions (seed 003)",
        vec![lag, bsp],
        (1, 2),
    )))
}

/// The sliding Lagrange window (interpolating) vs the printed `bspline` procedure
/// (approximating) on the same points (the seed's: [`data::four_way_points`]`(7)`).
///
/// # Errors
/// The errors of the window curves (too few points).
pub fn blending_curves(points: &[Vector2<f64>]) -> Result<Figure> {
    let lagrange = trace(&WindowCurve::lagrange(points)?)?;
    let bspline = trace(&WindowCurve::printed_bspline(points)?)?;
    let panel = Panel::new(format!("{} data points", points.len()), "x", "y")
        .equal()
        .legend_at(SeriesLabelPosition::LowerRight)
        .with(Series::polygon("data / control points", points))
        .with(Series::line("Lagrange 4-point window (interpolates)", lagrange, C[0]).width(3))
        .with(Series::line("bspline procedure (approximates)", bspline, C[1]).width(3));
    Ok(Figure::from(Figure2d::new(
        "Sliding 4-point windows: Lagrange vs uniform cubic B-spline",
        vec![panel],
        (1, 1),
    )))
}

/// The notes' four-way comparison, one panel per point set: the `bspline` procedure's cubic
/// spline, the OpenGL evaluator spline of order `order`, de Casteljau and the Bernstein sum
/// (the seed's: 6 and 7 points, order 5).
///
/// # Errors
/// No point set; the errors of the curves (too few points, an order below 2).
pub fn four_way(point_sets: &[Vec<Vector2<f64>>], order: usize) -> Result<Figure> {
    if point_sets.is_empty() {
        return Err(crate::report::Error::Figure {
            name: "four_way".into(),
            message: "no point set to draw".into(),
        });
    }
    let mut panels = Vec::new();
    for points in point_sets {
        let count = points.len();
        let cubic = trace(&WindowCurve::printed_bspline(points)?)?;
        let opengl = opengl_polyline(points, order, 60, LastGroup::Truncated)?;
        let casteljau: Vec<Vector2<f64>> = linspace(0.0, 1.0, SAMPLES)
            .into_iter()
            .map(|u| de_casteljau(points, u))
            .collect::<crate::error::Result<_>>()?;
        let bezier: Vec<Vector2<f64>> = linspace(0.0, 1.0, 60)
            .into_iter()
            .filter_map(|u| bernstein_sum(points, u).ok())
            .collect();
        panels.push(
            Panel::new(format!("{count} control points"), "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(Series::polygon("control points", points))
                .with(Series::line("cubic spline (bspline procedure)", cubic, C[0]).width(3))
                .with(
                    Series::line(format!("OpenGL spline (order {order})"), xy(&opengl), C[1])
                        .width(3),
                )
                .with(Series::line("Casteljau", xy(&casteljau), C[2]).width(5))
                .with(
                    Series::line("Bézier (Bernstein sum, same curve)", xy(&bezier), BLACK)
                        .styled(Style::Points(3)),
                ),
        );
    }
    let rows = panels.len();
    Ok(Figure::from(
        Figure2d::new(
            "Four curves from the same control points",
            panels,
            (rows, 1),
        )
        .shared_legend(),
    ))
}

/// The OpenGL-evaluator spline of order 5, intended vs as printed (stale control points in
/// the last group; the seed's: 7 points, groups P0–P4, then P4–P6).
///
/// # Errors
/// The errors of the evaluator (fewer than 2 points).
pub fn opengl_last_group(points: &[Vector2<f64>]) -> Result<Figure> {
    let mut panels = Vec::new();
    for (title, last) in [
        ("last group truncated (intended)", LastGroup::Truncated),
        (
            "as printed: last group padded with stale points",
            LastGroup::AsPrinted,
        ),
    ] {
        let line = opengl_polyline(points, 5, 60, last)?;
        panels.push(
            Panel::new(title, "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(Series::polygon("control points", points))
                .with(Series::line("glMap1f order 5, step 4", xy(&line), C[1]).width(3)),
        );
    }
    Ok(Figure::from(
        Figure2d::new(
            format!(
                "OpenGL evaluator spline on {} points, groups of 5",
                points.len()
            ),
            panels,
            (2, 1),
        )
        .shared_legend(),
    ))
}

/// The bicubic surface of a 4×4 window sliding over a grid of points, uniform cubic B-spline
/// blending, one colour per cell, the grid as a net (the seed's: a 7×7 grid `z = f(x, y)`,
/// [`data::sliding_grid`]).
///
/// # Errors
/// The errors of [`crate::blending::surface::SlidingBicubic::try_new`] (a grid smaller than
/// 4×4, non-finite points).
pub fn sliding_bicubic(grid: &crate::grid::Grid<nalgebra::Vector3<f64>>) -> Result<Figure> {
    use crate::blending::functions::Blending;
    use crate::blending::surface::SlidingBicubic;
    use crate::report::draw::Plot3d;
    use crate::report::render3d::View;
    use crate::report::style::PATCH_PALETTE;
    let surface = SlidingBicubic::try_new(grid, Blending::UniformBSpline)?;
    let mut plot = Plot3d::new("Sliding 4×4 window, uniform cubic B-spline blending").view(View {
        yaw: 0.7,
        pitch: 0.55,
        scale: 1.0,
    });
    let (rows, cols) = surface.cells();
    for i in 0..rows {
        for j in 0..cols {
            let color = PATCH_PALETTE[(i + 2 * j) % PATCH_PALETTE.len()];
            plot = plot.grid(&surface.tabulate_cell((i, j), 9)?, Some(color), 0.9);
        }
    }
    Ok(plot
        .net(
            grid,
            RGBColor(90, 90, 90),
            &format!("{}×{} grid of points and its net", grid.rows(), grid.cols()),
        )
        .legend(
            "one colour per cell (4×4 window position)",
            PATCH_PALETTE[0],
        )
        .figure())
}
