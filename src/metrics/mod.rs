//! The error measures, one home for both kinds of object.
//!
//! - [`surface`]: a surface's error on a grid, per coordinate — the report's
//!   `norm(abs(A − B))` (MATLAB's 2-norm, [`matlab_norm`]), max-abs and RMS
//!   ([`CoordErrors`], [`compare`], [`ErrorAccumulator`]).
//! - [`curve`]: how far a plane curve is from the shape it draws (the symmetric Hausdorff
//!   distance between polylines, [`curve::SegmentTree`]) and how smooth it looks
//!   ([`curve::Smoothness`]).
//!
//! Until the next release the items of [`surface`] are also here (`metrics::matlab_norm`, the
//! path before issue 28), and [`curve`] is also `crate::curve_metrics`.

pub mod curve;
pub mod surface;

pub use surface::{compare, matlab_norm, CoordErrors, ErrorAccumulator};
