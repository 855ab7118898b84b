//! The experiments: the studies of the seeds, each built from the library's tools and
//! regenerating a table of its seed.
//!
//! - [`hermite_error`]: seed 000's error of a Hermite spline surface against its surface (§3
//!   and §6: per coordinate, MATLAB's `norm`, max-abs, RMS, on the report's grids), by three
//!   patch evaluations, and a convergence study of the error's order.
//! - [`outline`]: the fewest points per method for an outline of one or more contours within a
//!   tolerance — the one search behind the command line's `fewest`, seed 004's letters and
//!   coastline, and a notebook's own outlines.
//! - [`table_i`]: seed 004's Table I — for each shape and method, the fewest points that draw
//!   the shape within 1 % of its size, by the paper's point rules and by the automatic search
//!   ([`crate::interp::choice`]); the cross-method experiment; the letters and the coastline
//!   ([`outline`] on their contours).
//!
//! The error measures they use live in [`crate::metrics`]; their outputs (tables, figures) in
//! the report layer (`report::seed000`, `report::seed004`, `report::user`).

pub mod hermite_error;
pub mod outline;
pub mod table_i;
