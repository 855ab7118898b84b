//! The count search: the fewest points with which a family draws a target (module docs of
//! [`super`], **Count**) — an upper count (the known configuration's, or the first count where
//! a start meets the tolerance), the counts below it searched in full (down one by one, or
//! galloped and bisected), the minimality of the answer, and the counts of each family
//! (distinct points, repeats of a closed curve, guides).

use super::counts::{counted_of, distinct_of, fewest_counted, min_distinct};
use super::known::{better, checked_known};
use super::polish::{compass, equidistribute, finish, tune_parameter};
use super::prune::{pruned_starts, Seed};
use super::starts::{candidates, Candidate};
use super::{
    bound, bspline, polygon, Attempt, Choice, Family, Minimality, Scratch, Search, SearchOptions,
    Start, Target, MAX_EVALUATIONS, MAX_RANDOM_STARTS, POLISHED_STARTS,
};
use crate::error::{Error, Result};
use crate::interp::methods::{CubicEnd, Method};

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
    check_options(family, target.is_closed(), options)?;
    let search = |options: &SearchOptions| match family {
        Family::BSpline => bspline::search(target, options),
        Family::Linear => polygon::search(target, options),
        _ => placed(target, family, options),
    };
    // a family that contains the polygon is never worse than the polygon's optimum
    let Some(polygon) = polygon_of(target, family, options)? else {
        return search(options);
    };
    let counted = polygon.measure.counted;
    let given = checked_known(target, options)?;
    if given.as_ref().is_some_and(|k| k.measure.counted <= counted) {
        return search(options);
    }
    let from_polygon = SearchOptions {
        known: Some(polygon),
        ..options.clone()
    };
    if !options.every_count_below {
        // counts bisected: from the polygon's count down, and on its own (its rise from the
        // method's minimum and the starts pruned from its own configurations reach counts
        // that starts pruned from the polygon miss), the fewer points kept
        let from = search(&from_polygon)?;
        // on a dense reference (a digitised outline, whose answers count many points) on its
        // own up to half as many points again: its rise from the minimum looks at every count
        let max_points = if target.is_dense() {
            let cap = from.choice.measure.counted.saturating_mul(3) / 2;
            options
                .max_points
                .min(cap.max(fewest_counted(family, target.is_closed())))
        } else {
            options.max_points
        };
        let own = search(&SearchOptions {
            max_points,
            ..options.clone()
        })?;
        let fewer =
            own.choice.within_tolerance && own.choice.measure.counted < from.choice.measure.counted;
        return Ok(if fewer {
            merged(own, from)
        } else {
            merged(from, own)
        });
    }
    // every count searched: on its own first, again below the polygon's count if it ends
    // above it (or finds nothing within the tolerance)
    let found = search(options)?;
    if found.choice.within_tolerance && found.choice.measure.counted <= counted {
        return Ok(found);
    }
    search(&from_polygon)
}

/// The answer of `kept` with the evidence of both searches: every count either searched in
/// full (the better attempt where both searched it), the evaluations of both.
fn merged(kept: Search, other: Search) -> Search {
    let mut attempts = kept.attempts;
    for a in other.attempts {
        match attempts.iter_mut().find(|b| b.counted == a.counted) {
            Some(b) if a.within_tolerance && !b.within_tolerance => *b = a,
            Some(_) => {}
            None => attempts.push(a),
        }
    }
    attempts.sort_by_key(|a| a.counted);
    let mut choice = kept.choice;
    choice.evaluations = choice.evaluations.saturating_add(other.choice.evaluations);
    Search {
        choice,
        attempts,
        minimality: kept.minimality,
    }
}

/// The polygon's exact optimum drawn by `family`, when the family contains the polygon (module
/// docs, **Polygon**): an order-2 B-spline on its points, a cardinal spline with `a = 0`
/// through them (open: the chords continued as guides, which zero tangents ignore); `None`
/// for the other families, when it counts more than [`SearchOptions::max_points`], or when the
/// polygon's optimum cannot be computed (an outline beyond its limits, [`polygon`]).
///
/// # Errors
/// The errors of [`Target::measure`].
fn polygon_of(target: &Target, family: Family, options: &SearchOptions) -> Result<Option<Choice>> {
    let method = match family {
        Family::BSpline => Method::BSpline { order: 2 },
        Family::Cardinal => Method::Cardinal { a: 0.0 },
        _ => return Ok(None),
    };
    // an outline too large for the polygon's sweeps has no bound (the family's own search
    // still runs)
    let Ok(optimum) = polygon::fewest_within(
        target,
        target.tolerance(),
        min_distinct(Family::Linear, target.is_closed()),
        true,
    ) else {
        return Ok(None);
    };
    if !optimum.choice.within_tolerance {
        return Ok(None);
    }
    let mut points = optimum.choice.points;
    if family == Family::Cardinal && !target.is_closed() {
        let n = points.len();
        let (first, last) = (
            points[0] * 2.0 - points[1],
            points[n - 1] * 2.0 - points[n - 2],
        );
        points.insert(0, first);
        points.push(last);
    }
    let measure = target.measure(&method, &points)?;
    let within = measure.distances.hausdorff() <= target.tolerance();
    Ok(
        (within && measure.counted <= options.max_points).then_some(Choice {
            method,
            points,
            within_tolerance: true,
            measure,
            evaluations: 1,
            start: Start::Exact,
        }),
    )
}

/// The search of an interpolating family by placed points (module docs, steps 1–3, and
/// **Count**).
///
/// # Errors
/// As [`search`].
pub(super) fn placed(target: &Target, family: Family, options: &SearchOptions) -> Result<Search> {
    let closed = target.is_closed();
    let min = min_distinct(family, closed);
    // the count is capped at a few points per reference segment (points may sit anywhere on
    // a segment: a polygon's sides need them), which bounds the search's cost for any
    // `max_points`
    let max = distinct_of(family, closed, options.max_points).min(max_distinct_for(target));
    let mut counts = Counts::new(target, family, options)?;
    // 1. an upper count: the known one, or the first where a start meets the tolerance
    let risen = counts.found.is_none();
    let nearest = if risen { counts.rise(min, max)? } else { None };
    let top = counts.found.as_ref().map_or(max + 1, |f| f.0);
    // a dense reference's upper count from the rise's cheap looks (or its cap) lies far above
    // the answer (three to four times on a coastline): the gallop's steps start larger there
    let jump = risen && target.is_dense();
    // 2. the counts below it, each with the full budget (and the starts pruned from the
    // fewest points found so far)
    if options.every_count_below {
        counts.every_count_below(top, min)?;
    } else {
        counts.gallop_and_bisect(top, min, jump)?;
    }
    // nothing valid anywhere: the count whose best start came nearest, in full
    if counts.found.is_none() && counts.tried.iter().all(|a| a.2.is_none()) {
        if let Some((_, n)) = nearest.filter(|&(_, n)| counts.tried.iter().all(|a| a.0 != n)) {
            if let Some(c) = counts.full(n)? {
                counts.found = Some((n, c));
            }
        }
    }
    counts.answer(min)
}

/// The options' sizes, and a `max_points` at least the family's fewest.
///
/// # Errors
/// As [`search`].
fn check_options(family: Family, closed: bool, options: &SearchOptions) -> Result<()> {
    crate::error::size("maximum point count", options.max_points)?;
    if options.random_starts > MAX_RANDOM_STARTS {
        return Err(Error::TooLarge {
            what: "random starts per layout of the search",
            got: options.random_starts,
            max: MAX_RANDOM_STARTS,
        });
    }
    let min = fewest_counted(family, closed);
    if options.max_points < min {
        return Err(Error::TooFewPoints {
            what: "maximum point count of the search (the family's fewest on this target)",
            needed: min,
            got: options.max_points,
        });
    }
    Ok(())
}

/// A count search under way (interpolating families): what it found, the configuration it
/// prunes lower counts' starts from, every count searched in full, the evaluations made.
struct Counts<'a> {
    target: &'a Target,
    family: Family,
    options: &'a SearchOptions,
    /// The fewest distinct points within the tolerance so far, and their configuration.
    found: Option<(usize, Choice)>,
    /// The configuration within the tolerance with the fewest points so far, in the search's
    /// variables: the pruned starts of lower counts come from it.
    seed: Option<Seed>,
    /// Every count searched in full: distinct points, the attempt, its best configuration.
    tried: Vec<(usize, Attempt, Option<Choice>)>,
    evaluations: usize,
}

impl<'a> Counts<'a> {
    /// A search that starts from the known configuration of `options`, if it holds.
    fn new(target: &'a Target, family: Family, options: &'a SearchOptions) -> Result<Self> {
        let known = checked_known(target, options)?;
        let closed = target.is_closed();
        Ok(Counts {
            target,
            family,
            options,
            seed: known
                .as_ref()
                .and_then(|k| Seed::of_choice(target, family, k)),
            found: known.map(|k| (distinct_of(family, closed, k.measure.counted), k)),
            tried: Vec::new(),
            evaluations: 0,
        })
    }

    /// Step 1 without a known configuration: the first count from `min` up to `max` where a
    /// start meets the tolerance becomes `found`. Returns the count whose best start came
    /// nearest (searched in full when no count has a valid configuration: an Angular spline
    /// on a polygon, whose placements with many points have collinear triples).
    ///
    /// On a dense reference with counts bisected the counts looked at grow by doubling steps
    /// (a digitised outline's first count can be a hundred or more), and the first that meets
    /// is then bisected down to the lowest the looks meet, as the one-by-one rise would find
    /// where a look that meets at `n` meets at every count above.
    fn rise(&mut self, min: usize, max: usize) -> Result<Option<(f64, usize)>> {
        let mut nearest: Option<(f64, usize)> = None;
        let doubling = self.target.is_dense() && !self.options.every_count_below;
        let (mut n, mut step, mut failed) = (min, 1, min - 1);
        while n <= max {
            if self.look(n, &mut nearest)? {
                break;
            }
            failed = n;
            n = if doubling {
                let next = n.saturating_add(step).min(max);
                step = step.saturating_mul(2);
                if next == n {
                    break;
                }
                next
            } else {
                n + 1
            };
        }
        // bisect between the last count that failed and the first that met
        while let Some((top, _)) = self.found.as_ref().filter(|f| f.0 > failed + 1) {
            let mid = failed + (top - failed) / 2;
            if !self.look(mid, &mut nearest)? {
                failed = mid;
            }
        }
        Ok(nearest)
    }

    /// The first look at `n` points: `found` (and the seed) if a start meets the tolerance,
    /// `nearest` kept; whether it met.
    fn look(&mut self, n: usize, nearest: &mut Option<(f64, usize)>) -> Result<bool> {
        let (best, e, evals) = first_look(self.target, self.family, n, self.options)?;
        self.evaluations += evals;
        if e.is_finite() && nearest.is_none_or(|(b, _)| e < b) {
            *nearest = Some((e, n));
        }
        match best {
            Some((best, s)) => {
                self.found = Some((n, best));
                self.seed = s;
                Ok(true)
            }
            None => Ok(false),
        }
    }

    /// The full search of `n` distinct points, recorded; its configuration if it meets the
    /// tolerance (which then seeds the pruned starts of lower counts).
    fn full(&mut self, n: usize) -> Result<Option<Choice>> {
        let (target, family, options) = (self.target, self.family, self.options);
        let (attempt, best, evals) = full_search(target, family, n, options, self.seed.as_ref())?;
        self.evaluations += evals;
        let success = best
            .as_ref()
            .filter(|c| c.0.within_tolerance)
            .map(|c| c.0.clone());
        if let Some((_, s)) = best.as_ref().filter(|c| c.0.within_tolerance) {
            self.seed = s.clone().or(self.seed.take());
        }
        self.tried.push((n, attempt, best.map(|b| b.0)));
        Ok(success)
    }

    /// Step 2 with [`SearchOptions::every_count_below`]: down from the upper count `top`
    /// while the full search succeeds (each count pruned from the one above), then every
    /// lower count from the method's minimum up.
    fn every_count_below(&mut self, top: usize, min: usize) -> Result<()> {
        let mut n = top;
        while n > min {
            match self.full(n - 1)? {
                Some(c) => {
                    n -= 1;
                    self.found = Some((n, c));
                }
                None => break,
            }
        }
        let failed = n.saturating_sub(1);
        for m in min..failed {
            if let Some(c) = self.full(m)? {
                self.found = Some((m, c));
                break;
            }
        }
        Ok(())
    }

    /// Step 2 without it: gallop down from `top` while the full search succeeds (steps from 1,
    /// doubling; with `jump`, from [`DENSE_GALLOP_FRACTION`] of the first count found), then
    /// bisect between the lowest success and the highest failure (the count below the answer
    /// is so searched in full).
    fn gallop_and_bisect(&mut self, top: usize, min: usize, mut jump: bool) -> Result<()> {
        let (mut ok, mut bad) = (top, min - 1);
        let (mut step, mut galloping) = (1, true);
        if jump && self.found.is_some() {
            step = (top / DENSE_GALLOP_FRACTION).max(1);
            jump = false;
        }
        while ok - bad > 1 {
            let n = if galloping {
                ok.saturating_sub(step).max(bad + 1)
            } else {
                bad + (ok - bad) / 2
            };
            match self.full(n)? {
                Some(c) => {
                    ok = n;
                    self.found = Some((n, c));
                    step = if jump {
                        (n / DENSE_GALLOP_FRACTION).max(1)
                    } else {
                        step.saturating_mul(2)
                    };
                    jump = false;
                }
                None => {
                    bad = n;
                    galloping = false;
                }
            }
        }
        Ok(())
    }

    /// The answer: the configuration found and how minimal its count is, or, with nothing
    /// within the tolerance, the lowest error found.
    ///
    /// # Errors
    /// [`Error::Degenerate`] if no configuration tried is valid.
    fn answer(mut self, min: usize) -> Result<Search> {
        self.tried.sort_by_key(|a| a.0);
        let tried = &self.tried;
        let every_below = |n: usize| (min..n).all(|m| tried.iter().any(|a| a.0 == m));
        let (mut choice, minimality) = match self.found {
            Some((n, c)) => {
                let m = if n == min {
                    Minimality::MethodMinimum
                } else if let Some(b) = lower_bound(self.target, self.family, n - 1) {
                    b
                } else if every_below(n) {
                    Minimality::Searched
                } else {
                    Minimality::Bisected
                };
                (c, m)
            }
            None => {
                let best = tried
                    .iter()
                    .filter_map(|a| a.2.as_ref())
                    .min_by(|a, b| {
                        a.measure
                            .distances
                            .hausdorff()
                            .total_cmp(&b.measure.distances.hausdorff())
                    })
                    .cloned()
                    .ok_or(Error::Degenerate {
                        what: "automatic point choice",
                        reason: "no configuration of the method is valid on this target",
                    })?;
                (best, Minimality::NotMet)
            }
        };
        choice.evaluations = self.evaluations;
        Ok(Search {
            choice,
            attempts: self.tried.into_iter().map(|a| a.1).collect(),
            minimality,
        })
    }
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
    pool.sort_by(|a, b| a.0.total_cmp(&b.0));
    let order = polish_order(&pool, target.is_dense());
    let mut best: Option<Seeded> = None;
    for &i in &order {
        let (e, (layout, x, start)) = &pool[i];
        let factor = if target.is_dense() {
            DENSE_BUDGET_FACTOR
        } else {
            1
        };
        let budget = options
            .budget_per_coordinate
            .saturating_mul(factor)
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

/// The starts `pool` (sorted by error) to polish, in order (module docs, step 3). On a sparse
/// reference the best of each start family for each layout variant (cubic end condition)
/// first, then the rest by error, [`POLISHED_STARTS`] per variant. On a dense one by error
/// alone, those within [`DENSE_POLISH_SPREAD`] of the best error, at most
/// [`DENSE_POLISHED_STARTS`] (each with [`DENSE_BUDGET_FACTOR`] times the budget): there the
/// budget, not the step size, ends a compass search, and a start's error falls by a tenth to a
/// third under it, so the starts well behind the best (the generic placements behind the
/// pruned ones, near the answer) spend it without meeting the tolerance, where a longer search
/// of the best does.
fn polish_order(pool: &[(f64, Candidate)], dense: bool) -> Vec<usize> {
    if dense {
        let least = pool.first().map_or(0.0, |p| p.0);
        return (0..pool.len())
            .take_while(|&i| pool[i].0 <= DENSE_POLISH_SPREAD * least)
            .take(DENSE_POLISHED_STARTS)
            .collect();
    }
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
    order.truncate(POLISHED_STARTS.saturating_mul(variants.max(1)));
    order
}

/// On a dense reference, the starts polished are those within this factor of the best
/// start's error ([`polish_order`]).
const DENSE_POLISH_SPREAD: f64 = 1.15;

/// On a dense reference, the most starts polished per count ([`polish_order`]).
const DENSE_POLISHED_STARTS: usize = 2;

/// On a dense reference, the compass search's budget is this many times the options'.
const DENSE_BUDGET_FACTOR: usize = 3;

/// On a dense reference the gallop down from the rise's upper count steps by this fraction of
/// the first count found ([`Counts::gallop_and_bisect`]).
const DENSE_GALLOP_FRACTION: usize = 8;

/// The most distinct points the search tries on `target`: four per reference vertex, at
/// least 64.
pub fn max_distinct_for(target: &Target) -> usize {
    target.reference().len().saturating_mul(4).max(64)
}
