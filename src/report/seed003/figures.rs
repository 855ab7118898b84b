//! Figures of seed 003, the lecture notes on curves (de Casteljau, blending functions,
//! OpenGL evaluators, the sliding bicubic surface).

use crate::bezier::bernstein::bernstein_sum;
use crate::bezier::de_casteljau::de_casteljau_recursive;
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

/// Seed 003: de Casteljau's construction at `u = 0.3, 0.5, 0.7`.
pub fn de_casteljau_figure() -> Result<Figure> {
    let points = data::CASTELJAU_POINTS.map(|(x, y)| Vector2::new(x, y));
    crate::report::draw::de_casteljau(
        &points,
        &data::CASTELJAU_U,
        "de Casteljau: repeated linear interpolation (seed 003)",
    )
}

/// Seed 003: the Lagrange and uniform cubic B-spline blending functions.
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

/// Seed 003: the sliding Lagrange window (interpolating) vs the printed `bspline` procedure
/// (approximating) on the same points.
pub fn blending_curves() -> Result<Figure> {
    let points = data::four_way_points(7);
    let lagrange = trace(&WindowCurve::lagrange(&points)?)?;
    let bspline = trace(&WindowCurve::printed_bspline(&points)?)?;
    let panel = Panel::new("7 data points", "x", "y")
        .equal()
        .legend_at(SeriesLabelPosition::LowerRight)
        .with(Series::polygon("data / control points", &points))
        .with(Series::line("Lagrange 4-point window (interpolates)", lagrange, C[0]).width(3))
        .with(Series::line("bspline procedure (approximates)", bspline, C[1]).width(3));
    Ok(Figure::from(Figure2d::new(
        "Sliding 4-point windows: Lagrange vs uniform cubic B-spline (seed 003)",
        vec![panel],
        (1, 1),
    )))
}

/// Seed 003: the four-way comparison for 6 and 7 control points.
pub fn four_way() -> Result<Figure> {
    let mut panels = Vec::new();
    for count in [6, 7] {
        let points = data::four_way_points(count);
        let cubic = trace(&WindowCurve::printed_bspline(&points)?)?;
        let opengl = opengl_polyline(&points, 5, 60, LastGroup::Truncated)?;
        let casteljau: Vec<Vector2<f64>> = linspace(0.0, 1.0, SAMPLES)
            .into_iter()
            .map(|u| de_casteljau_recursive(&points, u))
            .collect::<crate::error::Result<_>>()?;
        let bezier: Vec<Vector2<f64>> = linspace(0.0, 1.0, 60)
            .into_iter()
            .filter_map(|u| bernstein_sum(&points, u).ok())
            .collect();
        panels.push(
            Panel::new(format!("{count} control points"), "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(Series::polygon("control points", &points))
                .with(Series::line("cubic spline (bspline procedure)", cubic, C[0]).width(3))
                .with(Series::line("OpenGL spline (order 5)", xy(&opengl), C[1]).width(3))
                .with(Series::line("Casteljau", xy(&casteljau), C[2]).width(5))
                .with(
                    Series::line("Bézier (Bernstein sum, same curve)", xy(&bezier), BLACK)
                        .styled(Style::Points(3)),
                ),
        );
    }
    Ok(Figure::from(
        Figure2d::new(
            "Four curves from the same control points (seed 003)",
            panels,
            (2, 1),
        )
        .shared_legend(),
    ))
}

/// Seed 003: the OpenGL-evaluator spline, intended vs as printed (stale control points in the
/// last group).
pub fn opengl_last_group() -> Result<Figure> {
    let points = data::four_way_points(7);
    let mut panels = Vec::new();
    for (title, last) in [
        ("last group truncated (intended)", LastGroup::Truncated),
        (
            "as printed: last group padded with stale points",
            LastGroup::AsPrinted,
        ),
    ] {
        let line = opengl_polyline(&points, 5, 60, last)?;
        panels.push(
            Panel::new(title, "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(Series::polygon("control points", &points))
                .with(Series::line("glMap1f order 5, step 4", xy(&line), C[1]).width(3)),
        );
    }
    Ok(Figure::from(
        Figure2d::new(
            "OpenGL evaluator spline on 7 points: groups P0–P4, then P4–P6",
            panels,
            (2, 1),
        )
        .shared_legend(),
    ))
}

/// Seed 003: the bicubic surface of a 4×4 window sliding over a 7×7 grid of points
/// `z = f(x, y)`, uniform cubic B-spline blending, one colour per cell, the grid as a net.
///
/// # Errors
/// Never in practice (the grid is fixed and valid).
pub fn sliding_bicubic() -> Result<Figure> {
    use crate::blending::functions::Blending;
    use crate::blending::surface::SlidingBicubic;
    use crate::report::draw::Plot3d;
    use crate::report::render3d::View;
    use crate::report::style::PATCH_PALETTE;
    let grid = data::sliding_grid();
    let surface = SlidingBicubic::try_new(&grid, Blending::UniformBSpline)?;
    let mut plot = Plot3d::new("Sliding 4×4 window, uniform cubic B-spline blending (seed 003)")
        .view(View {
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
            &grid,
            RGBColor(90, 90, 90),
            "7×7 grid of points z = f(x, y) and its net",
        )
        .legend(
            "one colour per cell (4×4 window position)",
            PATCH_PALETTE[0],
        )
        .figure())
}
