//! The interpolation-error experiments of seed 000 §3 and §6, and a convergence study.

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
}

/// Observed orders of convergence per measure and coordinate (x, y, z); `None` where an error
/// of either row is exactly zero (or the ratio is not finite), so no order can be measured.
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
    if let Some(index) = (1..ns.len()).find(|&k| ns[k] <= ns[k - 1]) {
        return Err(Error::NotIncreasing {
            what: "patch counts",
            index,
            value: ns[index] as f64,
            prev: ns[index - 1] as f64,
        });
    }
    let mut rows: Vec<ConvergenceRow> = Vec::with_capacity(ns.len());
    for &n in ns {
        let errors =
            uniform_spline_errors(surface, rect, n, n, prec, PatchEvaluation::HermiteMatrix)?;
        let h = rect.s.width() / n as f64;
        let order = rows.last().map(|prev| {
            let rate = |a: Vector3<f64>, b: Vector3<f64>| {
                std::array::from_fn(|k| {
                    let order = (a[k] / b[k]).ln() / (prev.h / h).ln();
                    (a[k] > 0.0 && b[k] > 0.0 && order.is_finite()).then_some(order)
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
        });
    }
    Ok(rows)
}
