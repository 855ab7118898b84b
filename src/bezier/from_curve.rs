//! Any curve as cubic Bézier segments — what drawing programs and SVG paths hold.
//!
//! The curve is taken piece by piece ([`ParametricCurve::span_at`]; a curve without pieces is
//! one). On a piece `[a, b]` the cubic through the curve's points at `u = 0, ⅓, ⅔, 1`
//! (`t = a + u(b − a)`) is written in Bézier form, `B = M⁻¹ P` with `M` the Bernstein matrix
//! at those parameters; it is then compared with the curve at the seven parameters
//! `u = 1/8, 2/8, …, 7/8` that it did not interpolate. A cubic (or lower-degree) polynomial piece
//! — a cubic spline's, a cardinal or Hermite spline's, a B-spline's of degree ≤ 3, a polygon's —
//! is its own interpolating cubic, so the check holds to rounding and the segment is the piece
//! itself: the conversion is exact. Any other piece (an Angular spline's, a NURBS arc, an
//! exact conic) is halved until every segment passes the check within `tolerance`, so the
//! segments stay within the tolerance at the checked parameters (a cubic approximation:
//! its error between them is of the same order, not bounded by the check).
//!
//! Only the points of the curve are used, never its derivative at a piece's end, so a curve
//! whose derivative jumps at a break (a B-spline with a knot of full multiplicity) converts
//! as well.

use crate::bezier::bernstein::bernstein3;
use crate::curve::ParametricCurve;
use crate::error::{Error, Result};
use nalgebra::SVector;

/// A cubic Bézier segment: its four control points.
pub type CubicSegment<const N: usize> = [SVector<f64, N>; 4];

/// The deepest halving of one piece (2¹⁶ segments a piece at most).
pub const MAX_HALVINGS: u32 = 16;

/// The curve as cubic Bézier segments within `tolerance` (module docs), in the order of the
/// parameter; consecutive segments share their end points exactly (each evaluated once at
/// the same parameter), and a closed curve's last end point is its first.
///
/// # Errors
/// [`Error::NotPositive`] for a tolerance that is not positive and finite;
/// [`Error::NonFinite`] where the curve is NaN or infinite; [`Error::NoConvergence`] if a
/// piece still misses the tolerance after [`MAX_HALVINGS`] halvings (a tolerance below the
/// rounding of the curve's own values, or a curve that is not continuous);
/// [`Error::TooLarge`] beyond [`crate::error::MAX_ELEMENTS`] segments.
pub fn cubic_segments<const N: usize, C: ParametricCurve<N> + ?Sized>(
    curve: &C,
    tolerance: f64,
) -> Result<Vec<CubicSegment<N>>> {
    crate::error::positive("Bézier conversion tolerance", tolerance)?;
    let (start, end) = curve.domain();
    let mut out = Vec::new();
    let mut a = start;
    while a < end {
        let b = match curve.span_at(a) {
            Some(span) if span.hi > a => span.hi.min(end),
            _ => end,
        };
        convert(curve, a, b, tolerance, 0, &mut out)?;
        a = b;
    }
    // a closed curve's end is its start: the two evaluations may differ by rounding, which
    // would leave the path open by an ulp
    if let (Some(first), Some(last)) = (out.first().map(|s| s[0]), out.last().map(|s| s[3])) {
        let scale = out
            .iter()
            .flat_map(|s| s.iter())
            .map(|p| p.amax())
            .fold(0.0f64, f64::max);
        if last != first && (last - first).amax() <= CLOSING_ROUNDING * scale {
            if let Some(s) = out.last_mut() {
                s[3] = first;
            }
        }
    }
    Ok(out)
}

/// Ends closer than this fraction of the curve's largest coordinate are one point (rounding of
/// two evaluations of a closed curve's start and end).
const CLOSING_ROUNDING: f64 = 64.0 * f64::EPSILON;

/// Appends the segments of `[a, b]`, halving it while the check fails.
fn convert<const N: usize, C: ParametricCurve<N> + ?Sized>(
    curve: &C,
    a: f64,
    b: f64,
    tolerance: f64,
    depth: u32,
    out: &mut Vec<CubicSegment<N>>,
) -> Result<()> {
    let at = |u: f64| -> Result<SVector<f64, N>> {
        // the ends exactly (a + 1·(b − a) need not be b), so neighbours share their points
        let t = if u == 1.0 { b } else { a + u * (b - a) };
        let p = curve.point(t);
        for &x in p.iter() {
            crate::error::finite("curve point", x)?;
        }
        Ok(p)
    };
    let q = [at(0.0)?, at(1.0 / 3.0)?, at(2.0 / 3.0)?, at(1.0)?];
    // the Bézier points of the cubic through q at u = 0, 1/3, 2/3, 1 (the inverse of the
    // Bernstein matrix at those parameters)
    let segment = [
        q[0],
        (-5.0 * q[0] + 18.0 * q[1] - 9.0 * q[2] + 2.0 * q[3]) / 6.0,
        (2.0 * q[0] - 9.0 * q[1] + 18.0 * q[2] - 5.0 * q[3]) / 6.0,
        q[3],
    ];
    let mut worst: f64 = 0.0;
    for k in 1..8 {
        let u = k as f64 / 8.0;
        worst = worst.max((bezier_point(&segment, u) - at(u)?).norm());
    }
    if worst <= tolerance {
        crate::error::size("Bézier segments", out.len() + 1)?;
        out.push(segment);
        return Ok(());
    }
    if depth >= MAX_HALVINGS {
        return Err(Error::NoConvergence {
            what: "cubic Bézier conversion of a curve piece",
            iterations: MAX_HALVINGS as usize,
        });
    }
    let m = 0.5 * (a + b);
    convert(curve, a, m, tolerance, depth + 1, out)?;
    convert(curve, m, b, tolerance, depth + 1, out)
}

/// The point of a cubic Bézier segment at `u` (Bernstein form, [`bernstein3`]).
pub fn bezier_point<const N: usize>(segment: &CubicSegment<N>, u: f64) -> SVector<f64, N> {
    let b = bernstein3(u);
    segment[0] * b[0] + segment[1] * b[1] + segment[2] * b[2] + segment[3] * b[3]
}
