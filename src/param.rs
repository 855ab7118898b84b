//! Parameter values for interpolating a sequence of points (seed 001, "Calcolo dei nodi di
//! interpolazione").

use crate::error::finite_points;
use crate::error::{Error, Result};
use nalgebra::SVector;

/// How parameters `t₀ < t₁ < … < t_n` in `[0, 1]` are assigned to points `P₀ … P_n`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Parametrization {
    /// `tᵢ = i/n`: ignores the distances between points (seed 001, "uniforme").
    Uniform,
    /// `tᵢ − tᵢ₋₁ ∝ ‖Pᵢ − Pᵢ₋₁‖`: the chord length (seed 001, "della corda").
    ChordLength,
    /// `tᵢ − tᵢ₋₁ ∝ ‖Pᵢ − Pᵢ₋₁‖^½` (E. T. Y. Lee, *Choosing nodes in parametric curve
    /// interpolation*, CAD 21, 1989): between the two, and free of cusps and self-intersections
    /// within a segment for Catmull–Rom curves (Yuksel, Schaefer, Keyser 2011).
    Centripetal,
}

/// Chord length, Rogers & Adams' choice and seed 004's default for parametric cubic splines
/// (spec decision A6: the paper does not state one).
impl Default for Parametrization {
    fn default() -> Self {
        Parametrization::ChordLength
    }
}

impl Parametrization {
    /// All variants.
    pub const ALL: [Parametrization; 3] = [
        Parametrization::Uniform,
        Parametrization::ChordLength,
        Parametrization::Centripetal,
    ];

    /// The parameters of `points`, `t₀ = 0`, `t_n = 1`, strictly increasing — checked on the
    /// computed values, not only on the steps: a step below the rounding of the running sum
    /// (a chord `10⁻²⁰` after one of length 1) would repeat a parameter. Coordinates near the
    /// overflow or underflow thresholds are scaled first (see `chords`; the parameters are
    /// scale-invariant).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 points; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`] points; [`Error::NonFinite`] for a NaN or infinite
    /// coordinate; [`Error::RepeatedPoint`] if two consecutive points coincide under a
    /// distance-based rule; [`Error::RepeatedParameter`] if two computed parameters coincide
    /// in `f64` (steps too unequal).
    pub fn parameters<const N: usize>(self, points: &[SVector<f64, N>]) -> Result<Vec<f64>> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "points to parametrize",
                needed: 2,
                got: points.len(),
            });
        }
        crate::error::size("points to parametrize", points.len())?;
        finite_points("point coordinate", points)?;
        let scale = points.iter().map(|p| p.amax()).fold(0.0, f64::max);
        let steps: Vec<f64> = match self {
            Parametrization::Uniform => vec![1.0; points.len() - 1],
            Parametrization::ChordLength => chords(points, scale).collect(),
            Parametrization::Centripetal => chords(points, scale).map(f64::sqrt).collect(),
        };
        if let Some(index) = steps.iter().position(|&d| d <= 0.0) {
            return Err(Error::RepeatedPoint { index: index + 1 });
        }
        let total: f64 = steps.iter().sum();
        let mut t = Vec::with_capacity(points.len());
        let mut acc = 0.0;
        t.push(0.0);
        for d in &steps[..steps.len() - 1] {
            acc += d;
            t.push(acc / total);
        }
        t.push(1.0);
        if let Some(index) = (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
            return Err(Error::RepeatedParameter {
                what: "computed parameters (a step is below the rounding of the total length)",
                index,
                value: t[index],
            });
        }
        Ok(t)
    }
}

/// Chord lengths `‖Pᵢ₊₁ − Pᵢ‖`, measured on the points divided by their largest coordinate
/// `scale` when it lies outside `[10⁻¹⁵⁰, 10¹⁵⁰]` (there the squares in the norm could
/// overflow or underflow; scaled differences are at most 2). Inside that range the points are
/// used as given, so ordinary data get the same bits as an unscaled computation.
fn chords<const N: usize>(
    points: &[SVector<f64, N>],
    scale: f64,
) -> impl Iterator<Item = f64> + '_ {
    let s = if scale > 0.0 && !(1e-150..=1e150).contains(&scale) {
        scale
    } else {
        1.0
    };
    points.windows(2).map(move |w| (w[1] / s - w[0] / s).norm())
}
