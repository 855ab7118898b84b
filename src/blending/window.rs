//! Curves from 4-point blending windows sliding along the data (seed 003): the Lagrange
//! window and the printed `bspline` procedure with its end-point repetition.

use crate::blending::functions::{printed_setbval, Blending};
use crate::curve::ParametricCurve;
use crate::error::{finite_points, Error, Result};
use nalgebra::SVector;
use num_dual::DualNum;

/// A curve made of cubic segments, segment `k` being `Σᵢ Q_{k+i} bᵢ(u)`, `u ∈ [0, 1]`, over a
/// sequence `Q` of window points and one of the [`Blending`] families.
///
/// - [`WindowCurve::lagrange`]: `Q = P` and segment `k` runs from `P_{k+1}` to `P_{k+2}`
///   (seed 003: "nel tratto P2-P3 uso i punti P1-P4"); the first and last data segments, which
///   have no full window, are the first and last window's cubic on `u ∈ [−1, 0]` and
///   `u ∈ [1, 2]` (our choice; the notes only treat the inner segments).
/// - [`WindowCurve::printed_bspline`]: `Q` is `P` with the first point repeated three times
///   and the last four times, as the printed `bspline` procedure pads it, segments
///   `k = 0 … n` (the listing's `make_one(1 … nd+1)`).
#[derive(Debug, Clone, PartialEq)]
pub struct WindowCurve<const N: usize> {
    window_points: Vec<SVector<f64, N>>,
    blending: Blending,
    segments: usize,
}

impl<const N: usize> WindowCurve<N> {
    /// The Lagrange sliding-window curve through `points` (at least 4).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 4 points; [`Error::NonFinite`].
    pub fn lagrange(points: &[SVector<f64, N>]) -> Result<Self> {
        check("Lagrange window points", points, 4)?;
        Ok(Self {
            window_points: points.to_vec(),
            blending: Blending::Lagrange,
            segments: points.len() - 1,
        })
    }

    /// The curve of the printed `bspline` procedure (seed 003, `EGD_4BSPLINE`): the data
    /// padded as `xx = (P₀, P₀, P₀, P₁, …, P_{n−1}, P_{n−1}, P_{n−1}, P_{n−1})` and one uniform
    /// cubic B-spline segment per `make_one(k)`, `k = 1 … n + 1`. The triple first point makes
    /// the curve start at `P₀`; the quadruple last point makes it end at `P_{n−1}`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] below 3 points (the listing draws a plain segment for 2 and
    /// nothing for fewer); [`Error::NonFinite`].
    pub fn printed_bspline(points: &[SVector<f64, N>]) -> Result<Self> {
        check("bspline points", points, 3)?;
        let (first, last) = (points[0], points[points.len() - 1]);
        let mut q = vec![first, first];
        q.extend_from_slice(points);
        q.extend([last; 3]);
        Ok(Self {
            segments: points.len() + 1,
            window_points: q,
            blending: Blending::UniformBSpline,
        })
    }

    /// The blending family.
    pub fn blending(&self) -> Blending {
        self.blending
    }

    /// The window points `Q` (the padded data for the printed B-spline).
    pub fn window_points(&self) -> &[SVector<f64, N>] {
        &self.window_points
    }

    /// Number of cubic segments (for the Lagrange curve, one per pair of consecutive points).
    pub fn segments(&self) -> usize {
        self.segments
    }

    /// The four window points segment `k` blends (`k` clamped to the segments): `Q_k … Q_{k+3}`
    /// for the printed B-spline; for the Lagrange curve the window of the data segment `k`
    /// (the first and last data segments use the first and last full window).
    pub fn window_of(&self, k: usize) -> &[SVector<f64, N>] {
        let k = k.min(self.segments.saturating_sub(1));
        let w = match self.blending {
            Blending::UniformBSpline => k,
            Blending::Lagrange => k.saturating_sub(1).min(self.window_points.len() - 4),
        };
        &self.window_points[w..w + 4]
    }

    /// `Σᵢ Q_{k+i} bᵢ(u)` for window `k`, any `u` and number type.
    fn window<D: DualNum<Primitive = f64> + Copy>(&self, k: usize, u: D) -> SVector<D, N> {
        self.blending
            .weights(u)
            .into_iter()
            .zip(&self.window_points[k..k + 4])
            .fold(SVector::zeros(), |acc, (w, q)| acc + q.map(D::from) * w)
    }
}

impl<const N: usize> ParametricCurve<N> for WindowCurve<N> {
    /// The point at the global parameter `s ∈ [0, segments]` (segment `k = ⌊s⌋`, local
    /// `u = s − k`; `s = segments` is the end of the last segment), for any number type.
    /// Outside the range the end segments are extrapolated.
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D) -> SVector<D, N> {
        let k = crate::branch::unit_piece(self.segments, &s);
        let u = s - k as f64;
        match self.blending {
            Blending::UniformBSpline => self.window(k, u),
            // data segment 0 is the first window on [−1, 0], the last one the last window on
            // [1, 2], segment k in between window k − 1 on [0, 1]
            Blending::Lagrange if k == 0 => self.window(0, u - 1.0),
            Blending::Lagrange if k == self.segments - 1 => self.window(k - 2, u + 1.0),
            Blending::Lagrange => self.window(k - 1, u),
        }
    }

    /// `[0, segments]`.
    fn domain(&self) -> (f64, f64) {
        (0.0, self.segments as f64)
    }

    /// `[k, k + 1)`, segment `k = ⌊s⌋`.
    fn span_at(&self, s: f64) -> Option<crate::domain::Span> {
        Some(crate::branch::unit_span(s, self.segments))
    }
}

/// The vertices the printed `bspline` procedure draws with `nb` line sections per segment
/// (`nb = 6` in the listing): the start `xx[0] = P₀`, then for `make_one(k)`, `k = 1 … n+1`,
/// the points at `u = j/nb`, `j = 0 … nb−1`, with the `setbval` weights as printed. Note that
/// `u = 1` is never sampled, so the drawn polyline stops at `u = (nb−1)/nb` of the last
/// segment, `(P_{n−2} − P_{n−1})/(6 nb³)` short of the last point (a hair's breadth).
///
/// # Errors
/// As [`WindowCurve::printed_bspline`]; [`Error::TooFewSamples`] for `nb = 0`;
/// [`Error::TooLarge`] if the vertices exceed [`crate::error::MAX_ELEMENTS`].
pub fn printed_bspline_polyline<const N: usize>(
    points: &[SVector<f64, N>],
    nb: usize,
) -> Result<Vec<SVector<f64, N>>> {
    if nb == 0 {
        return Err(Error::TooFewSamples {
            what: "line sections per segment (nb)",
            got: 0,
        });
    }
    let curve = WindowCurve::printed_bspline(points)?;
    let segments = crate::error::size_sum("bspline segments", points.len(), 1)?;
    crate::error::size_sum(
        "bspline polyline vertices",
        crate::error::size_product("bspline polyline vertices", segments, nb)?,
        1,
    )?;
    let b = printed_setbval(nb)?;
    let xx = curve.window_points();
    let mut out = vec![xx[0]];
    for k in 1..=points.len() + 1 {
        for weights in &b {
            out.push(
                (0..4)
                    .map(|i| xx[k + i - 1] * weights[i])
                    .fold(SVector::zeros(), |acc, v| acc + v),
            );
        }
    }
    Ok(out)
}

fn check<const N: usize>(
    what: &'static str,
    points: &[SVector<f64, N>],
    needed: usize,
) -> Result<()> {
    if points.len() < needed {
        return Err(Error::TooFewPoints {
            what,
            needed,
            got: points.len(),
        });
    }
    finite_points(what, points)
}
