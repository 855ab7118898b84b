//! Lower bounds on the error of whole classes of curves, which make a count provably minimal
//! when the class is all one point fewer can draw.
//!
//! **Widths.** The width of a set in the direction `u` is the length of its projection on
//! `u`. If two sets are within Hausdorff distance `d`, their widths in every direction
//! differ by at most `2d` (each projection lies within `d` of the other's). Hence:
//! - a straight segment has width 0 across itself, so its error is at least `w_min / 2`,
//!   half the reference's least width (an open B-spline of 2 vertices is a segment);
//! - a circle has the same width `2r` in every direction, so its error is at least
//!   `(w_max − w_min) / 4` (a closed Angular spline through 3 points is their circumcircle:
//!   every piece is an arc of the one circle through them).
//!
//! The least width of a polygon is attained across an edge of its convex hull, the largest
//! width is its diameter; both are computed exactly on the hull. Products of coordinates are
//! formed after an exact rescaling by a power of two, so that no input
//! within [`crate::error::MAX_COORDINATE`] overflows; points with a non-finite coordinate
//! are left out.

use nalgebra::Vector2;

/// A power of two `2ᵏ` that brings the largest finite coordinate of `points` into
/// `[½, 1]` (`k` within `±1020`; 1 for no finite non-zero coordinate): products of
/// rescaled differences cannot overflow, and the rescaling is exact.
fn unit_scale(points: &[Vector2<f64>]) -> f64 {
    let m = points
        .iter()
        .flat_map(|p| [p.x.abs(), p.y.abs()])
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    if m == 0.0 {
        return 1.0;
    }
    let k = (-m.log2().ceil()).clamp(-1020.0, 1020.0);
    2f64.powi(k as i32)
}

/// The convex hull of `points` (Andrew's monotone chain), counter-clockwise, without
/// repeated or collinear vertices; points with a non-finite coordinate are left out.
pub fn convex_hull(points: &[Vector2<f64>]) -> Vec<Vector2<f64>> {
    let mut p: Vec<Vector2<f64>> = points
        .iter()
        .copied()
        .filter(|q| q.x.is_finite() && q.y.is_finite())
        .collect();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let k = unit_scale(&p);
    let cross = |o: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>| {
        let (u, v) = (a * k - o * k, b * k - o * k);
        u.x * v.y - u.y * v.x
    };
    // the lower chain left to right, then the upper chain right to left
    let mut hull: Vec<Vector2<f64>> = Vec::with_capacity(2 * p.len());
    let chain = |hull: &mut Vec<Vector2<f64>>, points: &mut dyn Iterator<Item = Vector2<f64>>| {
        let start = hull.len();
        for q in points {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    };
    chain(&mut hull, &mut p.iter().copied());
    chain(&mut hull, &mut p.iter().rev().copied());
    hull
}

/// The least width and the diameter (largest width) of `points` (module docs); `(0, 0)`
/// for fewer than two distinct points.
pub fn widths(points: &[Vector2<f64>]) -> (f64, f64) {
    let hull = convex_hull(points);
    let n = hull.len();
    if n < 2 {
        return (0.0, 0.0);
    }
    // rescaled exactly: the products below cannot overflow (module docs)
    let k = unit_scale(&hull);
    let hull: Vec<Vector2<f64>> = hull.iter().map(|p| p * k).collect();
    let mut diameter: f64 = 0.0;
    for (i, a) in hull.iter().enumerate() {
        for b in &hull[i + 1..] {
            let d = b - a;
            diameter = diameter.max(d.x.hypot(d.y));
        }
    }
    if n < 3 {
        return (0.0, diameter / k);
    }
    let mut least = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (hull[i], hull[(i + 1) % n]);
        let e = b - a;
        let len = e.x.hypot(e.y);
        if len == 0.0 {
            continue;
        }
        let far = hull
            .iter()
            .map(|q| ((q.x - a.x) * e.y - (q.y - a.y) * e.x).abs() / len)
            .fold(0.0, f64::max);
        least = least.min(far);
    }
    (least / k, diameter / k)
}

/// The least error of any straight segment against `reference`: `w_min / 2`.
pub fn segment_bound(reference: &[Vector2<f64>]) -> f64 {
    0.5 * widths(reference).0
}

/// The least error of any circle against `reference`: `(w_max − w_min) / 4`.
pub fn circle_bound(reference: &[Vector2<f64>]) -> f64 {
    let (least, diameter) = widths(reference);
    0.25 * (diameter - least)
}

/// [`circle_bound`] for a circle drawn by samples: the sampled curve's chords cut the circle
/// by at most the sagitta `r (1 − cos(g/2))` of their arc `g`, taken here as `g ≤ π/8`
/// (far beyond the gaps of [`super::FINAL_SAMPLES`] samples per piece) with `r` at most the
/// reference's diameter `D`: the bound less `D (1 − cos(π/16))`.
pub fn sampled_circle_bound(reference: &[Vector2<f64>]) -> f64 {
    let (_, diameter) = widths(reference);
    circle_bound(reference) - diameter * (1.0 - (std::f64::consts::PI / 16.0).cos())
}
