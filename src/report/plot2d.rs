//! Plane figures made of panels of line and point series, drawn with plotters on any backend.

use crate::curve::ParametricCurve;
use crate::domain::linspace;
use crate::report::style::{FONT, LABEL_SIZE, TICK_SIZE, TITLE_SIZE};
use nalgebra::Vector2;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Samples per curve in the plane figures.
pub const SAMPLES: usize = 400;
/// Grey of control polygons and reference shapes.
pub const GREY: RGBColor = RGBColor(120, 120, 120);
/// Black.
pub const INK: RGBColor = RGBColor(0, 0, 0);

/// Plane points as `(x, y)` pairs.
pub fn xy(points: &[Vector2<f64>]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p.x, p.y)).collect()
}

/// `f` sampled at [`SAMPLES`] points of `[a, b]`.
pub fn sampled(a: f64, b: f64, f: impl Fn(f64) -> (f64, f64)) -> Vec<(f64, f64)> {
    linspace(a, b, SAMPLES).into_iter().map(f).collect()
}

/// Any plane curve sampled at [`SAMPLES`] parameters over its domain.
///
/// # Errors
/// As [`ParametricCurve::polyline`].
pub fn trace<C: ParametricCurve<2> + ?Sized>(c: &C) -> crate::error::Result<Vec<(f64, f64)>> {
    Ok(xy(&c.polyline(SAMPLES)?))
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Style {
    /// A solid polyline.
    Line,
    /// A dashed polyline.
    Dashed,
    /// Filled dots of the given radius (pixels).
    Points(u32),
    /// A solid polyline with dots at its vertices (a control polygon).
    LinePoints(u32),
    /// Crosses of the given half-size (pixels), the paper's mark for interpolation points.
    Crosses(u32),
}

/// One series of a panel.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; `None` keeps it out of the legend.
    pub label: Option<String>,
    /// The points `(x, y)`.
    pub points: Vec<(f64, f64)>,
    /// Colour.
    pub color: RGBColor,
    /// Stroke width in pixels.
    pub width: u32,
    /// Line, dashes or dots.
    pub style: Style,
}

impl Series {
    /// A solid line of width 2.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>, color: RGBColor) -> Self {
        Self {
            label: Some(label.into()),
            points,
            color,
            width: 2,
            style: Style::Line,
        }
    }

    /// The same series with another style.
    pub fn styled(mut self, style: Style) -> Self {
        self.style = style;
        self
    }

    /// The same series with another stroke width.
    pub fn width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }

    /// A control polygon: a thin grey line with dots at its vertices.
    pub fn polygon(label: impl Into<String>, points: &[Vector2<f64>]) -> Self {
        Self::line(label, xy(points), GREY)
            .width(1)
            .styled(Style::LinePoints(4))
    }

    /// Any plane curve sampled over its domain, as a solid line.
    ///
    /// # Errors
    /// As [`ParametricCurve::polyline`].
    pub fn curve<C: ParametricCurve<2> + ?Sized>(
        label: impl Into<String>,
        curve: &C,
        color: RGBColor,
    ) -> crate::error::Result<Self> {
        Ok(Self::line(label, trace(curve)?, color))
    }

    /// The same series without a legend entry.
    pub fn unlabeled(mut self) -> Self {
        self.label = None;
        self
    }
}

/// One panel: a titled Cartesian chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Panel title.
    pub title: String,
    /// x-axis label.
    pub x_label: String,
    /// y-axis label.
    pub y_label: String,
    /// The series, drawn in order.
    pub series: Vec<Series>,
    /// Equal data units per pixel in x and y (MATLAB's `axis equal`), for shapes.
    pub equal_aspect: bool,
    /// Fixed x range instead of the data's (padded) extent.
    pub x_range: Option<(f64, f64)>,
    /// Fixed y range instead of the data's (padded) extent.
    pub y_range: Option<(f64, f64)>,
    /// Where the legend goes.
    pub legend: SeriesLabelPosition,
    /// Logarithmic x axis (non-positive x are left out).
    pub log_x: bool,
    /// Logarithmic y axis (non-positive y are left out).
    pub log_y: bool,
    /// Text placed at data coordinates `(x, y)` (its top-left corner), for labelling points;
    /// notes do not widen the drawn range (place them among the data).
    pub notes: Vec<(f64, f64, String)>,
}

impl Panel {
    /// A panel with the given title and axis labels, no series yet.
    pub fn new(title: impl Into<String>, x_label: &str, y_label: &str) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            equal_aspect: false,
            x_range: None,
            y_range: None,
            legend: SeriesLabelPosition::UpperRight,
            log_x: false,
            log_y: false,
            notes: Vec::new(),
        }
    }

    /// With a text label at data coordinates `(x, y)`.
    pub fn note(mut self, x: f64, y: f64, text: impl Into<String>) -> Self {
        self.notes.push((x, y, text.into()));
        self
    }

    /// With logarithmic axes (`x`, `y`: which).
    pub fn log(mut self, x: bool, y: bool) -> Self {
        self.log_x = x;
        self.log_y = y;
        self
    }

    /// With a fixed x range.
    pub fn x_range(mut self, lo: f64, hi: f64) -> Self {
        self.x_range = Some((lo, hi));
        self
    }

    /// With equal axis scaling.
    pub fn equal(mut self) -> Self {
        self.equal_aspect = true;
        self
    }

    /// With the legend at `pos`.
    pub fn legend_at(mut self, pos: SeriesLabelPosition) -> Self {
        self.legend = pos;
        self
    }

    /// With a fixed y range.
    pub fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.y_range = Some((lo, hi));
        self
    }

    /// Adds a series.
    pub fn with(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }
}

/// A figure: a title over panels laid out in `rows × cols`, and an optional legend shared by
/// all panels in a strip along the bottom (for panels that show the same series).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure2d {
    /// Figure title.
    pub title: String,
    /// Panels, row by row.
    pub panels: Vec<Panel>,
    /// `(rows, cols)`.
    pub layout: (usize, usize),
    /// Entries `(label, colour, style)` of the shared legend; empty for none (panels then
    /// carry their own legends).
    pub legend: Vec<(String, RGBColor, Style)>,
}

impl Figure2d {
    /// A figure without a shared legend.
    pub fn new(title: impl Into<String>, panels: Vec<Panel>, layout: (usize, usize)) -> Self {
        Self {
            title: title.into(),
            panels,
            layout,
            legend: Vec::new(),
        }
    }

    /// Moves the panels' legend entries into a shared strip (each label once, in order of
    /// first appearance) and drops every panel's own legend (for panels showing the same
    /// series).
    pub fn shared_legend(mut self) -> Self {
        let mut legend: Vec<(String, RGBColor, Style)> = Vec::new();
        for s in self.panels.iter().flat_map(|p| &p.series) {
            if let Some(l) = &s.label {
                if !legend.iter().any(|e| &e.0 == l) {
                    legend.push((l.clone(), s.color, s.style));
                }
            }
        }
        self.legend = legend;
        for panel in &mut self.panels {
            for s in &mut panel.series {
                s.label = None;
            }
        }
        self
    }
}

/// The result of a plotters drawing call.
pub type Drawn<DB> =
    std::result::Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// Pixel sizes of a panel's decorations, used to predict its plotting area.
const MARGIN: u32 = 12;
const X_LABEL_AREA: u32 = 45;
const Y_LABEL_AREA: u32 = 62;
const CAPTION: u32 = 30;

/// Height of one row of the shared legend strip, and the room each entry takes.
const LEGEND_ROW: u32 = 26;
const LEGEND_SAMPLE: i32 = 24;

impl Figure2d {
    /// Draws the figure into `area` (already filled with the background).
    ///
    /// # Errors
    /// Whatever the backend reports.
    pub fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        if self.layout_problem().is_some() {
            return Err(DrawingAreaErrorKind::LayoutError);
        }
        // a long title shrinks to fit the width (about 0.55 em per character)
        let width = area.dim_in_pixel().0 as f64;
        let chars = self.title.chars().count().max(1) as f64;
        let size = (TITLE_SIZE as f64)
            .min(0.95 * width / (0.55 * chars))
            .max(12.0);
        let body = area.titled(&self.title, (FONT, size))?;
        let body = if self.legend.is_empty() {
            body
        } else {
            let (_, height) = body.dim_in_pixel();
            let rows = self.legend_rows(body.dim_in_pixel().0);
            let (panels, strip) = body.split_vertically(
                height.saturating_sub(
                    (rows.len() as u32)
                        .saturating_mul(LEGEND_ROW)
                        .saturating_add(8),
                ),
            );
            draw_legend_strip(&strip, &rows)?;
            panels
        };
        for (cell, panel) in body.split_evenly(self.layout).iter().zip(&self.panels) {
            draw_panel(cell, panel)?;
        }
        Ok(())
    }

    /// What is wrong with the layout, if anything: no rows or columns, or more than
    /// [`MAX_PANELS`] cells.
    pub fn layout_problem(&self) -> Option<String> {
        let (rows, cols) = self.layout;
        (rows == 0 || cols == 0 || rows.saturating_mul(cols) > MAX_PANELS).then(|| {
            format!(
                "a layout of {rows} × {cols} panels (at least 1 × 1, at most {MAX_PANELS} cells)"
            )
        })
    }

    /// The legend entries laid out in rows that fit `width` pixels (text width estimated
    /// from the label size).
    fn legend_rows(&self, width: u32) -> Vec<Vec<&(String, RGBColor, Style)>> {
        let mut rows: Vec<Vec<&(String, RGBColor, Style)>> = vec![Vec::new()];
        let mut used = 0;
        for entry in &self.legend {
            let w = entry_width(&entry.0);
            if used + w > width as i32 - 40 && !rows[rows.len() - 1].is_empty() {
                rows.push(Vec::new());
                used = 0;
            }
            used += w;
            let last = rows.len() - 1;
            rows[last].push(entry);
        }
        rows
    }
}

/// Pixels an entry of the legend strip takes: sample, gap, text (about 0.55 em per
/// character), spacing.
fn entry_width(label: &str) -> i32 {
    LEGEND_SAMPLE + 8 + (label.chars().count() as f64 * 0.55 * TICK_SIZE as f64) as i32 + 28
}

fn draw_legend_strip<DB: DrawingBackend>(
    strip: &DrawingArea<DB, Shift>,
    rows: &[Vec<&(String, RGBColor, Style)>],
) -> Drawn<DB> {
    let font = (FONT, TICK_SIZE).into_font().color(&BLACK);
    for (r, row) in rows.iter().enumerate() {
        let total: i32 = row.iter().map(|e| entry_width(&e.0)).sum();
        let mut x = (strip.dim_in_pixel().0 as i32 - total) / 2;
        let y = r as i32 * LEGEND_ROW as i32 + LEGEND_ROW as i32 / 2;
        for (label, color, style) in row.iter().map(|e| (&e.0, e.1, e.2)) {
            match style {
                Style::Points(radius) => {
                    strip.draw(&Circle::new(
                        (x + LEGEND_SAMPLE / 2, y),
                        radius.clamp(3, MAX_MARK),
                        color.filled(),
                    ))?;
                }
                Style::Crosses(radius) => {
                    strip.draw(&Cross::new(
                        (x + LEGEND_SAMPLE / 2, y),
                        radius.clamp(3, MAX_MARK) as i32,
                        color.stroke_width(2),
                    ))?;
                }
                Style::Dashed => {
                    for (a, b) in [(0, 9), (15, LEGEND_SAMPLE)] {
                        strip.draw(&PathElement::new(
                            vec![(x + a, y), (x + b, y)],
                            color.stroke_width(3),
                        ))?;
                    }
                }
                Style::Line | Style::LinePoints(_) => {
                    strip.draw(&PathElement::new(
                        vec![(x, y), (x + LEGEND_SAMPLE, y)],
                        color.stroke_width(3),
                    ))?;
                }
            }
            strip.draw(&Text::new(
                label.clone(),
                (x + LEGEND_SAMPLE + 8, y - TICK_SIZE as i32 / 2 - 1),
                font.clone(),
            ))?;
            x += entry_width(label);
        }
    }
    Ok(())
}

/// The most a marker's radius or a line's width is drawn with, in pixels (a larger value in
/// a [`Style`] or [`Series::width`] is drawn at this size).
pub const MAX_MARK: u32 = 100;

/// The most panels a figure lays out (`rows · cols`).
pub const MAX_PANELS: usize = 1024;

/// The largest magnitude an axis bound takes: a quarter of `f64::MAX`, so the width of any
/// axis range and every quantity the tick search derives from it stay finite.
const AXIS_LIMIT: f64 = f64::MAX / 4.0;

/// The narrowest axis range, relative to its bounds' magnitude: narrower ranges cannot carry
/// distinct tick labels in `f64`.
const MIN_RELATIVE_WIDTH: f64 = 1e-12;

/// An axis range made drawable: `lo < hi`, both finite, within `±AXIS_LIMIT`, and at least
/// [`MIN_RELATIVE_WIDTH`] of their magnitude apart, widened by `pad` of its width on each
/// side (a degenerate range by ±1, or ±5 % of its magnitude far from 0). Computed through
/// the midpoint and half width, so nothing overflows. `None` if `lo` or `hi` is not finite
/// or `lo > hi`.
pub(crate) fn axis_range(lo: f64, hi: f64, pad: f64) -> Option<(f64, f64)> {
    if !(lo.is_finite() && hi.is_finite()) || lo > hi {
        return None;
    }
    let mid = 0.5 * lo + 0.5 * hi;
    let half = 0.5 * hi - 0.5 * lo;
    let mut half = if half > 0.0 {
        half * (1.0 + 2.0 * pad)
    } else {
        (0.05 * mid.abs()).max(1.0)
    };
    half = half.max(MIN_RELATIVE_WIDTH * mid.abs()).min(AXIS_LIMIT);
    let lo = (mid - half).max(-AXIS_LIMIT);
    let hi = (mid + half).min(AXIS_LIMIT);
    // at the limit the clamps keep lo < hi: |mid| ≤ f64::MAX / 2 and half > 0
    Some(if lo < hi { (lo, hi) } else { (-1.0, 1.0) })
}

/// The extent of all finite points, padded by 5 % (and by ±1 for a degenerate side), each
/// side drawable ([`axis_range`]); a fixed range replaces its side when it is valid.
fn extent(panel: &Panel) -> ((f64, f64), (f64, f64)) {
    let ((x0, x1), (y0, y1)) = data_extent(panel);
    let side = |fixed: Option<(f64, f64)>, lo: f64, hi: f64, log: bool| {
        fixed
            .and_then(|(a, b)| if a < b { axis_range(a, b, 0.0) } else { None })
            .or_else(|| if log { decades(lo, hi) } else { None })
            .or_else(|| axis_range(lo, hi, 0.05))
            .unwrap_or((0.0, 1.0))
    };
    (
        side(panel.x_range, x0, x1, panel.log_x),
        side(panel.y_range, y0, y1, panel.log_y),
    )
}

/// A log axis (in `log₁₀` units) from `lo` to `hi`, widened down to a whole decade (and up
/// to one too if only one power of ten would lie inside), with a small margin: its ticks
/// are then powers of ten ([`decade_labels`]), at least two, never `0.0631` beside data at
/// `0.0625`.
fn decades(lo: f64, hi: f64) -> Option<(f64, f64)> {
    if !(lo.is_finite() && hi.is_finite()) || lo > hi {
        return None;
    }
    let a = lo.floor();
    let mut b = hi;
    if hi.floor() - a < 1.0 {
        b = (a + 1.0).max(hi.ceil());
    }
    let margin = 0.03 * (b - a);
    Some((a - margin, b + margin))
}

/// How many tick labels a log axis over `(lo, hi)` (`log₁₀` units) asks of plotters: one per
/// decade, so that the ticks it picks are whole powers of ten (every one, or every second,
/// fifth… beyond a dozen decades).
fn decade_labels((lo, hi): (f64, f64)) -> usize {
    let n = hi.floor() - lo.ceil() + 1.0;
    if n.is_finite() {
        n.clamp(2.0, 12.0) as usize
    } else {
        7
    }
}

/// The finite data's bounding box, `(x0, x1), (y0, y1)` (infinite when there is none).
fn data_extent(panel: &Panel) -> ((f64, f64), (f64, f64)) {
    let pts = panel.series.iter().flat_map(|s| s.points.iter());
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in pts.filter(|(x, y)| x.is_finite() && y.is_finite()) {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    ((x0, x1), (y0, y1))
}

/// The parts of the polyline `points` inside the box `[x0, x1] × [y0, y1]`, each segment
/// clipped to it (Liang–Barsky); a non-finite point breaks the line. Drawing only what lies
/// in (or near) the plotting area keeps every pixel coordinate small, whatever the data.
fn clip_polyline(
    points: &[(f64, f64)],
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Vec<Vec<(f64, f64)>> {
    let mut parts: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let clipped = if finite(&a) && finite(&b) {
            clip_segment(a, b, (x0, x1), (y0, y1))
        } else {
            None
        };
        match clipped {
            Some((p, q)) => {
                if current.last() != Some(&p) {
                    if current.len() > 1 {
                        parts.push(std::mem::take(&mut current));
                    }
                    current.clear();
                    current.push(p);
                }
                current.push(q);
            }
            None => {
                if current.len() > 1 {
                    parts.push(std::mem::take(&mut current));
                }
                current.clear();
            }
        }
    }
    if current.len() > 1 {
        parts.push(current);
    }
    if parts.is_empty() {
        // a single point (or isolated points) inside: a line of one point draws nothing,
        // but keeps the series' legend entry
        if let Some(&p) = points
            .iter()
            .find(|p| finite(p) && inside(**p, (x0, x1), (y0, y1)))
        {
            parts.push(vec![p]);
        }
    }
    parts
}

fn inside((x, y): (f64, f64), (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> bool {
    (x0..=x1).contains(&x) && (y0..=y1).contains(&y)
}

/// The part of the segment `ab` inside the box, or `None`. The segment is parametrised in
/// halves (`a/2 + t(b/2 − a/2)`, doubled), so no difference of coordinates overflows.
fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (ha, hb) = ((0.5 * a.0, 0.5 * a.1), (0.5 * b.0, 0.5 * b.1));
    let (dx, dy) = (hb.0 - ha.0, hb.1 - ha.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, ha.0 - 0.5 * x0),
        (dx, 0.5 * x1 - ha.0),
        (-dy, ha.1 - 0.5 * y0),
        (dy, 0.5 * y1 - ha.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0.is_nan() || t1.is_nan() || t0 > t1 {
        return None;
    }
    // the ends exactly where they are inside; every point clamped to the box, so rounding
    // of the parameters cannot leave one outside
    let at = |t: f64| {
        let (x, y) = if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (2.0 * (ha.0 + t * dx), 2.0 * (ha.1 + t * dy))
        };
        (x.clamp(x0, x1), y.clamp(y0, y1))
    };
    Some((at(t0), at(t1)))
}

/// The box points and lines are drawn in: the plotting ranges widened by half their width
/// on each side (so markers and lines that cross the border are drawn whole), computed
/// without overflow.
fn drawing_box((lo, hi): (f64, f64)) -> (f64, f64) {
    let half = 0.5 * hi - 0.5 * lo;
    ((lo - half).max(-f64::MAX), (hi + half).min(f64::MAX))
}

/// The panel with its log axes applied: points (and fixed ranges) as `log₁₀`, points with a
/// non-positive log coordinate dropped.
fn logged(panel: &Panel) -> Panel {
    let f = |on: bool, v: f64| if on { v.log10() } else { v };
    let mut p = panel.clone();
    for s in &mut p.series {
        s.points = s
            .points
            .iter()
            .filter(|(x, y)| (!panel.log_x || *x > 0.0) && (!panel.log_y || *y > 0.0))
            .map(|&(x, y)| (f(panel.log_x, x), f(panel.log_y, y)))
            .collect();
    }
    p.notes = panel
        .notes
        .iter()
        .filter(|(x, y, _)| (!panel.log_x || *x > 0.0) && (!panel.log_y || *y > 0.0))
        .map(|(x, y, t)| (f(panel.log_x, *x), f(panel.log_y, *y), t.clone()))
        .collect();
    p.x_range = panel
        .x_range
        .map(|(a, b)| (f(panel.log_x, a), f(panel.log_x, b)));
    p.y_range = panel
        .y_range
        .map(|(a, b)| (f(panel.log_y, a), f(panel.log_y, b)));
    p
}

/// A tick label: the value, or `10^v` on a log axis; on a linear axis spanning `span`, a
/// tick within `10⁻⁹ span` of zero is the rounding of 0 and prints as 0.
fn axis_label(log: bool, v: f64, span: f64) -> String {
    if log {
        // a log axis is labelled at powers of ten only (its range is whole decades)
        if (v - v.round()).abs() <= 1e-9 {
            power_label(v.round())
        } else {
            String::new()
        }
    } else {
        let v = if v.abs() <= 1e-9 * span { 0.0 } else { v };
        let a = v.abs();
        if a != 0.0 && !(1e-3..1e5).contains(&a) {
            format!("{v:.1e}")
        } else {
            let s = format!("{v:.4}");
            let s = s.trim_end_matches('0').trim_end_matches('.');
            if s == "-0" {
                "0".into()
            } else {
                s.to_string()
            }
        }
    }
}

/// A tick label of a log axis at `log₁₀ v = e`: plain decimals from 0.001 to 10⁴, powers
/// of ten beyond.
fn power_label(e: f64) -> String {
    let v = 10f64.powf(e);
    if (-3.0..=4.0).contains(&e) {
        // three significant digits: 0.0316, 0.316, 3.16, 31.6
        let decimals = (2.0 - e.floor()).max(0.0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.0e}")
    }
}

fn draw_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, panel: &Panel) -> Drawn<DB> {
    let owned;
    let panel = if panel.log_x || panel.log_y {
        owned = logged(panel);
        &owned
    } else {
        panel
    };
    let (mut xs, mut ys) = extent(panel);
    if panel.equal_aspect {
        (xs, ys) = equal_aspect(area.dim_in_pixel(), xs, ys);
    }
    let ((x0, x1), (y0, y1)) = (xs, ys);
    let (bx, by) = (drawing_box(xs), drawing_box(ys));
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, (FONT, LABEL_SIZE + 2))
        .margin(MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(if panel.log_y {
            Y_LABEL_AREA + 12
        } else {
            Y_LABEL_AREA
        })
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .axis_desc_style((FONT, LABEL_SIZE))
        .label_style((FONT, TICK_SIZE))
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(215, 215, 215))
        .x_labels(if panel.log_x { decade_labels(xs) } else { 7 })
        .y_labels(if panel.log_y { decade_labels(ys) } else { 7 })
        .x_label_formatter(&|v| axis_label(panel.log_x, *v, x1 - x0))
        .y_label_formatter(&|v| axis_label(panel.log_y, *v, y1 - y0))
        .draw()?;
    let mut labelled = false;
    for s in &panel.series {
        labelled |= draw_series(&mut chart, s, bx, by)?;
    }
    let note_font = (FONT, TICK_SIZE + 1).into_font().color(&BLACK);
    for (x, y, text) in panel
        .notes
        .iter()
        .filter(|(x, y, _)| inside((*x, *y), bx, by))
    {
        chart.draw_series(std::iter::once(Text::new(
            text.clone(),
            (*x, *y),
            note_font.clone(),
        )))?;
    }
    if labelled {
        chart
            .configure_series_labels()
            .position(panel.legend.clone())
            .label_font((FONT, TICK_SIZE))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.4))
            .draw()?;
    }
    Ok(())
}

/// The ranges grown on their shorter side so that one data unit spans as many pixels in `x`
/// as in `y` on an area of `(w, h)` pixels (the given ranges if the grown ones cannot be
/// drawn).
fn equal_aspect(
    (w, h): (u32, u32),
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> ((f64, f64), (f64, f64)) {
    let pw = w.saturating_sub(Y_LABEL_AREA + 2 * MARGIN).max(1) as f64;
    let ph = h.saturating_sub(X_LABEL_AREA + CAPTION + 2 * MARGIN).max(1) as f64;
    // in half widths, so nothing overflows; the ranges are made drawable again after
    let scale = ((0.5 * x1 - 0.5 * x0) / pw).max((0.5 * y1 - 0.5 * y0) / ph);
    let (cx, cy) = (0.5 * x0 + 0.5 * x1, 0.5 * y0 + 0.5 * y1);
    let grown = |c: f64, p: f64| axis_range(c - scale * p, c + scale * p, 0.0);
    match (grown(cx, pw), grown(cy, ph)) {
        (Some(x), Some(y)) => (x, y),
        _ => ((x0, x1), (y0, y1)),
    }
}

/// A panel's chart.
type Chart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// One series on the chart — its line (clipped to the drawing box `bx × by`), its markers and
/// its legend entry; whether it has one.
fn draw_series<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    s: &Series,
    bx: (f64, f64),
    by: (f64, f64),
) -> Result<bool, DrawingAreaErrorKind<DB::ErrorType>> {
    let color = s.color;
    let width = s.width.min(MAX_MARK);
    let stroke = color.stroke_width(width);
    // what lies in (or near) the plotting area only, so pixel coordinates stay small
    let marks = || {
        s.points
            .iter()
            .copied()
            .filter(|&p| inside(p, bx, by))
            .collect::<Vec<_>>()
    };
    if matches!(s.style, Style::Line | Style::Dashed | Style::LinePoints(_)) {
        for part in clip_polyline(&s.points, bx, by) {
            if s.style == Style::Dashed {
                chart.draw_series(DashedLineSeries::new(part, 9, 6, stroke))?;
            } else {
                chart.draw_series(LineSeries::new(part, stroke))?;
            }
        }
    }
    // the legend entry hangs on the markers' series (empty for plain lines)
    let anno = match s.style {
        Style::Points(r) | Style::LinePoints(r) => {
            let r = r.min(MAX_MARK);
            chart.draw_series(
                marks()
                    .into_iter()
                    .map(|p| Circle::new(p, r, color.filled())),
            )?
        }
        Style::Crosses(r) => {
            let r = r.min(MAX_MARK) as i32;
            chart.draw_series(
                marks()
                    .into_iter()
                    .map(|p| Cross::new(p, r, color.stroke_width(2))),
            )?
        }
        Style::Line | Style::Dashed => {
            chart.draw_series(std::iter::empty::<Circle<(f64, f64), u32>>())?
        }
    };
    let Some(label) = &s.label else {
        return Ok(false);
    };
    let anno = anno.label(label.as_str());
    match s.style {
        Style::Points(r) => {
            let r = r.clamp(3, MAX_MARK);
            anno.legend(move |(x, y)| Circle::new((x + 10, y), r, color.filled()));
        }
        Style::Crosses(r) => {
            let r = r.clamp(3, MAX_MARK) as i32;
            anno.legend(move |(x, y)| Cross::new((x + 10, y), r, color.stroke_width(2)));
        }
        _ => {
            let width = width.max(2);
            anno.legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(width))
            });
        }
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::axis_label;

    #[test]
    fn a_rounded_zero_tick_prints_as_zero() {
        assert_eq!(axis_label(false, 1.1e-16, 1.3), "0");
        assert_eq!(axis_label(false, -2e-17, 1.3), "0");
        assert_eq!(axis_label(false, 0.2, 1.3), "0.2");
        // a genuinely small axis keeps its small ticks
        assert_eq!(axis_label(false, 2e-12, 1e-11), "2.0e-12");
    }
}

#[cfg(test)]
mod log_axis_tests {
    use super::*;

    #[test]
    fn log_axes_span_whole_decades_and_ask_for_one_label_per_decade() {
        // h from 1/16 to 2: down to a whole decade (0.01), up to the data (2): 0.01, 0.1, 1
        let (lo, hi) = (0.0625f64.log10(), 2f64.log10());
        let (a, b) = decades(lo, hi).unwrap();
        assert!(a < -2.0 && a > -2.1 && b > hi && b < 0.4, "{a} {b}");
        assert_eq!(decade_labels((a, b)), 3);
        // errors from 1e-6 to 0.06: whole decades below, the data's top above
        let (a, b) = decades(1e-6f64.log10(), 0.06f64.log10()).unwrap();
        assert!((a + 6.0).abs() < 0.2 && b < -1.0, "{a} {b}");
        assert_eq!(decade_labels((a, b)), 5);
        // within one decade: both neighbouring powers of ten
        let (a, b) = decades(0.2f64.log10(), 0.5f64.log10()).unwrap();
        assert!(a < -1.0 && b > 0.0);
        // degenerate input is not a range, and never overflows
        assert_eq!(decades(f64::NAN, 1.0), None);
        assert_eq!(decades(2.0, 1.0), None);
        assert_eq!(decade_labels((f64::NEG_INFINITY, 3.0)), 7);
        assert_eq!(decade_labels((-400.0, 400.0)), 12);
        // labels only at powers of ten
        assert_eq!(axis_label(true, -2.0, 3.0), "0.01");
        assert_eq!(axis_label(true, -12.0, 3.0), "1e-12");
        assert_eq!(axis_label(true, -1.5, 3.0), "");
    }
}
