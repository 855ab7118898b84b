//! The cubic blending functions of seed 003: Lagrange 4-point and uniform cubic B-spline.

use num_dual::DualNum;

/// The four cubic blending functions of a 4-point window.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Blending {
    /// Lagrange cubics through the window at `u = −1, 0, 1, 2` ([`lagrange4`]): the curve
    /// interpolates the data.
    Lagrange,
    /// Uniform cubic B-spline blending ([`uniform_bspline4`]): the curve approximates the
    /// data, C² across windows.
    UniformBSpline,
}

impl Blending {
    /// The four weights at `u`.
    pub fn weights<D: DualNum<Primitive = f64> + Copy>(self, u: D) -> [D; 4] {
        match self {
            Blending::Lagrange => lagrange4(u),
            Blending::UniformBSpline => uniform_bspline4(u),
        }
    }
}

/// Seed 003's Lagrange blending functions for 4 points placed at `u = −1, 0, 1, 2`:
///
/// `B₁ = u(u−1)(u−2) / ((−1)(−2)(−3))`, `B₂ = (u+1)(u−1)(u−2) / ((1)(−1)(−2))`,
/// `B₃ = (u+1)u(u−2) / ((2)(1)(−1))`, `B₄ = (u+1)u(u−1) / ((3)(2)(1))`.
///
/// `Bᵢ` is 1 at its own node and 0 at the other three, so `Σ Pᵢ Bᵢ(u)` passes through the
/// points; the segment `u ∈ [0, 1]` runs from `P₂` to `P₃`. The notes print `B₄`'s
/// denominator as `(3)(2)(−1)` (twice), which would give `B₄(2) = −1` and break the partition
/// of unity; `(3)(2)(1) = 6` is the value that makes `B₄(2) = 1`.
///
/// # Examples
/// ```
/// let b = splinelab::lagrange4(2.0_f64);
/// assert_eq!(b, [0.0, 0.0, 0.0, 1.0]);
/// ```
pub fn lagrange4<D: DualNum<Primitive = f64> + Copy>(u: D) -> [D; 4] {
    let (a, b, c, d) = (u + 1.0, u, u - 1.0, u - 2.0);
    [
        b * c * d / -6.0,
        a * c * d / 2.0,
        a * b * d / -2.0,
        a * b * c / 6.0,
    ]
}

/// The uniform cubic B-spline blending functions on `u ∈ [0, 1]` (seed 003, `setbval`):
///
/// `b₀ = (1 − u)³/6`, `b₁ = (3u³ − 6u² + 4)/6`, `b₂ = (−3u³ + 3u² + 3u + 1)/6`, `b₃ = u³/6`.
///
/// They are the four uniform B-splines of degree 3 that are non-zero on one knot interval
/// (knots at the integers), so they are non-negative and sum to 1, and `Σ Pₖ₋₁₊ᵢ bᵢ(u)`
/// joins the next window with continuous first and second derivatives.
///
/// # Examples
/// ```
/// let b = splinelab::uniform_bspline4(0.0_f64);
/// assert!((b[0] - 1.0 / 6.0).abs() < 1e-16 && (b[1] - 4.0 / 6.0).abs() < 1e-16);
/// ```
pub fn uniform_bspline4<D: DualNum<Primitive = f64> + Copy>(u: D) -> [D; 4] {
    let r = -u + 1.0;
    let u2 = u * u;
    let u3 = u2 * u;
    [
        r * r * r / 6.0,
        (u3 * 3.0 - u2 * 6.0 + 4.0) / 6.0,
        (-u3 * 3.0 + u2 * 3.0 + u * 3.0 + 1.0) / 6.0,
        u3 / 6.0,
    ]
}

/// The table `b[i][j]` of the printed `setbval` for `nb` samples `u = j/nb`, `j = 0 … nb−1`,
/// computed the way the listing does: `b₀ = (1−u)³/6`, `b₂ = (((1 − u)u + 1)u + 1/3)/2`
/// (a Horner form of `(−3u³ + 3u² + 3u + 1)/6`), `b₃ = u³/6`, `b₁ = 1 − b₀ − b₂ − b₃`.
/// Kept to check the listing against [`uniform_bspline4`]; returns `[b₀, b₁, b₂, b₃]` per `j`.
///
/// # Errors
/// [`crate::error::Error::TooLarge`] if `nb` exceeds [`crate::error::MAX_ELEMENTS`].
pub fn printed_setbval(nb: usize) -> crate::error::Result<Vec<[f64; 4]>> {
    crate::error::size("setbval samples (nb)", nb)?;
    Ok((0..nb)
        .map(|j| {
            let u = j as f64 / nb as f64;
            let b0 = (1.0 - u) * (1.0 - u) * (1.0 - u) / 6.0;
            let b2 = (((1.0 - u) * u + 1.0) * u + 1.0 / 3.0) / 2.0;
            let b3 = u * u * u / 6.0;
            [b0, 1.0 - b0 - b2 - b3, b2, b3]
        })
        .collect())
}
