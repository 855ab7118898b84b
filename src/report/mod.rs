//! The report layer (feature `report`): figures (plotters) and tables from data, the
//! seeds' outputs as thin calls of them, output files and benchmark workloads.
//!
//! - [`draw`]: figures of the user's own objects — any surface on a domain (with patch
//!   outlines, corner points, derivative arrows, control nets), curves in the plane and in
//!   space with control polygons and tangents, bases, error maps and convergence plots for
//!   any surface and partition, line and log plots of any series. Each returns a [`Figure`].
//! - [`animation`]: processes in time — de Casteljau's construction as `u` runs, a blending
//!   window sliding along the data — as looping GIFs shown inline in a notebook.
//! - [`table`](mod@table): a [`Table`] (a [`frame::Frame`], title, notes) from any tabulation, error
//!   study or convergence study; Markdown, HTML and CSV for any frame (and, with the
//!   `polars` feature, for any polars DataFrame through `Frame::try_from`).
//! - [`frame`]: named columns of numbers, integers, flags or text, the data of a table;
//!   [`record`]: a table from a slice of row structs ([`crate::record!`]).
//! - [`export`]: meshes as OBJ, PLY and STL, curves as SVG paths, written atomically.
//! - [`user`]: a user's own data through the seeds' methods — fit a curve to points, the
//!   fewest points for an outline, a spline surface on a partition as a mesh (the CLI's
//!   `fit`, `fewest` and `surface`).
//! - [`notebook`]: what a notebook displays — matrices in the report's layout, partials,
//!   formulas, labelled values.
//! - [`bench`](mod@bench): the workloads of `splinelab bench`, their timing, peers' timings and the
//!   scaling figure; `Output` (one output, its id and build) and the registry below
//!   ([`outputs`]).
//! - [`site`]: a static site of a run's outputs (figures, tables, the notebooks' pages and
//!   the API documentation), opened from the file system.
//! - [`seed000`], [`seed001`], [`seed003`]: each seed's outputs with the seed's data, listed
//!   once in its `OUTPUTS`; [`outputs`] is their concatenation, which the CLI writes.
//!
//! It depends on the mathematics; the mathematics never depends on it.

pub mod animation;
pub mod bench;
pub mod draw;
pub mod error;
pub mod export;
pub mod figure;
mod files;
pub mod frame;
pub mod heatmap;
pub mod legend;
pub mod notebook;
mod output;
pub mod plot2d;
pub mod record;
pub mod render3d;
pub mod seed000;
pub mod seed001;
pub mod seed003;
pub mod seed004;
pub mod site;
pub mod style;
mod supersample;
pub mod table;
pub mod user;

pub use animation::Animation;
pub use error::{Error, Result};
pub use figure::Figure;
pub use files::remove_temporaries_on_interrupt;
pub use legend::Legend;
pub use output::{Build, Output};
pub use table::Table;

use std::path::{Path, PathBuf};

/// Every output, seed by seed, in generation order.
pub fn outputs() -> impl Iterator<Item = &'static Output> {
    seed000::OUTPUTS
        .iter()
        .chain(seed001::OUTPUTS)
        .chain(seed003::OUTPUTS)
        .chain(seed004::OUTPUTS)
}

/// The output with this id.
///
/// # Errors
/// [`Error::UnknownId`] if there is none.
pub fn find(id: &str) -> Result<&'static Output> {
    outputs()
        .find(|o| o.id == id)
        .ok_or_else(|| Error::UnknownId {
            what: "output",
            id: id.to_string(),
        })
}

/// The figure with this id, computed (for a notebook cell: `report::figure("fig2-torus")?`).
///
/// # Errors
/// [`Error::UnknownId`] if there is no figure with this id; errors of the computation.
pub fn figure(id: &str) -> Result<Figure> {
    match find(id)?.build {
        Build::Figure(f) => f(),
        Build::Table(_) => Err(Error::UnknownId {
            what: "figure",
            id: id.to_string(),
        }),
    }
}

/// The table with this id, computed.
///
/// # Errors
/// [`Error::UnknownId`] if there is no table with this id; errors of the computation.
pub fn table(id: &str) -> Result<Table> {
    match find(id)?.build {
        Build::Table(f) => f(),
        Build::Figure(_) => Err(Error::UnknownId {
            what: "table",
            id: id.to_string(),
        }),
    }
}

/// Every output id with its one-line description, one per line (what `--list` prints).
pub fn describe_outputs() -> String {
    outputs()
        .map(|o| format!("{:<24} {}", o.id, o.description))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Regenerates one output by id into `dir`.
///
/// # Errors
/// [`Error::UnknownId`] for an unknown id; the errors of [`Output::write`].
pub fn write_only(dir: &Path, id: &str) -> Result<Vec<PathBuf>> {
    find(id)?.write(dir)
}

/// Regenerates every output into `dir`.
///
/// # Errors
/// The first error of [`Output::write`].
pub fn write_all(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    for output in outputs() {
        written.extend(output.write(dir)?);
    }
    Ok(written)
}
