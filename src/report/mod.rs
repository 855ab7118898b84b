//! The report layer: tables (polars DataFrames), figures (plotters), output files and
//! benchmark workloads.
//!
//! It depends on the mathematics; the mathematics never depends on it.

pub mod bench;
pub mod curve_data;
pub mod curve_figures;
pub mod curve_tables;
pub mod figures;
pub mod notebook;
pub mod output;
pub mod plot2d;
pub mod printed;
pub mod render3d;
pub mod style;
pub mod tables;

pub use figures::FigureId;
pub use output::{describe_outputs, list_outputs, write_all, write_only, OutputSpec};
pub use tables::Table;
