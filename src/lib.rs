//! # splinelab
//!
//! Numerical methods of computer graphics — Hermite, Bézier, spline surfaces — with exact
//! derivatives from dual numbers ([`num_dual`]) instead of a symbolic toolbox, and the
//! figures and tables of the course report *Interpolazione di superfici alla Hermite*
//! regenerated from code.
//!
//! - [`ParametricSurface`]: a surface written once, generic over the number type;
//!   [`SurfaceDerivatives`] gives `X, X_s, X_t, X_st` exactly ([`Torus`], [`Sphere`],
//!   [`ExpSurface`], [`FnSurface`] for closures).
//! - [`HermitePatch`] (`H(s)ᵀ C H(t)`), [`BezierPatch`] (Bernstein and de Casteljau),
//!   [`HermiteSpline`] (piecewise surfaces over partitions).
//! - [`metrics`] and [`study`]: the report's error measure (MATLAB `norm`), max-abs, RMS,
//!   the §3/§6 experiments and a convergence study.
//! - [`report`]: tables (polars), output files and benchmarks used by the `splinelab` CLI.

pub mod bezier;
pub mod domain;
pub mod error;
pub mod grid;
pub mod hermite;
pub mod metrics;
pub mod report;
pub mod study;
pub mod surface;
pub mod tensor;

pub use bezier::bernstein::{bernstein3, bernstein_all, bernstein_sum};
pub use bezier::codice7::report_codice7_net;
pub use bezier::de_casteljau::{de_casteljau, de_casteljau_surface};
pub use bezier::patch::BezierPatch;
pub use domain::{Interval, Partition, Rect};
pub use error::{Error, Result};
pub use grid::Grid;
pub use hermite::basis::hermite_basis;
pub use hermite::patch::HermitePatch;
pub use hermite::spline_surface::HermiteSpline;
pub use metrics::{compare, matlab_norm, CoordErrors};
pub use study::{convergence, spline_errors, uniform_spline_errors, PatchEvaluation};
pub use surface::{
    partials_on_grid, partials_on_grid_into, tabulate, ExpSurface, FnSurface, ParametricSurface,
    Partials, Sphere, SurfaceDerivatives, Torus,
};
