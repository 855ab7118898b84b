//! The report's Codice 7 (`bezier_matrix`) transcribed literally, sign error included.
//!
//! Seed 000 §4 prints, for entry (3,2) of the Bézier net,
//! `M(3, 2) = C(4, 1) + C(4, 2)/3 - C(3, 1)/3 + C(3, 2)/9;` (both transcriptions, seeds 000
//! and 002). The correct entry of `M = A C Aᵀ` is `… − C(3,2)/9`: the twist at the corner
//! `(s, t) = (1, 0)` enters with the product of the signs of `b₂ = P(1) − P′(1)/3` (in s) and
//! `b₁ = P(0) + P′(0)/3` (in t), i.e. `(−1/3)(+1/3) = −1/9`; compare M(2,3), its mirror
//! image, which the report prints with `− C(2,3)/9`.
//!
//! This function exists only to reproduce the report's printed numbers and show where they
//! come from; use [`BezierPatch::from_hermite`] for the correct net. On the torus the error
//! is invisible whenever `tₐ = 0`, because `X_st = (sin t sin s, −sin t cos s, 0)` vanishes
//! at `t = 0` — which is why the report's equivalence check (Codice 10, on `[0, 1]²`) passed.

use crate::bezier::patch::BezierPatch;
use crate::error::{Error, Result};
use crate::exact::Field;
use crate::hermite::patch::HermitePatch;
use nalgebra::DMatrix;

/// The net the report's Codice 7 builds from `C` (1-based indices in the comments), applied
/// to all three planes as Codice 8 does, plane by plane ([`codice7_plane`]'s code).
pub fn report_codice7_net(h: &HermitePatch) -> BezierPatch {
    let planes: [[[f64; 4]; 4]; 3] =
        std::array::from_fn(|k| codice7(|i, j| h.matrix()[i - 1][j - 1][k]));
    BezierPatch::from_net(std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            nalgebra::Vector3::new(planes[0][i][j], planes[1][i][j], planes[2][i][j])
        })
    }))
}

/// One plane of the report's Codice 7 (`M = bezier_matrix(C)`), sign error included, over any
/// [`Field`]: in `f64` it gives the report's numbers; in exact rationals, applied to the
/// sixteen unit matrices, it shows the one entry where it differs from `A C Aᵀ` (notebook 04).
///
/// # Errors
/// [`Error::ShapeMismatch`] if `c` is not 4 × 4.
pub fn codice7_plane<T: Field>(c: &DMatrix<T>) -> Result<DMatrix<T>> {
    if c.shape() != (4, 4) {
        return Err(Error::ShapeMismatch {
            left_rows: c.nrows(),
            left_cols: c.ncols(),
            right_rows: 4,
            right_cols: 4,
        });
    }
    let m = codice7(|i, j| c[(i - 1, j - 1)].clone());
    Ok(DMatrix::from_fn(4, 4, |i, j| m[i][j].clone()))
}

/// Codice 7's sixteen lines, with `c(i, j)` the 1-based entry `C(i, j)`.
fn codice7<T: Field>(c: impl Fn(usize, usize) -> T) -> [[T; 4]; 4] {
    let three = T::one() + T::one() + T::one();
    let nine = three.clone() * three.clone();
    let third = |x: T| x / three.clone();
    let ninth = |x: T| x / nine.clone();
    let mut m: [[T; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| T::zero()));
    let mut set = |i: usize, j: usize, v: T| m[i - 1][j - 1] = v;
    set(1, 1, c(1, 1));
    set(1, 4, c(1, 4));
    set(4, 1, c(4, 1));
    set(4, 4, c(4, 4));
    set(1, 2, c(1, 1) + third(c(1, 2)));
    set(2, 1, c(1, 1) + third(c(2, 1)));
    set(
        2,
        2,
        c(1, 1) + third(c(1, 2)) + third(c(2, 1)) + ninth(c(2, 2)),
    );
    set(3, 1, c(4, 1) - third(c(3, 1)));
    set(4, 2, c(4, 1) + third(c(4, 2)));
    // Printed as `+ C(3, 2)/9`: the sign error, kept on purpose (see the module docs).
    set(
        3,
        2,
        c(4, 1) + third(c(4, 2)) - third(c(3, 1)) + ninth(c(3, 2)),
    );
    set(2, 4, c(1, 4) + third(c(2, 4)));
    set(1, 3, c(1, 4) - third(c(1, 3)));
    set(
        2,
        3,
        c(1, 4) + third(c(2, 4)) - third(c(1, 3)) - ninth(c(2, 3)),
    );
    set(3, 4, c(4, 4) - third(c(3, 4)));
    set(4, 3, c(4, 4) - third(c(4, 3)));
    set(
        3,
        3,
        c(4, 4) - third(c(4, 3)) - third(c(3, 4)) + ninth(c(3, 3)),
    );
    m
}
