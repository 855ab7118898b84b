//! Bicubic Hermite interpolation of surfaces (seed 000 §1–3, §5–6).

pub mod basis;
pub mod curve;
pub mod patch;
pub mod spline_surface;
