//! The cubic Hermite basis of seed 000 §1.

use num_dual::DualNum;

/// The cubic Hermite basis `H(t) = (H₀, H₁, H₂, H₃)` (seed 000 §1, Codice 5):
///
/// `H₀ = 1 − 3t² + 2t³`, `H₁ = t − 2t² + t³`, `H₂ = t³ − t²`, `H₃ = 3t² − 2t³`,
///
/// the weights of `P(0)`, `P′(0)`, `P′(1)`, `P(1)` in that order, so that
/// `P(t) = H₀ P(0) + H₁ P′(0) + H₂ P′(1) + H₃ P(1)` is the cubic with those end values and
/// end derivatives. Generic over the number type, so derivatives of the basis come exact.
///
/// # Examples
/// ```
/// let h = splinelab::hermite_basis(0.5_f64);
/// assert_eq!(h, [0.5, 0.125, -0.125, 0.5]);
/// ```
pub fn hermite_basis<D: DualNum<Primitive = f64> + Copy>(t: D) -> [D; 4] {
    let t2 = t * t;
    let t3 = t2 * t;
    [
        t3 * 2.0 - t2 * 3.0 + 1.0,
        t3 - t2 * 2.0 + t,
        t3 - t2,
        t2 * 3.0 - t3 * 2.0,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::Dual64;

    #[test]
    fn end_values_and_derivatives_select_one_coefficient_each() {
        // H(0) = (1,0,0,0), H(1) = (0,0,0,1), H'(0) = (0,1,0,0), H'(1) = (0,0,1,0)
        for (t, value, slope) in [
            (0.0, [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]),
            (1.0, [0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0]),
        ] {
            let h = hermite_basis(Dual64::from_re(t).derivative());
            for k in 0..4 {
                assert_eq!(h[k].re, value[k], "H{k}({t})");
                assert_eq!(h[k].eps, slope[k], "H{k}'({t})");
            }
        }
    }
}
