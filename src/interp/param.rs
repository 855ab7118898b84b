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

impl Parametrization {
    /// All variants.
    pub const ALL: [Parametrization; 3] = [
        Parametrization::Uniform,
        Parametrization::ChordLength,
        Parametrization::Centripetal,
    ];

    /// A short label.
    pub fn label(self) -> &'static str {
        match self {
            Parametrization::Uniform => "uniform",
            Parametrization::ChordLength => "chord length",
            Parametrization::Centripetal => "centripetal",
        }
    }

    /// The parameters of `points`, `t₀ = 0`, `t_n = 1`, strictly increasing.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 points; [`Error::NonFinite`] for a NaN or
    /// infinite coordinate; [`Error::RepeatedPoint`] if two consecutive points coincide under a
    /// distance-based rule (their parameters would coincide).
    pub fn parameters<const N: usize>(self, points: &[SVector<f64, N>]) -> Result<Vec<f64>> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "points to parametrize",
                needed: 2,
                got: points.len(),
            });
        }
        finite_points("point coordinate", points)?;
        let steps: Vec<f64> = match self {
            Parametrization::Uniform => vec![1.0; points.len() - 1],
            Parametrization::ChordLength => chords(points).collect(),
            Parametrization::Centripetal => chords(points).map(f64::sqrt).collect(),
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
        Ok(t)
    }
}

fn chords<const N: usize>(points: &[SVector<f64, N>]) -> impl Iterator<Item = f64> + '_ {
    points.windows(2).map(|w| (w[1] - w[0]).norm())
}
