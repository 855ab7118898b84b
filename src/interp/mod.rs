//! Interpolation: polynomial (power basis, Lagrange), piecewise linear, cubic splines with
//! four end conditions, B-spline collocation (seeds 001 and 004); the parameters of the points
//! are [`crate::Parametrization`].

pub(crate) mod angular;
pub(crate) mod cardinal;
pub mod choice;
pub mod collocation;
pub(crate) mod cubic;
pub(crate) mod linear;
pub(crate) mod methods;
pub(crate) mod moments;
pub(crate) mod polynomial;

pub use angular::{classify, COLLINEAR_SIN};
pub use cubic::PERIODIC_MATCH;
pub use methods::ring;
pub use polynomial::{max_interpolation_error, vandermonde_condition, RUNGE_INTERVAL};

use crate::error::{Error, Result};
use nalgebra::SVector;
use num_dual::DualNum;

/// The relative residual an interpolant may leave at its own data before it is refused:
/// `max |s(xᵢ) − yᵢ| ≤ RESIDUAL_TOLERANCE · max |yᵢ|` (absolute when all data are 0), for
/// every interpolation route of the crate (power basis, Lagrange, cubic splines, B-spline
/// collocation). A well-conditioned problem leaves `≈ n ε`, about `10⁻¹⁵`; six orders of
/// magnitude above that, a larger residual means the problem is too ill-conditioned for `f64`
/// and [`Error::IllConditioned`] is returned instead of an interpolant that does not
/// interpolate.
pub const RESIDUAL_TOLERANCE: f64 = 1e-10;

/// `Q₁ … Q_m, Q₁, Q₂, Q₃`: a closed curve of four-point segments as seed 004 closes it (the
/// cardinal and Angular splines; spec decision A5).
///
/// # Errors
/// [`Error::TooFewPoints`] below 3 points; [`Error::TooLarge`] if `m + 3` exceeds
/// [`crate::error::MAX_ELEMENTS`].
pub(crate) fn closed_by_three<T: Copy>(what: &'static str, points: &[T]) -> Result<Vec<T>> {
    if points.len() < 3 {
        return Err(Error::TooFewPoints {
            what,
            needed: 3,
            got: points.len(),
        });
    }
    crate::error::size_sum(what, points.len(), 3)?;
    let mut all = points.to_vec();
    all.extend_from_slice(&points[..3]);
    Ok(all)
}

/// `max rᵢ / scale` (or `max rᵢ` when `scale = 0`), NaN-propagating.
pub(crate) fn relative_residual(residuals: impl Iterator<Item = f64>, scale: f64) -> f64 {
    let worst = residuals.fold(0.0, |m: f64, r| if r.is_nan() || r > m { r } else { m });
    if scale > 0.0 {
        worst / scale
    } else {
        worst
    }
}

/// `Ok` if the relative residual is within [`RESIDUAL_TOLERANCE`].
///
/// # Errors
/// [`Error::IllConditioned`] otherwise (NaN included).
pub(crate) fn accept_residual(what: &'static str, residual: f64) -> Result<()> {
    if residual <= RESIDUAL_TOLERANCE {
        Ok(())
    } else {
        Err(Error::IllConditioned {
            what,
            residual,
            tolerance: RESIDUAL_TOLERANCE,
        })
    }
}

/// The chord `y₀ (1 − u) + y₁ u` between two values, written as `y₀ + (y₁ − y₀) u` on the
/// first half and `y₁ − (y₁ − y₀)(1 − u)` on the second: exact at both ends (`u = 0`, `u = 1`),
/// and its derivative part is the one product `(y₁ − y₀) u′`, never the difference of two
/// large products `y₁ u′ − y₀ u′` (which is NaN where `|y| / h` overflows although the slope
/// is 0).
#[inline]
pub(crate) fn chord<D: DualNum<Primitive = f64> + Copy, const N: usize>(
    y0: &SVector<f64, N>,
    y1: &SVector<f64, N>,
    u: D,
) -> SVector<D, N> {
    let diff = (y1 - y0).map(D::from);
    // two forms of one chord: which is taken does not change the formula
    if crate::branch::read_quietly(&u) <= 0.5 {
        y0.map(D::from) + diff * u
    } else {
        y1.map(D::from) - diff * (-u + 1.0)
    }
}

/// Checks interpolation abscissae (or parameters): [`crate::domain::check_nodes`], the one
/// rule for strictly increasing nodes.
///
/// # Errors
/// As [`crate::domain::check_nodes`].
pub(crate) fn check_sites(what: &'static str, x: &[f64]) -> Result<()> {
    crate::domain::check_nodes(what, x).map(|_| ())
}
