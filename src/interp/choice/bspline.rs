//! The B-spline search (module docs of [`super`]): least-squares control polygons of every
//! order for every vertex count from the fewest up.

use super::count::{better, checked_known};
use super::{bound, Attempt, Choice, Minimality, Search, SearchOptions, Start, Target, MAX_ORDER};
use crate::bspline::fit::fit_bspline;
use crate::error::{Error, Result};
use crate::interp::methods::Method;
use nalgebra::Vector2;

/// The B-spline search (module docs of [`super`]), with its evidence: every vertex count
/// below the answer is fitted with every order; an open curve of 2 vertices is a segment
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
    let mut found = None;
    for vertices in min_vertices..=max_vertices {
        let mut at_count: Option<Choice> = None;
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
            let Ok(measure) = target.measure(&method, &points) else {
                continue;
            };
            let c = Choice {
                method,
                points,
                within_tolerance: measure.distances.hausdorff() <= target.tolerance(),
                measure,
                evaluations: 0,
                start: Start::Fit,
            };
            if better(&c, at_count.as_ref()) {
                at_count = Some(c);
            }
        }
        attempts.push(Attempt {
            counted: at_count.as_ref().map_or(vertices, |c| c.measure.counted),
            best_error: at_count.as_ref().map(|c| c.measure.distances.hausdorff()),
            starts: orders,
            within_tolerance: at_count.as_ref().is_some_and(|c| c.within_tolerance),
        });
        if let Some(c) = at_count {
            let done = c.within_tolerance;
            if done {
                found = Some(vertices);
            }
            if better(&c, best.as_ref()) || done {
                best = Some(c);
            }
            if done {
                break;
            }
        }
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
            } else {
                Minimality::Searched
            }
        }
        Some(_) => Minimality::Searched,
    };
    Ok(Search {
        choice,
        attempts,
        minimality,
    })
}
