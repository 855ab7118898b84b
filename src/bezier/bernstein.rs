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
///
/// # Errors
/// [`crate::error::Error::TooLarge`] if `n + 1` exceeds [`crate::error::MAX_ELEMENTS`] (the work
/// is `O(n²)`: a degree above [`MAX_BERNSTEIN_DEGREE`] is refused as well).
pub fn bernstein_all<D: DualNum<Primitive = f64> + Copy>(
    n: usize,
    u: D,
) -> crate::error::Result<Vec<D>> {
    let len = crate::error::size_sum("Bernstein polynomials (degree + 1)", n, 1)?;
    if n > MAX_BERNSTEIN_DEGREE {
        return Err(crate::error::Error::TooLarge {
            what: "Bernstein degree (O(n²) work)",
            got: n,
            max: MAX_BERNSTEIN_DEGREE,
        });
    }
    let r = -u + 1.0;
    let mut b = vec![D::from(0.0); len];
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
    Ok(b)
}

/// The largest degree [`bernstein_all`] and [`bernstein_sum`] accept: their triangular
/// scheme costs `n²/2` steps, about a second at this degree.
pub const MAX_BERNSTEIN_DEGREE: usize = 1 << 14;

/// The Bézier curve `Σᵢ Bᵢⁿ(u) Pᵢ` by its Bernstein sum, `n = points.len() − 1`. The
/// reference the de Casteljau algorithm is checked against.
///
/// # Errors
/// [`crate::error::Error::TooFewPoints`] for no points; the errors of [`bernstein_all`].
pub fn bernstein_sum<P, D>(points: &[P], u: D) -> crate::error::Result<P>
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: DualNum<Primitive = f64> + Copy,
{
    let too_few = || crate::error::Error::TooFewPoints {
        what: "Bernstein sum control points",
        needed: 1,
        got: 0,
    };
    let n = points.len().checked_sub(1).ok_or_else(too_few)?;
    let b = bernstein_all(n, u)?;
    points
        .iter()
        .zip(b)
        .map(|(p, w)| p.clone() * w)
        .reduce(|a, b| a + b)
        .ok_or_else(too_few)
}
