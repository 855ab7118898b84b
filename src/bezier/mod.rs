//! Bézier form: Bernstein basis, de Casteljau, the bicubic Bézier patch (seed 000 §4).

pub mod bernstein;
pub mod codice7;
pub mod de_casteljau;
pub mod patch;
