//! The Angular spline of seed 004 §3 (Barsi & Milanesi 1986, after the IEI Pisa reports): a
//! local, parameter-free G¹ curve through plane points, each piece built from the circles
//! through consecutive points. Read in full in `spec/seed004.md` §1.7.
//!
//! **Tangents.** At an interpolated point `Pᵢ` the curve is tangent to the circle `Cᵢ` through
//! `Pᵢ₋₁, Pᵢ, Pᵢ₊₁`, oriented the way the points run round it; with `u = Pᵢ − Pᵢ₋₁`,
//! `v = Pᵢ₊₁ − Pᵢ` the oriented tangent is `tᵢ ∝ u/|u|² + v/|v|²` (for collinear points, the
//! line). It vanishes only when `Pᵢ₊₁ = Pᵢ₋₁` ([`Error::ReversedPoints`]).
//!
//! **One piece** `Pᵢ → Pᵢ₊₁` depends on `Pᵢ₋₁ … Pᵢ₊₂` only. In the local frame (origin at the
//! chord's midpoint, x along the chord, `Pᵢ = (−d, 0)`, `Pᵢ₊₁ = (d, 0)`), let `φᵢ`, `φᵢ₊₁` be
//! the angles of the two end tangents from the x-axis and `ϑ = φ + π/2` the angles of the
//! radii. In the **standard case** (`φᵢ > 0 > φᵢ₊₁`: both guides below the chord) the paper's
//! curve is the locus of the point at angle `α` on the circle through `Pᵢ, Pᵢ₊₁` centred at
//! `(0, c(α))`, with `c(α) = −d tan(kα + ψ)`,
//!
//! ```text
//! k = (ϑᵢ₊₁ + ϑᵢ − π)/(ϑᵢ₊₁ − ϑᵢ),   ψ = π − ϑᵢ − kϑᵢ,   α from ϑᵢ down to ϑᵢ₊₁,
//! x(α) = d cos α / cos α′,   y(α) = d (sin α − sin α′)/cos α′,   α′ = kα + ψ.
//! ```
//!
//! Here `α` is linear in the piece parameter `s ∈ [0, 1]`, and so is `α′` (from `π − ϑᵢ` to
//! `ϑᵢ₊₁`). With `β = α − π/2` and `γ = π/2 − α′` the same curve reads
//!
//! ```text
//! β(s) = (1 − s) φᵢ + s φᵢ₊₁,   γ(s) = (1 − s) φᵢ − s φᵢ₊₁,
//! x = −d sin β / sin γ,   y = −2d sin((1 − s) φᵢ) sin(s φᵢ₊₁) / sin γ,
//! ```
//!
//! which is what is evaluated: the ends are hit exactly (`β = γ` at `s = 0`, `β = −γ` at
//! `s = 1`, and a factor of `y` vanishes), `sin α − sin α′` no longer cancels, and
//! `sin γ ≥ min(sin φᵢ, sin |φᵢ₊₁|) > 0` on the whole piece (the sine is concave on `[0, π]`).
//! The paper's form is kept as the independent reference of the tests. When `φᵢ₊₁ = −φᵢ`
//! (`k = 0`, four concyclic points) the piece is an exact arc of the circle.
//!
//! **The other cases.** Both guides above the chord (`φᵢ < 0 < φᵢ₊₁`, the paper's Fig. 4): the
//! standard piece of the mirrored data, mirrored back. Guides on opposite sides (`φᵢ`, `φᵢ₊₁`
//! of one sign): an inflection, split at a point `P_F` with a tangent there chosen by an
//! [`InflectionRule`] — the paper uses "a heuristic procedure" it does not give; the default
//! [`HermiteMidpoint`] is the spec's decision A1.
//!
//! **End tangents on the chord line** (collinear points; the paper does not cover them, spec
//! decision A2 revised). The half-angle form gives the limits directly:
//!
//! - *Both* angles to 0 (`φᵢ = εa`, `φᵢ₊₁ = −εb`, `ε → 0`): `x → −d((1 − s)a − sb)/((1 − s)a + sb)`
//!   and `y = O(εd)`: the piece tends to the chord, with both end tangents along it. The
//!   straight chord is the G¹ limit, and a piece whose two angles are within
//!   [`COLLINEAR_SIN`] of 0 is the chord ([`PieceKind::Straight`]).
//! - *One* angle to 0, the other fixed (`φᵢ → 0`, `φᵢ₊₁ = −b`): for every `s > 0`, `x → d` and
//!   `y → 0` — the piece runs along the chord and turns in a hook of size `≈ 2φᵢd` at `Pᵢ₊₁`.
//!   The limit arrives at `Pᵢ₊₁` along the chord, not along its tangent: a corner of angle
//!   `b`. No G¹ curve is the limit, so such a piece is refused ([`Error::NoSmoothPiece`]).
//! - An angle to `π` (a tangent pointing back along the chord, as when collinear points
//!   reverse direction): the piece first runs backwards along the chord line, to
//!   `x = −d(π + b)/(π − b)`, and turns there with a spike in the limit: refused too.
//!
//! Angles just beyond the threshold keep the paper's curve: G¹, with a hook of size about
//! `2d|sin φ|` that is invisible at `10⁻⁹`. A consequence: the piece at either end of a run
//! of collinear points beside a turn has one tangent on its chord and the other not, so
//! an Angular spline has straight pieces only when all its points lie on one line, and it
//! cannot draw a polygon's corners (the paper's rectangle from corner triples is not G¹; the
//! seed-004 study reports it out of tolerance).
//!
//! **Properties** (tested): interpolation, G¹ at every joint of every curve built (the joined curve is not G²: the
//! curvature at an end is not the circle's), locality (four points per piece), invariance
//! under similarities. The paper claims invariance under *all* affine maps; that is false —
//! a shear or a non-uniform scale changes the curve (the tests carry a counterexample).

use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use nalgebra::Vector2;
use num_dual::DualNum;

/// An end tangent whose angle `φ` from the chord has `|sin φ| ≤ COLLINEAR_SIN` lies on the
/// chord line ([`classify`]: the piece is the straight chord when both do and point forward,
/// and has no G¹ curve otherwise).
pub const COLLINEAR_SIN: f64 = 1e-9;

/// How a piece `Pᵢ → Pᵢ₊₁` is built, from the end tangents' angles `φᵢ`, `φᵢ₊₁` to the chord.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PieceKind {
    /// Both end tangents along the chord, forwards: the straight chord.
    Straight,
    /// `φᵢ > 0 > φᵢ₊₁`: the paper's standard case, a hump to the left of the chord.
    Standard,
    /// `φᵢ < 0 < φᵢ₊₁`: the mirror image of a standard piece (seed 004 Fig. 4).
    Reflected,
    /// `φᵢ`, `φᵢ₊₁` of one sign: two pieces joined at an inflection point.
    Inflection,
}

/// The case of a piece whose end tangents make angles `phi_a`, `phi_b` (radians, in
/// `(−π, π]`) with its chord: the one classification rule of the construction.
///
/// An angle within [`COLLINEAR_SIN`] of the chord line is on it. The straight chord is the
/// limit of the paper's curve as *both* angles tend to 0 (module docs), so a piece is
/// [`PieceKind::Straight`] when both are on the line and point forward. When only one is,
/// or one points back along the chord (`φ → π`), the limit has a corner or a spike and there
/// is no G¹ piece: [`Error::NoSmoothPiece`] (with `point` 0: the caller knows the index).
///
/// # Errors
/// [`Error::NoSmoothPiece`] as above; [`Error::NonFinite`] for a NaN angle.
pub fn classify(phi_a: f64, phi_b: f64) -> Result<PieceKind> {
    crate::error::finite("Angular end angle", phi_a)?;
    crate::error::finite("Angular end angle", phi_b)?;
    let on_line = |phi: f64| phi.sin().abs() <= COLLINEAR_SIN;
    let refuse = |reason| Err(Error::NoSmoothPiece { point: 0, reason });
    match (on_line(phi_a), on_line(phi_b)) {
        (true, true) if phi_a.cos() > 0.0 && phi_b.cos() > 0.0 => Ok(PieceKind::Straight),
        (true, true) => refuse("an end tangent points back along the chord (the points reverse direction on a line)"),
        (true, false) | (false, true) => refuse("one end tangent lies on the chord line and the other does not (the limit is the chord with a corner)"),
        _ if phi_a > 0.0 && phi_b < 0.0 => Ok(PieceKind::Standard),
        _ if phi_a < 0.0 && phi_b > 0.0 => Ok(PieceKind::Reflected),
        _ => Ok(PieceKind::Inflection),
    }
}

/// An inflection point in a piece's frame: position `(x, y)` in units of the half chord `d`
/// (the piece runs from `(−1, 0)` to `(1, 0)`) and the tangent's angle `phi` from the chord.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InflectionPoint {
    /// Abscissa, in units of `d`.
    pub x: f64,
    /// Ordinate, in units of `d`.
    pub y: f64,
    /// Angle of the tangent at the inflection point from the chord direction.
    pub phi: f64,
}

/// Where an inflection piece is split and the tangent there: the one part of the Angular
/// spline the paper leaves open ("a heuristic procedure", seed 004 §3). Replaceable: pass your
/// own to [`AngularSpline::with_rule`].
///
/// `split` is called in the frame where both end angles are positive, `φᵢ, φᵢ₊₁ ∈ (0, π)`
/// (the curve leaves `Pᵢ` above the chord and reaches `Pᵢ₊₁` from below). Each half must then
/// be a standard, reflected or straight piece; a rule that makes a half an inflection again,
/// or returns a non-finite or far-away point, is refused with [`Error::Degenerate`].
pub trait InflectionRule {
    /// The rule's name, as figures and tables print it.
    fn name(&self) -> &'static str;
    /// The inflection point for end angles `phi_a, phi_b ∈ (0, π)`.
    fn split(&self, phi_a: f64, phi_b: f64) -> InflectionPoint;
}

/// Spec decision A1, the default: `P_F` at the chord's midpoint, with the tangent of the cubic
/// Hermite interpolant of the two ends (end derivatives `2d tᵢ`, `2d tᵢ₊₁`) at its middle,
///
/// `φ_F = −atan2(½(sin φᵢ + sin φᵢ₊₁), 3 − ½(cos φᵢ + cos φᵢ₊₁))`.
///
/// Always valid: `φ_F ∈ (−19.5°, 0)`, so the first half is a standard piece and the second a
/// reflected one for every `φᵢ, φᵢ₊₁ ∈ (0, π)`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct HermiteMidpoint;

impl InflectionRule for HermiteMidpoint {
    fn name(&self) -> &'static str {
        "Hermite midpoint (A1)"
    }

    fn split(&self, phi_a: f64, phi_b: f64) -> InflectionPoint {
        let phi =
            -(0.5 * (phi_a.sin() + phi_b.sin())).atan2(3.0 - 0.5 * (phi_a.cos() + phi_b.cos()));
        InflectionPoint {
            x: 0.0,
            y: 0.0,
            phi,
        }
    }
}

/// The "mirror" (biarc-like) alternative: `P_F` at the chord's midpoint with
/// `φ_F = −(φᵢ + φᵢ₊₁)/2`. Valid for all end angles, but on the sinusoid sampled at its
/// extrema about ten times less accurate than [`HermiteMidpoint`] (spec §1.7).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct MirrorMidpoint;

impl InflectionRule for MirrorMidpoint {
    fn name(&self) -> &'static str {
        "mirror midpoint"
    }

    fn split(&self, phi_a: f64, phi_b: f64) -> InflectionPoint {
        InflectionPoint {
            x: 0.0,
            y: 0.0,
            phi: -0.5 * (phi_a + phi_b),
        }
    }
}

/// One elementary arc: a standard piece in the frame `origin + x·ex + y·ey` (`ex`, `ey` carry
/// the half chord `d` and the reflection), or the straight chord.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Arc {
    origin: Vector2<f64>,
    ex: Vector2<f64>,
    ey: Vector2<f64>,
    phi_a: f64,
    phi_b: f64,
    straight: bool,
}

impl Arc {
    /// The point at `s ∈ [0, 1]` (module docs: the half-angle form of the paper's curve).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D) -> Vector2<D> {
        let (x, y) = if self.straight {
            (s * 2.0 - 1.0, D::zero())
        } else {
            let r = D::one() - s;
            let (a, b) = (r * self.phi_a, s * self.phi_b);
            let sin_gamma = (a - b).sin();
            (
                -(a + b).sin() / sin_gamma,
                a.sin() * b.sin() * (-2.0) / sin_gamma,
            )
        };
        Vector2::new(
            x * self.ex.x + y * self.ey.x + self.origin.x,
            x * self.ex.y + y * self.ey.y + self.origin.y,
        )
    }
}

/// Below this `min(sin φᵢ, sin |φᵢ₊₁|)` a run is evaluated point by point: the rotations'
/// absolute error (`≈ 10⁻¹⁶` per step) stays below `10⁻¹²` of `sin γ ≥ min(…)`.
const FAST_MIN_SIN: f64 = 1e-3;

/// Steps between re-seeding the rotations with exact sines and cosines.
const RESEED: usize = 32;

/// The fewest points of an arc's run that [`AngularSpline::sample_pieces_into`] advances by
/// rotation.
const PIECE_RUN: usize = 4;

/// `(cos, sin)` of `c + w·s₀`, and the rotation by `w·Δ`: one linear angle of a run.
#[derive(Clone, Copy)]
struct Rotor {
    c: f64,
    w: f64,
    cos: f64,
    sin: f64,
    step_cos: f64,
    step_sin: f64,
}

impl Rotor {
    fn new(c: f64, w: f64, delta: f64) -> Self {
        let (step_sin, step_cos) = (w * delta).sin_cos();
        Self {
            c,
            w,
            cos: 1.0,
            sin: 0.0,
            step_cos,
            step_sin,
        }
    }

    #[inline]
    fn seed(&mut self, s: f64) {
        (self.sin, self.cos) = (self.c + self.w * s).sin_cos();
    }

    #[inline]
    fn advance(&mut self) {
        let (c, s) = (self.cos, self.sin);
        self.cos = c * self.step_cos - s * self.step_sin;
        self.sin = s * self.step_cos + c * self.step_sin;
    }
}

impl Arc {
    /// Whether a run of `n` equally spaced points is evaluated by rotation: at least `least`
    /// points, not straight, and away from the straight limit (where the rotations would lose
    /// digits).
    fn rotates(&self, n: usize, least: usize) -> bool {
        let m = self.phi_a.sin().min((-self.phi_b).sin());
        !self.straight && n >= least && m >= FAST_MIN_SIN
    }

    /// The points at `n` equally spaced `s = s₀ + kΔ`, appended to `out`: the half-angle form
    /// with the four sines of linear angles advanced by rotation (re-seeded with exact values
    /// every [`RESEED`] points).
    fn extend_uniform(&self, s0: f64, delta: f64, n: usize, out: &mut Vec<Vector2<f64>>) {
        let (a, b) = (self.phi_a, self.phi_b);
        // sin((1 − s)φᵢ), sin(s φᵢ₊₁), sin γ = sin(φᵢ − s(φᵢ + φᵢ₊₁)), sin β = sin(φᵢ + s(φᵢ₊₁ − φᵢ))
        let mut r = [
            Rotor::new(a, -a, delta),
            Rotor::new(0.0, b, delta),
            Rotor::new(a, -(a + b), delta),
            Rotor::new(a, b - a, delta),
        ];
        let (o, ex, ey) = (self.origin, self.ex, self.ey);
        let mut k = 0;
        while k < n {
            let s = s0 + k as f64 * delta;
            for rotor in &mut r {
                rotor.seed(s);
            }
            let block = RESEED.min(n - k);
            for _ in 0..block {
                let inv = 1.0 / r[2].sin;
                let x = -r[3].sin * inv;
                let y = -2.0 * r[0].sin * r[1].sin * inv;
                out.push(Vector2::new(
                    x * ex.x + y * ey.x + o.x,
                    x * ex.y + y * ey.y + o.y,
                ));
                for rotor in &mut r {
                    rotor.advance();
                }
            }
            k += block;
        }
    }
}

fn hypot(v: Vector2<f64>) -> f64 {
    v.x.hypot(v.y)
}

/// The unit tangent at `b` of the circle through `a, b, c`, oriented from `a` through `b` to
/// `c` (the line's direction when they are collinear); the points are distinct and `a ≠ c`.
///
/// `|v|²u + |u|²v` (`u = b − a`, `v = c − b`) has norm `|u||v||w|` with `w = c − a`; its two
/// terms cancel only when `w` is small, and then the equal form
/// `|u|²(w − 2(w·û)û + |w|²u/|u|²)` is used, which has no cancellation. Everything is scaled
/// by the lengths first, so no square overflows.
fn circle_tangent(a: Vector2<f64>, b: Vector2<f64>, c: Vector2<f64>) -> Vector2<f64> {
    let (u, v, w) = (b - a, c - b, c - a);
    let (lu, lv, lw) = (hypot(u), hypot(v), hypot(w));
    let uh = u / lu;
    let t = if lw < 0.5 * lu.min(lv) {
        let wh = w / lw;
        wh - uh * (2.0 * wh.dot(&uh)) + uh * (lw / lu)
    } else {
        // |v|û + |u|v̂ in units of the longer side, so no component is subnormal
        let m = lu.max(lv);
        uh * (lv / m) + (v / lv) * (lu / m)
    };
    t / hypot(t)
}

/// The circle through three points, `(centre, radius)`, or `None` when they are collinear
/// (or two coincide): the circles `Cᵢ` of the construction, for figures and checks.
pub fn circumcircle(
    a: Vector2<f64>,
    b: Vector2<f64>,
    c: Vector2<f64>,
) -> Option<(Vector2<f64>, f64)> {
    // relative to a, so the determinant keeps its digits far from the origin, and in units
    // of a power of two near the differences' size (exact), so no square or product
    // underflows or overflows whatever the points' magnitude
    let (u, v) = (b - a, c - a);
    let m = u.amax().max(v.amax());
    if m == 0.0 || !m.is_finite() {
        return None;
    }
    let unit = 2f64.powi(m.log2().floor().clamp(-1022.0, 1023.0) as i32);
    let (u, v) = (u / unit, v / unit);
    let d = 2.0 * u.perp(&v);
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    let (uu, vv) = (u.norm_squared(), v.norm_squared());
    let centre = Vector2::new(v.y * uu - u.y * vv, u.x * vv - v.x * uu) / d;
    let (centre, r) = (centre * unit, hypot(centre) * unit);
    (r.is_finite() && centre.iter().all(|x| x.is_finite())).then_some((a + centre, r))
}

/// The guide `G` before `p1` that makes the circle
/// through `G, p1, p2` tangent at `p1` to `tangent`, oriented along it — so an Angular spline
/// whose first points are `G, p1, p2, …` leaves `p1` along `tangent` (spec §1.7). The same
/// call with the points reversed and `−tangent` gives the last guide.
///
/// When `tangent · (p2 − p1) > 0`, `G` is the mirror image of `p2` in the normal at `p1`;
/// otherwise it is the midpoint of the circle's arc from `p2` back to `p1`.
///
/// # Errors
/// [`Error::NonFinite`] or [`Error::CoordinateTooLarge`] for an input;
/// [`Error::RepeatedPoint`] if `p1 = p2`; [`Error::Degenerate`] for a zero tangent or one
/// pointing straight away from `p2` (no finite circle is tangent to it through `p2`, within
/// [`COLLINEAR_SIN`]); [`Error::CoordinateTooLarge`] if `G` is beyond the coordinate limit.
pub fn guide_point(
    p1: Vector2<f64>,
    p2: Vector2<f64>,
    tangent: Vector2<f64>,
) -> Result<Vector2<f64>> {
    finite_points("guide point input", &[p1, p2, tangent])?;
    if p1 == p2 {
        return Err(Error::RepeatedPoint { index: 1 });
    }
    let lt = hypot(tangent);
    if lt == 0.0 {
        return Err(Error::Degenerate {
            what: "guide point",
            reason: "the tangent is zero",
        });
    }
    let t = tangent / lt;
    let chord = p2 - p1;
    let lc = hypot(chord);
    let ch = chord / lc;
    let along = t.dot(&ch);
    let g = if along > 0.0 {
        p2 - t * (2.0 * along * lc)
    } else {
        // the circle through p1 tangent to t: centre p1 + r n, n the unit normal on p2's side
        let side = t.perp(&ch);
        if side.abs() <= COLLINEAR_SIN {
            return Err(Error::Degenerate {
                what: "guide point",
                reason: "the tangent points straight away from the next point",
            });
        }
        let n = Vector2::new(-t.y, t.x) * side.signum();
        // r = |chord|² / (2 chord·n), written to avoid squaring
        let r = lc / (2.0 * ch.dot(&n));
        let centre = p1 + n * r;
        let a1 = (p1 - centre).y.atan2((p1 - centre).x);
        let a2 = (p2 - centre).y.atan2((p2 - centre).x);
        // travel is counter-clockwise when the tangent turns left towards p2
        let ccw = side.signum();
        let mut ahead = ccw * (a2 - a1);
        ahead = ahead.rem_euclid(std::f64::consts::TAU);
        let behind = 0.5 * (std::f64::consts::TAU - ahead);
        let ag = a1 - ccw * behind;
        centre + Vector2::new(ag.cos(), ag.sin()) * r
    };
    for x in g.iter() {
        crate::error::derived_coordinate("guide point", *x)?;
    }
    Ok(g)
}

/// The Angular spline through `P₁ … P_{m−2}` with guides `P₀` and `P_{m−1}`, parameter
/// `u ∈ [0, m − 3]` (piece `j` on `[j, j + 1]`, from `P_{j+1}` to `P_{j+2}`; an inflection piece
/// has its two halves on `[j, j + ½]` and `[j + ½, j + 1]`).
#[derive(Debug, Clone, PartialEq)]
pub struct AngularSpline {
    points: Vec<Vector2<f64>>,
    tangents: Vec<Vector2<f64>>,
    kinds: Vec<PieceKind>,
    arcs: Vec<Arc>,
    breaks: Vec<f64>,
    rule: &'static str,
}

impl AngularSpline {
    /// The open Angular spline of `points` (the first and last are guides), with the default
    /// inflection rule [`HermiteMidpoint`].
    ///
    /// # Errors
    /// See [`AngularSpline::with_rule`].
    pub fn try_new(points: Vec<Vector2<f64>>) -> Result<Self> {
        Self::with_rule(points, &HermiteMidpoint)
    }

    /// The open Angular spline of `points` with the inflection rule `rule`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 4 points; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`]; [`Error::NonFinite`] or [`Error::CoordinateTooLarge`]
    /// for a point; [`Error::RepeatedPoint`] for two equal consecutive points;
    /// [`Error::ReversedPoints`] if `Pᵢ₊₁ = Pᵢ₋₁` (no circle); [`Error::NoSmoothPiece`] for
    /// a piece with one end tangent on its chord line and the other not, or one pointing back
    /// along it ([`classify`]: no G¹ piece exists), or for points so close (a subnormal chord)
    /// that a piece's tangent underflows to zero; [`Error::Degenerate`] if the rule's split
    /// is unusable; [`Error::CoordinateTooLarge`] if a piece could leave the
    /// coordinate limit.
    pub fn with_rule(points: Vec<Vector2<f64>>, rule: &dyn InflectionRule) -> Result<Self> {
        crate::error::size("Angular spline points", points.len())?;
        if points.len() < 4 {
            return Err(Error::TooFewPoints {
                what: "Angular spline points (2 guides and 2 interpolated)",
                needed: 4,
                got: points.len(),
            });
        }
        finite_points("Angular spline point", &points)?;
        if let Some(i) = (1..points.len()).find(|&i| points[i] == points[i - 1]) {
            return Err(Error::RepeatedPoint { index: i });
        }
        if let Some(i) = (1..points.len() - 1).find(|&i| points[i + 1] == points[i - 1]) {
            return Err(Error::ReversedPoints { index: i });
        }
        let tangents: Vec<Vector2<f64>> = points
            .windows(3)
            .map(|w| circle_tangent(w[0], w[1], w[2]))
            .collect();
        let pieces = points.len() - 3;
        let mut kinds = Vec::with_capacity(pieces);
        let mut arcs = Vec::with_capacity(pieces);
        let mut breaks = Vec::with_capacity(pieces + 1);
        breaks.push(0.0);
        for j in 0..pieces {
            let (p0, p1) = (points[j + 1], points[j + 2]);
            let (kind, piece) =
                build(p0, p1, tangents[j], tangents[j + 1], rule).map_err(|e| match e {
                    Error::NoSmoothPiece { reason, .. } => Error::NoSmoothPiece {
                        point: j + 1,
                        reason,
                    },
                    other => other,
                })?;
            kinds.push(kind);
            if let [first, second] = piece[..] {
                arcs.extend([first, second]);
                breaks.push(j as f64 + 0.5);
            } else {
                arcs.push(piece[0]);
            }
            breaks.push((j + 1) as f64);
        }
        let spline = Self {
            points,
            tangents,
            kinds,
            arcs,
            breaks,
            rule: rule.name(),
        };
        spline.check_subnormal_pieces()?;
        Ok(spline)
    }

    /// A piece whose chord is below `f64::MIN_POSITIVE` is computed in subnormal numbers,
    /// which keep fewer digits the smaller they are; where its derivative at an end underflows
    /// to zero (ends `5e-324` apart beside points of size 1) it has no tangent there, so no G¹
    /// curve: [`Error::NoSmoothPiece`]. Pieces of normal size are not evaluated.
    fn check_subnormal_pieces(&self) -> Result<()> {
        for j in 0..self.kinds.len() {
            let (p0, p1) = (self.points[j + 1], self.points[j + 2]);
            if (p1 - p0).amax() >= f64::MIN_POSITIVE {
                continue;
            }
            for s in [0.0, 1.0] {
                let d = self
                    .eval_piece(j, num_dual::Dual64::new(s, 1.0))
                    .map(|c| c.eps);
                // NaN counts as no tangent
                let moves = d.amax() > 0.0;
                if !moves {
                    return Err(Error::NoSmoothPiece {
                        point: j + 1,
                        reason:
                            "the points are so close that the piece's tangent underflows to zero",
                    });
                }
            }
        }
        Ok(())
    }

    /// The closed Angular spline through `points`, closed as seed 004 closes it: the first
    /// three points are repeated at the end (`Q₁ … Q_m, Q₁, Q₂, Q₃`, spec decision A5; the
    /// circle through 3 points takes "6 points"), so the curve runs `Q₂ → … → Q_m → Q₁ → Q₂`,
    /// G¹ all round. Default inflection rule.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 3 points; the errors of [`AngularSpline::with_rule`].
    pub fn closed(points: &[Vector2<f64>]) -> Result<Self> {
        Self::closed_with_rule(points, &HermiteMidpoint)
    }

    /// [`AngularSpline::closed`] with the inflection rule `rule`.
    ///
    /// # Errors
    /// As [`AngularSpline::closed`].
    pub fn closed_with_rule(points: &[Vector2<f64>], rule: &dyn InflectionRule) -> Result<Self> {
        let all = crate::interp::closed_by_three("closed Angular spline points", points)?;
        Self::with_rule(all, rule)
    }

    /// The points, guides included.
    pub fn points(&self) -> &[Vector2<f64>] {
        &self.points
    }

    /// The unit tangents at the interpolated points `P₁ … P_{m−2}` (circle tangents).
    pub fn tangents(&self) -> &[Vector2<f64>] {
        &self.tangents
    }

    /// The case of each piece.
    pub fn kinds(&self) -> &[PieceKind] {
        &self.kinds
    }

    /// Number of pieces, `m − 3`.
    pub fn pieces(&self) -> usize {
        self.kinds.len()
    }

    /// The name of the inflection rule the spline was built with.
    pub fn rule(&self) -> &'static str {
        self.rule
    }

    /// Piece `j` at its own parameter `s ∈ [0, 1]` (from `P_{j+1}` at 0 to `P_{j+2}` at 1),
    /// exact at both ends: each piece's one-sided values and derivatives at a joint.
    ///
    /// # Panics
    /// If `j` is not below [`AngularSpline::pieces`].
    pub fn eval_piece<D: DualNum<Primitive = f64> + Copy>(&self, j: usize, s: D) -> Vector2<D> {
        assert!(j < self.pieces(), "piece {j} of {}", self.pieces());
        self.eval_in(j, s)
    }

    /// `samples` points at equally spaced parameters over the domain, both ends included,
    /// into `out` (cleared first): the points of [`ParametricCurve::polyline`], computed
    /// faster. Within one arc the parameters are equally spaced, so the four sines of the
    /// half-angle form are sines of linear functions of the step and are advanced by complex
    /// rotation, re-seeded with exact values every 32 points (points differ from
    /// [`ParametricCurve::point`] by a few `10⁻¹⁵` of the points' scale; tested); runs near the
    /// straight limit and short runs are evaluated point by point. A piece whose end tangents
    /// both point nearly backwards along its chord is a huge loop (its extent grows like
    /// `d / sin φ`) and ill-conditioned in its parameter: there the two evaluations agree to
    /// about `10⁻¹⁰` of the curve's extent, as the rounding of the parameter allows.
    ///
    /// # Errors
    /// [`Error::TooFewSamples`] below 2; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`].
    pub fn polyline_into(&self, samples: usize, out: &mut Vec<Vector2<f64>>) -> Result<()> {
        crate::error::samples("Angular spline samples", samples)?;
        out.clear();
        out.reserve(samples);
        let (a, b) = self.domain();
        if samples < 4 * self.arcs.len() {
            // a few samples per arc or fewer: the rotation cannot repay its set-up per arc;
            // the reference path itself (measured: twice as fast below 10⁴ samples on the
            // 1000-point ellipse)
            out.extend(
                crate::domain::linspace(a, b, samples)
                    .into_iter()
                    .map(|t| self.point(t)),
            );
            return Ok(());
        }
        let step = (b - a) / (samples - 1) as f64;
        let mut k = 0;
        let last_arc = self.arcs.len() - 1;
        for (i, arc) in self.arcs.iter().enumerate() {
            let (lo, hi) = (self.breaks[i], self.breaks[i + 1]);
            let width = hi - lo;
            // the samples u_k = k·step in [lo, hi) (the last arc takes b too)
            let end = if i == last_arc {
                samples
            } else {
                let mut e = ((hi - a) / step).floor() as usize;
                e = e.clamp(k, samples);
                while e > k && a + (e - 1) as f64 * step >= hi {
                    e -= 1;
                }
                while e < samples && a + e as f64 * step < hi {
                    e += 1;
                }
                e
            };
            if end > k {
                let n = end - k;
                if arc.rotates(n, 2 * RESEED) {
                    let s0 = (a + k as f64 * step - lo) / width;
                    arc.extend_uniform(s0, step / width, n, out);
                } else {
                    // exactly the reference's evaluation
                    out.extend((k..end).map(|i| self.point(a + i as f64 * step)));
                }
                k = end;
            }
        }
        // the right end exactly, as the reference's linspace has it
        if let Some(p) = out.last_mut() {
            *p = self.point(b);
        }
        Ok(())
    }

    /// `per_piece` points at equally spaced parameters over each piece, both ends included (a
    /// joint once), into `out` (cleared first): the points of
    /// [`crate::metrics::curve::sample_pieces_into`] over the integer breaks, computed faster.
    /// Within an arc the parameters are equally spaced, so runs of at least four
    /// points are advanced by rotation as in [`AngularSpline::polyline_into`] (its set-up, eight
    /// sines and cosines, costs what two points do by the half-angle form); the points differ
    /// from the reference's by a few `10⁻¹⁵` of the curve's extent (tested).
    ///
    /// # Errors
    /// [`Error::TooFewSamples`] below 2 per piece; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`] in all; [`Error::Overflow`] for a point that is not
    /// finite.
    pub fn sample_pieces_into(&self, per_piece: usize, out: &mut Vec<Vector2<f64>>) -> Result<()> {
        crate::error::samples("samples per piece", per_piece)?;
        let total = crate::error::size_product("curve samples", self.pieces(), per_piece)?;
        out.clear();
        out.reserve(total);
        let step = 1.0 / (per_piece - 1) as f64;
        for j in 0..self.pieces() {
            // the arcs of piece j and the parameter ranges they take: the whole piece, or
            // its halves [0, ½) and [½, 1) for an inflection (its arcs at 2s and 2s − 1)
            let k = self.breaks.partition_point(|&b| b < j as f64);
            let runs: &[(usize, f64, usize, usize)] = if self.kinds[j] == PieceKind::Inflection {
                let half = (0..per_piece - 1)
                    .take_while(|&i| (i as f64 * step) < 0.5)
                    .count();
                &[(k, 0.0, 0, half), (k + 1, -1.0, half, per_piece - 1)]
            } else {
                &[(k, 0.0, 0, per_piece - 1)]
            };
            let scale = if runs.len() == 2 { 2.0 } else { 1.0 };
            for &(arc, shift, from, to) in runs {
                let arc = &self.arcs[arc];
                let n = to - from;
                if arc.rotates(n, PIECE_RUN) {
                    arc.extend_uniform(scale * from as f64 * step + shift, scale * step, n, out);
                } else {
                    out.extend((from..to).map(|i| arc.eval(scale * (i as f64 * step) + shift)));
                }
            }
        }
        out.push(self.point(self.pieces() as f64));
        crate::error::derived_points("curve sample", out)
    }

    fn eval_in<D: DualNum<Primitive = f64> + Copy>(&self, j: usize, s: D) -> Vector2<D> {
        use crate::branch::Condition;
        // the arcs of piece j: breaks[k] = j and the next one or two
        let k = self.breaks.partition_point(|&b| b < j as f64);
        if self.kinds[j] == PieceKind::Inflection {
            // the two arcs of an inflection piece: s ∈ [0, ½) and [½, 1]
            let first = crate::branch::choose(&s, |x| {
                if x < 0.5 {
                    (true, Condition::below(0.5, false))
                } else {
                    (false, Condition::above(0.5, true))
                }
            });
            if first {
                self.arcs[k].eval(s * 2.0)
            } else {
                self.arcs[k + 1].eval(s * 2.0 - 1.0)
            }
        } else {
            self.arcs[k].eval(s)
        }
    }
}

/// The arcs of the piece `p0 → p1` with unit end tangents `t0`, `t1`: one, or two for an
/// inflection.
fn build(
    p0: Vector2<f64>,
    p1: Vector2<f64>,
    t0: Vector2<f64>,
    t1: Vector2<f64>,
    rule: &dyn InflectionRule,
) -> Result<(PieceKind, Vec<Arc>)> {
    let frame = Frame::new(p0, p1);
    let (phi_a, phi_b) = (frame.angle(t0), frame.angle(t1));
    let kind = classify(phi_a, phi_b)?;
    if kind != PieceKind::Inflection {
        return Ok((kind, vec![frame.arc(kind, phi_a, phi_b)?]));
    }
    let sigma = phi_a.signum();
    let split = rule.split(sigma * phi_a, sigma * phi_b);
    let usable = [split.x, split.y, split.phi].iter().all(|v| v.is_finite())
        && split.x.abs() <= 4.0
        && split.y.abs() <= 4.0;
    if !usable {
        return Err(Error::Degenerate {
            what: "inflection rule",
            reason: "the split point is not finite or lies more than 4 half chords away",
        });
    }
    let pf = frame.origin + frame.ex * (frame.d * split.x) + frame.ey * (sigma * frame.d * split.y);
    let tf = frame.ex * split.phi.cos() + frame.ey * (sigma * split.phi.sin());
    if pf == p0 || pf == p1 {
        return Err(Error::Degenerate {
            what: "inflection rule",
            reason: "the split point is an end of the piece",
        });
    }
    let mut arcs = Vec::with_capacity(2);
    for (first, (a, b, ta, tb)) in [(true, (p0, pf, t0, tf)), (false, (pf, p1, tf, t1))] {
        let half = Frame::new(a, b);
        let (ha, hb) = (half.angle(ta), half.angle(tb));
        // the split's own tangent on its half chord is the rule's failure; the piece's end
        // tangent on it (the half chord is the chord's direction) is the piece's
        let split_angle = if first { hb } else { ha };
        let kind = classify(ha, hb).map_err(|e| {
            if split_angle.sin().abs() <= COLLINEAR_SIN {
                Error::NoSmoothPiece {
                    point: 0,
                    reason: "the inflection's split tangent lies on a half's chord line (the end tangents are near the chord line)",
                }
            } else {
                e
            }
        })?;
        if kind == PieceKind::Inflection {
            return Err(Error::Degenerate {
                what: "inflection rule",
                reason: "a half of the split piece needs an inflection again",
            });
        }
        arcs.push(half.arc(kind, ha, hb)?);
    }
    Ok((PieceKind::Inflection, arcs))
}

/// The local frame of a chord (seed 004 Fig. 3).
struct Frame {
    origin: Vector2<f64>,
    ex: Vector2<f64>,
    ey: Vector2<f64>,
    d: f64,
}

impl Frame {
    fn new(p0: Vector2<f64>, p1: Vector2<f64>) -> Self {
        let chord = p1 - p0;
        let length = hypot(chord);
        let ex = chord / length;
        Self {
            origin: p0 + chord * 0.5,
            ex,
            ey: Vector2::new(-ex.y, ex.x),
            d: 0.5 * length,
        }
    }

    /// The angle of the unit vector `t` from the chord direction.
    fn angle(&self, t: Vector2<f64>) -> f64 {
        t.dot(&self.ey).atan2(t.dot(&self.ex))
    }

    /// The arc of a non-inflection piece, checked to stay within the coordinate limit.
    fn arc(&self, kind: PieceKind, phi_a: f64, phi_b: f64) -> Result<Arc> {
        let (sigma, straight) = match kind {
            PieceKind::Standard => (1.0, false),
            PieceKind::Reflected => (-1.0, false),
            _ => (1.0, true),
        };
        let (phi_a, phi_b) = if straight {
            (0.0, 0.0)
        } else {
            (sigma * phi_a, sigma * phi_b)
        };
        // every point lies on a circle through both ends centred at (0, c), c between the
        // end circles' cᵢ = d cot φᵢ in magnitude (c(α) is monotone): within |c| + √(c² + d²)
        // = d (1 + |cos φ|)/|sin φ| of the midpoint
        let reach_of = |phi: f64| self.d * ((1.0 + phi.cos().abs()) / phi.sin().abs());
        let reach = if straight {
            self.d
        } else {
            reach_of(phi_a).max(reach_of(phi_b))
        };
        for c in self.origin.iter() {
            crate::error::derived_coordinate("Angular spline piece extent", c.abs() + reach)?;
        }
        Ok(Arc {
            origin: self.origin,
            ex: self.ex * self.d,
            ey: self.ey * (sigma * self.d),
            phi_a,
            phi_b,
            straight,
        })
    }
}

impl ParametricCurve<2> for AngularSpline {
    /// `C(u)` on piece `j = ⌊u⌋` at `s = u − j` ([`AngularSpline::eval_piece`]); the right end
    /// belongs to the last piece. Outside the domain the curve stays at its end points (an
    /// Angular piece does not extrapolate: its formula is only valid for `s ∈ [0, 1]`).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, u: D) -> Vector2<D> {
        use crate::branch::{choose, unit_span, Condition};
        let (a, b) = self.domain();
        let n = self.pieces();
        // beyond the ends the curve is a constant point; inside, piece j = ⌊u⌋ (the right
        // end in the last): the choice and the values it holds for, recorded together
        let (j, s) = choose(&u, |x| {
            if x < a {
                ((0, Some(0.0)), Condition::below(a, false))
            } else if x > b {
                ((n - 1, Some(1.0)), Condition::above(b, false))
            } else {
                let span = unit_span(x, n);
                ((span.lo as usize, None), Condition::from(span))
            }
        });
        let s = match s {
            Some(end) => D::from(end),
            None => u - j as f64,
        };
        self.eval_in(j, s)
    }

    /// `[0, m − 3]`.
    fn domain(&self) -> (f64, f64) {
        (0.0, self.pieces() as f64)
    }

    /// `[j, j + 1)`, piece `j = ⌊u⌋` (the last one closed); the half `[j, j + ½)` or
    /// `[j + ½, j + 1)` of an inflection piece, whose two arcs are two formulas.
    fn span_at(&self, u: f64) -> Option<crate::domain::Span> {
        let whole = crate::branch::unit_span(u, self.pieces());
        let j = whole.lo as usize;
        if self.kinds[j] != PieceKind::Inflection {
            return Some(whole);
        }
        let mid = whole.lo + 0.5;
        Some(if u - whole.lo < 0.5 {
            crate::domain::Span {
                lo: whole.lo,
                hi: mid,
                closed: false,
            }
        } else {
            crate::domain::Span { lo: mid, ..whole }
        })
    }
}
