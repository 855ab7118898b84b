//! B-splines: knot vectors, the basis, curves (seed 001), curves of order `k` and
//! least-squares fits (seed 004).

pub(crate) mod basis;
pub(crate) mod curve;
pub(crate) mod fit;
pub(crate) mod knots;
pub(crate) mod scalar;
