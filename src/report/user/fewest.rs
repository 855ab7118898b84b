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
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::legend::parameter_legend;
use crate::report::plot2d::Figure2d;
use crate::report::table::Table;
use crate::report::{draw, Legend};
use crate::study::outline::{ContourSearch, OutlineStudy};

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
                m.contours.iter().map(f).collect::<Vec<_>>().join(" + ")
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
    for panel in panels {
        for series in &panel.series {
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

/// One figure per method: the whole outline in one panel (for more than one contour), then a
/// panel per contour, the curve over the outline with its points ([`draw::choice_panel`]).
///
/// # Errors
/// As [`draw::choice_panel`].
pub fn figures(found: &OutlineStudy) -> Result<Vec<(Family, Figure)>> {
    found
        .methods
        .iter()
        .map(|m| {
            let panels = m
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
            let mut panels = panels;
            if panels.len() > 1 {
                panels.insert(0, whole_outline(&panels, &m.family));
            }
            let n = panels.len();
            let cols = n.min(3);
            let rows = n.div_ceil(cols.max(1));
            let title = format!(
                "{}: {} points, error {:.2} % of the size",
                family_name(m.family),
                m.counted(),
                100.0 * m.error() / found.size
            );
            let figure = Figure::from(Figure2d::new(title, panels, (rows, cols)).shared_legend())
                .with_size(520 * cols as u32 + 80, 480 * rows as u32 + 80);
            Ok((m.family, figure))
        })
        .collect()
}
