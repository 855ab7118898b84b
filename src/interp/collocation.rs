//! Spline interpolation by collocation: solve for the control points of a B-spline so that it
//! passes through given data (seed 001, "Theorem: spline function interpolation" and "Curve
//! spline di interpolazione").

use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::KnotVector;
use crate::curve::{check_domain, ParametricCurve};
use crate::error::finite_points;
use crate::error::{finite, Error, Result};
use crate::interp::check_sites;
use crate::interp::cubic::{check_spline_data, EndCondition};
use crate::param::Parametrization;
use nalgebra::{DMatrix, DVector, SVector};

/// Which derivative a linear condition constrains.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DerivativeOrder {
    /// `s(x)`.
    Value,
    /// `s′(x)`.
    First,
    /// `s″(x)`.
    Second,
}

/// An extra linear condition `Σₖ cₖ s⁽ʳ⁾(xₖ) = value` on the spline (end conditions such as
/// `s′(x₀) = y′₀`, or `s″(x₀) − s″(x_n) = 0`).
#[derive(Debug, Clone, PartialEq)]
pub struct Condition<const N: usize> {
    /// The derivative order `r`.
    pub order: DerivativeOrder,
    /// The terms `(xₖ, cₖ)`.
    pub terms: Vec<(f64, f64)>,
    /// The right-hand side.
    pub value: SVector<f64, N>,
}

/// The value, first or second derivative of every basis function at `x` (zeros outside the
/// span), exact ([`BSplineBasis::nonzero_derivatives`]).
fn basis_row(basis: &BSplineBasis, x: f64, order: DerivativeOrder) -> Vec<f64> {
    let k = match order {
        DerivativeOrder::Value => 0,
        DerivativeOrder::First => 1,
        DerivativeOrder::Second => 2,
    };
    let (span, d) = basis.nonzero_derivatives(x);
    let mut row = vec![0.0; basis.len()];
    for (slot, v) in row[span - basis.degree()..=span].iter_mut().zip(d) {
        *slot = v[k];
    }
    row
}

/// The B-spline on `basis` with `s(xᵢ) = yᵢ` at the sites and the extra `conditions`: the
/// collocation system `Σⱼ cⱼ Nⱼ(xᵢ) = yᵢ` (plus one row per condition) solved for the control
/// points `cⱼ`, all coordinates at once (dense LU, O(n³): a reference and a teaching tool).
///
/// Without extra conditions this is the slides' theorem (Schoenberg–Whitney): with as many
/// sites as basis functions, sorted, the system has a unique solution if and only if
/// `Nⱼ(xⱼ) ≠ 0` for every `j` (each site lies in the support of "its" basis function; de Boor,
/// *A Practical Guide to Splines*, XIII). That condition is checked first and reported.
///
/// Each row is divided by its largest entry before the solve (row equilibration: derivative
/// rows scale like `h⁻ʳ`, and a tiny end interval would otherwise dominate the pivoting), and
/// the solution is checked by its backward error, which follows the problem's conditioning:
/// every row `i` of the equilibrated system must hold within
/// [`crate::interp::RESIDUAL_TOLERANCE`] of `max((|A| |c|)ᵢ + |bᵢ|, s)`, `s` the data scale
/// `max(max |yᵢ|, max |bᵢ|)`. A backward-stable solve (LU with partial pivoting, without
/// growth) leaves about `n ε` of `(|A| |c|)ᵢ`, however ill-conditioned the system: the curve
/// is then the exact solution of a system within `10⁻¹⁰` of the given one, row by row, and
/// its miss at the data is at most that much of the terms it sums (on knots `10⁻⁸` apart a
/// natural or clamped cubic misses its data by about `10⁻⁹` of their size, as scipy's
/// does). A larger residual — a solve that went wrong — is refused. The curve is then checked
/// where it matters, on itself: at every site it meets its value within
/// [`COLLOCATION_MISS`] of the data's size, else [`Error::IllConditioned`] (the backward
/// error alone lets huge control points miss the data by O(1)).
///
/// # Errors
/// [`Error::CountMismatch`] unless sites + conditions = basis functions and values match
/// sites; [`Error::NonFinite`]; [`Error::RepeatedParameter`] / [`Error::NotIncreasing`] for
/// unsorted sites; [`Error::OutOfDomain`] for a site or condition abscissa outside the
/// basis domain; [`Error::SchoenbergWhitney`] if the condition fails (no extra conditions);
/// [`Error::SingularSystem`] if the system is singular; [`Error::IllConditioned`] if the
/// solution's backward error exceeds the tolerance (the solve did not deliver it).
pub fn interpolate<const N: usize>(
    basis: BSplineBasis,
    sites: &[f64],
    values: &[SVector<f64, N>],
    conditions: &[Condition<N>],
) -> Result<BSplineCurve<N>> {
    check_collocation(&basis, sites, values, conditions)?;
    let size = basis.len();
    let mut a = DMatrix::<f64>::zeros(size, size);
    let mut rhs: Vec<SVector<f64, N>> = Vec::with_capacity(size);
    for (i, (&x, y)) in sites.iter().zip(values).enumerate() {
        a.row_mut(i)
            .copy_from_slice(&basis_row(&basis, x, DerivativeOrder::Value));
        rhs.push(*y);
    }
    for (k, c) in conditions.iter().enumerate() {
        let row = sites.len() + k;
        for &(x, w) in &c.terms {
            for (j, v) in basis_row(&basis, x, c.order).into_iter().enumerate() {
                a[(row, j)] += w * v;
            }
        }
        rhs.push(c.value);
    }
    let singular = || Error::SingularSystem {
        what: "collocation system",
    };
    // row equilibration: each row divided by its largest entry
    for (i, b) in rhs.iter_mut().enumerate() {
        let big = a.row(i).amax();
        let big = crate::error::derived("collocation row entry", big)?;
        if big == 0.0 {
            return Err(singular());
        }
        a.row_mut(i).scale_mut(1.0 / big);
        *b /= big;
        crate::error::derived_points("equilibrated collocation right-hand side", &[*b])?;
    }
    let lu = a.clone().lu();
    let mut points = vec![SVector::<f64, N>::zeros(); size];
    for d in 0..N {
        let b = DVector::from_fn(size, |i, _| rhs[i][d]);
        let x = lu.solve(&b).ok_or_else(singular)?;
        if x.iter().any(|v| !v.is_finite()) {
            return Err(singular());
        }
        for (p, v) in points.iter_mut().zip(x.iter()) {
            p[d] = *v;
        }
    }
    // the residual of every row, relative to what a backward-stable solve leaves there
    // (module docs): |rᵢ| against (|A| |c|)ᵢ + |bᵢ|, or the data scale if that is larger
    let scale = crate::horner::max_norm(values).max(crate::horner::max_norm(&rhs));
    let mut worst: f64 = 0.0;
    for i in 0..size {
        let (got, size_i) = (0..size).fold((SVector::<f64, N>::zeros(), 0.0f64), |acc, j| {
            (
                acc.0 + points[j] * a[(i, j)],
                acc.1 + a[(i, j)].abs() * points[j].amax(),
            )
        });
        let r = (got - rhs[i]).amax();
        let reach = (size_i + rhs[i].amax()).max(scale);
        let relative = if reach > 0.0 { r / reach } else { r };
        worst = if relative.is_nan() {
            relative
        } else {
            worst.max(relative)
        };
    }
    crate::interp::accept_residual("B-spline collocation", worst)?;
    let curve = BSplineCurve::try_new(basis, points)?;
    // the backward error bounds the miss by the size of the terms the curve sums, which is
    // no bound when the control points are huge: the curve itself must meet its data
    let mut miss: f64 = 0.0;
    for (&x, y) in sites.iter().zip(values) {
        let m = (curve.point(x) - y).amax();
        miss = if m.is_nan() { m } else { miss.max(m) };
    }
    // the values' size; with every value 0, the conditions' (in value units)
    let data = crate::horner::max_norm(values);
    let data = if data > 0.0 { data } else { scale };
    let relative = if data > 0.0 { miss / data } else { miss };
    if relative.is_nan() || relative > COLLOCATION_MISS {
        return Err(Error::IllConditioned {
            what: "B-spline collocation (the curve at its sites)",
            residual: relative,
            tolerance: COLLOCATION_MISS,
        });
    }
    Ok(curve)
}

/// The checks of [`interpolate`]'s input (its errors but the solve's).
fn check_collocation<const N: usize>(
    basis: &BSplineBasis,
    sites: &[f64],
    values: &[SVector<f64, N>],
    conditions: &[Condition<N>],
) -> Result<()> {
    if sites.len() != values.len() {
        return Err(Error::CountMismatch {
            what: "values (one per site)",
            expected: sites.len(),
            got: values.len(),
        });
    }
    let size = basis.len();
    if sites.len() + conditions.len() != size {
        return Err(Error::CountMismatch {
            what: "sites + conditions (one per basis function)",
            expected: size,
            got: sites.len() + conditions.len(),
        });
    }
    crate::error::size_product("collocation matrix entries", size, size)?;
    check_sites("collocation sites", sites)?;
    let domain = basis.domain();
    for &x in sites {
        check_domain("collocation site", x, domain)?;
    }
    finite_points("collocation value", values)?;
    for c in conditions {
        for &(x, w) in &c.terms {
            check_domain("condition site", x, domain)?;
            finite("condition coefficient", w)?;
        }
        finite_points("condition value", &[c.value])?;
    }
    if conditions.is_empty() {
        schoenberg_whitney(basis, sites)?;
    }
    Ok(())
}

/// The most an `Ok` collocation curve misses its data, evaluated on the curve itself at the
/// sites, relative to `max |yᵢ|` (when every value is 0, to the data scale of the
/// equilibrated system, `max |bᵢ|`: derivative conditions in value units): `10⁻⁸`. A backward-stable solve of an ill-conditioned but solvable system (knots `10⁻⁸`
/// apart beside unit intervals) misses by about `10⁻⁹`; a near-singular one solved with
/// control points of `10¹⁶` misses by the data's own size, and is refused.
pub const COLLOCATION_MISS: f64 = 1e-8;

/// Checks `Nⱼ(xⱼ) ≠ 0` for every `j` (sorted sites in the domain, one per basis function).
///
/// # Errors
/// [`Error::CountMismatch`] unless there is one site per basis function; the site checks of
/// [`interpolate`] ([`Error::NonFinite`], [`Error::RepeatedParameter`],
/// [`Error::NotIncreasing`], [`Error::OutOfDomain`]); [`Error::SchoenbergWhitney`] naming
/// the first `j` that fails.
pub fn schoenberg_whitney(basis: &BSplineBasis, sites: &[f64]) -> Result<()> {
    if sites.len() != basis.len() {
        return Err(Error::CountMismatch {
            what: "Schoenberg–Whitney sites (one per basis function)",
            expected: basis.len(),
            got: sites.len(),
        });
    }
    check_sites("Schoenberg–Whitney sites", sites)?;
    let domain = basis.domain();
    for &x in sites {
        check_domain("Schoenberg–Whitney site", x, domain)?;
    }
    let k = basis.knots().knots();
    let p = basis.degree();
    for (j, &x) in sites.iter().enumerate() {
        let (span, n) = basis.nonzero(x);
        let value = if j + p >= span && j <= span {
            n[j + p - span]
        } else {
            0.0
        };
        if value <= 0.0 {
            return Err(Error::SchoenbergWhitney {
                index: j,
                site: x,
                support_start: k[j],
                support_end: k[j + basis.degree() + 1],
            });
        }
    }
    Ok(())
}

/// The interpolating cubic spline by the B-spline route, independent of the tridiagonal one
/// of [`crate::interp::cubic::CubicSpline`]: knots `x₀` (×4), `x₁ … x_{n−1}`, `x_n` (×4) — the slides'
/// "nodes of the spline coincide with the interpolation points", leaving two degrees of
/// freedom — and the two end conditions as extra rows (`s′` or `s″` at the ends from the
/// exact basis derivatives).
///
/// # Errors
/// As [`interpolate`]; [`Error::TooFewPoints`] below 2 points (3 for periodic and anticyclic);
/// [`Error::PeriodicEndsMismatch`] for periodic data with `y₀ ≠ y_n`.
pub fn cubic_spline<const N: usize>(
    x: &[f64],
    y: &[SVector<f64, N>],
    end: EndCondition<N>,
) -> Result<BSplineCurve<N>> {
    check_spline_data(x, y, &end)?;
    let (a, b) = (x[0], x[x.len() - 1]);
    let mut knots = vec![a; 4];
    knots.extend_from_slice(&x[1..x.len() - 1]);
    knots.extend([b; 4]);
    let basis = BSplineBasis::try_new(KnotVector::try_new(knots)?, 3)?;
    use DerivativeOrder::{First, Second};
    let zero = SVector::<f64, N>::zeros();
    // s⁽ʳ⁾(at) = value at one end
    let at = |order, at: f64, value| Condition {
        order,
        terms: vec![(at, 1.0)],
        value,
    };
    // s⁽ʳ⁾(a) − σ s⁽ʳ⁾(b) = 0: σ = +1 periodic, −1 anticyclic
    let link = |order, sigma: f64| Condition {
        order,
        terms: vec![(a, 1.0), (b, -sigma)],
        value: zero,
    };
    let conditions = match end {
        EndCondition::Clamped { start, end } => vec![at(First, a, start), at(First, b, end)],
        EndCondition::Natural => vec![at(Second, a, zero), at(Second, b, zero)],
        EndCondition::Periodic | EndCondition::Cyclic => {
            vec![link(First, 1.0), link(Second, 1.0)]
        }
        EndCondition::Anticyclic => vec![link(First, -1.0), link(Second, -1.0)],
    };
    interpolate(basis, x, y, &conditions)
}

/// The interpolating B-spline curve of degree `degree` through `points` (seed 001, last
/// slide: parameters first, then the collocation system for the control points `Q_j`).
/// Parameters by `param`; clamped knots by averaging, `t_{j+p} = (u_j + … + u_{j+p−1})/p`
/// (*The NURBS Book* eq. 9.8), which always satisfies the Schoenberg–Whitney condition.
///
/// # Errors
/// [`Error::DegreeTooLow`] for degree 0; [`Error::TooFewPoints`] for fewer than
/// `degree + 1` points; errors of `param` and of [`interpolate`].
pub fn interpolate_curve<const N: usize>(
    points: &[SVector<f64, N>],
    degree: usize,
    param: Parametrization,
) -> Result<BSplineCurve<N>> {
    if degree == 0 {
        return Err(Error::DegreeTooLow { min: 1, got: 0 });
    }
    if points.len() <= degree {
        return Err(Error::TooFewPoints {
            what: "points for the interpolating curve",
            needed: degree.saturating_add(1),
            got: points.len(),
        });
    }
    let u = param.parameters(points)?;
    let n = points.len() - 1;
    let mut knots = vec![0.0; degree + 1];
    for j in 1..=n.saturating_sub(degree) {
        knots.push(u[j..j + degree].iter().sum::<f64>() / degree as f64);
    }
    knots.extend(std::iter::repeat_n(1.0, degree + 1));
    let basis = BSplineBasis::try_new(KnotVector::try_new(knots)?, degree)?;
    interpolate(basis, &u, points, &[])
}
