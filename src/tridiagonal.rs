//! O(n) solvers for tridiagonal and cyclic tridiagonal systems with vector right-hand sides
//! (the moment equations of cubic splines, one solve for every coordinate at once).
//!
//! The matrix is given row by row by a closure, so nothing of it is stored: for a million
//! unknowns that saves tens of megabytes, whose first touch (page faults) would cost more
//! than the elimination itself.

use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector, SVector};

/// Row `i` of a tridiagonal matrix: `sub · x[i−1] + diag · x[i] + sup · x[i+1]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Row {
    pub sub: f64,
    pub diag: f64,
    pub sup: f64,
}

/// Solves `A x = b` for the `n = out.len()` unknowns into `out`, row `i` of `A` being
/// `row(i)` and of `b` being `rhs(i)`; `corners = Some((top, bottom))` adds `top` at
/// `(0, n−1)` and `bottom` at `(n−1, 0)` (a cyclic system). `sub` of row 0 and `sup` of row
/// `n − 1` are ignored.
///
/// Thomas's algorithm without pivoting, stable for the diagonally dominant matrices of
/// spline moments; for the cyclic case Sherman–Morrison reduces the system to two tridiagonal
/// solves (*Numerical Recipes* §2.7). Fewer than 3 unknowns with corners, where the corners
/// overlap the band, are solved densely.
///
/// Returns the largest `‖xᵢ‖₁` of the solution (NaN if any entry is NaN), gathered while
/// the solution is written, so a caller that bounds its pieces needs no pass of its own.
///
/// # Errors
/// [`Error::SingularSystem`] on a zero or non-finite pivot.
pub(crate) fn solve<const N: usize>(
    row: impl Fn(usize) -> Row,
    rhs: impl Fn(usize) -> SVector<f64, N>,
    corners: Option<(f64, f64)>,
    out: &mut [SVector<f64, N>],
) -> Result<f64> {
    let n = out.len();
    if n == 0 {
        return Ok(0.0);
    }
    let mut scratch = Vec::new();
    let Some((beta, alpha)) = corners else {
        return thomas(&row, &rhs, &mut scratch, out);
    };
    if n < 3 {
        solve_dense(&row, &rhs, (beta, alpha), out)?;
        return Ok(out.iter().fold(0.0, |m, x| nan_max(m, l1(x))));
    }
    // A = B + u vᵀ with u = (γ, 0, …, 0, α)ᵀ, v = (1, 0, …, 0, β/γ)ᵀ, B = A − u vᵀ
    let gamma = -row(0).diag;
    let modified = |i: usize| {
        let mut r = row(i);
        if i == 0 {
            r.diag -= gamma;
        }
        if i == n - 1 {
            r.diag -= alpha * beta / gamma;
        }
        r
    };
    thomas(&modified, &rhs, &mut scratch, out)?;
    let mut z = vec![SVector::<f64, 1>::zeros(); n];
    let u = |i: usize| {
        SVector::<f64, 1>::new(if i == 0 {
            gamma
        } else if i == n - 1 {
            alpha
        } else {
            0.0
        })
    };
    thomas(&modified, &u, &mut scratch, &mut z)?;
    let denom = 1.0 + z[0].x + beta * z[n - 1].x / gamma;
    if denom == 0.0 || !denom.is_finite() {
        return Err(Error::SingularSystem {
            what: "cyclic tridiagonal system",
        });
    }
    let factor = (out[0] + out[n - 1] * (beta / gamma)) / denom;
    let mut largest = 0.0;
    for (x, zi) in out.iter_mut().zip(&z) {
        *x -= factor * zi.x;
        largest = nan_max(largest, l1(x));
    }
    Ok(largest)
}

/// `‖x‖₁`, NaN-propagating (≥ `‖x‖_∞`, and unlike `amax` it keeps a NaN).
#[inline]
pub(crate) fn l1<const N: usize>(x: &SVector<f64, N>) -> f64 {
    x.iter().fold(0.0, |a, c| a + c.abs())
}

/// `max(a, b)`, NaN if either is (`f64::max` would drop a NaN).
#[inline]
fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Dense LU for tiny cyclic systems.
fn solve_dense<const N: usize>(
    row: &impl Fn(usize) -> Row,
    rhs: &impl Fn(usize) -> SVector<f64, N>,
    (top, bottom): (f64, f64),
    out: &mut [SVector<f64, N>],
) -> Result<()> {
    let n = out.len();
    let mut a = DMatrix::<f64>::zeros(n, n);
    for i in 0..n {
        let r = row(i);
        a[(i, i)] += r.diag;
        if i > 0 {
            a[(i, i - 1)] += r.sub;
        }
        if i + 1 < n {
            a[(i, i + 1)] += r.sup;
        }
    }
    a[(0, n - 1)] += top;
    a[(n - 1, 0)] += bottom;
    let lu = a.lu();
    for k in 0..N {
        let b = DVector::from_fn(n, |i, _| rhs(i)[k]);
        let x = lu.solve(&b).ok_or(Error::SingularSystem {
            what: "cyclic system",
        })?;
        for (o, v) in out.iter_mut().zip(x.iter()) {
            o[k] = *v;
        }
    }
    Ok(())
}

/// Thomas's algorithm: forward elimination (the factors `c′ᵢ = supᵢ / pivotᵢ` kept in
/// `scratch`, the eliminated right-hand side in `out`), then back substitution in `out`.
fn thomas<const N: usize>(
    row: &impl Fn(usize) -> Row,
    rhs: &impl Fn(usize) -> SVector<f64, N>,
    scratch: &mut Vec<f64>,
    out: &mut [SVector<f64, N>],
) -> Result<f64> {
    let n = out.len();
    scratch.clear();
    scratch.resize(n, 0.0);
    let c = scratch.as_mut_slice();
    let singular = || Error::SingularSystem {
        what: "tridiagonal system",
    };
    let mut prev_c = 0.0;
    let mut prev_d = SVector::<f64, N>::zeros();
    for i in 0..n {
        let r = row(i);
        let (sub, pivot) = if i == 0 {
            (0.0, r.diag)
        } else {
            (r.sub, r.diag - r.sub * prev_c)
        };
        if pivot == 0.0 || !pivot.is_finite() {
            return Err(singular());
        }
        let inv = 1.0 / pivot;
        prev_c = r.sup * inv;
        prev_d = (rhs(i) - prev_d * sub) * inv;
        c[i] = prev_c;
        out[i] = prev_d;
    }
    let mut largest = l1(&out[n - 1]);
    for i in (0..n - 1).rev() {
        let next = out[i + 1];
        out[i] -= next * c[i];
        largest = nan_max(largest, l1(&out[i]));
    }
    Ok(largest)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    #[test]
    fn plain_and_cyclic_solves_satisfy_the_system() {
        for (n, corners) in [
            (1, None),
            (5, None),
            (2, Some((0.7, -0.7))),
            (7, Some((0.9, -0.6))),
        ] {
            let row = |i: usize| Row {
                sub: 1.0 + 0.1 * i as f64,
                diag: 5.0 + i as f64,
                sup: 0.5 - 0.05 * i as f64,
            };
            let b = |i: usize| Vector2::new(i as f64 - 2.0, (i * i) as f64);
            let mut x = vec![Vector2::zeros(); n];
            solve(row, b, corners, &mut x).expect("dominant system");
            // dense check
            let mut a = DMatrix::<f64>::zeros(n, n);
            for i in 0..n {
                a[(i, i)] += row(i).diag;
                if i > 0 {
                    a[(i, i - 1)] += row(i).sub;
                }
                if i + 1 < n {
                    a[(i, i + 1)] += row(i).sup;
                }
            }
            if let Some((top, bottom)) = corners {
                a[(0, n - 1)] += top;
                a[(n - 1, 0)] += bottom;
            }
            for i in 0..n {
                let got: Vector2<f64> = (0..n).map(|j| x[j] * a[(i, j)]).sum();
                assert!(
                    (got - b(i)).amax() < 1e-13,
                    "n = {n}, row {i}: {got:?} vs {:?}",
                    b(i)
                );
            }
        }
    }
}
