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

/// A clip region as simple shapes (each an outer contour and its holes, none overlapping):
/// the union of `region`'s filled paths, each filled by its own rule (i_overlay's boolean
/// operations, on an `i64` grid).
pub(crate) type Shapes = Vec<Vec<Vec<[f64; 2]>>>;

/// The contours of `contours` as i_overlay's closed contours (the repeated closing point off).
fn rings(contours: &[Contour]) -> Vec<Vec<[f64; 2]>> {
    contours
        .iter()
        .map(|c| {
            let mut ring: Vec<[f64; 2]> = c.points.iter().map(|p| [p.x, p.y]).collect();
            if ring.len() > 1 && ring.first() == ring.last() {
                ring.pop();
            }
            ring
        })
        .filter(|r| r.len() >= 3)
        .collect()
}

fn overlay_rule(rule: FillRule) -> i_overlay::core::fill_rule::FillRule {
    match rule {
        FillRule::NonZero => i_overlay::core::fill_rule::FillRule::NonZero,
        FillRule::EvenOdd => i_overlay::core::fill_rule::FillRule::EvenOdd,
    }
}

/// The union of the filled regions `region` (module docs of [`Shapes`]).
pub(crate) fn region_shapes(region: &[(Vec<Contour>, FillRule)]) -> Shapes {
    use i_overlay::float::simplify::SimplifyShape;
    let mut all: Shapes = Vec::new();
    for (contours, rule) in region {
        all.extend(rings(contours).simplify_shape_as::<i64>(overlay_rule(*rule)));
    }
    // simple shapes of consistent orientation: the non-zero rule is their union
    all.simplify_shape_as::<i64>(i_overlay::core::fill_rule::FillRule::NonZero)
}

/// The closed contours of `shapes` (outer contours and holes), each closed by its first point.
fn contours_of(shapes: Shapes) -> Vec<Contour> {
    shapes
        .into_iter()
        .flatten()
        .filter(|ring| ring.len() >= 3)
        .map(|ring| {
            let mut points: Vec<Vector2<f64>> =
                ring.iter().map(|p| Vector2::new(p[0], p[1])).collect();
            points.push(points[0]);
            Contour {
                points,
                closed: true,
            }
        })
        .collect()
}

/// What a viewer fills of `contours` (filled by `rule`) inside the clip region `clip`: the
/// boundary of their intersection, as closed contours.
pub(crate) fn clipped_fill(contours: &[Contour], rule: FillRule, clip: &Shapes) -> Vec<Contour> {
    use i_overlay::core::overlay_rule::OverlayRule;
    use i_overlay::float::simplify::SimplifyShape;
    use i_overlay::float::single::SingleFloatOverlay;
    let filled = rings(contours).simplify_shape_as::<i64>(overlay_rule(rule));
    contours_of(filled.overlay_as::<i64>(
        clip,
        OverlayRule::Intersect,
        i_overlay::core::fill_rule::FillRule::NonZero,
    ))
}

/// The parts of the centre lines `contours` inside the clip region `clip` (its edges
/// included), as open contours.
pub(crate) fn clipped_lines(contours: &[Contour], clip: &Shapes) -> Vec<Contour> {
    use i_overlay::float::clip::FloatClip;
    use i_overlay::string::clip::ClipRule;
    let rule = ClipRule {
        invert: false,
        boundary_included: true,
    };
    let mut out = Vec::new();
    for c in contours {
        let line: Vec<[f64; 2]> = c.points.iter().map(|p| [p.x, p.y]).collect();
        let pieces =
            line.clip_by_as::<i64>(clip, i_overlay::core::fill_rule::FillRule::NonZero, rule);
        out.extend(
            pieces
                .into_iter()
                .filter(|p| p.len() >= 2)
                .map(|p| Contour {
                    points: p.iter().map(|q| Vector2::new(q[0], q[1])).collect(),
                    closed: false,
                }),
        );
    }
    out
}
