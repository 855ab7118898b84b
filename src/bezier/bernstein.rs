//! Bernstein polynomials `Bᵢⁿ(u) = C(n, i) uⁱ (1 − u)ⁿ⁻ⁱ`.

use num_dual::DualNum;
use std::ops::{Add, Mul};

/// The cubic Bernstein basis of seed 000 §4 (Codice 9):
/// `B₀ = (1−t)³`, `B₁ = 3t(1−t)²`, `B₂ = 3t²(1−t)`, `B₃ = t³`.
///
/// # Examples
/// ```
/// assert_eq!(splinelab::bernstein3(0.5_f64), [0.125, 0.375, 0.375, 0.125]);
/// ```
pub fn bernstein3<D: DualNum<Primitive = f64> + Copy>(t: D) -> [D; 4] {
    let r = -t + 1.0;
    [r * r * r, t * r * r * 3.0, t * t * r * 3.0, t * t * t]
}

/// All `n + 1` Bernstein polynomials of degree `n` at `u`, by the triangular recurrence
/// `Bᵢⁿ = (1 − u) Bᵢⁿ⁻¹ + u Bᵢ₋₁ⁿ⁻¹` (*The NURBS Book*, A1.3), which needs no binomials.
pub fn bernstein_all<D: DualNum<Primitive = f64> + Copy>(n: usize, u: D) -> Vec<D> {
    let r = -u + 1.0;
    let mut b = vec![D::from(0.0); n + 1];
    b[0] = D::from(1.0);
    for j in 1..=n {
        let mut saved = D::from(0.0);
        for bk in b.iter_mut().take(j) {
            let tmp = *bk;
            *bk = saved + r * tmp;
            saved = u * tmp;
        }
        b[j] = saved;
    }
    b
}

/// The Bézier curve `Σᵢ Bᵢⁿ(u) Pᵢ` by its Bernstein sum, `n = points.len() − 1`; `None` for no
/// points. The reference the de Casteljau algorithm is checked against.
pub fn bernstein_sum<P, D>(points: &[P], u: D) -> Option<P>
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: DualNum<Primitive = f64> + Copy,
{
    let n = points.len().checked_sub(1)?;
    let b = bernstein_all(n, u);
    points
        .iter()
        .zip(b)
        .map(|(p, w)| p.clone() * w)
        .reduce(|a, b| a + b)
}
