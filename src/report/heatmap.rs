//! Values over a rectangle drawn as colours, with a colour bar: the error map of a spline
//! surface, or any sampled function of two parameters.

use crate::grid::Grid;
use crate::report::plot2d::axis_range;
use crate::report::plot2d::Drawn;
use crate::report::style::{colormap, FONT, LABEL_SIZE, TICK_SIZE, TITLE_SIZE};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// How values map to colours.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ColorScale {
    /// Linear from the smallest to the largest value.
    Linear,
    /// Logarithmic over this many decades below the largest value (smaller values, zeros
    /// included, take the lowest colour).
    Log {
        /// Decades shown.
        decades: f64,
    },
}

/// A colour map of `values[i][j]` at `(x[i], y[j])`.
#[derive(Debug, Clone)]
pub struct HeatMap {
    /// Title.
    pub title: String,
    /// x-axis label.
    pub x_label: String,
    /// y-axis label.
    pub y_label: String,
    /// Label of the colour bar.
    pub bar_label: String,
    /// Sample positions along x (increasing).
    pub x: Vec<f64>,
    /// Sample positions along y (increasing).
    pub y: Vec<f64>,
    /// The values, `x.len() × y.len()`.
    pub values: Grid<f64>,
    /// Vertical lines to draw (e.g. patch boundaries in u).
    pub x_lines: Vec<f64>,
    /// Horizontal lines to draw (patch boundaries in v).
    pub y_lines: Vec<f64>,
    /// The colour scale.
    pub scale: ColorScale,
    /// A line of text under the map.
    pub footnote: Option<String>,
}

impl HeatMap {
    /// Range of the finite values, `(lo, hi)` with `lo < hi`.
    fn value_range(&self) -> (f64, f64) {
        let finite = self
            .values
            .as_slice()
            .iter()
            .copied()
            .filter(|v| v.is_finite());
        let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        match self.scale {
            ColorScale::Log { decades } => {
                // at least 10⁻³⁰⁰ · 10^decades, so the lower end stays a normal number
                let hi = hi.clamp(1e-300, f64::MAX);
                let decades = if decades.is_finite() { decades } else { 6.0 };
                let decades = decades.clamp(0.5, 300.0).min(hi.log10() + 300.0);
                (hi * 10f64.powf(-decades), hi)
            }
            ColorScale::Linear if lo.is_finite() && hi > lo => {
                axis_range(lo, hi, 0.0).unwrap_or((0.0, 1.0))
            }
            ColorScale::Linear if lo.is_finite() => axis_range(lo, lo, 0.0).unwrap_or((0.0, 1.0)),
            ColorScale::Linear => (0.0, 1.0),
        }
    }

    /// Position of `v` on the colour scale, in `[0, 1]`.
    fn level(&self, v: f64, (lo, hi): (f64, f64)) -> f64 {
        let l = match self.scale {
            ColorScale::Log { .. } => (v.max(lo) / lo).log10() / (hi / lo).log10(),
            ColorScale::Linear => (v - lo) / (hi - lo),
        };
        if l.is_finite() {
            l.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// Draws the map into `area` (already filled with the background).
    ///
    /// # Errors
    /// Whatever the backend reports.
    pub fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        let range = self.value_range();
        let (x0, x1) = ends(&self.x);
        let (y0, y1) = ends(&self.y);
        // cells and lines are clamped to the map, so no pixel lies far outside it
        let (cx, cy) = (|x: f64| x.clamp(x0, x1), |y: f64| y.clamp(y0, y1));
        let (main, bar) = area.split_horizontally(area.dim_in_pixel().0.saturating_sub(170));
        let mut chart = ChartBuilder::on(&main)
            .caption(&self.title, (FONT, TITLE_SIZE - 4))
            .margin(20)
            .x_label_area_size(55)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .axis_desc_style((FONT, LABEL_SIZE))
            .label_style((FONT, TICK_SIZE))
            .draw()?;
        // halfway to the neighbours (in halves, so no sum overflows)
        let half = |v: &[f64], i: usize| {
            let lo = if i == 0 {
                v[0]
            } else {
                0.5 * v[i - 1] + 0.5 * v[i]
            };
            let hi = if i + 1 == v.len() {
                v[i]
            } else {
                0.5 * v[i] + 0.5 * v[i + 1]
            };
            (lo, hi)
        };
        let cell = |i: usize, j: usize| {
            let (xa, xb) = half(&self.x, i);
            let (ya, yb) = half(&self.y, j);
            if !(xa.is_finite() && xb.is_finite() && ya.is_finite() && yb.is_finite()) {
                return None;
            }
            let color = colormap(self.level(*self.values.get(i, j), range));
            Some(Rectangle::new(
                [(cx(xa), cy(ya)), (cx(xb), cy(yb))],
                color.filled(),
            ))
        };
        let (n, m) = (
            self.x.len().min(self.values.rows()),
            self.y.len().min(self.values.cols()),
        );
        chart.draw_series((0..n).flat_map(|i| (0..m).filter_map(move |j| cell(i, j))))?;
        for &k in self.x_lines.iter().filter(|k| (x0..=x1).contains(*k)) {
            chart.draw_series([PathElement::new(
                vec![(k, y0), (k, y1)],
                WHITE.stroke_width(2),
            )])?;
        }
        for &k in self.y_lines.iter().filter(|k| (y0..=y1).contains(*k)) {
            chart.draw_series([PathElement::new(
                vec![(x0, k), (x1, k)],
                WHITE.stroke_width(2),
            )])?;
        }
        draw_color_bar(&bar, &self.bar_label, range, self.scale)?;
        if let Some(note) = &self.footnote {
            main.draw(&Text::new(
                note.clone(),
                (90, main.dim_in_pixel().1 as i32 - 20),
                (FONT, TICK_SIZE).into_font().color(&BLACK),
            ))?;
        }
        Ok(())
    }
}

/// The range of the finite samples, drawable ([`axis_range`]; widened if they are equal,
/// `(0, 1)` for none).
fn ends(v: &[f64]) -> (f64, f64) {
    let (lo, hi) = v
        .iter()
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        });
    axis_range(lo, hi, 0.0).unwrap_or((0.0, 1.0))
}

/// A vertical colour bar for values in `(lo, hi)` with its label, filling `bar`.
pub fn draw_color_bar<DB: DrawingBackend>(
    bar: &DrawingArea<DB, Shift>,
    label: &str,
    (lo, hi): (f64, f64),
    scale: ColorScale,
) -> Drawn<DB> {
    let steps = 100;
    let (w, h) = bar.dim_in_pixel();
    let (top, bottom) = (h / 8, h / 8);
    // the label reads upwards on the bar's right, centred on it, as an axis name does
    let label_room = LABEL_SIZE + 16;
    let builder = |b: &mut ChartBuilder<DB>| {
        b.margin_top(top)
            .margin_bottom(bottom)
            .margin_right(label_room)
            .margin_left(4)
            .y_label_area_size(64);
    };
    let bar_label = (FONT, LABEL_SIZE)
        .into_font()
        .transform(FontTransform::Rotate270)
        .color(&BLACK)
        .pos(Pos::new(HPos::Center, VPos::Center));
    bar.draw(&Text::new(
        label.to_string(),
        (
            w.saturating_sub(label_room / 2) as i32,
            (top + (h - top - bottom) / 2) as i32,
        ),
        bar_label,
    ))?;
    match scale {
        ColorScale::Log { .. } => {
            let mut b = ChartBuilder::on(bar);
            builder(&mut b);
            let mut cb = b.build_cartesian_2d(0.0..1.0, (lo..hi).log_scale())?;
            cb.configure_mesh()
                .disable_mesh()
                .disable_x_axis()
                .label_style((FONT, TICK_SIZE))
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .draw()?;
            let at = |k: usize| lo * (hi / lo).powf(k as f64 / steps as f64);
            cb.draw_series((0..steps).map(|k| {
                Rectangle::new(
                    [(0.0, at(k)), (1.0, at(k + 1))],
                    colormap(k as f64 / steps as f64).filled(),
                )
            }))?;
        }
        ColorScale::Linear => {
            let mut b = ChartBuilder::on(bar);
            builder(&mut b);
            let mut cb = b.build_cartesian_2d(0.0..1.0, lo..hi)?;
            cb.configure_mesh()
                .disable_mesh()
                .disable_x_axis()
                .label_style((FONT, TICK_SIZE))
                .y_label_formatter(&|v| {
                    let s = format!("{v:.3}");
                    s.trim_end_matches('0').trim_end_matches('.').to_string()
                })
                .draw()?;
            let at = |k: usize| lo + (hi - lo) * k as f64 / steps as f64;
            cb.draw_series((0..steps).map(|k| {
                Rectangle::new(
                    [(0.0, at(k)), (1.0, at(k + 1))],
                    colormap(k as f64 / steps as f64).filled(),
                )
            }))?;
        }
    }
    Ok(())
}
