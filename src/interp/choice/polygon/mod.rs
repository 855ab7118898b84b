//! The polygon's fewest points, exactly (module docs of [`super`], **Polygon**): the shortest
//! path over the graph of shortcuts that stay within the tolerance (Imai & Iri, "Polygonal
//! approximations of a curve — formulations and algorithms", 1988), every shortcut from one
//! point tested in one sweep by the cones of Chan & Chin ("On approximation of polygonal
//! curves with minimum number of line segments or minimum error", 1996).
//!
//! **Files.** This file: the search, the candidates, the bound; `cone.rs`: the cone of
//! directions within the tolerance of every vertex swept; `graph.rs`: the sweeps that list
//! the shortcuts and the shortest paths and cycles over them; `straight.rs`: the exactly
//! straight runs of the reference merged into one segment before the sweeps.
//!
//! **Candidates.** The points may sit at the reference's vertices and at equal steps along
//! each of its segments, at most `h` apart along the outline, `h` = [`RESOLUTION`] × 2 × the
//! tolerance. It is coarser only when the points along the segments would exceed
//! [`ALONG_PER_SEGMENT`] per segment and [`MIN_ALONG`] in all (a tolerance far below the
//! outline's size), or the work its limits ([`MAX_CANDIDATES`], [`MAX_SHORTCUTS`],
//! [`MAX_CYCLE_WORK`]); the answer's bound states the `h` it used. An open outline's polygon
//! starts and ends at the outline's ends, as every placement of the search. A vertex that
//! lies exactly between its neighbours (`straight.rs`) is no candidate of its own: the
//! outline is the same, and a straight run of `m` such vertices would add `m²` shortcuts.
//! No side has zero length (a polygon's neighbours differ): an outline through one point
//! twice gets a point between.
//!
//! **Shortcuts.** The side from candidate `a` to candidate `b` is allowed when the outline
//! between them lies within the tolerance `ε` of the side. The outline runs from one end of
//! the side to the other, so its projection on the side's line covers the side: every point
//! of the side is then within `ε` of the outline too — the measure is the symmetric one of
//! the table, taken side by side (each side against the stretch of outline it replaces; the
//! table's Hausdorff distance, against the whole outline, can only be smaller). The outline
//! between is straight between reference vertices and a point's distance to a segment is
//! convex along a straight line, so the reference vertices between `a` and `b` decide.
//!
//! **Cones.** The rays from `a` that pass within `ε` of a point `q` farther than `ε` from `a`
//! are the directions within `asin(ε / |q − a|)` of `q − a`; sweeping forward from `a`, the
//! intersection of these arcs over the vertices passed is a cone (an arc narrower than π)
//! that only narrows, and `b` is reachable forward when `b − a` lies in it; the sweep stops
//! when it is empty. A backward sweep from `b` does the same for the rays from `b`. A point
//! within `ε` of both rays — of the ray from `a` towards `b` and of the ray from `b` towards
//! `a` — is within `ε` of the segment `ab`, so the side is allowed exactly when both sweeps
//! reach it: `O(n r)` for `n` candidates reaching `r` candidates on. The sides between two
//! candidates of one reference segment are all allowed and are not listed (the path scans
//! carry the least distance along the segment), and the points along a segment that a cone
//! holds are one interval of them, found by bisection: long straight sides cost no more
//! than their vertices.
//!
//! **Shortest path.** Open: the fewest sides from the first candidate to the last (one pass in
//! order). Closed: a polygon has a side covering every candidate `k`, so it has a vertex among
//! the candidates from which a shortcut passes `k` (or `k` itself); for the `k` with the fewest
//! such starts, the shortest closed path from every start is computed, all starts in one pass
//! (a distance per start, the passes over the shortcuts shared), and the least is the answer.
//!
//! **Why it is the fewest.** Every polygon with points in order along the outline whose sides
//! each lie within `ε − h/2` of their stretch can have its points moved to the nearest
//! candidates, each by at most `h/2` along the outline: each side moves by at most `h/2`, and
//! the bits of outline that change sides lie within `h/2` of a moved point, so the sides stay
//! within `ε` (given `h ≤ ε`). So no polygon with fewer points is within `ε − h/2`:
//! [`Minimality::Optimum`].
//!
//! The answer is measured as every configuration is ([`Target::measure`]); a side that the
//! cones allow by rounding but the measure does not (or, on an exact shape, a point placed on
//! the curve beside its reference chord) makes the search run again with the tolerance
//! lowered by the excess.

use super::{Attempt, Choice, Minimality, Search, SearchOptions, Start, Target};
use crate::error::{Error, Result};
use crate::interp::methods::Method;
use cone::V;
use graph::{Item, Shortcuts};

mod cone;
mod graph;
mod straight;

pub use graph::{MAX_CYCLE_WORK, MAX_SHORTCUTS};

/// The candidates' spacing along the outline as a fraction of twice the tolerance: every
/// point of the outline is within `RESOLUTION × ε` of a candidate, so a polygon with fewer
/// points errs by more than `(1 − RESOLUTION) ε` (module docs).
pub const RESOLUTION: f64 = 1.0 / 32.0;

/// The most candidates: beyond, the spacing is doubled until they fit.
pub const MAX_CANDIDATES: usize = 1 << 20;

/// The most candidates along the sides per reference segment, on average (at least
/// [`MIN_ALONG`] in all): beyond, the spacing is the finest that keeps them within (a
/// tolerance far below the outline's size would otherwise put millions of candidates on a
/// few long sides).
pub const ALONG_PER_SEGMENT: usize = 32;

/// The most candidates along the sides of `segments` reference segments.
fn along_cap(segments: usize) -> usize {
    segments.saturating_mul(ALONG_PER_SEGMENT).max(MIN_ALONG)
}

/// The candidates along the sides always allowed, whatever the segments.
pub const MIN_ALONG: usize = 8192;

/// The most reference vertices that are all candidates (below, the candidates are a superset
/// of the vertices).
pub const VERTEX_CANDIDATES: usize = 1 << 14;

/// The fewest points of the polygon on `target` (module docs): the exact optimum over the
/// candidates, or, when it counts more than [`SearchOptions::max_points`], the polygon over
/// the reference's vertices of at most that many points with the least tolerance it meets
/// (bisected), not within the target's tolerance ([`Minimality::NotMet`]).
///
/// # Errors
/// [`Error::Degenerate`] if no polygon can be measured on the target.
pub(super) fn search(target: &Target, options: &SearchOptions) -> Result<Search> {
    let closed = target.is_closed();
    let min_distinct = super::counts::min_distinct(super::Family::Linear, closed);
    let tolerance = target.tolerance();
    let found = fewest_within(target, tolerance, min_distinct, true)?;
    if found.choice.measure.counted <= options.max_points && found.choice.within_tolerance {
        let known = super::known::checked_known(target, options)?;
        if let Some(k) = known.filter(|k| k.measure.counted < found.choice.measure.counted) {
            // a given polygon the side-by-side measure does not allow, but the table's does
            return Ok(Search {
                attempts: vec![attempt_of(&k)],
                choice: k,
                minimality: Minimality::Searched,
            });
        }
        let bound = found.bound();
        // candidates too far apart for the argument: the fewest over them, not proven
        let minimality = if bound > 0.0 {
            Minimality::Optimum { bound }
        } else {
            Minimality::Candidates {
                spacing: 2.0 * found.snap,
            }
        };
        return Ok(Search {
            attempts: vec![attempt_of(&found.choice)],
            choice: found.choice,
            minimality,
        });
    }
    // too many points: the least tolerance met with at most max_points, by bisection between
    // the tolerance (too many) and the outline's size (a triangle or a segment meets it, or
    // the size doubled does)
    let max_distinct = options.max_points.saturating_sub(usize::from(closed));
    let mut lo = tolerance;
    let mut hi = 2.0 * target.size().max(tolerance);
    let mut best = None;
    for _ in 0..48 {
        let f = fewest_within(target, hi, min_distinct, false)?;
        if f.choice.points.len() <= max_distinct {
            best = Some(f);
            break;
        }
        lo = hi;
        hi *= 2.0;
    }
    let mut best = best.ok_or(Error::Degenerate {
        what: "automatic point choice",
        reason: "no polygon of at most the maximum point count meets any tolerance",
    })?;
    for _ in 0..16 {
        let mid = 0.5 * (lo + hi);
        let f = fewest_within(target, mid, min_distinct, false)?;
        if f.choice.points.len() <= max_distinct {
            hi = mid;
            best = f;
        } else {
            lo = mid;
        }
    }
    let mut choice = best.choice;
    choice.within_tolerance = choice.measure.distances.hausdorff() <= tolerance;
    Ok(Search {
        attempts: vec![attempt_of(&choice)],
        choice,
        minimality: Minimality::NotMet,
    })
}

fn attempt_of(c: &Choice) -> Attempt {
    Attempt {
        counted: c.measure.counted,
        best_error: Some(c.measure.distances.hausdorff()),
        starts: 1,
        within_tolerance: c.within_tolerance,
    }
}

/// The exact optimum within one tolerance, with what its minimality rests on.
pub(super) struct Optimum {
    /// The polygon, measured against the target's tolerance.
    pub choice: Choice,
    /// The tolerance the cones used (the one asked, or lower after a rounding excess).
    pub used: f64,
    /// The largest distance along the outline from a point to the nearest candidate.
    pub snap: f64,
}

impl Optimum {
    /// The error every polygon with fewer points exceeds (module docs); 0 when the candidates
    /// are too coarse for the argument (`snap` above half the tolerance).
    fn bound(&self) -> f64 {
        if 2.0 * self.snap <= self.used {
            self.used - self.snap
        } else {
            0.0
        }
    }
}

/// The exact optimum within `tolerance` (module docs), at least `min_distinct` points, the
/// configuration measured against the target's own tolerance; with `exact`, over the
/// candidates along the sides too and the one of about the least error among the fewest
/// ([`REFINEMENTS`]), otherwise over the reference's vertices alone (a segment longer than a
/// quarter of the outline cut once or more), a bound of 0.
///
/// # Errors
/// [`Error::Degenerate`] if no polygon measures within `tolerance` even after lowering it.
pub(super) fn fewest_within(
    target: &Target,
    tolerance: f64,
    min_distinct: usize,
    exact: bool,
) -> Result<Optimum> {
    let mut used = tolerance;
    for _ in 0..8 {
        let (items, path, snap) = optimum_points(target, used, min_distinct, exact)?;
        let path = if exact {
            least_tolerance(&items, target.is_closed(), path, used, min_distinct)
        } else {
            path
        };
        let candidates: Vec<&Item> = items.iter().filter(|i| i.candidate).collect();
        let points: Vec<V> = path.iter().map(|&i| candidates[i].p).collect();
        let method = Method::Linear;
        let measure = target.measure(&method, &points)?;
        let error = measure.distances.hausdorff();
        if error <= tolerance {
            return Ok(Optimum {
                choice: Choice {
                    method,
                    points,
                    within_tolerance: error <= target.tolerance(),
                    measure,
                    evaluations: 1,
                    start: Start::Exact,
                },
                used,
                snap,
            });
        }
        // rounding, or a point on an exact curve beside its chord: lower by the excess
        used -= 2.0 * (error - tolerance) + f64::EPSILON * target.size();
        if used.is_nan() || used <= 0.0 {
            break;
        }
    }
    Err(Error::Degenerate {
        what: "polygon optimum",
        reason: "its sides stay outside the tolerance after rounding corrections",
    })
}

/// Among the polygons of as many points as `path` over the same candidates, one with about
/// the least tolerance (module docs): a tolerance a billionth of `eps` tried first (a polygon
/// outline's own corners), then [`REFINEMENTS`] bisections between it and `eps`.
fn least_tolerance(
    items: &[Item],
    closed: bool,
    path: Vec<usize>,
    eps: f64,
    min_distinct: usize,
) -> Vec<usize> {
    let count = path.len();
    let within = |e: f64| {
        fewest_over(items, e, closed, min_distinct)
            .flatten()
            .filter(|p| p.len() <= count)
    };
    let (mut lo, mut hi) = (eps * 1e-9, eps);
    if let Some(p) = within(lo) {
        return p;
    }
    let mut best = path;
    for _ in 0..REFINEMENTS {
        let mid = 0.5 * (lo + hi);
        match within(mid) {
            Some(p) => {
                best = p;
                hi = mid;
            }
            None => lo = mid,
        }
    }
    best
}

/// Bisections of the tolerance among the fewest points (module docs).
pub const REFINEMENTS: usize = 3;

/// A point of the outline the sweeps pass: a reference vertex, whose distance to a side
/// counts, or a point along a segment; either may be a candidate.
/// The points the sweeps pass, the optimum's candidates within `eps` (indices among the
/// candidates) and the largest distance along the outline to a candidate. The spacing along
/// the sides is `2 RESOLUTION eps` with `along` (no finer than the caps
/// [`ALONG_PER_SEGMENT`] and [`MIN_ALONG`] allow), else a quarter of the outline; every
/// reference vertex is a candidate while the outline has at most [`VERTEX_CANDIDATES`]
/// vertices. Beyond [`MAX_SHORTCUTS`] or [`MAX_CYCLE_WORK`], the spacing is doubled up to a
/// quarter of the outline, then only the vertices that keep the candidates within the spacing
/// are candidates, the spacing again from the start and doubled until the work fits.
///
/// # Errors
/// [`Error::Degenerate`] if no polygon follows the outline; [`Error::TooLarge`] if the work
/// exceeds its limits at every spacing.
fn optimum_points(
    target: &Target,
    eps: f64,
    min_distinct: usize,
    along: bool,
) -> Result<(Vec<Item>, Vec<usize>, f64)> {
    // straight runs as one segment each: the same outline, fewer shortcuts
    let merged = straight::merged(target)?;
    let target = merged.as_ref().unwrap_or(target);
    let widest = target.length() / 4.0;
    // the finest spacing the caps on the candidates along the sides allow: the pieces beyond
    // the segments' own number are at most length / h
    let segments = target.arcs().len() - 1;
    let finest = (target.length() / along_cap(segments) as f64).max(f64::MIN_POSITIVE);
    let mut all = target.reference().len() <= VERTEX_CANDIDATES;
    let start = if along || !all {
        (2.0 * RESOLUTION * eps).max(finest).min(widest)
    } else {
        widest
    };
    let mut h = start;
    loop {
        if let Some(items) = items(target, h, all)? {
            if let Some(path) = fewest_over(&items, eps, target.is_closed(), min_distinct) {
                let path = path.ok_or(Error::Degenerate {
                    what: "polygon optimum",
                    reason: "no polygon of the fewest points a polygon needs follows the outline",
                })?;
                let snap = max_gap(&items, target.is_closed(), target.length()) / 2.0;
                return Ok((items, path, snap));
            }
        }
        // coarser along the sides first, then the vertices thinned, from the start again
        if h < widest {
            h = (2.0 * h).min(widest);
        } else if all {
            all = false;
            h = start;
        } else {
            return Err(Error::TooLarge {
                what: "outline vertices for the polygon's optimum (its sweeps pass their limit)",
                got: target.reference().len(),
                max: MAX_CANDIDATES,
            });
        }
    }
}

/// The fewest of the candidates among `items` (their indices among the candidates, in
/// order) that draw the items within `eps`, at least `min_distinct`: `None` beyond
/// [`MAX_SHORTCUTS`] or [`MAX_CYCLE_WORK`], `Some(None)` if no polygon follows them.
fn fewest_over(
    items: &[Item],
    eps: f64,
    closed: bool,
    min_distinct: usize,
) -> Option<Option<Vec<usize>>> {
    let graph = Shortcuts::new(items, eps, closed)?;
    if closed {
        graph.shortest_cycle(min_distinct)
    } else {
        Some(graph.shortest_path(min_distinct))
    }
}

/// The largest gap between consecutive candidates along the outline (a closed one's last to
/// its first included).
fn max_gap(items: &[Item], closed: bool, length: f64) -> f64 {
    let s: Vec<f64> = items.iter().filter(|i| i.candidate).map(|i| i.s).collect();
    let inner = s.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    match (closed, s.first(), s.last()) {
        (true, Some(first), Some(last)) => inner.max(first + length - last),
        _ => inner,
    }
}

/// How many parts a reference segment of `length` is cut into at spacing `h`.
fn parts(length: f64, h: f64) -> usize {
    let k = (length / h).ceil();
    if k.is_finite() && k >= 1.0 {
        (k as usize).min(MAX_CANDIDATES)
    } else {
        1
    }
}

/// The points the sweeps pass at spacing `h` (module docs), in order along the outline (a
/// closed one without its closing vertex): every reference vertex, a candidate when `all`
/// or when passing it over would leave more than `h` between candidates (an open outline's
/// ends always); points at equal steps along the segments longer than `h`, candidates all.
/// `None` beyond [`MAX_CANDIDATES`] points, or with fewer than 3 candidates.
fn items(target: &Target, h: f64, all: bool) -> Result<Option<Vec<Item>>> {
    let points = target.reference();
    let arcs = target.arcs();
    let closed = target.is_closed();
    let mut total = usize::from(!closed);
    for w in arcs.windows(2) {
        total = total.saturating_add(parts(w[1] - w[0], h));
    }
    let segments = arcs.len() - 1;
    let along = total - segments - usize::from(!closed);
    if total > MAX_CANDIDATES || along > along_cap(segments) {
        return Ok(None);
    }
    let mut out: Vec<Item> = Vec::with_capacity(total);
    // a point where the previous one is adds nothing: it is merged into it (a polygon's
    // consecutive points differ)
    let mut push = |item: Item| match out.last_mut() {
        Some(last) if last.p == item.p => {
            last.vertex |= item.vertex;
            last.candidate |= item.candidate;
        }
        _ => out.push(item),
    };
    let mut last = 0.0;
    for (k, w) in arcs.windows(2).enumerate() {
        let candidate = all || k == 0 || w[1] - last > h;
        if candidate {
            last = w[0];
        }
        push(Item {
            p: points[k],
            s: w[0],
            vertex: true,
            candidate,
        });
        let n = parts(w[1] - w[0], h);
        for j in 1..n {
            let s = w[0] + (w[1] - w[0]) * j as f64 / n as f64;
            let p = target.point(s);
            crate::error::finite_points("polygon optimum candidate", &[p])?;
            last = s;
            push(Item {
                p,
                s,
                vertex: false,
                candidate: true,
            });
        }
    }
    if !closed {
        push(Item {
            p: points[points.len() - 1],
            s: target.length(),
            vertex: true,
            candidate: true,
        });
    } else if out.len() > 1 && out[out.len() - 1].p == out[0].p {
        let end = out.pop().expect("two items at least");
        out[0].candidate |= end.candidate;
    }
    Ok((out.iter().filter(|i| i.candidate).count() >= 3).then_some(out))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::curve::segment_distance;
    use proptest::prelude::*;

    /// Whether the side from `a` forward to `b` keeps every vertex between within `eps`,
    /// by brute force.
    fn side_ok(p: &[V], a: usize, b: usize, eps: f64) -> bool {
        let n = p.len();
        let mut k = (a + 1) % n;
        while k != b {
            if segment_distance(p[k], p[a], p[b]) > eps {
                return false;
            }
            k = (k + 1) % n;
        }
        true
    }

    /// The fewest points by trying every subset of the vertices.
    fn brute_force(p: &[V], eps: f64, closed: bool) -> usize {
        let n = p.len();
        let mut best = usize::MAX;
        for mask in 0u32..(1 << n) {
            let set: Vec<usize> = (0..n).filter(|&i| mask >> i & 1 == 1).collect();
            if set.len() < 3 || set.len() >= best {
                continue;
            }
            if !closed && (set[0] != 0 || *set.last().unwrap() != n - 1) {
                continue;
            }
            let sides = if closed { set.len() } else { set.len() - 1 };
            if (0..sides).all(|i| side_ok(p, set[i], set[(i + 1) % set.len()], eps)) {
                best = set.len();
            }
        }
        best
    }

    fn outline() -> impl Strategy<Value = (Vec<V>, f64, bool)> {
        (
            prop::collection::vec((0.0..1.0f64, 0.0..1.0f64), 4..=11),
            0.01..0.4f64,
            any::<bool>(),
        )
            .prop_map(|(xy, eps, closed)| {
                (
                    xy.into_iter().map(|(x, y)| V::new(x, y)).collect(),
                    eps,
                    closed,
                )
            })
    }

    /// Whether every reference vertex among `items` strictly between candidates `a` and `b`
    /// (forward) lies within `eps` of the side, by brute force.
    fn items_side_ok(items: &[Item], a: usize, b: usize, eps: f64) -> bool {
        let m = items.len();
        let mut k = (a + 1) % m;
        while k != b {
            if items[k].vertex && segment_distance(items[k].p, items[a].p, items[b].p) > eps {
                return false;
            }
            k = (k + 1) % m;
        }
        true
    }

    /// The fewest points over the candidates of `items`, at least `min_points`, by
    /// breadth-first search over every pair of candidates tested by brute force.
    fn items_brute_force(
        items: &[Item],
        eps: f64,
        closed: bool,
        min_points: usize,
    ) -> Option<usize> {
        let at: Vec<usize> = (0..items.len()).filter(|&k| items[k].candidate).collect();
        let n = at.len();
        let (starts, min_sides) = if closed {
            ((0..n).collect::<Vec<_>>(), min_points)
        } else {
            (vec![0], min_points - 1)
        };
        let span = if closed { n } else { n - 1 };
        let mut best: Option<usize> = None;
        for s in starts {
            // positions unrolled from s: reached with exactly `sides` sides
            let mut layer = vec![false; span + 1];
            layer[0] = true;
            for sides in 1..=span {
                let mut next = vec![false; span + 1];
                for q in 0..span {
                    if !layer[q] {
                        continue;
                    }
                    for (r, slot) in next.iter_mut().enumerate().skip(q + 1) {
                        let (a, b) = (at[(s + q) % n], at[(s + r) % n]);
                        if items_side_ok(items, a, b, eps) {
                            *slot = true;
                        }
                    }
                }
                layer = next;
                if layer[span] && sides >= min_sides {
                    let points = if closed { sides } else { sides + 1 };
                    best = Some(best.map_or(points, |b| b.min(points)));
                    break;
                }
            }
        }
        best
    }

    /// Outlines of a few vertices with points along their sides, some vertices not
    /// candidates (an open outline's ends always are).
    fn outline_with_points_along() -> impl Strategy<Value = (Vec<Item>, f64, bool)> {
        (
            prop::collection::vec(
                ((0.0..1.0f64, 0.0..1.0f64), any::<bool>(), 0usize..12),
                3..=7,
            ),
            0.01..0.3f64,
            any::<bool>(),
        )
            .prop_map(|(vertices, eps, closed)| {
                let last = vertices.len() - 1;
                let mut items = Vec::new();
                for (k, &((x, y), candidate, along)) in vertices.iter().enumerate() {
                    let p = V::new(x, y);
                    let end = !closed && (k == 0 || k == last);
                    items.push(Item {
                        p,
                        s: 0.0,
                        vertex: true,
                        candidate: candidate || end,
                    });
                    if k == last && !closed {
                        break;
                    }
                    let ((nx, ny), _, _) = vertices[(k + 1) % vertices.len()];
                    let q = V::new(nx, ny);
                    for j in 1..=along {
                        let f = j as f64 / (along + 1) as f64;
                        items.push(Item {
                            p: p + (q - p) * f,
                            s: 0.0,
                            vertex: false,
                            candidate: true,
                        });
                    }
                }
                (items, eps, closed)
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        /// With points along the sides (the sides along one segment implied, not listed),
        /// the shortest path is the fewest by brute force over every pair of candidates,
        /// and each of its sides passes the brute-force test.
        #[test]
        fn sides_along_the_segments_match_every_pair((items, eps, closed) in outline_with_points_along()) {
            let n = items.iter().filter(|i| i.candidate).count();
            prop_assume!(n >= 3);
            let min_points = if closed { 3 } else { 2 };
            let found = fewest_over(&items, eps, closed, min_points).unwrap();
            let brute = items_brute_force(&items, eps, closed, min_points);
            prop_assert_eq!(found.as_ref().map(Vec::len), brute);
            if let Some(path) = found {
                let at: Vec<usize> = (0..items.len()).filter(|&k| items[k].candidate).collect();
                let sides = if closed { path.len() } else { path.len() - 1 };
                for i in 0..sides {
                    let (a, b) = (at[path[i]], at[path[(i + 1) % path.len()]]);
                    prop_assert!(items_side_ok(&items, a, b, eps), "side {} → {}", a, b);
                }
            }
        }

        /// The shortest path over the cones' shortcuts is the fewest of every subset, and
        /// every side it takes passes the brute-force test.
        #[test]
        fn optimum_is_every_subsets_fewest((p, eps, closed) in outline()) {
            let c: Vec<Item> = p
                .iter()
                .map(|&p| Item { p, s: 0.0, vertex: true, candidate: true })
                .collect();
            let path = fewest_over(&c, eps, closed, 3).unwrap().unwrap();
            prop_assert_eq!(path.len(), brute_force(&p, eps, closed));
            let sides = if closed { path.len() } else { path.len() - 1 };
            for i in 0..sides {
                let (a, b) = (path[i], path[(i + 1) % path.len()]);
                prop_assert!(side_ok(&p, a, b, eps), "side {} → {}", a, b);
            }
            if !closed {
                prop_assert_eq!(path[0], 0);
                prop_assert_eq!(path[path.len() - 1], p.len() - 1);
            }
        }

        /// Points along the sides can only lower the count, and the answer meets the
        /// tolerance by the table's measure.
        #[test]
        fn candidates_along_the_sides_never_cost((p, eps, closed) in outline()) {
            let size = 1.0;
            let Ok(target) = Target::polyline(&p, closed, eps * size) else {
                return Ok(());
            };
            let found = fewest_within(&target, target.tolerance(), 3, true).unwrap();
            prop_assert!(found.choice.within_tolerance);
            let vertices = brute_force(&p, eps, closed);
            prop_assert!(found.choice.points.len() <= vertices);
        }
    }

    /// The exact optimum is never above the multistart search of the placed points.
    #[test]
    fn never_above_the_placed_search() {
        let mut rng = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            (rng >> 11) as f64 / (1u64 << 53) as f64
        };
        let options = SearchOptions {
            max_points: 24,
            budget_per_coordinate: 10,
            every_count_below: false,
            ..SearchOptions::default()
        };
        for case in 0..24 {
            let closed = case % 2 == 0;
            // a wobbly ring or arc of 40 vertices
            let p: Vec<V> = (0..40)
                .map(|k| {
                    let t = k as f64 / 40.0 * if closed { std::f64::consts::TAU } else { 3.0 };
                    let r = 1.0 + 0.3 * next();
                    V::new(r * t.cos(), r * t.sin())
                })
                .collect();
            let target = Target::polyline(&p, closed, 0.05).unwrap();
            let exact = search(&target, &options).unwrap();
            let placed =
                super::super::count::placed(&target, super::super::Family::Linear, &options)
                    .unwrap();
            assert!(
                exact.choice.within_tolerance || !placed.choice.within_tolerance,
                "case {case}"
            );
            if placed.choice.within_tolerance {
                assert!(
                    exact.choice.measure.counted <= placed.choice.measure.counted,
                    "case {case}: {} against {}",
                    exact.choice.measure.counted,
                    placed.choice.measure.counted
                );
            }
        }
    }
}
