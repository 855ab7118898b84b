//! Polynomial pieces of any degree in power form `c₀ + c₁s + … + c_p sᵖ` with vector
//! coefficients, in the scaled variable `s = (t − t₀)/w ∈ [0, 1]` of a piece of width `w`:
//! the coefficients from the piece's Bézier points, their evaluation (Horner's rule in `s²` on
//! pairs of coefficients), and the check that the power form is as accurate as the form it
//! replaces.

use nalgebra::SVector;
use num_dual::DualNum;

/// `c₀ + c₁s + … + c_p sᵖ`, for any number type (`c` non-empty), by Horner's rule on the
/// pairs `c_{2k} + c_{2k+1} s` in `s²` (Estrin's first level): the same number of
/// multiply-adds as plain Horner, and half its chain of dependent operations, so that
/// consecutive points overlap in the processor. Its rounding error on `s ∈ [0, 1]` is of
/// Horner's order, `≤ (p + 2) ε Σₖ ‖cₖ‖ sᵏ` to first order (each product and sum is exact
/// to one rounding, and every coefficient's path has at most `p + 2` of them).
#[inline]
pub(crate) fn eval<D: DualNum<Primitive = f64> + Copy, const N: usize>(
    c: &[SVector<f64, N>],
    s: D,
) -> SVector<D, N> {
    let lift = |v: &SVector<f64, N>| v.map(D::from);
    let s2 = s * s;
    let pair = |k: usize| match c.get(2 * k + 1) {
        Some(odd) => lift(odd) * s + lift(&c[2 * k]),
        None => lift(&c[2 * k]),
    };
    let pairs = c.len().div_ceil(2);
    if pairs == 0 {
        return SVector::zeros();
    }
    (0..pairs - 1)
        .rev()
        .fold(pair(pairs - 1), |acc, k| acc * s2 + pair(k))
}

/// Turns the Bézier points `b₀ … b_p` of a piece (on `s ∈ [0, 1]`) into its power
/// coefficients in place: `c_k = C(p, k) Δᵏ b₀` (forward differences; Farin, *Curves and
/// Surfaces for CAGD*, §5.3 — the monomial form of `Σ bᵢ Bᵢᵖ(s)`). The binomials are exact up
/// to [`MAX_POWER_DEGREE`] (`C(p, k−1)(p − k + 1) = k C(p, k)`, integers below 2⁵³).
pub(crate) fn bezier_to_power<const N: usize>(b: &mut [SVector<f64, N>]) {
    let p = b.len().saturating_sub(1);
    for k in 1..=p {
        for j in (k..=p).rev() {
            let prev = b[j - 1];
            b[j] -= prev;
        }
    }
    let mut binomial = 1.0;
    for (k, c) in b.iter_mut().enumerate().skip(1) {
        binomial = binomial * (p + 1 - k) as f64 / k as f64;
        *c *= binomial;
    }
}

/// The highest degree given a power form: above it every span is evaluated by its basis
/// (a power form of degree 32 may already grow to `3³²` times its Bézier points, which
/// [`safe`] declines unless the data are very smooth, and forming it costs `p³/2` vector
/// operations per span).
pub(crate) const MAX_POWER_DEGREE: usize = 32;

/// How much larger than the control points a span's power form may grow,
/// `Σₖ ‖cₖ‖ ≤ TAYLOR_GROWTH · max ‖Pᵢ‖` for its coefficients in the scaled variable
/// `s = (t − t_ℓ)/w ∈ [0, 1]`, before [`safe`] declines it. [`eval`] has absolute error
/// `≤ (p + 2) ε Σₖ ‖cₖ‖ |s|ᵏ` at degree `p` (to first order), so within the bound the power
/// form is as accurate as `(p + 2) · 256 ε · max ‖Pᵢ‖` (`1.4 · 10⁻¹³ max ‖Pᵢ‖` at degree 3,
/// `2.6 · 10⁻¹³` at degree 7), close to the basis form's `(p + 1)ε max ‖Pᵢ‖`. A Bézier piece has
/// `Σₖ ‖cₖ‖ ≤ Σₖ C(p, k) 2ᵏ max ‖bᵢ‖ = 3ᵖ max ‖bᵢ‖` at worst (a zig-zag), far less for
/// smooth data (the differences `Δᵏ b₀` are small): a cubic B-spline span stays below about
/// 40 whatever its knots, while high degrees on wild control points, and NURBS spans with
/// very unequal weights, fall back to the basis form.
pub(crate) const TAYLOR_GROWTH: f64 = 256.0;

/// `max ‖Pᵢ‖_∞` of a set of points (0 for none).
pub(crate) fn max_norm<const N: usize>(points: &[SVector<f64, N>]) -> f64 {
    points.iter().map(|p| p.amax()).fold(0.0, f64::max)
}

/// `Σₖ ‖cₖ‖_∞`: the size of a power form on `s ∈ [0, 1]` (NaN and infinite coefficients make
/// it non-finite).
pub(crate) fn size<const N: usize>(c: &[SVector<f64, N>]) -> f64 {
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
pub(crate) fn safe<const N: usize>(c: &[SVector<f64, N>], scale: f64) -> bool {
    let s = size(c);
    s.is_finite() && s <= TAYLOR_GROWTH * scale
}

/// Storage for the `p + 1` coefficients of a power form: an array when the degree is known at
/// compile time, a `Vec` otherwise.
pub(crate) trait Coefficients<const N: usize>:
    AsRef<[SVector<f64, N>]> + AsMut<[SVector<f64, N>]>
{
    /// `p + 1` zero coefficients.
    fn zeros(len: usize) -> Self;
}

impl<const N: usize, const K: usize> Coefficients<N> for [SVector<f64, N>; K] {
    fn zeros(len: usize) -> Self {
        debug_assert_eq!(len, K);
        [SVector::zeros(); K]
    }
}

impl<const N: usize> Coefficients<N> for Vec<SVector<f64, N>> {
    fn zeros(len: usize) -> Self {
        vec![SVector::zeros(); len]
    }
}

/// `$recv.$method::<C…>(args…)` with, for each dimension `n` of the list, the coefficient
/// storage `C` of a power form of degree `$p`: `[SVector<f64, n>; p + 1]` up to degree 7 (so
/// that Horner's loop is unrolled at compile time), `Vec<SVector<f64, n>>` above (the same
/// code, the loop bound known only at run time).
macro_rules! by_degree {
    ($p:expr, [$($n:tt),+], $recv:ident . $method:ident ( $($arg:expr),* )) => {
        match $p {
            0 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 1]),+>($($arg),*),
            1 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 2]),+>($($arg),*),
            2 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 3]),+>($($arg),*),
            3 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 4]),+>($($arg),*),
            4 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 5]),+>($($arg),*),
            5 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 6]),+>($($arg),*),
            6 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 7]),+>($($arg),*),
            7 => $recv.$method::<$([nalgebra::SVector<f64, $n>; 8]),+>($($arg),*),
            _ => $recv.$method::<$(Vec<nalgebra::SVector<f64, $n>>),+>($($arg),*),
        }
    };
}
pub(crate) use by_degree;

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector1;

    #[test]
    fn bezier_to_power_matches_the_bernstein_sum() {
        // b = (1, −2, 3, 0.5, 4, −1): Σ bᵢ C(5, i) sⁱ (1 − s)⁵⁻ⁱ against the power form
        let b = [1.0, -2.0, 3.0, 0.5, 4.0, -1.0].map(Vector1::new);
        let mut c = b;
        bezier_to_power(&mut c);
        for s in [0.0, 0.1, 0.37, 0.5, 0.9, 1.0] {
            let binom = [1.0, 5.0, 10.0, 10.0, 5.0, 1.0];
            let direct: f64 = (0..6)
                .map(|i| b[i].x * binom[i] * s.powi(i as i32) * (1.0 - s).powi(5 - i as i32))
                .sum();
            let horner: f64 = eval(&c, s).x;
            assert!(
                (direct - horner).abs() < 1e-14,
                "s = {s}: {direct} vs {horner}"
            );
        }
        let mut one = [Vector1::new(2.5)];
        bezier_to_power(&mut one);
        assert_eq!(eval(&one, 0.3).x, 2.5);
    }
}
