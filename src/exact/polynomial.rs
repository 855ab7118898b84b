//! Polynomials in one variable over a [`Field`]: `c₀ + c₁s + … + cₙsⁿ`.

use super::Field;
use nalgebra::DMatrix;
use std::ops::{Add, Mul, Sub};

/// A polynomial `c₀ + c₁s + … + cₙsⁿ` with coefficients in a [`Field`] (exact with
/// [`Rational`](super::Rational)), kept with no trailing zero coefficient (the zero polynomial has none).
#[derive(Debug, Clone, PartialEq)]
pub struct Polynomial<T> {
    coefficients: Vec<T>,
}

impl<T: Field> Polynomial<T> {
    /// The polynomial of the coefficients `c₀, c₁, …` (ascending powers).
    pub fn new(coefficients: Vec<T>) -> Polynomial<T> {
        let mut coefficients = coefficients;
        while coefficients.last().is_some_and(|c| c.is_zero()) {
            coefficients.pop();
        }
        Polynomial { coefficients }
    }

    /// The monomial `sᵏ`.
    pub fn monomial(k: usize) -> Polynomial<T> {
        let mut c = vec![T::zero(); k + 1];
        c[k] = T::one();
        Polynomial { coefficients: c }
    }

    /// The constant `c`.
    pub fn constant(c: T) -> Polynomial<T> {
        Polynomial::new(vec![c])
    }

    /// The polynomial whose coefficients `c₀, c₁, …` are column `col` of `m` (a column of
    /// `K⁻¹` is one basis function in the monomials); the zero polynomial if `col` is out of
    /// range.
    pub fn from_column(m: &DMatrix<T>, col: usize) -> Polynomial<T> {
        if col >= m.ncols() {
            return Polynomial::new(Vec::new());
        }
        Polynomial::new(m.column(col).iter().cloned().collect())
    }

    /// The coefficients `c₀, c₁, …, cₙ` (empty for the zero polynomial).
    pub fn coefficients(&self) -> &[T] {
        &self.coefficients
    }

    /// The degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coefficients.len().checked_sub(1)
    }

    /// The value at `x` (Horner's rule).
    pub fn eval(&self, x: &T) -> T {
        self.coefficients
            .iter()
            .rev()
            .fold(T::zero(), |acc, c| acc * x.clone() + c.clone())
    }

    /// The derivative `c₁ + 2c₂s + … + n cₙ sⁿ⁻¹`.
    pub fn derivative(&self) -> Polynomial<T> {
        let mut k = T::zero();
        let c = self
            .coefficients
            .iter()
            .map(|c| {
                let term = k.clone() * c.clone();
                k = k.clone() + T::one();
                term
            })
            .skip(1)
            .collect();
        Polynomial::new(c)
    }

    /// The `d`-th derivative (the polynomial itself for `d = 0`).
    pub fn derivative_n(&self, d: usize) -> Polynomial<T> {
        (0..d.min(self.coefficients.len())).fold(self.clone(), |p, _| p.derivative())
    }

    /// The composition `p(q(s))` (Horner's rule on polynomials): `p.compose(&(1 − s))` is
    /// `p(1 − s)`.
    pub fn compose(&self, inner: &Polynomial<T>) -> Polynomial<T> {
        self.coefficients
            .iter()
            .rev()
            .fold(Polynomial::new(Vec::new()), |acc, c| {
                &(&acc * inner) + &Polynomial::constant(c.clone())
            })
    }

    /// `c · p`.
    pub fn scale(&self, c: &T) -> Polynomial<T> {
        Polynomial::new(
            self.coefficients
                .iter()
                .map(|x| x.clone() * c.clone())
                .collect(),
        )
    }
}

fn zip_with<T: Field>(a: &[T], b: &[T], f: impl Fn(T, T) -> T) -> Vec<T> {
    (0..a.len().max(b.len()))
        .map(|i| {
            let x = a.get(i).cloned().unwrap_or_else(T::zero);
            let y = b.get(i).cloned().unwrap_or_else(T::zero);
            f(x, y)
        })
        .collect()
}

impl<T: Field> Add for &Polynomial<T> {
    type Output = Polynomial<T>;
    fn add(self, rhs: &Polynomial<T>) -> Polynomial<T> {
        Polynomial::new(zip_with(&self.coefficients, &rhs.coefficients, |x, y| {
            x + y
        }))
    }
}

impl<T: Field> Sub for &Polynomial<T> {
    type Output = Polynomial<T>;
    fn sub(self, rhs: &Polynomial<T>) -> Polynomial<T> {
        Polynomial::new(zip_with(&self.coefficients, &rhs.coefficients, |x, y| {
            x - y
        }))
    }
}

impl<T: Field> Mul for &Polynomial<T> {
    type Output = Polynomial<T>;
    fn mul(self, rhs: &Polynomial<T>) -> Polynomial<T> {
        let (a, b) = (&self.coefficients, &rhs.coefficients);
        if a.is_empty() || b.is_empty() {
            return Polynomial::new(Vec::new());
        }
        let mut c = vec![T::zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                c[i + j] = c[i + j].clone() + x.clone() * y.clone();
            }
        }
        Polynomial::new(c)
    }
}
