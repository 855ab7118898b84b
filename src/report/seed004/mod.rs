//! Seed 004, Barsi & Milanesi's comparison of interpolation methods: the Bézier and B-spline
//! figures, the Angular spline's construction, Table I's shapes under the four methods, the
//! cross-method experiment, the letter "a" and the Sicilian coastline.
//!
//! - [`figures`]: every figure but Table I's grid;
//! - [`table_i`]: Table I, its grid of panels, the cross-method table;
//! - [`fewest`]: the letters' and the coastline's fewest points;
//! - [`conclusions`]: the paper's conclusions beside the evidence.

pub mod conclusions;
pub mod fewest;
pub mod figures;
pub mod table_i;

use crate::report::Output;

/// Seed 004's outputs, in generation order.
pub const OUTPUTS: &[Output] = &[
    Output::figure(
        "fig-seed004-bezier",
        "Seed 004 Fig. 1: a Bézier curve and its defining polygon",
        || figures::bezier(&crate::curve::plane_points(&figures::POLYGON)),
    ),
    Output::figure(
        "fig-seed004-bspline-orders",
        "Seed 004 Fig. 2: one polygon as B-splines of order 2 (the polygon) to n + 1 (Bézier)",
        || figures::bspline_orders(&crate::curve::plane_points(&figures::POLYGON)),
    ),
    Output::figure(
        "fig-seed004-angular-frame",
        "Seed 004 Fig. 3: the Angular piece's local frame, circles, centres and tangents",
        || figures::angular_frame(figures::FRAME_GUIDES),
    ),
    Output::figure(
        "fig-seed004-angular-reflection",
        "Seed 004 Fig. 4: the Angular reflection case (guides above the chord)",
        || figures::angular_reflection(figures::REFLECTION_GUIDES),
    ),
    Output::figure(
        "fig-seed004-angular-pieces",
        "Seed 004 Fig. 5 a–f: single Angular pieces for six pairs of guides",
        || figures::angular_pieces(&figures::angular_cases()),
    ),
    Output::figure(
        "fig-seed004-cardinal-a",
        "Seed 004: the cardinal spline's a on the 4-point circle (0.2, 0.5, 0.83, 1.2)",
        || figures::cardinal_a(&crate::shapes::Shape::Circle, 4, &[0.2, 0.5, 0.83, 1.2]),
    ),
    Output::figure(
        "fig-seed004-circle",
        "Seed 004 Table I: the circle with the four methods",
        figures::circle,
    ),
    Output::figure(
        "fig-seed004-ellipse-0.7",
        "Seed 004 Table I: the ellipse 0.7 with the four methods",
        figures::ellipse_07,
    ),
    Output::figure(
        "fig-seed004-ellipse-0.4",
        "Seed 004 Table I: the ellipse 0.4 with the four methods",
        figures::ellipse_04,
    ),
    Output::figure(
        "fig-seed004-parabola-2",
        "Seed 004 Table I: the parabola y = x², |x| ≤ 2, with the four methods",
        figures::parabola_2,
    ),
    Output::figure(
        "fig-seed004-parabola-1",
        "Seed 004 Table I: the parabola y = x², |x| ≤ 1, with the four methods",
        figures::parabola_1,
    ),
    Output::figure(
        "fig-seed004-hyperbola-2",
        "Seed 004 Table I: the hyperbola y = 2√(1 + x²) with the four methods",
        figures::hyperbola_2,
    ),
    Output::figure(
        "fig-seed004-hyperbola-0.5",
        "Seed 004 Table I: the hyperbola y = ½√(1 + x²) with the four methods",
        figures::hyperbola_05,
    ),
    Output::figure(
        "fig-seed004-sinusoid",
        "Seed 004 Table I: one period of the sinusoid with the four methods",
        figures::sinusoid,
    ),
    Output::figure(
        "fig-seed004-rectangle",
        "Seed 004 Table I: the 2 : 1 rectangle with the four methods",
        figures::rectangle,
    ),
    Output::table(
        "table-i",
        "Seed 004 Table I regenerated: printed, the paper's rule, the fewest points found automatically",
        table_i::table,
    ),
    Output::table(
        "table-i-counts",
        "Seed 004 Table I at a glance: printed count → fewest found within 1 %, a row per method",
        || table_i::counts_of(table_i::study()?),
    ),
    Output::figure(
        "fig-table-i",
        "Seed 004 Table I's 36 panels with the automatic points (rows: methods, columns: shapes)",
        table_i::figure,
    ),
    Output::table(
        "table-i-cross",
        "Seed 004: points optimal for one method drawn by each other method",
        table_i::cross,
    ),
    Output::figure(
        "fig-seed004-cross-circle",
        "Seed 004 Fig. 6: the circle's Angular points under the cardinal and the cubic",
        figures::cross_circle,
    ),
    Output::figure(
        "fig-seed004-cross-rectangle",
        "Seed 004 Fig. 7: the rectangle's cardinal points under the Angular and the cubic",
        figures::cross_rectangle,
    ),
    Output::figure(
        "fig-seed004-cross-sinusoid",
        "Seed 004 Fig. 8 a–b: the sinusoid's cubic points under the Angular and the cardinal",
        figures::cross_sinusoid,
    ),
    Output::figure(
        "fig-seed004-cross-parabola",
        "Seed 004 Fig. 8 c–d: the parabola's cubic points under the Angular and the cardinal",
        figures::cross_parabola,
    ),
    Output::figure(
        "fig-seed004-letter-a-1",
        "Seed 004 Figs 9–11: the letter a (DejaVu Sans) with Angular, cardinal, cubic",
        figures::letter_a_1,
    ),
    Output::figure(
        "fig-seed004-letter-a-2",
        "Seed 004 Figs 12–14: the letter a (DejaVu Serif) with Angular, cardinal, cubic",
        figures::letter_a_2,
    ),
    Output::figure(
        "fig-seed004-letter-a-3",
        "Seed 004 Figs 15–17: the polygonal letter a with Angular, cardinal, cubic",
        figures::letter_a_3,
    ),
    Output::figure(
        "fig-seed004-letter-a-4",
        "Seed 004 Figs 18–20: the letter a (DejaVu Serif Italic) with Angular, cardinal, cubic",
        figures::letter_a_4,
    ),
    Output::figure(
        "fig-seed004-sicily-decimated",
        "Seed 004: the Sicilian coast decimated to about 50 points, four methods",
        || figures::sicily_decimated(crate::seeds::seed004::COAST_STEP, &figures::SICILY_METHODS),
    ),
    Output::figure(
        "fig-seed004-sicily-chosen",
        "Seed 004: the Sicilian coast with the paper's counts (92, 81, 84)",
        figures::sicily_chosen,
    ),
    Output::table(
        "table-seed004-fewest",
        "Seed 004: the fewest points per method for the letters a and the Sicilian coast",
        fewest::letters_and_coast,
    ),
    Output::table(
        "table-seed004-conclusions",
        "Seed 004: the paper's conclusions beside the evidence of our runs",
        conclusions::conclusions,
    ),
];
