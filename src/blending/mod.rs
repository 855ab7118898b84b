//! Seed 003's blending-function curves and surfaces: Lagrange and uniform B-spline windows,
//! the printed `bspline` and OpenGL-evaluator procedures, the sliding bicubic surface.

pub(crate) mod functions;
pub mod opengl;
pub mod surface;
pub mod window;
