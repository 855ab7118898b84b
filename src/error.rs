//! The crate's one error type.

use thiserror::Error;

/// Everything that can go wrong when building or evaluating splinelab objects.
///
/// Construction and tabulation return `Result<_, Error>`; evaluation of an object that was
/// validated on construction does not fail.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter (bound, node, evaluation point) was NaN or infinite.
    #[error("{what} must be finite, got {value}")]
    NonFinite {
        /// Which input was not finite.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// An interval or rectangle side has zero or negative width.
    #[error("{what}: interval [{start}, {end}] must satisfy start < end")]
    EmptyInterval {
        /// Which interval.
        what: &'static str,
        /// Its start.
        start: f64,
        /// Its end.
        end: f64,
    },
    /// A partition needs at least two nodes (one patch).
    #[error("{what}: a partition needs at least 2 nodes, got {got}")]
    PartitionTooShort {
        /// Which partition.
        what: &'static str,
        /// How many nodes were given.
        got: usize,
    },
    /// Partition nodes must be strictly increasing.
    #[error("{what}: nodes must be strictly increasing, but node {index} ({value}) <= node {prev_index} ({prev})", prev_index = index - 1)]
    NotIncreasing {
        /// Which partition.
        what: &'static str,
        /// Index of the first node that is not larger than its predecessor.
        index: usize,
        /// Its value.
        value: f64,
        /// The predecessor's value.
        prev: f64,
    },
    /// A shape parameter (a radius, say) must be positive and finite.
    #[error("{what} must be positive and finite, got {value}")]
    NotPositive {
        /// Which parameter.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A count of patches was zero.
    #[error("{what}: the number of patches must be at least 1, got 0")]
    ZeroPatches {
        /// Which count.
        what: &'static str,
    },
    /// A tabulation needs at least two samples per side (both ends of the interval).
    #[error("{what}: at least 2 samples are needed, got {got}")]
    TooFewSamples {
        /// Which sample count.
        what: &'static str,
        /// How many were asked for.
        got: usize,
    },
    /// A parameter lies outside the domain of the object evaluated.
    #[error("{what} = {value} lies outside the domain [{start}, {end}]")]
    OutOfDomain {
        /// Which parameter.
        what: &'static str,
        /// Its value.
        value: f64,
        /// Domain start.
        start: f64,
        /// Domain end.
        end: f64,
    },
    /// A curve or net needs more control points than it was given.
    #[error("{what}: at least {needed} points are needed, got {got}")]
    TooFewPoints {
        /// Which input.
        what: &'static str,
        /// How many are needed.
        needed: usize,
        /// How many were given.
        got: usize,
    },
    /// Two grids that are compared have different shapes.
    #[error("grid shapes differ: {left_rows}x{left_cols} vs {right_rows}x{right_cols}")]
    ShapeMismatch {
        /// Rows of the first grid.
        left_rows: usize,
        /// Columns of the first grid.
        left_cols: usize,
        /// Rows of the second grid.
        right_rows: usize,
        /// Columns of the second grid.
        right_cols: usize,
    },
    /// A knot vector (or a basis) needs more knots.
    #[error("knot vector: at least {needed} knots are needed, got {got}")]
    TooFewKnots {
        /// How many are needed.
        needed: usize,
        /// How many were given.
        got: usize,
    },
    /// Knots must be non-decreasing.
    #[error("knot vector: knot {index} ({value}) is smaller than knot {prev_index} ({prev})", prev_index = index - 1)]
    KnotsNotSorted {
        /// Index of the first knot smaller than its predecessor.
        index: usize,
        /// Its value.
        value: f64,
        /// The predecessor's value.
        prev: f64,
    },
    /// A knot is repeated more often than the order allows (or a multiplicity is 0).
    #[error(
        "knot multiplicity {multiplicity} at breakpoint {index} is not in 1..={max} (the order)"
    )]
    MultiplicityTooHigh {
        /// Index of the breakpoint (distinct knot value).
        index: usize,
        /// Its multiplicity.
        multiplicity: usize,
        /// The largest allowed, the order `p + 1`.
        max: usize,
    },
    /// A spline order of 0 was asked for (the order is degree + 1 ≥ 1).
    #[error("the order of a spline must be at least 1, got 0")]
    ZeroOrder,
    /// A degree (or order) too low for the method.
    #[error("degree (or order) {got} is too low: at least {min} is needed")]
    DegreeTooLow {
        /// The smallest allowed.
        min: usize,
        /// What was given.
        got: usize,
    },
    /// Two inputs that must match in length do not.
    #[error("{what}: expected {expected}, got {got}")]
    CountMismatch {
        /// What is counted.
        what: &'static str,
        /// The count required.
        expected: usize,
        /// The count given.
        got: usize,
    },
    /// An index past the end of a collection.
    #[error("{what} index {index} is out of range (length {len})")]
    IndexOutOfRange {
        /// Which collection.
        what: &'static str,
        /// The index given.
        index: usize,
        /// The collection's length.
        len: usize,
    },
    /// A NURBS weight that is not positive and finite.
    #[error("weight {index} must be positive and finite, got {value}")]
    NonPositiveWeight {
        /// Index of the weight.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// Two interpolation abscissae (or parameters) are equal.
    #[error("{what}: value {index} ({value}) repeats the previous one; interpolation needs distinct values")]
    RepeatedParameter {
        /// Which input.
        what: &'static str,
        /// Index of the repeated value.
        index: usize,
        /// The value.
        value: f64,
    },
    /// Two consecutive points coincide, so a distance-based parametrization cannot separate them.
    #[error("point {index} coincides with point {prev_index}: chord-based parameters would repeat", prev_index = index - 1)]
    RepeatedPoint {
        /// Index of the second of the two points.
        index: usize,
    },
    /// Periodic (cyclic) end conditions need data whose first and last values coincide.
    #[error(
        "periodic ends need the first and last data points to coincide; they are {distance} apart"
    )]
    PeriodicEndsMismatch {
        /// Distance between the first and last values.
        distance: f64,
    },
    /// A linear system has no unique solution (or its solve broke down numerically).
    #[error("{what} is singular")]
    SingularSystem {
        /// Which system.
        what: &'static str,
    },
    /// The Schoenberg–Whitney condition fails: a collocation site lies outside the support of
    /// its basis function, so the interpolation problem has no unique solution.
    #[error("Schoenberg–Whitney condition fails: site {index} ({site}) is outside the support [{support_start}, {support_end}) of basis function {index}")]
    SchoenbergWhitney {
        /// Index `j` of the site and of the basis function.
        index: usize,
        /// The site `x_j`.
        site: f64,
        /// Start `t_j` of the support.
        support_start: f64,
        /// End `t_{j+p+1}` of the support.
        support_end: f64,
    },
    /// Reading or writing a file failed.
    #[error("{path}: {message}")]
    Io {
        /// The file or folder.
        path: std::path::PathBuf,
        /// What the operating system said.
        message: String,
    },
    /// An output or workload id that does not exist.
    #[error("unknown {what} id `{id}` (see --list)")]
    UnknownId {
        /// Output or workload.
        what: &'static str,
        /// The id asked for.
        id: String,
    },
    /// A figure could not be drawn.
    #[error("figure {id}: {message}")]
    Figure {
        /// The figure id.
        id: String,
        /// What went wrong.
        message: String,
    },
    /// A table could not be built (polars error, stringified).
    #[error("table {id}: {message}")]
    Table {
        /// The table id.
        id: String,
        /// What polars said.
        message: String,
    },
}

/// Shorthand for `Result<T, splinelab::Error>`.
pub type Result<T> = std::result::Result<T, Error>;

/// Returns `value` if it is finite, else [`Error::NonFinite`].
pub(crate) fn finite(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NonFinite { what, value })
    }
}

/// Checks that every coordinate of every point is finite.
pub(crate) fn finite_points<const N: usize>(
    what: &'static str,
    points: &[nalgebra::SVector<f64, N>],
) -> Result<()> {
    for p in points {
        for &x in p.iter() {
            finite(what, x)?;
        }
    }
    Ok(())
}

/// Returns `n` if it is at least 2, else [`Error::TooFewSamples`].
pub(crate) fn samples(what: &'static str, n: usize) -> Result<usize> {
    if n >= 2 {
        Ok(n)
    } else {
        Err(Error::TooFewSamples { what, got: n })
    }
}
