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

/// A tridiagonal system given row by row (nothing of it stored), for [`solve_twisted`]:
/// implementations mark both methods `#[inline(always)]`, so the solver's loops see the
/// arithmetic of the rows.
pub(crate) trait Band<const N: usize>: Sync {
    /// Row `i` of the matrix (`sub` of row 0 and `sup` of the last row are ignored).
    fn row(&self, i: usize) -> Row;
    /// Entry `i` of the right-hand side.
    fn rhs(&self, i: usize) -> SVector<f64, N>;
}

/// Unknowns from which [`solve_twisted`] runs its two halves on two threads (below, one
/// thread runs both: a thread costs tens of microseconds, the elimination about 10 ns per
/// unknown).
pub(crate) const TWISTED_PARALLEL_MIN: usize = 1 << 14;

/// Solves the tridiagonal system `A x = b` (no corners) like [`solve`], by the twisted
/// ("burn at both ends") factorization: the top half `0 ..= k` is eliminated downwards
/// (`xᵢ + cᵢ xᵢ₊₁ = dᵢ`, Thomas's recurrence), the bottom half `k + 1 .. n` upwards
/// (`eᵢ xᵢ₋₁ + xᵢ = gᵢ`), the two meet in a 2 × 2 system
///
/// `x_k = (d_k − c_k g_{k+1}) / (1 − c_k e_{k+1})`, `x_{k+1} = g_{k+1} − e_{k+1} x_k`,
///
/// and each half is back-substituted outwards (van der Vorst, *Large tridiagonal and block
/// tridiagonal linear systems on vector and parallel computers*, Parallel Computing 5, 1987).
/// The halves are independent, so on a machine with two cores they run at once (from
/// [`TWISTED_PARALLEL_MIN`] unknowns); the arithmetic, and so the result, is the same on one
/// core or two. For the strictly diagonally dominant matrices of spline moments
/// `|cᵢ|, |eᵢ| < 1`, so the meeting's denominator is at least `1 − |c_k e_{k+1}| > 0` and the
/// solve is as stable as Thomas's.
///
/// `factors` (`n` entries) is scratch for the elimination factors `cᵢ`, `eᵢ`; on `Ok`
/// `factors[i] = refill[i]` (on an error it holds factors) — so a caller may lend a buffer it
/// is about to fill anyway (the cubic spline lends its abscissae, refilled from the data),
/// and from 4 unknowns the solve allocates nothing.
/// Returns the largest `‖xᵢ‖₁` (NaN if any entry is NaN).
///
/// # Errors
/// [`Error::SingularSystem`] on a zero or non-finite pivot or meeting denominator.
pub(crate) fn solve_twisted<const N: usize>(
    system: &impl Band<N>,
    factors: &mut [f64],
    refill: &[f64],
    out: &mut [SVector<f64, N>],
) -> Result<f64> {
    let row = |i: usize| system.row(i);
    let rhs = |i: usize| system.rhs(i);
    let n = out.len();
    let singular = || Error::SingularSystem {
        what: "tridiagonal system",
    };
    if n == 0 {
        return Ok(0.0);
    }
    if n < 4 {
        let largest = thomas(&row, &rhs, &mut Vec::new(), out)?;
        for (i, f) in factors.iter_mut().enumerate().take(n) {
            *f = refill[i];
        }
        return Ok(largest);
    }
    let k = (n - 1) / 2;
    let (top_f, bottom_f) = factors[..n].split_at_mut(k + 1);
    let (top_x, bottom_x) = out.split_at_mut(k + 1);
    let parallel = n >= TWISTED_PARALLEL_MIN;
    let pivot_ok = |p: f64| p != 0.0 && p.is_finite();
    // elimination: the top half downwards, the bottom half upwards
    let ((c_k, d_k, top_ok), (e_k1, g_k1, bottom_ok)) = crate::parallel::join(
        parallel,
        || {
            let (mut c, mut d, mut ok) = (0.0, SVector::<f64, N>::zeros(), true);
            for (i, (f, x)) in top_f.iter_mut().zip(top_x.iter_mut()).enumerate() {
                let r = row(i);
                let (sub, pivot) = if i == 0 {
                    (0.0, r.diag)
                } else {
                    (r.sub, r.diag - r.sub * c)
                };
                ok &= pivot_ok(pivot);
                let inv = 1.0 / pivot;
                c = r.sup * inv;
                d = (rhs(i) - d * sub) * inv;
                *f = c;
                *x = d;
            }
            (c, d, ok)
        },
        || {
            let (mut e, mut g, mut ok) = (0.0, SVector::<f64, N>::zeros(), true);
            for (j, (f, x)) in bottom_f
                .iter_mut()
                .zip(bottom_x.iter_mut())
                .enumerate()
                .rev()
            {
                let i = k + 1 + j;
                let r = row(i);
                let (sup, pivot) = if i == n - 1 {
                    (0.0, r.diag)
                } else {
                    (r.sup, r.diag - r.sup * e)
                };
                ok &= pivot_ok(pivot);
                let inv = 1.0 / pivot;
                e = r.sub * inv;
                g = (rhs(i) - g * sup) * inv;
                *f = e;
                *x = g;
            }
            (e, g, ok)
        },
    );
    let denom = 1.0 - c_k * e_k1;
    if !(top_ok && bottom_ok && pivot_ok(denom)) {
        return Err(singular());
    }
    let x_k = (d_k - g_k1 * c_k) / denom;
    let x_k1 = g_k1 - x_k * e_k1;
    // back substitution, outwards from the meeting
    let (top, bottom) = crate::parallel::join(
        parallel,
        || {
            top_x[k] = x_k;
            top_f[k] = refill[k];
            let mut largest = l1(&x_k);
            for i in (0..k).rev() {
                let next = top_x[i + 1];
                top_x[i] -= next * top_f[i];
                top_f[i] = refill[i];
                largest = nan_max(largest, l1(&top_x[i]));
            }
            largest
        },
        || {
            bottom_x[0] = x_k1;
            bottom_f[0] = refill[k + 1];
            let mut largest = l1(&x_k1);
            for j in 1..bottom_x.len() {
                let prev = bottom_x[j - 1];
                bottom_x[j] -= prev * bottom_f[j];
                bottom_f[j] = refill[k + 1 + j];
                largest = nan_max(largest, l1(&bottom_x[j]));
            }
            largest
        },
    );
    Ok(nan_max(top, bottom))
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

    /// A system of `Band` rows from closures, for the tests.
    struct Rows<F, G>(F, G);

    impl<const N: usize, F, G> Band<N> for Rows<F, G>
    where
        F: Fn(usize) -> Row + Sync,
        G: Fn(usize) -> SVector<f64, N> + Sync,
    {
        fn row(&self, i: usize) -> Row {
            (self.0)(i)
        }
        fn rhs(&self, i: usize) -> SVector<f64, N> {
            (self.1)(i)
        }
    }

    /// The twisted solve (the fast path, two threads from `TWISTED_PARALLEL_MIN` unknowns)
    /// against Thomas's algorithm (the reference path) on strictly diagonally dominant systems
    /// with entries spread over many orders of magnitude (the moment systems of very uneven
    /// meshes), sizes across the threading threshold; and the refill of the scratch.
    #[test]
    fn twisted_matches_thomas() {
        use proptest::prelude::*;
        let sizes = prop_oneof![
            1usize..=12,
            13usize..=300,
            Just(TWISTED_PARALLEL_MIN - 1),
            Just(TWISTED_PARALLEL_MIN + 7),
        ];
        let config = ProptestConfig {
            cases: 64,
            failure_persistence: None,
            ..ProptestConfig::default()
        };
        proptest!(config, |(n in sizes, seed in any::<u64>(), spread in 0.0f64..12.0)| {
            // a cheap deterministic generator per case
            let mut state = seed | 1;
            let mut next = move || {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                (state >> 11) as f64 / (1u64 << 53) as f64
            };
            let gaps: Vec<f64> = (0..=n).map(|_| 10f64.powf(spread * (next() - 0.5))).collect();
            let b: Vec<Vector2<f64>> = (0..n)
                .map(|_| Vector2::new(next() - 0.5, 1e3 * (next() - 0.5)))
                .collect();
            // the moment-equation shape: sub = h_{i−1}, diag = 2(h_{i−1} + h_i), sup = h_i
            let row = |i: usize| Row {
                sub: gaps[i],
                diag: 2.0 * (gaps[i] + gaps[i + 1]),
                sup: gaps[i + 1],
            };
            let mut reference = vec![Vector2::zeros(); n];
            let largest_ref = solve(row, |i| b[i], None, &mut reference).expect("dominant");
            let mut fast = vec![Vector2::zeros(); n];
            let mut scratch = vec![f64::NAN; n];
            let refill: Vec<f64> = (0..n).map(|i| i as f64).collect();
            let largest = solve_twisted(&Rows(row, |i: usize| b[i]), &mut scratch, &refill, &mut fast)
                .expect("dominant");
            prop_assert_eq!(&scratch, &refill);
            let scale = reference.iter().map(|v| v.amax()).fold(0.0, f64::max);
            for (i, (x, r)) in fast.iter().zip(&reference).enumerate() {
                prop_assert!((x - r).amax() <= 1e-13 * scale, "n = {}, x[{}] = {:?} vs {:?}", n, i, x, r);
            }
            prop_assert!((largest - largest_ref).abs() <= 1e-12 * largest_ref.max(1e-300));
        });
    }

    #[test]
    fn twisted_reports_a_singular_pivot() {
        let row = |_: usize| Row {
            sub: 1.0,
            diag: 0.0,
            sup: 1.0,
        };
        for n in [2, 10] {
            let mut x = vec![Vector2::zeros(); n];
            let mut f = vec![0.0; n];
            let r = solve_twisted(
                &Rows(row, |_: usize| Vector2::new(1.0, 1.0)),
                &mut f,
                &vec![0.0; n],
                &mut x,
            );
            assert!(matches!(r, Err(Error::SingularSystem { .. })), "{r:?}");
        }
    }
}
