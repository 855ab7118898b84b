//! A piecewise cubic Hermite curve: values and tangents at the knots, one cubic per knot
//! interval — the common base of seed 004's interpolating curves (the cardinal spline derives
//! its tangents from the neighbouring points).
//!
//! On `[uₖ, uₖ₊₁]` with `h = uₖ₊₁ − uₖ` and `t = (u − uₖ)/h`:
//!
//! ```text
//! C(u) = H₀(t) Pₖ + H₁(t) h Mₖ + H₂(t) h Mₖ₊₁ + H₃(t) Pₖ₊₁
//! ```
//!
//! with the cubic Hermite basis of seed 000 §1 ([`hermite_basis`]) and `Mₖ = C′(uₖ)` the
//! tangents with respect to `u` (the factor `h` is the chain rule `dC/dt = h dC/du`).

use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use crate::hermite::basis::hermite_basis;
use nalgebra::SVector;
use num_dual::DualNum;

/// A C¹ piecewise cubic through `Pₖ` with tangents `Mₖ` at knots `uₖ`.
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteCurve<const N: usize> {
    knots: Vec<f64>,
    points: Vec<SVector<f64, N>>,
    tangents: Vec<SVector<f64, N>>,
}

impl<const N: usize> HermiteCurve<N> {
    /// The curve through `points` at `knots` with `tangents` (derivatives with respect to the
    /// knot parameter).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 2 points; [`Error::CountMismatch`] unless the three
    /// inputs have the same length; the knot rule of [`crate::domain::Partition::try_new`]
    /// (finite, strictly increasing, gaps representable); [`Error::NonFinite`] or
    /// [`Error::CoordinateTooLarge`] for a point, or for a tangent scaled by its intervals'
    /// widths (the Hermite form uses `h Mₖ`).
    pub fn try_new(
        knots: Vec<f64>,
        points: Vec<SVector<f64, N>>,
        tangents: Vec<SVector<f64, N>>,
    ) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "Hermite curve points",
                needed: 2,
                got: points.len(),
            });
        }
        for (what, len) in [
            ("Hermite curve knots", knots.len()),
            ("Hermite curve tangents", tangents.len()),
        ] {
            if len != points.len() {
                return Err(Error::CountMismatch {
                    what,
                    expected: points.len(),
                    got: len,
                });
            }
        }
        crate::domain::check_nodes("Hermite curve knots", &knots)?;
        finite_points("Hermite curve point", &points)?;
        let scaled: Vec<SVector<f64, N>> = (0..points.len())
            .flat_map(|k| {
                let left = (k > 0).then(|| tangents[k] * (knots[k] - knots[k - 1]));
                let right = (k + 1 < knots.len()).then(|| tangents[k] * (knots[k + 1] - knots[k]));
                left.into_iter().chain(right)
            })
            .collect();
        finite_points("Hermite curve tangent times its interval width", &scaled)?;
        Ok(Self {
            knots,
            points,
            tangents,
        })
    }

    /// The knots `u₀ < … < u_n`.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The points `Pₖ`.
    pub fn points(&self) -> &[SVector<f64, N>] {
        &self.points
    }

    /// The tangents `Mₖ`.
    pub fn tangents(&self) -> &[SVector<f64, N>] {
        &self.tangents
    }
}

impl<const N: usize> ParametricCurve<N> for HermiteCurve<N> {
    /// `C(u)` by the Hermite form of the interval holding `u` (the right end belongs to the
    /// last interval; outside, the end cubics extrapolate).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, u: D) -> SVector<D, N> {
        let k = crate::branch::piece(&self.knots, &u);
        let h = self.knots[k + 1] - self.knots[k];
        let t = (u - self.knots[k]) / h;
        let [h0, h1, h2, h3] = hermite_basis(t);
        let lift = |v: SVector<f64, N>| v.map(D::from);
        lift(self.points[k]) * h0
            + lift(self.tangents[k] * h) * h1
            + lift(self.tangents[k + 1] * h) * h2
            + lift(self.points[k + 1]) * h3
    }

    /// `[u₀, u_n]`.
    fn domain(&self) -> (f64, f64) {
        (self.knots[0], self.knots[self.knots.len() - 1])
    }

    /// `[uₖ, uₖ₊₁)`, the interval of `u`.
    fn span_at(&self, u: f64) -> Option<crate::domain::Span> {
        let k = crate::domain::locate(&self.knots, u);
        Some(crate::domain::Span::of(&self.knots, k))
    }
}
