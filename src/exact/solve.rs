//! Gaussian elimination over any [`Field`]: one code for `f64` and for exact rationals.

use super::{check_dimension, Field};
use crate::error::{Error, Result};
use nalgebra::DMatrix;

/// The solution `X` of `A X = B` (`A` square and invertible, `B` with as many rows as `A`).
///
/// Gaussian elimination, the largest pivot of each column first (`|x|` by
/// [`Field::size`]); then the residual `A X − B` is checked entry by entry ([`Field::is_negligible`]
/// against `Σₖ |aᵢₖ| · maxₖ |xₖⱼ| + |bᵢⱼ|`): exactly zero for rationals, within rounding for `f64`.
///
/// # Errors
/// [`Error::ShapeMismatch`] if `A` is not square or `B` has another number of rows;
/// [`Error::TooLarge`] beyond [`super::MAX_DIMENSION`]; [`Error::NonFinite`] if an `f64` entry
/// is not finite; [`Error::SingularSystem`] if a pivot is zero (negligible, for `f64`);
/// [`Error::IllConditioned`] if the residual check fails; [`Error::Overflow`] if an `f64`
/// solution is not finite.
pub fn solve<T: Field>(a: &DMatrix<T>, b: &DMatrix<T>) -> Result<DMatrix<T>> {
    check_square(a)?;
    if b.nrows() != a.nrows() {
        return Err(Error::ShapeMismatch {
            left_rows: a.nrows(),
            left_cols: a.ncols(),
            right_rows: b.nrows(),
            right_cols: b.ncols(),
        });
    }
    check_dimension("exact::solve right-hand sides", b.ncols())?;
    check_finite("exact::solve matrix", a)?;
    check_finite("exact::solve right-hand side", b)?;
    let x = eliminate(a.clone(), b.clone())?;
    if !x.iter().all(Field::is_finite) {
        return Err(Error::Overflow {
            what: "exact::solve solution",
            value: f64::INFINITY,
        });
    }
    check_residual(a, &x, b)?;
    Ok(x)
}

/// The inverse `A⁻¹`: [`solve`] with `B = I`.
///
/// # Errors
/// As [`solve`].
pub fn inverse<T: Field>(a: &DMatrix<T>) -> Result<DMatrix<T>> {
    check_square(a)?;
    solve(a, &super::identity(a.nrows()))
}

/// The determinant of a square matrix, by the same elimination (the product of the pivots,
/// its sign flipped by each row swap): exact for rationals; `0` when a column has no pivot
/// (for `f64`, none above rounding).
///
/// # Errors
/// [`Error::ShapeMismatch`] if `A` is not square, [`Error::TooLarge`] beyond
/// [`super::MAX_DIMENSION`], [`Error::NonFinite`] if an `f64` entry is not finite,
/// [`Error::Overflow`] if an `f64` determinant overflows.
pub fn determinant<T: Field>(a: &DMatrix<T>) -> Result<T> {
    check_square(a)?;
    check_finite("exact::determinant matrix", a)?;
    let mut u = a.clone();
    let mut none = DMatrix::from_element(a.nrows(), 0, T::zero());
    let Some(swaps) = forward(&mut u, &mut none) else {
        return Ok(T::zero());
    };
    let mut det = if swaps % 2 == 0 { T::one() } else { -T::one() };
    for i in 0..u.nrows() {
        det = det * u[(i, i)].clone();
    }
    if !det.is_finite() {
        return Err(Error::Overflow {
            what: "exact::determinant",
            value: f64::INFINITY,
        });
    }
    Ok(det)
}

/// Reduces `[A | B]` to `[U | B′]` (`U` upper triangular) by Gaussian elimination, the
/// largest pivot of each column first; the number of row swaps, or `None` when a column has
/// no pivot (zero; for `f64`, rounding residue of the column as given).
fn forward<T: Field>(a: &mut DMatrix<T>, b: &mut DMatrix<T>) -> Option<usize> {
    let n = a.nrows();
    let scales: Vec<f64> = (0..n).map(|c| column_scale(a, c)).collect();
    let mut swaps = 0;
    for col in 0..n {
        let p = pivot_row(a, col, scales[col])?;
        if p != col {
            a.swap_rows(p, col);
            b.swap_rows(p, col);
            swaps += 1;
        }
        let pivot = a[(col, col)].clone();
        for r in col + 1..n {
            let f = a[(r, col)].clone() / pivot.clone();
            if f.is_zero() {
                continue;
            }
            a[(r, col)] = T::zero();
            for c in col + 1..n {
                let v = a[(col, c)].clone();
                a[(r, c)] = a[(r, c)].clone() - f.clone() * v;
            }
            for c in 0..b.ncols() {
                let v = b[(col, c)].clone();
                b[(r, c)] = b[(r, c)].clone() - f.clone() * v;
            }
        }
    }
    Some(swaps)
}

/// `X` of `A X = B`: forward elimination, then back substitution.
fn eliminate<T: Field>(mut a: DMatrix<T>, mut b: DMatrix<T>) -> Result<DMatrix<T>> {
    forward(&mut a, &mut b).ok_or(Error::SingularSystem {
        what: "exact::solve matrix",
    })?;
    let n = a.nrows();
    for c in 0..b.ncols() {
        for i in (0..n).rev() {
            let mut v = b[(i, c)].clone();
            for k in i + 1..n {
                v = v - a[(i, k)].clone() * b[(k, c)].clone();
            }
            b[(i, c)] = v / a[(i, i)].clone();
        }
    }
    Ok(b)
}

/// The row at or below `col` with the largest entry in column `col`, unless that entry is
/// zero (negligible against the column's original size `scale`, for `f64`).
fn pivot_row<T: Field>(m: &DMatrix<T>, col: usize, scale: f64) -> Option<usize> {
    let n = m.nrows();
    let best = (col..n).max_by(|&i, &j| m[(i, col)].size().total_cmp(&m[(j, col)].size()))?;
    // the pivot is measured against the column as given, not as elimination left it: a
    // column of zeros, or of rounding residue only, has no pivot
    (!m[(best, col)].is_negligible(scale, n)).then_some(best)
}

/// `Σᵢ |aᵢⱼ|` of column `j`: the size its eliminated entries are rounding residue of.
fn column_scale<T: Field>(a: &DMatrix<T>, j: usize) -> f64 {
    a.column(j).iter().map(Field::size).sum()
}

/// `A X − B` is zero entry by entry, against `Σₖ |aᵢₖ| · maxₖ |xₖⱼ| + |bᵢⱼ|`.
fn check_residual<T: Field>(a: &DMatrix<T>, x: &DMatrix<T>, b: &DMatrix<T>) -> Result<()> {
    let n = a.nrows();
    for j in 0..b.ncols() {
        for i in 0..n {
            let mut r = -b[(i, j)].clone();
            let (mut row, mut largest) = (0.0, 0.0f64);
            for k in 0..n {
                r = r + a[(i, k)].clone() * x[(k, j)].clone();
                row += a[(i, k)].size();
                largest = largest.max(x[(k, j)].size());
            }
            // normwise by row: partial pivoting bounds the residual by the row's size times
            // the solution's, up to the elimination's growth
            let scale = row * largest + b[(i, j)].size();
            // the bound of a solve with a backward-stable elimination: the n-term sum's
            // rounding, times n for the elimination's growth
            if !r.is_negligible(scale, n * n + 1) {
                return Err(Error::IllConditioned {
                    what: "exact::solve",
                    residual: r.size() / scale.max(f64::MIN_POSITIVE),
                    tolerance: 4.0 * ((n * n + 1) as f64) * f64::EPSILON,
                });
            }
        }
    }
    Ok(())
}

fn check_square<T>(a: &DMatrix<T>) -> Result<()> {
    check_dimension("exact: matrix rows", a.nrows())?;
    check_dimension("exact: matrix columns", a.ncols())?;
    if !a.is_square() {
        return Err(Error::ShapeMismatch {
            left_rows: a.nrows(),
            left_cols: a.ncols(),
            right_rows: a.ncols(),
            right_cols: a.nrows(),
        });
    }
    Ok(())
}

fn check_finite<T: Field>(what: &'static str, m: &DMatrix<T>) -> Result<()> {
    match m.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(Error::NonFinite {
            what,
            value: x.size(),
        }),
        None => Ok(()),
    }
}
