//! The de Casteljau algorithm for curves of any degree and its tensor-product form
//! (seed 000 §4, Codice 11–12; seed 003).

use crate::error::{Error, Result};
use crate::grid::Grid;
use num_dual::DualNum;
use std::ops::{Add, Mul};

/// Reduces `points` in place by repeated linear interpolation
/// `Qᵢ ← (1 − u) Qᵢ + u Qᵢ₊₁` (Codice 12) and returns `Q₀ = P(u)`.
///
/// # Panics
/// If `points` is empty.
pub(crate) fn reduce<P, D>(points: &mut [P], u: D) -> P
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: DualNum<Primitive = f64> + Copy,
{
    let r = -u + 1.0;
    for level in (1..points.len()).rev() {
        for i in 0..level {
            points[i] = points[i].clone() * r + points[i + 1].clone() * u;
        }
    }
    points[0].clone()
}

/// The point at `u` of the Bézier curve with control points `points` (any degree, any point
/// type that supports affine combinations: `f64`, `nalgebra` vectors, dual-number vectors),
/// by de Casteljau's algorithm (Codice 12).
///
/// # Errors
/// [`Error::TooFewPoints`] for an empty slice.
///
/// # Examples
/// ```
/// use nalgebra::Vector2;
/// let p = [Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0), Vector2::new(2.0, 0.0)];
/// let mid = splinelab::de_casteljau(&p, 0.5).unwrap();
/// assert_eq!(mid, Vector2::new(1.0, 1.0));
/// ```
pub fn de_casteljau<P, D>(points: &[P], u: D) -> Result<P>
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: DualNum<Primitive = f64> + Copy,
{
    if points.is_empty() {
        return Err(Error::TooFewPoints {
            what: "de Casteljau control points",
            needed: 1,
            got: 0,
        });
    }
    Ok(reduce(&mut points.to_vec(), u))
}

/// The point at `(u, v)` of the tensor-product Bézier surface with control net `net`
/// (row `i` ↔ the `i`-th u control index), as Codice 11: each row is reduced in `v`, then the
/// resulting column of points in `u`. Any degree in each direction.
///
/// # Errors
/// [`Error::TooFewPoints`] for an empty net.
pub fn de_casteljau_surface<P, D>(net: &Grid<P>, u: D, v: D) -> Result<P>
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: DualNum<Primitive = f64> + Copy,
{
    if net.rows() == 0 || net.cols() == 0 {
        return Err(Error::TooFewPoints {
            what: "de Casteljau control net",
            needed: 1,
            got: 0,
        });
    }
    let mut q: Vec<P> = (0..net.rows())
        .map(|i| reduce(&mut net.row(i).to_vec(), v))
        .collect();
    Ok(reduce(&mut q, u))
}
