//! Automatic choice of interpolation points: the fewest points with which a method draws a
//! shape within a tolerance — the problem seed 004 (Barsi & Milanesi 1986) calls "not at all
//! simple" and leaves open, solved here for shapes given as dense polylines or exact curves.
//!
//! **Target.** A [`Target`] is a shape to draw: a dense reference polyline (closed or open), a
//! tolerance, and a coordinate along it, the arc length `s` of the reference. Points are put
//! on the shape at chosen `s`: on the exact curve when the target is a [`Shape`] (the
//! reference vertex parameters are mapped linearly), on the polyline otherwise. Beyond the
//! ends of an open target (the guides of the Angular and cardinal splines) the same map
//! extrapolates: the exact curve continued, or the end segment's line.
//!
//! **Error.** The symmetric Hausdorff distance ([`crate::curve_metrics`]) between the curve,
//! sampled on each piece, and the reference; a configuration is accepted when it is at most
//! the tolerance with [`FINAL_SAMPLES`] samples per piece.
//!
//! **Search, for one count `n`:**
//! 1. *Initial placement*: points at equal steps of the weight
//!    `W(s) = (1 − β) s / L + β Θ(s) / Θ(L)`, where `Θ(s)` is the absolute turning of the
//!    reference up to `s` (`∫|κ| ds` on a smooth shape; a corner is a jump, so it gets a point
//!    of its own as soon as its turning exceeds one step): `β ∈ {0, ½, ¾}`, closed targets
//!    also shifted by half a step. Open targets keep a point at each end.
//! 2. *Error equidistribution*: the largest distance `eⱼ` of the reference between points
//!    `j` and `j + 1` to the curve is taken as `cⱼ Δⱼᵖ` (`Δⱼ` the arc between them, `p = 2`),
//!    and the arcs are rescaled to `Δⱼ ∝ cⱼ^{−1/p}` (damped, a few rounds): where the curve is
//!    far from the shape the points close up, where it is exact (a straight side) they spread.
//! 3. *Compass search* on every coordinate (positions, the guides' offsets, the cardinal `a`):
//!    steps `±h` accepted when they lower the error, `h` halved when no step does, within an
//!    evaluation budget.
//!
//! **Count.** The count rises from the method's minimum until an initial placement (step 1)
//! meets the tolerance, or a configuration known to meet it is given
//! ([`SearchOptions::known`]); the search then descends one point at a time through steps 1–3
//! and stops at the first count where no configuration is found. *Limits*: the search is
//! local and the descent greedy — a count below the first failure is not tried, and a count
//! reported as impossible may be possible from a placement none of the starts reaches. The
//! result is deterministic (no random starts).
//!
//! **B-splines** are not interpolating: for each vertex count and each order `2 ≤ k ≤ n` (at
//! most [`MAX_ORDER`]) the control polygon is fitted to the reference by least squares with
//! parameter correction ([`crate::bspline::fit::fit_bspline`]), and the smallest vertex count
//! that any order brings under the tolerance is kept (the lowest error among its orders).

use crate::bspline::fit::fit_bspline;
use crate::curve::ParametricCurve;
use crate::curve_metrics::{
    curvature_profile, distances_to, sample_pieces_into, smoothness, Distances, SegmentTree,
    Smoothness,
};
use crate::error::{Error, Result};
use crate::interp::methods::{CubicEnd, Interpolant, Method};
use crate::shapes::Shape;
use nalgebra::Vector2;

/// Samples per piece for the accepted error (spec decision A19: at least 256).
pub const FINAL_SAMPLES: usize = 256;

/// Samples per piece while searching.
pub const SEARCH_SAMPLES: usize = 24;

/// The fraction of the tolerance at which the compass search stops.
pub const GOAL: f64 = 0.9;

/// The most error evaluations one compass search makes, whatever
/// [`SearchOptions::budget_per_coordinate`] asks.
pub const MAX_EVALUATIONS: usize = 100_000;

/// How many of the best starts the compass search polishes, one after the other until one
/// meets the tolerance.
pub const POLISHED_STARTS: usize = 2;

/// The highest B-spline order tried.
pub const MAX_ORDER: usize = 12;

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
    /// Arc positions of the corners: vertices turning by more than [`CORNER_TURN`].
    corners: Vec<f64>,
    /// Inflections of the exact shape (for comparison with a curve's), if known.
    shape_inflections: Option<usize>,
}

/// A reference vertex turning by more than this (radians, 30°) is a corner, which the
/// feature placement puts a point on.
pub const CORNER_TURN: f64 = std::f64::consts::FRAC_PI_6;

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
        })
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
        Ok(self)
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
    /// open one it extrapolates beyond the ends.
    pub fn point(&self, s: f64) -> Vector2<f64> {
        let len = self.length();
        let s = if self.closed { s.rem_euclid(len) } else { s };
        let last = self.arc.len() - 2;
        let i = self
            .arc
            .partition_point(|&x| x <= s)
            .saturating_sub(1)
            .min(last);
        let (s0, s1) = (self.arc[i], self.arc[i + 1]);
        let f = if s1 > s0 { (s - s0) / (s1 - s0) } else { 0.0 };
        match &self.exact {
            Some((shape, t)) => shape.point(t[i] + (t[i + 1] - t[i]) * f),
            None => {
                let p = self.reference();
                p[i] + (p[i + 1] - p[i]) * f
            }
        }
    }

    /// `n` positions of initial placement (module docs, step 1) with turning share `beta`
    /// and, on a closed target, a shift of `phase` steps.
    pub fn placement(&self, n: usize, beta: f64, phase: f64) -> Vec<f64> {
        let len = self.length();
        let beta = if self.turning.is_empty() { 0.0 } else { beta };
        // W(s) = (1 − β) s/L + β Θ(s)/Θ(L), inverted by bisection on s (W is monotone)
        let w = |s: f64| (1.0 - beta) * s / len + beta * turning_at(&self.turning, s);
        let inverse = |target: f64| {
            let (mut lo, mut hi) = (0.0, len);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if w(mid) < target {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            hi
        };
        if self.closed {
            (0..n)
                .map(|k| inverse((k as f64 + phase) / n as f64))
                .collect()
        } else {
            let n = n.max(2);
            (0..n)
                .map(|k| match k {
                    0 => 0.0,
                    k if k == n - 1 => len,
                    k => inverse(k as f64 / (n - 1) as f64),
                })
                .collect()
        }
    }

    /// `n` positions with a point on every corner ([`CORNER_TURN`]) and the rest spread
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
        sample_pieces_into(&curve, &breaks, FINAL_SAMPLES, &mut line)?;
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
    fn search_error(&self, method: &Method, points: &[Vector2<f64>], buf: &mut Scratch) -> f64 {
        let Ok(curve) = method.curve(points, self.closed) else {
            return f64::INFINITY;
        };
        if sample_pieces_into(&curve, &curve.breaks(), SEARCH_SAMPLES, &mut buf.line).is_err() {
            return f64::INFINITY;
        }
        distances_to(&buf.line, &self.tree)
            .map(|d| d.hausdorff())
            .unwrap_or(f64::INFINITY)
    }
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

/// Buffers reused across evaluations.
#[derive(Debug, Default)]
struct Scratch {
    line: Vec<Vector2<f64>>,
}

/// The error and smoothness of one configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measure {
    /// One-sided and symmetric distances to the reference.
    pub distances: Distances,
    /// The curvature measures (dimensionless by the target's size).
    pub smoothness: Smoothness,
    /// The points as seed 004 counts them (a closed curve's repeats included).
    pub counted: usize,
}

/// A configuration found by the search: the method with its parameter, its points, and their
/// measure.
#[derive(Debug, Clone, PartialEq)]
pub struct Choice {
    /// The method with the chosen parameter (`a`, end condition, order).
    pub method: Method,
    /// The distinct points: for a closed curve without the repeats the method adds
    /// ([`Method::prepared`]), for a B-spline its control polygon.
    pub points: Vec<Vector2<f64>>,
    /// The measure with [`FINAL_SAMPLES`] samples per piece.
    pub measure: Measure,
    /// Whether its error is within the target's tolerance.
    pub within_tolerance: bool,
    /// Error evaluations the search made for it (all counts tried).
    pub evaluations: usize,
}

/// Which method the search chooses points for (its parameter is chosen too).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// The Angular spline.
    Angular,
    /// The cardinal spline, `a` chosen in `[0.001, 2]` to [`A_STEP`].
    Cardinal,
    /// The cubic spline, the best of the relaxed, cyclic and anticyclic ends.
    Cubic,
    /// The B-spline, order and control polygon chosen.
    BSpline,
    /// The polygon through the points.
    Linear,
}

impl Family {
    /// The family of a method.
    pub fn of(method: &Method) -> Option<Family> {
        match method {
            Method::Angular => Some(Family::Angular),
            Method::Cardinal { .. } => Some(Family::Cardinal),
            Method::Cubic { .. } => Some(Family::Cubic),
            Method::BSpline { .. } => Some(Family::BSpline),
            Method::Linear => Some(Family::Linear),
        }
    }

    /// Whether an open curve of this family needs a guide beyond each end.
    fn guided(self) -> bool {
        matches!(self, Family::Angular | Family::Cardinal)
    }
}

/// How far the search goes.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchOptions {
    /// The most points (as counted) tried; never more distinct points than
    /// [`max_distinct_for`] the target.
    pub max_points: usize,
    /// Error evaluations per count and start, per free coordinate (at least 50 and at most
    /// [`MAX_EVALUATIONS`] in all).
    pub budget_per_coordinate: usize,
    /// A configuration known to meet the tolerance: the search starts below its count and
    /// returns it if it finds nothing with fewer points.
    pub known: Option<Choice>,
}

impl Default for SearchOptions {
    fn default() -> Self {
        SearchOptions {
            max_points: 40,
            budget_per_coordinate: 40,
            known: None,
        }
    }
}

/// The fewest points with which `family` draws `target` within its tolerance (module docs).
/// If no count up to [`SearchOptions::max_points`] does, the configuration with the lowest
/// error at the largest count is returned with `within_tolerance == false`.
///
/// Every configuration tried counts at most [`SearchOptions::max_points`] points (as the
/// paper counts them: repeats and guides included).
///
/// # Errors
/// [`Error::TooLarge`] for a `max_points` beyond [`crate::error::MAX_ELEMENTS`];
/// [`Error::TooFewPoints`] for a `max_points` below the family's fewest on this target;
/// [`Error::Degenerate`] if no configuration tried is valid (an Angular spline on a polygon
/// whose every placement has collinear triples, say); the errors of [`Target::measure`] on
/// the returned configuration.
pub fn fewest_points(target: &Target, family: Family, options: &SearchOptions) -> Result<Choice> {
    crate::error::size("maximum point count", options.max_points)?;
    let min = fewest_counted(family, target.closed);
    if options.max_points < min {
        return Err(Error::TooFewPoints {
            what: "maximum point count of the search (the family's fewest on this target)",
            needed: min,
            got: options.max_points,
        });
    }
    if family == Family::BSpline {
        return fewest_bspline(target, options);
    }
    let mut evaluations = 0;
    let min = min_distinct(family, target.closed);
    // the count is capped at a few points per reference segment (points may sit anywhere on
    // a segment: a polygon's sides need them), which bounds the search's cost for any
    // `max_points`
    let max = distinct_of(family, target.closed, options.max_points).min(max_distinct_for(target));
    let known = checked_known(target, options)?;
    let mut found: Option<(usize, Choice)> =
        known.map(|k| (distinct_of(family, target.closed, k.measure.counted), k));
    // rise until a start meets the tolerance (or up to the known count)
    let top = found.as_ref().map_or(max + 1, |f| f.0);
    // the best valid configuration seen at any count: the answer when none meets the
    // tolerance and the largest count has no valid configuration
    let mut fallback: Option<Choice> = None;
    // the count whose best start came nearest, for the search when no count succeeds
    let mut nearest: Option<(f64, usize)> = None;
    for n in min..top {
        let (best, e, evals) = starts(target, family, n)?;
        evaluations += evals;
        if e.is_finite() && nearest.is_none_or(|(b, _)| e < b) {
            nearest = Some((e, n));
        }
        if let Some(best) = best.filter(|b| b.within_tolerance) {
            found = Some((n, best));
            break;
        }
    }
    // descend: gallop down while the full search succeeds, then bisect between the lowest
    // success and the highest failure
    let mut ok = found.as_ref().map_or(max + 1, |f| f.0);
    let mut bad = min - 1;
    let mut failure = None;
    let mut step = 1;
    let mut galloping = true;
    while ok - bad > 1 {
        let n = if galloping {
            ok.saturating_sub(step).max(bad + 1)
        } else {
            bad + (ok - bad) / 2
        };
        let (choice, evals) = place(target, family, n, options.budget_per_coordinate)?;
        evaluations += evals;
        match choice {
            Some(c) if c.within_tolerance => {
                ok = n;
                found = Some((n, c));
                step *= 2;
            }
            other => {
                bad = n;
                if let Some(c) = &other {
                    if better(c, fallback.as_ref()) {
                        fallback = Some(c.clone());
                    }
                }
                if failure.is_none() || n == max {
                    failure = other;
                }
                galloping = false;
            }
        }
    }
    if found.is_none() && failure.is_none() {
        // the largest count has no valid configuration (an Angular spline on a polygon, whose
        // placements with many points have collinear triples): the full search at the count
        // whose start came nearest
        if let Some((_, n)) = nearest.filter(|&(_, n)| n != max) {
            let (choice, evals) = place(target, family, n, options.budget_per_coordinate)?;
            evaluations += evals;
            fallback = choice;
        }
    }
    let mut choice = match (found, failure.or(fallback)) {
        (Some((_, c)), _) => c,
        (None, Some(f)) => f,
        (None, None) => {
            return Err(Error::Degenerate {
                what: "automatic point choice",
                reason: "no configuration of the method is valid on this target",
            })
        }
    };
    choice.evaluations = evaluations;
    Ok(choice)
}

/// The known configuration of `options`, measured again on `target` (its fields are public,
/// so nothing it claims is trusted): `None` unless it builds, meets the tolerance and counts
/// at least the family's fewest and at most `max_points`.
///
/// # Errors
/// The errors of [`Target::measure`] for a known configuration that does not build (NaN
/// points, say).
fn checked_known(target: &Target, options: &SearchOptions) -> Result<Option<Choice>> {
    let Some(k) = &options.known else {
        return Ok(None);
    };
    let measure = target.measure(&k.method, &k.points)?;
    let within = measure.distances.hausdorff() <= target.tolerance;
    let counted = measure.counted;
    let min = Family::of(&k.method).map_or(0, |f| fewest_counted(f, target.closed));
    Ok(
        (within && counted >= min && counted <= options.max_points).then(|| Choice {
            method: k.method,
            points: k.points.clone(),
            within_tolerance: true,
            measure,
            evaluations: k.evaluations,
        }),
    )
}

/// The most distinct points the search tries on `target`: four per reference vertex, at
/// least 64.
pub fn max_distinct_for(target: &Target) -> usize {
    target.reference().len().saturating_mul(4).max(64)
}

/// The fewest distinct points of a family: 3 closed (Angular and cardinal: 3 + 3 repeats),
/// 2 + 2 guides open for the guided families, 3 for the cubic.
fn min_distinct(family: Family, closed: bool) -> usize {
    match (family, closed) {
        (_, true) => 3,
        (Family::Angular | Family::Cardinal, false) => 4,
        _ => 3,
    }
}

/// Distinct points behind a counted number (the repeats of a closed curve taken off).
fn distinct_of(family: Family, closed: bool, counted: usize) -> usize {
    counted.saturating_sub(repeats(family, closed))
}

/// The fewest points a family counts: the B-spline fit's fewest vertices (4 closed, the
/// closing one counted once; 2 open), else [`min_distinct`] with the closed curve's repeats.
fn fewest_counted(family: Family, closed: bool) -> usize {
    match (family, closed) {
        (Family::BSpline, true) => 4,
        (Family::BSpline, false) => 2,
        _ => counted_of(family, closed, min_distinct(family, closed)),
    }
}

/// The points counted for `distinct` distinct points (repeats of a closed curve added).
fn counted_of(family: Family, closed: bool, distinct: usize) -> usize {
    distinct.saturating_add(repeats(family, closed))
}

/// The repeats a closed curve of the family counts: Angular and cardinal 3, others 1.
fn repeats(family: Family, closed: bool) -> usize {
    match (family, closed) {
        (_, false) => 0,
        (Family::Angular | Family::Cardinal, true) => 3,
        (_, true) => 1,
    }
}

/// The variables of one search: positions (open targets: the inner ones; the ends are fixed),
/// guide offsets, the cardinal `a`.
#[derive(Debug, Clone)]
struct Layout {
    family: Family,
    closed: bool,
    /// Distinct points on the shape (the guides not included).
    on_shape: usize,
    end: CubicEnd,
}

impl Layout {
    fn positions(&self) -> usize {
        if self.closed {
            self.on_shape
        } else {
            self.on_shape - 2
        }
    }

    fn guides(&self) -> usize {
        if !self.closed && self.family.guided() {
            2
        } else {
            0
        }
    }

    fn method(&self, x: &[f64]) -> Method {
        match self.family {
            Family::Angular => Method::Angular,
            Family::Cardinal => Method::Cardinal {
                a: quantized_a(x[x.len() - 1]),
            },
            Family::Cubic => Method::Cubic { end: self.end },
            // B-splines are fitted, not placed (fewest_bspline); never reached
            Family::Linear | Family::BSpline => Method::Linear,
        }
    }

    /// The arc positions of the points on the shape, `None` if out of order.
    fn arcs(&self, target: &Target, x: &[f64]) -> Option<Vec<f64>> {
        let len = target.length();
        let gap = 1e-6 * len;
        let inner = &x[..self.positions()];
        let mut s: Vec<f64> = if self.closed {
            inner.to_vec()
        } else {
            let mut s = Vec::with_capacity(self.on_shape);
            s.push(0.0);
            s.extend_from_slice(inner);
            s.push(len);
            s
        };
        let ordered = s.windows(2).all(|w| w[1] - w[0] > gap);
        let closes = !self.closed || s[s.len() - 1] - s[0] < len - gap;
        if !(ordered && closes) {
            return None;
        }
        if self.closed {
            // the first point in [0, L)
            let shift = s[0].rem_euclid(len) - s[0];
            s.iter_mut().for_each(|v| *v += shift);
        }
        Some(s)
    }

    fn points(&self, target: &Target, x: &[f64]) -> Option<Vec<Vector2<f64>>> {
        let s = self.arcs(target, x)?;
        let mut points: Vec<Vector2<f64>> = s.iter().map(|&v| target.point(v)).collect();
        if self.guides() == 2 {
            let k = self.positions();
            let (g0, g1) = (x[k], x[k + 1]);
            let len = target.length();
            if !(g0 > 1e-6 * len && g1 > 1e-6 * len && g0 <= len && g1 <= len) {
                return None;
            }
            points.insert(0, target.point(-g0));
            points.push(target.point(len + g1));
        }
        Some(points)
    }
}

/// The cardinal `a` the search tries: a multiple of [`A_STEP`] in `[A_STEP, 2]`, so the
/// chosen value prints as it is (`a = 1.3`, not `1.2999999999999998`).
fn quantized_a(a: f64) -> f64 {
    let k = (a / A_STEP).round().clamp(1.0, 2.0 / A_STEP);
    // k · 0.001 as k / 1000: the nearest double to the decimal
    k / (1.0 / A_STEP).round()
}

/// The resolution of the cardinal `a` the search chooses.
pub const A_STEP: f64 = 0.001;

/// The initial placements of `n` distinct points (step 1 of the module docs): the one with
/// the lowest coarse error, measured densely if that error is within the tolerance; and the
/// evaluations made.
fn starts(target: &Target, family: Family, n: usize) -> Result<(Option<Choice>, f64, usize)> {
    let mut best: Option<(f64, Layout, Vec<f64>)> = None;
    let mut evaluations = 0;
    let mut scratch = Scratch::default();
    for layout in layouts(target, family, n) {
        for x in initial_vectors(target, &layout) {
            let (x, e, evals) = tune_parameter(target, &layout, x, &mut scratch);
            evaluations += evals;
            if best.as_ref().is_none_or(|b| e < b.0) {
                best = Some((e, layout.clone(), x));
            }
        }
    }
    match best {
        Some((e, layout, x)) if e <= target.tolerance => {
            Ok((finish(target, &layout, &x)?, e, evaluations))
        }
        Some((e, ..)) => Ok((None, e, evaluations)),
        None => Ok((None, f64::INFINITY, evaluations)),
    }
}

/// The search for `n` distinct points (steps 1–3 of the module docs): the best configuration
/// found, and the evaluations made.
fn place(
    target: &Target,
    family: Family,
    n: usize,
    budget_per_coordinate: usize,
) -> Result<(Option<Choice>, usize)> {
    let mut best: Option<Choice> = None;
    let mut evaluations = 0;
    for layout in layouts(target, family, n) {
        let mut scratch = Scratch::default();
        // every start equidistributed; the best ones polished until one meets the tolerance
        let mut starts: Vec<(Vec<f64>, f64)> = Vec::new();
        for x in initial_vectors(target, &layout) {
            let (x, e, evals) = tune_parameter(target, &layout, x, &mut scratch);
            evaluations += evals;
            let (x, e, evals) = equidistribute(target, &layout, x, e, &mut scratch);
            evaluations += evals;
            starts.push((x, e));
        }
        starts.sort_by(|a, b| a.1.total_cmp(&b.1));
        for (x, e) in starts.into_iter().take(POLISHED_STARTS) {
            let dims = x.len();
            let budget = budget_per_coordinate
                .saturating_mul(dims)
                .clamp(50, MAX_EVALUATIONS);
            let (x, _, evals) = compass(target, &layout, x, e, budget, &mut scratch);
            evaluations += evals;
            if let Some(c) = finish(target, &layout, &x)? {
                if better(&c, best.as_ref()) {
                    best = Some(c);
                }
            }
            if best.as_ref().is_some_and(|b| b.within_tolerance) {
                break;
            }
        }
        if best.as_ref().is_some_and(|b| b.within_tolerance) {
            // a count needs one end condition that meets the tolerance
            break;
        }
    }
    Ok((best, evaluations))
}

/// Within tolerance first, then the lower error.
fn better(c: &Choice, best: Option<&Choice>) -> bool {
    match best {
        None => true,
        Some(b) => {
            (c.within_tolerance, -c.measure.distances.hausdorff())
                > (b.within_tolerance, -b.measure.distances.hausdorff())
        }
    }
}

/// The layouts of `n` distinct points: one per cubic end condition, else one.
fn layouts(target: &Target, family: Family, n: usize) -> Vec<Layout> {
    let guides = if !target.closed && family.guided() {
        2
    } else {
        0
    };
    let on_shape = n.saturating_sub(guides);
    if on_shape < 2 || (target.closed && on_shape < 3) {
        return Vec::new();
    }
    let ends: &[CubicEnd] = if family == Family::Cubic {
        &[CubicEnd::Relaxed, CubicEnd::Cyclic, CubicEnd::Anticyclic]
    } else {
        &[CubicEnd::Relaxed]
    };
    ends.iter()
        .map(|&end| Layout {
            family,
            closed: target.closed,
            on_shape,
            end,
        })
        .collect()
}

/// The variable vectors of the initial placements.
fn initial_vectors(target: &Target, layout: &Layout) -> Vec<Vec<f64>> {
    let mut out = Vec::new();
    let phases: &[f64] = if layout.closed { &[0.0, 0.5] } else { &[0.0] };
    let mut placements = Vec::new();
    for &beta in &[0.0, 0.5, 0.75] {
        for &phase in phases {
            placements.push(target.placement(layout.on_shape, beta, phase));
        }
    }
    placements.extend(target.feature_placement(layout.on_shape));
    for s in placements {
        let mut x: Vec<f64> = if layout.closed {
            s
        } else {
            s[1..s.len() - 1].to_vec()
        };
        if layout.guides() == 2 {
            // a guide half a step beyond each end
            let step = target.length() / (layout.on_shape - 1) as f64;
            x.push(0.5 * step);
            x.push(0.5 * step);
        }
        if layout.family == Family::Cardinal {
            x.push(0.5);
        }
        out.push(x);
    }
    out
}

/// The cardinal `a` set to the best of a coarse grid (other families: unchanged), with the
/// error of the result.
fn tune_parameter(
    target: &Target,
    layout: &Layout,
    mut x: Vec<f64>,
    scratch: &mut Scratch,
) -> (Vec<f64>, f64, usize) {
    let mut evals = 0;
    if layout.family != Family::Cardinal {
        let e = error_of(target, layout, &x, scratch);
        return (x, e, 1);
    }
    let last = x.len() - 1;
    let mut best = (f64::INFINITY, x[last]);
    for a in [0.001, 0.25, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2] {
        x[last] = a;
        let e = error_of(target, layout, &x, scratch);
        evals += 1;
        if e < best.0 {
            best = (e, a);
        }
    }
    x[last] = best.1;
    (x, best.0, evals)
}

fn error_of(target: &Target, layout: &Layout, x: &[f64], scratch: &mut Scratch) -> f64 {
    match layout.points(target, x) {
        Some(points) => target.search_error(&layout.method(x), &points, scratch),
        None => f64::INFINITY,
    }
}

/// Step 2 of the module docs: a few damped rounds of error equidistribution over the arcs
/// between points, keeping the best.
fn equidistribute(
    target: &Target,
    layout: &Layout,
    x: Vec<f64>,
    e: f64,
    scratch: &mut Scratch,
) -> (Vec<f64>, f64, usize) {
    const ROUNDS: usize = 8;
    const P: f64 = 2.0;
    let mut best = (x.clone(), e);
    let mut x = x;
    let mut evals = 0;
    let len = target.length();
    for _ in 0..ROUNDS {
        let Some(s) = layout.arcs(target, &x) else {
            break;
        };
        let Some(points) = layout.points(target, &x) else {
            break;
        };
        let Ok(curve) = layout.method(&x).curve(&points, layout.closed) else {
            break;
        };
        let Some(errors) = arc_errors(target, &curve, &s, scratch) else {
            break;
        };
        // Δⱼ' ∝ cⱼ^{−1/p}, cⱼ = eⱼ / Δⱼᵖ, floored so exact arcs do not take everything
        let arcs: Vec<f64> = (0..errors.len())
            .map(|j| {
                let next = if j + 1 < s.len() {
                    s[j + 1]
                } else {
                    s[0] + len
                };
                next - s[j]
            })
            .collect();
        let c: Vec<f64> = errors
            .iter()
            .zip(&arcs)
            .map(|(&e, &d)| e / d.powf(P))
            .collect();
        let cmax = c.iter().copied().fold(0.0, f64::max);
        if !(cmax > 0.0 && cmax.is_finite()) {
            break;
        }
        let want: Vec<f64> = c
            .iter()
            .map(|&cj| cj.max(1e-3 * cmax).powf(-1.0 / P))
            .collect();
        let total: f64 = want.iter().sum();
        let span = arcs.iter().sum::<f64>();
        // damped: the geometric mean of the old and the wanted arcs, renormalised
        let mixed: Vec<f64> = arcs
            .iter()
            .zip(&want)
            .map(|(&d, &w)| (d * w * span / total).sqrt())
            .collect();
        let norm = span / mixed.iter().sum::<f64>();
        let mut acc = s[0];
        let mut new_s = vec![s[0]];
        for d in &mixed[..mixed.len() - usize::from(!layout.closed)] {
            acc += d * norm;
            new_s.push(acc);
        }
        if layout.closed {
            new_s.pop();
        }
        let k = layout.positions();
        let inner = if layout.closed {
            &new_s[..]
        } else {
            &new_s[1..new_s.len().min(k + 1)]
        };
        if inner.len() != k {
            break;
        }
        x[..k].copy_from_slice(inner);
        let e = error_of(target, layout, &x, scratch);
        evals += 1;
        if e < best.1 {
            best = (x.clone(), e);
        }
    }
    (best.0, best.1, evals)
}

/// The largest distance of the reference between consecutive points (arc positions `s`,
/// sorted in `[0, L)` for a closed target) to the curve, per arc; `None` if the curve cannot
/// be sampled.
fn arc_errors(
    target: &Target,
    curve: &Interpolant,
    s: &[f64],
    scratch: &mut Scratch,
) -> Option<Vec<f64>> {
    sample_pieces_into(curve, &curve.breaks(), SEARCH_SAMPLES, &mut scratch.line).ok()?;
    let tree = SegmentTree::new(&scratch.line).ok()?;
    let arcs = if target.closed { s.len() } else { s.len() - 1 };
    let mut errors = vec![0.0; arcs];
    let len = target.length();
    for (p, &a) in target.reference().iter().zip(&target.arc) {
        // the arc j with s[j] ≤ a < s[j + 1] (closed: a before the first point belongs to
        // the arc that wraps past the last)
        let a = if target.closed && a < s[0] {
            a + len
        } else {
            a
        };
        let j = s
            .partition_point(|&v| v <= a)
            .saturating_sub(1)
            .min(arcs - 1);
        let d = tree.distance(*p);
        if d > errors[j] {
            errors[j] = d;
        }
    }
    Some(errors)
}

/// Step 3 of the module docs: compass search from `x` (error `e`) within `budget`
/// evaluations, stopping early at [`GOAL`] of the tolerance (the coarse error a little below
/// it, so the dense check passes).
fn compass(
    target: &Target,
    layout: &Layout,
    mut x: Vec<f64>,
    mut e: f64,
    budget: usize,
    scratch: &mut Scratch,
) -> (Vec<f64>, f64, usize) {
    let len = target.length();
    let k = layout.positions();
    let mut h: Vec<f64> = (0..x.len())
        .map(|j| {
            if j < k + layout.guides() {
                0.25 * len / layout.on_shape as f64
            } else {
                0.1
            }
        })
        .collect();
    let floor: Vec<f64> = h.iter().map(|v| v / 256.0).collect();
    let mut evals = 0;
    let goal = GOAL * target.tolerance;
    while evals < budget && e > goal {
        let mut improved = false;
        for j in 0..x.len() {
            for sign in [1.0, -1.0] {
                let old = x[j];
                x[j] = old + sign * h[j];
                let f = error_of(target, layout, &x, scratch);
                evals += 1;
                if f < e {
                    e = f;
                    improved = true;
                    break;
                }
                x[j] = old;
            }
            if evals >= budget {
                break;
            }
        }
        if !improved {
            let mut all_small = true;
            for (hj, fj) in h.iter_mut().zip(&floor) {
                *hj *= 0.5;
                all_small &= *hj < *fj;
            }
            if all_small {
                break;
            }
        }
    }
    (x, e, evals)
}

/// The configuration of `x` measured densely.
fn finish(target: &Target, layout: &Layout, x: &[f64]) -> Result<Option<Choice>> {
    let Some(points) = layout.points(target, x) else {
        return Ok(None);
    };
    let method = layout.method(x);
    let Ok(measure) = target.measure(&method, &points) else {
        return Ok(None);
    };
    Ok(Some(Choice {
        method,
        points,
        within_tolerance: measure.distances.hausdorff() <= target.tolerance,
        measure,
        evaluations: 0,
    }))
}

/// The B-spline search (module docs).
fn fewest_bspline(target: &Target, options: &SearchOptions) -> Result<Choice> {
    const CORRECTIONS: usize = 20;
    const FIT_SAMPLES: usize = 360;
    let closed = target.closed;
    // the fit's samples: the reference thinned to about FIT_SAMPLES, ends kept
    let reference = target.reference();
    let step = (reference.len() / FIT_SAMPLES).max(1);
    let mut samples: Vec<Vector2<f64>> = reference.iter().step_by(step).copied().collect();
    if samples.last() != reference.last() {
        samples.push(reference[reference.len() - 1]);
    }
    samples.dedup();
    let mut evaluations = 0;
    let mut best: Option<Choice> = None;
    let min_vertices = if closed { 4 } else { 2 };
    let known = checked_known(target, options)?;
    let max_vertices = known
        .as_ref()
        .map(|k| k.measure.counted.saturating_sub(1))
        .unwrap_or(options.max_points)
        .min(samples.len());
    for vertices in min_vertices..=max_vertices {
        let mut at_count: Option<Choice> = None;
        for order in 2..=vertices.min(MAX_ORDER) {
            let Ok(fit) = fit_bspline(&samples, vertices, order, CORRECTIONS) else {
                continue;
            };
            evaluations += fit.iterations + 1;
            let method = Method::BSpline { order };
            let mut points = fit.curve.points().to_vec();
            if closed {
                // the fit closes the polygon on its first vertex; the method repeats it
                points.pop();
            }
            let Ok(measure) = target.measure(&method, &points) else {
                continue;
            };
            let c = Choice {
                method,
                points,
                within_tolerance: measure.distances.hausdorff() <= target.tolerance,
                measure,
                evaluations: 0,
            };
            if better(&c, at_count.as_ref()) {
                at_count = Some(c);
            }
        }
        if let Some(c) = at_count {
            let done = c.within_tolerance;
            if better(&c, best.as_ref()) || done {
                best = Some(c);
            }
            if done {
                break;
            }
        }
    }
    let mut choice = match (best, known) {
        (Some(b), _) if b.within_tolerance => b,
        (_, Some(k)) => k,
        (Some(b), None) => b,
        (None, None) => {
            return Err(Error::Degenerate {
                what: "automatic point choice",
                reason: "no B-spline of any order fits this target",
            })
        }
    };
    choice.evaluations = evaluations;
    Ok(choice)
}
