//! Seed 004's interpolation methods behind one type, so a comparison can run every method on
//! every point set: the Angular spline, the cardinal spline with its `a`, the parametric cubic
//! spline with the paper's three end conditions, the B-spline of order `k` (its points are the
//! control polygon) and linear interpolation.
//!
//! Closed curves are made as the paper makes them (spec decision A5): the Angular and cardinal
//! splines repeat the first three points, the cubic spline, B-spline and polygon repeat the
//! first point; [`Method::counted_points`] counts the repeats as the paper's Table I does.

use crate::bspline::curve::BSplineCurve;
use crate::curve::ParametricCurve;
use crate::error::Result;
use crate::interp::angular::AngularSpline;
use crate::interp::cardinal::CardinalSpline;
use crate::interp::cubic::{CubicSpline, EndCondition};
use crate::interp::linear::PiecewiseLinear;
use crate::param::Parametrization;
use nalgebra::Vector2;
use num_dual::DualNum;

/// The end conditions seed 004 used for the cubic spline (clamped needs end tangents a
/// draughtsman cannot give, so the paper left it out).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CubicEnd {
    /// `P″ = 0` at both ends (natural).
    Relaxed,
    /// `P′`, `P″` equal at the ends: periodic on a closed curve, [`EndCondition::Cyclic`] on
    /// open data.
    Cyclic,
    /// `P′₁ = −P′ₙ`, `P″₁ = −P″ₙ`.
    Anticyclic,
}

impl CubicEnd {
    /// The three, in the paper's order.
    pub const ALL: [CubicEnd; 3] = [CubicEnd::Relaxed, CubicEnd::Cyclic, CubicEnd::Anticyclic];

    /// The spline end condition for closed or open data.
    pub fn condition(self, closed: bool) -> EndCondition<2> {
        match (self, closed) {
            (CubicEnd::Relaxed, _) => EndCondition::Natural,
            (CubicEnd::Cyclic, true) => EndCondition::Periodic,
            (CubicEnd::Cyclic, false) => EndCondition::Cyclic,
            (CubicEnd::Anticyclic, _) => EndCondition::Anticyclic,
        }
    }
}

/// One of seed 004's methods with its parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// The Angular spline (no parameter).
    Angular,
    /// The cardinal spline with tangents `a (Pᵢ₊₁ − Pᵢ₋₁)`.
    Cardinal {
        /// The parameter `a > 0`.
        a: f64,
    },
    /// The parametric cubic spline, chord-length parameters.
    Cubic {
        /// The end condition.
        end: CubicEnd,
    },
    /// The B-spline of order `k` on open uniform knots through the points as its polygon.
    BSpline {
        /// The order `k ≥ 2`.
        order: usize,
    },
    /// The polygon through the points.
    Linear,
}

impl Method {
    /// The method's family name (`Angular`, `Cardinal`, `Cubic`, `B-spline`, `Linear`).
    pub fn family(&self) -> &'static str {
        match self {
            Method::Angular => "Angular",
            Method::Cardinal { .. } => "Cardinal",
            Method::Cubic { .. } => "Cubic",
            Method::BSpline { .. } => "B-spline",
            Method::Linear => "Linear",
        }
    }

    /// How many of the first points a closed curve repeats at its end: 3 for the four-point
    /// segments of the Angular and cardinal splines, 1 for the others; none when open.
    fn repeats(&self, closed: bool) -> usize {
        match (self, closed) {
            (_, false) => 0,
            (Method::Angular | Method::Cardinal { .. }, true) => 3,
            (_, true) => 1,
        }
    }

    /// The points of `points` as the method uses them: closed curves get the paper's repeats
    /// (after [`ring`] drops a closing repeat the points already have).
    pub fn prepared(&self, points: &[Vector2<f64>], closed: bool) -> Vec<Vector2<f64>> {
        self.repeated(ring(points, closed), closed)
    }

    /// `points` (a ring without its closing repeat) and a closed curve's repeats.
    fn repeated(&self, points: &[Vector2<f64>], closed: bool) -> Vec<Vector2<f64>> {
        let mut all = points.to_vec();
        all.extend(points.iter().take(self.repeats(closed)).copied());
        all
    }

    /// How many points the paper counts for `distinct` points: the repeats of a closed curve
    /// included (a closed Angular circle through 3 points is "6 points").
    pub fn counted_points(&self, distinct: usize, closed: bool) -> usize {
        distinct.saturating_add(self.repeats(closed))
    }

    /// The curve of the method through (or, for the B-spline, guided by) `points`, closed as
    /// the paper closes curves when `closed`.
    ///
    /// # Errors
    /// The errors of the method's constructor ([`AngularSpline::try_new`],
    /// [`CardinalSpline::try_new`], [`CubicSpline::curve`], [`BSplineCurve::with_order`],
    /// [`PiecewiseLinear::curve`]).
    /// A closed curve's points may end with a repeat of the first, the usual way a ring is
    /// stored: it is dropped ([`ring`]). Two consecutive points that coincide are named by
    /// their indices (from 0) in `points`.
    pub fn curve(&self, points: &[Vector2<f64>], closed: bool) -> Result<Interpolant> {
        self.curve_of_ring(ring(points, closed), closed)
    }

    fn curve_of_ring(&self, points: &[Vector2<f64>], closed: bool) -> Result<Interpolant> {
        let all = self.repeated(points, closed);
        Ok(match *self {
            Method::Angular if closed => Interpolant::Angular(AngularSpline::closed(points)?),
            Method::Angular => Interpolant::Angular(AngularSpline::try_new(all)?),
            Method::Cardinal { a } if closed => {
                Interpolant::Cardinal(CardinalSpline::closed(points, a)?)
            }
            Method::Cardinal { a } => Interpolant::Cardinal(CardinalSpline::try_new(all, a)?),
            Method::Cubic { end } => Interpolant::Cubic(CubicSpline::curve(
                &all,
                Parametrization::ChordLength,
                end.condition(closed),
            )?),
            Method::BSpline { order } => {
                Interpolant::BSpline(BSplineCurve::with_order(all, order)?)
            }
            Method::Linear => {
                Interpolant::Linear(PiecewiseLinear::curve(&all, Parametrization::ChordLength)?)
            }
        })
    }
}

/// The points of a ring without the repeat that closes it: `points` less its last point when
/// `closed`, there are more than two, and the last equals the first; else `points`.
pub fn ring(points: &[Vector2<f64>], closed: bool) -> &[Vector2<f64>] {
    match points {
        [first, .., last] if closed && points.len() > 2 && first == last => {
            &points[..points.len() - 1]
        }
        _ => points,
    }
}

/// The curve a [`Method`] made.
#[derive(Debug, Clone, PartialEq)]
pub enum Interpolant {
    /// An Angular spline.
    Angular(AngularSpline),
    /// A cardinal spline.
    Cardinal(CardinalSpline<2>),
    /// A cubic spline curve.
    Cubic(CubicSpline<2>),
    /// A B-spline curve.
    BSpline(BSplineCurve<2>),
    /// A polygon.
    Linear(PiecewiseLinear<2>),
}

impl Interpolant {
    /// `per_piece` points at equally spaced parameters over each piece between
    /// [`Interpolant::breaks`], both ends included (a joint once), into `out` (cleared first):
    /// [`crate::metrics::curve::sample_pieces_into`], the Angular spline's faster
    /// ([`AngularSpline::sample_pieces_into`]).
    ///
    /// # Errors
    /// As [`crate::metrics::curve::sample_pieces_into`].
    pub fn sample_pieces_into(&self, per_piece: usize, out: &mut Vec<Vector2<f64>>) -> Result<()> {
        match self {
            Interpolant::Angular(c) => c.sample_pieces_into(per_piece, out),
            _ => crate::metrics::curve::sample_pieces_into(self, &self.breaks(), per_piece, out),
        }
    }

    /// The parameters where the curve's pieces meet, both ends of the domain included, sorted
    /// and distinct: the Angular and cardinal segments' integers, the cubic spline's and
    /// polygon's nodes, the B-spline's distinct knots inside its domain.
    pub fn breaks(&self) -> Vec<f64> {
        let integers = |n: usize| (0..=n).map(|k| k as f64).collect();
        match self {
            Interpolant::Angular(c) => integers(c.pieces()),
            Interpolant::Cardinal(c) => integers(c.segments()),
            Interpolant::Cubic(c) => c.nodes().to_vec(),
            Interpolant::Linear(c) => c.nodes().to_vec(),
            Interpolant::BSpline(c) => {
                let (a, b) = c.domain();
                let mut ks: Vec<f64> = c
                    .basis()
                    .knots()
                    .breakpoints()
                    .into_iter()
                    .map(|(k, _)| k)
                    .filter(|&k| k > a && k < b)
                    .collect();
                ks.insert(0, a);
                ks.push(b);
                ks
            }
        }
    }
}

impl ParametricCurve<2> for Interpolant {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> Vector2<D> {
        match self {
            Interpolant::Angular(c) => c.eval(t),
            Interpolant::Cardinal(c) => c.eval(t),
            Interpolant::Cubic(c) => c.eval(t),
            Interpolant::BSpline(c) => c.eval(t),
            Interpolant::Linear(c) => c.eval(t),
        }
    }

    fn domain(&self) -> (f64, f64) {
        match self {
            Interpolant::Angular(c) => c.domain(),
            Interpolant::Cardinal(c) => c.domain(),
            Interpolant::Cubic(c) => c.domain(),
            Interpolant::BSpline(c) => c.domain(),
            Interpolant::Linear(c) => c.domain(),
        }
    }

    fn span_at(&self, t: f64) -> Option<crate::domain::Span> {
        match self {
            Interpolant::Angular(c) => c.span_at(t),
            Interpolant::Cardinal(c) => c.span_at(t),
            Interpolant::Cubic(c) => c.span_at(t),
            Interpolant::BSpline(c) => c.span_at(t),
            Interpolant::Linear(c) => c.span_at(t),
        }
    }
}
