//! The arithmetic and num-dual traits of [`Expr`]: every operation builds a node (simplified
//! on construction) and carries the numeric value along, so that generic code that branches
//! on `re()` takes the numeric path's branch (and the branch is recorded).

use super::expr::{Expr, Func};
use num_dual::{DualNum, DualStruct, Mappable};
use num_traits::{FromPrimitive, Inv, Num, One, Signed, Zero};
use std::fmt;
use std::iter::{Product, Sum};
use std::ops::{
    Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Rem, RemAssign, Sub, SubAssign,
};

macro_rules! binary {
    ($trait:ident, $method:ident, $assign:ident, $assign_method:ident, $build:expr) => {
        impl $trait for Expr {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr {
                $build(self, rhs)
            }
        }
        impl<'a> $trait<&'a Expr> for Expr {
            type Output = Expr;
            fn $method(self, rhs: &'a Expr) -> Expr {
                $build(self, *rhs)
            }
        }
        impl $trait<f64> for Expr {
            type Output = Expr;
            fn $method(self, rhs: f64) -> Expr {
                $build(self, Expr::constant(rhs))
            }
        }
        impl $trait<Expr> for f64 {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr {
                $build(Expr::constant(self), rhs)
            }
        }
        impl $assign for Expr {
            fn $assign_method(&mut self, rhs: Expr) {
                *self = $build(*self, rhs);
            }
        }
        impl $assign<f64> for Expr {
            fn $assign_method(&mut self, rhs: f64) {
                *self = $build(*self, Expr::constant(rhs));
            }
        }
    };
}

binary!(Add, add, AddAssign, add_assign, Expr::add);
binary!(Sub, sub, SubAssign, sub_assign, Expr::sub);
binary!(Mul, mul, MulAssign, mul_assign, Expr::mul);
binary!(Div, div, DivAssign, div_assign, Expr::div);
binary!(Rem, rem, RemAssign, rem_assign, |a: Expr, b: Expr| {
    // no formula: an opaque node with the numeric value (documented in `crate::symbolic`)
    Expr::opaque("rem", a, a.value % b.value)
});

impl Neg for Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        Expr::neg(self)
    }
}

impl Zero for Expr {
    fn zero() -> Expr {
        Expr::constant(0.0)
    }
    fn is_zero(&self) -> bool {
        self.as_constant() == Some(0.0)
    }
}

impl One for Expr {
    fn one() -> Expr {
        Expr::constant(1.0)
    }
}

impl Num for Expr {
    type FromStrRadixErr = &'static str;
    /// Parsing has no formula: always an error (documented).
    fn from_str_radix(_: &str, _: u32) -> Result<Expr, &'static str> {
        Err("expressions are not parsed from strings")
    }
}

impl Signed for Expr {
    fn abs(&self) -> Expr {
        Expr::apply(Func::Abs, *self)
    }
    fn abs_sub(&self, other: &Expr) -> Expr {
        let d = *self - *other;
        d.branch(if d.value > 0.0 { "> 0" } else { "≤ 0" });
        if d.value > 0.0 {
            d
        } else {
            Expr::constant(0.0)
        }
    }
    fn signum(&self) -> Expr {
        self.branch(if self.value > 0.0 {
            "> 0"
        } else if self.value < 0.0 {
            "< 0"
        } else {
            "= 0"
        });
        Expr::constant(self.value.signum())
    }
    fn is_positive(&self) -> bool {
        self.branch(if self.value > 0.0 { "> 0" } else { "≤ 0" });
        self.value > 0.0
    }
    fn is_negative(&self) -> bool {
        self.branch(if self.value < 0.0 { "< 0" } else { "≥ 0" });
        self.value < 0.0
    }
}

impl Inv for Expr {
    type Output = Expr;
    fn inv(self) -> Expr {
        Expr::div(Expr::constant(1.0), self)
    }
}

impl Sum for Expr {
    fn sum<I: Iterator<Item = Expr>>(iter: I) -> Expr {
        iter.fold(Expr::constant(0.0), Expr::add)
    }
}

impl<'a> Sum<&'a Expr> for Expr {
    fn sum<I: Iterator<Item = &'a Expr>>(iter: I) -> Expr {
        iter.fold(Expr::constant(0.0), |a, b| Expr::add(a, *b))
    }
}

impl Product for Expr {
    fn product<I: Iterator<Item = Expr>>(iter: I) -> Expr {
        iter.fold(Expr::constant(1.0), Expr::mul)
    }
}

impl<'a> Product<&'a Expr> for Expr {
    fn product<I: Iterator<Item = &'a Expr>>(iter: I) -> Expr {
        iter.fold(Expr::constant(1.0), |a, b| Expr::mul(a, *b))
    }
}

impl FromPrimitive for Expr {
    fn from_i64(n: i64) -> Option<Expr> {
        Some(Expr::constant(n as f64))
    }
    fn from_u64(n: u64) -> Option<Expr> {
        Some(Expr::constant(n as f64))
    }
    fn from_f64(x: f64) -> Option<Expr> {
        Some(Expr::constant(x))
    }
}

impl From<f64> for Expr {
    fn from(x: f64) -> Expr {
        Expr::constant(x)
    }
}

impl DualStruct for Expr {
    type Real = f64;
    type Inner = Expr;
    /// The value at the trace point; the read is recorded ([`crate::symbolic`]: a formula
    /// whose code read a value other than through a recorded piece holds at the trace point
    /// only).
    fn re(&self) -> f64 {
        super::expr::note_read(self.id, self.generation, self.value);
        self.value
    }
    fn from_inner(inner: &Expr) -> Expr {
        *inner
    }
}

impl Mappable<Expr> for Expr {
    type Output<O> = O;
    fn map_dual<M: Fn(Expr) -> O, O>(self, f: M) -> O {
        f(self)
    }
}

/// Comparisons follow the numeric values at the trace point (and are recorded as branches).
impl PartialEq for Expr {
    fn eq(&self, other: &Expr) -> bool {
        let d = Expr::sub(*self, *other);
        d.branch(if d.value == 0.0 { "= 0" } else { "≠ 0" });
        self.value == other.value
    }
}

impl PartialOrd for Expr {
    fn partial_cmp(&self, other: &Expr) -> Option<std::cmp::Ordering> {
        let d = Expr::sub(*self, *other);
        d.branch(sign_word(d.value));
        self.value.partial_cmp(&other.value)
    }
}

impl PartialEq<f64> for Expr {
    fn eq(&self, other: &f64) -> bool {
        let d = Expr::sub(*self, Expr::constant(*other));
        d.branch(if d.value == 0.0 { "= 0" } else { "≠ 0" });
        self.value == *other
    }
}

impl PartialOrd<f64> for Expr {
    fn partial_cmp(&self, other: &f64) -> Option<std::cmp::Ordering> {
        let d = Expr::sub(*self, Expr::constant(*other));
        d.branch(sign_word(d.value));
        self.value.partial_cmp(other)
    }
}

fn sign_word(x: f64) -> &'static str {
    if x > 0.0 {
        "> 0"
    } else if x < 0.0 {
        "< 0"
    } else {
        "= 0"
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&super::print::plain(self))
    }
}

/// The `DualNum` functions that are one [`Func`] node each: `fn sin(&self) -> Expr`, ….
macro_rules! applied {
    ($($name:ident => $func:ident,)*) => {
        $(
            fn $name(&self) -> Expr {
                Expr::apply(Func::$func, *self)
            }
        )*
    };
}

impl DualNum for Expr {
    applied! {
        sqrt => Sqrt,
        cbrt => Cbrt,
        exp => Exp,
        ln => Ln,
        sin => Sin,
        cos => Cos,
        tan => Tan,
        asin => Asin,
        acos => Acos,
        atan => Atan,
        sinh => Sinh,
        cosh => Cosh,
        tanh => Tanh,
        asinh => Asinh,
        acosh => Acosh,
        atanh => Atanh,
        sph_j0 => SphJ0,
        sph_j1 => SphJ1,
        sph_j2 => SphJ2,
    }
    type Primitive = f64;
    const NDERIV: usize = 0;
    type InnerDual = Expr;

    fn from_re(re: Expr) -> Expr {
        re
    }
    fn scale(self, factor: &Expr) -> Expr {
        self * *factor
    }
    fn recip(&self) -> Expr {
        Expr::div(Expr::constant(1.0), *self)
    }
    fn powi(&self, n: i32) -> Expr {
        Expr::powi(*self, n)
    }
    fn powf(&self, n: f64) -> Expr {
        Expr::powf(*self, n)
    }
    fn exp2(&self) -> Expr {
        Expr::pow(Expr::constant(2.0), *self)
    }
    fn exp_m1(&self) -> Expr {
        Expr::sub(Expr::apply(Func::Exp, *self), Expr::constant(1.0))
    }
    fn log(&self, base: f64) -> Expr {
        Expr::div(Expr::apply(Func::Ln, *self), Expr::constant(base.ln()))
    }
    fn log2(&self) -> Expr {
        self.log(2.0)
    }
    fn log10(&self) -> Expr {
        self.log(10.0)
    }
    fn ln_1p(&self) -> Expr {
        Expr::apply(Func::Ln, Expr::add(Expr::constant(1.0), *self))
    }
    fn sin_cos(&self) -> (Expr, Expr) {
        (self.sin(), self.cos())
    }
    fn atan2(&self, other: Expr) -> Expr {
        Expr::atan2(*self, other)
    }
}
