//! Bicubic Hermite interpolation of surfaces (seed 000 §1–3, §5–6).

pub(crate) mod basis;
pub(crate) mod curve;
pub(crate) mod patch;
pub(crate) mod spline_surface;
