//! Whether a clip region leaves drawn contours whole: every drawn point inside the region (or
//! on its edge) and no drawn segment crossing an edge of it. The SVG document reader accepts a
//! `clip-path` that passes this test (it changes nothing of the outline) and refuses one that
//! does not.

use super::flatten::Contour;
use nalgebra::Vector2;

/// How a drawn path is filled: which points its contours enclose.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FillRule {
    /// SVG's `nonzero`.
    NonZero,
    /// SVG's `evenodd`.
    EvenOdd,
}

/// The most pairs of (drawn segment, region edge) compared: beyond, the test is refused rather
/// than run for minutes.
const MAX_PAIRS: u64 = 200_000_000;

/// `Ok` if every contour of `drawn` lies inside the union of the filled regions `region`
/// (each a path's contours with its fill rule), edges included; `Err` with the reason
/// otherwise.
pub(crate) fn contains(
    region: &[(Vec<Contour>, FillRule)],
    drawn: &[&Contour],
) -> std::result::Result<(), String> {
    let edges: Vec<(Vector2<f64>, Vector2<f64>)> = region
        .iter()
        .flat_map(|(contours, _)| contours.iter())
        .flat_map(|c| c.points.windows(2).map(|w| (w[0], w[1])))
        .collect();
    if edges.is_empty() {
        return if drawn.is_empty() {
            Ok(())
        } else {
            Err("the clip region is empty".into())
        };
    }
    let segments: u64 = drawn
        .iter()
        .map(|c| c.points.len().saturating_sub(1) as u64)
        .sum();
    if segments.saturating_mul(edges.len() as u64) > MAX_PAIRS {
        return Err(format!(
            "{segments} drawn segments against {} clip edges are too many to compare",
            edges.len()
        ));
    }
    // a scale for "on the edge": rounding of the parser's single precision
    let size = edges
        .iter()
        .flat_map(|(a, b)| [a.amax(), b.amax()])
        .fold(0.0f64, f64::max);
    let near = 1e-6 * size.max(f64::MIN_POSITIVE);
    for c in drawn {
        for &p in &c.points {
            let on_edge = edges
                .iter()
                .any(|&(a, b)| crate::metrics::curve::segment_distance(p, a, b) <= near);
            if !on_edge && !inside(region, p) {
                return Err(format!(
                    "the point ({:.6}, {:.6}) lies outside it",
                    p.x + 0.0,
                    0.0 - p.y
                ));
            }
        }
        for w in c.points.windows(2) {
            if let Some(&(a, b)) = edges.iter().find(|&&(a, b)| crosses(w[0], w[1], a, b)) {
                return Err(format!(
                    "the segment from ({:.6}, {:.6}) to ({:.6}, {:.6}) crosses its edge from ({:.6}, {:.6}) to ({:.6}, {:.6})",
                    w[0].x, -w[0].y, w[1].x, -w[1].y, a.x, -a.y, b.x, -b.y
                ));
            }
        }
    }
    Ok(())
}

/// Whether `p` is inside one of the regions (its winding number by the region's rule).
fn inside(region: &[(Vec<Contour>, FillRule)], p: Vector2<f64>) -> bool {
    region.iter().any(|(contours, rule)| {
        let winding: i64 = contours
            .iter()
            .flat_map(|c| c.points.windows(2))
            .map(|w| winding_step(w[0], w[1], p))
            .sum();
        match rule {
            FillRule::NonZero => winding != 0,
            FillRule::EvenOdd => winding % 2 != 0,
        }
    })
}

/// The signed crossing of the horizontal ray from `p` to +x by the edge
/// `a → b` (+1 upward, −1 downward, 0 none), half-open in `y`.
fn winding_step(a: Vector2<f64>, b: Vector2<f64>, p: Vector2<f64>) -> i64 {
    let cross = (b - a).perp(&(p - a));
    if a.y <= p.y && b.y > p.y && cross > 0.0 {
        1
    } else if b.y <= p.y && a.y > p.y && cross < 0.0 {
        -1
    } else {
        0
    }
}

/// Whether the segments `p q` and `a b` cross properly (each one's ends strictly on both sides
/// of the other's line).
fn crosses(p: Vector2<f64>, q: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> bool {
    let side = |u: Vector2<f64>, v: Vector2<f64>, w: Vector2<f64>| (v - u).perp(&(w - u));
    let (d1, d2) = (side(a, b, p), side(a, b, q));
    let (d3, d4) = (side(p, q, a), side(p, q, b));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}
