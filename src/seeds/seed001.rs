//! The worked examples of seed 001, the lecture slides on splines (knot vectors, points,
//! parameters), shared by the figures, the tables, the tests and the notebooks. Knots and
//! printed values come from the slides; the control points are ours (the slides' figures,
//! which held theirs, are lost).

use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::KnotVector;
use crate::error::Result;
use crate::interp::cubic::EndCondition;
use crate::interp::polynomial::{
    max_interpolation_error, runge, vandermonde_condition, NodeFamily, RUNGE_INTERVAL,
};
use crate::nurbs::NurbsCurve;
use nalgebra::Vector2;
use std::f64::consts::TAU;

/// Seed 001, "Esempio: base B-spline, n = 1": `Δ* = (0, 0, 1, 2, 3, 4, 5, 5)`.
pub const BASIS_N1: [f64; 8] = [0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0];
/// Seed 001, "Esempio: base B-Spline, n = 2": `Δ* = (0, 0, 0, 1, 2, 3, 4, 4, 4)`.
pub const BASIS_N2: [f64; 9] = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0];

/// Seed 001, "Partizione dell'unità": degree 2, knots `(0,0,0,1,2,2,2)`, `t = 0.6`.
pub const UNITY_KNOTS: [f64; 7] = [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
/// Degree of the partition-of-unity example.
pub const UNITY_DEGREE: usize = 2;
/// Parameter of the partition-of-unity example.
pub const UNITY_T: f64 = 0.6;
/// `N₁,₂ … N₄,₂` at `t = 0.6` as printed.
pub const UNITY_PRINTED: [&str; 4] = ["0.16", "0.66", "0.18", "0.0"];

/// Seed 001, "Partizione estesa" example: `[0, 1]`, `m = 4`, `Δ = {1/2, 3/4}`, `M = {1, 2}`.
pub const EXTENDED_INTERIOR: [f64; 2] = [0.5, 0.75];
/// Multiplicities of the extended-partition example.
pub const EXTENDED_MULTIPLICITIES: [usize; 2] = [1, 2];
/// Order of the extended-partition example.
pub const EXTENDED_ORDER: usize = 4;
/// The printed `Δ*`, as text.
pub const EXTENDED_PRINTED: &str = "{−3/4, −1/2, −1/4, 0, 1/2, 3/4, 3/4, 1, 5/4, 3/2, 7/4}";
/// The printed `Δ*`, as numbers.
pub const EXTENDED_PRINTED_VALUES: [f64; 11] = [
    -0.75, -0.5, -0.25, 0.0, 0.5, 0.75, 0.75, 1.0, 1.25, 1.5, 1.75,
];
/// The end-knot spacing that reproduces the printed example (the slides do not state it).
pub const EXTENDED_SPACING: f64 = 0.25;

/// Seed 001, "Esempio spline cubica": knots `{0,0,0,0,¼,½,¾,1,1,1,1}`.
pub const LOCALITY_KNOTS: [f64; 11] = [0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0];
/// The control point the slides move (`P₄`, numbered from 0: its basis function `N₄,₃` has
/// support `[t₄, t₈) = [¼, 1)`).
pub const LOCALITY_INDEX: usize = 4;
const LOCALITY_POINTS: [(f64, f64); 7] = [
    (0.0, 0.0),
    (1.0, 2.0),
    (2.5, 2.6),
    (4.0, 0.6),
    (5.5, 2.4),
    (7.0, 1.8),
    (8.0, 0.0),
];
/// Where `P₄` is moved to.
const LOCALITY_MOVED: (f64, f64) = (6.0, 4.0);

/// The cubic locality example.
///
/// # Errors
/// Never in practice (the data are valid); errors of the constructors.
pub fn locality_curve() -> Result<BSplineCurve<2>> {
    let basis = BSplineBasis::try_new(KnotVector::try_new(LOCALITY_KNOTS.to_vec())?, 3)?;
    BSplineCurve::try_new(basis, to_points(&LOCALITY_POINTS))
}

/// `P₄′`.
pub fn locality_moved_point() -> Vector2<f64> {
    Vector2::new(LOCALITY_MOVED.0, LOCALITY_MOVED.1)
}

/// `|P₄′ − P₄|`.
pub fn locality_shift() -> f64 {
    let p = LOCALITY_POINTS[LOCALITY_INDEX];
    (locality_moved_point() - Vector2::new(p.0, p.1)).norm()
}

/// Seed 001, "Esempio: Curva spline m = 3": knots `{0,0,0,1/8,…,7/8,1,1,1}` (13 knots,
/// 10 control points).
///
/// # Errors
/// Never in practice; errors of the constructors.
pub fn quadratic_example() -> Result<BSplineCurve<2>> {
    let mut knots = vec![0.0; 3];
    knots.extend((1..8).map(|k| k as f64 / 8.0));
    knots.extend([1.0; 3]);
    let basis = BSplineBasis::try_new(KnotVector::try_new(knots)?, 2)?;
    let points: Vec<Vector2<f64>> = (0..10)
        .map(|i| {
            let x = i as f64;
            Vector2::new(x, if i % 2 == 0 { 0.3 * x } else { 2.0 + 0.3 * x })
        })
        .collect();
    BSplineCurve::try_new(basis, points)
}

/// The control point whose weight the weight figure varies.
pub const WEIGHT_INDEX: usize = 3;
/// The weights shown (1 is the plain B-spline).
pub const WEIGHTS: [f64; 6] = [0.05, 0.3, 1.0, 2.0, 5.0, 20.0];

/// A cubic NURBS on open uniform knots with unit weights, for the weight figure.
///
/// # Errors
/// Never in practice; errors of the constructors.
pub fn weight_example() -> Result<NurbsCurve<2>> {
    let points = to_points(&[
        (0.0, 0.0),
        (1.0, 2.0),
        (3.0, 2.5),
        (4.0, 0.5),
        (5.0, 2.5),
        (7.0, 2.0),
        (8.0, 0.0),
    ]);
    let basis = BSplineBasis::try_new(KnotVector::open_uniform(3, points.len(), 0.0, 1.0)?, 3)?;
    NurbsCurve::try_new(basis, points, vec![1.0; 7])
}

/// The degree of seed 001's Runge figure.
pub const RUNGE_DEGREE: usize = 9;
/// Degrees of the Runge table.
pub const RUNGE_DEGREES: [usize; 11] = [2, 4, 6, 8, 9, 10, 12, 14, 16, 18, 20];
/// Samples of `[−5, 5]` on which the Runge errors are measured.
pub const RUNGE_SAMPLES: usize = 2001;

/// One row of the Runge study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RungeRow {
    /// Polynomial degree (`degree + 1` nodes).
    pub degree: usize,
    /// `max |p − f|` with equispaced nodes.
    pub equispaced: f64,
    /// `max |p − f|` with Chebyshev nodes.
    pub chebyshev: f64,
    /// 2-norm condition number of the Vandermonde matrix of the equispaced nodes (`None`:
    /// numerically singular, see [`vandermonde_condition`]).
    pub vandermonde_condition: Option<f64>,
}

impl RungeRow {
    /// The error for a node family.
    pub fn error(&self, family: NodeFamily) -> f64 {
        match family {
            NodeFamily::Equispaced => self.equispaced,
            NodeFamily::Chebyshev => self.chebyshev,
        }
    }
}

/// The Runge study over [`RUNGE_DEGREES`].
///
/// # Errors
/// Never in practice; errors of the interpolation.
pub fn runge_rows() -> Result<Vec<RungeRow>> {
    runge_rows_for(&RUNGE_DEGREES)
}

/// The Runge study over any degrees.
///
/// # Errors
/// The errors of the interpolation (a degree beyond the interpolants' limit).
pub fn runge_rows_for(degrees: &[usize]) -> Result<Vec<RungeRow>> {
    degrees
        .iter()
        .map(|&degree| {
            let err = |family| {
                max_interpolation_error(runge, RUNGE_INTERVAL, degree, family, RUNGE_SAMPLES)
            };
            let nodes = NodeFamily::Equispaced.nodes(RUNGE_INTERVAL.0, RUNGE_INTERVAL.1, degree)?;
            Ok(RungeRow {
                degree,
                equispaced: err(NodeFamily::Equispaced)?,
                chebyshev: err(NodeFamily::Chebyshev)?,
                vandermonde_condition: vandermonde_condition(&nodes)?,
            })
        })
        .collect()
}

/// Points with uneven spacing for the parametrization figure.
pub const PARAM_POINTS: [(f64, f64); 7] = [
    (0.0, 0.0),
    (0.4, 1.2),
    (0.7, 1.4),
    (3.5, 1.6),
    (4.0, 0.2),
    (6.5, 0.0),
    (7.0, 1.5),
];

/// Seven samples of `sin x` on `[0, 2π]`, the data of the end-condition figure and table.
pub fn spline_ends_data() -> (Vec<f64>, Vec<f64>) {
    let x = crate::domain::linspace(0.0, TAU, 7);
    let y = x.iter().map(|t| t.sin()).collect();
    (x, y)
}

/// The four end conditions, clamped with the true slopes `cos 0 = cos 2π = 1`.
pub fn end_conditions() -> [EndCondition<1>; 4] {
    [
        EndCondition::clamped(1.0, 1.0),
        EndCondition::Natural,
        EndCondition::Periodic,
        EndCondition::Anticyclic,
    ]
}

fn to_points(p: &[(f64, f64)]) -> Vec<Vector2<f64>> {
    p.iter().map(|&(x, y)| Vector2::new(x, y)).collect()
}
