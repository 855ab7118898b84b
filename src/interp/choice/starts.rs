//! The variables of one search and the starts it is begun from (module docs of
//! [`super`], steps 1 and 2).
//!
//! A [`Layout`] maps a vector of variables to the method's points: arc positions of the
//! points on the shape (an open target's ends fixed), the free guides of an open Angular or
//! cardinal curve (two plane points), the cardinal `a`. A symmetric layout has fewer
//! variables: mirror pairs of positions `s₀ ± δ` (closed) or `δ, L − δ` (open), points on the
//! axis where the count asks for them, and one guide whose mirror image is the other.

use super::symmetry::Mirror;
use super::target::{Target, Weight};
use super::{Family, Start};
use crate::interp::methods::{CubicEnd, Method};
use nalgebra::Vector2;

/// The cardinal `a` the search tries: a multiple of `A_STEP` (0.001) in `[A_STEP, 2]`, so the
/// chosen value prints as it is (`a = 1.3`, not `1.2999999999999998`).
pub(super) fn quantized_a(a: f64) -> f64 {
    let k = (a / A_STEP).round().clamp(1.0, 2.0 / A_STEP);
    // k · 0.001 as k / 1000: the nearest double to the decimal
    k / (1.0 / A_STEP).round()
}

/// The resolution of the cardinal `a` the search chooses.
pub(crate) const A_STEP: f64 = 0.001;

/// How far from its end a guide may be, in target lengths (a parabola's guides one
/// parameter step beyond the ends are 3.5 lengths away).
pub(crate) const GUIDE_REACH: f64 = 100.0;

/// A symmetric layout's shape: the mirror, and which axis points carry a point (closed:
/// `near` at the anchor, `far` half a turn on; open: `near` the middle of the arc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Symmetric {
    pub mirror: Mirror,
    pub near: bool,
    pub far: bool,
    /// Mirror pairs of positions.
    pub pairs: usize,
}

/// The variables of one search (module docs).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Layout {
    pub family: Family,
    pub closed: bool,
    /// Distinct points on the shape (the guides not included).
    pub on_shape: usize,
    pub end: CubicEnd,
    pub symmetric: Option<Symmetric>,
}

impl Layout {
    /// Position variables.
    pub fn positions(&self) -> usize {
        match (self.symmetric, self.closed) {
            (Some(s), _) => s.pairs,
            (None, true) => self.on_shape,
            (None, false) => self.on_shape - 2,
        }
    }

    /// Guide coordinates: two plane points, one for a symmetric layout (its image is the
    /// other).
    pub fn guide_coordinates(&self) -> usize {
        match (self.closed || !self.family.guided(), self.symmetric) {
            (true, _) => 0,
            (false, Some(_)) => 2,
            (false, None) => 4,
        }
    }

    pub fn method(&self, x: &[f64]) -> Method {
        match self.family {
            Family::Angular => Method::Angular,
            Family::Cardinal => Method::Cardinal {
                a: quantized_a(x[x.len() - 1]),
            },
            Family::Cubic => Method::Cubic { end: self.end },
            // B-splines are fitted, not placed (super::bspline); never reached
            Family::Linear | Family::BSpline => Method::Linear,
        }
    }

    /// The arc positions of the points on the shape, in order (a closed target's first in
    /// `[0, L)`), `None` if the variables put them out of order.
    pub fn arcs(&self, target: &Target, x: &[f64]) -> Option<Vec<f64>> {
        let len = target.length();
        let gap = 1e-6 * len;
        let inner = &x[..self.positions()];
        let mut s: Vec<f64> = Vec::with_capacity(self.on_shape);
        match (self.symmetric, self.closed) {
            (Some(sym), closed) => {
                let half = 0.5 * len;
                let ordered = inner.windows(2).all(|w| w[1] - w[0] > gap)
                    && inner.first().is_none_or(|&d| d > gap)
                    && inner.last().is_none_or(|&d| d < half - gap);
                if !ordered {
                    return None;
                }
                let s0 = if closed { sym.mirror.anchor } else { 0.0 };
                if closed && sym.near {
                    s.push(s0);
                }
                if !closed {
                    s.push(0.0);
                }
                s.extend(inner.iter().map(|d| s0 + d));
                if sym.far || (!closed && sym.near) {
                    s.push(s0 + half);
                }
                s.extend(inner.iter().rev().map(|d| s0 + len - d));
                if !closed {
                    s.push(len);
                }
            }
            (None, true) => s.extend_from_slice(inner),
            (None, false) => {
                s.push(0.0);
                s.extend_from_slice(inner);
                s.push(len);
            }
        }
        if s.len() != self.on_shape {
            return None;
        }
        let ordered = s.windows(2).all(|w| w[1] - w[0] > gap);
        let closes = !self.closed || s[s.len() - 1] - s[0] < len - gap;
        if !(ordered && closes) {
            return None;
        }
        if self.closed {
            let shift = s[0].rem_euclid(len) - s[0];
            s.iter_mut().for_each(|v| *v += shift);
        }
        Some(s)
    }

    /// The guides of an open guided layout, `None` if they are not finite, on their end, or
    /// farther from it than `GUIDE_REACH` (100) target lengths.
    fn guides(&self, target: &Target, x: &[f64]) -> Option<(Vector2<f64>, Vector2<f64>)> {
        let k = self.positions();
        let len = target.length();
        let first = Vector2::new(x[k], x[k + 1]);
        let last = match self.symmetric {
            Some(sym) => sym.mirror.isometry.apply(first),
            None => Vector2::new(x[k + 2], x[k + 3]),
        };
        let (a, b) = (target.point(0.0), target.point(len));
        let near = |g: Vector2<f64>, end: Vector2<f64>| {
            let d = g - end;
            let d = d.x.hypot(d.y);
            d > 1e-6 * len && d <= GUIDE_REACH * len
        };
        (near(first, a) && near(last, b)).then_some((first, last))
    }

    /// The method's points for the variables `x` (guides included), `None` if invalid.
    pub fn points(&self, target: &Target, x: &[f64]) -> Option<Vec<Vector2<f64>>> {
        let s = self.arcs(target, x)?;
        let mut points: Vec<Vector2<f64>> = s.iter().map(|&v| target.point(v)).collect();
        if self.guide_coordinates() > 0 {
            let (g0, g1) = self.guides(target, x)?;
            points.insert(0, g0);
            points.push(g1);
        }
        Some(points)
    }

    /// The variables of a plain layout for the positions `s` (all the points on the shape, in
    /// order), with the guides `guides` and the cardinal `a` appended.
    pub fn variables(&self, s: &[f64], guides: &[Vector2<f64>], a: f64) -> Vec<f64> {
        let mut x: Vec<f64> = if self.closed {
            s.to_vec()
        } else {
            s[1..s.len() - 1].to_vec()
        };
        self.append(&mut x, guides, a);
        x
    }

    fn append(&self, x: &mut Vec<f64>, guides: &[Vector2<f64>], a: f64) {
        let wanted = self.guide_coordinates() / 2;
        for g in guides.iter().take(wanted) {
            x.extend([g.x, g.y]);
        }
        if self.family == Family::Cardinal {
            x.push(a);
        }
    }
}

/// The layouts of `n` distinct points: plain, then symmetric for every mirror of the target
/// and every way of putting points on its axis; for the cubic one of each per end condition.
pub(super) fn layouts(target: &Target, family: Family, n: usize) -> Vec<Layout> {
    let guides = if !target.is_closed() && family.guided() {
        2
    } else {
        0
    };
    let on_shape = n.saturating_sub(guides);
    let closed = target.is_closed();
    if on_shape < 2 || (closed && on_shape < 3) {
        return Vec::new();
    }
    let ends: &[CubicEnd] = if family == Family::Cubic {
        &CubicEnd::ALL
    } else {
        &[CubicEnd::Relaxed]
    };
    let mut out = Vec::new();
    for &end in ends {
        let plain = Layout {
            family,
            closed,
            on_shape,
            end,
            symmetric: None,
        };
        out.push(plain.clone());
        for &mirror in target.mirrors() {
            let shapes: &[(bool, bool)] = if closed {
                &[(true, true), (false, false), (true, false), (false, true)]
            } else {
                &[(false, false), (true, false)]
            };
            for &(near, far) in shapes {
                let on_axis = if closed {
                    usize::from(near) + usize::from(far)
                } else {
                    2 + usize::from(near)
                };
                if on_shape < on_axis || (on_shape - on_axis) % 2 != 0 {
                    continue;
                }
                let pairs = (on_shape - on_axis) / 2;
                out.push(Layout {
                    symmetric: Some(Symmetric {
                        mirror,
                        near,
                        far,
                        pairs,
                    }),
                    ..plain.clone()
                });
            }
        }
    }
    out
}

/// The weights of the structured placements: arc length, turning, the shape's parameter.
fn weights(target: &Target) -> Vec<(Weight, Start)> {
    let mut w = vec![
        (Weight::Arc, Start::ArcLength),
        (Weight::Turning(0.5), Start::Turning),
        (Weight::Turning(0.75), Start::Turning),
    ];
    if target.has_own_parameter() {
        w.push((Weight::Parameter, Start::ShapeParameter));
    }
    w
}

/// The guide pairs tried with the positions `s` of an open target: on the shape half the end
/// gap beyond the ends, at one parameter step beyond (the exact shape continued), and the end
/// points' reflections of their neighbours (the chord continued).
fn guide_choices(target: &Target, s: &[f64]) -> Vec<[Vector2<f64>; 2]> {
    let n = s.len();
    let len = target.length();
    let (first, last) = (s[1] - s[0], s[n - 1] - s[n - 2]);
    let (a, b) = (target.point(0.0), target.point(len));
    let mut out = vec![
        [target.point(-0.5 * first), target.point(len + 0.5 * last)],
        [
            a * 2.0 - target.point(s[1]),
            b * 2.0 - target.point(s[n - 2]),
        ],
    ];
    if let (Some(t0), Some(t1), Some(tp), Some(tq)) = (
        target.parameter_at(0.0),
        target.parameter_at(s[1]),
        target.parameter_at(s[n - 2]),
        target.parameter_at(len),
    ) {
        if let (Some(g0), Some(g1)) = (
            target.point_at_parameter(2.0 * t0 - t1),
            target.point_at_parameter(2.0 * tq - tp),
        ) {
            out.push([g0, g1]);
        }
    }
    out
}

/// The cardinal `a` of the starts (tuned on a grid afterwards, [`super::polish::tune_parameter`]).
const START_A: f64 = 0.5;

/// One start: its layout, variables, and the family it comes from.
pub(super) type Candidate = (Layout, Vec<f64>, Start);

/// The structured starts of a plain layout: equal steps of each weight (closed: two phases),
/// the feature placement (corners), each with every guide choice.
fn plain_starts(target: &Target, layout: &Layout, out: &mut Vec<Candidate>) {
    let phases: &[f64] = if layout.closed { &[0.0, 0.5] } else { &[0.0] };
    let mut placements: Vec<(Vec<f64>, Start)> = Vec::new();
    for (weight, start) in weights(target) {
        for &phase in phases {
            placements.push((
                target.equal_steps(weight, 0.0, layout.on_shape, phase),
                start,
            ));
        }
    }
    if let Some(s) = target.feature_placement(layout.on_shape) {
        placements.push((s, Start::Corners));
    }
    for (s, start) in placements {
        if layout.guide_coordinates() > 0 {
            for g in guide_choices(target, &s) {
                out.push((layout.clone(), layout.variables(&s, &g, START_A), start));
            }
        } else {
            out.push((layout.clone(), layout.variables(&s, &[], START_A), start));
        }
    }
}

/// The starts of a symmetric layout: equal steps of each weight from the axis, the axis
/// points kept where the layout has them.
fn symmetric_starts(target: &Target, layout: &Layout, sym: &Symmetric, out: &mut Vec<Candidate>) {
    let n = layout.on_shape;
    for (weight, _) in weights(target) {
        let deltas: Vec<f64> = if layout.closed {
            // k/n from a point on the anchor, (k − ½)/n without one
            let shift = if sym.near { 0.0 } else { 0.5 };
            let s0 = sym.mirror.anchor;
            (1..=sym.pairs)
                .map(|k| target.weight_inverse(weight, s0, (k as f64 - shift) / n as f64) - s0)
                .collect()
        } else {
            (1..=sym.pairs)
                .map(|k| target.weight_inverse(weight, 0.0, k as f64 / (n - 1) as f64))
                .collect()
        };
        let mut x = deltas;
        if layout.guide_coordinates() > 0 {
            let Some(s) = layout.arcs(target, &x) else {
                continue;
            };
            for g in guide_choices(target, &s) {
                let mut y = x.clone();
                layout.append(&mut y, &g, START_A);
                out.push((layout.clone(), y, Start::Symmetric));
            }
        } else {
            layout.append(&mut x, &[], START_A);
            out.push((layout.clone(), x, Start::Symmetric));
        }
    }
}

/// SplitMix64: the seeded generator of the random starts (deterministic on every machine).
#[derive(Debug, Clone)]
pub(super) struct SplitMix(u64);

impl SplitMix {
    pub fn new(seed: u64) -> Self {
        SplitMix(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` random starts of a plain layout: sorted uniform positions, guides at a random
/// offset from the ends (up to a step), `a` uniform in `[0.2, 1.5]`.
fn random_starts(
    target: &Target,
    layout: &Layout,
    count: usize,
    rng: &mut SplitMix,
    out: &mut Vec<Candidate>,
) {
    let len = target.length();
    let n = layout.on_shape;
    for _ in 0..count {
        let mut s: Vec<f64> = (0..layout.positions()).map(|_| rng.unit() * len).collect();
        s.sort_by(f64::total_cmp);
        if !layout.closed {
            s.insert(0, 0.0);
            s.push(len);
        }
        let step = len / (n - 1) as f64;
        let ends = [target.point(0.0), target.point(len)];
        let guides: Vec<Vector2<f64>> = ends
            .iter()
            .map(|&e| {
                let (r, t) = (
                    (0.1 + 0.9 * rng.unit()) * step,
                    std::f64::consts::TAU * rng.unit(),
                );
                e + Vector2::new(t.cos(), t.sin()) * r
            })
            .collect();
        let a = 0.2 + 1.3 * rng.unit();
        out.push((
            layout.clone(),
            layout.variables(&s, &guides, a),
            Start::Random,
        ));
    }
}

/// Every start for `n` distinct points (module docs of [`super`], step 1): the structured
/// placements of each layout and `random` random ones per plain layout from `seed`.
pub(super) fn candidates(
    target: &Target,
    family: Family,
    n: usize,
    random: usize,
    seed: u64,
) -> Vec<Candidate> {
    let mut out = Vec::new();
    let mut rng = SplitMix::new(seed ^ (n as u64).wrapping_mul(0x2545_F491_4F6C_DD1D));
    for layout in layouts(target, family, n) {
        match layout.symmetric {
            None => {
                plain_starts(target, &layout, &mut out);
                random_starts(target, &layout, random, &mut rng, &mut out);
            }
            Some(sym) => symmetric_starts(target, &layout, &sym, &mut out),
        }
    }
    out
}
