//! Cubic pieces in power form `c₀ + c₁h + c₂h² + c₃h³` with vector coefficients: Horner
//! evaluation, and the exact coefficients of a polynomial piece from one evaluation at a
//! third-order dual number (its Taylor expansion).

use nalgebra::SVector;
use num_dual::{Dual3_64, DualNum};

/// The highest degree whose pieces [`taylor`] can form (third-order dual numbers).
pub(crate) const TAYLOR_DEGREE: usize = 3;

/// Power coefficients `[c₀, c₁, c₂, c₃]` of a piece of degree ≤ 3 in `h = t − t₀`.
pub(crate) type Cubic<const N: usize> = [SVector<f64, N>; 4];

/// `c₀ + c₁h + c₂h² + c₃h³` by Horner's rule, for any number type.
#[inline]
pub(crate) fn eval<D: DualNum<Primitive = f64> + Copy, const N: usize>(
    c: &Cubic<N>,
    h: D,
) -> SVector<D, N> {
    let lift = |v: &SVector<f64, N>| v.map(D::from);
    ((lift(&c[3]) * h + lift(&c[2])) * h + lift(&c[1])) * h + lift(&c[0])
}

/// The seed `t₀ + ε` whose image under a polynomial of degree ≤ 3 carries its Taylor
/// coefficients at `t₀` (see [`taylor`]).
pub(crate) fn seed(t0: f64) -> Dual3_64 {
    Dual3_64::from_re(t0).derivative()
}

/// The Taylor coefficients `f(t₀), f′(t₀), f″(t₀)/2, f‴(t₀)/6` of a value computed at
/// [`seed`]`(t₀)`: for a polynomial of degree ≤ 3 they are its power coefficients in
/// `h = t − t₀`, exact to rounding (forward-mode differentiation involves no truncation).
pub(crate) fn taylor<const N: usize>(v: &SVector<Dual3_64, N>) -> Cubic<N> {
    [
        v.map(|d| d.re),
        v.map(|d| d.v1),
        v.map(|d| d.v2 / 2.0),
        v.map(|d| d.v3 / 6.0),
    ]
}

/// How much larger than the control points a span's power form may grow,
/// `Σₖ ‖cₖ‖ wᵏ ≤ TAYLOR_GROWTH · max ‖Pᵢ‖`, before [`safe`] declines it. Horner's rule has
/// absolute error `≤ 6ε Σₖ ‖cₖ‖ |h|ᵏ` (degree 3), so within the bound the power form is as
/// accurate as `1.5 · 10⁻¹³ · max ‖Pᵢ‖`, close to the basis form's `(p + 1)ε max ‖Pᵢ‖`. A cubic
/// B-spline span stays below about 40 whatever its knots (each derivative is bounded by
/// differences of control points over knot spans no shorter than the span), so the bound
/// binds only on spans whose coefficients overflow or, for NURBS, whose weights are very
/// unequal.
pub(crate) const TAYLOR_GROWTH: f64 = 256.0;

/// `max ‖Pᵢ‖_∞` of a set of points (0 for none).
pub(crate) fn max_norm<const N: usize>(points: &[SVector<f64, N>]) -> f64 {
    points.iter().map(|p| p.amax()).fold(0.0, f64::max)
}

/// `Σₖ ‖cₖ‖_∞ wᵏ`: the size of the power form over a span of width `w` (NaN and infinite
/// coefficients make it non-finite).
pub(crate) fn size<const N: usize>(c: &Cubic<N>, width: f64) -> f64 {
    // ‖·‖_∞ that keeps a NaN (f64::max would drop it)
    let amax = |v: &SVector<f64, N>| {
        v.iter().fold(0.0, |m: f64, &x| {
            if x.is_nan() || x.abs() > m {
                x.abs()
            } else {
                m
            }
        })
    };
    c.iter().rev().fold(0.0, |acc, ck| acc * width + amax(ck))
}

/// Whether the power form `c` over a span of width `width` may replace the basis form of a
/// piece whose values are of size `scale`: finite coefficients and
/// [`size`]`(c, w) ≤ TAYLOR_GROWTH · scale`.
pub(crate) fn safe<const N: usize>(c: &Cubic<N>, width: f64, scale: f64) -> bool {
    let s = size(c, width);
    s.is_finite() && s <= TAYLOR_GROWTH * scale
}
