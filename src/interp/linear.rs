//! Piecewise linear interpolation (seed 001, "Polinomi a tratti di interpolazione di grado 1").

use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use crate::interp::check_sites;
use crate::param::Parametrization;
use nalgebra::SVector;
use num_dual::DualNum;

/// The polygon through `(xᵢ, yᵢ)`: `p(x) = yₖ + (x − xₖ)(yₖ₊₁ − yₖ)/(xₖ₊₁ − xₖ)` on
/// `[xₖ, xₖ₊₁]` (seed 001), evaluated as the chord `(1 − u) yₖ + u yₖ₊₁`,
/// `u = (x − xₖ)/(xₖ₊₁ − xₖ)`, exact at both nodes.
/// Continuous, with a derivative that jumps at the nodes.
///
/// # Examples
/// ```
/// use nalgebra::Vector1;
/// use splinelab::{ParametricCurve, PiecewiseLinear};
/// let p = PiecewiseLinear::try_new(&[0.0, 1.0, 3.0], &[Vector1::new(0.0), Vector1::new(2.0), Vector1::new(0.0)]).unwrap();
/// assert_eq!(p.point(2.0).x, 1.0);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PiecewiseLinear<const N: usize> {
    x: Vec<f64>,
    y: Vec<SVector<f64, N>>,
}

impl<const N: usize> PiecewiseLinear<N> {
    /// The polygon through `(xᵢ, yᵢ)`.
    ///
    /// # Errors
    /// [`Error::CountMismatch`], [`Error::TooFewPoints`] (below 2), [`Error::NonFinite`],
    /// [`Error::RepeatedParameter`], [`Error::NotIncreasing`], [`Error::GapTooSmall`],
    /// [`Error::CoordinateTooLarge`].
    pub fn try_new(x: &[f64], y: &[SVector<f64, N>]) -> Result<Self> {
        if x.len() != y.len() {
            return Err(Error::CountMismatch {
                what: "values (one per abscissa)",
                expected: x.len(),
                got: y.len(),
            });
        }
        if x.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "piecewise linear data",
                needed: 2,
                got: x.len(),
            });
        }
        check_sites("piecewise linear abscissae", x)?;
        finite_points("piecewise linear value", y)?;
        Ok(Self {
            x: x.to_vec(),
            y: y.to_vec(),
        })
    }

    /// The polygon through `points` at the parameters of `param`.
    ///
    /// # Errors
    /// As [`Parametrization::parameters`].
    pub fn curve(points: &[SVector<f64, N>], param: Parametrization) -> Result<Self> {
        let t = param.parameters(points)?;
        Self::try_new(&t, points)
    }

    /// The nodes `x₀ < … < x_n` (the corners of the polygon).
    pub fn nodes(&self) -> &[f64] {
        &self.x
    }
}

impl<const N: usize> ParametricCurve<N> for PiecewiseLinear<N> {
    /// `p(x)` for any number type (end pieces extrapolated outside `[x₀, x_n]`).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, x: D) -> SVector<D, N> {
        let k = crate::branch::piece(&self.x, &x);
        // the chord in u = (x − xₖ)/(xₖ₊₁ − xₖ): exact at both nodes, and no slope that could
        // over- or underflow
        let u = (x - self.x[k]) / (self.x[k + 1] - self.x[k]);
        crate::interp::chord(&self.y[k], &self.y[k + 1], u)
    }

    /// `[x₀, x_n]`.
    fn domain(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }

    /// `[xₖ, xₖ₊₁)`, the interval of `x`.
    fn span_at(&self, x: f64) -> Option<crate::domain::Span> {
        Some(crate::domain::Span::of(
            &self.x,
            crate::domain::locate(&self.x, x),
        ))
    }
}
