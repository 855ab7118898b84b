//! The B-spline search (module docs of [`super`]): least-squares control polygons of every
//! order for every vertex count from the fewest up (or doubled and bisected).

use super::known::{better, checked_known};
use super::{
    bound, Attempt, Choice, Minimality, Scratch, Search, SearchOptions, Start, Target, MAX_ORDER,
};
use crate::bspline::fit::fit_bspline;
use crate::error::{Error, Result};
use crate::interp::methods::Method;
use nalgebra::Vector2;

/// The B-spline search (module docs of [`super`]), with its evidence: every vertex count
/// below the answer is fitted with every order (with [`SearchOptions::every_count_below`]
/// off, the counts doubling and bisection tried); an open curve of 2 vertices is a segment
/// ([`bound::segment_bound`]).
pub(super) fn search(target: &Target, options: &SearchOptions) -> Result<Search> {
    let closed = target.is_closed();
    let samples = fit_samples(target);
    let min_vertices = if closed { 4 } else { 2 };
    let known = checked_known(target, options)?;
    let max_vertices = known
        .as_ref()
        .map(|k| k.measure.counted.saturating_sub(1))
        .unwrap_or(options.max_points)
        .min(samples.len());
    let mut sweep = OrderSweep {
        target,
        samples,
        scratch: Scratch::default(),
        evaluations: 0,
        attempts: Vec::new(),
        best: None,
        found: None,
    };
    walk_counts(
        min_vertices,
        max_vertices,
        options.every_count_below,
        |vertices| sweep.at_count(vertices),
    );
    if !options.every_count_below {
        sweep.attempts.sort_by_key(|a| a.counted);
    }
    let OrderSweep {
        evaluations,
        attempts,
        best,
        mut found,
        ..
    } = sweep;
    let known_count = known.as_ref().map(|k| k.measure.counted);
    let mut choice = match (best, known) {
        (Some(b), _) if b.within_tolerance => b,
        (_, Some(k)) => {
            found = known_count;
            k
        }
        (Some(b), None) => b,
        (None, None) => {
            return Err(Error::Degenerate {
                what: "automatic point choice",
                reason: "no B-spline of any order fits this target",
            })
        }
    };
    choice.evaluations = evaluations;
    Ok(Search {
        choice,
        attempts,
        minimality: minimality(target, found, min_vertices, options),
    })
}

/// The samples the polygons are fitted to: the reference thinned to about `FIT_SAMPLES`, its
/// ends kept.
fn fit_samples(target: &Target) -> Vec<Vector2<f64>> {
    const FIT_SAMPLES: usize = 360;
    let reference = target.reference();
    let step = (reference.len() / FIT_SAMPLES).max(1);
    let mut samples: Vec<Vector2<f64>> = reference.iter().step_by(step).copied().collect();
    if samples.last() != reference.last() {
        samples.push(reference[reference.len() - 1]);
    }
    samples.dedup();
    samples
}

/// The vertex counts tried, each by `try_count` (true: within the tolerance), from
/// `min` to `max`: every count from the fewest up to the first within the tolerance, or
/// (`every_count_below` off) doubling up to a count within it, then bisection below it, the
/// count one below the answer searched in full.
fn walk_counts(
    min: usize,
    max: usize,
    every_count_below: bool,
    mut try_count: impl FnMut(usize) -> bool,
) {
    if every_count_below {
        for vertices in min..=max {
            if try_count(vertices) {
                break;
            }
        }
        return;
    }
    if min > max {
        return;
    }
    let (mut lo, mut hi) = (None, None);
    let mut v = min;
    loop {
        if try_count(v) {
            hi = Some(v);
            break;
        }
        lo = Some(v);
        if v >= max {
            break;
        }
        v = v.saturating_mul(2).min(max);
    }
    if let (Some(mut lo), Some(mut hi)) = (lo, hi) {
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if try_count(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
    }
}

/// One vertex count fitted with every order, and what the counts so far found.
struct OrderSweep<'a> {
    target: &'a Target,
    samples: Vec<Vector2<f64>>,
    scratch: Scratch,
    /// Fit iterations and measures spent.
    evaluations: usize,
    /// Each count tried.
    attempts: Vec<Attempt>,
    /// The fewest-vertex configuration within the tolerance, else the best one.
    best: Option<Choice>,
    /// The fewest vertices within the tolerance.
    found: Option<usize>,
}

impl OrderSweep<'_> {
    /// Fits of every order at `vertices` vertices: the best configuration recorded, true if
    /// within the tolerance. A dense reference's orders are screened by the search's coarse
    /// error and the best of them measured exactly (each exact measure costs the whole
    /// reference).
    fn at_count(&mut self, vertices: usize) -> bool {
        const CORRECTIONS: usize = 20;
        let target = self.target;
        let mut at_count: Option<Choice> = None;
        let mut screened: Option<(f64, Method, Vec<Vector2<f64>>)> = None;
        let mut orders = 0;
        for order in 2..=vertices.min(MAX_ORDER) {
            orders += 1;
            let Ok(fit) = fit_bspline(&self.samples, vertices, order, CORRECTIONS) else {
                continue;
            };
            self.evaluations += fit.iterations + 1;
            let method = Method::BSpline { order };
            let mut points = fit.curve.points().to_vec();
            if target.is_closed() {
                // the fit closes the polygon on its first vertex; the method repeats it
                points.pop();
            }
            if target.is_dense() {
                let e = target.search_error(&method, &points, &mut self.scratch);
                if e.is_finite() && screened.as_ref().is_none_or(|s| e < s.0) {
                    screened = Some((e, method, points));
                }
                continue;
            }
            if let Some(c) = exact_choice(target, method, points) {
                if better(&c, at_count.as_ref()) {
                    at_count = Some(c);
                }
            }
        }
        if let Some((_, method, points)) = screened {
            at_count = exact_choice(target, method, points);
        }
        self.attempts.push(Attempt {
            counted: at_count.as_ref().map_or(vertices, |c| c.measure.counted),
            best_error: at_count.as_ref().map(|c| c.measure.distances.hausdorff()),
            starts: orders,
            within_tolerance: at_count.as_ref().is_some_and(|c| c.within_tolerance),
        });
        let Some(c) = at_count else { return false };
        let done = c.within_tolerance;
        if done && self.found.is_none_or(|f| vertices < f) {
            self.found = Some(vertices);
            self.best = Some(c);
        } else if self.found.is_none() && better(&c, self.best.as_ref()) {
            self.best = Some(c);
        }
        done
    }
}

/// How sure the count is: the method's minimum, a segment's bound for an open curve of 3
/// vertices, else searched or bisected; not met without a count within the tolerance.
fn minimality(
    target: &Target,
    found: Option<usize>,
    min_vertices: usize,
    options: &SearchOptions,
) -> Minimality {
    let searched = if options.every_count_below {
        Minimality::Searched
    } else {
        Minimality::Bisected
    };
    match found {
        None => Minimality::NotMet,
        Some(v) if v == min_vertices => Minimality::MethodMinimum,
        Some(3) if !target.is_closed() => {
            let b = bound::segment_bound(target.reference());
            if b > target.tolerance() {
                Minimality::LowerBound {
                    class: "a segment (2 vertices)",
                    bound: b,
                }
            } else {
                searched
            }
        }
        Some(_) => searched,
    }
}

/// The configuration with its exact measure ([`Target::measure`]); `None` if the method
/// refuses the points.
fn exact_choice(target: &Target, method: Method, points: Vec<Vector2<f64>>) -> Option<Choice> {
    let measure = target.measure(&method, &points).ok()?;
    Some(Choice {
        method,
        points,
        within_tolerance: measure.distances.hausdorff() <= target.tolerance(),
        measure,
        evaluations: 0,
        start: Start::Fit,
    })
}
