//! The shape a search draws: a dense reference, its tolerance, the arc coordinate along it,
//! the weights whose equal steps place points, and the mirror symmetries of the shape.

use super::symmetry::{mirrors, ArcShape, Mirror};
use super::{Measure, Scratch, FINAL_SAMPLES, SEARCH_SAMPLES};
use crate::curve::ParametricCurve;
use crate::error::{Error, Result};
use crate::interp::methods::Method;
use crate::metrics::curve::{
    curvature_profile, distances_to, segment_distance, smoothness, SegmentTree,
};
use crate::shapes::Shape;
use nalgebra::Vector2;

/// Samples per piece of the curvature profile behind [`Measure::smoothness`].
const CURVATURE_SAMPLES: usize = 64;

/// A shape to draw (module docs).
#[derive(Debug, Clone)]
pub struct Target {
    tree: SegmentTree,
    arc: Vec<f64>,
    /// The exact shape and the parameter of each reference vertex.
    exact: Option<(Shape, Vec<f64>)>,
    closed: bool,
    tolerance: f64,
    size: f64,
    /// `(W, s)` breakpoints of the placement weight with `β = 1`: the normalised turning.
    turning: Vec<(f64, f64)>,
    /// Arc positions of the corners: vertices turning by more than `CORNER_TURN` (30°).
    corners: Vec<f64>,
    /// Inflections of the exact shape (for comparison with a curve's), if known.
    shape_inflections: Option<usize>,
    /// The mirror symmetries of the reference ([`super::symmetry`]).
    mirrors: Vec<Mirror>,
    /// For a reference of more than [`COARSE_ABOVE`] vertices: its simplification within
    /// [`COARSE_FRACTION`] of the tolerance ([`simplified`]), against which the search's error
    /// is measured ([`Target::measure`] always uses the whole reference).
    coarse: Option<(SegmentTree, Vec<f64>)>,
}

/// References with more vertices than this are searched against a simplification
/// ([`Target::measure`] stays exact): a digitised outline of 10⁴ points costs the search its
/// distance from every vertex to every curve tried, a simplification within a sixteenth of the
/// tolerance a few hundred. The paper's shapes (2 049 vertices: exactly this), letters
/// and coast are not above it.
pub const COARSE_ABOVE: usize = 2049;

/// The simplification's distance from the reference, as a fraction of the tolerance: the
/// compass search stops at 0.9 of the tolerance measured on it, 0.9625 at most on the
/// reference, and every answer is measured on the reference itself. (A sixty-fourth before:
/// a quarter of the vertices again, for the same counts on the outlines tried.)
pub const COARSE_FRACTION: f64 = 1.0 / 16.0;

/// A reference vertex turning by more than this (radians, 30°) is a corner, which the
/// feature placement puts a point on.
pub(crate) const CORNER_TURN: f64 = std::f64::consts::FRAC_PI_6;

impl Target {
    /// The target of a dense polyline `points` (a closed one ends where it starts: the first
    /// point is repeated at the end if it is not there), drawn within `tolerance`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 2 points (3 distinct for a closed target);
    /// [`Error::NonFinite`] / [`Error::CoordinateTooLarge`] for a coordinate;
    /// [`Error::NotPositive`] for a tolerance that is not finite and positive;
    /// [`Error::Degenerate`] for a polyline of zero length; [`Error::Overflow`] if its length
    /// is not finite; [`Error::TooLarge`] beyond [`crate::error::MAX_ELEMENTS`] points.
    pub fn polyline(points: &[Vector2<f64>], closed: bool, tolerance: f64) -> Result<Self> {
        crate::error::positive("target tolerance", tolerance)?;
        let mut points = points.to_vec();
        if closed && points.len() > 1 && points[0] != points[points.len() - 1] {
            points.push(points[0]);
        }
        let needed = if closed { 4 } else { 2 };
        if points.len() < needed {
            return Err(Error::TooFewPoints {
                what: "target polyline points",
                needed,
                got: points.len(),
            });
        }
        let tree = SegmentTree::new(&points)?;
        let points = tree.points();
        let mut arc = Vec::with_capacity(points.len());
        let mut s = 0.0;
        arc.push(0.0);
        for w in points.windows(2) {
            // hypot: no overflow of the squares near the coordinate limit
            let d = w[1] - w[0];
            s += d.x.hypot(d.y);
            arc.push(s);
        }
        crate::error::derived("target length", s)?;
        if s <= 0.0 {
            return Err(Error::Degenerate {
                what: "target polyline",
                reason: "it has zero length",
            });
        }
        let (lo, hi) = points.iter().fold(
            (
                Vector2::repeat(f64::INFINITY),
                Vector2::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), p| (lo.inf(p), hi.sup(p)),
        );
        let size = (hi - lo).amax();
        let angles = turning_angles(points, closed);
        let turning = turning_weight(&angles, &arc);
        let mut corners: Vec<f64> = angles
            .iter()
            .zip(&arc)
            .filter(|(&a, _)| a > CORNER_TURN)
            .map(|(_, &s)| s)
            .collect();
        if !closed {
            // the ends are points anyway
            corners.retain(|&c| c > 0.0 && c < s);
        }
        Ok(Target {
            tree,
            arc,
            exact: None,
            closed,
            tolerance,
            size,
            turning,
            corners,
            shape_inflections: None,
            mirrors: Vec::new(),
            coarse: None,
        }
        .with_mirrors()
        .with_coarse())
    }

    /// The target of an exact shape: its reference with `samples` segments
    /// ([`Shape::reference`]), points placed on the exact curve, the shape's own tolerance
    /// ([`Shape::tolerance`]).
    ///
    /// # Errors
    /// As [`Shape::reference`] and [`Target::polyline`].
    pub fn shape(shape: &Shape, samples: usize) -> Result<Self> {
        let shape = shape.validated()?;
        let reference = shape.reference(samples)?;
        let mut target = Target::polyline(&reference, shape.is_closed(), shape.tolerance())?;
        // the parameter of each reference vertex: equally spaced, or arc length on the
        // rectangle (its reference follows the sides)
        let (a, b) = shape.domain();
        let params: Vec<f64> = match shape {
            Shape::Rectangle { .. } => target.arc.clone(),
            _ => {
                let n = reference.len() - 1;
                (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect()
            }
        };
        let breaks = shape_breaks(&shape);
        let profile = curvature_profile(&shape, &breaks, CURVATURE_SAMPLES)?;
        target.shape_inflections = Some(smoothness(&profile, target.size).inflections);
        target.exact = Some((shape, params));
        Ok(target)
    }

    /// The same target with another tolerance.
    ///
    /// # Errors
    /// [`Error::NotPositive`] for a tolerance that is not finite and positive.
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        self.tolerance = crate::error::positive("target tolerance", tolerance)?;
        Ok(self.with_coarse())
    }

    /// Sets [`Target::coarse`] for the current tolerance.
    fn with_coarse(mut self) -> Self {
        let points = self.tree.points();
        self.coarse = (points.len() > COARSE_ABOVE)
            .then(|| {
                let kept = simplified_indices(points, COARSE_FRACTION * self.tolerance);
                let coarse: Vec<Vector2<f64>> = kept.iter().map(|&i| points[i]).collect();
                let arcs = kept.iter().map(|&i| self.arc[i]).collect();
                SegmentTree::new(&coarse).ok().map(|t| (t, arcs))
            })
            .flatten();
        self
    }

    /// Whether the reference has more than [`COARSE_ABOVE`] vertices, so the search measures
    /// its candidates against a simplification ([`simplified`]) and only its answers exactly.
    pub fn is_dense(&self) -> bool {
        self.coarse.is_some()
    }

    /// The polyline the search measures against, with the arc position of each vertex: the
    /// reference's simplification on a dense target ([`Target::is_dense`]), else the
    /// reference.
    pub(super) fn search_reference(&self) -> (&[Vector2<f64>], &[f64]) {
        match &self.coarse {
            Some((tree, arcs)) => (tree.points(), arcs),
            None => (self.tree.points(), &self.arc),
        }
    }

    /// The reference polyline.
    pub fn reference(&self) -> &[Vector2<f64>] {
        self.tree.points()
    }

    /// Whether the shape is closed.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The tolerance.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The larger side of the reference's bounding box (the length that makes curvatures
    /// dimensionless).
    pub fn size(&self) -> f64 {
        self.size
    }

    /// The reference's length `L`.
    pub fn length(&self) -> f64 {
        self.arc[self.arc.len() - 1]
    }

    /// The inflections of the exact shape, when the target is one.
    pub fn shape_inflections(&self) -> Option<usize> {
        self.shape_inflections
    }

    /// The point at arc length `s` (module docs): on a closed target `s` wraps around, on an
    /// open one it extrapolates beyond the ends. It is finite for every finite `s` on a
    /// closed target; on an open one, or for a NaN `s`, it can be non-finite: check `s`
    /// first.
    pub fn point(&self, s: f64) -> Vector2<f64> {
        let (i, f) = self.locate(s);
        match &self.exact {
            Some((shape, t)) => shape.point(t[i] + (t[i + 1] - t[i]) * f),
            None => {
                let p = self.reference();
                p[i] + (p[i + 1] - p[i]) * f
            }
        }
    }

    /// The reference segment of arc `s` (wrapped on a closed target) and the fraction along
    /// it (beyond the ends of an open target: the end segment's, extrapolated).
    fn locate(&self, s: f64) -> (usize, f64) {
        let len = self.length();
        let s = if self.closed { s.rem_euclid(len) } else { s };
        let last = self.arc.len() - 2;
        let i = self
            .arc
            .partition_point(|&x| x <= s)
            .saturating_sub(1)
            .min(last);
        let (s0, s1) = (self.arc[i], self.arc[i + 1]);
        (i, if s1 > s0 { (s - s0) / (s1 - s0) } else { 0.0 })
    }

    /// The arc position of the vertex of the searched reference ([`Target::search_reference`])
    /// nearest to `p`: where on the shape a point of a curve lies, roughly (to the vertices'
    /// spacing); `None` for a point that is not finite.
    pub(super) fn search_arc_near(&self, p: Vector2<f64>) -> Option<f64> {
        let (points, arcs) = self.search_reference();
        let nearest = (0..points.len())
            .map(|i| ((points[i] - p).norm_squared(), i))
            .filter(|(d, _)| d.is_finite())
            .min_by(|a, b| a.0.total_cmp(&b.0))?;
        Some(arcs[nearest.1])
    }

    /// The arc position of the reference point nearest to `p` (on a closed target in
    /// `[0, L]`).
    pub(super) fn arc_of(&self, p: Vector2<f64>) -> f64 {
        let points = self.reference();
        let nearest = (0..points.len() - 1).min_by(|&i, &j| {
            let d = |k: usize| segment_distance(p, points[k], points[k + 1]);
            d(i).total_cmp(&d(j))
        });
        let Some(i) = nearest else {
            return 0.0;
        };
        let (a, b) = (points[i], points[i + 1]);
        let t = (p - a).dot(&(b - a)) / (b - a).norm_squared();
        let t = if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.0
        };
        self.arc[i] + t * (self.arc[i + 1] - self.arc[i])
    }

    /// The shape's own parameter at arc `s`, when the target is an exact shape; `None`
    /// otherwise, or if `s` or the parameter is not finite.
    pub fn parameter_at(&self, s: f64) -> Option<f64> {
        if !s.is_finite() {
            return None;
        }
        let (i, f) = self.locate(s);
        self.exact
            .as_ref()
            .map(|(_, t)| t[i] + (t[i + 1] - t[i]) * f)
            .filter(|t| t.is_finite())
    }

    /// The exact shape's point at its parameter `t` (beyond its domain: the formula
    /// continued), when the target is an exact shape; `None` otherwise, or if the point is
    /// not finite.
    pub fn point_at_parameter(&self, t: f64) -> Option<Vector2<f64>> {
        self.exact
            .as_ref()
            .map(|(shape, _)| shape.point(t))
            .filter(|p| p.x.is_finite() && p.y.is_finite())
    }

    /// The weight `w(s) ∈ [0, 1]` on `[0, L]` whose equal steps place points (module docs,
    /// step 1), monotone in `s`; continued on a closed target by one per turn, so that
    /// `w(s + L) = w(s) + 1`.
    pub(super) fn weight(&self, weight: Weight, s: f64) -> f64 {
        let len = self.length();
        let turns = if self.closed { (s / len).floor() } else { 0.0 };
        let s = s - turns * len;
        let w = match weight {
            Weight::Arc => s / len,
            Weight::Turning(beta) if !self.turning.is_empty() => {
                (1.0 - beta) * s / len + beta * turning_at(&self.turning, s)
            }
            Weight::Turning(_) => s / len,
            Weight::Parameter => match &self.exact {
                Some((_, t)) => {
                    let (t0, t1) = (t[0], t[t.len() - 1]);
                    let at = self.parameter_at(s).unwrap_or(t0);
                    (at - t0) / (t1 - t0)
                }
                None => s / len,
            },
        };
        turns + w
    }

    /// The arc `s ≥ anchor` where the weight grown since `anchor` reaches `f` (a fraction of a
    /// turn), by bisection on the monotone weight; within `[anchor, anchor + L]`.
    pub(super) fn weight_inverse(&self, weight: Weight, anchor: f64, f: f64) -> f64 {
        let len = self.length();
        let w0 = self.weight(weight, anchor);
        let (mut lo, mut hi) = (anchor, anchor + len);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.weight(weight, mid) - w0 < f {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        hi
    }

    /// `n` arcs at equal steps of `weight` from `anchor`: on a closed target shifted by
    /// `phase` steps, on an open one from end to end (`anchor` is then the start).
    pub(super) fn equal_steps(
        &self,
        weight: Weight,
        anchor: f64,
        n: usize,
        phase: f64,
    ) -> Vec<f64> {
        let len = self.length();
        if self.closed {
            (0..n)
                .map(|k| self.weight_inverse(weight, anchor, (k as f64 + phase) / n as f64))
                .collect()
        } else {
            let n = n.max(2);
            (0..n)
                .map(|k| match k {
                    0 => 0.0,
                    k if k == n - 1 => len,
                    k => self.weight_inverse(weight, 0.0, k as f64 / (n - 1) as f64),
                })
                .collect()
        }
    }

    /// Whether the target is an exact shape's (points are placed on the shape).
    pub(super) fn is_exact_shape(&self) -> bool {
        self.exact.is_some()
    }

    /// Whether the target is an exact shape whose parameter differs from arc length (the
    /// rectangle's does not).
    pub(super) fn has_own_parameter(&self) -> bool {
        matches!(&self.exact, Some((shape, _)) if !matches!(shape, Shape::Rectangle { .. }))
    }

    /// The arc length at each reference vertex.
    pub(super) fn arcs(&self) -> &[f64] {
        &self.arc
    }

    /// The mirror symmetries found on the reference.
    pub(super) fn mirrors(&self) -> &[Mirror] {
        &self.mirrors
    }

    fn with_mirrors(mut self) -> Self {
        self.mirrors = mirrors(&self);
        self
    }

    /// `n` positions of initial placement (module docs, step 1) with turning share `beta`
    /// and, on a closed target, a shift of `phase` steps.
    pub fn placement(&self, n: usize, beta: f64, phase: f64) -> Vec<f64> {
        self.equal_steps(Weight::Turning(beta), 0.0, n, phase)
    }

    /// `n` positions with a point on every corner (`CORNER_TURN` (30°)) and the rest spread
    /// over the arcs between corners — one in each first if there are enough, then in
    /// proportion to the arcs' lengths (largest remainders) — equally spaced within each (on
    /// a polygon: points on the sides, so that three points in a row are collinear); `None`
    /// without corners or with fewer than `n` places for them.
    pub fn feature_placement(&self, n: usize) -> Option<Vec<f64>> {
        let len = self.length();
        let mut anchors = self.corners.clone();
        if !self.closed {
            anchors.insert(0, 0.0);
            anchors.push(len);
        }
        if self.corners.is_empty() || n < anchors.len() {
            return None;
        }
        let gaps: Vec<f64> = if self.closed {
            (0..anchors.len())
                .map(|i| {
                    let next = anchors.get(i + 1).copied().unwrap_or(anchors[0] + len);
                    next - anchors[i]
                })
                .collect()
        } else {
            anchors.windows(2).map(|w| w[1] - w[0]).collect()
        };
        // one point inside every arc first when there are enough (then three points in a
        // row lie on each side of a polygon), the rest in proportion to the arcs' lengths
        let mut spare = n - anchors.len();
        let base = usize::from(spare >= gaps.len());
        spare -= base * gaps.len();
        let total: f64 = gaps.iter().sum();
        let quota: Vec<f64> = gaps.iter().map(|g| spare as f64 * g / total).collect();
        let mut fill: Vec<usize> = quota.iter().map(|q| q.floor() as usize + base).collect();
        // fewer left than gaps: the fractional parts sum to less than their number
        let left = (spare + base * gaps.len()).saturating_sub(fill.iter().sum());
        let mut order: Vec<usize> = (0..gaps.len()).collect();
        let frac = |i: usize| quota[i] - quota[i].floor();
        order.sort_by(|&i, &j| frac(j).total_cmp(&frac(i)));
        for &i in order.iter().take(left) {
            fill[i] += 1;
        }
        let mut out = Vec::with_capacity(n);
        for (i, (&g, &k)) in gaps.iter().zip(&fill).enumerate() {
            out.push(anchors[i]);
            out.extend((1..=k).map(|j| anchors[i] + g * j as f64 / (k + 1) as f64));
        }
        if !self.closed {
            out.push(len);
        }
        Some(out)
    }

    /// The error and smoothness of `method` through `points` (closed as the target is),
    /// with [`FINAL_SAMPLES`] samples per piece.
    ///
    /// # Errors
    /// The errors of [`Method::curve`]; [`Error::Overflow`] for a curve that is not finite.
    pub fn measure(&self, method: &Method, points: &[Vector2<f64>]) -> Result<Measure> {
        let curve = method.curve(points, self.closed)?;
        let breaks = curve.breaks();
        let mut line = Vec::new();
        curve.sample_pieces_into(FINAL_SAMPLES, &mut line)?;
        let distances = distances_to(&line, &self.tree)?;
        let profile = curvature_profile(&curve, &breaks, CURVATURE_SAMPLES)?;
        Ok(Measure {
            distances,
            smoothness: smoothness(&profile, self.size),
            counted: method.counted_points(points.len(), self.closed),
        })
    }

    /// The coarse error used while searching (infinite for a configuration the method
    /// refuses).
    pub(super) fn search_error(
        &self,
        method: &Method,
        points: &[Vector2<f64>],
        buf: &mut Scratch,
    ) -> f64 {
        self.search_error_below(method, points, buf, f64::INFINITY)
    }

    /// [`Target::search_error`] when it is below `limit`; otherwise a value at least `limit`
    /// (the measure stops as soon as it knows: a search that keeps only what beats its best
    /// so far decides alike).
    pub(super) fn search_error_below(
        &self,
        method: &Method,
        points: &[Vector2<f64>],
        buf: &mut Scratch,
        limit: f64,
    ) -> f64 {
        let Ok(curve) = method.curve(points, self.closed) else {
            return f64::INFINITY;
        };
        if curve
            .sample_pieces_into(SEARCH_SAMPLES, &mut buf.line)
            .is_err()
        {
            return f64::INFINITY;
        }
        // the simplification is within COARSE_FRACTION of the tolerance of the reference (in
        // Hausdorff distance: every point of either lies that close to the other), so the
        // error against it is too
        let reference = self.coarse.as_ref().map_or(&self.tree, |c| &c.0);
        if crate::error::finite_points("curve sample", &buf.line).is_err() {
            return f64::INFINITY;
        }
        let (away, at) = reference.farthest_below_from(&buf.line, limit, buf.worst_sample);
        buf.worst_sample = at;
        if away >= limit {
            return away;
        }
        // the samples follow the curve: a tree split along it needs no sorting
        let Ok(curve) = SegmentTree::along(&buf.line) else {
            return f64::INFINITY;
        };
        let (missed, vertex) =
            curve.farthest_below_from(reference.points(), limit, buf.worst_vertex);
        buf.worst_vertex = vertex;
        if missed < limit {
            buf.worst_point = if missed > away {
                vertex.map(|v| reference.points()[v])
            } else {
                at.map(|i| buf.line[i])
            };
        }
        away.max(missed)
    }
}

/// The most vertices one segment of [`simplified`] stands for.
pub const MAX_RUN: usize = 64;

/// The vertices of a simplification of the polyline `points` within `epsilon`: greedily from
/// each kept vertex, the farthest vertex (at most [`MAX_RUN`] on) such that every vertex
/// between lies within `epsilon` of the segment to it. The two are within `epsilon` of each
/// other in Hausdorff distance: every vertex of `points` — so every point of it, a segment's
/// `epsilon`-neighbourhood being convex — lies within `epsilon` of the simplified polyline,
/// and every point of a kept segment within `epsilon` of `points` (the polyline between its
/// ends runs inside its `epsilon`-band from one end to the other, so it passes every point
/// of the segment at that distance). The ends are the polyline's; the work is linear in the
/// vertices (at most [`MAX_RUN`]² distance evaluations per kept vertex).
pub fn simplified(points: &[Vector2<f64>], epsilon: f64) -> Vec<Vector2<f64>> {
    simplified_indices(points, epsilon)
        .into_iter()
        .map(|i| points[i])
        .collect()
}

/// The indices of [`simplified`]'s vertices in `points`.
fn simplified_indices(points: &[Vector2<f64>], epsilon: f64) -> Vec<usize> {
    let n = points.len();
    if n < 3 {
        return (0..n).collect();
    }
    let mut out = vec![0];
    let mut a = 0;
    let mut b = 1;
    while b < n - 1 {
        let c = b + 1;
        let fits = c - a <= MAX_RUN
            && points[a + 1..c]
                .iter()
                .all(|&p| segment_distance(p, points[a], points[c]) <= epsilon);
        if fits {
            b = c;
        } else {
            out.push(b);
            a = b;
            b = a + 1;
        }
    }
    out.push(n - 1);
    out
}

/// The breaks of a shape's pieces: the rectangle's corners, else its domain's ends.
fn shape_breaks(shape: &Shape) -> Vec<f64> {
    let (a, b) = shape.domain();
    match *shape {
        Shape::Rectangle { width, height } => {
            vec![0.0, height, height + width, 2.0 * height + width, b]
        }
        _ => vec![a, b],
    }
}

/// The absolute turning angle at each vertex (a closed polyline's first vertex between the
/// last segment and the first; an open one's ends 0; the closing vertex of a closed one 0).
fn turning_angles(points: &[Vector2<f64>], closed: bool) -> Vec<f64> {
    let n = points.len();
    let turn = |a: Vector2<f64>, b: Vector2<f64>, c: Vector2<f64>| {
        let (u, v) = (b - a, c - b);
        let cross = u.x * v.y - u.y * v.x;
        let dot = u.dot(&v);
        if u.norm_squared() > 0.0 && v.norm_squared() > 0.0 {
            cross.atan2(dot).abs()
        } else {
            0.0
        }
    };
    (0..n)
        .map(|i| {
            if i > 0 && i < n - 1 {
                turn(points[i - 1], points[i], points[i + 1])
            } else if closed && i == 0 {
                turn(points[n - 2], points[0], points[1])
            } else {
                0.0
            }
        })
        .collect()
}

/// The normalised cumulative absolute turning `(Θ(s)/Θ(L), s)` at the vertices (a vertex's
/// turning counted as a jump there), or empty for a straight polyline.
fn turning_weight(angles: &[f64], arc: &[f64]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * angles.len());
    let mut total = 0.0;
    for (&angle, &a) in angles.iter().zip(arc) {
        out.push((total, a));
        total += angle;
        out.push((total, a));
    }
    if !(total > 0.0 && total.is_finite()) {
        return Vec::new();
    }
    for p in &mut out {
        p.0 /= total;
    }
    out
}

/// `Θ(s)/Θ(L)`, interpolated linearly between vertices (the turning is a jump at each).
fn turning_at(turning: &[(f64, f64)], s: f64) -> f64 {
    // the last breakpoint with arc ≤ s, taking the value after the jump
    let i = turning.partition_point(|p| p.1 <= s);
    if i == 0 {
        return 0.0;
    }
    if i >= turning.len() {
        return 1.0;
    }
    let (w0, s0) = turning[i - 1];
    let (w1, s1) = turning[i];
    if s1 > s0 {
        w0 + (w1 - w0) * (s - s0) / (s1 - s0)
    } else {
        w0
    }
}

/// A weight whose equal steps place points (module docs, step 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Weight {
    /// Arc length.
    Arc,
    /// `(1 − β) s / L + β Θ(s) / Θ(L)`: arc length mixed with the absolute turning.
    Turning(f64),
    /// The exact shape's own parameter (arc length on a polyline).
    Parameter,
}

impl ArcShape for Target {
    fn length(&self) -> f64 {
        Target::length(self)
    }

    fn size(&self) -> f64 {
        Target::size(self)
    }

    fn is_closed(&self) -> bool {
        Target::is_closed(self)
    }

    fn point(&self, s: f64) -> Vector2<f64> {
        Target::point(self, s)
    }
}
