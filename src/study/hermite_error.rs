//! The interpolation-error experiments of seed 000 §3 and §6, and a convergence study.
//!
//! ```
//! use splinelab::prelude::*;
//! use splinelab::study::hermite_error::{convergence, uniform_spline_errors, PatchEvaluation};
//!
//! // the report's §6 error of the torus on 2 × 2 patches, 15 × 15 samples per patch
//! let e = uniform_spline_errors(&Torus::default(), &Rect::unit(), 2, 2, 15,
//!                               PatchEvaluation::HermiteMatrix)?;
//! assert!(e.max_abs.max() < 1e-2);
//!
//! // the error falls as h⁴; a coordinate the spline reproduces is at rounding level, and no
//! // order is computed from it
//! surface!(Tilted = |s, t| Vector3::new(s.sin(), t.exp(), s + t * 2.0));
//! let rows = convergence(&Tilted, &Rect::unit(), &[2, 4, 8], 15)?;
//! let last = rows.last().unwrap().order.unwrap();
//! assert!((last.max_abs[0].unwrap() - 4.0).abs() < 0.2);  // x = sin s: order 4
//! assert!(rows[2].at_rounding(rows[2].errors.max_abs.z));  // z is linear: reproduced
//! assert_eq!(last.max_abs[2], None);
//! // a bad argument is named: `prec` here, not `ns`
//! let bad = convergence(&Tilted, &Rect::unit(), &[1, 2], 1).unwrap_err();
//! assert!(bad.to_string().starts_with("prec"));
//! # Ok::<(), splinelab::Error>(())
//! ```

use crate::bezier::codice7::report_codice7_net;
use crate::bezier::patch::BezierPatch;
use crate::domain::{Partition, Rect};
use crate::error::{Error, Result};
use crate::hermite::spline_surface::HermiteSurface;
use crate::metrics::surface::{CoordErrors, ErrorAccumulator};
use crate::surface::{tabulate, SurfaceDerivatives};
use nalgebra::Vector3;

/// Samples per patch side in the report's error computation (`prec = 15`, Codice 14). The §3
/// listing (Codice 6) does not print its sample count; 15 reproduces both §3 rows to every
/// printed digit, and the report's §6 says its n = m = 1 row equals §3.
pub const REPORT_PREC: usize = 15;

/// The name the studies' errors give their sample count per patch side.
const PREC: &str = "prec (samples per patch side)";

/// How a patch is tabulated in an error experiment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PatchEvaluation {
    /// `H(s)ᵀ C H(t)` (Codice 5).
    HermiteMatrix,
    /// The correct Bézier net ([`BezierPatch::from_hermite`]) by de Casteljau.
    DeCasteljau,
    /// The report's printed path: the net of Codice 7 as printed
    /// ([`crate::report_codice7_net`], sign error included), tabulated by de Casteljau
    /// (Codice 11–12) as Codice 14 does.
    ReportListing,
}

impl PatchEvaluation {
    /// All variants, in a fixed order.
    pub const ALL: [PatchEvaluation; 3] = [
        PatchEvaluation::HermiteMatrix,
        PatchEvaluation::DeCasteljau,
        PatchEvaluation::ReportListing,
    ];
}

/// Codice 14 for any surface and partitions: every patch of the Hermite spline is tabulated
/// on `prec × prec` local samples (by `eval`), compared with the surface at the matching
/// global samples `linspace(uᵢ, uᵢ₊₁, prec) × linspace(vⱼ, vⱼ₊₁, prec)`, and the per-patch
/// errors are reduced ([`CoordErrors`]).
///
/// # Errors
/// [`Error::TooFewSamples`] if `prec < 2`; [`Error::TooLarge`] for more patches or samples
/// than [`crate::error::MAX_ELEMENTS`]; the errors of [`HermiteSurface::try_from_surface`],
/// of [`tabulate`] and of [`ErrorAccumulator::add_patch`] (a surface that is NaN or overflows
/// anywhere on the samples is an error, never a hang or a NaN measure).
pub fn spline_errors<S: SurfaceDerivatives + Sync + ?Sized>(
    surface: &S,
    u: Partition,
    v: Partition,
    prec: usize,
    eval: PatchEvaluation,
) -> Result<CoordErrors> {
    crate::error::samples(PREC, prec)?;
    let spline = HermiteSurface::try_from_surface(surface, u, v)?;
    let (n, m) = spline.patch_counts();
    let mut acc = ErrorAccumulator::new();
    for i in 0..n {
        for j in 0..m {
            let patch = spline.patch(i, j);
            let approx = match eval {
                PatchEvaluation::HermiteMatrix => patch.tabulate(prec, prec)?,
                PatchEvaluation::DeCasteljau => {
                    BezierPatch::from_hermite(&patch).tabulate_de_casteljau(prec, prec)?
                }
                PatchEvaluation::ReportListing => {
                    report_codice7_net(&patch).tabulate_de_casteljau(prec, prec)?
                }
            };
            let exact = tabulate(surface, &spline.patch_rect(i, j), prec, prec)?;
            acc.add_patch(&approx, &exact)?;
        }
    }
    Ok(acc.finish())
}

/// [`spline_errors`] on `n × m` uniform patches of `rect`.
///
/// # Errors
/// [`Error::ZeroPatches`] if `n` or `m` is 0; [`Error::TooFewSamples`] if `prec < 2`.
pub fn uniform_spline_errors<S: SurfaceDerivatives + Sync + ?Sized>(
    surface: &S,
    rect: &Rect,
    n: usize,
    m: usize,
    prec: usize,
    eval: PatchEvaluation,
) -> Result<CoordErrors> {
    crate::error::samples(PREC, prec)?;
    let u = Partition::uniform(rect.s.start(), rect.s.end(), n)?;
    let v = Partition::uniform(rect.t.start(), rect.t.end(), m)?;
    spline_errors(surface, u, v, prec, eval)
}

/// One row of a convergence study: `n × n` patches of side `h`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConvergenceRow {
    /// Patches per side.
    pub n: usize,
    /// Patch side in s (the study's `h`).
    pub h: f64,
    /// The errors.
    pub errors: CoordErrors,
    /// Observed order `log(e_prev / e) / log(h_prev / h)` of each measure against the previous
    /// row; `None` on the first row.
    pub order: Option<ConvergenceOrders>,
    /// The rounding level of the study: [`ROUNDING_ULPS`] `· ε ·` the largest coordinate of
    /// the surface on the rectangle. An error at or below it is the rounding of `f64`
    /// arithmetic, not interpolation error (the spline reproduces that coordinate: a
    /// bicubic surface, a coordinate linear in `s` and `t`), and no order is computed from
    /// it ([`ConvergenceRow::at_rounding`]).
    pub rounding: f64,
}

/// How many units of rounding (`ε` times the surface's largest coordinate) an error may be and
/// still be the rounding of `f64`: the Hermite form adds sixteen products of data of that
/// size, the measures take differences and norms of them.
pub const ROUNDING_ULPS: f64 = 128.0;

impl ConvergenceRow {
    /// Whether `error` (one of this row's) is at rounding level ([`ConvergenceRow::rounding`]).
    pub fn at_rounding(&self, error: f64) -> bool {
        error <= self.rounding
    }
}

/// Observed orders of convergence per measure and coordinate (x, y, z); `None` where an error
/// of either row is at rounding level ([`ConvergenceRow::rounding`]: zero included), or the
/// ratio is not finite, so no order can be measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConvergenceOrders {
    /// Order of the report's measure.
    pub report_norm: [Option<f64>; 3],
    /// Order of the max-abs error.
    pub max_abs: [Option<f64>; 3],
    /// Order of the RMS error.
    pub rms: [Option<f64>; 3],
}

/// Convergence of the Hermite spline on `n × n` uniform patches of `rect` for each `n` in
/// `ns` (increasing), with the observed order between consecutive rows. Bicubic Hermite
/// interpolation has error `O(h⁴)`.
///
/// # Errors
/// [`Error::ZeroPatches`] for `n = 0`, [`Error::NotIncreasing`] unless `ns` increases,
/// [`Error::TooFewSamples`] if `prec < 2`.
pub fn convergence<S: SurfaceDerivatives + Sync + ?Sized>(
    surface: &S,
    rect: &Rect,
    ns: &[usize],
    prec: usize,
) -> Result<Vec<ConvergenceRow>> {
    crate::error::samples(PREC, prec)?;
    if let Some(index) = (1..ns.len()).find(|&k| ns[k] <= ns[k - 1]) {
        return Err(Error::NotIncreasing {
            what: "patch counts",
            index,
            value: ns[index] as f64,
            prev: ns[index - 1] as f64,
        });
    }
    let mut rows: Vec<ConvergenceRow> = Vec::with_capacity(ns.len());
    if ns.is_empty() {
        return Ok(rows);
    }
    let rounding = rounding_level(surface, rect)?;
    for &n in ns {
        let errors =
            uniform_spline_errors(surface, rect, n, n, prec, PatchEvaluation::HermiteMatrix)?;
        let h = rect.s.width() / n as f64;
        let order = rows.last().map(|prev| {
            let rate = |a: Vector3<f64>, b: Vector3<f64>| {
                std::array::from_fn(|k| {
                    let order = (a[k] / b[k]).ln() / (prev.h / h).ln();
                    (a[k] > rounding && b[k] > rounding && order.is_finite()).then_some(order)
                })
            };
            ConvergenceOrders {
                report_norm: rate(prev.errors.report_norm, errors.report_norm),
                max_abs: rate(prev.errors.max_abs, errors.max_abs),
                rms: rate(prev.errors.rms, errors.rms),
            }
        });
        rows.push(ConvergenceRow {
            n,
            h,
            errors,
            order,
            rounding,
        });
    }
    Ok(rows)
}

/// [`ROUNDING_ULPS`] `· ε ·` the largest coordinate of `surface` on a `33 × 33` grid of
/// `rect`.
fn rounding_level<S: SurfaceDerivatives + ?Sized>(surface: &S, rect: &Rect) -> Result<f64> {
    let grid = tabulate(surface, rect, 33, 33)?;
    let size = grid
        .as_slice()
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    Ok(ROUNDING_ULPS * f64::EPSILON * size)
}
