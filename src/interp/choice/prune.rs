//! Starts from a configuration that meets the tolerance with more points (module docs of
//! [`super`], step 1, *pruned*): its points taken off one at a time, each time the one whose
//! removal raises the error least (on a dense reference, many at a time while many remain).

use super::polish::error_below;
use super::starts::{Candidate, Layout};
use super::target::Target;
use super::{Choice, Family, Scratch, Start};
use crate::interp::methods::{CubicEnd, Method};
use nalgebra::Vector2;

/// Pruned starts kept per count: the best removals of the last step.
const KEPT: usize = 3;

/// Points taken off in one step are more than this many places apart.
const BATCH_GAP: usize = 2;

/// A configuration in the search's variables: the positions on the shape (arc, in order),
/// the guides of an open guided curve, the cardinal `a`, the cubic end.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Seed {
    arcs: Vec<f64>,
    guides: Vec<Vector2<f64>>,
    a: f64,
    end: CubicEnd,
}

impl Seed {
    /// The seed of the variables `x` of `layout`, `None` if they are invalid.
    pub fn of_layout(target: &Target, layout: &Layout, x: &[f64]) -> Option<Seed> {
        let arcs = layout.arcs(target, x)?;
        let points = layout.points(target, x)?;
        let guides = if layout.guide_coordinates() > 0 {
            vec![points[0], points[points.len() - 1]]
        } else {
            Vec::new()
        };
        let a = match layout.method(x) {
            Method::Cardinal { a } => a,
            _ => 0.5,
        };
        Some(Seed {
            arcs,
            guides,
            a,
            end: layout.end,
        })
    }

    /// The seed of a configuration given as points (a known one): each point on the shape
    /// at the arc of its nearest reference point; `None` if the points do not follow the
    /// reference's direction or are not of `family`.
    pub fn of_choice(target: &Target, family: Family, choice: &Choice) -> Option<Seed> {
        if Family::of(&choice.method) != Some(family) {
            return None;
        }
        let guided = !target.is_closed() && family.guided();
        let points = &choice.points;
        let on: &[Vector2<f64>] = if guided {
            points.get(1..points.len().checked_sub(1)?)?
        } else {
            points
        };
        let len = target.length();
        let mut arcs: Vec<f64> = on.iter().map(|&p| target.arc_of(p)).collect();
        if target.is_closed() {
            // start at the smallest arc
            let first = (0..arcs.len()).min_by(|&i, &j| arcs[i].total_cmp(&arcs[j]))?;
            arcs.rotate_left(first);
        } else if arcs.len() >= 2 {
            // the layout's ends are the shape's
            let last = arcs.len() - 1;
            arcs[0] = 0.0;
            arcs[last] = len;
        }
        if !arcs.windows(2).all(|w| w[1] > w[0]) {
            return None;
        }
        let guides = if guided {
            vec![points[0], points[points.len() - 1]]
        } else {
            Vec::new()
        };
        let (a, end) = match choice.method {
            Method::Cardinal { a } => (a, CubicEnd::Relaxed),
            Method::Cubic { end } => (0.5, end),
            _ => (0.5, CubicEnd::Relaxed),
        };
        Some(Seed {
            arcs,
            guides,
            a,
            end,
        })
    }

    /// Distinct points of the seed (guides included).
    pub fn distinct(&self) -> usize {
        self.arcs.len() + self.guides.len()
    }
}

/// The starts for `n` distinct points pruned from `seed` (module docs): up to [`KEPT`], with
/// the evaluations made. None if the seed has no more points than `n`.
pub(super) fn pruned_starts(
    target: &Target,
    family: Family,
    seed: &Seed,
    n: usize,
    scratch: &mut Scratch,
) -> (Vec<Candidate>, usize) {
    let on_shape = n.saturating_sub(seed.guides.len());
    let fewest = if target.is_closed() { 3 } else { 2 };
    if seed.distinct() <= n || on_shape < fewest {
        return (Vec::new(), 0);
    }
    let layout = Layout {
        family,
        closed: target.is_closed(),
        on_shape,
        end: seed.end,
        symmetric: None,
    };
    let mut evals = 0;
    let mut arcs = seed.arcs.clone();
    let mut kept: Vec<(f64, Vec<f64>)> = Vec::new();
    while arcs.len() > on_shape {
        let last_step = arcs.len() == on_shape + 1;
        // an open target's ends stay
        let removable = if layout.closed {
            0..arcs.len()
        } else {
            1..arcs.len() - 1
        };
        // on a dense reference, many points to take off: up to half of them in one step, the
        // best removals that are apart (no two within BATCH_GAP places), which leaves the last
        // steps one by one
        let excess = arcs.len() - on_shape;
        let batch = if target.is_dense() {
            (excess / 2).max(1)
        } else {
            1
        };
        // the removals the step uses: the KEPT best on the last, else the best from which
        // `batch` apart ones are chosen (each one chosen rules out at most 2 BATCH_GAP others);
        // a removal that cannot be among them is measured only until it is known not to be
        let want = if last_step {
            KEPT
        } else {
            batch + 2 * BATCH_GAP * (batch - 1)
        };
        let mut tried: Vec<(f64, usize)> = Vec::with_capacity(want + 1);
        for i in removable {
            let fewer = removed(&arcs, &[i]);
            let step = Layout {
                on_shape: fewer.len(),
                ..layout.clone()
            };
            let x = step.variables(&fewer, &seed.guides, seed.a);
            let limit = if tried.len() == want {
                tried[want - 1].0
            } else {
                f64::INFINITY
            };
            let e = error_below(target, &step, &x, scratch, limit);
            evals += 1;
            if e.is_finite() && e < limit {
                // after the equal ones: the order of a stable sort of every removal
                let at = tried.partition_point(|t| t.0 <= e);
                tried.insert(at, (e, i));
                tried.truncate(want);
            }
        }
        if last_step {
            kept = tried
                .into_iter()
                .map(|(e, i)| (e, removed(&arcs, &[i])))
                .collect();
            break;
        }
        let mut chosen: Vec<usize> = Vec::new();
        let len = arcs.len();
        for &(_, i) in &tried {
            if chosen.len() == batch {
                break;
            }
            let apart = chosen.iter().all(|&j| {
                let d = i.abs_diff(j);
                let d = if layout.closed { d.min(len - d) } else { d };
                d > BATCH_GAP
            });
            if apart {
                chosen.push(i);
            }
        }
        if chosen.is_empty() {
            return (Vec::new(), evals);
        }
        arcs = removed(&arcs, &chosen);
    }
    let starts = kept
        .into_iter()
        .map(|(_, s)| {
            let x = layout.variables(&s, &seed.guides, seed.a);
            (layout.clone(), x, Start::Pruned)
        })
        .collect();
    (starts, evals)
}

/// `arcs` without the places `at`.
fn removed(arcs: &[f64], at: &[usize]) -> Vec<f64> {
    arcs.iter()
        .enumerate()
        .filter(|(i, _)| !at.contains(i))
        .map(|(_, &a)| a)
        .collect()
}
