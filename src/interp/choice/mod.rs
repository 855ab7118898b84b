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
//! **Search, for one count `n`** ([`Attempt`]):
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
//!    the next best, up to [`POLISHED_STARTS`] per end condition, on every coordinate
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
//! every count below it is fitted.

pub mod bound;
mod bspline;
mod layout;
mod local;
mod prune;
pub mod symmetry;
mod target;

pub use layout::{A_STEP, GUIDE_REACH};
pub use target::{Target, CORNER_TURN};

use crate::error::{Error, Result};
use crate::interp::methods::{CubicEnd, Method};
use crate::metrics::curve::{Distances, Smoothness};
use layout::{candidates, Candidate};
use local::{compass, equidistribute, finish, tune_parameter};
use nalgebra::Vector2;
use prune::{pruned_starts, Seed};

/// Samples per piece for the accepted error (spec decision A19: at least 256).
pub const FINAL_SAMPLES: usize = 256;

/// Samples per piece while searching.
pub const SEARCH_SAMPLES: usize = 24;

/// The fraction of the tolerance at which the compass search stops.
pub const GOAL: f64 = 0.9;

/// The most error evaluations one compass search makes, whatever
/// [`SearchOptions::budget_per_coordinate`] asks.
pub const MAX_EVALUATIONS: usize = 100_000;

/// How many starts the compass search polishes per count and layout variant (a cubic end
/// condition), one after the other until one meets the tolerance: the best of each start
/// family and variant first.
pub const POLISHED_STARTS: usize = 5;

/// The highest B-spline order tried.
pub const MAX_ORDER: usize = 12;

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
    /// A configuration with more points that meets the tolerance, points taken off
    /// (module docs, step 1).
    Pruned,
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
            Minimality::Searched => "fewest found (every lower count searched)".into(),
            Minimality::Bisected => "fewest found (lower counts bisected)".into(),
            Minimality::NotMet => "none within the tolerance".into(),
        }
    }

    /// Whether the count is proven minimal.
    pub fn proven(&self) -> bool {
        matches!(
            self,
            Minimality::MethodMinimum | Minimality::LowerBound { .. }
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

/// The fewest points with which `family` draws `target` within its tolerance (module docs):
/// [`search`]'s choice.
///
/// # Errors
/// As [`search`].
pub fn fewest_points(target: &Target, family: Family, options: &SearchOptions) -> Result<Choice> {
    search(target, family, options).map(|s| s.choice)
}

/// The fewest points with which `family` draws `target` within its tolerance, with the
/// evidence (module docs). If no count up to [`SearchOptions::max_points`] does, the
/// configuration with the lowest error found is returned with `within_tolerance == false`.
///
/// Every configuration tried counts at most [`SearchOptions::max_points`] points (as the
/// paper counts them: repeats and guides included).
///
/// # Errors
/// [`Error::TooLarge`] for a `max_points` beyond [`crate::error::MAX_ELEMENTS`] or
/// `random_starts` beyond [`MAX_RANDOM_STARTS`];
/// [`Error::TooFewPoints`] for a `max_points` below the family's fewest on this target;
/// [`Error::Degenerate`] if no configuration tried is valid (an Angular spline on a polygon
/// whose every placement has collinear triples, say); the errors of [`Target::measure`] on
/// the returned configuration.
pub fn search(target: &Target, family: Family, options: &SearchOptions) -> Result<Search> {
    crate::error::size("maximum point count", options.max_points)?;
    if options.random_starts > MAX_RANDOM_STARTS {
        return Err(Error::TooLarge {
            what: "random starts per layout of the search",
            got: options.random_starts,
            max: MAX_RANDOM_STARTS,
        });
    }
    let closed = target.is_closed();
    let min = fewest_counted(family, closed);
    if options.max_points < min {
        return Err(Error::TooFewPoints {
            what: "maximum point count of the search (the family's fewest on this target)",
            needed: min,
            got: options.max_points,
        });
    }
    if family == Family::BSpline {
        return bspline::search(target, options);
    }
    let mut evaluations = 0;
    let min = min_distinct(family, closed);
    // the count is capped at a few points per reference segment (points may sit anywhere on
    // a segment: a polygon's sides need them), which bounds the search's cost for any
    // `max_points`
    let max = distinct_of(family, closed, options.max_points).min(max_distinct_for(target));
    let known = checked_known(target, options)?;
    // the configuration within the tolerance with the fewest points so far, in the search's
    // variables: the pruned starts of lower counts come from it
    let mut seed: Option<Seed> = known
        .as_ref()
        .and_then(|k| Seed::of_choice(target, family, k));
    let mut found: Option<(usize, Choice)> =
        known.map(|k| (distinct_of(family, closed, k.measure.counted), k));
    // 1. an upper count: the known one, or the first where a start meets the tolerance
    // the count whose best start came nearest, searched in full when no other count has a
    // valid configuration (an Angular spline on a polygon, whose placements with many points
    // have collinear triples)
    let mut nearest: Option<(f64, usize)> = None;
    if found.is_none() {
        for n in min..=max {
            let (best, e, evals) = first_look(target, family, n, options)?;
            evaluations += evals;
            if e.is_finite() && nearest.is_none_or(|(b, _)| e < b) {
                nearest = Some((e, n));
            }
            if let Some((best, s)) = best {
                found = Some((n, best));
                seed = s;
                break;
            }
        }
    }
    let top = found.as_ref().map_or(max + 1, |f| f.0);
    // 2. the counts below it, each with the full budget (and the starts pruned from the
    // fewest points found so far)
    let mut attempts: Vec<(usize, Attempt, Option<Choice>)> = Vec::new();
    type Tried = Vec<(usize, Attempt, Option<Choice>)>;
    let full = |n: usize,
                seed: &mut Option<Seed>,
                evaluations: &mut usize,
                attempts: &mut Tried|
     -> Result<Option<Choice>> {
        let (attempt, best, evals) = full_search(target, family, n, options, seed.as_ref())?;
        *evaluations += evals;
        let success = best
            .as_ref()
            .filter(|c| c.0.within_tolerance)
            .map(|c| c.0.clone());
        if let Some((_, s)) = best.as_ref().filter(|c| c.0.within_tolerance) {
            *seed = s.clone().or(seed.take());
        }
        attempts.push((n, attempt, best.map(|b| b.0)));
        Ok(success)
    };
    if options.every_count_below {
        // down from the upper count while the full search succeeds (each count pruned from
        // the one above), then every lower count from the method's minimum up
        let mut n = top;
        while n > min {
            match full(n - 1, &mut seed, &mut evaluations, &mut attempts)? {
                Some(c) => {
                    n -= 1;
                    found = Some((n, c));
                }
                None => break,
            }
        }
        let failed = n.saturating_sub(1);
        for m in min..failed {
            if let Some(c) = full(m, &mut seed, &mut evaluations, &mut attempts)? {
                found = Some((m, c));
                break;
            }
        }
    } else {
        // gallop down while the full search succeeds, then bisect between the lowest
        // success and the highest failure; the count below the answer searched in full
        let (mut ok, mut bad) = (top, min - 1);
        let (mut step, mut galloping) = (1, true);
        while ok - bad > 1 {
            let n = if galloping {
                ok.saturating_sub(step).max(bad + 1)
            } else {
                bad + (ok - bad) / 2
            };
            match full(n, &mut seed, &mut evaluations, &mut attempts)? {
                Some(c) => {
                    ok = n;
                    found = Some((n, c));
                    step *= 2;
                }
                None => {
                    bad = n;
                    galloping = false;
                }
            }
        }
    }
    if found.is_none() && attempts.iter().all(|a| a.2.is_none()) {
        if let Some((_, n)) = nearest.filter(|&(_, n)| attempts.iter().all(|a| a.0 != n)) {
            full(n, &mut seed, &mut evaluations, &mut attempts)?;
        }
    }
    attempts.sort_by_key(|a| a.0);
    let every_below = |n: usize| (min..n).all(|m| attempts.iter().any(|a| a.0 == m));
    let (mut choice, minimality) = match found {
        Some((n, c)) => {
            let m = if n == min {
                Minimality::MethodMinimum
            } else if let Some(b) = lower_bound(target, family, n - 1) {
                b
            } else if every_below(n) {
                Minimality::Searched
            } else {
                Minimality::Bisected
            };
            (c, m)
        }
        None => {
            // nothing within the tolerance: the lowest error found
            let best = attempts
                .iter()
                .filter_map(|a| a.2.as_ref())
                .min_by(|a, b| {
                    a.measure
                        .distances
                        .hausdorff()
                        .total_cmp(&b.measure.distances.hausdorff())
                })
                .cloned();
            match best {
                Some(b) => (b, Minimality::NotMet),
                None => {
                    return Err(Error::Degenerate {
                        what: "automatic point choice",
                        reason: "no configuration of the method is valid on this target",
                    })
                }
            }
        }
    };
    choice.evaluations = evaluations;
    Ok(Search {
        choice,
        attempts: attempts.into_iter().map(|a| a.1).collect(),
        minimality,
    })
}

/// A lower bound that makes `n − 1 = below` distinct points of `family` fail (module docs,
/// [`bound`]): a closed Angular spline through 3 points is their circumcircle.
fn lower_bound(target: &Target, family: Family, below: usize) -> Option<Minimality> {
    if !(family == Family::Angular && target.is_closed() && below == 3) {
        return None;
    }
    let bound = bound::sampled_circle_bound(target.reference());
    (bound > target.tolerance()).then_some(Minimality::LowerBound {
        class: "a circle (a closed Angular spline through 3 points)",
        bound,
    })
}

/// A configuration with its seed for the pruned starts of lower counts.
type Seeded = (Choice, Option<Seed>);

/// The first look at `n` points (the rise to an upper count): the starts with the cardinal
/// `a` tuned, the best measured densely if its coarse error is within the tolerance; the
/// configuration (with its seed) if it meets the tolerance, the best coarse error, and the
/// evaluations made.
fn first_look(
    target: &Target,
    family: Family,
    n: usize,
    options: &SearchOptions,
) -> Result<(Option<Seeded>, f64, usize)> {
    let mut scratch = Scratch::default();
    let mut evaluations = 0;
    let mut best: Option<(f64, Candidate)> = None;
    for (layout, x, start) in candidates(target, family, n, options.random_starts, options.seed) {
        let (x, e, evals) = tune_parameter(target, &layout, x, &mut scratch);
        evaluations += evals;
        if best.as_ref().is_none_or(|b| e < b.0) {
            best = Some((e, (layout, x, start)));
        }
    }
    match best {
        Some((e, (layout, x, start))) if e <= target.tolerance() => Ok((
            finish(target, &layout, &x, start)?
                .filter(|c| c.within_tolerance)
                .map(|c| (c, Seed::of_layout(target, &layout, &x))),
            e,
            evaluations,
        )),
        Some((e, _)) => Ok((None, e, evaluations)),
        None => Ok((None, f64::INFINITY, evaluations)),
    }
}

/// The full search for `n` distinct points (steps 1–3 of the module docs), with the starts
/// pruned `from` a configuration with more points: the attempt, the best configuration found
/// (with its seed), and the evaluations made.
fn full_search(
    target: &Target,
    family: Family,
    n: usize,
    options: &SearchOptions,
    from: Option<&Seed>,
) -> Result<(Attempt, Option<Seeded>, usize)> {
    let mut scratch = Scratch::default();
    let mut evaluations = 0;
    let mut all = candidates(target, family, n, options.random_starts, options.seed);
    if let Some(seed) = from {
        let (pruned, evals) = pruned_starts(target, family, seed, n, &mut scratch);
        evaluations += evals;
        all.extend(pruned);
    }
    let starts = all.len();
    let mut pool: Vec<(f64, Candidate)> = Vec::with_capacity(starts);
    for (layout, x, start) in all {
        let (x, e, evals) = tune_parameter(target, &layout, x, &mut scratch);
        evaluations += evals;
        let (x, e, evals) = equidistribute(target, &layout, x, e, &mut scratch);
        evaluations += evals;
        if e.is_finite() {
            pool.push((e, (layout, x, start)));
        }
    }
    // the best of each start family for each layout variant (cubic end condition) first, by
    // error, then the rest by error; POLISHED_STARTS polished per variant
    pool.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut order: Vec<usize> = Vec::new();
    let mut seen: Vec<(CubicEnd, Start)> = Vec::new();
    for (i, (_, (layout, _, start))) in pool.iter().enumerate() {
        if !seen.contains(&(layout.end, *start)) {
            seen.push((layout.end, *start));
            order.push(i);
        }
    }
    let rest: Vec<usize> = (0..pool.len()).filter(|i| !order.contains(i)).collect();
    order.extend(rest);
    let variants = CubicEnd::ALL
        .iter()
        .filter(|&&end| seen.iter().any(|s| s.0 == end))
        .count();
    let polished = POLISHED_STARTS.saturating_mul(variants.max(1));
    let mut best: Option<Seeded> = None;
    for &i in order.iter().take(polished) {
        let (e, (layout, x, start)) = &pool[i];
        let budget = options
            .budget_per_coordinate
            .saturating_mul(x.len())
            .clamp(50, MAX_EVALUATIONS);
        let (x, _, evals) = compass(target, layout, x.clone(), *e, budget, &mut scratch);
        evaluations += evals;
        if let Some(c) = finish(target, layout, &x, *start)? {
            if better(&c, best.as_ref().map(|b| &b.0)) {
                best = Some((c, Seed::of_layout(target, layout, &x)));
            }
        }
        if best.as_ref().is_some_and(|b| b.0.within_tolerance) {
            break;
        }
    }
    let attempt = Attempt {
        counted: counted_of(family, target.is_closed(), n),
        best_error: best.as_ref().map(|b| b.0.measure.distances.hausdorff()),
        starts,
        within_tolerance: best.as_ref().is_some_and(|b| b.0.within_tolerance),
    };
    Ok((attempt, best, evaluations))
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
    let within = measure.distances.hausdorff() <= target.tolerance();
    let counted = measure.counted;
    let min = Family::of(&k.method).map_or(0, |f| fewest_counted(f, target.is_closed()));
    Ok(
        (within && counted >= min && counted <= options.max_points).then(|| Choice {
            method: k.method,
            points: k.points.clone(),
            within_tolerance: true,
            measure,
            evaluations: k.evaluations,
            start: Start::Known,
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
