//! Parametric curves written once, generic over the number type, with exact derivatives.

use crate::error::Result;
use nalgebra::SVector;
use num_dual::{Dual2_64, Dual64, DualNum};

/// Plane points from `(x, y)` pairs, as a cell writes them:
/// `plane_points(&[(0.0, 0.0), (1.0, 2.2)])`.
pub fn plane_points(pairs: &[(f64, f64)]) -> Vec<nalgebra::Vector2<f64>> {
    pairs
        .iter()
        .map(|&(x, y)| nalgebra::Vector2::new(x, y))
        .collect()
}

/// A parametric curve `C(t) ∈ ℝᴺ` given by one formula generic over the number type (the
/// curve counterpart of [`crate::surface::ParametricSurface`]; kurbo's `ParamCurve`).
///
/// Implement [`ParametricCurve::eval`] and [`ParametricCurve::domain`]; points, checked points
/// and exact first and second derivatives (dual numbers, no finite differences) follow.
/// B-spline, NURBS, cubic-spline, polygon and blending-window curves all implement it, so one
/// function can sample, differentiate and plot any of them.
///
/// # Examples
/// ```
/// use nalgebra::Vector2;
/// use splinelab::{NurbsCurve, ParametricCurve, signed_curvature};
/// let circle = NurbsCurve::circle9(Vector2::zeros(), 2.0).unwrap();
/// let [_, d1, d2] = circle.derivatives2(0.3);
/// assert!((signed_curvature(&d1, &d2) - 0.5).abs() < 1e-14); // κ = 1/r
/// ```
pub trait ParametricCurve<const N: usize> {
    /// `C(t)` for any number type. Outside [`ParametricCurve::domain`] a curve extrapolates
    /// its end pieces.
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> SVector<D, N>;

    /// The parameter domain `[a, b]`.
    fn domain(&self) -> (f64, f64);

    /// The piece of a piecewise curve that [`ParametricCurve::eval`] uses at `t`: the span on
    /// which the formula traced there holds ([`crate::symbolic::curve_formulas`]). `None`
    /// (the default) for a curve that is one formula over its whole domain; every piecewise
    /// curve of the crate overrides it.
    fn span_at(&self, t: f64) -> Option<crate::domain::Span> {
        let _ = t;
        None
    }

    /// `C(t)`.
    fn point(&self, t: f64) -> SVector<f64, N> {
        self.eval(t)
    }

    /// `C(t)`, checked.
    ///
    /// # Errors
    /// [`crate::error::Error::NonFinite`] for a NaN or infinite `t`; [`crate::error::Error::OutOfDomain`] outside the
    /// domain (both ends included).
    fn try_point(&self, t: f64) -> Result<SVector<f64, N>> {
        check_domain("curve parameter", t, self.domain())?;
        Ok(self.point(t))
    }

    /// `C′(t)`, exact: one evaluation at the dual number `t + ε`.
    fn derivative(&self, t: f64) -> SVector<f64, N> {
        self.eval(Dual64::from_re(t).derivative()).map(|d| d.eps)
    }

    /// `samples` points at equally spaced parameters over the domain, both ends included (a
    /// polyline for drawing).
    ///
    /// # Errors
    /// [`crate::error::Error::TooFewSamples`] below 2.
    fn polyline(&self, samples: usize) -> Result<Vec<SVector<f64, N>>> {
        let (a, b) = self.domain();
        crate::error::samples("polyline samples", samples)?;
        Ok(crate::domain::linspace(a, b, samples)
            .into_iter()
            .map(|t| self.point(t))
            .collect())
    }

    /// `(C(t), C′(t), C″(t))`, exact: one evaluation at a second-order dual number.
    fn derivatives2(&self, t: f64) -> [SVector<f64, N>; 3] {
        let c = self.eval(Dual2_64::from_re(t).derivative());
        [c.map(|d| d.re), c.map(|d| d.v1), c.map(|d| d.v2)]
    }
}

/// Curvature of a plane curve from its first two derivatives,
/// `κ = (x′y″ − y′x″) / (x′² + y′²)^{3/2}` (signed: positive when turning left).
pub fn signed_curvature(d1: &SVector<f64, 2>, d2: &SVector<f64, 2>) -> f64 {
    (d1.x * d2.y - d1.y * d2.x) / d1.norm().powi(3)
}

pub(crate) use crate::domain::check_domain;
