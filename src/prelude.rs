//! What a notebook cell or a first program needs in one `use`: the points and vectors
//! (nalgebra), the dual numbers and their trait (num-dual), the main splinelab types and
//! traits, `surface!` and `symbolic`. An explicit list, not a glob of the crate.
//!
//! It exports no `Result` alias, so std's `Result<T, E>` keeps its two parameters in a file
//! that uses the prelude; `splinelab::Result<T>` is `Result<T, splinelab::Error>`, and `?`
//! converts between [`Error`] and the report layer's error both ways.
//!
//! # Examples
//! ```
//! use splinelab::prelude::*;
//!
//! // a surface of one's own, a `pub` struct with exact partials and formulas
//! surface!(pub Bump = |s, t| Vector3::new(s, t, (s * t).sin()));
//!
//! fn main() -> Result<(), Box<dyn std::error::Error>> {   // std's Result
//!     let d = Bump.partials(0.0, 2.0);
//!     assert_eq!(d.ds.z, 2.0);                             // ∂/∂s sin(st) = t cos(st)
//!     println!("{}", symbolic::surface_formulas(&Bump, 0.5, 0.5)?);
//!     Ok(())
//! }
//! ```
//!
//! A closure works too (written over hyper-dual numbers, since a closure cannot be generic):
//! ```
//! use splinelab::prelude::*;
//! // a user surface written once over hyper-dual numbers: exact X_st, no extra dependency
//! let saddle = FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * t.sin()));
//! let d = saddle.partials(0.5, 0.25);
//! assert!((d.dst.z - 0.25f64.cos()).abs() < 1e-15); // ∂²(s sin t)/∂s∂t = cos t
//! let spline = HermiteSurface::try_from_surface(
//!     &saddle,
//!     Partition::uniform(0.0, 1.0, 4).unwrap(),
//!     Partition::uniform(0.0, 1.0, 4).unwrap(),
//! )
//! .unwrap();
//! assert!((spline.try_point(0.5, 0.25).unwrap() - saddle.point(0.5, 0.25)).norm() < 1e-15);
//! ```

pub use nalgebra::{DMatrix, Matrix4, SVector, Vector1, Vector2, Vector3};
pub use num_dual::{Dual2_64, Dual3_64, Dual64, DualNum, HyperDual64};

pub use crate::{
    plane_points, AngularSpline, BSplineBasis, BSplineCurve, BezierPatch, CardinalSpline,
    CubicSpline, EndCondition, Error, FnSurface, HermiteCurve, HermitePatch, HermiteSurface,
    Interval, KnotVector, Lagrange, Mesh, NurbsCurve, ParametricCurve, ParametricSurface,
    Parametrization, Partition, PiecewiseLinear, Rect, SurfaceDerivatives, Torus,
};
// formulas from the same generic code (`symbolic::surface_formulas(&s, 0.3, 0.7)?`), and
// `surface!`, a user surface written once for numbers and formulas alike
pub use crate::{surface, symbolic};

#[cfg(feature = "report")]
pub use crate::report::{
    draw::{Plot2d, Plot3d},
    render3d::View,
    Figure, Table,
};
