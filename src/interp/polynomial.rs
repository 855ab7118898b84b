//! Polynomial interpolation: power basis with the Vandermonde system, Lagrange form, Runge's
//! phenomenon (seed 001, "Interpolazione polinomiale", "Il fenomeno di Runge").

use crate::error::{finite, Error, Result};
use crate::interp::check_sites;
use nalgebra::{DMatrix, DVector};
use num_dual::DualNum;

/// Checks interpolation data: equal lengths, at least one point, finite, distinct nodes (the
/// uniqueness theorem of seed 001 needs `tᵢ ≠ tⱼ`; here they must also be increasing).
fn check_data(x: &[f64], y: &[f64]) -> Result<()> {
    if x.len() != y.len() {
        return Err(Error::CountMismatch {
            what: "values (one per node)",
            expected: x.len(),
            got: y.len(),
        });
    }
    if x.is_empty() {
        return Err(Error::TooFewPoints {
            what: "interpolation nodes",
            needed: 1,
            got: 0,
        });
    }
    // the O(n²) work and storage of both forms
    crate::error::size_product("interpolation nodes squared", x.len(), x.len())?;
    check_sites("interpolation nodes", x)?;
    for &v in y {
        crate::error::coordinate("interpolation value", v)?;
    }
    Ok(())
}

/// The largest residual `max |p(xᵢ) − yᵢ|` of an interpolant relative to the data scale
/// `max |yᵢ|` (absolute when all data are 0), checked against
/// [`crate::interp::RESIDUAL_TOLERANCE`].
///
/// # Errors
/// [`Error::IllConditioned`] above the tolerance or for a non-finite residual.
fn check_residual(what: &'static str, x: &[f64], y: &[f64], p: impl Fn(f64) -> f64) -> Result<()> {
    let scale = y.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
    let residual = crate::interp::relative_residual(
        x.iter().zip(y).map(|(&xi, &yi)| (p(xi) - yi).abs()),
        scale,
    );
    crate::interp::accept_residual(what, residual)
}

/// A polynomial in the power basis, `p(t) = Σⱼ aⱼ tʲ`.
#[derive(Debug, Clone, PartialEq)]
pub struct PowerPolynomial {
    coeffs: Vec<f64>,
}

impl PowerPolynomial {
    /// The interpolating polynomial of degree `≤ n` through `n + 1` points, from the
    /// Vandermonde system `V a = y`, `V_{ij} = tᵢʲ` (seed 001), solved by LU with partial
    /// pivoting (nalgebra). The matrix is notoriously ill-conditioned for many equispaced
    /// nodes (its condition number grows exponentially with the degree): see
    /// [`vandermonde_condition`] and prefer [`Lagrange`] for evaluation.
    ///
    /// The result is checked: `p(xᵢ)` (Horner) must reproduce every `yᵢ` within
    /// [`crate::interp::RESIDUAL_TOLERANCE`] of `max |yᵢ|`, else the system was too
    /// ill-conditioned for `f64` and no polynomial is returned.
    ///
    /// # Errors
    /// As the data checks ([`Error::CountMismatch`], [`Error::TooFewPoints`],
    /// [`Error::NonFinite`], [`Error::RepeatedParameter`], [`Error::NotIncreasing`],
    /// [`Error::TooLarge`] beyond `√MAX_ELEMENTS` nodes); [`Error::Overflow`] if a power
    /// `xᵢʲ` overflows; [`Error::SingularSystem`] if the factorisation breaks down
    /// numerically; [`Error::IllConditioned`] if the solution misses the data.
    pub fn interpolate(x: &[f64], y: &[f64]) -> Result<Self> {
        check_data(x, y)?;
        let v = vandermonde(x)?;
        let singular = || Error::SingularSystem {
            what: "Vandermonde system",
        };
        let a = v
            .lu()
            .solve(&DVector::from_column_slice(y))
            .ok_or_else(singular)?;
        if a.iter().any(|c| !c.is_finite()) {
            return Err(singular());
        }
        let p = Self {
            coeffs: a.iter().copied().collect(),
        };
        check_residual("Vandermonde interpolation", x, y, |t| p.eval(t))?;
        Ok(p)
    }

    /// The coefficients `a₀ … a_n`.
    pub fn coefficients(&self) -> &[f64] {
        &self.coeffs
    }

    /// `p(t)` by Horner's rule, for any number type.
    pub fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> D {
        self.coeffs
            .iter()
            .rev()
            .fold(D::zero(), |acc, &c| acc * t + c)
    }
}

/// The Vandermonde matrix `V_{ij} = xᵢʲ`, `j = 0 … n`.
///
/// # Errors
/// [`Error::Overflow`] if a power overflows.
fn vandermonde(x: &[f64]) -> Result<DMatrix<f64>> {
    let n = x.len();
    let mut v = DMatrix::zeros(n, n);
    for (i, &xi) in x.iter().enumerate() {
        let mut power = 1.0;
        for j in 0..n {
            v[(i, j)] = crate::error::derived("Vandermonde entry xᵢʲ", power)?;
            power *= xi;
        }
    }
    Ok(v)
}

/// The 2-norm condition number of the Vandermonde matrix of `x` (ratio of extreme singular
/// values): how many digits the power-basis solve may lose (`log₁₀ κ`). `Ok(None)` when the
/// smallest singular value is at or below rounding (`σ_min ≤ ε σ_max`): the matrix is
/// numerically singular and its condition number cannot be measured in `f64`.
///
/// # Errors
/// [`Error::NonFinite`] for a NaN or infinite node; [`Error::TooLarge`] beyond
/// `√MAX_ELEMENTS` nodes; [`Error::Overflow`] if a power `xᵢʲ` overflows;
/// [`Error::NoConvergence`] if the bounded SVD does not converge.
pub fn vandermonde_condition(x: &[f64]) -> Result<Option<f64>> {
    crate::error::size_product("Vandermonde nodes squared", x.len(), x.len())?;
    for &v in x {
        finite("Vandermonde node", v)?;
    }
    if x.is_empty() {
        return Ok(None);
    }
    let s = crate::metrics::surface::singular_values(&vandermonde(x)?)?;
    let max = crate::error::derived("largest singular value of the Vandermonde matrix", s.max())?;
    let min = s.min();
    Ok((min > f64::EPSILON * max).then(|| max / min))
}

/// The interpolating polynomial in Lagrange form (seed 001),
/// `p(t) = Σᵢ yᵢ ℓᵢ(t)`, `ℓᵢ(t) = Πⱼ≠ᵢ (t − tⱼ)/(tᵢ − tⱼ)`:
/// no linear system, so no Vandermonde conditioning.
///
/// Evaluated in the barycentric form (Berrut and Trefethen, *Barycentric Lagrange
/// interpolation*, SIAM Review 46, 2004), `p(t) = Σᵢ λᵢ yᵢ / Σᵢ λᵢ` with
/// `λᵢ = wᵢ/(t − tᵢ)` and the weights `wᵢ = 1/Πⱼ≠ᵢ (tᵢ − tⱼ)` formed from their logarithms
/// and scaled so that `max |wᵢ| = 1`: the products over many nodes never overflow (150
/// nodes on `[0, 1000]` have `Π |tᵢ − tⱼ| ≈ 10⁴⁰⁰`). Numerator and denominator are multiplied
/// by `t − t_k` for the node `t_k` nearest to `t`, so `λ_k = w_k` and every other `|λᵢ| ≤ |wᵢ|`:
/// no division by zero at a node (where `p(t_k) = y_k` exactly), for plain and dual numbers
/// alike, and O(n) per evaluation.
///
/// # Examples
/// ```
/// use splinelab::Lagrange;
/// let p = Lagrange::try_new(&[0.0, 1.0, 2.0], &[1.0, 3.0, 7.0]).unwrap(); // t² + t + 1
/// assert!((p.eval(3.0_f64) - 13.0).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Lagrange {
    x: Vec<f64>,
    /// `yᵢ / s` with `s = max |yᵢ|` (or 1), so that the sums stay below 1 per term.
    y: Vec<f64>,
    /// The data scale `s`.
    scale: f64,
    /// Barycentric weights scaled to `max |wᵢ| = 1`.
    w: Vec<f64>,
    /// `ln max |wᵢ|` of the unscaled weights (for the first barycentric form).
    log_top: f64,
}

impl Lagrange {
    /// The interpolant through `(xᵢ, yᵢ)`.
    ///
    /// # Errors
    /// As [`PowerPolynomial::interpolate`]'s data checks; [`Error::Overflow`] if the ratio of
    /// the largest to the smallest barycentric weight exceeds the `f64` range (more than about
    /// 1 000 equispaced nodes: such an interpolant is meaningless in `f64`).
    pub fn try_new(x: &[f64], y: &[f64]) -> Result<Self> {
        check_data(x, y)?;
        let n = x.len();
        // log |wᵢ| = −Σⱼ≠ᵢ ln |tᵢ − tⱼ|; sign (−1)^{#j > i} for increasing nodes
        let logs: Vec<f64> = (0..n)
            .map(|i| {
                -(0..n)
                    .filter(|&j| j != i)
                    .map(|j| (x[i] - x[j]).abs().ln())
                    .sum::<f64>()
            })
            .collect();
        let top = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let mut w = Vec::with_capacity(n);
        for (i, &l) in logs.iter().enumerate() {
            let magnitude = (l - top).exp();
            if magnitude.is_nan() || magnitude < f64::MIN_POSITIVE {
                return Err(Error::Overflow {
                    what: "ratio of the largest to the smallest barycentric weight",
                    value: (top - l).exp(),
                });
            }
            w.push(if (n - 1 - i).is_multiple_of(2) {
                magnitude
            } else {
                -magnitude
            });
        }
        let s = y.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
        let scale = if s > 0.0 { s } else { 1.0 };
        let p = Self {
            x: x.to_vec(),
            y: y.iter().map(|v| v / scale).collect(),
            scale,
            w,
            log_top: top,
        };
        check_residual("Lagrange interpolation", x, y, |t| p.eval(t))?;
        Ok(p)
    }

    /// The nodes.
    pub fn nodes(&self) -> &[f64] {
        &self.x
    }

    /// The index of the node nearest to `x`.
    fn nearest(&self, x: f64) -> usize {
        (0..self.x.len())
            .min_by(|&a, &b| (self.x[a] - x).abs().total_cmp(&(self.x[b] - x).abs()))
            .unwrap_or(0)
    }

    /// The scaled barycentric terms `λᵢ` at `t` (see [`Lagrange`]): `ℓᵢ(t) = λᵢ / Σⱼ λⱼ`.
    fn lambdas<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> Vec<D> {
        // the nearest node only steadies the rounding: every choice gives the same polynomial
        let k = self.nearest(crate::branch::read_quietly(&t));
        let near = t - self.x[k];
        (0..self.x.len())
            .map(|i| {
                if i == k {
                    D::from(self.w[k])
                } else {
                    near * self.w[i] / (t - self.x[i])
                }
            })
            .collect()
    }

    /// `ℓᵢ(t)` for every `i`, for any number type.
    pub fn basis<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> Vec<D> {
        let l = self.lambdas(t);
        let total = l.iter().fold(D::zero(), |acc, &v| acc + v).recip();
        l.into_iter().map(|v| v * total).collect()
    }

    /// `p(t) = Σ yᵢ ℓᵢ(t)`: the second barycentric form; where its denominator `Σ λᵢ` has
    /// cancelled by more than 8 digits (extreme node geometry, where the second form is not
    /// stable) the first form instead (`Lagrange::first_form`, backward stable, Higham
    /// 2004).
    pub fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> D {
        let l = self.lambdas(t);
        let (num, den, size) = l.iter().zip(&self.y).fold(
            (D::zero(), D::zero(), 0.0),
            |(num, den, size), (&v, &y)| {
                (
                    num + v * y,
                    den + v,
                    size + crate::branch::read_quietly(&v).abs(),
                )
            },
        );
        // the two barycentric forms are one polynomial: the choice is for rounding only
        let d = crate::branch::read_quietly(&den);
        if d.is_finite() && d.abs() > 1e-8 * size {
            num / den * self.scale
        } else {
            self.first_form(t)
        }
    }

    /// The first (modified Lagrange) barycentric form,
    /// `p(t) = ℓ(t) Σᵢ wᵢ yᵢ / (t − tᵢ)`, `ℓ(t) = Πⱼ (t − tⱼ)`, written around the nearest node
    /// `t_k` as `e^{ln W} ℓ_{≠k}(t) [w_k y_k + (t − t_k) Σ_{i≠k} wᵢ yᵢ / (t − tᵢ)]` (scaled
    /// weights `wᵢ`, `W = max` of the unscaled ones), with the magnitude of
    /// `W ℓ_{≠k}(t)` formed from logarithms so that it neither overflows nor underflows
    /// before it is applied (saturated at `f64::MAX`, where the interpolant itself overflows).
    fn first_form<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> D {
        let x0 = crate::branch::read_quietly(&t);
        let k = self.nearest(x0);
        let near = t - self.x[k];
        let mut bracket = D::from(self.w[k] * self.y[k]);
        let mut sum = D::zero();
        let mut unit = D::one(); // Π_{j≠k} (t − tⱼ)/|x₀ − tⱼ|, of size 1
        let mut log = self.log_top;
        for (j, &xj) in self.x.iter().enumerate() {
            if j == k {
                continue;
            }
            let diff = t - xj;
            sum += diff.recip() * (self.w[j] * self.y[j]);
            let magnitude = (x0 - xj).abs();
            unit *= diff / magnitude;
            log += magnitude.ln();
        }
        bracket += near * sum;
        let factor = log.exp().min(f64::MAX);
        // left to right: a zero bracket stays zero, never 0 · ∞
        bracket * unit * factor * self.scale
    }
}

/// Where interpolation nodes are placed on `[a, b]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NodeFamily {
    /// `a + i (b − a)/n`, `i = 0 … n` (seed 001's Runge example).
    Equispaced,
    /// Chebyshev points of the first kind, `(a + b)/2 − (b − a)/2 · cos((2i + 1)π / (2n + 2))`,
    /// in increasing order: they minimise `max |Π(t − tᵢ)|` and keep the interpolant of a
    /// smooth function convergent (Trefethen, *Approximation Theory and Approximation
    /// Practice*, ch. 8 and 13).
    Chebyshev,
}

impl NodeFamily {
    /// The `degree + 1` nodes on `[a, b]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`], [`Error::EmptyInterval`], [`Error::Overflow`] or
    /// [`Error::GapTooSmall`] for a bad interval; [`Error::TooLarge`] if `degree + 1` exceeds
    /// [`crate::error::MAX_ELEMENTS`]; [`Error::RepeatedParameter`] or [`Error::GapTooSmall`]
    /// if the nodes are not distinct in `f64` (more nodes than the interval resolves).
    pub fn nodes(self, a: f64, b: f64, degree: usize) -> Result<Vec<f64>> {
        crate::error::size_sum("interpolation nodes (degree + 1)", degree, 1)?;
        crate::domain::Interval::named("node interval", a, b)?;
        let n = degree as f64;
        let nodes = match self {
            NodeFamily::Equispaced if degree == 0 => vec![0.5 * (a + b)],
            NodeFamily::Equispaced => crate::domain::linspace(a, b, degree + 1),
            NodeFamily::Chebyshev => (0..=degree)
                .map(|i| {
                    let angle = (2.0 * i as f64 + 1.0) * std::f64::consts::PI / (2.0 * n + 2.0);
                    0.5 * (a + b) - 0.5 * (b - a) * angle.cos()
                })
                .collect(),
        };
        check_sites(
            "interpolation nodes (too many for the interval's width at f64 resolution)",
            &nodes,
        )?;
        Ok(nodes)
    }
}

/// Runge's function `f(x) = 1 / (1 + x²)` (seed 001: on `[−5, 5]`), for any number type.
pub fn runge<D: DualNum<Primitive = f64> + Copy>(x: D) -> D {
    (x * x + 1.0).recip()
}

/// The interval of seed 001's Runge example.
pub const RUNGE_INTERVAL: (f64, f64) = (-5.0, 5.0);

/// `max |p(x) − f(x)|` over `samples` equispaced points of `[a, b]` (ends included) for the
/// interpolant `p` of `f` of degree `degree` on `family` nodes (Lagrange form).
///
/// # Errors
/// [`Error::TooFewSamples`] if `samples < 2`; errors of the node construction and of
/// [`Lagrange::try_new`]; [`Error::Overflow`] if `f` or the interpolant is NaN or infinite at
/// a sample (an error measure never drops NaN).
pub fn max_interpolation_error(
    f: impl Fn(f64) -> f64,
    (a, b): (f64, f64),
    degree: usize,
    family: NodeFamily,
    samples: usize,
) -> Result<f64> {
    crate::error::samples("error samples", samples)?;
    let x = family.nodes(a, b, degree)?;
    let y: Vec<f64> = x.iter().map(|&t| f(t)).collect();
    let p = Lagrange::try_new(&x, &y)?;
    let mut worst: f64 = 0.0;
    for t in crate::domain::linspace(a, b, samples) {
        worst = worst.max(crate::error::derived(
            "interpolation error |p − f| at a sample",
            (p.eval(t) - f(t)).abs(),
        )?);
    }
    Ok(worst)
}
