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
