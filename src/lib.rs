//! # splinelab
//!
//! Numerical methods of computer graphics — Hermite, Bézier, B-spline, NURBS and
//! interpolating splines — with exact derivatives from dual numbers ([`num_dual`]) instead
//! of a symbolic toolbox, and the figures and tables of the course report *Interpolazione di
//! superfici alla Hermite* and of the lecture notes behind it regenerated from code.
//!
//! - [`ParametricSurface`]: a surface written once, generic over the number type;
//!   [`SurfaceDerivatives`] gives `X, X_s, X_t, X_st` exactly ([`Torus`], [`Sphere`],
//!   [`ExpSurface`], [`FnSurface`] for closures).
//! - [`HermitePatch`] (`H(s)ᵀ C H(t)`), [`BezierPatch`] (Bernstein and de Casteljau),
//!   [`HermiteSurface`] (piecewise surfaces over partitions).
//! - [`study`]: the experiments — seed 000's Hermite error study ([`study::hermite_error`]: §3,
//!   §6, convergence), the fewest points for an outline ([`study::outline`]: the CLI's
//!   `fewest`, seed 004's letters and coast) and seed 004's Table I ([`study::table_i`]);
//!   [`metrics`]: the error
//!   measures they use (a surface's per-coordinate errors, MATLAB `norm`, max-abs, RMS; a
//!   curve's Hausdorff distance and smoothness).
//! - [`ParametricCurve`]: a curve written once, generic over the number type, with exact
//!   derivatives; [`KnotVector`], [`BSplineBasis`], [`BSplineCurve`], [`NurbsCurve`]:
//!   B-splines and NURBS (seed 001), generic over dimension and number type.
//! - [`interp`]: polynomial interpolation ([`PowerPolynomial`], [`Lagrange`]), parametrizations,
//!   [`PiecewiseLinear`], [`CubicSpline`] with clamped, natural, periodic and anticyclic ends,
//!   B-spline collocation.
//! - [`blending`]: seed 003's blending functions, the printed `bspline` and OpenGL-evaluator
//!   procedures, the sliding bicubic surface.
//! - [`exact`]: exact rational arithmetic for the derivations — [`exact::Rational`], matrices
//!   of them with a solve, inverse and determinant written once over `f64` and rationals,
//!   polynomials, the conditions that define a basis (`K`, `K⁻¹`, the Hermite basis) and the
//!   Bernstein polynomials; the notebooks compute and assert the seeds' matrices with it.
//! - [`symbolic`]: the same generic code run on an expression type inside the dual numbers,
//!   so formulas and numbers come from one path: the partials of any surface
//!   ([`symbolic::surface_formulas`]; [`surface!`] writes one's own), curves on a piece,
//!   the Hermite, Bernstein and B-spline bases, a patch as `H(s)ᵀ C H(t)`; plain text,
//!   LaTeX and MathML.
//! - [`Mesh`]: a surface's triangles on a rectangle with its exact normals (`X_s × X_t`) and
//!   texture coordinates, for the report layer's OBJ, PLY and STL files (`report::export`).
//! - [`input`]: users' points from text (CSV, SVG path data, SVG documents) and glyphs of
//!   fonts, with the line and column of what cannot be read.
//! - [`seeds`]: the seeds' worked examples as data (knots, points, parameters), no I/O.
//! - [`report`] (feature `report`, on by default): figures and tables of the user's own
//!   objects ([`report::draw`], [`report::table`](mod@report::table)), the seeds' outputs built with them, output
//!   files and benchmarks used by the `splinelab` CLI and the notebooks; a user's own points,
//!   outlines and partitions through the methods, drawn and tabulated ([`report::user`]: fit,
//!   fewest, surface) and
//!   standard files out ([`report::export`]: OBJ, PLY, STL, SVG).
//!
//! # Features
//!
//! - `report` (default): the report layer — figures (plotters) and tables; implies `svg` (SVG
//!   documents in, usvg) and `fonts` (glyph outlines, ttf-parser).
//! - `polars` (default): tables to and from polars DataFrames (`report::Table::to_polars`,
//!   `Frame::try_from(&DataFrame)`); implies `report`.
//! - `cli` (default): the `splinelab` program (clap, anyhow); implies `report`.
//!
//! With `default-features = false` the crate is the mathematics alone: num-dual, nalgebra,
//! thiserror and num-traits (already a dependency of num-dual).

/// The linear-algebra crate of the points and vectors (`nalgebra`), re-exported so a notebook
/// cell or a user crate needs no `:dep` line of its own and always gets the version splinelab
/// is built with.
pub use nalgebra;
/// The dual-number crate (`num-dual`), re-exported for the same reason: a surface closure
/// written over `num_dual::HyperDual64` uses the same types as the library.
pub use num_dual;

/// The README's Rust examples, compiled (and, but for the `no_run` ones, run) as doc tests, so
/// that a renamed item breaks the build instead of the reader's first program (issue 28).
#[cfg(all(doctest, feature = "report"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeExamples;

pub mod bezier;
pub mod blending;
mod branch;
pub mod bspline;
pub(crate) mod curve;
pub(crate) mod domain;
pub(crate) mod error;
pub mod exact;
pub(crate) mod grid;
pub mod hermite;
mod horner;
pub mod input;
pub mod interp;
mod lanes;
mod memory;
pub(crate) mod mesh;
pub mod metrics;
pub(crate) mod nurbs;
mod parallel;
pub(crate) mod param;
pub mod prelude;
mod printed;
#[cfg(feature = "report")]
pub mod report;
pub mod seeds;
pub(crate) mod shapes;
pub mod study;
pub(crate) mod surface;
pub mod symbolic;
pub mod tensor;
mod tridiagonal;

pub use bezier::bernstein::{bernstein3, bernstein_all, bernstein_sum};
pub use bezier::codice7::{codice7_plane, report_codice7_net};
pub use bezier::de_casteljau::{
    de_casteljau, de_casteljau_levels, de_casteljau_recursive, de_casteljau_recursive_counted,
    de_casteljau_surface, BezierParameter,
};
pub use bezier::patch::BezierPatch;
pub use blending::functions::{lagrange4, printed_setbval, uniform_bspline4, Blending};
pub use bspline::basis::{BSplineBasis, KnotScalar};
pub use bspline::curve::BSplineCurve;
pub use bspline::fit::{fit_bspline, BSplineFit};
pub use bspline::knots::{EndKnots, KnotVector};
pub use curve::{plane_points, signed_curvature, ParametricCurve};
pub use domain::{Interval, Partition, Rect, Span};
pub use error::{Error, LayerError, Result, MAX_COORDINATE, MAX_ELEMENTS};
pub use grid::Grid;
pub use hermite::basis::hermite_basis;
pub use hermite::curve::HermiteCurve;
pub use hermite::patch::HermitePatch;
pub use hermite::spline_surface::HermiteSurface;
pub use interp::angular::{
    circumcircle, guide_point, AngularSpline, HermiteMidpoint, InflectionPoint, InflectionRule,
    MirrorMidpoint, PieceKind,
};
pub use interp::cardinal::{cardinal_matrix, CardinalSpline};
pub use interp::cubic::{CubicSpline, EndCondition};
pub use interp::linear::PiecewiseLinear;
pub use interp::methods::{CubicEnd, Interpolant, Method};
pub use interp::moments::moment_system;
pub use interp::polynomial::{runge, Lagrange, NodeFamily, PowerPolynomial};
pub use mesh::{Mesh, PARALLEL_TANGENTS};
pub use metrics::surface::{compare, matlab_norm, CoordErrors};
pub use nurbs::{NurbsCurve, MIN_WEIGHT_RATIO};
pub use param::Parametrization;
pub use shapes::{Shape, TOLERANCE_FRACTION};
pub use surface::{
    partials_on_grid, partials_on_grid_into, tabulate, ExpSurface, FnSurface, ParametricSurface,
    Partials, Sphere, SurfaceDerivatives, SurfaceFn, Torus,
};
