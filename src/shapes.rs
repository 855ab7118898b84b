//! Exact test shapes with dense reference samples: the conics, sinusoid and rectangle that
//! seed 004 interpolates (parameters from `spec/seed004.md` §4 where the paper states none).
//!
//! Each shape is an exact [`ParametricCurve`] (generic over the number type, so curvature and
//! tangents come from dual numbers) with a [`Shape::reference`] polyline dense enough to
//! measure interpolation errors against, and the tolerance the comparison uses: 1 % of the
//! larger side of the bounding box ([`TOLERANCE_FRACTION`], spec decision A12 — about the
//! width of a pen stroke on the paper's figures).

use crate::curve::ParametricCurve;
use crate::error::{Error, Result};
use nalgebra::Vector2;
use num_dual::DualNum;
use std::f64::consts::{PI, TAU};

/// The error allowed in seed 004's comparison, as a fraction of the larger bounding-box side:
/// the relaxed cubic through 11 equally spaced points of a closed circle is the first under
/// it (1.0 %), which is the paper's printed count (spec §4 calibration).
pub const TOLERANCE_FRACTION: f64 = 0.01;

/// A test shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// The unit circle `(cos t, sin t)`, `t ∈ [0, 2π]`.
    Circle,
    /// The ellipse `(cos t, ratio · sin t)`, `t ∈ [0, 2π]` (seed 004: ratios 0.7 and 0.4).
    Ellipse {
        /// Minor over major semi-axis, in `(0, 1]`.
        ratio: f64,
    },
    /// The parabola `y = x²` for `|x| ≤ half_width` (2: "more closed", 1: "more open").
    Parabola {
        /// The largest `|x|`.
        half_width: f64,
    },
    /// The hyperbola branch `y = b √(1 + x²)` for `|x| ≤ 2` (`b = 2`: "more closed",
    /// `b = ½`: "more open").
    Hyperbola {
        /// The semi-axis `b`.
        b: f64,
    },
    /// `y = sin x` for `x ∈ [0, 2π · periods]`.
    Sinusoid {
        /// Number of periods.
        periods: f64,
    },
    /// The rectangle `[−w/2, w/2] × [−h/2, h/2]`, run counter-clockwise from `(w/2, −h/2)`
    /// by arc length (seed 004: 2 : 1).
    Rectangle {
        /// Width.
        width: f64,
        /// Height.
        height: f64,
    },
}

impl Shape {
    /// A checked shape: every parameter finite and positive (an ellipse ratio at most 1, a
    /// parabola half-width, hyperbola `b` and rectangle sides at most `1e100`, at most `1e6`
    /// periods of the sinusoid).
    ///
    /// # Errors
    /// [`Error::NotPositive`] for a parameter that is not finite and positive;
    /// [`Error::OutOfDomain`] beyond the bounds above.
    pub fn validated(self) -> Result<Self> {
        let (what, value, max) = match self {
            Shape::Circle => return Ok(self),
            Shape::Ellipse { ratio } => ("ellipse axis ratio", ratio, 1.0),
            Shape::Parabola { half_width } => ("parabola half-width", half_width, 1e100),
            Shape::Hyperbola { b } => ("hyperbola semi-axis b", b, 1e100),
            Shape::Sinusoid { periods } => ("sinusoid periods", periods, 1e6),
            Shape::Rectangle { width, height } => {
                crate::error::positive("rectangle height", height)?;
                check_max("rectangle height", height, 1e100)?;
                ("rectangle width", width, 1e100)
            }
        };
        crate::error::positive(what, value)?;
        check_max(what, value, max)?;
        Ok(self)
    }

    /// Whether the shape is a closed curve.
    pub fn is_closed(&self) -> bool {
        matches!(
            self,
            Shape::Circle | Shape::Ellipse { .. } | Shape::Rectangle { .. }
        )
    }

    /// A short name (`circle`, `ellipse-0.7`, …), as output ids use it.
    pub fn name(&self) -> String {
        match *self {
            Shape::Circle => "circle".into(),
            Shape::Ellipse { ratio } => format!("ellipse-{ratio}"),
            Shape::Parabola { half_width } => format!("parabola-{half_width}"),
            Shape::Hyperbola { b } => format!("hyperbola-{b}"),
            Shape::Sinusoid { periods } => format!("sinusoid-{periods}"),
            Shape::Rectangle { width, height } => format!("rectangle-{width}x{height}"),
        }
    }

    /// `(x_min, x_max, y_min, y_max)`, exact.
    pub fn bounding_box(&self) -> (f64, f64, f64, f64) {
        match *self {
            Shape::Circle => (-1.0, 1.0, -1.0, 1.0),
            Shape::Ellipse { ratio } => (-1.0, 1.0, -ratio, ratio),
            Shape::Parabola { half_width: x } => (-x, x, 0.0, x * x),
            Shape::Hyperbola { b } => (-2.0, 2.0, b, b * 5f64.sqrt()),
            Shape::Sinusoid { periods } => {
                let (lo, hi) = if periods >= 0.75 {
                    (-1.0, 1.0)
                } else if periods >= 0.25 {
                    ((TAU * periods).sin().min(0.0), 1.0)
                } else {
                    (0.0, (TAU * periods).sin())
                };
                (0.0, TAU * periods, lo, hi)
            }
            Shape::Rectangle { width, height } => {
                (-width / 2.0, width / 2.0, -height / 2.0, height / 2.0)
            }
        }
    }

    /// The comparison's tolerance: [`TOLERANCE_FRACTION`] of the larger bounding-box side.
    pub fn tolerance(&self) -> f64 {
        let (x0, x1, y0, y1) = self.bounding_box();
        TOLERANCE_FRACTION * (x1 - x0).max(y1 - y0)
    }

    /// About `samples + 1` points of the shape at equally spaced parameters, the closed ones
    /// ending exactly at their first point: the reference polyline interpolants are measured
    /// against. The rectangle's samples are split between its sides in proportion to their
    /// lengths, so every corner is a sample and the polyline is the rectangle exactly.
    ///
    /// # Errors
    /// The errors of [`Shape::validated`]; [`Error::TooFewSamples`] below 4;
    /// [`Error::TooLarge`] beyond [`crate::error::MAX_ELEMENTS`].
    pub fn reference(&self, samples: usize) -> Result<Vec<Vector2<f64>>> {
        self.validated()?;
        crate::error::samples("shape reference samples", samples)?;
        if samples < 4 {
            return Err(Error::TooFewSamples {
                what: "shape reference samples (at least 4)",
                got: samples,
            });
        }
        let mut points = match *self {
            Shape::Rectangle { width, height } => {
                let corners = self.corners();
                let perimeter = 2.0 * (width + height);
                let mut out = Vec::with_capacity(samples + 1);
                for k in 0..4 {
                    let (a, b) = (corners[k], corners[(k + 1) % 4]);
                    let side = if k % 2 == 0 { height } else { width };
                    let n = ((samples as f64 * side / perimeter).round() as usize).max(1);
                    out.extend((0..n).map(|i| a + (b - a) * (i as f64 / n as f64)));
                }
                out.push(corners[0]);
                out
            }
            _ => self.polyline(samples + 1)?,
        };
        if self.is_closed() {
            let n = points.len();
            points[n - 1] = points[0];
        }
        Ok(points)
    }

    /// The rectangle's corners, counter-clockwise from `(w/2, −h/2)` (empty for the others).
    pub fn corners(&self) -> Vec<Vector2<f64>> {
        match *self {
            Shape::Rectangle { width, height } => rectangle_corners(width, height).to_vec(),
            _ => Vec::new(),
        }
    }
}

fn rectangle_corners(width: f64, height: f64) -> [Vector2<f64>; 4] {
    let (x, y) = (width / 2.0, height / 2.0);
    [
        Vector2::new(x, -y),
        Vector2::new(x, y),
        Vector2::new(-x, y),
        Vector2::new(-x, -y),
    ]
}

fn check_max(what: &'static str, value: f64, max: f64) -> Result<()> {
    if value <= max {
        Ok(())
    } else {
        Err(Error::OutOfDomain {
            what,
            value,
            start: 0.0,
            end: max,
        })
    }
}

impl ParametricCurve<2> for Shape {
    /// The exact point: angle for the circle and ellipses, abscissa for the parabola,
    /// hyperbola and sinusoid, arc length for the rectangle (its corners at the breaks).
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> Vector2<D> {
        match *self {
            Shape::Circle => Vector2::new(t.cos(), t.sin()),
            Shape::Ellipse { ratio } => Vector2::new(t.cos(), t.sin() * ratio),
            Shape::Parabola { .. } => Vector2::new(t, t * t),
            Shape::Hyperbola { b } => Vector2::new(t, (t * t + 1.0).sqrt() * b),
            Shape::Sinusoid { .. } => Vector2::new(t, t.sin()),
            Shape::Rectangle { width, height } => {
                let corners = rectangle_corners(width, height);
                let sides = [height, width, height, width];
                // the sides' parameter intervals; the side of t is one formula
                let mut nodes = [0.0; 5];
                for k in 0..4 {
                    nodes[k + 1] = nodes[k] + sides[k];
                }
                let k = crate::branch::piece(&nodes, &t);
                let start = nodes[k];
                let (a, b) = (corners[k], corners[(k + 1) % 4]);
                let s = (t - start) / sides[k];
                Vector2::new(s * (b.x - a.x) + a.x, s * (b.y - a.y) + a.y)
            }
        }
    }

    fn domain(&self) -> (f64, f64) {
        match *self {
            Shape::Circle | Shape::Ellipse { .. } => (0.0, TAU),
            Shape::Parabola { half_width } => (-half_width, half_width),
            Shape::Hyperbola { .. } => (-2.0, 2.0),
            Shape::Sinusoid { periods } => (0.0, 2.0 * PI * periods),
            Shape::Rectangle { width, height } => (0.0, 2.0 * (width + height)),
        }
    }

    /// The rectangle's side of `t` (its corners are the breaks); the other shapes are one
    /// formula.
    fn span_at(&self, t: f64) -> Option<crate::domain::Span> {
        let Shape::Rectangle { width, height } = *self else {
            return None;
        };
        let sides = [height, width, height, width];
        let mut breaks = [0.0; 5];
        for k in 0..4 {
            breaks[k + 1] = breaks[k] + sides[k];
        }
        // the side eval uses: the last k ≤ 3 with t ≥ breaks[k]
        let k = (1..4).take_while(|&k| t >= breaks[k]).count();
        Some(crate::domain::Span::of(&breaks, k))
    }
}
