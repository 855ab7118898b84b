//! The report layer: tables (polars DataFrames), output files and benchmark workloads.
//!
//! It depends on the mathematics; the mathematics never depends on it.

pub mod bench;
pub mod figures;
pub mod notebook;
pub mod output;
pub mod printed;
pub mod render3d;
pub mod style;
pub mod tables;

pub use figures::FigureId;
pub use output::{describe_outputs, list_outputs, write_all, write_only, OutputSpec};
pub use tables::Table;
