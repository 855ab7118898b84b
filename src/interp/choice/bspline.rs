//! The B-spline search (module docs of [`super`]): least-squares control polygons of every
//! order for every vertex count from the fewest up (or doubled and bisected).

use super::count::{better, checked_known};
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
    const CORRECTIONS: usize = 20;
    const FIT_SAMPLES: usize = 360;
    let closed = target.is_closed();
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
    let mut attempts = Vec::new();
    let mut found: Option<usize> = None;
    let mut scratch = Scratch::default();
    // one vertex count with every order: its best configuration, true if within tolerance
    let mut consider = |vertices: usize| -> bool {
        let mut at_count: Option<Choice> = None;
        // a dense reference: the orders are screened by the search's coarse error and the
        // best of them measured exactly (each exact measure costs the whole reference)
        let mut screened: Option<(f64, Method, Vec<Vector2<f64>>)> = None;
        let mut orders = 0;
        for order in 2..=vertices.min(MAX_ORDER) {
            orders += 1;
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
            if target.is_dense() {
                let e = target.search_error(&method, &points, &mut scratch);
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
        attempts.push(Attempt {
            counted: at_count.as_ref().map_or(vertices, |c| c.measure.counted),
            best_error: at_count.as_ref().map(|c| c.measure.distances.hausdorff()),
            starts: orders,
            within_tolerance: at_count.as_ref().is_some_and(|c| c.within_tolerance),
        });
        let Some(c) = at_count else { return false };
        let done = c.within_tolerance;
        if done && found.is_none_or(|f| vertices < f) {
            found = Some(vertices);
            best = Some(c);
        } else if found.is_none() && better(&c, best.as_ref()) {
            best = Some(c);
        }
        done
    };
    if options.every_count_below {
        // every count from the fewest up, the first within the tolerance the answer
        for vertices in min_vertices..=max_vertices {
            if consider(vertices) {
                break;
            }
        }
    } else if min_vertices <= max_vertices {
        // doubling up to a count within the tolerance, then bisection below it; the count
        // one below the answer is searched in full
        let (mut lo, mut hi) = (None, None);
        let mut v = min_vertices;
        loop {
            if consider(v) {
                hi = Some(v);
                break;
            }
            lo = Some(v);
            if v >= max_vertices {
                break;
            }
            v = v.saturating_mul(2).min(max_vertices);
        }
        if let (Some(mut lo), Some(mut hi)) = (lo, hi) {
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                if consider(mid) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
        }
        attempts.sort_by_key(|a| a.counted);
    }
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
    let minimality = match found {
        None => Minimality::NotMet,
        Some(v) if v == min_vertices => Minimality::MethodMinimum,
        Some(3) if !closed => {
            let b = bound::segment_bound(target.reference());
            if b > target.tolerance() {
                Minimality::LowerBound {
                    class: "a segment (2 vertices)",
                    bound: b,
                }
            } else if options.every_count_below {
                Minimality::Searched
            } else {
                Minimality::Bisected
            }
        }
        Some(_) if options.every_count_below => Minimality::Searched,
        Some(_) => Minimality::Bisected,
    };
    Ok(Search {
        choice,
        attempts,
        minimality,
    })
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
