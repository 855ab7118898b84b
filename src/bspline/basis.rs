//! The B-spline basis `N_{i,p}` on a knot vector: Cox–de Boor as the reference and the
//! one-pass evaluator of all non-zero functions (seed 001, "Base B-spline").

use crate::bspline::knots::KnotVector;
use crate::error::{Error, Result};
use crate::lanes::Lanes;
use nalgebra::SVector;
use num_dual::DualNum;
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

pub use super::scalar::KnotScalar;

/// `$body` with `$l` a constant `p + 1` (the count of non-zero basis values) for degrees
/// `p = 0 … 7`, so that arrays and loops of that length are sized and unrolled at compile
/// time; `$other` above.
macro_rules! by_count {
    ($p:expr, $l:ident => $body:expr, _ => $other:expr) => {
        match $p {
            0 => {
                const $l: usize = 1;
                $body
            }
            1 => {
                const $l: usize = 2;
                $body
            }
            2 => {
                const $l: usize = 3;
                $body
            }
            3 => {
                const $l: usize = 4;
                $body
            }
            4 => {
                const $l: usize = 5;
                $body
            }
            5 => {
                const $l: usize = 6;
                $body
            }
            6 => {
                const $l: usize = 7;
                $body
            }
            7 => {
                const $l: usize = 8;
                $body
            }
            _ => $other,
        }
    };
}

/// The normalised B-spline basis `{N_{i,p}}`, `i = 0 … n`, of degree `p` (order `m = p + 1`) on a
/// knot vector `t₀ ≤ … ≤ t_{n+p+1}` (0-based; the slides count from 1).
///
/// Valid when the knot vector has at least `2(p + 1)` knots, no knot of multiplicity above
/// `p + 1`, and a non-empty domain `[a, b] = [t_p, t_{n+1}]`, where the functions sum to 1.
///
/// Conventions (seed 001): `N_{i,0}(t) = 1` on `[tᵢ, tᵢ₊₁)`, else 0, and `0/0 = 0` in the
/// Cox–de Boor recurrence. **The right end `t = b` is the left limit**: it belongs to the
/// last non-empty span `[t_ℓ, t_{ℓ+1})` with `t_ℓ < b`, whatever the multiplicity of `b`
/// and whether or not the vector is clamped (the half-open rule alone would give all zeros
/// at a clamped end, and an empty span where `b` is repeated without being clamped, e.g.
/// knots `(0,0,0,1,1,1,2)`, degree 2, at `t = 1`). Values and derivatives there are those
/// of that span's polynomial, for every evaluator of the crate.
///
/// # Examples
/// ```
/// use splinelab::{BSplineBasis, KnotVector};
/// // seed 001: degree 2, knots (0,0,0,1,2,2,2), t = 0.6 → 0.16, 0.66, 0.18, 0
/// let basis = BSplineBasis::new(KnotVector::new(vec![0., 0., 0., 1., 2., 2., 2.]), 2);
/// let n = basis.all(0.6_f64);
/// assert!((n[0] - 0.16).abs() < 1e-15 && (n[1] - 0.66).abs() < 1e-15);
/// assert!((n[2] - 0.18).abs() < 1e-15 && n[3] == 0.0);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineBasis {
    knots: KnotVector,
    degree: usize,
}

impl BSplineBasis {
    /// The basis of degree `degree` on `knots`.
    ///
    /// # Panics
    /// On an invalid combination; see [`BSplineBasis::try_new`].
    pub fn new(knots: KnotVector, degree: usize) -> Self {
        Self::try_new(knots, degree).expect("invalid B-spline basis")
    }

    /// The basis of degree `degree` on `knots`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] for a degree above [`crate::error::MAX_ELEMENTS`];
    /// [`Error::TooFewKnots`] for fewer than `2(p + 1)` knots; [`Error::MultiplicityTooHigh`]
    /// for a knot repeated more than `p + 1` times; [`Error::EmptyInterval`] if the domain
    /// `[t_p, t_{n+1}]` is empty.
    pub fn try_new(knots: KnotVector, degree: usize) -> Result<Self> {
        // 2(p + 1) knots are needed; a degree beyond any knot vector's length is named as such
        crate::error::size("B-spline degree", degree)?;
        let needed = 2 * (degree + 1);
        if knots.len() < needed {
            return Err(Error::TooFewKnots {
                needed,
                got: knots.len(),
            });
        }
        if let Some((index, (_, m))) = knots
            .breakpoints()
            .into_iter()
            .enumerate()
            .find(|(_, (_, m))| *m > degree + 1)
        {
            return Err(Error::MultiplicityTooHigh {
                index,
                multiplicity: m,
                max: degree + 1,
            });
        }
        let basis = Self { knots, degree };
        let (a, b) = basis.domain();
        if a >= b {
            return Err(Error::EmptyInterval {
                what: "B-spline domain [t_p, t_{n+1}]",
                start: a,
                end: b,
            });
        }
        Ok(basis)
    }

    /// The knot vector.
    pub fn knots(&self) -> &KnotVector {
        &self.knots
    }

    /// The degree `p`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The order `m = p + 1`.
    pub fn order(&self) -> usize {
        self.degree + 1
    }

    /// The number of basis functions `n + 1` (= knots − order): the number of control points
    /// of a curve on this basis (seed 001: `n_cp + m` knots).
    pub fn len(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// Always false: a valid basis has at least `p + 1` functions.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The domain `[a, b] = [t_p, t_{n+1}]` on which the basis is a partition of unity.
    pub fn domain(&self) -> (f64, f64) {
        let t = self.knots.knots();
        (t[self.degree], t[t.len() - self.degree - 1])
    }

    /// The span `ℓ` with `t_ℓ ≤ t < t_{ℓ+1}`, `p ≤ ℓ ≤ n`, holding `t` (*The NURBS Book* A2.1),
    /// always a non-empty one (`t_ℓ < t_{ℓ+1}`). At and beyond the right end `b` it is the last
    /// span with `t_ℓ < b` (the left limit, see [`BSplineBasis`]); below `a` the first
    /// non-empty span. Evaluation outside `[a, b]` extrapolates that span's polynomial.
    pub fn find_span(&self, t: f64) -> usize {
        self.span_by(t, None)
    }

    /// [`BSplineBasis::find_span`] searched from the span `hint` (any index): the same span,
    /// found by galloping from `hint` ([`crate::domain::partition_point_from`]), so sorted
    /// parameters that skip spans cost `O(log d)` comparisons near the previous span.
    pub(crate) fn find_span_near(&self, hint: usize, t: f64) -> usize {
        // the hint itself, where it holds t (two loads, no search): t_ℓ ≤ t < t_{ℓ+1} makes ℓ
        // the last knot index with t_ℓ ≤ t, a non-empty span, and t < t_{ℓ+1} ≤ b
        let k = self.knots.knots();
        if (self.degree..self.len()).contains(&hint) && k[hint] <= t && t < k[hint + 1] {
            return hint;
        }
        self.span_by(t, Some(hint.saturating_sub(self.degree)))
    }

    /// [`BSplineBasis::find_span`], its searches of the interior knots `t_{p+1} … t_n` binary,
    /// or galloping from index `from` of them.
    #[inline]
    fn span_by(&self, t: f64, from: Option<usize>) -> usize {
        fn search(knots: &[f64], from: Option<usize>, pred: impl Fn(f64) -> bool) -> usize {
            match from {
                None => knots.partition_point(|&x| pred(x)),
                Some(h) => crate::domain::partition_point_from(knots, h, pred),
            }
        }
        let k = self.knots.knots();
        let p = self.degree;
        let n = self.len() - 1;
        let b = k[n + 1];
        if t >= b {
            // the last ℓ ≤ n with t_ℓ < b (ℓ = p qualifies: t_p = a < b), so t_{ℓ+1} ≥ b > t_ℓ
            return p + search(&k[p + 1..=n], from, |x| x < b);
        }
        // the last ℓ in [p, n] with t_ℓ ≤ t: t_{ℓ+1} > t ≥ t_ℓ, a non-empty span, unless t is
        // below the domain and the first span is empty (a = t_p = t_{p+1}): then the first
        // non-empty one
        let span = p + search(&k[p + 1..=n], from, |x| x <= t);
        (span..=n).find(|&s| k[s] < k[s + 1]).unwrap_or(span)
    }

    /// The values on which span `span`, picked for the value `x`, holds: its interval, the
    /// end spans extended beyond the domain where `x` lies beyond it (they extrapolate).
    fn span_condition(&self, span: usize, x: f64) -> crate::branch::Condition {
        crate::branch::beyond(self.span_interval(span), x, self.domain())
    }

    /// The knot span `[t_ℓ, t_ℓ₊₁)` of `t` ([`BSplineBasis::find_span`]: the right end of the
    /// domain belongs to the last non-empty span, which is then closed), on which every basis
    /// function is one polynomial.
    pub fn span_of(&self, t: f64) -> crate::domain::Span {
        self.span_interval(self.find_span(t))
    }

    /// Knot span `span` as an interval, closed if it ends at the domain's right end.
    fn span_interval(&self, span: usize) -> crate::domain::Span {
        let k = self.knots.knots();
        crate::domain::Span {
            lo: k[span],
            hi: k[span + 1],
            closed: k[span + 1] >= self.domain().1,
        }
    }

    /// The power form of the piece of `points` (the `p + 1` control points of span `span`)
    /// in the span's scaled variable: its Bézier points ([`BSplineBasis::span_bezier`]) turned
    /// into power coefficients (`horner::bezier_to_power`); `None` above
    /// `horner::MAX_POWER_DEGREE`, where no power form is made. One path for the B-spline
    /// curve's points and the NURBS curve's numerator and denominator.
    pub(crate) fn span_power<C: crate::horner::Coefficients<N>, const N: usize>(
        &self,
        span: usize,
        points: &[SVector<f64, N>],
    ) -> Option<C> {
        let p = self.degree;
        if p > crate::horner::MAX_POWER_DEGREE {
            return None;
        }
        let (mut tmp, mut c) = (C::zeros(p + 1), C::zeros(p + 1));
        self.span_bezier(span, points, tmp.as_mut(), c.as_mut());
        crate::horner::bezier_to_power(c.as_mut());
        Some(c)
    }

    /// The Bézier points `b₀ … b_p` (into `out`) of the piece on span `ℓ = span` of the curve
    /// whose control points on the span are `points = P_{ℓ−p} … P_ℓ`: on `[a, b] = [t_ℓ, t_{ℓ+1}]`,
    /// `Σᵢ Pᵢ N_{i,p}(t) = Σₖ bₖ Bₖᵖ(s)`, `s = (t − a)/(b − a)`.
    ///
    /// By blossoming (Ramshaw; Farin, *Curves and Surfaces for CAGD*, ch. 8):
    /// `bₖ = B(a^{p−k}, b^k)`, in two de Boor triangles (`d_j ← (1 − α) d_{j−1} + α d_j` at level
    /// `r`, nodes `j = p … r`, `α = (u − t_J)/(t_{J+p+1−r} − t_J)`, `J = ℓ − p + j`, and `1 − α`
    /// as `(t_{J+p+1−r} − u)/(t_{J+p+1−r} − t_J)`):
    /// 1. at `u = a` on the control points: the last node after level `r` is
    ///    `Q_r = B(a^r, t_{ℓ+1}, …, t_{ℓ+p−r})` — the control points once `a` is inserted `p`
    ///    times;
    /// 2. `R_m = Q_{p−m}` are the control points of the same piece on the knots
    ///    `a, …, a (p times), t_{ℓ+1}, …, t_{ℓ+p}` (the window of `R_m` is
    ///    `a^{p−m}, t_{ℓ+1}, …, t_{ℓ+m}`); de Boor's triangle at `u = b = t_{ℓ+1}` on them leaves
    ///    node `k` after level `k` at `B(b^k, a^{p−k}) = bₖ` (its knots beyond the `k` arguments
    ///    are all `a`), and later levels do not touch it.
    ///
    /// `p(p + 1)` vector combinations and `p(p + 1)/2 + p` divisions per span (one triangle
    /// per Bézier point, as before, took `p(p + 1)²/2`). Every interval `[t_J, t_{J+p+1−r}]` of
    /// either triangle contains the span, so the denominators are at least its width and every
    /// `α` is in `[0, 1]`: the Bézier points are convex combinations of the control points,
    /// accurate however close the knots. `tmp` holds `p + 1` entries, like `points` and `out`.
    pub(crate) fn span_bezier<const N: usize>(
        &self,
        span: usize,
        points: &[SVector<f64, N>],
        tmp: &mut [SVector<f64, N>],
        out: &mut [SVector<f64, N>],
    ) {
        let p = self.degree;
        let k = self.knots.knots();
        let (a, b) = (k[span], k[span + 1]);
        // the level's nodes from the top down: d_j ← β d_{j−1} + α d_j, the two weights from
        // the distances to the interval's ends (as in the basis recurrence), not 1 − α from α:
        // when α is within ulps of 1 the small weight keeps its relative accuracy, which
        // matters where it multiplies a large weight of a NURBS curve
        let lerp = |d: &mut [SVector<f64, N>], j: usize, lo: f64, hi: f64, u: f64| {
            let inv = 1.0 / (hi - lo);
            d[j] = d[j - 1] * ((hi - u) * inv) + d[j] * ((u - lo) * inv);
        };
        // 1. at a: the last node after each level, stored as R_m = Q_{p−m} (out[p − r])
        tmp.copy_from_slice(points);
        out[p] = tmp[p];
        for r in 1..=p {
            for j in (r..=p).rev() {
                lerp(tmp, j, k[span - p + j], k[span + j + 1 - r], a);
            }
            out[p - r] = tmp[p];
        }
        // 2. at b on the R's, whose knots t_J are all a: node k ends as b_k
        for r in 1..=p {
            for j in (r..=p).rev() {
                lerp(out, j, a, k[span + j + 1 - r], b);
            }
        }
    }

    /// `f` of the `p + 1` basis values on `span` at `t` ([`BSplineBasis::nonzero_into`]),
    /// kept on the stack up to degree 7: the point-by-point paths allocate nothing there.
    /// Up to degree 7 the degree is made a constant of the code (one match per call), so
    /// the triangle is unrolled and its knot reads need no bounds checks — the sparse batch
    /// paths evaluate every parameter here.
    #[inline]
    pub(crate) fn with_nonzero<D: DualNum<Primitive = f64> + Copy, R>(
        &self,
        span: usize,
        t: D,
        f: impl FnOnce(&[D]) -> R,
    ) -> R {
        by_count!(self.degree, L => self.with_nonzero_of::<D, R, L>(span, t, f), _ => {
            let mut n = vec![D::zero(); self.degree + 1];
            self.nonzero_into(span, t, &mut n);
            f(&n)
        })
    }

    /// [`BSplineBasis::with_nonzero`] for degree `L − 1` (the caller's match checked it).
    #[inline(always)]
    fn with_nonzero_of<D: DualNum<Primitive = f64> + Copy, R, const L: usize>(
        &self,
        span: usize,
        t: D,
        f: impl FnOnce(&[D]) -> R,
    ) -> R {
        let mut n = [D::zero(); L];
        if D::NDERIV == 0 {
            // plain numbers: the triangle on the span's knot window, every length a constant
            let p = L - 1;
            triangle(&self.knots.knots()[span + 1 - p..span + 1 + p], t, &mut n);
        } else {
            self.nonzero_into(span, t, &mut n);
        }
        f(&n)
    }

    /// `f(g, n)` for each of `G` parameters `ts[g]` on their spans `spans[g]`, `n` the
    /// `p + 1` basis values there: [`BSplineBasis::with_nonzero`] at `G` points at once, the
    /// triangle run on [`Lanes`] (the same operations, so the same values bit for bit), so
    /// that the points' divisions and knot loads overlap. The sparse batch paths.
    #[inline]
    pub(crate) fn with_nonzero_lanes<const G: usize>(
        &self,
        spans: &[usize; G],
        ts: &[f64; G],
        f: impl FnMut(usize, &[f64]),
    ) {
        by_count!(self.degree, L => self.lanes_of::<G, L>(spans, ts, f), _ => {
            let mut f = f;
            for (g, (&span, &t)) in spans.iter().zip(ts).enumerate() {
                self.with_nonzero(span, t, |n| f(g, n));
            }
        })
    }

    /// [`BSplineBasis::with_nonzero_lanes`] for degree `L − 1` (the caller's match checked it).
    #[inline(always)]
    fn lanes_of<const G: usize, const L: usize>(
        &self,
        spans: &[usize; G],
        ts: &[f64; G],
        mut f: impl FnMut(usize, &[f64]),
    ) {
        let p = L - 1;
        let k = self.knots.knots();
        // the knot windows t_{ℓ+1−p} … t_{ℓ+p} of the G spans, lane g holding span g's (2p
        // knots, at most 14 for the degrees `by_count!` makes constant)
        let mut w = [Lanes::<G>::splat(0.0); 14];
        for (i, wi) in w[..2 * p].iter_mut().enumerate() {
            for (x, &span) in wi.0.iter_mut().zip(spans) {
                *x = k[span + 1 - p + i];
            }
        }
        let mut n = [Lanes::<G>::splat(0.0); L];
        triangle(&w[..2 * p], Lanes(*ts), &mut n);
        for g in 0..G {
            f(g, &Lanes::lane(&n, g));
        }
    }

    /// The `p + 1` basis functions that may be non-zero on span `span`,
    /// `N_{span−p,p}(t), …, N_{span,p}(t)`, written into `out`.
    ///
    /// Generic over the number type: at a dual number `t = t₀ + δ` (`δ` its derivative part)
    /// it yields the derivatives too. Values come from the triangular scheme of *The NURBS
    /// Book* A2.2 (the slides' recurrence computed in place; no `0/0` can occur). For a dual
    /// number the derivatives `N⁽ᵏ⁾(t₀)`, `k ≤ min(p, D::NDERIV)`, come from the derivative
    /// recurrence A2.3 at the real part, and the result is the span polynomial's exact Taylor
    /// expansion `Σₖ N⁽ᵏ⁾(t₀) δᵏ / k!` (exact: `δ^{NDERIV+1} = 0`). Differentiating through
    /// the value recurrence instead would lose about `log₁₀(gap⁻¹)` digits where knots nearly
    /// coincide (knots `.5, .5 + 10⁻⁹`: 8 digits of `N″`); A2.3 divides only by knot
    /// differences of the lower-degree supports and keeps full accuracy.
    ///
    /// # Panics
    /// If `out.len() != p + 1` or `span` is not in `p ..= n`.
    pub fn nonzero_into<D: DualNum<Primitive = f64> + Copy>(
        &self,
        span: usize,
        t: D,
        out: &mut [D],
    ) {
        let p = self.degree;
        assert_eq!(out.len(), p + 1, "one slot per non-zero basis function");
        assert!(span >= p && span < self.len(), "span {span} out of range");
        let k = self.knots.knots();
        if D::NDERIV == 0 {
            // plain numbers: values only, on the span's window of 2p knots
            triangle(&k[span + 1 - p..span + 1 + p], t, out);
            return;
        }
        // the expansion point (the piece was picked by the span): any point of the span gives
        // the same polynomial. Numbers expand at t itself (the most accurate value there);
        // a traced formula at the span's start t_ℓ, so its coefficients are the exact Taylor
        // coefficients there and the piece reads in u = t − t_ℓ without cancellation
        let t0 = if crate::branch::traced() {
            k[span]
        } else {
            crate::branch::read_quietly(&t)
        };
        // the Taylor expansion stops at NDERIV: exact for dual numbers of plain numbers,
        // whose part beyond the real one is nilpotent. Under a symbolic trace the real part
        // itself is a formula in t, so the span polynomial is expanded to its full degree p
        // (exact for any t: the formula holds on the whole span, not only at t₀)
        let order = if crate::branch::traced() {
            p
        } else {
            p.min(D::NDERIV)
        };
        // derivatives with respect to z = (t − t₀)/w, w the span's width: wᵏ N⁽ᵏ⁾ stays of
        // the size of the values however narrow or wide the span, so nothing over- or
        // underflows on the way (and the value part is never touched by an overflow)
        let w = k[span + 1] - k[span];
        let ders = derivatives_on_span(k, span, p, t0, order, w);
        let z = (t - t0) / w;
        let mut factorial = vec![1.0; order + 1];
        for j in 1..=order {
            factorial[j] = factorial[j - 1] * j as f64;
        }
        for (j, slot) in out.iter_mut().enumerate() {
            // Horner in z: Σₖ (wᵏ N⁽ᵏ⁾) zᵏ / k!
            let mut acc = D::from(ders[order][j] / factorial[order]);
            for q in (0..order).rev() {
                acc = acc * z + ders[q][j] / factorial[q];
            }
            *slot = acc;
        }
    }

    /// The span holding `t` and the non-zero basis functions there (see
    /// [`BSplineBasis::nonzero_into`]).
    pub fn nonzero<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> (usize, Vec<D>) {
        let span = crate::branch::choose(&t, |x| {
            let span = self.find_span(x);
            (span, self.span_condition(span, x))
        });
        let mut out = vec![D::zero(); self.degree + 1];
        self.nonzero_into(span, t, &mut out);
        (span, out)
    }

    /// The span holding `t` and, for each of the `p + 1` basis functions that may be non-zero
    /// there, `[N(t), N′(t), N″(t)]` — one pass of [`BSplineBasis::nonzero_into`] at the
    /// second-order dual number `t + ε`, so the derivatives are exact (no difference quotient,
    /// no separate derivative recurrence).
    ///
    /// # Examples
    /// ```
    /// use splinelab::{BSplineBasis, KnotVector};
    /// // linear B-splines on (0,0,1,2,2): at t = 0.5 the slopes are −1 and +1
    /// let basis = BSplineBasis::new(KnotVector::new(vec![0., 0., 1., 2., 2.]), 1);
    /// let (span, d) = basis.nonzero_derivatives(0.5);
    /// assert_eq!(span, 1);
    /// assert_eq!(d, vec![[0.5, -1.0, 0.0], [0.5, 1.0, 0.0]]);
    /// ```
    pub fn nonzero_derivatives(&self, t: f64) -> (usize, Vec<[f64; 3]>) {
        let span = self.find_span(t);
        let d = self.unscaled_derivatives(span, t, 2);
        (
            span,
            (0..=self.degree)
                .map(|j| [d[0][j], d[1][j], d[2][j]])
                .collect(),
        )
    }

    /// `N⁽ᵏ⁾(t)`, `k ≤ order`, on `span`: the scaled derivatives `wᵏ N⁽ᵏ⁾` of
    /// [`derivatives_on_span`] multiplied `k` times by `1/w` (finite: spans are at least
    /// `f64::MIN_POSITIVE` wide), so a derivative whose true value overflows is `±∞`, never
    /// NaN, and a zero stays zero.
    fn unscaled_derivatives(&self, span: usize, t: f64, order: usize) -> Vec<Vec<f64>> {
        let k = self.knots.knots();
        let w = k[span + 1] - k[span];
        let mut d = derivatives_on_span(k, span, self.degree, t, order, w);
        let inv = 1.0 / w;
        for (q, row) in d.iter_mut().enumerate() {
            for v in row.iter_mut() {
                for _ in 0..q {
                    *v *= inv;
                }
            }
        }
        d
    }

    /// The span holding `t` and `N⁽ᵏ⁾(t)` for `k = 0 … order` of its `p + 1` non-zero
    /// functions (`result[k][j]` for `N_{span−p+j}`; zero rows for `k > p`), by the
    /// derivative recurrence of *The NURBS Book* A2.3.
    ///
    /// # Errors
    /// [`Error::TooLarge`] if `order` exceeds [`crate::error::MAX_ELEMENTS`].
    pub fn derivatives(&self, t: f64, order: usize) -> Result<(usize, Vec<Vec<f64>>)> {
        crate::error::size_product(
            "derivative rows × functions",
            order.saturating_add(1),
            self.degree + 1,
        )?;
        let span = self.find_span(t);
        Ok((span, self.unscaled_derivatives(span, t, order)))
    }

    /// All `n + 1` basis functions at `t` (zeros outside the span), by the one-pass evaluator.
    pub fn all<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> Vec<D> {
        let (span, values) = self.nonzero(t);
        let mut all = vec![D::zero(); self.len()];
        all[span - self.degree..=span].copy_from_slice(&values);
        all
    }

    /// `N_{i,q}(t)` by the Cox–de Boor recurrence as printed in seed 001,
    ///
    /// `N_{i,q}(t) = (t − tᵢ)/(t_{i+q} − tᵢ) N_{i,q−1}(t) + (t_{i+q+1} − t)/(t_{i+q+1} − t_{i+1}) N_{i+1,q−1}(t)`,
    ///
    /// with `0/0 = 0` (a term whose knot difference is zero is dropped) and the right-end rule
    /// of [`BSplineBasis`] (at `t = b` exactly, `N_{ℓ,0} = 1` on the last non-empty span
    /// only). The reference the one-pass evaluator is tested against: the recurrence is
    /// evaluated level by level (`N_{i..=i+q, 0}`, then degree 1, …), `O(q²)` and without
    /// recursion. Its derivatives at a dual number are those of the recurrence itself and lose
    /// digits where knots nearly coincide (see [`BSplineBasis::nonzero_into`]); it is a
    /// reference for values.
    ///
    /// It is written once, over [`KnotScalar`]: `f64` and every dual number (values and exact
    /// derivatives, formulas under a symbolic trace) and the exact [`crate::exact::Rational`]
    /// (the slides' fractions: `N_{1,2}(3/5) = 33/50`).
    ///
    /// # Panics
    /// If `i + q + 1` exceeds the last knot index.
    pub fn cox_de_boor<T: KnotScalar>(&self, i: usize, q: usize, t: T) -> T {
        let mut levels = self.cox_de_boor_levels(i, q, t);
        levels
            .pop()
            .map_or_else(T::zero, |mut last| last.swap_remove(0))
    }

    /// The whole Cox–de Boor triangle at `t`, as the slides build it by hand: row `d`
    /// (`0 … p`) holds `N_{0,d}(t), N_{1,d}(t), …`, every function of degree `d` on these knots
    /// (`m − 1 − d` of them for `m` knots), padded with zeros to the width of row 0. Row `p` is
    /// the basis; each row sums to one on the domain. From [`BSplineBasis::cox_de_boor_levels`].
    ///
    /// # Errors
    /// [`Error::TooLarge`] above 256 knots (the triangle is written out whole);
    /// [`Error::NonFinite`] for a NaN or infinite `t`.
    pub fn cox_de_boor_table<T: KnotScalar + nalgebra::Scalar>(
        &self,
        t: T,
    ) -> Result<nalgebra::DMatrix<T>> {
        const MAX_KNOTS: usize = 256;
        crate::error::finite("Cox–de Boor table parameter t", t.value())?;
        let m = self.knots.knots().len();
        if m > MAX_KNOTS {
            return Err(Error::TooLarge {
                what: "knots of a Cox–de Boor table",
                got: m,
                max: MAX_KNOTS,
            });
        }
        let p = self.degree;
        let levels = self.cox_de_boor_levels(0, m - 2, t);
        Ok(nalgebra::DMatrix::from_fn(p + 1, m - 1, |d, i| {
            levels[d].get(i).cloned().unwrap_or_else(T::zero)
        }))
    }

    /// Every step of [`BSplineBasis::cox_de_boor`] for `N_{i,q}(t)`: row `d` (`0 … q`) holds
    /// `N_{i,d}(t), …, N_{i+q−d,d}(t)`, the functions of degree `d` that `N_{i,q}` is built
    /// from; the last row is `[N_{i,q}(t)]`.
    ///
    /// # Panics
    /// If `i + q + 1` exceeds the last knot index.
    pub fn cox_de_boor_levels<T: KnotScalar>(&self, i: usize, q: usize, t: T) -> Vec<Vec<T>> {
        let k = self.knots.knots();
        let last = i.checked_add(q).and_then(|s| s.checked_add(1));
        assert!(
            last.is_some_and(|l| l < k.len()),
            "N_{{{i},{q}}} needs knot i + q + 1, beyond the last knot index {}",
            k.len() - 1
        );
        let b = self.domain().1;
        let end_span = self.find_span(b);
        // level 0: N_{m,0} = 1 for the one m with t_m ≤ t < t_{m+1}; at the right end b
        // exactly, the last non-empty span is closed on the right and no other N_{·,0} is 1
        // (for a clamped end the half-open rule would give all zeros; where b is repeated, an
        // empty span). The knot span of t is picked here: the formula holds there.
        let one: Option<usize> = t.locate(
            |order| {
                if order(b) == Ordering::Equal {
                    return Some(end_span);
                }
                (i..=i + q).find(|&m| order(k[m]).is_ge() && order(k[m + 1]).is_lt())
            },
            |x| self.span_condition(self.find_span(x), x),
        );
        let mut level: Vec<T> = (i..=i + q)
            .map(|m| if one == Some(m) { T::one() } else { T::zero() })
            .collect();
        let mut levels = Vec::with_capacity(q + 1);
        for d in 1..=q {
            levels.push(level.clone());
            // N_{m,d} for m = i … i + q − d from N_{m,d−1} and N_{m+1,d−1}
            for j in 0..=q - d {
                let m = i + j;
                let mut value = T::zero();
                // N / d first: where N = 0 the product is 0 even if (t − tₘ)/d would overflow
                let d1 = k[m + d] - k[m];
                if d1 > 0.0 {
                    value += t.minus_knot(k[m]) * level[j].over(d1);
                }
                let d2 = k[m + d + 1] - k[m + 1];
                if d2 > 0.0 {
                    value += t.knot_minus(k[m + d + 1]) * level[j + 1].over(d2);
                }
                level[j] = value;
            }
            level.truncate(q - d + 1);
        }
        levels.push(level);
        levels
    }
}

/// `unitᵏ N⁽ᵏ⁾(t)` for `k = 0 … order` of the `p + 1` functions that may be non-zero on span
/// `ℓ` (`ders[k][j]` for `N_{ℓ−p+j,p}`): the derivatives with respect to `z = t / unit`, by
/// *The NURBS Book* A2.3 (`DersBasisFuns`). The triangle of A2.2 keeps the lower-degree
/// values `N_{·,p−k}` and the knot differences, and the `k`-th derivative is
/// `p!/(p−k)! Σⱼ a_{k,j} N_{·,p−k}` with the coefficients `a_{k,j}` formed by differences
/// divided by knot spans of the lower-degree supports — here by those spans measured in
/// units of `unit`. With `unit` the width of span `ℓ`, every such span is at least one
/// unit long (each support contains span `ℓ`), so the coefficients stay below `2ᵏ` and
/// nothing overflows, however close the knots. Knot differences are taken directly from the
/// knots (not as sums of `t − tᵢ` terms). Rows `k > p` are zero.
fn derivatives_on_span(
    k: &[f64],
    span: usize,
    p: usize,
    t: f64,
    order: usize,
    unit: f64,
) -> Vec<Vec<f64>> {
    // ndu[j][r], r ≤ j: lower triangle holds knot differences, upper (r > j ... ) basis values:
    // ndu[r][j] = N_{ℓ−j+r, j}(t) for r ≤ j, ndu[j][r] = t_{ℓ+r+1} − t_{ℓ+1+r−j} for r < j
    let mut ndu = vec![vec![0.0; p + 1]; p + 1];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        let mut saved = 0.0;
        for r in 0..j {
            let right = k[span + r + 1] - t;
            let left = t - k[span + 1 + r - j];
            ndu[j][r] = k[span + r + 1] - k[span + 1 + r - j];
            let temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right * temp;
            saved = left * temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = vec![vec![0.0; p + 1]; order + 1];
    for (j, d) in ders[0].iter_mut().enumerate() {
        *d = ndu[j][p];
    }
    let top = order.min(p);
    let mut a = [vec![0.0; p + 1], vec![0.0; p + 1]];
    for r in 0..=p {
        let (mut s1, mut s2) = (0, 1);
        a[0][0] = 1.0;
        for kk in 1..=top {
            let mut d = 0.0;
            let rk = r as isize - kk as isize;
            let pk = p - kk;
            // a knot span of the lower-degree support, in units
            let gap = |idx: usize| ndu[pk + 1][idx] / unit;
            if r >= kk {
                let rk = rk as usize;
                a[s2][0] = a[s1][0] / gap(rk);
                d = a[s2][0] * ndu[rk][pk];
            }
            let j1: usize = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2: usize = if r <= pk + 1 { kk - 1 } else { p - r };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / gap(idx);
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][kk] = -a[s1][kk - 1] / gap(r);
                d += a[s2][kk] * ndu[r][pk];
            }
            ders[kk][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    // multiply by p!/(p−k)!
    let mut factor = p as f64;
    for (kk, row) in ders.iter_mut().enumerate().take(top + 1).skip(1) {
        for v in row.iter_mut() {
            *v *= factor;
        }
        factor *= (p - kk) as f64;
    }
    ders
}

/// The triangular scheme of *The NURBS Book* A2.2 on span `ℓ` for degree `p = out.len() − 1`:
/// the non-zero `N_{ℓ−p,p}(t) … N_{ℓ,p}(t)` into `out`, from the span's knot window
/// `w = t_{ℓ+1−p} … t_{ℓ+p}` (`2p` knots, `t_{ℓ+i} = w[p − 1 + i]`). With `out`'s length a
/// constant of the caller the loops unroll and every index is known to be in bounds.
///
/// Generic over the number `D` and the knots `K`: plain and dual numbers on `f64` knots, and
/// [`Lanes`] of parameters on lanes of knots (several points, each on its own span, at once).
#[inline(always)]
fn triangle<D, K>(w: &[K], t: D, out: &mut [D])
where
    K: Copy + Sub<Output = K>,
    f64: Div<K, Output = K>,
    D: Copy + Zero + One + Neg<Output = D> + Add<K, Output = D> + Sub<K, Output = D>,
    D: Mul<K, Output = D>,
{
    let p = out.len() - 1;
    let w = &w[..2 * p];
    out[0] = D::one();
    for j in 1..=p {
        let mut saved = D::zero();
        for r in 0..j {
            // right = t_{ℓ+r+1} − t, left = t − t_{ℓ+1−j+r}; their sum is the knot difference
            // t_{ℓ+r+1} − t_{ℓ+1−j+r} ≥ t_{ℓ+1} − t_ℓ > 0 on a non-empty span: no 0/0
            let (hi, lo) = (w[p + r], w[p + r - j]);
            let temp = out[r] * (1.0 / (hi - lo));
            out[r] = saved + temp * (-t + hi);
            saved = temp * (t - lo);
        }
        out[j] = saved;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The galloping span search is `find_span`, from every hint, at every knot, between
    /// knots, outside the domain and at NaN, on knots with repeats and empty spans.
    #[test]
    fn find_span_near_is_find_span_from_every_hint() {
        for p in 0..=3usize {
            let mut k = vec![0.0; p + 1];
            k.extend([0.5, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 3.0, 3.5]);
            k.extend(vec![4.0; p + 1]);
            let Ok(knots) = KnotVector::try_new(k.clone()) else {
                continue;
            };
            let Ok(basis) = BSplineBasis::try_new(knots, p) else {
                continue;
            };
            let mut ts: Vec<f64> = (-4..=36).map(|i| i as f64 * 0.125).collect();
            ts.extend(k.iter().flat_map(|&x| [x, x.next_up(), x.next_down()]));
            ts.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
            for &t in &ts {
                let want = basis.find_span(t);
                for hint in 0..k.len() + 3 {
                    assert_eq!(
                        basis.find_span_near(hint, t),
                        want,
                        "p {p}, t {t}, hint {hint}"
                    );
                }
            }
        }
    }

    #[test]
    fn spans_are_never_empty() {
        // degree 2 with a = 0 repeated at t₂ … t₄: the span [t₂, t₃) is empty
        let basis = BSplineBasis::new(KnotVector::new(vec![-1.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0]), 2);
        let k = basis.knots().knots();
        for t in [-0.5, 0.0, 0.5, 1.0, 2.0, 2.5] {
            let s = basis.find_span(t);
            assert!(k[s] < k[s + 1], "t = {t}: empty span {s}");
            assert!(basis.all(t).iter().all(|v| v.is_finite()), "t = {t}");
        }
        assert_eq!(basis.find_span(0.0), 3);
        assert_eq!(
            basis.find_span(-0.5),
            3,
            "extrapolates the first non-empty span"
        );
        assert_eq!(
            basis.find_span(2.0),
            3,
            "the right end b = t₄ … belongs to the last span"
        );
    }
}
