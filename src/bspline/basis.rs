//! The B-spline basis `N_{i,p}` on a knot vector: Cox–de Boor as the reference and the
//! one-pass evaluator of all non-zero functions (seed 001, "Base B-spline").

use crate::bspline::knots::KnotVector;
use crate::error::{Error, Result};
use num_dual::{Dual2_64, DualNum};

/// The normalised B-spline basis `{N_{i,p}}`, `i = 0 … n`, of degree `p` (order `m = p + 1`) on a
/// knot vector `t₀ ≤ … ≤ t_{n+p+1}` (0-based; the slides count from 1).
///
/// Valid when the knot vector has at least `2(p + 1)` knots, no knot of multiplicity above
/// `p + 1`, and a non-empty domain `[a, b] = [t_p, t_{n+1}]`, where the functions sum to 1.
///
/// Conventions (seed 001): `N_{i,0}(t) = 1` on `[tᵢ, tᵢ₊₁)`, else 0, and `0/0 = 0` in the
/// Cox–de Boor recurrence. The right end `t = b` belongs to the last non-empty span (the
/// half-open rule alone would give all zeros there).
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
    /// [`Error::TooFewKnots`] for fewer than `2(p + 1)` knots; [`Error::MultiplicityTooHigh`]
    /// for a knot repeated more than `p + 1` times; [`Error::EmptyInterval`] if the domain
    /// `[t_p, t_{n+1}]` is empty.
    pub fn try_new(knots: KnotVector, degree: usize) -> Result<Self> {
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

    /// The span `ℓ` with `t_ℓ ≤ t < t_{ℓ+1}`, `p ≤ ℓ ≤ n`, holding `t` (*The NURBS Book* A2.1).
    /// The right end `b` belongs to the last span; points outside `[a, b]` go to the nearest
    /// end span (evaluation there extrapolates that span's polynomial).
    pub fn find_span(&self, t: f64) -> usize {
        let k = self.knots.knots();
        let n = self.len() - 1;
        // the last ℓ in [p, n] with t_ℓ ≤ t: a non-empty span, since t_{ℓ+1} > t_ℓ unless
        // ℓ = p (t below the domain or at a), and t_n < t_{n+1} = b because no knot repeats
        // more than p + 1 times
        let span = self.degree + k[self.degree + 1..=n].partition_point(|&x| x <= t);
        // left of an empty first span (a knot of multiplicity p + 1 at a = t_{p+1}, with
        // t_p = a too): move to the first non-empty one
        (span..=n).find(|&s| k[s] < k[s + 1]).unwrap_or(span)
    }

    /// The `p + 1` basis functions that may be non-zero on span `span`,
    /// `N_{span−p,p}(t), …, N_{span,p}(t)`, written into `out` (*The NURBS Book* A2.2: the
    /// triangular scheme of the slides computed in place, no `0/0` can occur).
    ///
    /// Generic over the number type: at a dual number `t + ε` it yields the derivatives too.
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
        // the same scheme for every degree; a constant degree lets the compiler unroll it
        match p {
            1 => triangle(k, span, 1, t, out),
            2 => triangle(k, span, 2, t, out),
            3 => triangle(k, span, 3, t, out),
            _ => triangle(k, span, p, t, out),
        }
    }

    /// The span holding `t` and the non-zero basis functions there (see
    /// [`BSplineBasis::nonzero_into`]).
    pub fn nonzero<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> (usize, Vec<D>) {
        let span = self.find_span(t.re());
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
        let (span, n) = self.nonzero(Dual2_64::from_re(t).derivative());
        (span, n.into_iter().map(|d| [d.re, d.v1, d.v2]).collect())
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
    /// of [`BSplineBasis`]. Exponential in `q`: the reference the fast evaluator is tested
    /// against, not for production use.
    ///
    /// # Panics
    /// If `i + q + 1` exceeds the last knot index.
    pub fn cox_de_boor<D: DualNum<Primitive = f64> + Copy>(&self, i: usize, q: usize, t: D) -> D {
        let k = self.knots.knots();
        assert!(
            i + q + 1 < k.len(),
            "N_{{{i},{q}}} needs knot {}",
            i + q + 1
        );
        if q == 0 {
            let x = t.re();
            let b = self.domain().1;
            // At the right end b exactly, the last non-empty span is closed on the right and no
            // other N_{i,0} is 1 (for a clamped end the half-open rule would give all zeros;
            // for an unclamped one it would pick the span [b, t_{n+2}) outside the domain).
            let one = if x.total_cmp(&b).is_eq() {
                i == self.find_span(b)
            } else {
                k[i] <= x && x < k[i + 1]
            };
            return if one { D::one() } else { D::zero() };
        }
        let mut value = D::zero();
        let d1 = k[i + q] - k[i];
        if d1 > 0.0 {
            value += (t - k[i]) / d1 * self.cox_de_boor(i, q - 1, t);
        }
        let d2 = k[i + q + 1] - k[i + 1];
        if d2 > 0.0 {
            value += (-t + k[i + q + 1]) / d2 * self.cox_de_boor(i + 1, q - 1, t);
        }
        value
    }
}

/// The triangular scheme of *The NURBS Book* A2.2 on span `ℓ = span` for degree `p`: the
/// non-zero `N_{ℓ−p,p}(t) … N_{ℓ,p}(t)` into `out`.
#[inline(always)]
fn triangle<D: DualNum<Primitive = f64> + Copy>(
    k: &[f64],
    span: usize,
    p: usize,
    t: D,
    out: &mut [D],
) {
    out[0] = D::one();
    for j in 1..=p {
        let mut saved = D::zero();
        for r in 0..j {
            // right = t_{ℓ+r+1} − t, left = t − t_{ℓ+1−j+r}; their sum is the knot difference
            // t_{ℓ+r+1} − t_{ℓ+1−j+r} ≥ t_{ℓ+1} − t_ℓ > 0 on a non-empty span: no 0/0
            let temp = out[r] * (1.0 / (k[span + r + 1] - k[span + 1 + r - j]));
            let right = -t + k[span + r + 1];
            let left = t - k[span + 1 + r - j];
            out[r] = saved + temp * right;
            saved = temp * left;
        }
        out[j] = saved;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
