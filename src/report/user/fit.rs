//! One of seed 004's methods through a user's points ([`Fit`]): the curve sampled as CSV, drawn
//! over its points, as an SVG path of cubic Béziers, and its formulas piece by piece.
//!
//! ```
//! use nalgebra::Vector2;
//! use splinelab::report::user::fit::{Fit, FormulaStyle};
//! use splinelab::{CubicEnd, Method};
//! let points = [(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (3.0, 1.0)].map(|(x, y)| Vector2::new(x, y));
//! let fit = Fit::try_new(&points, Method::Cubic { end: CubicEnd::Relaxed }, false)?;
//! let csv = fit.samples_csv(4)?; // t,x,y: 4 samples a piece and the end
//! assert_eq!(csv.lines().count(), 1 + 3 * 4 + 1);
//! let formulas = fit.formulas(FormulaStyle::Plain)?;
//! assert!(formulas.starts_with("piece 1 of 3"));
//! # Ok::<(), splinelab::report::Error>(())
//! ```

use crate::bezier::from_curve::{cubic_segments, CubicSegment};
use crate::curve::ParametricCurve;
use crate::interp::methods::{Interpolant, Method};
use crate::printed::decimal;
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::plot2d::{xy, Figure2d, Panel, Series, Style, GREY, INK};
use crate::report::style::LINE_PALETTE;
use crate::report::Legend;
use crate::symbolic::curve_formulas_local;
use nalgebra::Vector2;
use std::fmt::Write as _;

/// A method's curve through a user's points.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The method with its parameter.
    pub method: Method,
    /// Whether the curve is closed (as the paper closes curves: [`Method::prepared`]).
    pub closed: bool,
    /// The points given.
    pub points: Vec<Vector2<f64>>,
    /// The curve.
    pub curve: Interpolant,
}

/// The most point markers a fit's figure draws (beyond, every k-th point).
pub const MAX_MARKERS: usize = 400;

/// How [`Fit::formulas`] writes the formulas.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FormulaStyle {
    /// Plain text (`1 + 3*u^2 - 2*u^3`), one line a coordinate.
    Plain,
    /// LaTeX, one `align*` environment a piece.
    Latex,
}

impl Fit {
    /// The curve of `method` through `points` (a B-spline's points are its control polygon),
    /// closed when `closed`.
    ///
    /// # Errors
    /// The errors of [`Method::curve`] (too few points, coincident neighbours, a bad
    /// parameter, non-finite coordinates, points through which the method has no curve) as
    /// [`crate::report::Error::Core`]; [`crate::error::Error::NonFinite`] if the curve is not finite
    /// at a break between its pieces.
    pub fn try_new(points: &[Vector2<f64>], method: Method, closed: bool) -> Result<Fit> {
        let curve = method.curve(points, closed)?;
        for t in curve.breaks() {
            curve.try_point(t)?;
        }
        Ok(Fit {
            method,
            closed,
            points: points.to_vec(),
            curve,
        })
    }

    /// Whether the points given end with a repeat of the first that closes the ring, dropped
    /// for the closed curve ([`crate::interp::methods::ring`]).
    pub fn dropped_ring_repeat(&self) -> bool {
        crate::interp::methods::ring(&self.points, self.closed).len() < self.points.len()
    }

    /// The points the method draws through: the given ones and a closed curve's repeats.
    pub fn drawn_points(&self) -> Vec<Vector2<f64>> {
        self.method.prepared(&self.points, self.closed)
    }

    /// `(t, point)` at `per_piece` equal steps of every piece and at the curve's end.
    ///
    /// # Errors
    /// [`crate::error::Error::TooFewSamples`] below 2 samples a piece; [`crate::error::Error::TooLarge`] if the
    /// samples exceed [`crate::error::MAX_ELEMENTS`]; [`crate::error::Error::NonFinite`] where the
    /// curve is not finite.
    pub fn samples(&self, per_piece: usize) -> Result<Vec<(f64, Vector2<f64>)>> {
        if per_piece < 2 {
            return Err(crate::error::Error::TooFewSamples {
                what: "samples per piece",
                got: per_piece,
            }
            .into());
        }
        let breaks = self.curve.breaks();
        let pieces = breaks.len().saturating_sub(1);
        let total = pieces
            .checked_mul(per_piece)
            .and_then(|n| n.checked_add(1))
            .filter(|&n| n <= crate::error::MAX_ELEMENTS)
            .ok_or(crate::error::Error::TooLarge {
                what: "curve samples",
                got: pieces.saturating_mul(per_piece),
                max: crate::error::MAX_ELEMENTS,
            })?;
        let mut out = Vec::with_capacity(total);
        for w in breaks.windows(2) {
            for k in 0..per_piece {
                let t = w[0] + (w[1] - w[0]) * k as f64 / per_piece as f64;
                out.push((t, self.curve.try_point(t)?));
            }
        }
        if let Some(&end) = breaks.last() {
            out.push((end, self.curve.try_point(end)?));
        }
        Ok(out)
    }

    /// [`Fit::samples`] as CSV: a header `t,x,y`, then one line a sample, every number the
    /// shortest decimal that reads back to the same `f64`.
    ///
    /// # Errors
    /// As [`Fit::samples`].
    pub fn samples_csv(&self, per_piece: usize) -> Result<String> {
        let samples = self.samples(per_piece)?;
        let mut csv = String::from("t,x,y\n");
        for (t, p) in samples {
            let _ = writeln!(csv, "{},{},{}", decimal(t), decimal(p.x), decimal(p.y));
        }
        Ok(csv)
    }

    /// The curve as cubic Bézier segments ([`cubic_segments`]): exact for the cubic pieces of
    /// the cardinal and cubic splines, B-splines of order ≤ 4 and polygons; the Angular
    /// spline's and higher-order B-splines' pieces halved until within `tolerance`.
    ///
    /// # Errors
    /// As [`cubic_segments`].
    pub fn bezier(&self, tolerance: f64) -> Result<Vec<CubicSegment<2>>> {
        Ok(cubic_segments(&self.curve, tolerance)?)
    }

    /// The curve as a standalone SVG document of cubic Béziers ([`Fit::bezier`] within
    /// `tolerance`, by default 10⁻⁴ of the size of the points' bounding box;
    /// [`crate::report::export::svg_document`] with a stroke of 2·10⁻³ of that size).
    ///
    /// # Errors
    /// As [`Fit::bezier`].
    pub fn svg_document(&self, tolerance: Option<f64>) -> Result<String> {
        let size = crate::study::outline::size(&[crate::input::Contour {
            points: self.drawn_points(),
            closed: false,
        }])
        .max(f64::MIN_POSITIVE);
        let segments = self.bezier(tolerance.unwrap_or(1e-4 * size))?;
        crate::report::export::svg_document(&segments, 2e-3 * size)
    }

    /// The curve over its points (a B-spline's control polygon drawn), titled with the method.
    ///
    /// # Errors
    /// As [`ParametricCurve::polyline`].
    pub fn figure(&self) -> Result<Figure> {
        let drawn = self.drawn_points();
        let title = format!(
            "{} {} {} points{}",
            self.method.legend(),
            if matches!(self.method, Method::BSpline { .. }) {
                "on the control polygon of"
            } else {
                "through"
            },
            self.points.len(),
            if self.closed { ", closed" } else { "" }
        );
        let pieces = self.curve.breaks().len().saturating_sub(1).max(1);
        let curve = self
            .curve
            .polyline(pieces.saturating_mul(64).min(1 << 16))?;
        // markers that leave the curve visible: smaller as the points grow many, and at most
        // MAX_MARKERS of them (every k-th point, said in the legend)
        let step = drawn.len().div_ceil(MAX_MARKERS).max(1);
        let marked: Vec<Vector2<f64>> = drawn.iter().step_by(step).copied().collect();
        let size = match drawn.len() {
            0..=100 => 5,
            101..=1000 => 3,
            _ => 2,
        };
        let label = if step > 1 {
            format!("points (one in {step} of {} marked)", drawn.len())
        } else {
            "points".to_string()
        };
        let mut panel = Panel::new("", "x", "y").equal();
        if matches!(self.method, Method::BSpline { .. }) {
            panel = panel.with(Series::line("control polygon", xy(&drawn), GREY).width(1));
        }
        // the curve drawn over the markers
        let panel =
            panel
                .with(Series::line(label, xy(&marked), INK).styled(Style::Crosses(size)))
                .with(
                    Series::line("curve", xy(&curve), LINE_PALETTE[0])
                        .width(if drawn.len() > 1000 { 2 } else { 3 }),
                );
        Ok(Figure::from(Figure2d::new(title, vec![panel], (1, 1))).with_size(800, 640))
    }

    /// The ranges of `t` on which one formula gives the curve, piece by piece: each piece
    /// `[tᵢ, tᵢ₊₁]` cut where the curve's evaluation changes formula within it
    /// ([`ParametricCurve::span_at`]: an Angular inflection piece's two arcs).
    pub fn formula_ranges(&self) -> Vec<Vec<(f64, f64)>> {
        self.curve
            .breaks()
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let mut ranges = Vec::new();
                let mut lo = a;
                // at most a few formulas a piece; the bound keeps a curve whose spans do not
                // advance from looping
                for _ in 0..64 {
                    let hi = match self.curve.span_at(lo) {
                        Some(span) if span.hi > lo && span.hi < b => span.hi,
                        _ => b,
                    };
                    ranges.push((lo, hi));
                    if hi >= b {
                        break;
                    }
                    lo = hi;
                }
                ranges
            })
            .collect()
    }

    /// The formulas of `x` and `y` on every piece, in the local variable `u = t − t₀` of the
    /// range they hold on ([`curve_formulas_local`], traced from the same generic code that
    /// evaluates the curve): one range a piece, or one an arc where a piece changes formula
    /// within it ([`Fit::formula_ranges`]: an Angular inflection piece's two arcs, each with
    /// its own range). Every formula is checked against the curve at 17 parameters spread
    /// over the whole range it is printed for, ends included.
    ///
    /// # Errors
    /// As [`curve_formulas_local`] (a formula beyond the size limits);
    /// [`crate::error::Error::FormulaCheck`] where a formula is not the curve on its range.
    pub fn formulas(&self, style: FormulaStyle) -> Result<String> {
        let ranges = self.formula_ranges();
        let pieces = ranges.len();
        let mut out = String::new();
        for (i, piece) in ranges.iter().enumerate() {
            for (k, &(a, b)) in piece.iter().enumerate() {
                let f = curve_formulas_local(&self.curve, 0.5 * (a + b))?;
                let origin = f.origin.unwrap_or(0.0);
                self.check_formulas(&f.point, origin, a, b)?;
                let arc = if piece.len() > 1 {
                    format!(", arc {} of {}", k + 1, piece.len())
                } else {
                    String::new()
                };
                let (o, a, b) = (
                    crate::printed::number(origin),
                    crate::printed::number(a),
                    crate::printed::number(b),
                );
                match style {
                    FormulaStyle::Plain => {
                        let _ = writeln!(
                            out,
                            "piece {} of {pieces}{arc}, t in [{a}, {b}], u = t - {o}:",
                            i + 1
                        );
                        for (name, x) in ["x", "y"].iter().zip(&f.point) {
                            let _ = writeln!(out, "  {name}(u) = {}", x.plain());
                        }
                    }
                    FormulaStyle::Latex => {
                        let _ = writeln!(
                            out,
                            "% piece {} of {pieces}{arc}, t \\in [{a}, {b}], u = t - {o}\n\\begin{{align*}}",
                            i + 1
                        );
                        for (name, x) in ["x", "y"].iter().zip(&f.point) {
                            let _ = writeln!(out, "  {name}(u) &= {} \\\\", x.latex());
                        }
                        out.push_str("\\end{align*}\n");
                    }
                }
            }
        }
        Ok(out)
    }

    /// That the formulas `point` (in `u = t − origin`) give the curve on `[a, b]`: at 17
    /// parameters spread over it, ends included, each coordinate within `10⁻⁹` of the curve's
    /// size (rounding of the two evaluations is far below; a formula of another piece or arc
    /// misses by the curve's own scale).
    fn check_formulas(
        &self,
        point: &[crate::symbolic::Formula],
        origin: f64,
        a: f64,
        b: f64,
    ) -> Result<()> {
        const SAMPLES: usize = 16;
        let drawn = self.drawn_points();
        let scale = drawn
            .iter()
            .map(|p| p.amax())
            .fold(0.0f64, f64::max)
            .max(f64::MIN_POSITIVE);
        let allowed = 1e-9 * scale;
        for k in 0..=SAMPLES {
            let t = a + (b - a) * (k as f64 / SAMPLES as f64);
            let curve = self.curve.try_point(t)?;
            for (c, formula) in point.iter().enumerate() {
                let value = formula.eval(&[t - origin]);
                if (value - curve[c]).abs() > allowed || value.is_nan() {
                    return Err(crate::error::Error::FormulaCheck {
                        formula: format!(
                            "{} = {} on t in [{}, {}], at t = {}",
                            ["x(u)", "y(u)"][c.min(1)],
                            formula.plain(),
                            crate::printed::number(a),
                            crate::printed::number(b),
                            crate::printed::number(t)
                        ),
                        evaluated: value,
                        traced: curve[c],
                        bound: allowed,
                    }
                    .into());
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points whose middle Angular piece has an inflection: two arcs, two formulas.
    fn inflection() -> Fit {
        let points =
            [(0.0, 0.0), (1.0, 0.0), (2.0, 1.0), (3.0, 1.0)].map(|(x, y)| Vector2::new(x, y));
        Fit::try_new(&points, Method::Angular, false).unwrap()
    }

    #[test]
    fn an_inflection_piece_prints_each_arc_on_its_own_range() {
        let fit = inflection();
        assert_eq!(fit.formula_ranges(), vec![vec![(0.0, 0.5), (0.5, 1.0)]]);
        let text = fit.formulas(FormulaStyle::Plain).unwrap();
        assert!(
            text.contains("piece 1 of 1, arc 1 of 2, t in [0, 1/2], u = t - 0:"),
            "{text}"
        );
        assert!(
            text.contains("piece 1 of 1, arc 2 of 2, t in [1/2, 1], u = t - 1/2:"),
            "{text}"
        );
    }

    #[test]
    fn a_formula_is_refused_on_a_range_where_it_is_not_the_curve() {
        let fit = inflection();
        // the second arc's formulas claimed for the whole piece, as one trace at the piece's
        // middle would: refused
        let f = curve_formulas_local(&fit.curve, 0.75).unwrap();
        let origin = f.origin.unwrap();
        assert!(fit.check_formulas(&f.point, origin, 0.5, 1.0).is_ok());
        let err = fit.check_formulas(&f.point, origin, 0.0, 1.0).unwrap_err();
        assert!(
            err.to_string()
                .contains("on t in [0, 1], at t = 0 gives 4.0169"),
            "{err}"
        );
    }
}
