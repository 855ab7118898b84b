//! Bézier form: Bernstein basis, de Casteljau, the bicubic Bézier patch (seed 000 §4), and
//! any curve as cubic Bézier segments ([`from_curve`]: exact for cubic pieces).

pub(crate) mod bernstein;
pub(crate) mod codice7;
pub(crate) mod de_casteljau;
pub mod from_curve;
pub(crate) mod patch;

pub use bernstein::MAX_BERNSTEIN_DEGREE;
pub use de_casteljau::MAX_RECURSIVE_POINTS;
