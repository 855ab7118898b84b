//! The report layer's error: the mathematics' [`crate::error::Error`] plus what only files, ids,
//! figures and tables can get wrong.

use std::path::PathBuf;

/// Everything that can go wrong when building, drawing or writing an output.
///
/// `Debug` prints the `Display` message, as [`crate::error::Error`] does, so a notebook cell or an
/// `.expect(…)` shows words, not fields.
#[derive(Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An error of the mathematics behind the output.
    #[error(transparent)]
    Core(crate::error::Error),
    /// Reading or writing a file failed.
    #[error("{path}: {message}")]
    Io {
        /// The file or folder.
        path: PathBuf,
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
    /// A figure could not be drawn (or encoded).
    #[error("figure {name}: {message}")]
    Figure {
        /// The figure's id or title.
        name: String,
        /// What went wrong.
        message: String,
    },
    /// A table could not be built (ragged or repeated columns) or converted to or from
    /// polars (its error, as text).
    #[error("table {name}: {message}")]
    Table {
        /// The table's id or title.
        name: String,
        /// What went wrong.
        message: String,
    },
    /// A text input (a data file, a peer's timings) could not be read: where and why.
    #[error("{what}, line {line}: {message}")]
    Parse {
        /// The input.
        what: String,
        /// The line at fault (1-based).
        line: usize,
        /// What is wrong with it.
        message: String,
    },
}

impl std::fmt::Debug for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
    }
}

/// A mathematical error as a report error: the report error it carries if it is one
/// ([`crate::error::Error::Layer`], so conversions never nest), else [`Error::Core`].
impl From<crate::error::Error> for Error {
    fn from(e: crate::error::Error) -> Error {
        match e {
            crate::error::Error::Layer(inner) => match inner.downcast_ref::<Error>() {
                Some(mine) => mine.clone(),
                None => Error::Core(crate::error::Error::Layer(inner)),
            },
            e => Error::Core(e),
        }
    }
}

/// A report error as a mathematical one, for `?` in a function returning
/// [`crate::Result`]: the mathematical error itself if that is all it carries, else the
/// report error kept whole in [`crate::error::Error::Layer`].
impl From<Error> for crate::error::Error {
    fn from(e: Error) -> crate::error::Error {
        match e {
            Error::Core(e) => e,
            e => crate::error::Error::Layer(crate::error::LayerError::new(e)),
        }
    }
}

/// Shorthand for `Result<T, splinelab::report::Error>`.
pub type Result<T> = std::result::Result<T, Error>;

/// An [`Error::Io`] maker for `path`, for `map_err`.
pub(crate) fn io_err(path: &std::path::Path) -> impl FnOnce(std::io::Error) -> Error + '_ {
    move |e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}
