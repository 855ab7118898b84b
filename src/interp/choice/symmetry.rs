//! The mirror symmetries of a target, behind the symmetric placements of the search.
//!
//! **Closed targets.** A mirror axis meets a closed curve at two points half a turn apart,
//! `P(s₀)` and `P(s₀ + L/2)`, and maps `P(s₀ + δ)` to `P(s₀ − δ)` for every `δ`. Candidate
//! anchors `s₀` at `CANDIDATES` (256) equal steps are scored by the largest
//! `|R(P(s₀ + δ)) − P(s₀ − δ)|` over `PROBES` (24) values of `δ` (`R` the reflection across the
//! line through the two axis points), the local minima refined by golden section, and an
//! anchor kept when its score is at most `SYMMETRIC` (10⁻⁵) of the target's size; at most
//! `MAX_AXES` (2) axes, the best first (a circle has them all).
//!
//! **Open targets.** The map is `s ↦ L − s` (the ends swap), the isometry either the
//! reflection across the perpendicular bisector of the ends (the parabola, the hyperbola) or
//! the half-turn about their midpoint (the sinusoid).

use nalgebra::Vector2;

/// What the symmetry search reads of a shape ([`super::Target`] is one): its arc length, its
/// size (the larger bounding-box side), whether it is closed, and its point at an arc length
/// (taken modulo the length when closed).
pub trait ArcShape {
    /// The arc length `L`.
    fn length(&self) -> f64;
    /// The larger side of the bounding box.
    fn size(&self) -> f64;
    /// Whether the shape is a closed curve.
    fn is_closed(&self) -> bool;
    /// The point at arc length `s`.
    fn point(&self, s: f64) -> Vector2<f64>;
}

/// Candidate anchors of a closed target.
pub(crate) const CANDIDATES: usize = 256;

/// Values of `δ` probed per anchor.
pub(crate) const PROBES: usize = 24;

/// The largest score (a fraction of the target's size) of a symmetry kept: the sagitta of
/// a 2048-segment reference is far below it, a visible asymmetry far above.
pub(crate) const SYMMETRIC: f64 = 1e-5;

/// The most axes kept per closed target.
pub(crate) const MAX_AXES: usize = 2;

/// A plane isometry of order two.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Isometry {
    /// The reflection across the line through `point` along the unit `direction`.
    Reflection {
        /// A point of the axis.
        point: Vector2<f64>,
        /// Its unit direction.
        direction: Vector2<f64>,
    },
    /// The half-turn about `centre`.
    HalfTurn {
        /// The fixed point.
        centre: Vector2<f64>,
    },
}

impl Isometry {
    /// The image of `p`.
    pub fn apply(&self, p: Vector2<f64>) -> Vector2<f64> {
        match *self {
            Isometry::Reflection { point, direction } => {
                let d = p - point;
                point + direction * (2.0 * d.dot(&direction)) - d
            }
            Isometry::HalfTurn { centre } => centre * 2.0 - p,
        }
    }

    /// The reflection across the line through `a` and `b`, `None` if they coincide.
    fn through(a: Vector2<f64>, b: Vector2<f64>) -> Option<Isometry> {
        let d = b - a;
        let n = d.x.hypot(d.y);
        (n > 0.0 && n.is_finite()).then(|| Isometry::Reflection {
            point: a,
            direction: d / n,
        })
    }
}

/// A mirror symmetry of a target: on a closed one the anchor `s₀` where the axis meets it
/// (the other meeting is at `s₀ + L/2`); on an open one the anchor is 0 and the map of arcs
/// `s ↦ L − s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mirror {
    /// The arc of an axis point (closed), 0 (open).
    pub anchor: f64,
    /// The isometry.
    pub isometry: Isometry,
}

/// The largest displacement, as a fraction of the size, of the mirror image of the
/// target's points from the points it should map to.
fn score<S: ArcShape + ?Sized>(target: &S, mirror: &Mirror) -> f64 {
    let len = target.length();
    let size = target.size();
    let mut worst: f64 = 0.0;
    for j in 0..PROBES {
        let u = (j as f64 + 0.5) / PROBES as f64;
        let (from, to) = if target.is_closed() {
            let d = 0.5 * len * u;
            (mirror.anchor + d, mirror.anchor - d)
        } else {
            let s = 0.5 * len * u;
            (s, len - s)
        };
        let e = mirror.isometry.apply(target.point(from)) - target.point(to);
        let e = e.x.hypot(e.y) / size;
        worst = worst.max(if e.is_nan() { f64::INFINITY } else { e });
    }
    worst
}

/// The closed target's mirror anchored at `s0`, if the axis points differ.
fn closed_mirror<S: ArcShape + ?Sized>(target: &S, s0: f64) -> Option<Mirror> {
    let len = target.length();
    let isometry = Isometry::through(target.point(s0), target.point(s0 + 0.5 * len))?;
    Some(Mirror {
        anchor: s0.rem_euclid(len),
        isometry,
    })
}

/// The mirror symmetries of `target` (module docs), best first.
pub fn mirrors<S: ArcShape + ?Sized>(target: &S) -> Vec<Mirror> {
    let len = target.length();
    if !(len.is_finite() && target.size() > 0.0 && target.size().is_finite()) {
        return Vec::new();
    }
    if !target.is_closed() {
        let (a, b) = (target.point(0.0), target.point(len));
        let mid = (a + b) * 0.5;
        let d = b - a;
        let candidates = [
            Isometry::through(mid, mid + Vector2::new(-d.y, d.x)),
            Some(Isometry::HalfTurn { centre: mid }),
        ];
        return candidates
            .into_iter()
            .flatten()
            .map(|isometry| Mirror {
                anchor: 0.0,
                isometry,
            })
            .filter(|m| score(target, m) <= SYMMETRIC)
            .take(1)
            .collect();
    }
    let step = len / CANDIDATES as f64;
    let at = |s: f64| closed_mirror(target, s).map_or(f64::INFINITY, |m| score(target, &m));
    let scores: Vec<f64> = (0..CANDIDATES).map(|k| at(k as f64 * step)).collect();
    let mut found: Vec<(f64, Mirror)> = Vec::new();
    for k in 0..CANDIDATES {
        let (prev, next) = (
            scores[(k + CANDIDATES - 1) % CANDIDATES],
            scores[(k + 1) % CANDIDATES],
        );
        if !(scores[k] <= prev && scores[k] <= next && scores[k] < 0.05) {
            continue;
        }
        // golden section on [s − step, s + step] (not needed where the candidate is exact)
        let (mut lo, mut hi) = ((k as f64 - 1.0) * step, (k as f64 + 1.0) * step);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let rounds = if scores[k] <= SYMMETRIC { 0 } else { 40 };
        if rounds == 0 {
            (lo, hi) = (k as f64 * step, k as f64 * step);
        }
        for _ in 0..rounds {
            let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if at(x1) <= at(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        let s0 = 0.5 * (lo + hi);
        let Some(m) = closed_mirror(target, s0) else {
            continue;
        };
        let e = score(target, &m);
        if e > SYMMETRIC {
            continue;
        }
        // the same axis: the same anchor or the other meeting point, half a turn on
        let same = |other: &Mirror| {
            let d = (other.anchor - m.anchor).rem_euclid(0.5 * len);
            d.min(0.5 * len - d) < 2.0 * step
        };
        if found.iter().any(|(_, o)| same(o)) {
            continue;
        }
        found.push((e, m));
    }
    found.sort_by(|a, b| a.0.total_cmp(&b.0));
    found.into_iter().take(MAX_AXES).map(|(_, m)| m).collect()
}
