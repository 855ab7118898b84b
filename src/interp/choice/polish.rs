//! The polish of a start (module docs of [`super`], steps 2–3): the cardinal `a` on a grid,
//! error equidistribution, compass search, and the dense measure of the result.

use super::starts::Layout;
use super::target::Target;
use super::{Choice, Family, Scratch, Start, GOAL, SEARCH_SAMPLES};
use crate::error::Result;
use crate::interp::methods::Interpolant;
use crate::metrics::curve::SegmentTree;
use nalgebra::Vector2;

/// The cardinal `a` set to the best of a coarse grid (other families: unchanged), with the
/// error of the result.
pub(super) fn tune_parameter(
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
    let own = x[last];
    for a in [own, 0.001, 0.25, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2, 1.5] {
        x[last] = a;
        let e = error_below(target, layout, &x, scratch, best.0);
        evals += 1;
        if e < best.0 {
            best = (e, a);
        }
    }
    x[last] = best.1;
    (x, best.0, evals)
}

pub(super) fn error_of(target: &Target, layout: &Layout, x: &[f64], scratch: &mut Scratch) -> f64 {
    error_below(target, layout, x, scratch, f64::INFINITY)
}

/// [`error_of`] when below `limit`, otherwise a value at least `limit`
/// ([`Target::search_error_below`]): for the stages that keep only what beats their best.
pub(super) fn error_below(
    target: &Target,
    layout: &Layout,
    x: &[f64],
    scratch: &mut Scratch,
    limit: f64,
) -> f64 {
    match layout.points(target, x) {
        Some(points) => target.search_error_below(&layout.method(x), &points, scratch, limit),
        None => f64::INFINITY,
    }
}

/// Step 2 of the module docs: a few damped rounds of error equidistribution over the arcs
/// between points, keeping the best.
pub(super) fn equidistribute(
    target: &Target,
    layout: &Layout,
    x: Vec<f64>,
    e: f64,
    scratch: &mut Scratch,
) -> (Vec<f64>, f64, usize) {
    const ROUNDS: usize = 8;
    const P: f64 = 2.0;
    if layout.symmetric.is_some() {
        // a rescaling of every arc would break the mirror pairs: symmetric starts go to
        // the compass search as they are
        return (x, e, 0);
    }
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
        let e = error_below(target, layout, &x, scratch, best.1);
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
    curve
        .sample_pieces_into(SEARCH_SAMPLES, &mut scratch.line)
        .ok()?;
    let tree = SegmentTree::along(&scratch.line).ok()?;
    let arcs = if target.is_closed() {
        s.len()
    } else {
        s.len() - 1
    };
    let mut errors = vec![0.0; arcs];
    let len = target.length();
    // a dense target: its simplification's vertices (within a sixteenth of the tolerance)
    let (points, at) = target.search_reference();
    for (p, &a) in points.iter().zip(at) {
        // the arc j with s[j] ≤ a < s[j + 1] (closed: a before the first point belongs to
        // the arc that wraps past the last)
        let a = if target.is_closed() && a < s[0] {
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
/// evaluations, stopping early at `GOAL` (0.9) of the tolerance (the coarse error a little below
/// it, so the dense check passes). On a dense reference (plain layouts) the search is
/// [`focused`].
pub(super) fn compass(
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
            if j < k + layout.guide_coordinates() {
                0.25 * len / layout.on_shape as f64
            } else {
                0.1
            }
        })
        .collect();
    let floor: Vec<f64> = h.iter().map(|v| v / 256.0).collect();
    if target.is_dense() && layout.symmetric.is_none() {
        return focused(target, layout, x, (h, floor), budget, scratch);
    }
    let mut evals = 0;
    let goal = GOAL * target.tolerance();
    while evals < budget && e > goal {
        let mut improved = false;
        for (j, &hj) in h.iter().enumerate() {
            if let Some(f) = step(target, layout, &mut x, (j, hj), e, scratch, &mut evals) {
                e = f;
                improved = true;
            }
            if evals >= budget {
                break;
            }
        }
        if !improved && halve(&mut h, &floor, 0..floor.len()) {
            break;
        }
    }
    (x, e, evals)
}

/// The compass search on a dense reference, whose answers have many points: the error is a
/// largest distance, which only the points near where it is reached can lower, so the steps
/// `±h` are tried on those first — the [`FOCUS`] positions around that place (two before it,
/// two after) and the guides and the cardinal `a` — and the first that lowers the error is
/// taken (the place then found again); when none does, the focus's steps are halved. It ends
/// at `GOAL` of the tolerance, at the budget, or when the focus's steps are all below their
/// floor (`steps`: the initial steps and their floors).
fn focused(
    target: &Target,
    layout: &Layout,
    mut x: Vec<f64>,
    steps: (Vec<f64>, Vec<f64>),
    budget: usize,
    scratch: &mut Scratch,
) -> (Vec<f64>, f64, usize) {
    let (mut h, floor) = steps;
    let goal = GOAL * target.tolerance();
    // measured in full once, for the place where the error is reached
    scratch.worst_point = None;
    let mut e = error_of(target, layout, &x, scratch);
    let mut evals = 1;
    while evals < budget && e > goal && e.is_finite() {
        let focus = focus_of(target, layout, &x, scratch.worst_point);
        let mut improved = false;
        for &j in &focus {
            if let Some(f) = step(target, layout, &mut x, (j, h[j]), e, scratch, &mut evals) {
                e = f;
                improved = true;
                break;
            }
            if evals >= budget {
                break;
            }
        }
        if !improved && halve(&mut h, &floor, focus.iter().copied()) {
            break;
        }
    }
    (x, e, evals)
}

/// Halves the steps `h[j]` of the coordinates `which`; whether all of them are now below
/// their floors (the search has converged on them).
fn halve(h: &mut [f64], floor: &[f64], which: impl Iterator<Item = usize>) -> bool {
    let mut all_small = true;
    for j in which {
        h[j] *= 0.5;
        all_small &= h[j] < floor[j];
    }
    all_small
}

/// The compass step on coordinate `j` of `x` by `h` (`(j, h)`): `x[j] + h`, else `x[j] − h`,
/// kept at the first whose error is below `e` (returned), `x` restored when neither is; the
/// evaluations counted in `evals`.
fn step(
    target: &Target,
    layout: &Layout,
    x: &mut [f64],
    (j, h): (usize, f64),
    e: f64,
    scratch: &mut Scratch,
    evals: &mut usize,
) -> Option<f64> {
    let old = x[j];
    for sign in [1.0, -1.0] {
        x[j] = old + sign * h;
        let f = error_below(target, layout, x, scratch, e);
        *evals += 1;
        if f < e {
            return Some(f);
        }
    }
    x[j] = old;
    None
}

/// Positions around the place where the error is reached that [`focused`] moves.
const FOCUS: usize = 4;

/// The coordinates [`focused`] tries: the [`FOCUS`] positions nearest along the shape to
/// `worst` (cyclically on a closed target), then the guides and the cardinal `a`; every
/// coordinate when the place is unknown.
fn focus_of(
    target: &Target,
    layout: &Layout,
    x: &[f64],
    worst: Option<Vector2<f64>>,
) -> Vec<usize> {
    let k = layout.positions();
    let Some(w) = worst.and_then(|p| target.search_arc_near(p)) else {
        return (0..x.len()).collect();
    };
    // positions before the place: the focus is the two before it and the two after
    let before = x[..k].partition_point(|&s| s <= w);
    let half = FOCUS / 2;
    let mut focus: Vec<usize> = if layout.closed {
        (0..FOCUS.min(k))
            .map(|i| (before + k + i - half) % k)
            .collect()
    } else {
        (before.saturating_sub(half)..(before + half).min(k)).collect()
    };
    focus.extend(k..x.len());
    focus
}

/// The configuration of `x` measured densely.
pub(super) fn finish(
    target: &Target,
    layout: &Layout,
    x: &[f64],
    start: Start,
) -> Result<Option<Choice>> {
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
        within_tolerance: measure.distances.hausdorff() <= target.tolerance(),
        measure,
        evaluations: 0,
        start,
    }))
}
