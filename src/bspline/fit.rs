//! B-spline curves of order `k` on Rogers & Adams' open uniform knots (seed 004 §1.4), and a
//! least-squares fit of the control polygon to a dense shape — the stand-in for the paper's
//! hand-placed control points (spec decision A10).
//!
//! **Order and knots.** With `n + 1` vertices and order `k` (degree `k − 1`,
//! `2 ≤ k ≤ n + 1`) the knots are `k` zeros, `1, 2, …, n − k + 1`, then `k` copies of
//! `n − k + 2`: the curve passes through the first and last vertices only, is the control
//! polygon itself at `k = 2` and the Bézier curve of the polygon at `k = n + 1`.
//!
//! **Fit.** Given samples `Q₀ … Q_{m−1}` of a shape, the first and last vertices are fixed at
//! the shape's ends (`P₀ = Q₀`, `P_n = Q_{m−1}`; a closed shape has `Q_{m−1} = Q₀`, so
//! the polygon closes on itself, "first vertex = last" as the paper draws closed figures), and
//! the inner vertices minimise `Σⱼ ‖C(tⱼ) − Qⱼ‖²` — a linear least-squares problem in
//! `P₁ … P_{n−1}`, solved by QR (Givens rotations, row by row: a row has a few non-zeros), its
//! conditioning read from the singular values of the triangular factor (those of the system). The parameters start at normalised chord length and are
//! then re-projected: each `tⱼ` moves by Newton steps on `(C(t) − Qⱼ)·C′(t) = 0` to the
//! nearest point of the current curve (Hoschek's parameter correction), and the control points
//! are solved again minimising the squared distance to each foot point's tangent line plus
//! `w = 0.001` times the tangential part (the tangent-distance minimisation of Wang, Pottmann
//! & Liu 2006, damped: plain parameter correction stalls, the pure tangent distance can
//! diverge). Every step keeps the best polygon found, so the reported distance never grows.

use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::KnotVector;
use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use nalgebra::{DMatrix, SVector};

impl<const N: usize> BSplineCurve<N> {
    /// The B-spline of order `order` (degree `order − 1`) with control polygon `points` on
    /// Rogers & Adams' open uniform knots `0 … 0, 1, 2, …, n − k + 1, n − k + 2 … n − k + 2`
    /// (module docs; domain `[0, n − k + 2]`).
    ///
    /// # Errors
    /// [`Error::DegreeTooLow`] for `order < 2`; [`Error::TooFewPoints`] if `order` exceeds the
    /// number of points; [`Error::NonFinite`] or [`Error::CoordinateTooLarge`] for a point;
    /// the errors of [`KnotVector::open_uniform`].
    pub fn with_order(points: Vec<SVector<f64, N>>, order: usize) -> Result<Self> {
        if order < 2 {
            return Err(Error::DegreeTooLow { min: 2, got: order });
        }
        crate::error::size("B-spline control points", points.len())?;
        if points.len() < order {
            return Err(Error::TooFewPoints {
                what: "control points for this B-spline order",
                needed: order,
                got: points.len(),
            });
        }
        finite_points("B-spline control point", &points)?;
        let degree = order - 1;
        let spans = (points.len() - degree) as f64;
        let knots = KnotVector::open_uniform(degree, points.len(), 0.0, spans)?;
        Self::try_new(BSplineBasis::try_new(knots, degree)?, points)
    }
}

/// A least-squares B-spline fit (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineFit<const N: usize> {
    /// The fitted curve (order and vertex count as asked).
    pub curve: BSplineCurve<N>,
    /// `max ‖C(tⱼ) − Qⱼ‖` at the final parameters: how far the samples are from the curve.
    pub max_distance: f64,
    /// Parameter corrections done.
    pub iterations: usize,
}

/// Fits a B-spline of order `order` with `count` vertices to the samples `shape` (module
/// docs), with at most `corrections` parameter corrections.
///
/// # Errors
/// [`Error::TooFewPoints`] for fewer than 2 samples or fewer samples than vertices;
/// [`Error::DegreeTooLow`] / [`Error::TooFewPoints`] for an order outside `2 ..= count`;
/// [`Error::NonFinite`] or [`Error::CoordinateTooLarge`] for a sample;
/// [`Error::RepeatedPoint`] for consecutive equal samples (no chord-length parameters);
/// [`Error::TooLarge`] if `samples × vertices` exceeds [`crate::error::MAX_ELEMENTS`];
/// [`Error::IllConditioned`] if the samples do not determine every vertex (a basis function
/// with no sample in its support) or the solve is not finite.
pub fn fit_bspline<const N: usize>(
    shape: &[SVector<f64, N>],
    count: usize,
    order: usize,
    corrections: usize,
) -> Result<BSplineFit<N>> {
    crate::error::size("fit samples", shape.len())?;
    if shape.len() < 2 || shape.len() < count {
        return Err(Error::TooFewPoints {
            what: "shape samples for the fit (at least the vertex count)",
            needed: count.max(2),
            got: shape.len(),
        });
    }
    // the dense system is (N · samples) × (N · vertices)
    crate::error::size_product(
        "fit matrix (samples × vertices × dimension²)",
        shape.len().saturating_mul(N),
        count.saturating_mul(N),
    )?;
    finite_points("fit sample", shape)?;
    // fit in units of the largest coordinate (the fit commutes with scaling), so no squared
    // distance overflows or underflows
    let unit = shape.iter().map(|p| p.amax()).fold(0.0, f64::max);
    let unit = if unit > 0.0 { unit } else { 1.0 };
    let scaled: Vec<SVector<f64, N>> = shape.iter().map(|p| p / unit).collect();
    let ends = (shape[0], shape[shape.len() - 1]);
    let shape = &scaled[..];
    // a first polygon to fix the knots and the order checks: the shape's ends and samples
    let initial: Vec<SVector<f64, N>> = (0..count.max(1))
        .map(|i| shape[(i * (shape.len() - 1)) / (count.max(2) - 1)])
        .collect();
    let template = BSplineCurve::with_order(initial, order)?;
    let (a, b) = template.domain();
    let mut t: Vec<f64> = crate::param::Parametrization::ChordLength
        .parameters(shape)?
        .into_iter()
        .map(|u| a + (b - a) * u)
        .collect();
    let mut current = solve_polygon(&template, shape, &t, None)?;
    let mut best = (current.clone(), distance(&current, shape, &t));
    let mut done = 0;
    let mut stalled = 0;
    while done < corrections && stalled < STALL {
        t = t
            .iter()
            .zip(shape)
            .map(|(&t0, q)| project(&current, q, t0, (a, b)))
            .collect();
        let tangents: Vec<SVector<f64, N>> = t
            .iter()
            .map(|&tj| {
                let d = current.derivative(tj);
                let len = d.norm();
                if len > 0.0 && len.is_finite() {
                    d / len
                } else {
                    SVector::zeros()
                }
            })
            .collect();
        // the distance of the samples to the curve they were projected on
        let projected = distance(&current, shape, &t);
        if projected < best.1 * (1.0 - 1e-9) {
            best = (current.clone(), projected);
            stalled = 0;
        } else {
            stalled += 1;
        }
        current = solve_polygon(&template, shape, &t, Some(&tangents))?;
        done += 1;
    }
    let last = t
        .iter()
        .zip(shape)
        .map(|(&t0, q)| project(&current, q, t0, (a, b)))
        .collect::<Vec<f64>>();
    let final_distance = distance(&current, shape, &last);
    if final_distance < best.1 {
        best = (current, final_distance);
    }
    let (best, best_distance) = best;
    let mut points: Vec<SVector<f64, N>> = best.points().iter().map(|p| p * unit).collect();
    let n = points.len();
    (points[0], points[n - 1]) = ends; // exactly, not through the scaling
    crate::error::derived_points("fitted B-spline vertex", &points)?;
    finite_points("fitted B-spline vertex", &points)?;
    Ok(BSplineFit {
        curve: BSplineCurve::try_new(best.basis().clone(), points)?,
        max_distance: crate::error::derived("fit distance", best_distance * unit)?,
        iterations: done,
    })
}

/// `max ‖C(tⱼ) − Qⱼ‖`.
fn distance<const N: usize>(c: &BSplineCurve<N>, shape: &[SVector<f64, N>], t: &[f64]) -> f64 {
    t.iter()
        .zip(shape)
        .map(|(&tj, q)| (c.point(tj) - q).norm())
        .fold(0.0, f64::max)
}

/// The parameter of the point of `c` nearest to `q`, by Newton steps on
/// `f(t) = (C(t) − q)·C′(t)` from `t0`, kept in `[a, b]` and only where the distance drops.
fn project<const N: usize>(
    c: &BSplineCurve<N>,
    q: &SVector<f64, N>,
    t0: f64,
    (a, b): (f64, f64),
) -> f64 {
    let mut t = t0;
    let mut dist = (c.point(t) - q).norm_squared();
    for _ in 0..8 {
        let [p, d1, d2] = c.derivatives2(t);
        let r = p - q;
        let f = r.dot(&d1);
        let df = d1.norm_squared() + r.dot(&d2);
        if df.is_nan() || df <= 0.0 {
            break;
        }
        let next = (t - f / df).clamp(a, b);
        let nd = (c.point(next) - q).norm_squared();
        if nd.is_nan() || nd >= dist {
            break;
        }
        t = next;
        dist = nd;
    }
    t
}

/// Corrections without improvement after which the fit stops.
const STALL: usize = 5;

/// Weight of the tangential part of the error in the corrected fits (`w` in the module docs).
const TANGENTIAL_WEIGHT: f64 = 0.001;

/// The inner vertices minimising `Σ (C(tⱼ) − Qⱼ)ᵀ Mⱼ (C(tⱼ) − Qⱼ)` with the end vertices at the
/// shape's ends: `Mⱼ = I` without tangents, else `Mⱼ = I − (1 − w) TⱼTⱼᵀ` (the squared
/// distance to the tangent line at the foot point plus `w` times the tangential part).
fn solve_polygon<const N: usize>(
    template: &BSplineCurve<N>,
    shape: &[SVector<f64, N>],
    t: &[f64],
    tangents: Option<&[SVector<f64, N>]>,
) -> Result<BSplineCurve<N>> {
    let basis = template.basis();
    let n = basis.len();
    let (first, last) = (shape[0], shape[shape.len() - 1]);
    let mut points = vec![first; n];
    points[n - 1] = last;
    if n > 2 {
        let inner = n - 2;
        crate::error::size_product("fit rows", shape.len(), N)?;
        let cols = inner * N;
        // the triangular factor R of A = QR and Qᵀb beside it, one row of A at a time by
        // Givens rotations (A has a few non-zeros a row: its B-spline values)
        let mut r = DMatrix::<f64>::zeros(cols, cols + 1);
        let mut row = vec![0.0; cols + 1];
        // Lⱼ = I − (1 − √w) TTᵀ, so LⱼᵀLⱼ = Mⱼ
        let shrink = 1.0 - TANGENTIAL_WEIGHT.sqrt();
        for (j, (&tj, q)) in t.iter().zip(shape).enumerate() {
            let l = match tangents {
                Some(ts) => SMatrixN::<N>::identity() - ts[j] * ts[j].transpose() * shrink,
                None => SMatrixN::<N>::identity(),
            };
            let (span, values) = basis.nonzero(tj);
            let mut res = *q;
            for (k, &v) in values.iter().enumerate() {
                let i = span - basis.degree() + k;
                if i == 0 {
                    res -= first * v;
                } else if i == n - 1 {
                    res -= last * v;
                }
            }
            let lr = l * res;
            for out in 0..N {
                row.fill(0.0);
                let mut lo = cols;
                for (k, &v) in values.iter().enumerate() {
                    let i = span - basis.degree() + k;
                    if i > 0 && i < n - 1 {
                        for c in 0..N {
                            row[(i - 1) * N + c] += l[(out, c)] * v;
                        }
                        lo = lo.min((i - 1) * N);
                    }
                }
                row[cols] = lr[out];
                rotate_into(&mut r, &mut row, lo);
            }
        }
        let triangle = r.columns(0, cols).into_owned();
        let singular = triangle.singular_values();
        let (lo, hi) = singular
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), &s| {
                (lo.min(s), hi.max(s))
            });
        if lo.is_nan() || lo <= 1e-12 * hi {
            return Err(Error::IllConditioned {
                what: "B-spline fit: a vertex is not determined by the samples (smallest/largest singular value)",
                residual: if hi > 0.0 { lo / hi } else { 0.0 },
                tolerance: 1e-12,
            });
        }
        let x = triangle
            .solve_upper_triangular(&r.columns(cols, 1).into_owned())
            .ok_or(Error::IllConditioned {
                what: "B-spline fit solve",
                residual: f64::NAN,
                tolerance: 1e-12,
            })?;
        for i in 0..inner {
            points[i + 1] = SVector::from_fn(|c, _| x[(i * N + c, 0)]);
        }
    }
    crate::error::derived_points("fitted B-spline vertex", &points)?;
    BSplineCurve::try_new(basis.clone(), points)
}

type SMatrixN<const N: usize> = nalgebra::SMatrix<f64, N, N>;

/// Adds `row` (its first non-zero at or after `lo`, its right-hand side last) to the
/// triangular factor `r` by Givens rotations, each zeroing one entry of `row` against the
/// diagonal of `r` (an empty row of `r` takes the row over).
fn rotate_into(r: &mut DMatrix<f64>, row: &mut [f64], lo: usize) {
    let cols = r.nrows();
    for c in lo..cols {
        if row[c] == 0.0 {
            continue;
        }
        let (a, b) = (r[(c, c)], row[c]);
        let rho = a.hypot(b);
        let (cs, sn) = (a / rho, b / rho);
        for k in c..=cols {
            let (x, y) = (r[(c, k)], row[k]);
            r[(c, k)] = cs * x + sn * y;
            row[k] = cs * y - sn * x;
        }
        row[c] = 0.0;
    }
}
