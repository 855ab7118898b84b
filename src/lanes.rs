//! `G` independent numbers computed together: the arithmetic of the batch paths that evaluate
//! one formula at several points at once (each point its own data), so that the processor
//! works on the points side by side — vector instructions where it has them, overlapping
//! divisions and memory loads where not — instead of one after the other.
//!
//! A formula generic over its number and knot types (the B-spline triangle,
//! `bspline::basis::triangle`) runs on `Lanes` unchanged: lane `g` of every result is the
//! formula at lane `g` of the inputs, operation for operation as in `f64` (each lane is rounded
//! as the scalar operation would round it), so a batch on lanes equals the point-by-point
//! evaluation bit for bit.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// Points a batch path evaluates side by side once it meets a sparse run (the B-spline's
/// `walk_spans`, the cubic spline's batch): their intervals are found first (the loads of all
/// of them in flight at once), then their values computed together ([`Lanes`]), so that
/// independent points overlap instead of each waiting on the memory its interval needs.
pub(crate) const SPARSE_BLOCK: usize = 8;

/// `G` numbers side by side; every operation acts lane by lane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Lanes<const G: usize>(pub(crate) [f64; G]);

impl<const G: usize> Lanes<G> {
    /// Every lane `x`.
    #[inline(always)]
    pub(crate) fn splat(x: f64) -> Self {
        Lanes([x; G])
    }

    /// Lane `g` of each of `v`: one point's values out of a batch.
    #[inline(always)]
    pub(crate) fn lane<const L: usize>(v: &[Self; L], g: usize) -> [f64; L] {
        std::array::from_fn(|i| v[i].0[g])
    }
}

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl<const G: usize> $tr for Lanes<G> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, rhs: Self) -> Self {
                Lanes(std::array::from_fn(|g| self.0[g] $op rhs.0[g]))
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);
lanewise!(Div, div, /);

impl<const G: usize> Neg for Lanes<G> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Lanes(self.0.map(|x| -x))
    }
}

/// `x / v` in every lane (a reciprocal of each lane for `x = 1`).
impl<const G: usize> Div<Lanes<G>> for f64 {
    type Output = Lanes<G>;
    #[inline(always)]
    fn div(self, rhs: Lanes<G>) -> Lanes<G> {
        Lanes::splat(self) / rhs
    }
}

impl<const G: usize> num_traits::Zero for Lanes<G> {
    fn zero() -> Self {
        Lanes::splat(0.0)
    }
    fn is_zero(&self) -> bool {
        self.0.iter().all(|&x| x == 0.0)
    }
}

impl<const G: usize> num_traits::One for Lanes<G> {
    fn one() -> Self {
        Lanes::splat(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_operation_acts_lane_by_lane_as_f64() {
        let a = Lanes([1.5, -2.0, 1e-300, 3.0]);
        let b = Lanes([0.1, 7.0, 1e10, -0.0]);
        for g in 0..4 {
            let (x, y) = (a.0[g], b.0[g]);
            assert_eq!((a + b).0[g].to_bits(), (x + y).to_bits());
            assert_eq!((a - b).0[g].to_bits(), (x - y).to_bits());
            assert_eq!((a * b).0[g].to_bits(), (x * y).to_bits());
            assert_eq!((a / b).0[g].to_bits(), (x / y).to_bits());
            assert_eq!((1.0 / b).0[g].to_bits(), (1.0 / y).to_bits());
            assert_eq!((-a).0[g].to_bits(), (-x).to_bits());
        }
        assert_eq!(Lanes::lane(&[a, b], 1), [-2.0, 7.0]);
    }
}
