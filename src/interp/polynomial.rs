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
    check_sites("interpolation nodes", x)?;
    for &v in y {
        finite("interpolation value", v)?;
    }
    Ok(())
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
    /// # Errors
    /// As the data checks ([`Error::CountMismatch`], [`Error::TooFewPoints`],
    /// [`Error::NonFinite`], [`Error::RepeatedParameter`], [`Error::NotIncreasing`]);
    /// [`Error::SingularSystem`] if the factorisation breaks down numerically.
    pub fn interpolate(x: &[f64], y: &[f64]) -> Result<Self> {
        check_data(x, y)?;
        let v = vandermonde(x);
        let a = v
            .lu()
            .solve(&DVector::from_column_slice(y))
            .ok_or(Error::SingularSystem {
                what: "Vandermonde system",
            })?;
        if a.iter().any(|c| !c.is_finite()) {
            return Err(Error::SingularSystem {
                what: "Vandermonde system",
            });
        }
        Ok(Self {
            coeffs: a.iter().copied().collect(),
        })
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
fn vandermonde(x: &[f64]) -> DMatrix<f64> {
    DMatrix::from_fn(x.len(), x.len(), |i, j| x[i].powi(j as i32))
}

/// The 2-norm condition number of the Vandermonde matrix of `x` (ratio of extreme singular
/// values): how many digits the power-basis solve may lose (`log₁₀ κ`). `None` when the
/// smallest singular value is at or below rounding (`σ_min ≤ ε σ_max`): the matrix is
/// numerically singular and its condition number cannot be measured in `f64`.
pub fn vandermonde_condition(x: &[f64]) -> Option<f64> {
    let s = vandermonde(x).singular_values();
    let (max, min) = (s.max(), s.min());
    (min > f64::EPSILON * max).then(|| max / min)
}

/// The interpolating polynomial in Lagrange form (seed 001),
/// `p(t) = Σᵢ yᵢ ℓᵢ(t)`, `ℓᵢ(t) = Πⱼ≠ᵢ (t − tⱼ)/(tᵢ − tⱼ)`:
/// no linear system, so no Vandermonde conditioning; O(n²) per evaluation.
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
    y: Vec<f64>,
    /// `1 / Πⱼ≠ᵢ (tᵢ − tⱼ)`, the denominators of the `ℓᵢ`.
    inv_denominators: Vec<f64>,
}

impl Lagrange {
    /// The interpolant through `(xᵢ, yᵢ)`.
    ///
    /// # Errors
    /// As [`PowerPolynomial::interpolate`]'s data checks.
    pub fn try_new(x: &[f64], y: &[f64]) -> Result<Self> {
        check_data(x, y)?;
        let inv_denominators = (0..x.len())
            .map(|i| {
                let d: f64 = (0..x.len())
                    .filter(|&j| j != i)
                    .map(|j| x[i] - x[j])
                    .product();
                1.0 / d
            })
            .collect();
        Ok(Self {
            x: x.to_vec(),
            y: y.to_vec(),
            inv_denominators,
        })
    }

    /// The nodes.
    pub fn nodes(&self) -> &[f64] {
        &self.x
    }

    /// `ℓᵢ(t)` for every `i`, for any number type.
    pub fn basis<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> Vec<D> {
        (0..self.x.len())
            .map(|i| {
                let num = (0..self.x.len())
                    .filter(|&j| j != i)
                    .fold(D::one(), |acc, j| acc * (t - self.x[j]));
                num * self.inv_denominators[i]
            })
            .collect()
    }

    /// `p(t) = Σ yᵢ ℓᵢ(t)`.
    pub fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> D {
        self.basis(t)
            .into_iter()
            .zip(&self.y)
            .fold(D::zero(), |acc, (l, &y)| acc + l * y)
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
    /// A short label.
    pub fn label(self) -> &'static str {
        match self {
            NodeFamily::Equispaced => "equispaced",
            NodeFamily::Chebyshev => "Chebyshev",
        }
    }

    /// The `degree + 1` nodes on `[a, b]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] or [`Error::EmptyInterval`] for a bad interval.
    pub fn nodes(self, a: f64, b: f64, degree: usize) -> Result<Vec<f64>> {
        crate::domain::Interval::named("node interval", a, b)?;
        let n = degree as f64;
        Ok(match self {
            NodeFamily::Equispaced if degree == 0 => vec![0.5 * (a + b)],
            NodeFamily::Equispaced => crate::domain::linspace(a, b, degree + 1),
            NodeFamily::Chebyshev => (0..=degree)
                .map(|i| {
                    let angle = (2.0 * i as f64 + 1.0) * std::f64::consts::PI / (2.0 * n + 2.0);
                    0.5 * (a + b) - 0.5 * (b - a) * angle.cos()
                })
                .collect(),
        })
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
/// [`Error::TooFewSamples`] if `samples < 2`; errors of the node construction.
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
    Ok(crate::domain::linspace(a, b, samples)
        .into_iter()
        .map(|t| (p.eval(t) - f(t)).abs())
        .fold(0.0, f64::max))
}
