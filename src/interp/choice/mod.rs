//! Automatic choice of interpolation points: the fewest points with which a method draws a
//! shape within a tolerance — the problem seed 004 (Barsi & Milanesi 1986) calls "not at all
//! simple" and leaves open, solved here for shapes given as dense polylines or exact curves.
//!
//! **Target.** A [`Target`] is a shape to draw: a dense reference polyline (closed or open), a
//! tolerance, and a coordinate along it, the arc length `s` of the reference. Points are put
//! on the shape at chosen `s`: on the exact curve when the target is a [`Shape`](crate::shapes::Shape) (the
//! reference vertex parameters are mapped linearly), on the polyline otherwise. The guides of
//! an open Angular or cardinal curve (not drawn) are free points of the plane.
//!
//! **Error.** The symmetric Hausdorff distance ([`crate::metrics::curve`]) between the curve,
//! sampled on each piece, and the reference; a configuration is accepted when it is at most
//! the tolerance with [`FINAL_SAMPLES`] samples per piece.
//!
//! **Search, for one count `n`** ([`Attempt`]; each step in its file: `starts.rs`,
//! `prune.rs`, `polish.rs`):
//! 1. *Starts*, deterministic and tagged with their family ([`Start`]): points at equal steps
//!    of a weight — arc length `s / L`; arc length mixed with the absolute turning,
//!    `W(s) = (1 − β) s / L + β Θ(s) / Θ(L)` with `β ∈ {½, ¾}` (`Θ(s)` is `∫|κ| ds`, a corner
//!    a jump); the exact shape's own parameter — closed targets also shifted by half a step;
//!    a point on every corner ([`Target::feature_placement`]); *symmetric* placements for
//!    each mirror axis of the shape ([`symmetry`]), searched in the mirror's own variables
//!    (pairs `s₀ ± δ`, points on the axis, one guide and its image); and
//!    [`SearchOptions::random_starts`] random placements per layout from
//!    [`SearchOptions::seed`]. An open guided curve gets three guide choices per placement:
//!    on the shape beyond the ends, one parameter step beyond (the exact shape continued), and
//!    the chord continued. The cubic spline is searched with each end condition (relaxed,
//!    cyclic, anticyclic) as one pool, the cardinal `a` set on a grid for each start.
//!    *Pruned* starts: the configuration within the tolerance with the fewest
//!    points found so far (or the given one), its points taken off one at a time, each time
//!    the one whose removal raises the error least; the three best last removals are starts.
//!    Known exact configurations lie in this space: a cardinal spline with `a = ½` and points
//!    at equal parameter steps reproduces a quadratic (a parabola from 2 points and 2
//!    guides), a closed Angular spline through 3 points of a circle is the circle, an
//!    order-2 B-spline is the polygon of its vertices.
//! 2. *Error equidistribution* (plain layouts): the largest distance `eⱼ` of the reference
//!    between points `j` and `j + 1` to the curve is taken as `cⱼ Δⱼᵖ` (`Δⱼ` the arc between
//!    them, `p = 2`), and the arcs are rescaled to `Δⱼ ∝ cⱼ^{−1/p}` (damped, a few rounds).
//! 3. *Compass search* from the best start of each family (and cubic end condition), then
//!    the next best, up to `POLISHED_STARTS` (5) per end condition, on every coordinate
//!    (positions, guides, `a`): steps `±h` accepted when they lower the error, `h` halved
//!    when no step does, within an evaluation budget
//!    ([`SearchOptions::budget_per_coordinate`]), until one meets the tolerance.
//!
//! **Count.** An upper count is the given configuration's ([`SearchOptions::known`]) or the
//! first count from the method's minimum where a start (step 1) meets the tolerance. With
//! [`SearchOptions::every_count_below`] the counts below it are searched down, one by one,
//! while the full search (steps 1–3) succeeds; then every count from the minimum up to the
//! first failure is searched with the full budget, and the lowest success is the answer: the
//! assumption "a count that fails means the lower counts fail" is not made. Without it the
//! counts are galloped down and bisected, and the count one below the answer searched in
//! full. [`search`] reports, beside
//! the choice, every count searched and its best error ([`Search::attempts`]), and whether
//! the count is provably minimal ([`Minimality`]): the method's own minimum, or a lower bound
//! on the error of everything one point fewer can draw ([`bound`]). Otherwise a count is the
//! fewest *found*: the search is a multistart local one, not an exhaustive one. The result
//! is deterministic.
//!
//! **B-splines** are not interpolating: for each vertex count and each order `2 ≤ k ≤ n` (at
//! most [`MAX_ORDER`]) the control polygon is fitted to the reference by least squares with
//! parameter correction ([`crate::bspline::fit::fit_bspline`]), and the smallest vertex count
//! that any order brings under the tolerance is kept (the lowest error among its orders);
//! every count below it is fitted — or, with [`SearchOptions::every_count_below`] off, the
//! counts are doubled up to one within the tolerance and bisected below it, the count one
//! below the answer fitted with every order.
//!
//! **Polygon.** The polygon's fewest points are computed exactly ([`polygon`]): the shortest
//! path over the shortcuts that keep the outline within the tolerance (Imai & Iri 1988, Chan &
//! Chin 1996), over candidates at the reference's vertices and along its sides; its
//! minimality is [`Minimality::Optimum`]. Two families contain the polygon, and their search
//! honours it: an order-2 B-spline on the same points is the polygon (the B-spline count is
//! never above the polygon's), and a cardinal spline with `a = 0` through them too (zero
//! tangents; an open curve adds its 2 guides, a closed one repeats 3 points where the polygon
//! repeats 1: the cardinal count is at most the polygon's + 2). When a family's search ends
//! above that bound, or finds nothing within the tolerance, it runs again from the polygon's
//! configuration ([`SearchOptions::known`]). The Angular spline (arcs) and the cubic spline
//! (C²) do not contain the polygon: no bound follows for them.
//!
//! **Dense references** (more than [`COARSE_ABOVE`] vertices, a digitised outline): the search
//! measures its candidates against a simplification of the reference within
//! [`COARSE_FRACTION`] of the tolerance ([`simplified`]; the two are that close in Hausdorff
//! distance, so every error it compares is within that of the exact one), and its answers
//! against the whole reference ([`Target::measure`]); a B-spline's orders are screened so too
//! and the best measured exactly. Its answers count many points, so the search's steps are
//! larger there: the rise to an upper count doubles its step, the gallop down from it starts
//! with an eighth of it, a pruned start takes off half of the points still to go at a time
//! (no two within two places of each other, so the last steps take one), and the compass
//! search polishes the starts by error alone, at most two within 15 % of the best, with three
//! times the budget. The paper's shapes, letters and
//! coast are below the limit.

pub mod bound;
mod bspline;
mod count;
mod counts;
mod known;
mod polish;
pub mod polygon;
mod prune;
mod starts;
pub mod symmetry;
mod target;

pub use count::{fewest_points, max_distinct_for, search};
pub use target::{simplified, Target, COARSE_ABOVE, COARSE_FRACTION, MAX_RUN};

use crate::interp::methods::Method;
use crate::metrics::curve::{Distances, Smoothness};
use nalgebra::Vector2;

/// Samples per piece for the accepted error (spec decision A19: at least 256).
pub const FINAL_SAMPLES: usize = 256;

/// Samples per piece while searching.
pub(crate) const SEARCH_SAMPLES: usize = 24;

/// The fraction of the tolerance at which the compass search stops.
pub(crate) const GOAL: f64 = 0.9;

/// The most error evaluations one compass search makes, whatever
/// [`SearchOptions::budget_per_coordinate`] asks.
pub const MAX_EVALUATIONS: usize = 100_000;

/// How many starts the compass search polishes per count and layout variant (a cubic end
/// condition), one after the other until one meets the tolerance: the best of each start
/// family and variant first.
pub(crate) const POLISHED_STARTS: usize = 5;

/// The highest B-spline order tried.
pub const MAX_ORDER: usize = 12;

/// Buffers reused across evaluations.
#[derive(Debug, Default)]
struct Scratch {
    line: Vec<Vector2<f64>>,
    /// Where the last error measured was reached or passed its limit: the curve sample and
    /// the reference vertex measured first next time (a configuration that differs a little
    /// is likely to be farthest there, and a search that only asks whether it beats its best
    /// then stops at once; the error does not depend on them).
    worst_sample: Option<usize>,
    worst_vertex: Option<usize>,
    /// Where the last error measured in full (below its limit) was reached: a curve sample or
    /// a reference vertex.
    worst_point: Option<Vector2<f64>>,
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
    /// The family of the start the configuration was reached from.
    pub start: Start,
}

/// The family of starts a configuration came from (module docs, step 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Start {
    /// Equal steps of arc length.
    ArcLength,
    /// Equal steps of arc length mixed with the turning.
    Turning,
    /// Equal steps of the exact shape's own parameter.
    ShapeParameter,
    /// A point on every corner.
    Corners,
    /// A placement symmetric about a mirror axis of the shape, searched in its variables.
    Symmetric,
    /// A seeded random placement.
    Random,
    /// The configuration given to the search ([`SearchOptions::known`]).
    Known,
    /// A least-squares fit (B-splines).
    Fit,
    /// The polygon's exact optimum ([`polygon`]).
    Exact,
    /// A configuration with more points that meets the tolerance, points taken off
    /// (module docs, step 1).
    Pruned,
}

/// Which method the search chooses points for (its parameter is chosen too).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// The Angular spline.
    Angular,
    /// The cardinal spline, `a` chosen in `[0.001, 2]` to `A_STEP` (0.001) (or `a = 0`, the polygon,
    /// module docs **Polygon**).
    Cardinal,
    /// The cubic spline, the best of the relaxed, cyclic and anticyclic ends.
    Cubic,
    /// The B-spline, order and control polygon chosen.
    BSpline,
    /// The polygon through the points.
    Linear,
}

impl Family {
    /// Every family, the polygon last.
    pub const ALL: [Family; 5] = [
        Family::Angular,
        Family::Cardinal,
        Family::Cubic,
        Family::BSpline,
        Family::Linear,
    ];

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

/// The seed of the random starts by default.
pub const SEED: u64 = 0x5EED_0004_1986;

/// Random starts per layout and count by default.
pub const RANDOM_STARTS: usize = 8;

/// The most random starts per layout and count a search accepts.
pub const MAX_RANDOM_STARTS: usize = 1024;

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
    /// Random starts per layout and count (module docs, step 1), at most
    /// [`MAX_RANDOM_STARTS`].
    pub random_starts: usize,
    /// The seed of the random starts.
    pub seed: u64,
    /// Search every count below the answer with the full budget (module docs, *Count*);
    /// otherwise bisect, and search the count one below the answer.
    pub every_count_below: bool,
}

impl Default for SearchOptions {
    fn default() -> Self {
        SearchOptions {
            max_points: 40,
            budget_per_coordinate: 40,
            known: None,
            random_starts: RANDOM_STARTS,
            seed: SEED,
            every_count_below: true,
        }
    }
}

/// One count searched with the full budget (steps 1–3 of the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Attempt {
    /// The points, as counted.
    pub counted: usize,
    /// The smallest error found ([`FINAL_SAMPLES`] per piece), `None` if no start was valid.
    pub best_error: Option<f64>,
    /// The starts tried (B-splines: the orders fitted).
    pub starts: usize,
    /// Whether the best configuration meets the tolerance.
    pub within_tolerance: bool,
}

/// Whether a count is known to be the fewest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Minimality {
    /// The method's fewest points on the target.
    MethodMinimum,
    /// Everything one point fewer draws has an error of at least `bound` (above the
    /// tolerance): `class` says what it draws ([`bound`]).
    LowerBound {
        /// What one point fewer draws.
        class: &'static str,
        /// The lower bound on its error.
        bound: f64,
    },
    /// The exact optimum (the polygon, [`polygon`]): every polygon with fewer points, placed
    /// anywhere along the outline in its order, errs by more than `bound` (its sides against
    /// the stretches of outline they replace).
    Optimum {
        /// The error every polygon with fewer points exceeds.
        bound: f64,
    },
    /// The polygon's fewest over candidates up to `spacing` apart along the outline, too far
    /// apart for [`Minimality::Optimum`]'s argument (an outline too long for finer ones):
    /// not proven.
    Candidates {
        /// The largest distance along the outline between consecutive candidates.
        spacing: f64,
    },
    /// Every lower count was searched with the full budget and none met the tolerance: the
    /// fewest found, not proven.
    Searched,
    /// Not every lower count was searched ([`SearchOptions::every_count_below`] off).
    Bisected,
    /// No count met the tolerance.
    NotMet,
}

impl Minimality {
    /// In words, with a bound as a percentage of `size`.
    pub fn describe(&self, size: f64) -> String {
        match *self {
            Minimality::MethodMinimum => "proven: the method's minimum".into(),
            Minimality::LowerBound { class, bound } => format!(
                "proven: one fewer draws {class}, error ≥ {:.2} %",
                100.0 * bound / size
            ),
            Minimality::Optimum { bound } => format!(
                "proven (exact optimum): fewer points err > {:.3} %",
                100.0 * bound / size
            ),
            Minimality::Candidates { spacing } => format!(
                "fewest over candidates {:.3} % apart (not proven)",
                100.0 * spacing / size
            ),
            Minimality::Searched => {
                "fewest found by a local search (every lower count searched, none within)".into()
            }
            Minimality::Bisected => "fewest found by a local search (lower counts bisected)".into(),
            Minimality::NotMet => "none within the tolerance".into(),
        }
    }

    /// Whether the count is proven minimal.
    pub fn proven(&self) -> bool {
        matches!(
            self,
            Minimality::MethodMinimum | Minimality::LowerBound { .. } | Minimality::Optimum { .. }
        )
    }
}

/// A search's answer with its evidence.
#[derive(Debug, Clone, PartialEq)]
pub struct Search {
    /// The fewest points found ([`fewest_points`]).
    pub choice: Choice,
    /// Every count searched with the full budget, in increasing order.
    pub attempts: Vec<Attempt>,
    /// Whether the count is known to be the fewest.
    pub minimality: Minimality,
}

impl Search {
    /// The count one point below the answer, if it was searched.
    pub fn below(&self) -> Option<&Attempt> {
        attempt_below(&self.attempts, &self.choice)
    }
}

/// The attempt one point below `choice`'s count among `attempts`, if it was searched.
pub fn attempt_below<'a>(attempts: &'a [Attempt], choice: &Choice) -> Option<&'a Attempt> {
    let n = choice.measure.counted.checked_sub(1)?;
    attempts.iter().find(|a| a.counted == n)
}
