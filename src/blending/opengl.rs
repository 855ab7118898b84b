//! The OpenGL-evaluator spline of seed 003 (`bsplineOGL`): consecutive groups of `order`
//! control points, each drawn as a Bézier curve by `glMap1f`/`glEvalCoord1f`, stepping by
//! `order − 1` so that groups share their end points.

use crate::bezier::bernstein::bernstein_sum;
use crate::error::finite_points;
use crate::error::{Error, Result};
use nalgebra::SVector;

/// What the last group holds when fewer than `order` points remain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LastGroup {
    /// The remaining points only: a Bézier curve of lower degree (what the listing evidently
    /// intends; a group of one point is dropped).
    Truncated,
    /// Exactly as printed: `glMap1f` is always called with order 5 on the array
    /// `PuntiContr`, whose first `kptLim` entries are refreshed, so the remaining entries still
    /// hold points of the previous group. The `while (kb < PointCount)` loop also runs when a
    /// single point remains (e.g. 9 points: groups `P₀…P₄`, `P₄…P₈`, then `P₈, P₅, P₆, P₇, P₈`).
    /// The listing's first group needs `order` points (with fewer, the array is uninitialised).
    AsPrinted,
}

/// The control-point groups of the OpenGL-evaluator spline: `P_{kb} … P_{kb+order−1}` for
/// `kb = 0, order − 1, 2(order − 1), …` while `kb < len` (the listing's loop), the last one
/// completed according to `last`.
///
/// # Errors
/// [`Error::DegreeTooLow`] for `order < 2`; [`Error::TooFewPoints`] below 3 points (the
/// listing returns early for `PointCount <= 2`), or below `order` points with
/// [`LastGroup::AsPrinted`]; [`Error::NonFinite`].
pub fn opengl_groups<const N: usize>(
    points: &[SVector<f64, N>],
    order: usize,
    last: LastGroup,
) -> Result<Vec<Vec<SVector<f64, N>>>> {
    if order < 2 {
        return Err(Error::DegreeTooLow { min: 2, got: order });
    }
    let needed = match last {
        LastGroup::Truncated => 3,
        LastGroup::AsPrinted => order.max(3),
    };
    if points.len() < needed {
        return Err(Error::TooFewPoints {
            what: "OpenGL evaluator control points",
            needed,
            got: points.len(),
        });
    }
    finite_points("OpenGL evaluator control point", points)?;
    let mut groups = Vec::new();
    // never more than the points there are: the order may be huge
    let mut buffer: Vec<SVector<f64, N>> = Vec::with_capacity(order.min(points.len()));
    let mut kb = 0;
    while kb < points.len() {
        let fresh = &points[kb..kb.saturating_add(order).min(points.len())];
        match last {
            LastGroup::Truncated => {
                if fresh.len() >= 2 {
                    groups.push(fresh.to_vec());
                }
            }
            LastGroup::AsPrinted => {
                // overwrite the first kptLim entries of the persistent array
                if buffer.is_empty() {
                    buffer.extend_from_slice(fresh);
                } else {
                    buffer[..fresh.len()].copy_from_slice(fresh);
                }
                groups.push(buffer.clone());
            }
        }
        kb = kb.saturating_add(order - 1);
    }
    Ok(groups)
}

/// The polyline drawn by the OpenGL-evaluator spline: each group's Bézier curve sampled at
/// `u = k/nseg`, `k = 0 … nseg` (the listing's `glEvalCoord1f` loop), groups concatenated.
///
/// # Errors
/// As [`opengl_groups`]; [`Error::TooFewSamples`] for `nseg = 0`; [`Error::TooLarge`] if the
/// polyline's points exceed [`crate::error::MAX_ELEMENTS`].
pub fn opengl_polyline<const N: usize>(
    points: &[SVector<f64, N>],
    order: usize,
    nseg: usize,
    last: LastGroup,
) -> Result<Vec<SVector<f64, N>>> {
    if nseg == 0 {
        return Err(Error::TooFewSamples {
            what: "segments per group (nseg)",
            got: 0,
        });
    }
    let groups = opengl_groups(points, order, last)?;
    let per_group = crate::error::size_sum("segments per group (nseg)", nseg, 1)?;
    crate::error::size_product("OpenGL evaluator polyline points", groups.len(), per_group)?;
    let mut out = Vec::new();
    for group in groups {
        for k in 0..=nseg {
            let u = k as f64 / nseg as f64;
            out.push(bernstein_sum(&group, u)?);
        }
    }
    Ok(out)
}
