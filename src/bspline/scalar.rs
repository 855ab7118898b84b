//! The numbers the Cox–de Boor recurrence runs on: every dual number (values, derivatives, and
//! under a symbolic trace, formulas) and the exact [`Rational`] (the slides' fractions).

use crate::exact::Rational;
use num_dual::DualNum;
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::ops::{AddAssign, Mul};

/// A number the recurrence
/// `N_{i,q}(t) = (t − tᵢ)/(t_{i+q} − tᵢ) N_{i,q−1}(t) + (t_{i+q+1} − t)/(t_{i+q+1} − t_{i+1}) N_{i+1,q−1}(t)`
/// is written over ([`crate::BSplineBasis::cox_de_boor`]): sums and products, `t` against a
/// knot, a division by a knot difference, and the comparison with the knots that picks the
/// degree-0 function that is one. Knots stay `f64`; a [`Rational`] takes their exact values.
pub trait KnotScalar: Clone + Zero + One + AddAssign + Mul<Output = Self> {
    /// `t − k`.
    fn minus_knot(&self, k: f64) -> Self;
    /// `k − t`.
    fn knot_minus(&self, k: f64) -> Self;
    /// `self / d` for a knot difference `d > 0`.
    fn over(&self, d: f64) -> Self;
    /// The value as an `f64` (the real part of a dual number), for checks.
    fn value(&self) -> f64;
    /// `by(order)` where `order(k)` compares `t` with the knot `k`, and `condition(x)` the
    /// values on which the answer holds, for a value `x` of `t` (recorded under a symbolic
    /// trace, so that the formulas claim the piece the recurrence picked).
    fn locate<R>(
        &self,
        by: impl FnOnce(&dyn Fn(f64) -> Ordering) -> R,
        condition: impl FnOnce(f64) -> crate::branch::Condition,
    ) -> R;
}

impl<D: DualNum<Primitive = f64> + Copy> KnotScalar for D {
    fn minus_knot(&self, k: f64) -> Self {
        *self - k
    }

    fn knot_minus(&self, k: f64) -> Self {
        -*self + k
    }

    fn over(&self, d: f64) -> Self {
        *self / d
    }

    fn value(&self) -> f64 {
        self.re()
    }

    fn locate<R>(
        &self,
        by: impl FnOnce(&dyn Fn(f64) -> Ordering) -> R,
        condition: impl FnOnce(f64) -> crate::branch::Condition,
    ) -> R {
        crate::branch::choose(self, |x| {
            // a NaN compares as beyond every knot: no degree-0 function is one
            let answer = by(&|k| x.partial_cmp(&k).unwrap_or(Ordering::Greater));
            (answer, condition(x))
        })
    }
}

/// The exact value of a knot: knots are finite (checked by [`crate::KnotVector`]).
fn exact(k: f64) -> Rational {
    Rational::from_f64(k).unwrap_or_else(|_| Rational::zero())
}

impl KnotScalar for Rational {
    fn minus_knot(&self, k: f64) -> Self {
        self - &exact(k)
    }

    fn knot_minus(&self, k: f64) -> Self {
        &exact(k) - self
    }

    fn over(&self, d: f64) -> Self {
        self / &exact(d)
    }

    fn value(&self) -> f64 {
        self.to_f64()
    }

    fn locate<R>(
        &self,
        by: impl FnOnce(&dyn Fn(f64) -> Ordering) -> R,
        _condition: impl FnOnce(f64) -> crate::branch::Condition,
    ) -> R {
        by(&|k| self.cmp(&exact(k)))
    }
}
