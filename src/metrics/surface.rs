//! Error measures per coordinate: the report's `norm(abs(A − B))`, max-abs and RMS.

use crate::error::{Error, Result};
use crate::grid::Grid;
use nalgebra::{DMatrix, Vector3};

/// Iterations the SVD of [`matlab_norm`] may take per matrix dimension before it gives up
/// (Golub–Kahan with implicit shifts converges in a few per singular value; the bound only
/// exists so that no input can make it loop for ever).
const SVD_ITERATIONS_PER_DIM: usize = 1000;

/// MATLAB's `norm(M)` of a matrix: its 2-norm, the largest singular value (not Frobenius).
/// `0` for an empty matrix.
///
/// The matrix is scaled by its largest entry before the SVD (the norm is homogeneous), so
/// entries near the overflow threshold do not overflow inside the iteration; the iteration
/// count is bounded.
///
/// # Errors
/// [`Error::NonFinite`] for a NaN or infinite entry (checked before any iteration: the SVD
/// never converges on them); [`Error::NoConvergence`] if the bounded SVD does not converge;
/// [`Error::Overflow`] if the norm itself exceeds `f64::MAX`.
pub fn matlab_norm(m: &DMatrix<f64>) -> Result<f64> {
    if m.is_empty() {
        return Ok(0.0);
    }
    crate::error::derived("matrix norm", singular_values(m)?.max())
}

/// The singular values of a non-empty matrix, scaled SVD with a bounded iteration count (see
/// [`matlab_norm`]); all zero for a zero matrix.
///
/// # Errors
/// As [`matlab_norm`], except that an overflowing result is returned as infinite.
pub(crate) fn singular_values(m: &DMatrix<f64>) -> Result<nalgebra::DVector<f64>> {
    let mut scale: f64 = 0.0;
    for &x in m.iter() {
        crate::error::finite("matrix entry", x)?;
        scale = scale.max(x.abs());
    }
    let dim = m.nrows().min(m.ncols());
    if scale == 0.0 {
        return Ok(nalgebra::DVector::zeros(dim));
    }
    let iterations = SVD_ITERATIONS_PER_DIM.saturating_mul(m.nrows().max(m.ncols()));
    let svd = nalgebra::SVD::try_new(m / scale, false, false, f64::EPSILON, iterations).ok_or(
        Error::NoConvergence {
            what: "singular value decomposition",
            iterations,
        },
    )?;
    Ok(svd.singular_values * scale)
}

/// Errors of an approximation per coordinate (x, y, z).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoordErrors {
    /// The report's measure: `norm(abs(A − B))` per patch (largest singular value of the
    /// matrix of absolute errors on the patch's sample grid, Codice 6 and 14), averaged over
    /// patches (`mean(X_norms)`). It grows with the number of samples (for a constant error
    /// `e` on a `p × p` grid it is `p·e`), so it is a fingerprint of the report, not an error
    /// measure on its own.
    pub report_norm: Vector3<f64>,
    /// Largest absolute error over all samples.
    pub max_abs: Vector3<f64>,
    /// Root mean square of the errors over all samples (samples on shared patch edges are
    /// counted once per patch).
    pub rms: Vector3<f64>,
}

/// Collects per-patch errors and reduces them as Codice 14 does.
///
/// Sums are kept twice: plainly (the report's arithmetic, bit for bit) and in an
/// overflow-free form (a running mean of the norms; squares scaled by the running maximum, as
/// LAPACK's `dnrm2`), which is used only where the plain sum overflows — errors near
/// `f64::MAX` give their true mean and RMS, never `inf`.
#[derive(Debug, Clone, Default)]
pub struct ErrorAccumulator {
    norm_sum: Vector3<f64>,
    norm_mean: Vector3<f64>,
    patches: usize,
    max_abs: Vector3<f64>,
    sum_sq: Vector3<f64>,
    /// `Σ (d / max_abs)²` per coordinate, rescaled whenever `max_abs` grows.
    scaled_sq: Vector3<f64>,
    samples: usize,
}

impl ErrorAccumulator {
    /// An empty accumulator.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds one patch: `approx` and `exact` tabulated on the same grid.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] if the grids differ in shape; [`Error::NonFinite`] for a NaN
    /// or infinite value in either grid, or whose difference overflows (an error measure never
    /// ignores NaN); the errors of [`matlab_norm`].
    pub fn add_patch(
        &mut self,
        approx: &Grid<Vector3<f64>>,
        exact: &Grid<Vector3<f64>>,
    ) -> Result<()> {
        if (approx.rows(), approx.cols()) != (exact.rows(), exact.cols()) {
            return Err(Error::ShapeMismatch {
                left_rows: approx.rows(),
                left_cols: approx.cols(),
                right_rows: exact.rows(),
                right_cols: exact.cols(),
            });
        }
        let (r, c) = (approx.rows(), approx.cols());
        let mut diff: Vec<Vector3<f64>> = Vec::with_capacity(approx.as_slice().len());
        for (a, e) in approx.as_slice().iter().zip(exact.as_slice()) {
            for &x in a.iter().chain(e.iter()) {
                crate::error::finite("compared grid value", x)?;
            }
            let d = (a - e).abs();
            for &x in d.iter() {
                crate::error::derived("difference of compared grid values", x)?;
            }
            diff.push(d);
        }
        let count = (self.patches + 1) as f64;
        for (k, (sum, mean)) in self
            .norm_sum
            .iter_mut()
            .zip(self.norm_mean.iter_mut())
            .enumerate()
        {
            let norm = matlab_norm(&DMatrix::from_fn(r, c, |i, j| diff[i * c + j][k]))?;
            *sum += norm;
            *mean += (norm - *mean) / count;
        }
        for d in &diff {
            self.sum_sq += d.component_mul(d);
            for k in 0..3 {
                let (x, m) = (d[k], self.max_abs[k]);
                if x > m {
                    self.scaled_sq[k] = 1.0 + self.scaled_sq[k] * (m / x) * (m / x);
                    self.max_abs[k] = x;
                } else if x > 0.0 {
                    self.scaled_sq[k] += (x / m) * (x / m);
                }
            }
        }
        self.patches += 1;
        self.samples += diff.len();
        Ok(())
    }

    /// The reduced errors; all zero if nothing was added. Finite whatever the errors' size
    /// (the overflow-free sums replace the plain ones where those overflow or underflow).
    pub fn finish(&self) -> CoordErrors {
        let p = self.patches.max(1) as f64;
        let n = self.samples.max(1) as f64;
        // squares below this are subnormal or near it: the plain sum has lost digits
        const SQUARES_FLOOR: f64 = 1e-290;
        CoordErrors {
            report_norm: Vector3::from_fn(|k, _| {
                let plain = self.norm_sum[k] / p;
                if plain.is_finite() {
                    plain
                } else {
                    self.norm_mean[k]
                }
            }),
            max_abs: self.max_abs,
            rms: Vector3::from_fn(|k, _| {
                let plain = self.sum_sq[k];
                if self.max_abs[k] == 0.0 || (plain.is_finite() && plain >= SQUARES_FLOOR) {
                    (plain / n).sqrt()
                } else {
                    self.max_abs[k] * (self.scaled_sq[k] / n).sqrt()
                }
            }),
        }
    }
}

/// Errors of one tabulation against another (Codice 6 for a single patch).
///
/// # Errors
/// As [`ErrorAccumulator::add_patch`].
pub fn compare(approx: &Grid<Vector3<f64>>, exact: &Grid<Vector3<f64>>) -> Result<CoordErrors> {
    let mut acc = ErrorAccumulator::new();
    acc.add_patch(approx, exact)?;
    Ok(acc.finish())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matlab_norm_is_the_largest_singular_value_not_frobenius() {
        // rank-one all-ones p×p: singular value p, Frobenius p too; diag(3, 4): 4 vs 5
        let m = DMatrix::from_row_slice(2, 2, &[3.0, 0.0, 0.0, 4.0]);
        let n = matlab_norm(&m).expect("finite");
        assert!((n - 4.0).abs() < 1e-14, "{n}");
        let ones = DMatrix::from_element(15, 15, 1.0);
        let n = matlab_norm(&ones).expect("finite");
        assert!((n - 15.0).abs() < 1e-12, "{n}");
        // near the overflow threshold: scaled, not overflowed
        let big = DMatrix::from_element(3, 3, 1e307);
        let n = matlab_norm(&big).expect("finite");
        assert!((n / 3e307 - 1.0).abs() < 1e-12, "{n}");
        let huge = DMatrix::from_element(3, 3, 1e308);
        assert!(matches!(matlab_norm(&huge), Err(Error::Overflow { .. })));
        let nan = DMatrix::from_row_slice(2, 2, &[1.0, f64::NAN, 0.0, 1.0]);
        assert!(matches!(matlab_norm(&nan), Err(Error::NonFinite { .. })));
    }
}
