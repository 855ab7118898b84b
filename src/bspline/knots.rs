//! Knot vectors (extended partitions), validated once on construction (seed 001).

use crate::error::{derived, finite, size, size_sum, Error, Result};

/// A knot vector `t₀ ≤ t₁ ≤ … ≤ t_L` (the slides' *partizione estesa*, seed 001): finite,
/// non-decreasing, at least two knots and not all equal.
///
/// A knot vector alone has no degree; [`crate::bspline::basis::BSplineBasis`] pairs it with one and checks the
/// conditions that depend on it (length, multiplicities, a non-empty domain).
///
/// # Examples
/// ```
/// use splinelab::KnotVector;
/// let k = KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]);
/// assert_eq!(k.multiplicity(0.0), 3);
/// assert_eq!(k.multiplicity(1.0), 1);
/// assert_eq!(k.multiplicity(0.5), 0);
/// assert!(k.is_open(2));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct KnotVector {
    knots: Vec<f64>,
}

/// How the `m` extra knots at each end of an extended partition are placed (seed 001,
/// "Partizione estesa": only `t₁ ≤ … ≤ t_m = a` and `b = t_{m+K+1} ≤ … ≤ t_{2m+K}` are
/// required, so this is a choice).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndKnots {
    /// All `m` end knots coincide with `a` (resp. `b`): an open (clamped) knot vector, whose
    /// curve starts at the first control point and ends at the last.
    Clamped,
    /// Equally spaced end knots `a − (m−1)h, …, a − h, a` and `b, b + h, …, b + (m−1)h`. The
    /// slides' example (`[0,1]`, `m = 4`, `Δ = {1/2, 3/4}`, `M = {1, 2}`) uses `h = 1/4`.
    Spaced(f64),
}

impl KnotVector {
    /// A knot vector from its knots.
    ///
    /// # Panics
    /// On invalid knots; see [`KnotVector::try_new`].
    pub fn new(knots: Vec<f64>) -> Self {
        Self::try_new(knots).expect("invalid knot vector")
    }

    /// A knot vector from its knots.
    ///
    /// # Errors
    /// [`Error::TooFewKnots`] for fewer than 2 knots, [`Error::NonFinite`] for a NaN or
    /// infinite knot, [`Error::KnotsNotSorted`] if a knot is smaller than its predecessor,
    /// [`Error::EmptyInterval`] if all knots are equal; [`Error::Overflow`] if the width
    /// `t_L − t₀` overflows; [`Error::GapTooSmall`] for two consecutive distinct knots closer
    /// than `f64::MIN_POSITIVE` (the basis divides by knot differences); [`Error::TooLarge`]
    /// beyond [`crate::error::MAX_ELEMENTS`] knots.
    pub fn try_new(knots: Vec<f64>) -> Result<Self> {
        size("knots", knots.len())?;
        if knots.len() < 2 {
            return Err(Error::TooFewKnots {
                needed: 2,
                got: knots.len(),
            });
        }
        for &k in &knots {
            finite("knot", k)?;
        }
        if let Some(index) = (1..knots.len()).find(|&i| knots[i] < knots[i - 1]) {
            return Err(Error::KnotsNotSorted {
                index,
                value: knots[index],
                prev: knots[index - 1],
            });
        }
        let (first, last) = (knots[0], knots[knots.len() - 1]);
        if first >= last {
            return Err(Error::EmptyInterval {
                what: "knot vector",
                start: first,
                end: last,
            });
        }
        derived("knot vector width t_L − t₀", last - first)?;
        for i in 1..knots.len() {
            if knots[i] > knots[i - 1] {
                crate::domain::gap("knot vector", i, knots[i - 1], knots[i])?;
            }
        }
        Ok(Self { knots })
    }

    /// The extended partition of seed 001: from `[a, b]`, interior breakpoints
    /// `a < x₁ < … < x_k < b` with multiplicities `M = (m₁, …, m_k)`, `mᵢ ≤ m`, and the order
    /// `m` (degree `m − 1`), the `2m + K` knots (`K = Σ mᵢ`)
    ///
    /// `t₁ ≤ … ≤ t_m = a < x₁ (m₁ times) < … < x_k (m_k times) < b = t_{m+K+1} ≤ … ≤ t_{2m+K}`,
    ///
    /// with the `m − 1` outer knots at each end placed by `ends`. The slides' example,
    /// `extended_partition(0, 1, &[0.5, 0.75], &[1, 2], 4, EndKnots::Spaced(0.25))`, gives
    /// `{−3/4, −1/2, −1/4, 0, 1/2, 3/4, 3/4, 1, 5/4, 3/2, 7/4}`.
    ///
    /// # Errors
    /// [`Error::ZeroOrder`] for `order = 0`; [`Error::CountMismatch`] unless `interior` and
    /// `multiplicities` have the same length; [`Error::EmptyInterval`] unless `a < b`;
    /// [`Error::NotIncreasing`] unless `a < x₁ < … < x_k < b`; [`Error::MultiplicityTooHigh`]
    /// for an `mᵢ` of 0 or above `m`; [`Error::NotPositive`] for a spacing `h ≤ 0`;
    /// [`Error::NonFinite`] for NaN or infinite input.
    ///
    /// # Examples
    /// ```
    /// use splinelab::{EndKnots, KnotVector};
    /// let k = KnotVector::extended_partition(0.0, 1.0, &[0.5, 0.75], &[1, 2], 4, EndKnots::Spaced(0.25)).unwrap();
    /// assert_eq!(k.knots(), &[-0.75, -0.5, -0.25, 0.0, 0.5, 0.75, 0.75, 1.0, 1.25, 1.5, 1.75]);
    /// ```
    pub fn extended_partition(
        a: f64,
        b: f64,
        interior: &[f64],
        multiplicities: &[usize],
        order: usize,
        ends: EndKnots,
    ) -> Result<Self> {
        if order == 0 {
            return Err(Error::ZeroOrder);
        }
        size("order of the extended partition", order)?;
        if interior.len() != multiplicities.len() {
            return Err(Error::CountMismatch {
                what: "multiplicities (one per interior breakpoint)",
                expected: interior.len(),
                got: multiplicities.len(),
            });
        }
        crate::domain::Interval::named("extended partition [a, b]", a, b)?;
        let breakpoints: Vec<f64> = std::iter::once(a)
            .chain(interior.iter().copied())
            .chain(std::iter::once(b))
            .collect();
        crate::domain::Partition::named(
            "extended partition breakpoints a < x₁ < … < x_k < b",
            breakpoints,
        )?;
        if let Some((index, &got)) = multiplicities
            .iter()
            .enumerate()
            .find(|(_, &m)| m == 0 || m > order)
        {
            return Err(Error::MultiplicityTooHigh {
                index,
                multiplicity: got,
                max: order,
            });
        }
        // 2m + K knots, checked before anything is allocated
        let total = multiplicities
            .iter()
            .try_fold(2 * order, |acc, &m| acc.checked_add(m))
            .unwrap_or(usize::MAX);
        size("knots of the extended partition (2m + K)", total)?;
        let outer = |start: f64, sign: f64| -> Result<Vec<f64>> {
            match ends {
                EndKnots::Clamped => Ok(vec![start; order - 1]),
                EndKnots::Spaced(h) => {
                    crate::error::positive("end knot spacing", h)?;
                    (1..order)
                        .map(|k| {
                            derived("outer knot a − kh or b + kh", start + sign * k as f64 * h)
                        })
                        .collect()
                }
            }
        };
        let mut knots = outer(a, -1.0)?;
        knots.reverse();
        // a spacing below the resolution of a and b would repeat outer knots
        let after = outer(b, 1.0)?;
        if let EndKnots::Spaced(h) = ends {
            let left = knots.iter().chain(std::iter::once(&a));
            let right = std::iter::once(&b).chain(after.iter());
            for side in [left.copied().collect::<Vec<_>>(), right.copied().collect()] {
                if side.windows(2).any(|w| w[1] <= w[0]) {
                    return Err(Error::NotPositive {
                        what: "end knot spacing (below the f64 resolution at the interval's ends)",
                        value: h,
                    });
                }
            }
        }
        knots.push(a);
        for (&x, &m) in interior.iter().zip(multiplicities) {
            knots.extend(std::iter::repeat_n(x, m));
        }
        knots.push(b);
        knots.extend(after);
        Self::try_new(knots)
    }

    /// The open (clamped) uniform knot vector of `count` control points and degree `degree`
    /// on `[a, b]`: `a` and `b` repeated `degree + 1` times, `count − degree − 1` equally
    /// spaced interior knots (`linspace`, both ends included, as MATLAB).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] if `count ≤ degree`; [`Error::TooLarge`] if the knot count
    /// `count + degree + 1` exceeds [`crate::error::MAX_ELEMENTS`]; the errors of
    /// [`KnotVector::extended_partition`] (repeated interior knots when `count` is too large
    /// for the width of `[a, b]` at `f64` resolution are [`Error::NotIncreasing`]).
    pub fn open_uniform(degree: usize, count: usize, a: f64, b: f64) -> Result<Self> {
        let order = size_sum("degree + 1 of the open uniform knot vector", degree, 1)?;
        if count <= degree {
            return Err(Error::TooFewPoints {
                what: "control points of the open uniform knot vector",
                needed: order,
                got: count,
            });
        }
        size_sum("knots of the open uniform knot vector", count, order)?;
        let pieces = count - degree;
        crate::domain::Interval::named("open uniform knot vector", a, b)?;
        let nodes = crate::domain::linspace(a, b, pieces + 1);
        let interior = &nodes[1..pieces];
        Self::extended_partition(
            a,
            b,
            interior,
            &vec![1; interior.len()],
            order,
            EndKnots::Clamped,
        )
    }

    /// The knots.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// Number of knots.
    pub fn len(&self) -> usize {
        self.knots.len()
    }

    /// Always false: a valid knot vector has at least two knots.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// How many knots equal `x` (0 if `x` is not a knot).
    pub fn multiplicity(&self, x: f64) -> usize {
        let below = self.knots.partition_point(|&k| k < x);
        let up_to = self.knots.partition_point(|&k| k <= x);
        up_to - below
    }

    /// The distinct knot values with their multiplicities, in increasing order.
    pub fn breakpoints(&self) -> Vec<(f64, usize)> {
        let mut out: Vec<(f64, usize)> = Vec::new();
        for &k in &self.knots {
            match out.last_mut() {
                Some((value, m)) if *value >= k => *m += 1,
                _ => out.push((k, 1)),
            }
        }
        out
    }

    /// Whether the vector is open (*aperto*, seed 001) for `degree`: its first and last knots
    /// have multiplicity `degree + 1`, so the curve interpolates its end control points.
    pub fn is_open(&self, degree: usize) -> bool {
        let b = self.breakpoints();
        let Some(order) = degree.checked_add(1) else {
            return false;
        };
        b.len() >= 2 && b[0].1 == order && b[b.len() - 1].1 == order
    }

    /// Whether the vector is uniform (seed 001): its distinct interior breakpoints — those
    /// strictly inside `[t₀, t_L]` — together with the two ends are equally spaced (to a
    /// relative `1e-12`). A vector without interior breakpoints is uniform.
    pub fn is_uniform(&self) -> bool {
        let b: Vec<f64> = self.breakpoints().into_iter().map(|(x, _)| x).collect();
        let step = b[1] - b[0];
        let scale = (b[b.len() - 1] - b[0]).abs();
        b.windows(2)
            .all(|w| ((w[1] - w[0]) - step).abs() <= 1e-12 * scale)
    }
}

impl std::fmt::Display for KnotVector {
    /// `{t₀, t₁, …, t_L}` with each knot in Rust's shortest round-trip form.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let parts: Vec<String> = self.knots.iter().map(|k| format!("{k}")).collect();
        write!(f, "{{{}}}", parts.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slides_extended_partition() {
        // seed 001: [0,1], m = 4, Δ = {1/2, 3/4}, M = {1, 2}
        let k = KnotVector::extended_partition(
            0.0,
            1.0,
            &[0.5, 0.75],
            &[1, 2],
            4,
            EndKnots::Spaced(0.25),
        )
        .unwrap();
        let printed = [
            -0.75, -0.5, -0.25, 0.0, 0.5, 0.75, 0.75, 1.0, 1.25, 1.5, 1.75,
        ];
        assert_eq!(k.knots(), &printed, "Δ* of seed 001");
        // 2m + K knots
        assert_eq!(k.len(), 2 * 4 + 3);
    }

    #[test]
    fn open_uniform_is_open_and_uniform() {
        let k = KnotVector::open_uniform(3, 7, 0.0, 1.0).unwrap();
        assert_eq!(
            k.knots(),
            &[0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0]
        );
        assert!(k.is_open(3) && k.is_uniform());
        let non_uniform = KnotVector::new(vec![0.0, 0.0, 0.3, 1.0, 1.0]);
        assert!(non_uniform.is_open(1) && !non_uniform.is_uniform());
    }

    #[test]
    fn breakpoints_and_multiplicities() {
        let k = KnotVector::new(vec![0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0]);
        assert_eq!(
            k.breakpoints(),
            vec![(0.0, 2), (1.0, 1), (2.0, 1), (3.0, 1), (4.0, 1), (5.0, 2)]
        );
    }
}
