//! The numbers the exact routines run on: a field with a size to choose pivots by.

use super::Rational;
use num_traits::{One, Zero};
use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A field the solve, inverse and determinant are written over: [`f64`] (rounded) and
/// [`Rational`] (exact). What differs between them is said here and nowhere else: how large a
/// pivot is, and when a number that should be zero counts as zero.
pub trait Field:
    Clone
    + PartialEq
    + Debug
    + 'static
    + Zero
    + One
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The size pivots are chosen by (the largest first): `|x|` as an `f64` (beyond `f64`'s
    /// range infinite, never NaN, so pivots still compare).
    fn size(&self) -> f64 {
        self.to_f64().abs()
    }

    /// Whether `self`, computed as a sum of terms of total size `scale` over `n` steps, is zero:
    /// exactly zero for exact numbers, within the rounding bound `n·ε·scale` for `f64`.
    fn is_negligible(&self, scale: f64, n: usize) -> bool;

    /// Whether the number is finite (always, for exact numbers).
    fn is_finite(&self) -> bool;

    /// Whether the number is greater than zero.
    fn is_positive(&self) -> bool;

    /// The nearest `f64` (for messages and comparisons with rounded results).
    fn to_f64(&self) -> f64;

    /// The value of a finite `f64` in this field (exact for [`Rational`]).
    ///
    /// # Errors
    /// [`crate::Error::NonFinite`] for NaN or an infinity.
    fn from_f64(x: f64) -> crate::error::Result<Self>;
}

impl Field for f64 {
    fn is_negligible(&self, scale: f64, n: usize) -> bool {
        // the standard backward-error bound of an n-term sum, with a safety factor of 4
        self.abs() <= 4.0 * (n.max(1) as f64) * f64::EPSILON * scale
    }

    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }

    fn is_positive(&self) -> bool {
        *self > 0.0
    }

    fn to_f64(&self) -> f64 {
        *self
    }

    fn from_f64(x: f64) -> crate::error::Result<Self> {
        crate::error::finite("f64 value", x)
    }
}

impl Field for Rational {
    fn is_negligible(&self, _scale: f64, _n: usize) -> bool {
        self.is_zero()
    }

    fn is_finite(&self) -> bool {
        true
    }

    fn is_positive(&self) -> bool {
        *self > Rational::zero()
    }

    fn to_f64(&self) -> f64 {
        Rational::to_f64(self)
    }

    fn from_f64(x: f64) -> crate::error::Result<Self> {
        Rational::from_f64(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rational_is_negligible_only_at_zero() {
        let tiny = Rational::from(num_rational::BigRational::new(
            1.into(),
            num_bigint::BigInt::from(10).pow(400),
        ));
        assert!(!tiny.is_negligible(1.0, 4));
        assert!(Rational::zero().is_negligible(1.0, 4));
        assert!(1e-17.is_negligible(1.0, 4));
        assert!(!1e-14.is_negligible(1.0, 4));
    }
}
