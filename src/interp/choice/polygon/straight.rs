//! Straight runs of the reference merged for the polygon's sweeps: a vertex that lies exactly
//! on the segment between its neighbours, strictly between them, changes neither the
//! outline as a point set nor its arc length, but as a candidate of the sweeps it adds
//! shortcuts by the square of a straight run's vertices (a rectangle sampled at unit steps
//! along sides of 50 000 has 10⁹). Only exact cases are merged: the differences and the
//! cross product are certified exact by error-free transformations, so no rounding decides.

use super::super::target::Target;
use crate::error::Result;
use crate::metrics::curve::{two_diff, two_prod};
use nalgebra::Vector2;

/// Whether `b` lies on the segment from `a` to `c`, strictly between them, proven in exact
/// arithmetic: the differences `b − a`, `c − b` and the products of their cross product are
/// exact in floating point (their rounding errors, by two-sum and fused multiply-add, are 0),
/// the cross product is 0 and the two differences point the same way.
pub(super) fn exactly_between(a: Vector2<f64>, b: Vector2<f64>, c: Vector2<f64>) -> bool {
    let exact_diff = |x: f64, y: f64| {
        let (d, e) = two_diff(x, y);
        (d.is_finite() && e == 0.0).then_some(d)
    };
    // the fused multiply-add's remainder is exact only above the underflow range (a product
    // of tiny factors rounds to 0 with a remainder of 0 that proves nothing)
    let exact_prod = |x: f64, y: f64| {
        let (p, e) = two_prod(x, y);
        let representable = if p == 0.0 {
            x == 0.0 || y == 0.0
        } else {
            p.abs() >= 2f64.powi(-969)
        };
        (p.is_finite() && representable && e == 0.0).then_some(p)
    };
    let (Some(ux), Some(uy), Some(vx), Some(vy)) = (
        exact_diff(b.x, a.x),
        exact_diff(b.y, a.y),
        exact_diff(c.x, b.x),
        exact_diff(c.y, b.y),
    ) else {
        return false;
    };
    let (Some(p), Some(q)) = (exact_prod(ux, vy), exact_prod(uy, vx)) else {
        return false;
    };
    // same direction: collinear (p = q) with no component of opposite signs, both non-zero
    let same_way = ux * vx >= 0.0 && uy * vy >= 0.0;
    let nonzero = (ux != 0.0 || uy != 0.0) && (vx != 0.0 || vy != 0.0);
    p == q && same_way && nonzero
}

/// The target with every vertex that lies exactly between its neighbours taken off (module
/// docs), `None` when there is none or the target is an exact shape's (whose vertices carry
/// its parameter). A closed target keeps its first vertex.
///
/// # Errors
/// As [`Target::polyline`] (not expected: the outline is the same).
pub(super) fn merged(target: &Target) -> Result<Option<Target>> {
    if target.is_exact_shape() {
        return Ok(None);
    }
    let points = target.reference();
    let mut kept: Vec<Vector2<f64>> = Vec::with_capacity(points.len());
    for (k, &p) in points.iter().enumerate() {
        // kept[last] is the previous vertex kept: p's predecessor on the merged outline
        let between = k + 1 < points.len()
            && kept
                .last()
                .is_some_and(|&a| exactly_between(a, p, points[k + 1]));
        if !between {
            kept.push(p);
        }
    }
    if kept.len() == points.len() {
        return Ok(None);
    }
    Target::polyline(&kept, target.is_closed(), target.tolerance()).map(Some)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_exact_interior_points_are_between() {
        let v = Vector2::new;
        assert!(exactly_between(v(0.0, 0.0), v(1.0, 0.0), v(5.0, 0.0)));
        assert!(exactly_between(v(0.0, 0.0), v(1.0, 2.0), v(3.0, 6.0)));
        // a turn back, a repeat, a bend of one unit in 2⁵³
        assert!(!exactly_between(v(0.0, 0.0), v(2.0, 0.0), v(1.0, 0.0)));
        assert!(!exactly_between(v(0.0, 0.0), v(0.0, 0.0), v(1.0, 0.0)));
        assert!(!exactly_between(
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(2.0, 2f64.powi(-53))
        ));
        // 0.1, 0.2, 0.3 are not exactly collinear steps in binary: not certified
        assert!(!exactly_between(v(0.1, 0.1), v(0.2, 0.2), v(0.3, 0.3001)));
        // products that underflow prove nothing: a tiny bend is not a straight run
        let t = 1e-300;
        assert!(!exactly_between(v(t, 0.0), v(0.0, t), v(-t, 0.5 * t)));
    }
}
