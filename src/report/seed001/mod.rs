//! Seed 001, the lecture slides on splines: knot vectors, B-spline bases, NURBS, polynomial
//! interpolation and Runge's phenomenon, parametrizations, cubic-spline end conditions.

pub mod figures;
pub mod tables;

use crate::nurbs::NurbsCurve;
use crate::report::Output;
use crate::seeds::seed001 as data;
use nalgebra::Vector2;

/// Seed 001's outputs, in generation order.
pub const OUTPUTS: &[Output] = &[
    Output::table("knot-vectors", "Seed 001: knot vectors printed vs constructed (extended partition), open/uniform, basis size", tables::knot_vectors),
    Output::table("partition-of-unity", "Seed 001: degree 2, knots (0,0,0,1,2,2,2), t = 0.6 — printed vs Cox–de Boor vs one-pass", tables::partition_of_unity),
    Output::table("nurbs-circle", "Seed 001: radius and curvature error of the 7- and 9-point NURBS circles", tables::nurbs_circle),
    Output::table("runge-errors", "Seed 001: Runge's phenomenon, max error vs degree, equispaced vs Chebyshev, Vandermonde", tables::runge_errors),
    Output::table("cubic-spline-ends", "Seeds 001, 004: the four end conditions, residuals, tridiagonal vs collocation", tables::cubic_spline_ends),
    Output::figure("fig-bspline-bases", "Seed 001: B-spline bases n = 1, knots (0,0,1,2,3,4,5,5), and n = 2, (0,0,0,1,2,3,4,4,4)", || figures::bspline_bases(&figures::seed_bases()?)),
    Output::figure("fig-bspline-locality", "Seed 001: moving P₄ of the cubic on {0,0,0,0,¼,½,¾,1,1,1,1} changes it only on [¼, 1)", || figures::bspline_locality(&data::locality_curve()?, data::LOCALITY_INDEX, data::locality_moved_point())),
    Output::figure("fig-bspline-quadratic", "Seed 001: quadratic spline curve, knots {0,0,0,1/8,…,7/8,1,1,1}", || figures::bspline_quadratic(&data::quadratic_example()?)),
    Output::figure("fig-nurbs-circles", "Seed 001: the exact NURBS circle from 7 and from 9 control points", || figures::nurbs_circles(&[NurbsCurve::circle7(Vector2::zeros(), 1.0)?, NurbsCurve::circle9(Vector2::zeros(), 1.0)?])),
    Output::figure("fig-nurbs-weights", "Seed 001: the effect of one NURBS weight on the curve", || figures::nurbs_weights(&data::weight_example()?, data::WEIGHT_INDEX, &data::WEIGHTS)),
    Output::figure("fig-runge", "Seed 001: Runge's phenomenon, degree 9, equispaced vs Chebyshev nodes, error vs degree", || figures::runge_figure(data::RUNGE_DEGREE, &data::RUNGE_DEGREES)),
    Output::figure("fig-parametrizations", "Seed 001: uniform, chord-length and centripetal parameters for a spline curve", || figures::parametrizations(&crate::curve::plane_points(&data::PARAM_POINTS))),
    Output::figure("fig-cubic-spline-ends", "Seeds 001, 004: cubic spline with clamped, natural, periodic and anticyclic ends", || figures::cubic_spline_ends("sin x", f64::sin, &data::spline_ends_data().0, &data::end_conditions())),
];
