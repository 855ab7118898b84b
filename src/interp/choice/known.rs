//! The configurations a search compares: which of two is better ([`better`]), and the known
//! configuration a caller gives ([`super::SearchOptions::known`]) measured again before it is
//! trusted ([`checked_known`]).

use super::counts::fewest_counted;
use super::{Choice, Family, SearchOptions, Start, Target};
use crate::error::Result;

/// Within tolerance first, then the lower error.
pub(super) fn better(c: &Choice, best: Option<&Choice>) -> bool {
    match best {
        None => true,
        Some(b) => {
            (c.within_tolerance, -c.measure.distances.hausdorff())
                > (b.within_tolerance, -b.measure.distances.hausdorff())
        }
    }
}

/// The known configuration of `options`, measured again on `target` (its fields are public,
/// so nothing it claims is trusted): `None` unless it builds, meets the tolerance and counts
/// at least the family's fewest and at most `max_points`.
///
/// # Errors
/// The errors of [`Target::measure`] for a known configuration that does not build (NaN
/// points, say).
pub(super) fn checked_known(target: &Target, options: &SearchOptions) -> Result<Option<Choice>> {
    let Some(k) = &options.known else {
        return Ok(None);
    };
    let measure = target.measure(&k.method, &k.points)?;
    let within = measure.distances.hausdorff() <= target.tolerance();
    let counted = measure.counted;
    let min = Family::of(&k.method).map_or(0, |f| fewest_counted(f, target.is_closed()));
    Ok(
        (within && counted >= min && counted <= options.max_points).then(|| Choice {
            method: k.method,
            points: k.points.clone(),
            within_tolerance: true,
            measure,
            evaluations: k.evaluations,
            start: Start::Known,
        }),
    )
}
