//! The cardinal spline of seed 004 §1.6 (J. H. Clark's rule, reconstructed in
//! `spec/seed004.md` §2): cubic Hermite segments whose tangents are
//!
//! ```text
//! P′ᵢ = a (Pᵢ₊₁ − Pᵢ₋₁),
//! ```
//!
//! one segment per pair of consecutive points `Pᵢ, Pᵢ₊₁` on its own parameter `t ∈ [0, 1]`, so
//! each segment depends on the four points `Pᵢ₋₁ … Pᵢ₊₂` (the first and last points are guides,
//! not interpolated). In matrix form (the paper's `[t³ t² t 1] · M_h · G_h`, with the tangents
//! substituted):
//!
//! ```text
//!                         ⎡ −a   2−a   a−2    a ⎤ ⎡Pᵢ₋₁⎤
//! P(t) = [t³ t² t 1]  ·   ⎢ 2a   a−3  3−2a   −a ⎥ ⎢Pᵢ  ⎥
//!                         ⎢ −a    0     a     0 ⎥ ⎢Pᵢ₊₁⎥
//!                         ⎣  0    1     0     0 ⎦ ⎣Pᵢ₊₂⎦
//! ```
//!
//! (`a = ½` is Catmull–Rom; `a → 0` tends to the polygon, at distance O(a).) The weights of
//! each row sum to the row of `[0 0 0 1]`, so the curve is an affine combination of the points:
//! an affine image of the points gives the affine image of the curve, the same `a`.

use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use crate::hermite::curve::HermiteCurve;
use nalgebra::{Matrix4, SVector};
use num_dual::DualNum;

/// A cardinal spline through `P₁ … P_{m−2}` with guides `P₀` and `P_{m−1}`, parameter
/// `u ∈ [0, m − 3]` (segment `k` on `[k, k + 1]`, from `P_{k+1}` to `P_{k+2}`).
#[derive(Debug, Clone, PartialEq)]
pub struct CardinalSpline<const N: usize> {
    points: Vec<SVector<f64, N>>,
    a: f64,
    /// The inner points `P₁ … P_{m−2}` at knots `0, 1, …, m − 3` with Clark's tangents.
    hermite: HermiteCurve<N>,
}

/// `M_c(a)`, the matrix of the cardinal spline in the power basis `[t³ t² t 1]` acting on
/// `[Pᵢ₋₁, Pᵢ, Pᵢ₊₁, Pᵢ₊₂]` (module docs).
pub fn cardinal_matrix(a: f64) -> Matrix4<f64> {
    Matrix4::new(
        -a,
        2.0 - a,
        a - 2.0,
        a,
        2.0 * a,
        a - 3.0,
        3.0 - 2.0 * a,
        -a,
        -a,
        0.0,
        a,
        0.0,
        0.0,
        1.0,
        0.0,
        0.0,
    )
}

impl<const N: usize> CardinalSpline<N> {
    /// The open cardinal spline of `points` (the first and last are guides).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 4 points; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`]; [`Error::NonFinite`] or [`Error::CoordinateTooLarge`] for
    /// a point; [`Error::Negative`] unless `a` is finite and at least 0 (`a = 0` gives zero
    /// tangents: the curve is the polygon of the interpolated points, each side traced from
    /// rest to rest); [`Error::CoordinateTooLarge`] if a
    /// derived tangent `a (Pᵢ₊₁ − Pᵢ₋₁)` exceeds [`crate::error::MAX_COORDINATE`].
    pub fn try_new(points: Vec<SVector<f64, N>>, a: f64) -> Result<Self> {
        crate::error::size("cardinal spline points", points.len())?;
        if points.len() < 4 {
            return Err(Error::TooFewPoints {
                what: "cardinal spline points (2 guides and 2 interpolated)",
                needed: 4,
                got: points.len(),
            });
        }
        finite_points("cardinal spline point", &points)?;
        crate::error::non_negative("cardinal spline parameter a", a)?;
        let tangents: Vec<SVector<f64, N>> = points.windows(3).map(|w| (w[2] - w[0]) * a).collect();
        let inner = points[1..points.len() - 1].to_vec();
        let knots = (0..inner.len()).map(|k| k as f64).collect();
        // on unit knots the Hermite base checks the tangents a (Pᵢ₊₁ − Pᵢ₋₁) themselves
        let hermite = HermiteCurve::try_new(knots, inner, tangents)?;
        Ok(Self { points, a, hermite })
    }

    /// The closed cardinal spline through `points`, closed as seed 004 closes it: the first
    /// three points are repeated at the end (`Q₁ … Q_m, Q₁, Q₂, Q₃`, spec decision A5), so the
    /// curve runs `Q₂ → … → Q_m → Q₁ → Q₂` and is C¹ all round; the paper counts the repeated
    /// points among the points used.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 3 points; the errors of [`CardinalSpline::try_new`].
    pub fn closed(points: &[SVector<f64, N>], a: f64) -> Result<Self> {
        let all = crate::interp::closed_by_three("closed cardinal spline points", points)?;
        Self::try_new(all, a)
    }

    /// The points, guides included.
    pub fn points(&self) -> &[SVector<f64, N>] {
        &self.points
    }

    /// The parameter `a`.
    pub fn a(&self) -> f64 {
        self.a
    }

    /// Number of segments, `m − 3`.
    pub fn segments(&self) -> usize {
        self.points.len() - 3
    }

    /// The Hermite curve it is: the inner points at knots `0, 1, …` with Clark's tangents.
    pub fn hermite(&self) -> &HermiteCurve<N> {
        &self.hermite
    }
}

impl<const N: usize> ParametricCurve<N> for CardinalSpline<N> {
    /// `C(u)` on segment `k = ⌊u⌋`, `t = u − k`: the Hermite form
    /// `H₀(t) Pᵢ + H₁(t) P′ᵢ + H₂(t) P′ᵢ₊₁ + H₃(t) Pᵢ₊₁` with `i = k + 1` ([`HermiteCurve`]
    /// on unit knots).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, u: D) -> SVector<D, N> {
        self.hermite.eval(u)
    }

    /// `[0, m − 3]`.
    fn domain(&self) -> (f64, f64) {
        (0.0, self.segments() as f64)
    }

    fn span_at(&self, u: f64) -> Option<crate::domain::Span> {
        self.hermite.span_at(u)
    }
}
