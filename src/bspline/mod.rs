//! B-splines: knot vectors, the basis, curves (seed 001).

pub mod basis;
pub mod curve;
pub mod knots;
