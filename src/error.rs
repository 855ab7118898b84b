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

/// Returns `n` if it is at least 2, else [`Error::TooFewSamples`].
pub(crate) fn samples(what: &'static str, n: usize) -> Result<usize> {
    if n >= 2 {
        Ok(n)
    } else {
        Err(Error::TooFewSamples { what, got: n })
    }
}
