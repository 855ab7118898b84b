//! The experiments: the studies of the seeds, each built from the library's tools and
//! regenerating a table of its seed.
//!
//! - [`hermite_error`]: seed 000's error of a Hermite spline surface against its surface (§3
//!   and §6: per coordinate, MATLAB's `norm`, max-abs, RMS, on the report's grids), by three
//!   patch evaluations, and a convergence study of the error's order.
//! - [`table_i`]: seed 004's Table I — for each shape and method, the fewest points that draw
//!   the shape within 1 % of its size, by the paper's point rules and by the automatic search
//!   ([`crate::interp::choice`]); the cross-method experiment and the shapes made of several
//!   contours (letters, coastline).
//!
//! The error measures they use live in [`crate::metrics`]; their outputs (tables, figures) in
//! the report layer (`report::seed000`, `report::seed004`).
//!
//! Until the next release the items of [`hermite_error`] are also here (`study::convergence`,
//! the path before issue 28), and [`table_i`] is also `crate::comparison`.

pub mod hermite_error;
pub mod table_i;

pub use hermite_error::{
    convergence, spline_errors, uniform_spline_errors, ConvergenceOrders, ConvergenceRow,
    PatchEvaluation, REPORT_PREC,
};
