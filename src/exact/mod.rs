//! Exact linear algebra: rational numbers, matrices of them, their solve, inverse and
//! determinant, and polynomials with rational coefficients — so that a derivation whose
//! numbers are rational (the Hermite conditions and their inverse, `M = A C Aᵀ`, the
//! partition of unity of a B-spline basis) is computed, not typed.
//!
//! ```
//! use splinelab::exact::{self, Polynomial, Rational};
//! // the four Hermite conditions on p(s) = c₀ + c₁s + c₂s² + c₃s³, in seed 000's order:
//! // p(0), p′(0), p′(1), p(1)
//! let k = exact::conditions(4, &[(0, 0), (1, 0), (1, 1), (0, 1)])?;
//! let k_inv = exact::inverse(&k)?;
//! // H₀ = 1 − 3s² + 2s³, the first column of K⁻¹
//! assert_eq!(Polynomial::from_column(&k_inv, 0).plain("s"), "1 - 3*s^2 + 2*s^3");
//! assert_eq!(&k * &k_inv, exact::identity(4));
//! # Ok::<(), splinelab::Error>(())
//! ```
//!
//! **One code path.** [`solve`], [`inverse`] and [`determinant`] are written once over the
//! [`Field`] trait, which [`f64`] and [`Rational`] implement: Gaussian elimination with the
//! largest pivot of each column, then back substitution. On [`Rational`] every step is exact, a singular matrix is
//! one with a zero pivot and the residual `A x − b` is checked to be exactly zero; on `f64`
//! the same code is the textbook floating-point solve, a pivot negligible against the
//! column's size is singular and the residual is checked against its rounding bound (the
//! tests compare it with nalgebra's LU).
//!
//! Matrices are nalgebra's [`DMatrix`], so products, transposes and sums are nalgebra's own
//! (`&a * &c * a.transpose()`). [`Rational`] is this crate's name for `num-rational`'s
//! arbitrary-precision `BigRational`: no overflow, and [`from_f64`] converts a
//! floating-point number exactly (its binary fraction).
//!
//! **Bounds.** A matrix of more than [`MAX_DIMENSION`] rows or columns is refused
//! ([`Error::TooLarge`]): exact elimination costs `n³` operations on numbers that grow with
//! `n`.

mod field;
mod polynomial;
mod rational;
mod show;
mod solve;

pub use field::Field;
pub use polynomial::Polynomial;
pub use rational::Rational;
pub use show::{latex, mathml, plain, Written};
pub use solve::{determinant, inverse, solve};

use crate::error::{Error, Result};
use nalgebra::DMatrix;
use num_traits::Zero;

/// The largest number of rows or columns of a matrix the exact routines take.
pub const MAX_DIMENSION: usize = 256;

/// The integer `n` as a [`Rational`].
pub fn int(n: i64) -> Rational {
    Rational::integer(n)
}

/// The fraction `p / q` in lowest terms.
///
/// # Errors
/// [`Error::Degenerate`] if `q` is 0.
pub fn ratio(p: i64, q: i64) -> Result<Rational> {
    Rational::new(p, q)
}

/// The exact value of a finite `f64` (every finite `f64` is a binary fraction).
///
/// # Errors
/// [`Error::NonFinite`] if `x` is NaN or infinite.
pub fn from_f64(x: f64) -> Result<Rational> {
    Rational::from_f64(x)
}

/// Plane points with integer coordinates, exact: `exact::plane_points(&[(0, 0), (1, 3)])`.
pub fn plane_points(pairs: &[(i64, i64)]) -> Vec<nalgebra::Vector2<Rational>> {
    pairs
        .iter()
        .map(|&(x, y)| nalgebra::Vector2::new(int(x), int(y)))
        .collect()
}

/// The nearest `f64` to `q` (`±∞` when `q` is beyond `f64`'s range).
pub fn to_f64(q: &Rational) -> f64 {
    q.to_f64()
}

/// The `n × n` identity matrix over any [`Field`].
pub fn identity<T: Field>(n: usize) -> DMatrix<T> {
    DMatrix::from_fn(n, n, |i, j| if i == j { T::one() } else { T::zero() })
}

/// A matrix of rationals from rows of `(p, q)` fractions, row by row.
///
/// # Errors
/// [`Error::CountMismatch`] if the rows differ in length, [`Error::Degenerate`] if a
/// denominator is 0, [`Error::TooLarge`] beyond [`MAX_DIMENSION`].
pub fn matrix(rows: &[&[(i64, i64)]]) -> Result<DMatrix<Rational>> {
    let cols = rows.first().map_or(0, |r| r.len());
    check_dimension("exact::matrix rows", rows.len())?;
    check_dimension("exact::matrix columns", cols)?;
    let mut m = DMatrix::from_element(rows.len(), cols, Rational::zero());
    for (i, row) in rows.iter().enumerate() {
        if row.len() != cols {
            return Err(Error::CountMismatch {
                what: "exact::matrix: entries of a row",
                expected: cols,
                got: row.len(),
            });
        }
        for (j, &(p, q)) in row.iter().enumerate() {
            m[(i, j)] = ratio(p, q)?;
        }
    }
    Ok(m)
}

/// The exact value of every entry of a finite `f64` matrix.
///
/// # Errors
/// [`Error::NonFinite`] if an entry is not finite, [`Error::TooLarge`] beyond
/// [`MAX_DIMENSION`].
pub fn from_f64_matrix(m: &DMatrix<f64>) -> Result<DMatrix<Rational>> {
    check_dimension("exact::from_f64_matrix rows", m.nrows())?;
    check_dimension("exact::from_f64_matrix columns", m.ncols())?;
    let mut out = DMatrix::from_element(m.nrows(), m.ncols(), Rational::zero());
    for (o, &x) in out.iter_mut().zip(m.iter()) {
        *o = from_f64(x)?;
    }
    Ok(out)
}

/// The matrix of `conditions` on a polynomial of `n` coefficients `c₀ + c₁s + … `: row `k` is
/// the condition `(d, x)` — the `d`-th derivative at `s = x` — applied to each monomial
/// `sʲ`, so that `K c` lists the conditions' values. The four Hermite conditions are
/// `[(0, 0), (0, 1), (1, 0), (1, 1)]` (`p(0), p(1), p′(0), p′(1)`).
///
/// # Errors
/// [`Error::TooLarge`] if `n` or the number of conditions is beyond [`MAX_DIMENSION`].
pub fn conditions(n: usize, conditions: &[(usize, i64)]) -> Result<DMatrix<Rational>> {
    check_dimension("exact::conditions coefficients", n)?;
    let monomials: Vec<Polynomial<Rational>> = (0..n).map(Polynomial::monomial).collect();
    conditions_on(&monomials, conditions)
}

/// The matrix of `conditions` applied to `functions`: entry `(k, j)` is condition `k` — the
/// `d`-th derivative at `x`, given as `(d, x)` — of function `j`. On the monomials it is
/// [`conditions`]' `K`; on a basis that the conditions define, the identity.
///
/// # Errors
/// [`Error::TooLarge`] if there are more than [`MAX_DIMENSION`] functions or conditions.
pub fn conditions_on(
    functions: &[Polynomial<Rational>],
    conditions: &[(usize, i64)],
) -> Result<DMatrix<Rational>> {
    let at: Vec<(usize, Rational)> = conditions.iter().map(|&(d, x)| (d, int(x))).collect();
    conditions_on_at(functions, &at)
}

/// [`conditions_on`] at any rational points: `(d, x)` is the `d`-th derivative at `x`
/// (`exact::conditions_on_at(&h, &[(1, exact::ratio(1, 2)?)])` is `H′(1/2)`).
///
/// # Errors
/// [`Error::TooLarge`] if there are more than [`MAX_DIMENSION`] functions or conditions.
pub fn conditions_on_at(
    functions: &[Polynomial<Rational>],
    conditions: &[(usize, Rational)],
) -> Result<DMatrix<Rational>> {
    check_dimension("exact::conditions_on functions", functions.len())?;
    check_dimension("exact::conditions_on conditions", conditions.len())?;
    let mut k = DMatrix::from_element(conditions.len(), functions.len(), Rational::zero());
    for (row, (d, x)) in conditions.iter().enumerate() {
        for (j, f) in functions.iter().enumerate() {
            k[(row, j)] = f.derivative_n(*d).eval(x);
        }
    }
    Ok(k)
}

/// The Bernstein polynomials `Bᵢⁿ(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ`, `i = 0, …, n`, multiplied out in
/// powers of `t`, exactly.
///
/// # Errors
/// [`Error::TooLarge`] if `n + 1` is beyond [`MAX_DIMENSION`].
pub fn bernstein(n: usize) -> Result<Vec<Polynomial<Rational>>> {
    check_dimension("exact::bernstein functions", n.saturating_add(1))?;
    let t = Polynomial::monomial(1);
    let one_minus_t = Polynomial::new(vec![int(1), int(-1)]);
    let mut binomial = int(1);
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let mut p = Polynomial::constant(binomial.clone());
        for _ in 0..i {
            p = &p * &t;
        }
        for _ in i..n {
            p = &p * &one_minus_t;
        }
        out.push(p);
        // C(n, i + 1) = C(n, i) (n − i) / (i + 1)
        binomial = binomial * int((n - i) as i64) / int(i as i64 + 1);
    }
    Ok(out)
}

/// The polynomials whose coefficients in `basis` are the columns of `m`: polynomial `j` is
/// `Σᵢ mᵢⱼ basisᵢ`. With the Bernstein basis and `A`, the Hermite basis `H = AᵀB`.
///
/// # Errors
/// [`Error::CountMismatch`] if `m` has not one row per basis function.
pub fn in_basis(
    basis: &[Polynomial<Rational>],
    m: &DMatrix<Rational>,
) -> Result<Vec<Polynomial<Rational>>> {
    if m.nrows() != basis.len() {
        return Err(Error::CountMismatch {
            what: "exact::in_basis: rows of the matrix (one per basis function)",
            expected: basis.len(),
            got: m.nrows(),
        });
    }
    Ok((0..m.ncols())
        .map(|j| {
            basis
                .iter()
                .enumerate()
                .fold(Polynomial::new(Vec::new()), |acc, (i, b)| {
                    &acc + &b.scale(&m[(i, j)])
                })
        })
        .collect())
}

/// The `rows × cols` matrix with `1` at `(k, l)` and `0` elsewhere (all zeros if `(k, l)` is
/// outside it): a linear map on matrices is known by its values on these.
///
/// # Errors
/// [`Error::TooLarge`] beyond [`MAX_DIMENSION`].
pub fn unit(rows: usize, cols: usize, k: usize, l: usize) -> Result<DMatrix<Rational>> {
    check_dimension("exact::unit rows", rows)?;
    check_dimension("exact::unit columns", cols)?;
    Ok(DMatrix::from_fn(rows, cols, |i, j| {
        if (i, j) == (k, l) {
            int(1)
        } else {
            Rational::zero()
        }
    }))
}

/// Whether every entry of `m` is `0`, exactly.
pub fn is_zero<T: Field>(m: &DMatrix<T>) -> bool {
    m.iter().all(Zero::is_zero)
}

/// Whether `m` is the identity, exactly.
pub fn is_identity<T: Field>(m: &DMatrix<T>) -> bool {
    m.is_square()
        && m.iter().enumerate().all(|(k, x)| {
            let (j, i) = (k / m.nrows(), k % m.nrows());
            if i == j {
                x.is_one()
            } else {
                x.is_zero()
            }
        })
}

pub(crate) fn check_dimension(what: &'static str, n: usize) -> Result<()> {
    if n > MAX_DIMENSION {
        return Err(Error::TooLarge {
            what,
            got: n,
            max: MAX_DIMENSION,
        });
    }
    Ok(())
}
