//! The fewest points on a user's outline, drawn and tabulated: the search is
//! [`crate::study::outline::fewest`]; here its answer becomes a table ([`table`]), one figure
//! per method ([`figures`]) and the outline as the search read it ([`outline_frame`]).
//!
//! ```
//! use nalgebra::Vector2;
//! use splinelab::input::Contour;
//! use splinelab::interp::choice::{Family, SearchOptions};
//! use splinelab::report::user::fewest::table;
//! use splinelab::study::outline::{fewest, Tolerance};
//! let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)];
//! let mut points = Vec::new();
//! for w in corners.windows(2) {
//!     let (a, b) = (Vector2::new(w[0].0, w[0].1), Vector2::new(w[1].0, w[1].1));
//!     points.extend((0..50).map(|k| a + (b - a) * (k as f64 / 50.0)));
//! }
//! points.push(points[0]);
//! let square = [Contour { points, closed: true }];
//! let found = fewest(&square, Tolerance::Fraction(0.01), &[Family::Linear], &SearchOptions::default(), &|_| {})?;
//! assert_eq!(table("square-fewest", &found)?.df.height(), 1);
//! # Ok::<(), splinelab::report::Error>(())
//! ```

use crate::input::Contour;
use crate::interp::choice::Family;
use crate::interp::methods::{Interpolant, Method};
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::legend::parameter_legend;
use crate::report::plot2d::Figure2d;
use crate::report::table::Table;
use crate::report::user::fit::Fit;
use crate::report::{draw, Legend};
use crate::study::outline::{ContourSearch, MethodStudy, OutlineStudy};

crate::record! {
    /// A row of the fewest-points table: one method.
    struct FewestRow {
        method: String => "method",
        points: u32 => "points",
        per_contour: String => "per_contour",
        parameter: String => "parameter",
        error_pct: f64 => "error_pct",
        within: bool => "within_tolerance",
        minimality: String => "minimality",
    }
}

crate::record! {
    /// A point of an outline as the search reads it.
    struct OutlinePoint {
        contour: u32 => "contour",
        closed: bool => "closed",
        x: f64 => "x",
        y: f64 => "y",
    }
}

/// The outline as the searches read it, one row per point (`contour` from 1, `closed`, `x`,
/// `y`; a closed contour's last point repeats its first): `splinelab fewest` writes it beside
/// its table, so that other tools can be run on the same points (`scripts/fewest_peers.py`).
///
/// # Errors
/// [`crate::report::Error::Table`] if the frame cannot be built (an internal error).
pub fn outline_frame(id: &str, outline: &[Contour]) -> Result<crate::report::frame::Frame> {
    let rows: Vec<OutlinePoint> = outline
        .iter()
        .enumerate()
        .flat_map(|(k, c)| {
            let mut points = c.points.clone();
            if c.closed && points.first() != points.last() {
                points.push(points[0]);
            }
            points.into_iter().map(move |p| OutlinePoint {
                contour: u32::try_from(k + 1).unwrap_or(u32::MAX),
                closed: c.closed,
                x: p.x,
                y: p.y,
            })
        })
        .collect();
    crate::report::record::frame_of(id, &rows)
}

crate::record! {
    /// A point of a method's answer on one contour.
    struct AnswerPoint {
        contour: u32 => "contour",
        x: f64 => "x",
        y: f64 => "y",
    }
}

crate::record! {
    /// One contour's answer: its parameters, and the command that draws it again.
    struct AnswerRow {
        contour: u32 => "contour",
        closed: bool => "closed",
        method: String => "method",
        points: u32 => "points",
        a: String => "a",
        end: String => "end",
        order: String => "order",
        knots: String => "knots",
        error_pct: f64 => "error_pct",
        within: bool => "within_tolerance",
        redraw: String => "redraw",
    }
}

/// The contour number of the `k`-th contour (from 0) in the files: from 1.
fn contour_number(k: usize) -> u32 {
    u32::try_from(k + 1).unwrap_or(u32::MAX)
}

/// A method's answer as points (`id`): one row per point, `contour` (from 1), `x`, `y` —
/// the points [`crate::interp::choice::Choice::points`] holds: a closed curve's without the
/// repeats the method adds, an open Angular or cardinal curve's with its two guides (first
/// and last), a B-spline's control polygon. `splinelab fewest` writes it as
/// `NAME-METHOD-points.csv`; `splinelab fit --contour K` reads a contour of it back.
///
/// # Errors
/// [`crate::report::Error::Table`] if the frame cannot be built (an internal error).
pub fn answer_points(id: &str, method: &MethodStudy) -> Result<crate::report::frame::Frame> {
    let rows: Vec<AnswerPoint> = method
        .contours
        .iter()
        .enumerate()
        .flat_map(|(k, c)| {
            c.search.choice.points.iter().map(move |p| AnswerPoint {
                contour: contour_number(k),
                x: p.x,
                y: p.y,
            })
        })
        .collect();
    crate::report::record::frame_of(id, &rows)
}

/// The tolerance within which [`answer_svg`] draws the curves as cubic Béziers, for an
/// outline of `size`: 10⁻⁴ of it (what `splinelab fit` uses by default for its own curve),
/// to two significant digits, so that the `redraw` command states it exactly in a few
/// characters.
pub fn answer_tolerance(size: f64) -> f64 {
    let t = 1e-4 * size;
    format!("{t:.1e}").parse().unwrap_or(t)
}

/// A method's answer as parameters (`id`): per contour whether it is closed, the method,
/// the points as counted, the cardinal `a`, the cubic spline's end, the B-spline's order and
/// knots, the error in % of the outline's size, and the `splinelab fit` command that draws the
/// curve again from `points_file` (the [`answer_points`] file) with the Bézier tolerance of
/// [`answer_svg`], so that its `-path.svg` is the same curve.
///
/// # Errors
/// [`crate::report::Error::Table`] if the frame cannot be built (an internal error).
pub fn answer_parameters(
    id: &str,
    method: &MethodStudy,
    size: f64,
    points_file: &str,
) -> Result<crate::report::frame::Frame> {
    let tolerance = answer_tolerance(size);
    let rows: Vec<AnswerRow> = method
        .contours
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let choice = &c.search.choice;
            let closed = c.target.is_closed();
            let (mut a, mut end, mut order, mut knots) =
                (String::new(), String::new(), String::new(), String::new());
            let mut flags = String::new();
            match choice.method {
                Method::Cardinal { a: value } => {
                    a = format!("{value}");
                    flags = format!(" --a {value}");
                }
                Method::Cubic { end: e } => {
                    end = e.legend().into_owned();
                    flags = format!(" --end {end}");
                }
                Method::BSpline { order: o } => {
                    order = o.to_string();
                    flags = format!(" --order {o}");
                    if let Ok(Interpolant::BSpline(curve)) =
                        choice.method.curve(&choice.points, closed)
                    {
                        let k: Vec<String> = curve
                            .basis()
                            .knots()
                            .knots()
                            .iter()
                            .map(|t| format!("{t:?}"))
                            .collect();
                        knots = k.join(" ");
                    }
                }
                Method::Angular | Method::Linear => {}
            }
            AnswerRow {
                contour: contour_number(k),
                closed,
                method: family_name(method.family).into(),
                points: u32::try_from(choice.measure.counted).unwrap_or(u32::MAX),
                a,
                end,
                order,
                knots,
                error_pct: 100.0 * choice.measure.distances.hausdorff() / size,
                within: choice.within_tolerance,
                redraw: format!(
                    "splinelab fit --method {}{flags}{} --contour {} --tolerance {tolerance:?} {points_file}",
                    family_name(method.family),
                    if closed { " --closed" } else { "" },
                    contour_number(k),
                ),
            }
        })
        .collect();
    crate::report::record::frame_of(id, &rows)
}

/// A method's curves as one SVG document: every contour's curve a subpath of cubic Béziers
/// within [`answer_tolerance`] of it ([`Fit::bezier`]), `y` up as in the outline.
///
/// # Errors
/// As [`Fit::try_new`] and [`Fit::bezier`]; as [`crate::report::export::svg_document`].
pub fn answer_svg(method: &MethodStudy, size: f64) -> Result<String> {
    let tolerance = answer_tolerance(size);
    let mut segments = Vec::new();
    for c in &method.contours {
        let choice = &c.search.choice;
        let fit = Fit::try_new(&choice.points, choice.method, c.target.is_closed())?;
        segments.extend(fit.bezier(tolerance)?);
    }
    crate::report::export::svg_document(&segments, 2e-3 * size)
}

/// The searches as a table (`id`): per method the points (as counted, summed over the
/// contours), the counts per contour, the chosen parameters, the largest error in % of the
/// outline's size, whether within the tolerance, and whether the count is proven the fewest.
///
/// # Errors
/// [`crate::report::Error::Table`] if the frame cannot be built (an internal error).
pub fn table(id: &str, found: &OutlineStudy) -> Result<Table> {
    let rows: Vec<FewestRow> = found
        .methods
        .iter()
        .map(|m| {
            let join = |f: &dyn Fn(&ContourSearch) -> String| {
                per_contour(m.contours.iter().map(f).collect())
            };
            FewestRow {
                method: family_name(m.family).into(),
                points: u32::try_from(m.counted()).unwrap_or(u32::MAX),
                per_contour: join(&|c| c.search.choice.measure.counted.to_string()),
                parameter: join(&|c| parameter_legend(&c.search.choice.method)),
                error_pct: 100.0 * m.error() / found.size,
                within: m.within_tolerance(),
                minimality: m
                    .minimality()
                    .map_or_else(String::new, |q| q.describe(found.size)),
            }
        })
        .collect();
    Ok(Table::new(
        id,
        format!(
            "The fewest points per method within {} ({:.3} % of the size {})",
            crate::printed::rounded(found.tolerance, 6),
            100.0 * found.tolerance / found.size,
            crate::printed::rounded(found.size, 6)
        ),
        crate::report::record::frame_of(id, &rows)?,
    )
    .note("points: as seed 004 counts them (a closed curve's repeats included), summed over the contours; error_pct: the largest symmetric Hausdorff distance between a contour and its curve, in % of the outline's size (the larger side of its bounding box); the search is Table I's (interp::choice::search)."))
}

/// The whole outline in one panel: every contour panel's series drawn together, each label
/// once.
fn whole_outline(
    panels: &[crate::report::plot2d::Panel],
    family: &Family,
) -> crate::report::plot2d::Panel {
    let mut whole = crate::report::plot2d::Panel::new(
        format!("the whole outline: {}", family_name(*family)),
        "",
        "",
    )
    .equal();
    let mut seen = std::collections::HashSet::new();
    // the points' marks hide the outline beyond a few hundred: then the curves alone
    let marks: usize = panels
        .iter()
        .flat_map(|p| p.series.iter())
        .filter(|s| is_marks(s))
        .map(|s| s.points.len())
        .sum();
    let keep_marks = marks <= crate::report::user::fit::MAX_MARKERS;
    if !keep_marks {
        whole.x_label = format!("{marks} points, not marked");
    }
    for panel in panels {
        for series in panel.series.iter().filter(|s| keep_marks || !is_marks(s)) {
            let mut series = series.clone();
            if let Some(label) = &series.label {
                if !seen.insert(label.clone()) {
                    series.label = None;
                }
            }
            whole.series.push(series);
        }
    }
    whole
}

/// Whether a series marks points (dots or crosses, no line).
fn is_marks(series: &crate::report::plot2d::Series) -> bool {
    use crate::report::plot2d::Style;
    matches!(series.style, Style::Points(_) | Style::Crosses(_))
}

/// The per-contour values of a table cell: joined with ` + ` for up to
/// [`MAX_CONTOUR_PANELS`] contours; beyond, how many contours there are and the values by how
/// often they occur (the three commonest, `4 × 1520, 5 × 9, …`), so a map's row stays
/// readable.
fn per_contour(values: Vec<String>) -> String {
    if values.len() <= MAX_CONTOUR_PANELS {
        return values.join(" + ");
    }
    let mut counts: Vec<(String, usize)> = Vec::new();
    for v in &values {
        match counts.iter_mut().find(|(w, _)| w == v) {
            Some((_, n)) => *n += 1,
            None => counts.push((v.clone(), 1)),
        }
    }
    counts.sort_by_key(|c| std::cmp::Reverse(c.1));
    let shown: Vec<String> = counts
        .iter()
        .take(3)
        .map(|(v, n)| format!("{v} × {n}"))
        .collect();
    let more = if counts.len() > 3 { ", …" } else { "" };
    format!("{} contours: {}{more}", values.len(), shown.join(", "))
}

/// The indices of the `max` largest contours of `method` (the larger side of their bounding
/// boxes; ties to the earlier), in the outline's order.
fn largest_contours(method: &MethodStudy, max: usize) -> Vec<usize> {
    let mut by_size: Vec<(f64, usize)> = method
        .contours
        .iter()
        .enumerate()
        .map(|(k, c)| (c.target.size(), k))
        .collect();
    by_size.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut kept: Vec<usize> = by_size.into_iter().take(max).map(|(_, k)| k).collect();
    kept.sort_unstable();
    kept
}

/// A family's name on the command line and in tables.
pub fn family_name(family: Family) -> &'static str {
    match family {
        Family::Angular => "angular",
        Family::Cardinal => "cardinal",
        Family::Cubic => "cubic",
        Family::BSpline => "bspline",
        Family::Linear => "linear",
    }
}

/// The most contours a method's figure draws in panels of their own, beside the whole
/// outline: the largest (by the larger side of their bounding boxes), in the outline's order.
pub const MAX_CONTOUR_PANELS: usize = 8;

/// One figure per method: the whole outline in one panel (for more than one contour), then a
/// panel per contour, at most [`MAX_CONTOUR_PANELS`] of them (the largest; the title says
/// so), the curve over the outline with its points ([`draw::choice_panel`]).
///
/// # Errors
/// As [`draw::choice_panel`].
pub fn figures(found: &OutlineStudy) -> Result<Vec<(Family, Figure)>> {
    found
        .methods
        .iter()
        .map(|m| {
            let all = m
                .contours
                .iter()
                .enumerate()
                .map(|(k, c)| {
                    let choice = &c.search.choice;
                    let mut panel = draw::choice_panel(
                        format!("contour {}: {}", k + 1, choice.method.legend()),
                        &c.target,
                        choice,
                    )?;
                    // in % of the whole outline's size, as the table and the tolerance are
                    // (the panel's own would be the contour's)
                    panel.x_label = format!(
                        "{} pts, error {:.2} % of the outline's size{}",
                        choice.measure.counted,
                        100.0 * choice.measure.distances.hausdorff() / found.size,
                        if choice.within_tolerance {
                            ""
                        } else {
                            " (over the tolerance)"
                        }
                    );
                    Ok(panel)
                })
                .collect::<Result<Vec<_>>>()?;
            let shown = largest_contours(m, MAX_CONTOUR_PANELS);
            let mut panels: Vec<_> = shown.iter().map(|&k| all[k].clone()).collect();
            if all.len() > 1 {
                panels.insert(0, whole_outline(&all, &m.family));
            }
            let n = panels.len();
            let cols = n.min(3);
            let rows = n.div_ceil(cols.max(1));
            let mut title = format!(
                "{}: {} points, error {:.2} % of the size",
                family_name(m.family),
                m.counted(),
                100.0 * m.error() / found.size
            );
            if shown.len() < all.len() {
                title.push_str(&format!(
                    "; the {} largest of {} contours alone",
                    shown.len(),
                    all.len()
                ));
            }
            let figure = Figure::from(Figure2d::new(title, panels, (rows, cols)).shared_legend())
                .with_size(520 * cols as u32 + 80, 480 * rows as u32 + 80);
            Ok((m.family, figure))
        })
        .collect()
}
