//! Error measures per coordinate: the report's `norm(abs(A − B))`, max-abs and RMS.

use crate::error::{Error, Result};
use crate::grid::Grid;
use nalgebra::{DMatrix, Vector3};

/// MATLAB's `norm(M)` of a matrix: its 2-norm, the largest singular value (not Frobenius).
/// `0` for an empty matrix.
pub fn matlab_norm(m: &DMatrix<f64>) -> f64 {
    if m.is_empty() {
        return 0.0;
    }
    m.singular_values().max()
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
#[derive(Debug, Clone, Default)]
pub struct ErrorAccumulator {
    norm_sum: Vector3<f64>,
    patches: usize,
    max_abs: Vector3<f64>,
    sum_sq: Vector3<f64>,
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
    /// [`Error::ShapeMismatch`] if the grids differ in shape.
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
        let diff: Vec<Vector3<f64>> = approx
            .as_slice()
            .iter()
            .zip(exact.as_slice())
            .map(|(a, e)| (a - e).abs())
            .collect();
        for (k, sum) in self.norm_sum.iter_mut().enumerate() {
            *sum += matlab_norm(&DMatrix::from_fn(r, c, |i, j| diff[i * c + j][k]));
        }
        for d in &diff {
            self.max_abs = self.max_abs.sup(d);
            self.sum_sq += d.component_mul(d);
        }
        self.patches += 1;
        self.samples += diff.len();
        Ok(())
    }

    /// The reduced errors; all zero if nothing was added.
    pub fn finish(&self) -> CoordErrors {
        let p = self.patches.max(1) as f64;
        let n = self.samples.max(1) as f64;
        CoordErrors {
            report_norm: self.norm_sum / p,
            max_abs: self.max_abs,
            rms: (self.sum_sq / n).map(f64::sqrt),
        }
    }
}

/// Errors of one tabulation against another (Codice 6 for a single patch).
///
/// # Errors
/// [`Error::ShapeMismatch`] if the grids differ in shape.
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
        assert!((matlab_norm(&m) - 4.0).abs() < 1e-14, "{}", matlab_norm(&m));
        let ones = DMatrix::from_element(15, 15, 1.0);
        assert!((matlab_norm(&ones) - 15.0).abs() < 1e-12);
    }
}
