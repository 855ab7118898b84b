//! B-spline curves `C(t) = Σᵢ Pᵢ N_{i,p}(t)` in any dimension (seed 001, "Curva spline").

use crate::bspline::basis::BSplineBasis;
use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use crate::horner;
use crate::lanes::SPARSE_BLOCK;
use nalgebra::SVector;
use num_dual::DualNum;

/// A B-spline curve of degree `p` in `ℝᴺ`: `C(t) = Σᵢ Pᵢ N_{i,p}(t)` on the domain
/// `[t_p, t_{n+1}]` of its basis (seed 001; *The NURBS Book* A3.1).
///
/// Generic over the dimension (`N = 1` for spline functions, 2 and 3 for curves) and, in
/// [`BSplineCurve::eval`], over the number type: at `t + ε` ([`num_dual::Dual64`]) it gives the tangent,
/// at a second-order dual number ([`num_dual::Dual2_64`]) the second derivative, both exact.
///
/// The curve is `C^{p−mⱼ}` at a knot of multiplicity `mⱼ` (the slides' `C^{m−mⱼ−1}` with order
/// `m = p + 1`); moving `Pᵢ` changes it only on `[tᵢ, t_{i+p+1})`.
///
/// # Examples
/// ```
/// use nalgebra::Vector2;
/// use splinelab::{BSplineBasis, BSplineCurve, KnotVector, ParametricCurve};
/// let basis = BSplineBasis::new(KnotVector::open_uniform(2, 3, 0.0, 1.0).unwrap(), 2);
/// let pts = vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0), Vector2::new(2.0, 0.0)];
/// let c = BSplineCurve::new(basis, pts);
/// assert_eq!(c.point(0.5), Vector2::new(1.0, 1.0)); // a quadratic Bézier
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<const N: usize> {
    basis: BSplineBasis,
    points: Vec<SVector<f64, N>>,
}

impl<const N: usize> BSplineCurve<N> {
    /// The curve with control points `points` on `basis`.
    ///
    /// # Panics
    /// On invalid input; see [`BSplineCurve::try_new`].
    pub fn new(basis: BSplineBasis, points: Vec<SVector<f64, N>>) -> Self {
        Self::try_new(basis, points).expect("invalid B-spline curve")
    }

    /// The curve with control points `points` on `basis`.
    ///
    /// # Errors
    /// [`Error::CountMismatch`] unless there is one control point per basis function
    /// (knots − order); [`Error::NonFinite`] for a NaN or infinite coordinate.
    pub fn try_new(basis: BSplineBasis, points: Vec<SVector<f64, N>>) -> Result<Self> {
        if points.len() != basis.len() {
            return Err(Error::CountMismatch {
                what: "control points (knots − order)",
                expected: basis.len(),
                got: points.len(),
            });
        }
        finite_points("control point coordinate", &points)?;
        Ok(Self { basis, points })
    }

    /// The basis.
    pub fn basis(&self) -> &BSplineBasis {
        &self.basis
    }

    /// The control points.
    pub fn points(&self) -> &[SVector<f64, N>] {
        &self.points
    }

    /// A copy with control point `index` replaced.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] for a bad index; [`Error::NonFinite`] for a NaN or infinite
    /// coordinate.
    pub fn with_point(&self, index: usize, point: SVector<f64, N>) -> Result<Self> {
        if index >= self.points.len() {
            return Err(Error::IndexOutOfRange {
                what: "control point",
                index,
                len: self.points.len(),
            });
        }
        let mut points = self.points.clone();
        points[index] = point;
        Self::try_new(self.basis.clone(), points)
    }

    /// `Σ_{i=ℓ−p}^{ℓ} Pᵢ Nᵢ` for the `p + 1` non-zero basis values `n` of span `ℓ`.
    #[inline]
    fn combine<D: DualNum<Primitive = f64> + Copy>(&self, span: usize, n: &[D]) -> SVector<D, N> {
        // from n's length, so that a length known to the caller's code is known here too
        let first = span + 1 - n.len();
        n.iter()
            .zip(&self.points[first..=span])
            .fold(SVector::zeros(), |acc, (&w, p)| acc + p.map(D::from) * w)
    }

    /// Evaluates at every parameter of `ts` into `out` (replacing its contents), by the same formula as
    /// [`ParametricCurve::eval`]. The span search starts from the previous span, so sorted
    /// parameters cost a comparison or two each. Each span's polynomial is formed once, at any
    /// degree: its Bézier points by blossoming (`BSplineBasis::span_bezier`, convex
    /// combinations of the control points), then its power form in the scaled variable
    /// `s = (t − t_ℓ)/w` of the span (`w` its width) by forward differences; every point then
    /// costs `p` multiply-adds per coordinate (Horner's rule in `s²` on pairs of
    /// coefficients; up to degree 7 the loop is unrolled at compile time). From 65 536 parameters the two halves of `ts` are
    /// evaluated on two threads (a span's power form depends on the span alone, so the values
    /// are the same on one core or two).
    ///
    /// In the scaled variable the coefficients are of the size of the control points however
    /// narrow or wide the span, and the power form is used only where it is as accurate as the
    /// basis form: finite coefficients with `Σₖ ‖c̃ₖ‖ ≤ 256 · max ‖Pᵢ‖` over the span's control
    /// points (the evaluation's error is then at most `(p + 2) · 256 ε · max ‖Pᵢ‖`,
    /// `1.4e-13 · max ‖Pᵢ‖` at degree 3, `2.6e-13` at degree 7); elsewhere (wild control points at high degree,
    /// overflowing coefficients) the span is evaluated point by point as
    /// [`ParametricCurve::eval`] does. Above degree 32 no power form is made (see
    /// `horner::MAX_POWER_DEGREE`). A span's form is made each time at least four parameters
    /// in a row fall in it; sparse or unsorted parameters are evaluated point by point (the
    /// basis on the stack, no allocation), eight at a time side by side once a sparse run is
    /// met (their spans found first, then their basis triangles computed together): the same
    /// operations as [`ParametricCurve::eval`], so the same values bit for bit.
    pub fn eval_many(&self, ts: &[f64], out: &mut Vec<SVector<f64, N>>) {
        horner::by_degree!(self.basis.degree(), [N], self.eval_many_with(ts, out))
    }

    /// [`BSplineCurve::eval_many`] with the power forms stored in `C`.
    fn eval_many_with<C: horner::Coefficients<N>>(
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
                let points = &self.points[span - p..=span];
                let c: C = self.basis.span_power(span, points)?;
                horner::safe(c.as_ref(), horner::max_norm(points)).then_some(c)
            },
            |c, s| horner::eval(c.as_ref(), s),
            (
                |span, n| self.combine(span, n),
                |spans| read_ahead(&self.points, p, spans),
            ),
        );
    }
}

impl<const N: usize> ParametricCurve<N> for BSplineCurve<N> {
    /// `Σ Pᵢ N_{i,p}(t)` over the span of `t` (end spans extrapolated outside the domain).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> SVector<D, N> {
        let (span, n) = self.basis.nonzero(t);
        self.combine(span, &n)
    }

    fn domain(&self) -> (f64, f64) {
        self.basis.domain()
    }

    /// The knot span of `t` ([`BSplineBasis::span_of`]).
    fn span_at(&self, t: f64) -> Option<crate::domain::Span> {
        Some(self.basis.span_of(t))
    }
}

/// Parameters from which [`walk_spans`] splits a batch between two threads (below, a thread
/// costs more than it saves).
pub(crate) const EVAL_PARALLEL_MIN: usize = 1 << 16;

/// Parameters from which a *sparse* batch — fewer than [`FORM_MIN_RUN`] parameters per
/// span on average — is split between two threads ([`two_threads`]).
pub(crate) const SPARSE_PARALLEL_MIN: usize = 1 << 13;

/// Whether a batch of `queries` parameters on a curve of `pieces` spans is worth two
/// threads: from [`EVAL_PARALLEL_MIN`] parameters, or from [`SPARSE_PARALLEL_MIN`] when they
/// are sparse (fewer than [`FORM_MIN_RUN`] per span on average), where each costs a
/// point-by-point evaluation (about 20 ns at degree 3, measured) instead of a Horner step.
pub(crate) fn two_threads(queries: usize, pieces: usize) -> bool {
    let sparse = pieces.saturating_mul(FORM_MIN_RUN) > queries;
    queries
        >= if sparse {
            SPARSE_PARALLEL_MIN
        } else {
            EVAL_PARALLEL_MIN
        }
}

/// Reads the first and last control point of each of `spans` (degree `p`) before their basis
/// values are computed, so that their cache misses overlap with that work instead of stalling
/// the sums that need them (nothing is kept).
#[inline(always)]
pub(crate) fn read_ahead<const N: usize>(points: &[SVector<f64, N>], p: usize, spans: &[usize]) {
    let sum: f64 = spans
        .iter()
        .map(|&s| points[s - p].sum() + points[s].sum())
        .sum();
    std::hint::black_box(sum);
}

/// The fewest parameters in a span for which [`walk_spans`] forms the span's fast form;
/// shorter runs (sparse or unsorted parameters) are evaluated point by point, which costs
/// less than a form (its blossoming and power conversion are `O(p²)` per coordinate).
pub(crate) const FORM_MIN_RUN: usize = 4;

/// Evaluates a piecewise-polynomial object on a B-spline basis at every parameter of `ts`
/// into `out` (resized to `ts.len()`, former contents overwritten; `zero` fills new slots
/// before they are written): `piece(ℓ)` forms span `ℓ`'s data once per run of at least
/// [`FORM_MIN_RUN`] parameters in it (shorter runs are evaluated by `direct`), and `at(piece, (t − t_ℓ)/w)` evaluates each
/// point; where `piece` declines (`None`: its fast form would lose accuracy), each point is
/// `combine(ℓ, n)` of the span's basis values `n` at it — one at a time, or for a sparse
/// block [`SPARSE_BLOCK`] at a time on lanes (the same values bit for bit), after
/// `read_ahead(spans)` has read what the block's spans will need. From [`EVAL_PARALLEL_MIN`] parameters ([`SPARSE_PARALLEL_MIN`] for
/// sparse ones, [`two_threads`]) the two halves of `ts` are
/// walked on two threads; a span's data depend on the span alone, so the values are the
/// same whatever the split.
pub(crate) fn walk_spans<T: Copy + Send, P>(
    basis: &BSplineBasis,
    ts: &[f64],
    out: &mut Vec<T>,
    zero: T,
    piece: impl Fn(usize) -> Option<P> + Sync,
    at: impl Fn(&P, f64) -> T + Sync,
    (combine, read_ahead): (impl Fn(usize, &[f64]) -> T + Sync, impl Fn(&[usize]) + Sync),
) {
    let parallel = two_threads(ts.len(), basis.len() - basis.degree());
    crate::parallel::fill_halves(ts, out, zero, parallel, |ts, out| {
        walk_part(basis, ts, out, &piece, &at, &combine, &read_ahead)
    });
}

/// [`walk_spans`] on one thread, writing `out[i]` for `ts[i]`.
fn walk_part<T, P>(
    basis: &BSplineBasis,
    ts: &[f64],
    out: &mut [T],
    piece: &impl Fn(usize) -> Option<P>,
    at: &impl Fn(&P, f64) -> T,
    combine: &impl Fn(usize, &[f64]) -> T,
    read_ahead: &impl Fn(&[usize]),
) {
    // one point on its span, as `ParametricCurve::eval` evaluates it
    let direct = |span: usize, t: f64| basis.with_nonzero(span, t, |n| combine(span, n));
    let mut cursor = SpanCursor::new(basis);
    let mut data = None;
    // the span whose fast form `data` holds (formed lazily: only for runs long enough)
    let mut formed: Option<usize> = None;
    let mut i = 0;
    while i < ts.len() {
        cursor.advance(ts[i]);
        // the run of parameters that stay in this span (at least ts[i], which may be the
        // right end b or outside the domain), evaluated in one branch-free loop
        let (lo, hi) = (cursor.start(), cursor.hi);
        let run = 1 + ts[i + 1..]
            .iter()
            .position(|&t| !(lo <= t && t < hi))
            .unwrap_or(ts.len() - i - 1);
        let (chunk, slots) = (&ts[i..i + run], &mut out[i..i + run]);
        i += run;
        if run < FORM_MIN_RUN && formed != Some(cursor.span()) {
            // a few parameters in a span (sparse or unsorted ones): point by point, the
            // form would cost more than it saves; the next parameters likely too, so a block
            // of them is taken at once — their spans first, then their points in a loop
            // without branches between them, so that the processor overlaps independent
            // points (their divisions, their cache misses) instead of waiting on each
            let span = cursor.span();
            for (o, &t) in slots.iter_mut().zip(chunk) {
                *o = direct(span, t);
            }
            let len = SPARSE_BLOCK.min(ts.len() - i);
            if len == 0 {
                continue;
            }
            // a short last block repeats its last parameter (evaluated, not written)
            let (mut spans, mut params) = ([0usize; SPARSE_BLOCK], [ts[i + len - 1]; SPARSE_BLOCK]);
            params[..len].copy_from_slice(&ts[i..i + len]);
            for (s, &t) in spans.iter_mut().zip(&params) {
                cursor.advance(t);
                *s = cursor.span();
            }
            read_ahead(&spans);
            let slots = &mut out[i..i + len];
            basis.with_nonzero_lanes(&spans, &params, |g, n| {
                if let Some(o) = slots.get_mut(g) {
                    *o = combine(spans[g], n);
                }
            });
            i += len;
            continue;
        }
        if formed != Some(cursor.span()) {
            data = piece(cursor.span());
            formed = Some(cursor.span());
        }
        match &data {
            // only the run's first parameter can lie outside the span (beyond the domain's
            // ends, or its right end): there the power form would be extrapolated far from
            // where its accuracy holds (|s| ≫ 1 multiplies its rounding by |s|ᵖ), so it is
            // evaluated as `ParametricCurve::eval` does — batch and single agree everywhere
            Some(d) => {
                let first = usize::from(!(lo <= chunk[0] && chunk[0] <= hi));
                // finite: knot gaps are at least f64::MIN_POSITIVE
                let inv = 1.0 / (hi - lo);
                if first == 1 {
                    slots[0] = fallback(&direct, cursor.span(), chunk[0]);
                }
                for (o, &t) in slots[first..].iter_mut().zip(&chunk[first..]) {
                    *o = at(d, (t - lo) * inv);
                }
            }
            None => {
                for (o, &t) in slots.iter_mut().zip(chunk) {
                    *o = fallback(&direct, cursor.span(), t);
                }
            }
        }
    }
}

/// The point-by-point evaluation of a span the fast path declined, kept out of line so that
/// the fast loop stays small.
#[inline(never)]
fn fallback<T>(direct: &impl Fn(usize, f64) -> T, span: usize, t: f64) -> T {
    direct(span, t)
}

/// Walks a sequence of parameters span by span: each search gallops
/// ([`BSplineBasis::find_span_near`]) from the uniform guess of the span while it proves
/// near, else from the previous span (as [`crate::domain::IntervalCursor`]); any order stays
/// correct.
struct SpanCursor<'a> {
    basis: &'a BSplineBasis,
    /// The uniform guess of a parameter's span (offset by the degree), trusted while it
    /// proves near ([`crate::domain::IntervalCursor`]'s rule).
    guess: crate::domain::UniformGuess,
    span: usize,
    lo: f64,
    hi: f64,
}

impl<'a> SpanCursor<'a> {
    /// A cursor on the first span of the domain.
    fn new(basis: &'a BSplineBasis) -> Self {
        let (a, b) = basis.domain();
        let spans = basis.len() - basis.degree();
        let mut cursor = Self {
            basis,
            guess: crate::domain::UniformGuess::new(a, b, spans),
            span: 0,
            lo: 0.0,
            hi: 0.0,
        };
        cursor.enter(basis.find_span(basis.domain().0));
        cursor
    }

    fn enter(&mut self, span: usize) {
        let k = self.basis.knots().knots();
        self.span = span;
        self.lo = k[span];
        self.hi = k[span + 1];
    }

    /// The current span `ℓ`.
    fn span(&self) -> usize {
        self.span
    }

    /// The knot `t_ℓ` where the current span starts.
    fn start(&self) -> f64 {
        self.lo
    }

    /// Moves to the span of `t` (as [`BSplineBasis::find_span`]).
    #[inline]
    fn advance(&mut self, t: f64) {
        // inside the current span's half-open interval: unchanged (the right end b and points
        // outside the domain go through find_span, which applies the end rules)
        if self.lo <= t && t < self.hi {
            return;
        }
        // the next span (sorted parameters, one or a few per span): non-empty, since
        // t_{ℓ+1} = hi ≤ t < t_{ℓ+2}
        let k = self.basis.knots().knots();
        if self.span < self.basis.len() - 1 && self.hi <= t && t < k[self.span + 2] {
            self.enter(self.span + 1);
            return;
        }
        let p = self.basis.degree();
        let (basis, previous) = (self.basis, self.span);
        let span = self
            .guess
            .search(t, p, previous, |hint| basis.find_span_near(hint, t));
        if span != self.span {
            self.enter(span);
        }
    }
}
