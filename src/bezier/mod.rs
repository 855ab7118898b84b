//! Bézier form: Bernstein basis, de Casteljau, the bicubic Bézier patch (seed 000 §4), and
//! any curve as cubic Bézier segments ([`from_curve`]: exact for cubic pieces).

pub mod bernstein;
pub mod codice7;
pub mod de_casteljau;
pub mod from_curve;
pub mod patch;
