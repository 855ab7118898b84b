//! Seed 003, the lecture notes on curves: de Casteljau, Lagrange and B-spline blending,
//! the printed `bspline` and OpenGL-evaluator procedures, the sliding bicubic surface.

pub mod figures;
pub mod tables;

use crate::report::Output;
use crate::seeds::seed003 as data;

/// Seed 003's outputs, in generation order.
pub const OUTPUTS: &[Output] = &[
    Output::table(
        "de-casteljau",
        "Seed 003: de Casteljau at u = 0.3, 0.5, 0.7, recursive vs iterative vs Bernstein",
        tables::de_casteljau_table,
    ),
    Output::table(
        "seed003-checks",
        "Seed 003: the printed procedures (setbval, Lagrange B4, bspline, glMap1f) checked",
        tables::seed003_checks,
    ),
    Output::figure(
        "fig-de-casteljau",
        "Seed 003: de Casteljau's construction at u = 0.3, 0.5, 0.7",
        figures::de_casteljau_figure,
    ),
    Output::figure(
        "fig-blending-functions",
        "Seed 003: Lagrange 4-point and uniform cubic B-spline blending functions",
        figures::blending_functions,
    ),
    Output::figure(
        "fig-blending-curves",
        "Seed 003: sliding windows, Lagrange (interpolating) vs the bspline procedure",
        || figures::blending_curves(&data::four_way_points(7)),
    ),
    Output::figure(
        "fig-four-way",
        "Seed 003: cubic spline, OpenGL spline, Casteljau, Bézier for 6 and 7 points",
        || figures::four_way(&[data::four_way_points(6), data::four_way_points(7)], 5),
    ),
    Output::figure(
        "fig-opengl-evaluator",
        "Seed 003: the OpenGL-evaluator spline, last group intended vs as printed",
        || figures::opengl_last_group(&data::four_way_points(7)),
    ),
    Output::figure(
        "fig-sliding-bicubic",
        "Seed 003: bicubic surface of a 4×4 window sliding over a 7×7 grid",
        || figures::sliding_bicubic(&data::sliding_grid()),
    ),
];
