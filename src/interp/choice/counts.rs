//! The counts of each family: the fewest distinct points it needs, and the points seed 004
//! counts for a number of distinct ones (a closed curve's repeats: Angular and cardinal 3,
//! others 1).

use super::Family;

/// The fewest distinct points of a family: 3 closed (Angular and cardinal: 3 + 3 repeats),
/// 2 + 2 guides open for the guided families, 3 for the cubic, 2 for the polygon (a segment).
pub(super) fn min_distinct(family: Family, closed: bool) -> usize {
    match (family, closed) {
        (_, true) => 3,
        (Family::Angular | Family::Cardinal, false) => 4,
        (Family::Linear, false) => 2,
        _ => 3,
    }
}

/// Distinct points behind a counted number (the repeats of a closed curve taken off).
pub(super) fn distinct_of(family: Family, closed: bool, counted: usize) -> usize {
    counted.saturating_sub(repeats(family, closed))
}

/// The fewest points a family counts: the B-spline fit's fewest vertices (4 closed, the
/// closing one counted once; 2 open), else [`min_distinct`] with the closed curve's repeats.
pub(super) fn fewest_counted(family: Family, closed: bool) -> usize {
    match (family, closed) {
        (Family::BSpline, true) => 4,
        (Family::BSpline, false) => 2,
        _ => counted_of(family, closed, min_distinct(family, closed)),
    }
}

/// The points counted for `distinct` distinct points (repeats of a closed curve added).
pub(super) fn counted_of(family: Family, closed: bool, distinct: usize) -> usize {
    distinct.saturating_add(repeats(family, closed))
}

/// The repeats a closed curve of the family counts: Angular and cardinal 3, others 1.
fn repeats(family: Family, closed: bool) -> usize {
    match (family, closed) {
        (_, false) => 0,
        (Family::Angular | Family::Cardinal, true) => 3,
        (_, true) => 1,
    }
}
