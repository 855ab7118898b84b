//! One output of the reports ([`Output`]): its id, description and how it is built, and how it
//! is written. The registry of every output, seed by seed, is [`super::outputs`].

use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::table::Table;
use std::path::{Path, PathBuf};

/// How an output is computed.
#[derive(Debug, Clone, Copy)]
pub enum Build {
    /// A table, written as CSV and Markdown under `tables/`.
    Table(fn() -> Result<Table>),
    /// A figure, written as PNG and SVG under `figures/`.
    Figure(fn() -> Result<Figure>),
}

/// One output of the reports: an id (the file stem and `--only` argument), the seed it comes
/// from, a one-line description and how to build it.
#[derive(Debug, Clone, Copy)]
pub struct Output {
    /// Id used by `--only` and as the file stem.
    pub id: &'static str,
    /// One-line description for `--list`.
    pub description: &'static str,
    /// How it is computed.
    pub build: Build,
}

impl Output {
    /// A table output.
    pub const fn table(
        id: &'static str,
        description: &'static str,
        build: fn() -> Result<Table>,
    ) -> Self {
        Self {
            id,
            description,
            build: Build::Table(build),
        }
    }

    /// A figure output.
    pub const fn figure(
        id: &'static str,
        description: &'static str,
        build: fn() -> Result<Figure>,
    ) -> Self {
        Self {
            id,
            description,
            build: Build::Figure(build),
        }
    }

    /// Whether it is a figure.
    pub fn is_figure(&self) -> bool {
        matches!(self.build, Build::Figure(_))
    }

    /// Writes the output's files into `dir` (`tables/<id>.csv|md` or
    /// `figures/<id>.png|svg`); returns their paths.
    ///
    /// # Errors
    /// [`crate::report::Error::Io`] if a file cannot be written; errors of the computation or drawing.
    pub fn write(&self, dir: &Path) -> Result<Vec<PathBuf>> {
        match self.build {
            Build::Table(f) => {
                let mut table = f()?;
                table.id = self.id.to_string();
                table.write(&dir.join("tables"))
            }
            Build::Figure(f) => f()?.save(&dir.join("figures"), self.id),
        }
    }
}
