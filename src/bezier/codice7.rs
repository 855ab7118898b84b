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
use crate::hermite::patch::HermitePatch;

/// The net the report's Codice 7 builds from `C` (1-based indices in the comments), applied
/// to all three planes at once as Codice 8 does plane by plane.
pub fn report_codice7_net(h: &HermitePatch) -> BezierPatch {
    let c = |i: usize, j: usize| h.matrix()[i - 1][j - 1];
    let mut m = [[nalgebra::Vector3::zeros(); 4]; 4];
    let mut set = |i: usize, j: usize, v| m[i - 1][j - 1] = v;
    set(1, 1, c(1, 1));
    set(1, 4, c(1, 4));
    set(4, 1, c(4, 1));
    set(4, 4, c(4, 4));
    set(1, 2, c(1, 1) + c(1, 2) / 3.0);
    set(2, 1, c(1, 1) + c(2, 1) / 3.0);
    set(
        2,
        2,
        c(1, 1) + c(1, 2) / 3.0 + c(2, 1) / 3.0 + c(2, 2) / 9.0,
    );
    set(3, 1, c(4, 1) - c(3, 1) / 3.0);
    set(4, 2, c(4, 1) + c(4, 2) / 3.0);
    // Printed as `+ C(3, 2)/9`: the sign error, kept on purpose (see the module docs).
    set(
        3,
        2,
        c(4, 1) + c(4, 2) / 3.0 - c(3, 1) / 3.0 + c(3, 2) / 9.0,
    );
    set(2, 4, c(1, 4) + c(2, 4) / 3.0);
    set(1, 3, c(1, 4) - c(1, 3) / 3.0);
    set(
        2,
        3,
        c(1, 4) + c(2, 4) / 3.0 - c(1, 3) / 3.0 - c(2, 3) / 9.0,
    );
    set(3, 4, c(4, 4) - c(3, 4) / 3.0);
    set(4, 3, c(4, 4) - c(4, 3) / 3.0);
    set(
        3,
        3,
        c(4, 4) - c(4, 3) / 3.0 - c(3, 4) / 3.0 + c(3, 3) / 9.0,
    );
    BezierPatch::from_net(m)
}
