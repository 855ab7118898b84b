//! A formula's coefficient: its `f64` value and, where it is known, the exact fraction it is.
//!
//! A constant of the traced code is *read as a fraction* when it is within [`READ_ULPS`]
//! units in the last place (of the larger of itself and the largest constant of its
//! formulas) of one with a denominator of at most [`READ_DENOMINATOR`] (the
//! data of a spline on rational nodes: `0.35802469135802467` is `29/81`); the arithmetic
//! of the normal form is then exact on such coefficients, so that a patch whose data are
//! fractions multiplies out to fractions (`-s^3/3`, not `-0.3333333333333357*s^3`) and terms
//! that cancel exactly are gone. Constants are read only when *every* constant of the
//! formulas reads as a fraction: one that does not (`cos(π/4)`, `0.7071067811865476`, or a
//! fraction whose denominator exceeds [`READ_DENOMINATOR`]) leaves them all floating-point
//! numbers, so that a number that is not a fraction is never printed as one by chance. The value is
//! always the `f64` nearest to the fraction when there is one, and the capture check
//! ([`crate::symbolic`]) confirms the formula with these values against the traced
//! computation — a formula whose fractions do not pass is captured again without reading.

use num_rational::Ratio;
use num_traits::{CheckedAdd, CheckedMul, ToPrimitive};

/// The largest denominator a constant is read with: `2²⁰` (a bicubic's data on sevenths of
/// an interval have denominators up to `7⁶`). Any `f64` is within a few units in the last
/// place of *some* fraction with a denominator near `10⁸`; with denominators up to `2²⁰` the
/// chance that a number that is not a fraction is read as one is about `10⁻³`, and such a
/// number moves by at most [`READ_ULPS`]: a formula prints fractions only where every number
/// its coefficients came from was read as one (one floating-point number makes the
/// coefficients it touches floating point).
pub const READ_DENOMINATOR: i128 = 1 << 20;

/// How far (units in the last place) a constant may be from the fraction it is read as: the
/// rounding of data computed in `f64` from fractions (a spline's corner values and their
/// scaled derivatives, a few roundings each).
pub const READ_ULPS: f64 = 16.0;

/// The largest denominator printed as a fraction (`29/81`); a coefficient with a larger one,
/// or with a denominator of only 2s and 5s beyond 64 (`83/100`), prints as a decimal.
const PRINTED_DENOMINATOR: i128 = 1_000_000;

/// A coefficient (module docs).
#[derive(Debug, Clone, Copy)]
pub struct Coef {
    value: f64,
    exact: Option<Ratio<i128>>,
}

impl Coef {
    /// `1`.
    pub const ONE: Coef = Coef {
        value: 1.0,
        exact: Some(Ratio::new_raw(1, 1)),
    };

    /// `value` as it is: exact when it is exactly an integer or a fraction with denominator
    /// `≤ 64` (the fractions [`crate::printed::number`] prints), else a floating-point number.
    pub fn of(value: f64) -> Coef {
        let exact =
            crate::printed::fraction(value).map(|(p, q)| Ratio::new(i128::from(p), i128::from(q)));
        Coef { value, exact }
    }

    /// A constant of the traced code, read as a fraction where it is one within rounding
    /// (module docs) — [`READ_ULPS`] of the larger of its own size and `scale`, the size of
    /// the data it came with (a datum that cancelled to a small value carries the rounding
    /// of the large ones) — else [`Coef::of`].
    pub fn read(value: f64, scale: f64) -> Coef {
        match read_fraction(value, scale) {
            Some(q) => Coef::exact(q).unwrap_or(Coef::of(value)),
            None => Coef::of(value),
        }
    }

    /// Whether [`Coef::read`] reads `value` as a fraction (an integer included).
    pub fn readable(value: f64, scale: f64) -> bool {
        value == 0.0 || read_fraction(value, scale).is_some()
    }

    /// The fraction `q` with its nearest `f64` (`None` if that is not finite).
    fn exact(q: Ratio<i128>) -> Option<Coef> {
        let value = q.to_f64()?;
        value.is_finite().then_some(Coef {
            value,
            exact: Some(q),
        })
    }

    /// The value.
    pub fn value(self) -> f64 {
        self.value
    }

    /// Whether it is zero.
    pub fn is_zero(self) -> bool {
        self.value == 0.0
    }

    /// `−c`.
    pub fn neg(self) -> Coef {
        Coef {
            value: -self.value,
            exact: self.exact.and_then(|q| {
                q.numer()
                    .checked_neg()
                    .map(|p| Ratio::new_raw(p, *q.denom()))
            }),
        }
    }

    /// `a + b`, exact when both are (and the sum fits).
    pub fn add(self, other: Coef) -> Coef {
        self.combine(
            other,
            i128::checked_add,
            |a, b| a.checked_add(b),
            self.value + other.value,
        )
    }

    /// `a · b`, exact when both are (and the product fits).
    pub fn mul(self, other: Coef) -> Coef {
        self.combine(
            other,
            i128::checked_mul,
            |a, b| a.checked_mul(b),
            self.value * other.value,
        )
    }

    /// One exact operation on two coefficients: on integers directly (most coefficients: no
    /// common denominator to find), on fractions by `fraction`; `float` (the operation in
    /// `f64`) when either is not exact or the result does not fit.
    fn combine(
        self,
        other: Coef,
        integer: fn(i128, i128) -> Option<i128>,
        fraction: fn(&Ratio<i128>, &Ratio<i128>) -> Option<Ratio<i128>>,
        float: f64,
    ) -> Coef {
        let exact = match (self.exact, other.exact) {
            (Some(a), Some(b)) if a.is_integer() && b.is_integer() => {
                integer(*a.numer(), *b.numer()).map(Ratio::from_integer)
            }
            (Some(a), Some(b)) => fraction(&a, &b),
            _ => None,
        };
        exact.and_then(Coef::exact).unwrap_or(Coef::float(float))
    }

    /// `cⁿ`, exact when `c` is (and the power fits).
    pub fn powi(self, n: i32) -> Coef {
        let exact = self.exact.and_then(|q| {
            if q.numer() == &0 && n < 0 {
                return None;
            }
            let base = if n < 0 { q.recip() } else { q };
            let mut out = Ratio::from_integer(1i128);
            for _ in 0..n.unsigned_abs().min(64) {
                out = out.checked_mul(&base)?;
            }
            (n.unsigned_abs() <= 64).then_some(out)
        });
        match exact.and_then(Coef::exact) {
            Some(c) => c,
            None => Coef::float(self.value.powi(n)),
        }
    }

    /// A result of floating-point arithmetic: exact only if it is an integer (below `2⁵³`),
    /// so an integer stays one; no search for a fraction on the way.
    fn float(value: f64) -> Coef {
        let exact = (value.fract() == 0.0 && value.abs() < 9.0e15)
            .then(|| Ratio::from_integer(value as i128));
        Coef { value, exact }
    }

    /// Whether the coefficient is a fraction known exactly (not only a floating-point number).
    pub fn is_exact(self) -> bool {
        self.exact.is_some()
    }

    /// `(p, q)` to print the coefficient as `p/q`: its exact fraction when the denominator
    /// is at most `10⁶` and has a prime factor other than 2 and 5, or is at most 64 (`29/81`,
    /// `3/4`); else the fraction [`crate::printed::number`] finds in the value; `None`: a
    /// decimal (`0.83`, `0.7071067811865476`).
    pub fn fraction(self) -> Option<(i64, u64)> {
        if let Some(q) = self.exact {
            let (p, d) = (*q.numer(), *q.denom());
            let mut rest = d;
            for f in [2, 5] {
                while rest % f == 0 {
                    rest /= f;
                }
            }
            let decimal_denominator = rest == 1 && d > 64;
            if d <= PRINTED_DENOMINATOR
                && p.unsigned_abs() < 1_000_000_000_000_000
                && !decimal_denominator
            {
                return Some((p as i64, d as u64));
            }
        }
        crate::printed::fraction(self.value).map(|(p, q)| (p, u64::from(q)))
    }
}

/// The simplest fraction `p/q` (`q ≤` [`READ_DENOMINATOR`]) within [`READ_ULPS`] of `x`: the
/// first convergent of its continued fraction that close, if one is.
fn read_fraction(x: f64, scale: f64) -> Option<Ratio<i128>> {
    if !x.is_finite() || x.abs() >= 9.0e15 {
        return None;
    }
    if x.fract() == 0.0 {
        return Some(Ratio::from_integer(x as i128));
    }
    let target = x.abs();
    let scale = if scale.is_finite() { scale.abs() } else { 0.0 };
    let tolerance = READ_ULPS * f64::EPSILON * target.max(scale);
    let (mut h0, mut h1) = (0i128, 1i128);
    let (mut k0, mut k1) = (1i128, 0i128);
    let mut r = target;
    for _ in 0..64 {
        let a = r.floor();
        if a > 1e15 {
            return None;
        }
        let a = a as i128;
        let h = a.checked_mul(h1)?.checked_add(h0)?;
        let k = a.checked_mul(k1)?.checked_add(k0)?;
        if k > READ_DENOMINATOR {
            return None;
        }
        // a number that is not zero is not read as zero (dropping residue is the snapping's)
        if h != 0 && (h as f64 / k as f64 - target).abs() <= tolerance {
            let p = if x < 0.0 { -h } else { h };
            return Some(Ratio::new(p, k));
        }
        (h0, h1, k0, k1) = (h1, h, k1, k);
        let frac = r - r.floor();
        if frac == 0.0 {
            return None;
        }
        r = 1.0 / frac;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_computed_from_fractions_are_read_back_and_others_are_not() {
        // 29/81 as a spline's corner value computes it (rounded on the way)
        let s = 1.0f64 / 3.0;
        let x = s - s.powi(3) / 3.0 + s * s * s;
        assert_eq!(read_fraction(x, 0.0), Some(Ratio::new(29, 81)));
        assert_eq!(
            read_fraction(0.35802469135802467, 0.0),
            Some(Ratio::new(29, 81))
        );
        assert_eq!(read_fraction(-7.0 / 12.0, 0.0), Some(Ratio::new(-7, 12)));
        // a datum that cancelled to a small value: its rounding is the large data's
        let small = (1000.0f64 + 1.0 / 250.0) - 1000.0;
        assert_ne!(small, 1.0 / 250.0);
        assert_eq!(read_fraction(small, 0.0), None);
        assert_eq!(read_fraction(small, 1000.0), Some(Ratio::new(1, 250)));
        assert_eq!(read_fraction(0.1, 0.0), Some(Ratio::new(1, 10)));
        assert_eq!(read_fraction(3.0, 0.0), Some(Ratio::from_integer(3)));
        for not in [
            std::f64::consts::FRAC_1_SQRT_2,
            std::f64::consts::PI,
            0.3f64.cos(),
            1e-300,
            f64::NAN,
            f64::INFINITY,
            1e300,
        ] {
            assert_eq!(read_fraction(not, 1.0), None, "{not}");
        }
    }

    #[test]
    fn exact_arithmetic_cancels_what_floating_point_leaves() {
        let (a, b, c) = (
            Coef::read(0.1, 0.0),
            Coef::read(0.2, 0.0),
            Coef::read(0.3, 0.0),
        );
        let sum = a.add(b).add(c.neg());
        assert!(sum.is_zero(), "{sum:?}"); // 0.1 + 0.2 − 0.3 is 5.6e-17 in f64
        assert_eq!(Coef::read(1.0 / 3.0, 0.0).mul(Coef::of(3.0)).value(), 1.0);
        assert_eq!(Coef::read(2.0 / 3.0, 0.0).powi(-2).fraction(), Some((9, 4)));
        // a number that is not a fraction stays a float, and so does what it touches
        let r = Coef::read(std::f64::consts::FRAC_1_SQRT_2, 0.0);
        assert!(!r.is_exact() && !r.mul(Coef::read(0.5, 0.0)).is_exact());
        // printing: a fraction with other primes than 2 and 5, a decimal otherwise
        assert_eq!(Coef::read(0.83, 0.0).fraction(), None);
        assert_eq!(Coef::read(29.0 / 81.0, 0.0).fraction(), Some((29, 81)));
        assert_eq!(Coef::of(0.25).fraction(), Some((1, 4)));
    }

    #[test]
    fn overflow_falls_back_to_floating_point() {
        let big = Coef::read(1.0 / 4093.0, 0.0);
        let mut p = Coef::ONE;
        for _ in 0..16 {
            p = p.mul(big);
        }
        // 4093¹⁶ does not fit in i128: the product goes on in floating point
        assert!(!p.is_exact());
        assert!((p.value() - (1.0f64 / 4093.0).powi(16)).abs() <= 1e-14 * p.value());
        assert!(!big.powi(40).is_exact());
    }
}
