//! The de Casteljau algorithm for curves of any degree and its tensor-product form
//! (seed 000 §4, Codice 11–12; seed 003).

use crate::error::{Error, Result};
use crate::exact::Rational;
use crate::grid::Grid;
use num_dual::DualNum;
use num_traits::One;
use std::ops::{Add, Mul};

/// A curve parameter `u` de Casteljau's interpolation `(1 − u) Qᵢ + u Qᵢ₊₁` runs on: every
/// dual number (`f64`, exact derivatives, formulas) and the exact [`Rational`] (the notes'
/// construction in fractions).
pub trait BezierParameter: Clone {
    /// `1 − u`.
    fn complement(&self) -> Self;
}

impl<D: DualNum<Primitive = f64> + Copy> BezierParameter for D {
    fn complement(&self) -> Self {
        -*self + 1.0
    }
}

impl BezierParameter for Rational {
    fn complement(&self) -> Self {
        Rational::one() - self
    }
}

/// [`Error::TooFewPoints`] unless there are at least `needed` points.
fn at_least<P>(what: &'static str, points: &[P], needed: usize) -> Result<()> {
    if points.len() < needed {
        return Err(Error::TooFewPoints {
            what,
            needed,
            got: points.len(),
        });
    }
    Ok(())
}

/// Reduces `points` in place by repeated linear interpolation
/// `Qᵢ ← (1 − u) Qᵢ + u Qᵢ₊₁` (Codice 12) and returns `Q₀ = P(u)`.
///
/// # Panics
/// If `points` is empty.
pub(crate) fn reduce<P, D>(points: &mut [P], u: D) -> P
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: BezierParameter,
{
    let r = u.complement();
    for level in (1..points.len()).rev() {
        for i in 0..level {
            points[i] = points[i].clone() * r.clone() + points[i + 1].clone() * u.clone();
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
    D: BezierParameter,
{
    at_least("de Casteljau control points", points, 1)?;
    Ok(reduce(&mut points.to_vec(), u))
}

/// de Casteljau as printed in seed 003 (`castel`): the point of level `k` with index `i` is the
/// interpolation `(1 − u) P(i, k−1) + u P(i+1, k−1)` of two points of the level below, each
/// computed by a recursive call, down to the control points. Written as the listing (called
/// as `castel(punti, 0, PointCount − 1, u)`), so it makes `2ⁿ⁻¹ − 1` calls for `n` points —
/// exponential, unlike the `O(n²)` iterative [`de_casteljau`]; the notes' remark that their
/// program cannot draw curves of more than 20 control points with it fits this cost.
///
/// # Errors
/// [`Error::TooFewPoints`] below 2 points (the listing would recurse without end on one);
/// [`Error::TooLarge`] above [`MAX_RECURSIVE_POINTS`] points (the call count doubles with
/// every point, and the recursion depth grows with the input).
///
/// # Examples
/// ```
/// use nalgebra::Vector2;
/// let p = [Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0), Vector2::new(2.0, 0.0)];
/// let a = splinelab::de_casteljau_recursive(&p, 0.3).unwrap();
/// let b = splinelab::de_casteljau(&p, 0.3).unwrap();
/// assert!((a - b).norm() < 1e-15);
/// ```
pub fn de_casteljau_recursive<P, D>(points: &[P], u: D) -> Result<P>
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: BezierParameter,
{
    de_casteljau_recursive_counted(points, u).map(|(p, _)| p)
}

/// [`de_casteljau_recursive`] with the number of calls `castel` made, counted as it runs
/// (each call one linear interpolation): `2ⁿ⁻¹ − 1` for `n` points, against the
/// `n(n − 1)/2` interpolations of the triangle ([`de_casteljau_levels`]).
///
/// # Errors
/// As [`de_casteljau_recursive`].
pub fn de_casteljau_recursive_counted<P, D>(points: &[P], u: D) -> Result<(P, u64)>
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: BezierParameter,
{
    fn castel<P, D>(points: &[P], i: usize, level: usize, u: &D, calls: &mut u64) -> P
    where
        P: Clone + Add<Output = P> + Mul<D, Output = P>,
        D: BezierParameter,
    {
        *calls += 1;
        let r = u.complement();
        if level == 1 {
            points[i].clone() * r + points[i + 1].clone() * u.clone()
        } else {
            castel(points, i, level - 1, u, calls) * r
                + castel(points, i + 1, level - 1, u, calls) * u.clone()
        }
    }
    at_least("recursive de Casteljau control points", points, 2)?;
    if points.len() > MAX_RECURSIVE_POINTS {
        return Err(Error::TooLarge {
            what: "recursive de Casteljau control points (2ⁿ⁻¹ calls)",
            got: points.len(),
            max: MAX_RECURSIVE_POINTS,
        });
    }
    let mut calls = 0;
    let p = castel(points, 0, points.len() - 1, &u, &mut calls);
    Ok((p, calls))
}

/// The most control points [`de_casteljau_recursive`] accepts: `2²³ ≈ 8 · 10⁶` calls, a
/// fraction of a second, at a recursion depth of 23. (Seed 003 notes that its program cannot
/// draw curves of more than 20 points with it.)
pub const MAX_RECURSIVE_POINTS: usize = 24;

/// Every level of de Casteljau's triangle at `u`: level 0 is the control polygon, level `k`
/// the `n − k` points `(1 − u) Qᵢ + u Qᵢ₊₁` of level `k − 1`, the last level the curve point
/// (seed 003's construction figures at `u = 0.3, 0.5, 0.7`).
///
/// # Errors
/// [`Error::TooFewPoints`] for an empty slice; [`Error::TooLarge`] if the `n(n + 1)/2` points
/// of the triangle exceed [`crate::error::MAX_ELEMENTS`].
pub fn de_casteljau_levels<P, D>(points: &[P], u: D) -> Result<Vec<Vec<P>>>
where
    P: Clone + Add<Output = P> + Mul<D, Output = P>,
    D: BezierParameter,
{
    at_least("de Casteljau control points", points, 1)?;
    let n = points.len();
    crate::error::size_product("de Casteljau triangle points", n, n.div_ceil(2) + 1)?;
    let r = u.complement();
    let mut levels = vec![points.to_vec()];
    while let Some(last) = levels.last().filter(|l| l.len() > 1) {
        let next = last
            .windows(2)
            .map(|w| w[0].clone() * r.clone() + w[1].clone() * u.clone())
            .collect();
        levels.push(next);
    }
    Ok(levels)
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
