//! How far a plane curve is from the shape it draws, and how smooth it looks: the measures of
//! seed 004's comparison (spec §4: "a deviation about the width of the stroke" and a
//! "pleasing visual course").
//!
//! **Distances.** Both curves are dense polylines. The distance of a point to a polyline is
//! the exact minimum over its segments ([`segment_distance`]); the one-sided distance from
//! `A` to `B` is the largest such distance over the vertices of `A`,
//! `h(A, B) = maxₐ min_{s ∈ B} |a − s|`, and the symmetric Hausdorff distance is
//! `H(A, B) = max(h(A, B), h(B, A))`. Taken over vertices, `h` can miss at most the largest
//! distance reached inside a segment of `A`, which is at most half its length more — sample
//! densely ([`sample_pieces`]).
//!
//! Nearest segments are found through a bounding-volume tree of the segments
//! ([`SegmentTree`]: median splits, at most [`LEAF`] segments per leaf, so it takes `O(n)`
//! memory whatever the shape of the polyline), searched branch-and-bound; the one-sided
//! maximum stops searching a point as soon as it is nearer than the largest distance found
//! so far (Taha & Hanbury's early break), which does not change the result. Both are checked
//! against the brute-force minimum over all segments (tests/metrics.rs).
//!
//! **Smoothness.** The signed curvature `κ = (x′y″ − y′x″)/|C′|³` from exact derivatives
//! ([`crate::curve::signed_curvature`]), sampled along each piece, made dimensionless by a
//! length `L` (the shape's size): the number of sign changes of `κL` beyond a threshold
//! (inflections), the largest jump of `κL` across the breaks between pieces (a curvature
//! discontinuity shows as a jump; a C² curve has none), the largest `|κL|` and the samples
//! where the tangent vanishes (cusps).

use crate::curve::{signed_curvature, ParametricCurve};
use crate::error::{Error, Result};
use nalgebra::Vector2;

/// The most segments a leaf of a [`SegmentTree`] holds.
pub const LEAF: usize = 4;

/// The distance from `p` to the segment `ab` (to the point `a` when `a = b`), exact to a few
/// units of rounding of the distance itself at every magnitude.
///
/// The foot of the perpendicular is `a + t(b − a)`, `t = (p − a)·(b − a)/|b − a|²` clamped to
/// `[0, 1]`. At an end the distance is `|p − a|` or `|p − b|`; inside, it is
/// `|(p − a) × (b − a)| / |b − a|`. Both are formed from the differences `p − a`, `b − a`
/// carried with their rounding errors (two-sum) and the cross product with exact products
/// (fused multiply-add), in units of a power of two near the differences' size, so neither
/// the cancellation of a point near a long segment nor the squares of tiny or huge
/// coordinates lose the distance's digits: the error is a few `ε` of the distance plus
/// `ε²` of the segment's length.
pub fn segment_distance(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    // only beyond f64::MAX / 4 can a difference overflow: then in units of 4 (exact but for
    // subnormal bits, far below the rounding of such coordinates)
    let u = if p.amax().max(a.amax()).max(b.amax()) > f64::MAX / 4.0 {
        4.0
    } else {
        1.0
    };
    accurate_distance(p / u, a / u, b / u) * u
}

/// `x − y` and its rounding error: `x − y = d + e` exactly (Knuth's two-sum).
#[inline]
pub(crate) fn two_diff(x: f64, y: f64) -> (f64, f64) {
    let d = x - y;
    let z = d - x;
    (d, (x - (d - z)) - (y + z))
}

/// `x · y` and its rounding error: `x · y = p + e` exactly (finite, not underflowing).
#[inline]
pub(crate) fn two_prod(x: f64, y: f64) -> (f64, f64) {
    let p = x * y;
    (p, x.mul_add(y, -p))
}

/// A power of two near `m > 0` (finite), as a double: `2^⌊log₂ m⌋`, or 1 for `m = 0`.
#[inline]
fn power_near(m: f64) -> f64 {
    if m == 0.0 || !m.is_finite() {
        return 1.0;
    }
    if m.abs() < f64::MIN_POSITIVE {
        // subnormal: the smallest normal power, whose reciprocal is finite
        return f64::MIN_POSITIVE;
    }
    // a normal double with its significand cleared is 2^⌊log₂ |m|⌋ (the sign dropped)
    f64::from_bits(m.abs().to_bits() & 0x7ff0_0000_0000_0000)
}

/// [`segment_distance`] for coordinates at most `f64::MAX / 4` in magnitude (so the
/// differences are finite).
fn accurate_distance(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    // the differences with their errors: d = p − a, w = b − a
    let (dx, ex) = two_diff(p.x, a.x);
    let (dy, ey) = two_diff(p.y, a.y);
    let (wx, fx) = two_diff(b.x, a.x);
    let (wy, fy) = two_diff(b.y, a.y);
    // in units of a power of two near the larger difference (exact), so no square or
    // product below underflows or overflows
    let m = dx.abs().max(dy.abs()).max(wx.abs()).max(wy.abs());
    if m == 0.0 {
        return 0.0;
    }
    let k = 1.0 / power_near(m);
    let (dx, dy, ex, ey) = (dx * k, dy * k, ex * k, ey * k);
    let (wx, wy, fx, fy) = (wx * k, wy * k, fx * k, fy * k);
    let len2 = wx * wx + wy * wy;
    let dot = dx * wx + dy * wy;
    let back = if len2 == 0.0 || dot <= 0.0 {
        // the foot is a: |p − a|
        norm(dx + ex, dy + ey)
    } else if dot >= len2 {
        // the foot is b: |p − b| = |d − w|
        let (gx, gy) = (two_diff(dx, wx), two_diff(dy, wy));
        norm(gx.0 + (gx.1 + ex - fx), gy.0 + (gy.1 + ey - fy))
    } else {
        // inside: |d × w| / |w|, the cross product from exact products and the errors'
        // first-order terms
        let (p1, q1) = two_prod(dx, wy);
        let (p2, q2) = two_prod(dy, wx);
        let (s, r) = two_diff(p1, p2);
        let cross = s + (r + q1 - q2 + (ex * wy + dx * fy - ey * wx - dy * fx));
        cross.abs() / norm(wx + fx, wy + fy)
    };
    back / k
}

/// `√(x² + y²)` for `|x|, |y| ≤ 4` (the scaled differences of [`accurate_distance`]): the
/// plain formula, as accurate as `hypot` to a rounding, where the larger square is a normal
/// number (the smaller's underflow is then far below its rounding); `hypot` below.
#[inline]
fn norm(x: f64, y: f64) -> f64 {
    x.hypot(y)
}

#[derive(Debug, Clone, Copy)]
struct Node {
    lo: Vector2<f64>,
    hi: Vector2<f64>,
    /// A leaf: `order[first .. first + count]`; an inner node (`count == 0`): its children
    /// are nodes `first` and `first + 1`.
    first: u32,
    count: u32,
}

impl Node {
    /// The squared distance from `p` to the box (0 inside), in units of `1/k`.
    fn distance2(&self, p: Vector2<f64>, k: f64) -> f64 {
        let dx = (self.lo.x - p.x).max(p.x - self.hi.x).max(0.0) * k;
        let dy = (self.lo.y - p.y).max(p.y - self.hi.y).max(0.0) * k;
        dx * dx + dy * dy
    }
}

/// Relative slack of the tree's pruning (see the search in `SegmentTree::nearest`).
const PRUNE_SLACK: f64 = 1e-12;

/// The squared distance from `p` to `ab` by the plain formula `|(p − a) − t(b − a)|²`, for
/// pruning the search only: with coordinates at most 2 in magnitude its distance is within
/// [`CHEAP_REACH`] of the exact one (squares below `10⁻³⁰⁸` underflow, which only makes it
/// smaller).
#[inline]
fn cheap_distance2(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let ab = b - a;
    let d = p - a;
    let len2 = ab.norm_squared();
    let t = if len2 > 0.0 {
        (d.dot(&ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (d - ab * t).norm_squared()
}

/// How far [`cheap_distance2`]'s distance can be from the exact one, in units of `ε` times
/// the coordinates' magnitude (the differences, the foot and its subtraction: a few `ε` of
/// coordinates up to 2 each; taken generously).
const CHEAP_REACH: f64 = 64.0;

/// The segments of a polyline in a bounding-volume tree, for nearest-segment queries.
#[derive(Debug, Clone)]
pub struct SegmentTree {
    points: Vec<Vector2<f64>>,
    /// The largest coordinate magnitude.
    extent: f64,
    /// Segment `i` runs from `points[i]` to `points[i + 1]`.
    order: Vec<u32>,
    nodes: Vec<Node>,
}

impl SegmentTree {
    /// The tree of the polyline through `points` (a single point is a segment of length 0).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for no point; [`Error::NonFinite`] or
    /// [`Error::CoordinateTooLarge`] for a coordinate; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`] points.
    pub fn new(points: &[Vector2<f64>]) -> Result<Self> {
        Self::build(points, true)
    }

    /// The tree of the polyline through `points` split by position along it rather than in
    /// space: no sorting, so cheaper to build, and as good for a polyline whose consecutive
    /// segments lie near each other (a curve sampled densely). Its distances are
    /// [`SegmentTree::new`]'s exactly (both are the minimum over the segments).
    ///
    /// # Errors
    /// As [`SegmentTree::new`].
    pub fn along(points: &[Vector2<f64>]) -> Result<Self> {
        Self::build(points, false)
    }

    /// The tree, its nodes split at the median in space (`spatial`) or by position.
    fn build(points: &[Vector2<f64>], spatial: bool) -> Result<Self> {
        crate::error::size("polyline points", points.len())?;
        if points.is_empty() {
            return Err(Error::TooFewPoints {
                what: "polyline points",
                needed: 1,
                got: 0,
            });
        }
        crate::error::finite_points("polyline point", points)?;
        let mut points = points.to_vec();
        if points.len() == 1 {
            points.push(points[0]);
        }
        let segments = points.len() - 1;
        let mut tree = SegmentTree {
            extent: points.iter().map(|p| p.amax()).fold(0.0, f64::max),
            order: (0..segments as u32).collect(),
            nodes: Vec::with_capacity(2 * segments.div_ceil(LEAF) + 1),
            points,
        };
        tree.nodes.push(tree.bounds(0, segments));
        let mut stack = vec![(0usize, 0usize, segments)];
        while let Some((node, start, end)) = stack.pop() {
            if end - start <= LEAF {
                tree.nodes[node].first = start as u32;
                tree.nodes[node].count = (end - start) as u32;
                continue;
            }
            // split at the median of the segments' midpoints along the box's longer side
            let b = tree.nodes[node];
            let axis = usize::from(b.hi.y - b.lo.y > b.hi.x - b.lo.x);
            let mid = start + (end - start) / 2;
            let pts = &tree.points;
            let key = |i: &u32| pts[*i as usize][axis] + pts[*i as usize + 1][axis];
            if spatial {
                tree.order[start..end]
                    .select_nth_unstable_by(mid - start, |i, j| key(i).total_cmp(&key(j)));
            }
            let left = tree.nodes.len();
            let (lb, rb) = (tree.bounds(start, mid), tree.bounds(mid, end));
            tree.nodes.push(lb);
            tree.nodes.push(rb);
            tree.nodes[node].first = left as u32;
            stack.push((left, start, mid));
            stack.push((left + 1, mid, end));
        }
        Ok(tree)
    }

    /// The box of the segments `order[start..end]`, as a node without children.
    fn bounds(&self, start: usize, end: usize) -> Node {
        let mut lo = Vector2::repeat(f64::INFINITY);
        let mut hi = Vector2::repeat(f64::NEG_INFINITY);
        for &i in &self.order[start..end] {
            for p in [self.points[i as usize], self.points[i as usize + 1]] {
                lo = lo.inf(&p);
                hi = hi.sup(&p);
            }
        }
        Node {
            lo,
            hi,
            first: 0,
            count: 0,
        }
    }

    /// The polyline's vertices.
    pub fn points(&self) -> &[Vector2<f64>] {
        &self.points
    }

    /// The distance from `p` to the polyline: the minimum of [`segment_distance`] over its
    /// segments, exact to a few units of rounding of the distance at every magnitude.
    /// It is finite for `p` within [`crate::error::MAX_COORDINATE`]; beyond, or for a NaN
    /// coordinate, it is unspecified (`+∞` or NaN): check query points first.
    pub fn distance(&self, p: Vector2<f64>) -> f64 {
        self.nearest(p, 0.0).0
    }

    /// The distance from `p` to the polyline, except that the search may stop as soon as it
    /// knows the distance is below `stop` and return a bound below `stop` instead.
    ///
    /// The search prunes with the plain squared distance in units of a power of two near the
    /// coordinates' size (so no square overflows, and only squares far below the size
    /// underflow), and measures every segment that could tie or beat the best so far with
    /// the accurate [`segment_distance`]: the result is the brute-force minimum of
    /// [`segment_distance`] over the segments.
    ///
    /// Also returns the segment of the distance returned.
    fn nearest(&self, p: Vector2<f64>, stop: f64) -> (f64, usize) {
        let size = self.extent.max(p.amax());
        let u = power_near(size);
        let k = 1.0 / u;
        let q = p * k;
        let stop = stop * k;
        // the plain formula's distance is within `reach` of the exact one; the relative slack
        // covers the box distances' rounding
        let reach = CHEAP_REACH * f64::EPSILON * (size * k);
        // the accurate distance is taken only of the segments that may be the nearest, once
        // the search has passed them all: `upper` bounds the minimum (the least plain distance
        // plus `reach`), and a segment whose plain distance less `reach` is above it cannot be
        // it; the others wait in `pending`, in the order visited (the first of equal minima
        // wins, as a search that measured each at once would keep)
        let mut upper = f64::INFINITY;
        let mut pending = Pending::default();
        let measure = |s: usize| segment_distance(p, self.points[s], self.points[s + 1]) * k;
        // boxes and segments farther than this are skipped: (upper (1 + slack) + reach)²
        let mut limit = f64::INFINITY;
        // depth ≤ log₂(segments) + 1 < 64 for any size below MAX_ELEMENTS
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = self.nodes[stack[top] as usize];
            if node.distance2(p, k) > limit {
                continue;
            }
            if node.count > 0 {
                let first = node.first as usize;
                for &i in &self.order[first..first + node.count as usize] {
                    let (a, b) = (self.points[i as usize], self.points[i as usize + 1]);
                    let c2 = cheap_distance2(q, a * k, b * k);
                    if c2 > limit {
                        continue;
                    }
                    // the exact distance is at most the plain one plus `reach`: below `stop`,
                    // the caller needs no exact value
                    let plain = c2.sqrt();
                    let c = plain + reach;
                    if c < stop {
                        return (c * u, i as usize);
                    }
                    if c < upper {
                        upper = c;
                        let r = upper * (1.0 + PRUNE_SLACK) + reach;
                        limit = r * r;
                    }
                    pending.push(i as usize, plain - reach, upper, measure);
                }
                continue;
            }
            // the nearer child last, so it is searched first
            let (l, r) = (node.first, node.first + 1);
            let (dl, dr) = (
                self.nodes[l as usize].distance2(p, k),
                self.nodes[r as usize].distance2(p, k),
            );
            let (near, far) = if dl <= dr { (l, r) } else { (r, l) };
            stack[top] = far;
            stack[top + 1] = near;
            top += 2;
        }
        let (best, at) = pending.finish(upper, measure);
        (best * u, at)
    }

    /// Whether `segment_distance(p, a, b) < max` for segment `s` from `a` to `b`, decided by
    /// the plain formula where it is farther than its reach from `max` (as in
    /// [`SegmentTree::nearest`]), by [`segment_distance`] otherwise: the same answer, cheaper.
    fn nearer_than(&self, p: Vector2<f64>, s: usize, max: f64) -> bool {
        let (a, b) = (self.points[s], self.points[s + 1]);
        let size = self.extent.max(p.amax());
        let k = 1.0 / power_near(size);
        let reach = CHEAP_REACH * f64::EPSILON * (size * k);
        let c = cheap_distance2(p * k, a * k, b * k).sqrt();
        let m = max * k;
        if c + reach < m {
            true
        } else if c - reach >= m {
            false
        } else {
            segment_distance(p, a, b) < max
        }
    }

    /// The one-sided distance `maxᵢ min_{s} |from[i] − s|` from the points `from` to the
    /// polyline, and the index of a point where it is reached (`None` for no point). The
    /// points are visited spread out first, then in order with the previous point's nearest
    /// segment tried first ([`SegmentTree::farthest_below`]), which makes the early break
    /// effective on a curve's samples; the result does not depend on it.
    pub fn farthest(&self, from: &[Vector2<f64>]) -> (f64, Option<usize>) {
        self.farthest_below(from, f64::INFINITY)
    }

    /// As [`SegmentTree::farthest`], except that the search stops as soon as the distance
    /// found reaches `limit`: the result is exact when it is below `limit`, and otherwise a
    /// distance at least `limit` (a search comparing against its best so far needs no more).
    pub fn farthest_below(&self, from: &[Vector2<f64>], limit: f64) -> (f64, Option<usize>) {
        self.farthest_below_from(from, limit, None)
    }

    /// As [`SegmentTree::farthest_below`], with the point `first` (if it is an index of
    /// `from`) measured before the others: a search that asks whether a changed curve still
    /// reaches `limit` passes the point where the last one did, and stops at once when it does.
    /// The distance is [`SegmentTree::farthest_below`]'s whatever `first` is (below `limit` it
    /// is the exact maximum; at or above, at least `limit`).
    pub fn farthest_below_from(
        &self,
        from: &[Vector2<f64>],
        limit: f64,
        first: Option<usize>,
    ) -> (f64, Option<usize>) {
        let n = from.len();
        let mut max = 0.0;
        let mut at = None;
        if let Some(i) = first.filter(|&i| i < n) {
            let (d, _) = self.nearest(from[i], 0.0);
            max = d;
            at = Some(i);
            if max >= limit {
                return (max, at);
            }
        }
        // every SPREAD-th point first, so that the largest distance is near its end early;
        // then the others in order, each tried first on the segments where its predecessor
        // found one nearer than the largest so far (consecutive points of a curve lie near
        // each other): a point nearer than that changes nothing, whichever segment shows it
        let last = self.points.len() - 2;
        let mut hint: Option<usize> = None;
        let spread = (0..n).step_by(SPREAD);
        let rest = (0..n).filter(|i| i % SPREAD != 0);
        for i in spread.chain(rest) {
            let p = from[i];
            if at.is_some() && i % SPREAD != 0 {
                if let Some(h) = hint {
                    let near = (h..=(h + 1).min(last)).find(|&s| self.nearer_than(p, s, max));
                    if near.is_some() {
                        hint = near;
                        continue;
                    }
                }
            }
            let (d, s) = self.nearest(p, max);
            hint = Some(s);
            if d > max || at.is_none() {
                max = d;
                at = Some(i);
                if max >= limit {
                    break;
                }
            }
        }
        (max, at)
    }
}

/// The segments [`SegmentTree::nearest`] has passed that may be the nearest, waiting for
/// their accurate distance: at most [`PENDING`] (beyond, the oldest are measured at once), and
/// the least accurate distance measured so far with its segment.
#[derive(Default)]
struct Pending {
    /// `(segment, lower bound of its distance)`, in the order visited.
    waiting: [(usize, f64); PENDING],
    len: usize,
    /// The least accurate distance measured, and its segment (the first of equal ones).
    best: Option<(f64, usize)>,
}

/// How many segments [`Pending`] holds before it measures them.
const PENDING: usize = 16;

impl Pending {
    /// Adds segment `s` whose distance is at least `low`; drops those that cannot be below
    /// `upper` (their lower bound above it); measures the waiting ones by `measure` when
    /// full.
    fn push(&mut self, s: usize, low: f64, upper: f64, measure: impl Fn(usize) -> f64) {
        if low > upper {
            return;
        }
        if self.len == PENDING {
            self.keep_below(upper);
        }
        if self.len == PENDING {
            self.measure_all(&measure);
        }
        self.waiting[self.len] = (s, low);
        self.len += 1;
    }

    /// Drops the waiting segments whose lower bound is above `upper`, keeping the order.
    fn keep_below(&mut self, upper: f64) {
        let mut kept = 0;
        for j in 0..self.len {
            if self.waiting[j].1 <= upper {
                self.waiting[kept] = self.waiting[j];
                kept += 1;
            }
        }
        self.len = kept;
    }

    /// Measures every waiting segment, in order, into `best` (a tie keeps the earlier).
    fn measure_all(&mut self, measure: &impl Fn(usize) -> f64) {
        for j in 0..self.len {
            let s = self.waiting[j].0;
            let d = measure(s);
            if self.best.is_none_or(|(b, _)| d < b) {
                self.best = Some((d, s));
            }
        }
        self.len = 0;
    }

    /// The least accurate distance among the segments that may be the nearest, and its
    /// segment (`(∞, 0)` for none).
    fn finish(mut self, upper: f64, measure: impl Fn(usize) -> f64) -> (f64, usize) {
        self.keep_below(upper);
        self.measure_all(&measure);
        self.best.map_or((f64::INFINITY, 0), |(d, s)| (d, s))
    }
}

/// The points [`SegmentTree::farthest_below`] visits first: one in this many.
const SPREAD: usize = 16;

/// One-sided and symmetric distances between a curve and a reference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Distances {
    /// `h(curve, reference)`: the largest distance from a point of the curve to the
    /// reference (a curve straying from the shape).
    pub curve_to_reference: f64,
    /// `h(reference, curve)`: the largest distance from a point of the reference to the curve
    /// (a part of the shape the curve misses).
    pub reference_to_curve: f64,
}

impl Distances {
    /// The symmetric Hausdorff distance, the larger of the two.
    pub fn hausdorff(&self) -> f64 {
        self.curve_to_reference.max(self.reference_to_curve)
    }
}

/// The one-sided and symmetric distances between the polylines `curve` and `reference`
/// (module docs).
///
/// # Errors
/// As [`SegmentTree::new`] for either polyline.
pub fn polyline_distances(curve: &[Vector2<f64>], reference: &[Vector2<f64>]) -> Result<Distances> {
    distances_to(curve, &SegmentTree::new(reference)?)
}

/// As [`polyline_distances`] with the reference's tree built once (for many curves measured
/// against one shape).
///
/// # Errors
/// As [`SegmentTree::new`] for `curve`.
pub fn distances_to(curve: &[Vector2<f64>], reference: &SegmentTree) -> Result<Distances> {
    // a curve's samples follow it: its tree is split along it
    let to_curve = SegmentTree::along(curve)?;
    Ok(Distances {
        curve_to_reference: reference.farthest(curve).0,
        reference_to_curve: to_curve.farthest(reference.points()).0,
    })
}

/// The curve sampled at `per_piece` equally spaced parameters on each piece between
/// consecutive `breaks` (sorted, at least two), both ends of each piece included once: the
/// polyline distances are measured on.
///
/// # Errors
/// [`Error::TooFewPoints`] for fewer than two breaks; [`Error::TooFewSamples`] for fewer
/// than 2 samples per piece; [`Error::TooLarge`] for more than
/// [`crate::error::MAX_ELEMENTS`] samples; [`Error::Overflow`] for a sample that is not
/// finite.
pub fn sample_pieces<C: ParametricCurve<2> + ?Sized>(
    curve: &C,
    breaks: &[f64],
    per_piece: usize,
) -> Result<Vec<Vector2<f64>>> {
    let mut out = Vec::new();
    sample_pieces_into(curve, breaks, per_piece, &mut out)?;
    Ok(out)
}

/// As [`sample_pieces`], into `out` (cleared first), so that a search can reuse one buffer.
///
/// # Errors
/// As [`sample_pieces`].
pub fn sample_pieces_into<C: ParametricCurve<2> + ?Sized>(
    curve: &C,
    breaks: &[f64],
    per_piece: usize,
    out: &mut Vec<Vector2<f64>>,
) -> Result<()> {
    out.clear();
    let total = check_pieces("curve samples", breaks, per_piece)?;
    out.reserve(total);
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        for k in 0..per_piece - 1 {
            out.push(curve.point(a + (b - a) * (k as f64 / (per_piece - 1) as f64)));
        }
    }
    out.push(curve.point(breaks[breaks.len() - 1]));
    crate::error::derived_points("curve sample", out)
}

/// Checks at least two breaks and 2 … [`crate::error::MAX_ELEMENTS`] samples in all with
/// `per_piece` per piece; the total (pieces × per piece).
fn check_pieces(what: &'static str, breaks: &[f64], per_piece: usize) -> Result<usize> {
    if breaks.len() < 2 {
        return Err(Error::TooFewPoints {
            what: "curve breaks",
            needed: 2,
            got: breaks.len(),
        });
    }
    crate::error::samples("samples per piece", per_piece)?;
    crate::error::size_product(what, breaks.len() - 1, per_piece)
}

/// The signed curvature along each piece of `curve` at `per_piece` equally spaced parameters
/// (both ends of each piece: the curvature on either side of a break), `(t, κ(t))`, from exact
/// derivatives (NaN where the tangent vanishes).
///
/// # Errors
/// As [`sample_pieces`] (no finiteness check: a cusp is a NaN curvature).
pub fn curvature_profile<C: ParametricCurve<2> + ?Sized>(
    curve: &C,
    breaks: &[f64],
    per_piece: usize,
) -> Result<Vec<Vec<(f64, f64)>>> {
    check_pieces("curvature samples", breaks, per_piece)?;
    Ok(breaks
        .windows(2)
        .map(|w| {
            // the ends a hair inside the piece, so a piecewise curve is evaluated on it
            let (a, b) = (w[0], w[1]);
            let inset = (b - a) * 1e-9;
            (0..per_piece)
                .map(|k| {
                    let t = a + (b - a) * (k as f64 / (per_piece - 1) as f64);
                    let t = t.clamp(a + inset, b - inset);
                    let [_, d1, d2] = curve.derivatives2(t);
                    (t, signed_curvature(&d1, &d2))
                })
                .collect()
        })
        .collect())
}

/// How smooth a curve looks (module docs), from its [`curvature_profile`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Smoothness {
    /// Sign changes of `κL` (inflections), values with `|κL| ≤` [`FLAT`] counting as neither
    /// sign (straight stretches).
    pub inflections: usize,
    /// The largest jump of `κL` across a break between pieces.
    pub max_jump: f64,
    /// The largest `|κL|`.
    pub max_curvature: f64,
    /// Samples where the curvature is not finite (a vanishing tangent: a cusp).
    pub singular: usize,
}

/// Dimensionless curvatures `|κL|` at or below this count as straight (neither sign) when
/// counting inflections: a bend of a tenth of a radian over the whole length `L`.
pub const FLAT: f64 = 0.1;

/// The smoothness of a curvature profile with the length scale `length` (module docs).
pub fn smoothness(profile: &[Vec<(f64, f64)>], length: f64) -> Smoothness {
    let mut s = Smoothness {
        inflections: 0,
        max_jump: 0.0,
        max_curvature: 0.0,
        singular: 0,
    };
    let mut last_sign = 0.0;
    let mut end_of_last: Option<f64> = None;
    for piece in profile {
        for (k, &(_, kappa)) in piece.iter().enumerate() {
            let kl = kappa * length;
            if !kl.is_finite() {
                s.singular += 1;
                if k == 0 {
                    end_of_last = None;
                }
                continue;
            }
            if k == 0 {
                if let Some(prev) = end_of_last {
                    s.max_jump = s.max_jump.max((kl - prev).abs());
                }
            }
            s.max_curvature = s.max_curvature.max(kl.abs());
            if kl.abs() > FLAT {
                let sign = kl.signum();
                if last_sign != 0.0 && sign != last_sign {
                    s.inflections += 1;
                }
                last_sign = sign;
            }
        }
        end_of_last = piece.last().map(|p| p.1 * length).filter(|k| k.is_finite());
    }
    s
}
