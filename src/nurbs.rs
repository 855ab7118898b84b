//! NURBS curves: rational B-splines from weighted control points (seed 001, "Curve NURBS").

use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::walk_spans;
use crate::bspline::knots::KnotVector;
use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use crate::horner;
use nalgebra::{SVector, Vector2};
use num_dual::DualNum;

/// A NURBS curve of degree `p` in `ℝᴺ` (seed 001):
///
/// `C(t) = Σᵢ wᵢ Pᵢ N_{i,p}(t) / Σᵢ wᵢ N_{i,p}(t)`, weights `wᵢ > 0`,
///
/// the perspective projection `(X/W, …)` of the B-spline with homogeneous control points
/// `(wᵢPᵢ, wᵢ)`. With all weights 1 it is the B-spline curve on the same knots; a weight
/// `wᵢ` acts only on `[tᵢ, t_{i+p+1})`, pulling the curve towards `Pᵢ` as it grows.
/// Generic over the number type like [`crate::bspline::curve::BSplineCurve`].
///
/// # Examples
/// ```
/// use nalgebra::Vector2;
/// use splinelab::{NurbsCurve, ParametricCurve};
/// let circle = NurbsCurve::circle9(Vector2::new(0.0, 0.0), 2.0).unwrap();
/// let p = circle.point(0.3);
/// assert!((p.norm() - 2.0).abs() < 1e-14);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsCurve<const N: usize> {
    basis: BSplineBasis,
    points: Vec<SVector<f64, N>>,
    weights: Vec<f64>,
    /// `wᵢ / max wⱼ`, used in evaluation: the curve is unchanged by a common factor of the
    /// weights, and scaled weights keep `Σ wᵢNᵢ` away from underflow.
    scaled: Vec<f64>,
}

/// The smallest ratio `min wᵢ / max wᵢ` a NURBS curve accepts. The denominator
/// `Σ wᵢNᵢ ≥ min wᵢ / max wᵢ` (scaled weights, partition of unity) must stay a normal number
/// with room for the `p + 1` products: `10⁻²⁸⁰` leaves 28 orders of magnitude above
/// `f64::MIN_POSITIVE`. Weights spanning more than 280 orders of magnitude are rejected.
pub const MIN_WEIGHT_RATIO: f64 = 1e-280;

impl<const N: usize> NurbsCurve<N> {
    /// The curve with control points `points` and weights `weights` on `basis`.
    ///
    /// # Panics
    /// On invalid input; see [`NurbsCurve::try_new`].
    pub fn new(basis: BSplineBasis, points: Vec<SVector<f64, N>>, weights: Vec<f64>) -> Self {
        Self::try_new(basis, points, weights).expect("invalid NURBS curve")
    }

    /// The curve with control points `points` and weights `weights` on `basis`.
    ///
    /// # Errors
    /// [`Error::CountMismatch`] unless there is one control point and one weight per basis
    /// function; [`Error::NonPositiveWeight`] for a weight that is not positive and finite;
    /// [`Error::WeightRatio`] for one smaller than [`MIN_WEIGHT_RATIO`] times the largest;
    /// [`Error::NonFinite`] for a NaN or infinite coordinate.
    pub fn try_new(
        basis: BSplineBasis,
        points: Vec<SVector<f64, N>>,
        weights: Vec<f64>,
    ) -> Result<Self> {
        for (what, got) in [
            ("NURBS control points (knots − order)", points.len()),
            ("NURBS weights (one per control point)", weights.len()),
        ] {
            if got != basis.len() {
                return Err(Error::CountMismatch {
                    what,
                    expected: basis.len(),
                    got,
                });
            }
        }
        if let Some((index, &value)) = weights
            .iter()
            .enumerate()
            .find(|(_, w)| !(w.is_finite() && **w > 0.0))
        {
            return Err(Error::NonPositiveWeight { index, value });
        }
        finite_points("NURBS control point coordinate", &points)?;
        let max = weights.iter().copied().fold(0.0, f64::max);
        let scaled: Vec<f64> = weights.iter().map(|w| w / max).collect();
        if let Some((index, _)) = scaled
            .iter()
            .enumerate()
            .find(|(_, &r)| r.is_nan() || r < MIN_WEIGHT_RATIO)
        {
            return Err(Error::WeightRatio {
                index,
                value: weights[index],
                max,
                ratio: MIN_WEIGHT_RATIO,
            });
        }
        Ok(Self {
            basis,
            points,
            weights,
            scaled,
        })
    }

    /// The basis.
    pub fn basis(&self) -> &BSplineBasis {
        &self.basis
    }

    /// The control points.
    pub fn points(&self) -> &[SVector<f64, N>] {
        &self.points
    }

    /// The weights.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// A copy with weight `index` replaced (the slides' "weights as shape parameters").
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] for a bad index; [`Error::NonPositiveWeight`] unless
    /// `weight` is positive and finite.
    pub fn with_weight(&self, index: usize, weight: f64) -> Result<Self> {
        if index >= self.weights.len() {
            return Err(Error::IndexOutOfRange {
                what: "weight",
                index,
                len: self.weights.len(),
            });
        }
        let mut weights = self.weights.clone();
        weights[index] = weight;
        Self::try_new(self.basis.clone(), self.points.clone(), weights)
    }

    /// The homogeneous point `(Σ wᵢPᵢNᵢ, Σ wᵢNᵢ)` over the non-zero basis values `n` of span
    /// `ℓ`: the B-spline of the weighted control points `(wᵢPᵢ, wᵢ)` before projection.
    fn homogeneous<D: DualNum<Primitive = f64> + Copy>(
        &self,
        span: usize,
        n: &[D],
    ) -> (SVector<D, N>, D) {
        // from n's length, so that a length known to the caller's code is known here too
        let first = span + 1 - n.len();
        n.iter()
            .zip(&self.points[first..=span])
            .zip(&self.scaled[first..=span])
            .fold(
                (SVector::<D, N>::zeros(), D::zero()),
                |(num, den), ((&b, p), &w)| {
                    let wb = b * w;
                    (num + p.map(D::from) * wb, den + wb)
                },
            )
    }

    /// The perspective projection `X / W` of a homogeneous point; `W > 0` since the weights
    /// are positive and the basis is a partition of unity.
    fn project<D: DualNum<Primitive = f64> + Copy>(
        (num, den): (SVector<D, N>, D),
    ) -> SVector<D, N> {
        num * den.recip()
    }

    /// Evaluates at every parameter of `ts` into `out` (replacing its contents), by the same formula as
    /// [`ParametricCurve::eval`]. As [`crate::bspline::curve::BSplineCurve::eval_many`], at any degree: the
    /// numerator and denominator polynomials of each span are formed once (the Bézier points
    /// of the homogeneous control points `(wᵢPᵢ, wᵢ)` by blossoming, then their power forms),
    /// then each point costs two Horner evaluations and a division.
    ///
    /// The power forms are used on a span only where the projection keeps their accuracy:
    /// with `w_min` the smallest (scaled) weight of the span, `Σ wᵢNᵢ ≥ w_min` there, and the
    /// error of `X / W` is at most `(p + 2)ε (S_X + ‖P‖ S_W) / w_min` for the sizes `S` of the two
    /// power forms (`horner::size`); the span takes the fast path only if
    /// `S_W ≤ 256 · w_min` (so `W` keeps its relative accuracy and stays positive)
    /// and `S_X ≤ 256 · w_min · max ‖Pᵢ‖`. Very unequal weights (say `10⁻¹⁵` beside 1) send
    /// their spans to point-by-point evaluation as [`ParametricCurve::eval`].
    pub fn eval_many(&self, ts: &[f64], out: &mut Vec<SVector<f64, N>>) {
        horner::by_degree!(self.basis.degree(), [N, 1], self.eval_many_with(ts, out))
    }

    /// [`NurbsCurve::eval_many`] with the numerator's power form stored in `C` and the
    /// denominator's in `W`.
    fn eval_many_with<C: horner::Coefficients<N>, W: horner::Coefficients<1>>(
        &self,
        ts: &[f64],
        out: &mut Vec<SVector<f64, N>>,
    ) {
        let p = self.basis.degree();
        walk_spans(
            &self.basis,
            ts,
            out,
            SVector::zeros(),
            |span| {
                if p > horner::MAX_POWER_DEGREE {
                    return None;
                }
                let (mut hom, mut hom_w) = (C::zeros(p + 1), W::zeros(p + 1));
                let (points, weights) =
                    (&self.points[span - p..=span], &self.scaled[span - p..=span]);
                for (((h, hw), pt), &w) in hom
                    .as_mut()
                    .iter_mut()
                    .zip(hom_w.as_mut())
                    .zip(points)
                    .zip(weights)
                {
                    *h = pt * w;
                    hw.x = w;
                }
                let num: C = self.basis.span_power(span, hom.as_ref())?;
                let den: W = self.basis.span_power(span, hom_w.as_ref())?;
                let scale = horner::max_norm(points);
                let w_min = weights.iter().copied().fold(f64::INFINITY, f64::min);
                // the denominator keeps its relative accuracy (so it stays positive, whatever
                // the points), and the numerator its accuracy relative to the points
                let (s_num, s_den) = (horner::size(num.as_ref()), horner::size(den.as_ref()));
                let g = horner::TAYLOR_GROWTH * w_min;
                (s_den.is_finite() && s_den <= g && s_num.is_finite() && s_num <= g * scale)
                    .then_some((num, den))
            },
            |(num, den), s| {
                Self::project((
                    horner::eval(num.as_ref(), s),
                    horner::eval(den.as_ref(), s).x,
                ))
            },
            (|span, n| Self::project(self.homogeneous(span, n)), |_| ()),
        );
    }
}

impl<const N: usize> ParametricCurve<N> for NurbsCurve<N> {
    /// `Σ wᵢPᵢNᵢ(t) / Σ wᵢNᵢ(t)` over the span of `t` (end spans extrapolated outside the
    /// domain).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> SVector<D, N> {
        let (span, n) = self.basis.nonzero(t);
        Self::project(self.homogeneous(span, &n))
    }

    fn domain(&self) -> (f64, f64) {
        self.basis.domain()
    }

    /// The knot span of `t` ([`BSplineBasis::span_of`]).
    fn span_at(&self, t: f64) -> Option<crate::domain::Span> {
        Some(self.basis.span_of(t))
    }
}

impl NurbsCurve<2> {
    /// The circle of radius `radius` from 7 control points (seed 001, "Cerchio a 7 punti"):
    /// an equilateral triangle circumscribing the circle, knots
    /// `{0,0,0,1/3,1/3,2/3,2/3,1,1,1}`, weights `{1, ½, 1, ½, 1, ½, 1}`.
    ///
    /// The control points alternate between the midpoints of the triangle's sides (on the
    /// circle, weight 1) and its vertices (at distance `2r`, weight `cos 60° = ½`: each
    /// quadratic arc spans 120°, and a rational quadratic arc of angle `2θ` has middle weight
    /// `cos θ`; the slides write `cos(120)`, meaning the cosine of half the 120° arc). The
    /// curve starts at `center + (0, −r)` and runs counter-clockwise.
    ///
    /// # Errors
    /// [`Error::NotPositive`] unless `radius` is positive, finite and not subnormal (below
    /// `f64::MIN_POSITIVE` its points lose their precision); [`Error::NonFinite`] for a NaN or
    /// infinite centre; [`Error::CoordinateTooLarge`] for control points beyond
    /// [`crate::error::MAX_COORDINATE`].
    pub fn circle7(center: Vector2<f64>, radius: f64) -> Result<Self> {
        Self::regular_circle(center, radius, 3)
    }

    /// The circle of radius `radius` from 9 control points (seed 001, "Cerchio a 9 punti"): the
    /// circumscribed square, knots `{0,0,0,¼,¼,½,½,¾,¾,1,1,1}`, weights
    /// `{1, √2/2, 1, √2/2, …, 1}` (90° arcs, middle weight `cos 45°`). Starts at
    /// `center + (0, −r)`, counter-clockwise.
    ///
    /// # Errors
    /// As [`NurbsCurve::circle7`].
    pub fn circle9(center: Vector2<f64>, radius: f64) -> Result<Self> {
        Self::regular_circle(center, radius, 4)
    }

    /// The circle as `sides` rational quadratic arcs on the circumscribed regular polygon:
    /// `2·sides + 1` control points, double interior knots at `k/sides`.
    fn regular_circle(center: Vector2<f64>, radius: f64, sides: usize) -> Result<Self> {
        if !(radius.is_finite() && radius >= f64::MIN_POSITIVE) {
            return Err(Error::NotPositive {
                what: "circle radius (positive, finite, not subnormal)",
                value: radius,
            });
        }
        crate::error::finite_points("circle centre", &[center])?;
        let half = std::f64::consts::PI / sides as f64; // half of each arc's angle
        let start = -std::f64::consts::FRAC_PI_2;
        let mut points = Vec::with_capacity(2 * sides + 1);
        let mut weights = Vec::with_capacity(2 * sides + 1);
        for k in 0..=2 * sides {
            let angle = start + k as f64 * half;
            let dir = Vector2::new(angle.cos(), angle.sin());
            if k % 2 == 0 {
                points.push(center + dir * radius); // side midpoint, on the circle
                weights.push(1.0);
            } else {
                points.push(center + dir * (radius / half.cos())); // polygon vertex
                weights.push(half.cos());
            }
        }
        let mut knots = vec![0.0; 3];
        for k in 1..sides {
            let x = k as f64 / sides as f64;
            knots.extend([x, x]);
        }
        knots.extend([1.0; 3]);
        let basis = BSplineBasis::try_new(KnotVector::try_new(knots)?, 2)?;
        Self::try_new(basis, points, weights)
    }
}
