//! Cubic pieces in power form `c₀ + c₁h + c₂h² + c₃h³` with vector coefficients: Horner
//! evaluation, and the exact coefficients of a polynomial piece from one evaluation at a
//! third-order dual number (its Taylor expansion).

use nalgebra::SVector;
use num_dual::{Dual3_64, DualNum};

/// The highest degree whose pieces [`taylor`] can form (third-order dual numbers).
pub(crate) const TAYLOR_DEGREE: usize = 3;

/// Power coefficients `[c₀, c₁, c₂, c₃]` of a piece of degree ≤ 3 in its variable
/// (`s = (t − t₀)/w` for the pieces of [`taylor`]).
pub(crate) type Cubic<const N: usize> = [SVector<f64, N>; 4];

/// `c₀ + c₁s + c₂s² + c₃s³` by Horner's rule, for any number type.
#[inline]
pub(crate) fn eval<D: DualNum<Primitive = f64> + Copy, const N: usize>(
    c: &Cubic<N>,
    s: D,
) -> SVector<D, N> {
    let lift = |v: &SVector<f64, N>| v.map(D::from);
    ((lift(&c[3]) * s + lift(&c[2])) * s + lift(&c[1])) * s + lift(&c[0])
}

/// The seed `t₀ + w ε` whose image under a polynomial of degree ≤ 3 carries its Taylor
/// coefficients at `t₀` in the scaled variable `s = (t − t₀)/w` (see [`taylor`]). With `w`
/// the width of the piece, the coefficients are of the size of the values (`f⁽ᵏ⁾ wᵏ / k!`)
/// however narrow or wide the piece, so none of them over- or underflows.
pub(crate) fn seed(t0: f64, w: f64) -> Dual3_64 {
    Dual3_64::new(t0, w, 0.0, 0.0)
}

/// The Taylor coefficients `f(t₀), f′(t₀) w, f″(t₀) w²/2, f‴(t₀) w³/6` of a value computed at
/// [`seed`]`(t₀, w)`: for a polynomial of degree ≤ 3 they are its power coefficients in
/// `s = (t − t₀)/w`, exact to rounding (forward-mode differentiation involves no truncation).
pub(crate) fn taylor<const N: usize>(v: &SVector<Dual3_64, N>) -> Cubic<N> {
    [
        v.map(|d| d.re),
        v.map(|d| d.v1),
        v.map(|d| d.v2 / 2.0),
        v.map(|d| d.v3 / 6.0),
    ]
}

/// How much larger than the control points a span's power form may grow,
/// `Σₖ ‖c̃ₖ‖ ≤ TAYLOR_GROWTH · max ‖Pᵢ‖` for its coefficients in the scaled variable
/// `s = (t − t_ℓ)/w ∈ [0, 1]`, before [`safe`] declines it. Horner's rule has absolute error
/// `≤ 6ε Σₖ ‖c̃ₖ‖ |s|ᵏ` (degree 3), so within the bound the power form is as accurate as
/// `1.5 · 10⁻¹³ · max ‖Pᵢ‖`, close to the basis form's `(p + 1)ε max ‖Pᵢ‖`. A cubic B-spline
/// span stays below about 40 whatever its knots (each scaled derivative is bounded by
/// differences of control points over knot spans no shorter than the span), so the bound
/// binds only on spans whose coefficients overflow or, for NURBS, whose weights are very
/// unequal.
pub(crate) const TAYLOR_GROWTH: f64 = 256.0;

/// `max ‖Pᵢ‖_∞` of a set of points (0 for none).
pub(crate) fn max_norm<const N: usize>(points: &[SVector<f64, N>]) -> f64 {
    points.iter().map(|p| p.amax()).fold(0.0, f64::max)
}

/// `Σₖ ‖cₖ‖_∞`: the size of a power form on `s ∈ [0, 1]` (NaN and infinite coefficients make
/// it non-finite).
pub(crate) fn size<const N: usize>(c: &Cubic<N>) -> f64 {
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
    c.iter().map(amax).sum()
}

/// Whether the power form `c` (in the scaled variable) may replace the basis form of a
/// piece whose values are of size `scale`: finite coefficients and
/// [`size`]`(c) ≤ TAYLOR_GROWTH · scale`.
pub(crate) fn safe<const N: usize>(c: &Cubic<N>, scale: f64) -> bool {
    let s = size(c);
    s.is_finite() && s <= TAYLOR_GROWTH * scale
}
