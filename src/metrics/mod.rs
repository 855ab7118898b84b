//! The error measures, one home for both kinds of object.
//!
//! - `surface.rs`: a surface's error on a grid, per coordinate — the report's
//!   `norm(abs(A − B))` (MATLAB's 2-norm, [`crate::matlab_norm`]), max-abs and RMS
//!   ([`crate::CoordErrors`], [`crate::compare`], [`ErrorAccumulator`]).
//! - [`curve`]: how far a plane curve is from the shape it draws (the symmetric Hausdorff
//!   distance between polylines, [`curve::SegmentTree`]) and how smooth it looks
//!   ([`curve::Smoothness`]).

pub mod curve;
pub(crate) mod surface;

pub use surface::ErrorAccumulator;
