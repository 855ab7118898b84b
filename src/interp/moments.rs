//! The cubic spline's moment equations written out as one dense system over any field
//! (seed 001, "Spline cubiche di interpolazione"; seed 004 §2 for the anticyclic ends): the
//! reference that [`crate::CubicSpline`]'s O(n) tridiagonal solve is tested against, and the
//! system a notebook shows in exact fractions.

use crate::error::{Error, Result};
use crate::exact::Field;
use crate::interp::cubic::EndCondition;
use nalgebra::DMatrix;

/// The moment equations `A M = r` of the interpolating cubic spline through `(xᵢ, yᵢ)`,
/// `i = 0 … n`, in all `n + 1` unknowns `Mᵢ = s″(xᵢ)`, with `hᵢ = xᵢ₊₁ − xᵢ` and
/// `δᵢ = (yᵢ₊₁ − yᵢ)/hᵢ`:
///
/// - rows `1 … n − 1`, continuity of `s′` at the interior nodes:
///   `hᵢ₋₁ Mᵢ₋₁ + 2(hᵢ₋₁ + hᵢ) Mᵢ + hᵢ Mᵢ₊₁ = 6(δᵢ − δᵢ₋₁)`;
/// - rows `0` and `n`, the end condition:
///   - natural: `M₀ = 0`, `M_n = 0`;
///   - clamped (`s′(x₀) = a`, `s′(x_n) = b`): `2h₀M₀ + h₀M₁ = 6(δ₀ − a)`,
///     `h_{n−1}M_{n−1} + 2h_{n−1}M_n = 6(b − δ_{n−1})`;
///   - periodic and cyclic (`σ = 1`), anticyclic (`σ = −1`): `s′(x₀) = σ s′(x_n)`, i.e.
///     `2(h₀ + h_{n−1})M₀ + h₀M₁ + σh_{n−1}M_{n−1} = 6(δ₀ − σδ_{n−1})`, and `M_n − σM₀ = 0`.
///
/// Row 0 of the periodic kinds is written for `M_n = σM₀`, which row `n` states. Periodic and
/// cyclic ends give the same equations: whether the data's ends coincide is not checked here
/// ([`crate::CubicSpline`] checks it). Returns `(A, r)`, `r` a column.
///
/// # Errors
/// [`Error::CountMismatch`] if `x` and `y` differ in length; [`Error::TooFewPoints`] below 2
/// points (3 for the periodic kinds); [`Error::TooLarge`] above
/// [`crate::exact::MAX_DIMENSION`] points; [`Error::NonFinite`] for a non-finite number;
/// [`Error::NotIncreasing`] unless `x` is strictly increasing; [`Error::Overflow`] when a
/// coefficient the equations derive is not finite (`f64` nodes near `±f64::MAX`).
pub fn moment_system<T: Field>(
    x: &[T],
    y: &[T],
    end: &EndCondition<1>,
) -> Result<(DMatrix<T>, DMatrix<T>)> {
    if x.len() != y.len() {
        return Err(Error::CountMismatch {
            what: "moment system values (one per node)",
            expected: x.len(),
            got: y.len(),
        });
    }
    let periodic = !matches!(end, EndCondition::Natural | EndCondition::Clamped { .. });
    let needed = if periodic { 3 } else { 2 };
    if x.len() < needed {
        return Err(Error::TooFewPoints {
            what: "moment system nodes",
            needed,
            got: x.len(),
        });
    }
    crate::exact::check_dimension("moment system nodes", x.len())?;
    for (i, v) in x.iter().chain(y).enumerate() {
        if !v.is_finite() {
            return Err(Error::NonFinite {
                what: if i < x.len() {
                    "moment system node"
                } else {
                    "moment system value"
                },
                value: v.to_f64(),
            });
        }
    }
    let n = x.len() - 1;
    let h: Vec<T> = x.windows(2).map(|w| w[1].clone() - w[0].clone()).collect();
    if let Some(i) = h.iter().position(|hi| !hi.is_positive()) {
        return Err(Error::NotIncreasing {
            what: "moment system nodes",
            index: i + 1,
            value: x[i + 1].to_f64(),
            prev: x[i].to_f64(),
        });
    }
    let delta: Vec<T> = (0..n)
        .map(|i| (y[i + 1].clone() - y[i].clone()) / h[i].clone())
        .collect();
    let (two, six): (T, T) = (T::one() + T::one(), small(6));
    let mut a = DMatrix::from_element(n + 1, n + 1, T::zero());
    let mut r = DMatrix::from_element(n + 1, 1, T::zero());
    for i in 1..n {
        a[(i, i - 1)] = h[i - 1].clone();
        a[(i, i)] = two.clone() * (h[i - 1].clone() + h[i].clone());
        a[(i, i + 1)] = h[i].clone();
        r[(i, 0)] = six.clone() * (delta[i].clone() - delta[i - 1].clone());
    }
    match end {
        EndCondition::Natural => {
            a[(0, 0)] = T::one();
            a[(n, n)] = T::one();
        }
        EndCondition::Clamped { start, end } => {
            let (sa, sb) = (T::from_f64(start.x)?, T::from_f64(end.x)?);
            a[(0, 0)] = two.clone() * h[0].clone();
            a[(0, 1)] = h[0].clone();
            r[(0, 0)] = six.clone() * (delta[0].clone() - sa);
            a[(n, n - 1)] = h[n - 1].clone();
            a[(n, n)] = two.clone() * h[n - 1].clone();
            r[(n, 0)] = six.clone() * (sb - delta[n - 1].clone());
        }
        EndCondition::Periodic | EndCondition::Cyclic | EndCondition::Anticyclic => {
            let sigma = if matches!(end, EndCondition::Anticyclic) {
                -T::one()
            } else {
                T::one()
            };
            a[(0, 0)] = two * (h[0].clone() + h[n - 1].clone());
            a[(0, 1)] = h[0].clone();
            // n ≥ 2: M_{n−1} is not M₁'s column only when n > 2; for n = 2 both add up
            a[(0, n - 1)] = a[(0, n - 1)].clone() + sigma.clone() * h[n - 1].clone();
            r[(0, 0)] = six * (delta[0].clone() - sigma.clone() * delta[n - 1].clone());
            a[(n, n)] = T::one();
            a[(n, 0)] = -sigma;
        }
    }
    // what the rows derive (2(hᵢ₋₁ + hᵢ), 6(δᵢ − δᵢ₋₁)) can overflow f64 from finite data
    if let Some(v) = a.iter().chain(r.iter()).find(|v| !v.is_finite()) {
        return Err(Error::Overflow {
            what: "a moment equation's coefficient",
            value: v.to_f64(),
        });
    }
    Ok((a, r))
}

/// The integer `k` in any field, as a sum of ones.
fn small<T: Field>(k: u32) -> T {
    (0..k).fold(T::zero(), |s, _| s + T::one())
}
