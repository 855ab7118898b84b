//! The polygon's fewest points, exactly (module docs of [`super`], **Polygon**): the shortest
//! path over the graph of shortcuts that stay within the tolerance (Imai & Iri, "Polygonal
//! approximations of a curve — formulations and algorithms", 1988), every shortcut from one
//! point tested in one sweep by the cones of Chan & Chin ("On approximation of polygonal
//! curves with minimum number of line segments or minimum error", 1996).
//!
//! **Candidates.** The points may sit at the reference's vertices and at equal steps along
//! each of its segments, at most `h` apart along the outline, `h` = [`RESOLUTION`] × 2 × the
//! tolerance. It is coarser only when the points along the segments would exceed
//! [`ALONG_PER_SEGMENT`] per segment and [`MIN_ALONG`] in all (a tolerance far below the
//! outline's size), or the work its limits ([`MAX_CANDIDATES`], [`MAX_SHORTCUTS`],
//! [`MAX_CYCLE_WORK`]); the answer's bound states the `h` it used. An open outline's polygon
//! starts and ends at the outline's ends, as every placement of the search.
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
use nalgebra::Vector2;

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

/// The most (candidate, point) pairs the forward sweeps visit: beyond, the spacing is doubled until
/// they fit (the shortcuts' memory is four bytes each).
pub const MAX_SHORTCUTS: usize = 1 << 25;

/// The most work of the closed shortest path: passes of 256 starts times the sides and
/// candidates each pass visits (beyond, the spacing is doubled).
pub const MAX_CYCLE_WORK: usize = 1 << 26;

/// A distance that no path reaches (paths have fewer than [`MAX_CANDIDATES`] sides).
const UNREACHED: u32 = u32::MAX / 2;

/// Starts computed together in the closed shortest path (one lane each).
const LANES: usize = 256;

type V = Vector2<f64>;

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
        return Ok(Search {
            attempts: vec![attempt_of(&found.choice)],
            choice: found.choice,
            minimality: Minimality::Optimum { bound },
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
#[derive(Debug, Clone, Copy)]
struct Item {
    p: V,
    /// Its arc position.
    s: f64,
    vertex: bool,
    candidate: bool,
}

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

fn cross(a: V, b: V) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The directions from a point whose rays pass within the tolerance of every vertex swept
/// (module docs, **Cones**): all of them until a vertex lies farther than the tolerance,
/// then the arc counter-clockwise from `lo` and clockwise from `hi` (narrower than π, unit
/// vectors), or none.
#[derive(Debug, Clone, Copy)]
struct Cone {
    lo: V,
    hi: V,
    full: bool,
    empty: bool,
}

/// Whether `d` lies in the arc from `lo` counter-clockwise to `hi` (narrower than π).
fn in_arc(lo: V, hi: V, d: V) -> bool {
    cross(lo, d) >= 0.0 && cross(d, hi) >= 0.0
}

impl Cone {
    const FULL: Cone = Cone {
        lo: V::new(1.0, 0.0),
        hi: V::new(1.0, 0.0),
        full: true,
        empty: false,
    };

    /// One point passed by a sweep, at `d` from the apex: whether the ray towards it is in
    /// the cone (a side of zero length, `d = 0`, only while the cone is full: an outline
    /// through the same point twice), the cone then narrowed by it if it is a vertex (to the
    /// rays within `eps` of it: the directions within `asin(eps/|d|)` of `d`).
    #[inline(always)]
    fn pass(&mut self, d: V, vertex: bool, eps: f64) -> bool {
        if self.full {
            if vertex {
                self.narrow(d, eps);
            }
            return true;
        }
        let (c1, c2) = (cross(self.lo, d), cross(d, self.hi));
        let inside = c1 >= 0.0 && c2 >= 0.0 && d != V::zeros();
        // the rays along both edges pass within eps of d: so does every ray between (both
        // arcs narrower than π), and the cone stays as it is
        let kept =
            c1.abs() <= eps && c2.abs() <= eps && self.lo.dot(&d) >= 0.0 && self.hi.dot(&d) >= 0.0;
        if vertex && !kept {
            self.narrow(d, eps);
        }
        inside
    }

    /// The points `d(0), …, d(run − 1)` (from the apex, in order along a straight line) that
    /// lie in the cone, as an interval of their indices: the cone is the intersection of two
    /// half-planes through the apex, and each holds a prefix or a suffix of points along a
    /// line, found by bisection (a point at the apex, where both hold, is the caller's to
    /// leave out: it is in the cone only while the cone is full).
    fn interval(&self, run: usize, d: impl Fn(usize) -> V) -> (usize, usize) {
        if self.full {
            return (0, run);
        }
        if self.empty || run == 0 {
            return (0, 0);
        }
        let (lo1, hi1) = half_interval(run, |x| cross(self.lo, d(x)) >= 0.0);
        let (lo2, hi2) = half_interval(run, |x| cross(d(x), self.hi) >= 0.0);
        let lo = lo1.max(lo2);
        (lo, hi1.min(hi2).max(lo))
    }

    /// The cone narrowed to the rays that pass within `eps` of `w` (module docs).
    fn narrow(&mut self, w: V, eps: f64) {
        let r = (w.x * w.x + w.y * w.y).sqrt();
        if r.is_nan() || r <= eps {
            return;
        }
        let u = w / r;
        let s = eps / r;
        let c = ((1.0 - s) * (1.0 + s)).sqrt();
        let lo = V::new(u.x * c + u.y * s, u.y * c - u.x * s);
        let hi = V::new(u.x * c - u.y * s, u.y * c + u.x * s);
        if self.full {
            *self = Cone {
                lo,
                hi,
                full: false,
                empty: false,
            };
            return;
        }
        // two arcs narrower than π meet in one arc, which starts at the start of one of them
        // lying in the other, and ends likewise
        let (a, b) = (self.lo, self.hi);
        let start = if in_arc(a, b, lo) {
            Some(lo)
        } else {
            in_arc(lo, hi, a).then_some(a)
        };
        let end = if in_arc(a, b, hi) {
            Some(hi)
        } else {
            in_arc(lo, hi, b).then_some(b)
        };
        match (start, end) {
            (Some(lo), Some(hi)) => {
                self.lo = lo;
                self.hi = hi;
            }
            _ => self.empty = true,
        }
    }
}

/// The indices `0..run` where `f` holds, given that it holds on a prefix or a suffix (a
/// half-plane along a line): its ends, then a bisection for the change.
fn half_interval(run: usize, f: impl Fn(usize) -> bool) -> (usize, usize) {
    match (f(0), f(run - 1)) {
        (true, true) => (0, run),
        (false, false) => (0, 0),
        (head, _) => {
            // f(lo) == head != f(hi)
            let (mut lo, mut hi) = (0, run - 1);
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                if f(mid) == head {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            if head {
                (0, hi)
            } else {
                (hi, run)
            }
        }
    }
}

/// A count of sides in the closed shortest path's lanes: bytes while paths are short.
trait Lane: Copy + Ord {
    /// No path (or one as long).
    const FAR: Self;
    const ZERO: Self;
    /// One side more (saturating at [`Lane::FAR`]).
    fn next(self) -> Self;
    fn wide(self) -> u32;
}

impl Lane for u8 {
    const FAR: u8 = u8::MAX;
    const ZERO: u8 = 0;
    fn next(self) -> u8 {
        self.saturating_add(1)
    }
    fn wide(self) -> u32 {
        u32::from(self)
    }
}

impl Lane for u32 {
    const FAR: u32 = UNREACHED;
    const ZERO: u32 = 0;
    fn next(self) -> u32 {
        (self + 1).min(UNREACHED)
    }
    fn wide(self) -> u32 {
        self
    }
}

/// The allowed shortcuts (module docs): for each candidate, the offsets back to the
/// candidates with a side to it.
struct Shortcuts {
    n: usize,
    closed: bool,
    /// `preds[first[v]..first[v + 1]]`: offsets `d` of the sides `(v − d) → v`, increasing,
    /// except the sides along one reference segment ([`Along`]).
    first: Vec<usize>,
    preds: Vec<u32>,
    /// How each candidate joins the candidates before it on its reference segment.
    along: Vec<Along>,
    /// The largest forward offset of a side from each candidate.
    reach: Vec<u32>,
}

/// The sides between two candidates of one reference segment (its end vertices included)
/// are all allowed — the outline between them is that straight stretch — and are not
/// listed: each path scan carries the least distance over the segment so far (quadratic
/// lists on long straight sides otherwise).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Along {
    /// No candidate before it on its segment: no side along one.
    None,
    /// Sides from every candidate since the segment's first (a run that goes on).
    Run,
    /// Sides from every candidate since the segment's first, which it ends: a reference
    /// vertex, where the next run starts.
    End,
}

impl Along {
    /// The least over the run after this candidate: the run goes on, or starts here.
    #[inline(always)]
    fn carry<L: Lane>(self, run: L, here: L) -> L {
        match self {
            Along::Run => run.min(here),
            Along::None | Along::End => here,
        }
    }

    /// The distance the run gives this candidate (one side more than the run's least).
    #[inline(always)]
    fn reached<L: Lane>(self, run: L) -> L {
        match self {
            Along::None => L::FAR,
            Along::Run | Along::End => run.next(),
        }
    }
}

/// The outline as the cone sweeps read it: the items in units that bring the coordinates
/// within `[−1, 1]`, the candidates' positions, and per item the steps to the reference
/// vertices around it.
struct Sweeps<'a> {
    items: &'a [Item],
    /// The items' points, scaled.
    p: Vec<V>,
    /// The tolerance, scaled.
    eps: f64,
    closed: bool,
    /// The candidates' positions among the items.
    at: Vec<usize>,
    /// Candidates among the items before each position, unrolled once for closed outlines.
    cum: Vec<usize>,
    /// Steps from each item to the next reference vertex after it (`usize::MAX`: none; an
    /// open outline's end).
    next: Vec<usize>,
    /// Steps from each item back to the reference vertex before it (`usize::MAX`: none).
    prev: Vec<usize>,
}

/// The forward sweeps: the sides along the first segment implied (an offset `t0`), then bit
/// `t − t0 − 1` of row `i` says candidate `i + t` is reachable forward.
struct Forward {
    bits: Vec<u64>,
    /// Per candidate: its first word, `t0` and the last offset swept.
    rows: Vec<(usize, usize, usize)>,
    /// The largest forward offset of a side from each candidate.
    reach: Vec<u32>,
}

impl Forward {
    /// Whether candidate `i + t` is reachable forward from candidate `i`.
    fn has(&self, i: usize, t: usize) -> bool {
        let (start, t0, len) = self.rows[i];
        t > t0 && t <= len && self.bits[start + (t - t0 - 1) / 64] >> ((t - t0 - 1) % 64) & 1 == 1
    }
}

impl<'a> Sweeps<'a> {
    fn of(items: &'a [Item], eps: f64, closed: bool) -> Sweeps<'a> {
        // a power of two: exact, and no square overflows
        let largest = items.iter().map(|i| i.p.amax()).fold(0.0, f64::max);
        let unit = if largest > 0.0 {
            2f64.powi(-(largest.log2().ceil() as i32).clamp(-1000, 1000))
        } else {
            1.0
        };
        let m = items.len();
        let wrap = |k: usize| if k >= m { k - m } else { k };
        let mut cum = vec![0usize; 2 * m + 1];
        for x in 0..2 * m {
            cum[x + 1] = cum[x] + usize::from(items[wrap(x)].candidate);
        }
        let mut next = vec![usize::MAX; m];
        let mut prev = vec![usize::MAX; m];
        let mut seen = None;
        for x in (0..if closed { 2 * m } else { m }).rev() {
            if x < m {
                next[x] = seen.map_or(usize::MAX, |y: usize| y - x);
            }
            if items[wrap(x)].vertex {
                seen = Some(x);
            }
        }
        seen = None;
        for x in 0..if closed { 2 * m } else { m } {
            if x >= m || !closed {
                let k = wrap(x);
                prev[k] = seen.map_or(usize::MAX, |y: usize| x - y);
            }
            if items[wrap(x)].vertex {
                seen = Some(x);
            }
        }
        Sweeps {
            items,
            p: items.iter().map(|i| i.p * unit).collect(),
            eps: eps * unit,
            closed,
            at: (0..m).filter(|&k| items[k].candidate).collect(),
            cum,
            next,
            prev,
        }
    }

    fn wrap(&self, k: usize) -> usize {
        let m = self.items.len();
        if k >= m {
            k - m
        } else {
            k
        }
    }

    /// Every candidate's forward sweep; `None` beyond [`MAX_SHORTCUTS`] points visited.
    fn forward(&self) -> Option<Forward> {
        let (items, p, eps) = (self.items, &self.p, self.eps);
        let (n, m) = (self.at.len(), items.len());
        let mut bits: Vec<u64> = Vec::new();
        let mut rows: Vec<(usize, usize, usize)> = Vec::with_capacity(n);
        let mut reach = vec![0u32; n];
        let mut visited = 0usize;
        for (i, &a) in self.at.iter().enumerate() {
            let start = bits.len();
            let steps = if self.closed { m - 1 } else { m - 1 - a };
            let mut cone = Cone::FULL;
            // along the segment to its end vertex: no vertex between, every side allowed
            let jump = self.next[a].min(steps);
            let t0 = self.cum[a + jump + 1] - self.cum[a + 1];
            reach[i] = t0 as u32;
            if jump >= 1 {
                let e = self.wrap(a + jump);
                cone.pass(p[e] - p[a], items[e].vertex, eps);
            }
            let mut t = t0;
            let mut step = jump + 1;
            while step <= steps && !cone.empty {
                let k = self.wrap(a + step);
                // a vertex narrows the cone; the points along the segment after it do not,
                // and those in the cone are one interval of them
                let (run, (lo, hi)) = if items[k].vertex {
                    let inside = cone.pass(p[k] - p[a], true, eps);
                    (1, (0, usize::from(inside)))
                } else {
                    let run = self.next[k].min(steps + 1 - step);
                    (
                        run,
                        cone.interval(run, |x| p[self.wrap(a + step + x)] - p[a]),
                    )
                };
                let (first, last) = (t - t0, t - t0 + usize::from(items[k].candidate) * run);
                bits.resize(start + last.div_ceil(64), 0);
                for bit in first + lo..(first + hi).min(last) {
                    // a side of zero length only while the cone is full (as `Cone::pass`)
                    if cone.full || p[self.wrap(a + step + bit - first)] != p[a] {
                        bits[start + bit / 64] |= 1 << (bit % 64);
                    }
                }
                t += last - first;
                step += run;
                visited = visited.saturating_add(1 + hi - lo);
            }
            if visited > MAX_SHORTCUTS {
                return None;
            }
            rows.push((start, t0, t));
        }
        Some(Forward { bits, rows, reach })
    }

    /// Every candidate's backward sweep, each side kept when the forward sweep reaches it too
    /// (past the segment's sides): the offsets of the sides into each candidate, listed by
    /// `first`, and how each joins its segment ([`Along`]); `forward.reach` raised to the
    /// sides kept.
    fn backward(&self, forward: &mut Forward) -> (Vec<usize>, Vec<u32>, Vec<Along>) {
        let (items, p, eps) = (self.items, &self.p, self.eps);
        let (n, m) = (self.at.len(), items.len());
        let mut first = Vec::with_capacity(n + 1);
        let mut preds: Vec<u32> = Vec::new();
        let mut along = Vec::with_capacity(n);
        for (j, &b) in self.at.iter().enumerate() {
            first.push(preds.len());
            let steps = if self.closed { m - 1 } else { b };
            let jump = self.prev[b].min(steps);
            let unrolled = b + m;
            let t0 = self.cum[unrolled] - self.cum[unrolled - jump];
            along.push(match (t0, items[b].vertex) {
                (0, _) => Along::None,
                (_, true) => Along::End,
                (_, false) => Along::Run,
            });
            let mut cone = Cone::FULL;
            if jump >= 1 {
                let e = self.wrap(unrolled - jump);
                cone.pass(p[e] - p[b], items[e].vertex, eps);
            }
            let mut t = t0;
            let mut step = jump + 1;
            while step <= steps && !cone.empty {
                let k = self.wrap(unrolled - step);
                let (run, (lo, hi)) = if items[k].vertex {
                    let inside = cone.pass(p[k] - p[b], true, eps);
                    (1, (0, usize::from(inside)))
                } else {
                    let run = self.prev[k].min(steps + 1 - step);
                    (
                        run,
                        cone.interval(run, |x| p[self.wrap(unrolled - step - x)] - p[b]),
                    )
                };
                if items[k].candidate {
                    for x in lo..hi {
                        let t = t + x + 1;
                        let i = if j >= t { j - t } else { j + n - t };
                        let moved = cone.full || p[self.wrap(unrolled - step - x)] != p[b];
                        if moved && forward.has(i, t) {
                            preds.push(t as u32);
                            forward.reach[i] = forward.reach[i].max(t as u32);
                        }
                    }
                    t += run;
                }
                step += run;
            }
        }
        first.push(preds.len());
        (first, preds, along)
    }
}

impl Shortcuts {
    /// The shortcuts among the candidates of `items` within `eps`; `None` if the forward
    /// sweeps visit more than [`MAX_SHORTCUTS`] points.
    fn new(items: &[Item], eps: f64, closed: bool) -> Option<Shortcuts> {
        let outline = Sweeps::of(items, eps, closed);
        let mut forward = outline.forward()?;
        let (first, preds, along) = outline.backward(&mut forward);
        Some(Shortcuts {
            n: outline.at.len(),
            closed,
            first,
            preds,
            along,
            reach: forward.reach,
        })
    }

    fn preds(&self, v: usize) -> &[u32] {
        &self.preds[self.first[v]..self.first[v + 1]]
    }

    /// Open: the candidates of the fewest sides from the first to the last, at least
    /// `min_points` of them.
    fn shortest_path(&self, min_points: usize) -> Option<Vec<usize>> {
        let n = self.n;
        let mut dist = vec![UNREACHED; n];
        let mut parent = vec![usize::MAX; n];
        dist[0] = 0;
        // the least distance along the current segment and where
        let mut run = (0, 0);
        for v in 1..n {
            if self.along[v] != Along::None && run.0 + 1 < dist[v] {
                dist[v] = run.0 + 1;
                parent[v] = run.1;
            }
            for &d in self.preds(v) {
                let u = v - d as usize;
                if dist[u] + 1 < dist[v] {
                    dist[v] = dist[u] + 1;
                    parent[v] = u;
                }
            }
            if self.along[v] != Along::Run || dist[v] < run.0 {
                run = (dist[v], v);
            }
        }
        if dist[n - 1] >= UNREACHED {
            return None;
        }
        if (dist[n - 1] as usize) + 1 < min_points {
            return self.at_least(0, n - 1, min_points - 1);
        }
        let mut path = vec![n - 1];
        while let Some(&v) = path.last().filter(|&&v| v != 0) {
            path.push(parent[v]);
        }
        path.reverse();
        Some(path)
    }

    /// Closed: the candidates of the shortest closed path, at least `min_points` of them
    /// (module docs); `None` beyond [`MAX_CYCLE_WORK`], `Some(None)` if there is none.
    fn shortest_cycle(&self, min_points: usize) -> Option<Option<Vec<usize>>> {
        let n = self.n;
        // the candidate k passed by the fewest sides: cover[k] counts the starts a with a
        // side from a beyond k (a difference array over the cyclic positions)
        let mut diff = vec![0i64; n + 1];
        for a in 0..n {
            let r = self.reach[a] as usize;
            if r >= 2 {
                // k = a + 1 ..= a + r − 1, wrapped
                let (s, e) = (a + 1, a + r);
                if s >= n {
                    diff[s - n] += 1;
                    diff[e - n] -= 1;
                } else if e <= n {
                    diff[s] += 1;
                    diff[e] -= 1;
                } else {
                    diff[s] += 1;
                    diff[n] -= 1;
                    diff[0] += 1;
                    diff[e - n] -= 1;
                }
            }
        }
        let mut k = 0;
        let mut best = i64::MAX;
        let mut acc = 0;
        for (i, d) in diff.iter().take(n).enumerate() {
            acc += d;
            if acc < best {
                best = acc;
                k = i;
            }
        }
        // the starts, as offsets back from k (0: k itself)
        let mut back: Vec<usize> = (0..n)
            .filter_map(|a| {
                let off = (k + n - a) % n;
                (off == 0 || off < self.reach[a] as usize).then_some(off)
            })
            .collect();
        back.sort_unstable_by(|x, y| y.cmp(x));
        let passes = back.len().div_ceil(LANES);
        if passes.saturating_mul(self.preds.len() + self.n) > MAX_CYCLE_WORK {
            return None;
        }
        Some(self.cycle_from_starts(k, &back, min_points))
    }

    /// The shortest closed path over the starts `back` (offsets back from `k`, decreasing).
    fn cycle_from_starts(&self, k: usize, back: &[usize], min_points: usize) -> Option<Vec<usize>> {
        let n = self.n;
        // bytes first (as many lanes to an instruction as fit), wider if a path is as long
        let mut answer = self.least_cycle::<u8>(k, back);
        if answer.is_none_or(|(l, _)| l >= u8::FAR.wide()) {
            answer = self.least_cycle::<u32>(k, back);
        }
        let (length, off) = answer?;
        if (length as usize) < min_points {
            // fewer sides than a polygon needs (a thin outline): the fewest of at least
            // `min_points` from every start
            let mut path = back
                .iter()
                .filter_map(|&off| {
                    let start = (k + n - off) % n;
                    self.at_least(start, start + n, min_points)
                })
                .min_by_key(|p| p.len())?;
            path.pop();
            return Some(path);
        }
        self.path_from((k + n - off) % n)
    }

    /// The least of [`Shortcuts::cycles`] over the starts `back` and its start's offset.
    fn least_cycle<L: Lane>(&self, k: usize, back: &[usize]) -> Option<(u32, usize)> {
        let mut answer: Option<(u32, usize)> = None;
        for chunk in back.chunks(LANES) {
            for (lane, length) in self.cycles::<L>(k, chunk).into_iter().enumerate() {
                let length = length.wide();
                if length < UNREACHED && answer.is_none_or(|(l, _)| length < l) {
                    answer = Some((length, chunk[lane]));
                }
            }
        }
        answer
    }

    /// The fewest sides of a closed path from each start (`k` less each offset of `back`,
    /// decreasing) back to itself, all in one pass over the positions unrolled from the
    /// first start to the last start plus `n` ([`Lane::FAR`] for none, or as many as that).
    fn cycles<L: Lane>(&self, k: usize, back: &[usize]) -> Vec<L> {
        let n = self.n;
        let lanes = back.len();
        // rows in a ring of a power of two positions, a distance per lane
        let window =
            (self.preds.iter().copied().max().unwrap_or(1) as usize + 1).next_power_of_two();
        let first = k as i64 - back[0] as i64;
        let last = k as i64 + n as i64 - *back.last().unwrap_or(&0) as i64;
        let mut rows = vec![L::FAR; window * lanes];
        let mut out = vec![L::FAR; lanes];
        let slot = |p: i64| ((p - first) as usize & (window - 1)) * lanes;
        let mut row = vec![L::FAR; lanes];
        // the least distance along the current segment, per lane
        let mut run = vec![L::FAR; lanes];
        for p in first..=last {
            let v = p.rem_euclid(n as i64) as usize;
            let along = self.along[v];
            for (r, &s) in row.iter_mut().zip(&run) {
                *r = along.reached(s);
            }
            for &d in self.preds(v) {
                let q = p - d as i64;
                if q < first {
                    continue;
                }
                let src = &rows[slot(q)..slot(q) + lanes];
                for (r, &s) in row.iter_mut().zip(src) {
                    *r = (*r).min(s.next());
                }
            }
            for (lane, &off) in back.iter().enumerate() {
                let start = k as i64 - off as i64;
                if p == start {
                    row[lane] = L::ZERO;
                } else if p == start + n as i64 {
                    out[lane] = row[lane];
                }
            }
            for (r, &h) in run.iter_mut().zip(&row) {
                *r = along.carry(*r, h);
            }
            let at = slot(p);
            rows[at..at + lanes].copy_from_slice(&row);
        }
        out
    }

    /// The shortest closed path from `start` (its candidates, `start` once).
    fn path_from(&self, start: usize) -> Option<Vec<usize>> {
        let n = self.n;
        let mut dist = vec![UNREACHED; n + 1];
        let mut parent = vec![usize::MAX; n + 1];
        dist[0] = 0;
        let mut run = (0, 0);
        for p in 1..=n {
            let v = (start + p) % n;
            let along = self.along[v];
            if along != Along::None && run.0 + 1 < dist[p] {
                dist[p] = run.0 + 1;
                parent[p] = run.1;
            }
            for &d in self.preds(v) {
                let Some(q) = p.checked_sub(d as usize) else {
                    continue;
                };
                if dist[q] + 1 < dist[p] {
                    dist[p] = dist[q] + 1;
                    parent[p] = q;
                }
            }
            if along != Along::Run || dist[p] < run.0 {
                run = (dist[p], p);
            }
        }
        if dist[n] >= UNREACHED {
            return None;
        }
        let mut path = Vec::new();
        let mut p = parent[n];
        while p != 0 {
            path.push((start + p) % n);
            p = parent[p];
        }
        path.push(start);
        path.reverse();
        Some(path)
    }

    /// The fewest sides, at least `min_sides`, from unrolled position `from` to `to`
    /// (breadth-first, layer by layer): the candidates of the path, both ends included.
    fn at_least(&self, from: usize, to: usize, min_sides: usize) -> Option<Vec<usize>> {
        let span = to - from;
        let mut layers: Vec<Vec<u32>> = Vec::new();
        let mut current = vec![u32::MAX; span + 1];
        current[0] = 0;
        for _ in 0..span {
            let mut next = vec![u32::MAX; span + 1];
            // a position of the current segment in the current layer
            let mut run = (current[0] != u32::MAX).then_some(0);
            for (p, parent) in next.iter_mut().enumerate().skip(1) {
                let v = (from + p) % self.n;
                let along = self.along[v];
                let reached = self
                    .preds(v)
                    .iter()
                    .filter_map(|&d| p.checked_sub(d as usize))
                    .find(|&q| current[q] != u32::MAX)
                    .or(run.filter(|_| along != Along::None));
                if let Some(q) = reached {
                    *parent = q as u32;
                }
                let here = (current[p] != u32::MAX).then_some(p);
                run = match along {
                    Along::Run => run.or(here),
                    Along::None | Along::End => here,
                };
            }
            layers.push(std::mem::replace(&mut current, next));
            if current[span] != u32::MAX && layers.len() >= min_sides {
                let mut path = vec![span];
                let mut p = span;
                for layer in (1..=layers.len()).rev() {
                    let q = if layer == layers.len() {
                        current[p]
                    } else {
                        layers[layer][p]
                    } as usize;
                    path.push(q);
                    p = q;
                }
                path.reverse();
                let wrap = |p: usize| {
                    if self.closed {
                        (from + p) % self.n
                    } else {
                        from + p
                    }
                };
                return Some(path.into_iter().map(wrap).collect());
            }
            if current.iter().all(|&q| q == u32::MAX) {
                return None;
            }
        }
        None
    }
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
