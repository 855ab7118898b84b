//! The exact rational number of the derivations: a named type over `num-rational`'s
//! arbitrary-precision `BigRational`.

use crate::error::{Error, Result};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A rational number of arbitrary precision, always in lowest terms with a positive
/// denominator: no overflow, no rounding.
///
/// A type of this crate (not a re-exported alias), so that a notebook's kernel and a user's
/// crate name it as `splinelab::exact::Rational`. Arithmetic is `+ − × ÷` and their
/// assignments, on values and references; `a / b` with `b = 0` panics, as integer division
/// does ([`Rational::checked_div`] returns `None` instead). The library's own routines never
/// divide by zero.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Rational(BigRational);

impl Rational {
    /// The integer `n`.
    pub fn integer(n: i64) -> Rational {
        Rational(BigRational::from_integer(n.into()))
    }

    /// The fraction `p / q` in lowest terms.
    ///
    /// # Errors
    /// [`Error::Degenerate`] if `q` is 0.
    pub fn new(p: i64, q: i64) -> Result<Rational> {
        if q == 0 {
            return Err(Error::Degenerate {
                what: "exact::Rational::new",
                reason: "the denominator is 0",
            });
        }
        Ok(Rational(BigRational::new(p.into(), q.into())))
    }

    /// The exact value of a finite `f64` (every finite `f64` is a binary fraction).
    ///
    /// # Errors
    /// [`Error::NonFinite`] if `x` is NaN or infinite.
    pub fn from_f64(x: f64) -> Result<Rational> {
        BigRational::from_float(x)
            .map(Rational)
            .ok_or(Error::NonFinite {
                what: "exact::Rational::from_f64",
                value: x,
            })
    }

    /// The nearest `f64` (`±∞` beyond `f64`'s range).
    pub fn to_f64(&self) -> f64 {
        self.0.to_f64().unwrap_or(if self.0.is_negative() {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        })
    }

    /// The numerator (its sign is the number's).
    pub fn numer(&self) -> &BigInt {
        self.0.numer()
    }

    /// The denominator (positive).
    pub fn denom(&self) -> &BigInt {
        self.0.denom()
    }

    /// Whether the number is an integer.
    pub fn is_integer(&self) -> bool {
        self.0.is_integer()
    }

    /// Whether the number is below 0.
    pub fn is_negative(&self) -> bool {
        self.0.is_negative()
    }

    /// `|x|`.
    pub fn abs(&self) -> Rational {
        Rational(self.0.abs())
    }

    /// `self / rhs`, or `None` if `rhs` is 0.
    pub fn checked_div(&self, rhs: &Rational) -> Option<Rational> {
        (!rhs.0.is_zero()).then(|| Rational(&self.0 / &rhs.0))
    }

    /// The `num-rational` value.
    pub fn as_big_rational(&self) -> &BigRational {
        &self.0
    }
}

impl From<BigRational> for Rational {
    fn from(q: BigRational) -> Rational {
        Rational(q)
    }
}

impl From<BigInt> for Rational {
    fn from(n: BigInt) -> Rational {
        Rational(BigRational::from_integer(n))
    }
}

impl From<i64> for Rational {
    fn from(n: i64) -> Rational {
        Rational::integer(n)
    }
}

impl From<Rational> for BigRational {
    fn from(q: Rational) -> BigRational {
        q.0
    }
}

/// `-3/2`, `4`: as the fraction reads.
impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

/// As [`fmt::Display`]: a matrix of rationals prints its fractions.
impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl Zero for Rational {
    fn zero() -> Rational {
        Rational(BigRational::zero())
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
}

impl One for Rational {
    fn one() -> Rational {
        Rational(BigRational::one())
    }
}

impl Neg for Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        Rational(-self.0)
    }
}

impl Neg for &Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        Rational(-&self.0)
    }
}

/// `+ − × ÷` for values and references, and their assignments, from `num-rational`'s.
macro_rules! arithmetic {
    ($($op:ident $method:ident $assign:ident $assign_method:ident;)*) => {$(
        impl $op for Rational {
            type Output = Rational;
            fn $method(self, rhs: Rational) -> Rational {
                Rational($op::$method(self.0, rhs.0))
            }
        }
        impl $op<&Rational> for &Rational {
            type Output = Rational;
            fn $method(self, rhs: &Rational) -> Rational {
                Rational($op::$method(&self.0, &rhs.0))
            }
        }
        impl $op<&Rational> for Rational {
            type Output = Rational;
            fn $method(self, rhs: &Rational) -> Rational {
                Rational($op::$method(self.0, &rhs.0))
            }
        }
        impl $assign for Rational {
            fn $assign_method(&mut self, rhs: Rational) {
                $assign::$assign_method(&mut self.0, rhs.0);
            }
        }
        impl $assign<&Rational> for Rational {
            fn $assign_method(&mut self, rhs: &Rational) {
                $assign::$assign_method(&mut self.0, &rhs.0);
            }
        }
    )*};
}

arithmetic! {
    Add add AddAssign add_assign;
    Sub sub SubAssign sub_assign;
    Mul mul MulAssign mul_assign;
    Div div DivAssign div_assign;
}
