//! B-splines: knot vectors, the basis, curves (seed 001), curves of order `k` and
//! least-squares fits (seed 004).

pub mod basis;
pub mod curve;
pub mod fit;
pub mod knots;
