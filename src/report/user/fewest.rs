//! Table I's point search on a user's outline ([`fewest`]): for each method the fewest points
//! with which it draws the outline within a tolerance, as a table ([`table`]) and one figure
//! per method ([`figures`]); the paper's own shapes as outlines ([`shape_outline`]), on which
//! it finds `table-i`'s counts.
//!
//! Each contour of the outline is a [`Target::polyline`] searched on its own
//! ([`crate::interp::choice::search`]); a method's count is the sum over the contours, its error
//! the largest. The searches run on all cores, and `progress` hears of each one that ends.
//!
//! ```
//! use nalgebra::Vector2;
//! use splinelab::input::Contour;
//! use splinelab::interp::choice::{Family, SearchOptions};
//! use splinelab::report::user::fewest::{fewest, Tolerance};
//! // a unit square's outline, dense along its sides
//! let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)];
//! let mut points = Vec::new();
//! for w in corners.windows(2) {
//!     let (a, b) = (Vector2::new(w[0].0, w[0].1), Vector2::new(w[1].0, w[1].1));
//!     points.extend((0..50).map(|k| a + (b - a) * (k as f64 / 50.0)));
//! }
//! points.push(points[0]);
//! let square = [Contour { points, closed: true }];
//! let found = fewest(&square, Tolerance::Fraction(0.01), &[Family::Linear], &SearchOptions::default(), &|_| {})?;
//! assert_eq!(found.methods[0].counted(), 5); // the corners, the first repeated
//! # Ok::<(), splinelab::report::Error>(())
//! ```

use crate::input::Contour;
use crate::interp::choice::{search, Family, Minimality, Search, SearchOptions, Target};
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::plot2d::Figure2d;
use crate::report::seed004::table_i::parameter;
use crate::report::table::Table;
use crate::report::{draw, Legend};
use crate::seeds::seed004::SHAPES;
use crate::shapes::TOLERANCE_FRACTION;
use crate::study::table_i::{MAX_POINTS, REFERENCE_SEGMENTS};
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The tolerance of a search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tolerance {
    /// A fraction of the outline's size (the larger side of its bounding box): `1%` is
    /// `Fraction(0.01)`, Table I's.
    Fraction(f64),
    /// A distance in the outline's units.
    Absolute(f64),
}

impl Default for Tolerance {
    /// Table I's: 1 % of the size.
    fn default() -> Self {
        Tolerance::Fraction(TOLERANCE_FRACTION)
    }
}

impl FromStr for Tolerance {
    type Err = crate::Error;

    /// `1%` (a percentage of the size) or `0.05` (a distance); positive and finite.
    fn from_str(s: &str) -> crate::Result<Self> {
        let text = s.trim();
        let (number, percent) = match text.strip_suffix('%') {
            Some(n) => (n.trim(), true),
            None => (text, false),
        };
        let value: f64 = number.parse().map_err(|_| crate::Error::Parse {
            what: "tolerance",
            line: 1,
            column: 1,
            message: format!("{text:?} is neither a percentage (1%) nor a distance (0.05)"),
        })?;
        let value = crate::error::positive("tolerance", value)?;
        Ok(if percent {
            Tolerance::Fraction(value / 100.0)
        } else {
            Tolerance::Absolute(value)
        })
    }
}

impl Tolerance {
    /// The distance for an outline of `size`.
    pub fn of(self, size: f64) -> f64 {
        match self {
            Tolerance::Fraction(f) => f * size,
            Tolerance::Absolute(d) => d,
        }
    }
}

/// One contour's search.
#[derive(Debug, Clone)]
pub struct ContourSearch {
    /// The contour as the search drew it.
    pub target: Target,
    /// The answer with its evidence.
    pub search: Search,
}

/// One method's fewest points on every contour.
#[derive(Debug, Clone)]
pub struct MethodFewest {
    /// The method family.
    pub family: Family,
    /// Each contour's search, in the outline's order.
    pub contours: Vec<ContourSearch>,
}

impl MethodFewest {
    /// The points of all contours, as seed 004 counts them (a closed curve's repeats included).
    pub fn counted(&self) -> usize {
        self.contours
            .iter()
            .map(|c| c.search.choice.measure.counted)
            .sum()
    }

    /// The largest error over the contours (symmetric Hausdorff distance).
    pub fn error(&self) -> f64 {
        self.contours
            .iter()
            .map(|c| c.search.choice.measure.distances.hausdorff())
            .fold(0.0, f64::max)
    }

    /// Whether every contour is drawn within the tolerance.
    pub fn within_tolerance(&self) -> bool {
        self.contours
            .iter()
            .all(|c| c.search.choice.within_tolerance)
    }
}

/// The searches of every method on one outline.
#[derive(Debug, Clone)]
pub struct Fewest {
    /// The outline's size: the larger side of the bounding box of all its contours.
    pub size: f64,
    /// The tolerance, a distance.
    pub tolerance: f64,
    /// One entry per method asked for, in the order asked.
    pub methods: Vec<MethodFewest>,
}

/// How far the searches have come: `done` of `total` ended, the last of them `family`'s.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// Searches ended.
    pub done: usize,
    /// Searches in all (methods × contours).
    pub total: usize,
    /// The method of the search that just ended.
    pub family: Family,
}

/// For each of `families`, the fewest points drawing every contour of `outline` within
/// `tolerance` (module docs), with `options` (Table I's are [`SearchOptions::default`] with
/// `max_points = 40`; the letters' and the coast's a budget of 10 per coordinate, counts
/// bisected, up to 200 points).
///
/// # Errors
/// [`crate::Error::TooFewPoints`] for an outline without contours; the errors of
/// [`Target::polyline`] (a contour of fewer than 2 points, or 3 distinct when closed, or of
/// zero length; a tolerance that is not positive) and of [`search`], as
/// [`crate::report::Error::Core`].
pub fn fewest(
    outline: &[Contour],
    tolerance: Tolerance,
    families: &[Family],
    options: &SearchOptions,
    progress: &(dyn Fn(Progress) + Sync),
) -> Result<Fewest> {
    fewest_in_stages(
        outline,
        tolerance,
        families,
        std::slice::from_ref(options),
        progress,
    )
}

/// As [`fewest`], each contour searched with each of `stages` in turn, every stage starting
/// from the previous one's answer ([`SearchOptions::known`], its count within the stage's
/// `max_points`), and the best answer kept: so a later stage is never worse than an earlier
/// one. `splinelab fewest --thorough` is [`default_options`] then [`thorough_options`].
///
/// # Errors
/// As [`fewest`]; [`crate::Error::TooFewPoints`] for no stage.
pub fn fewest_in_stages(
    outline: &[Contour],
    tolerance: Tolerance,
    families: &[Family],
    stages: &[SearchOptions],
    progress: &(dyn Fn(Progress) + Sync),
) -> Result<Fewest> {
    if stages.is_empty() {
        return Err(crate::Error::TooFewPoints {
            what: "search stages",
            needed: 1,
            got: 0,
        }
        .into());
    }
    if outline.is_empty() || families.is_empty() {
        return Err(crate::Error::TooFewPoints {
            what: if outline.is_empty() {
                "outline contours"
            } else {
                "methods to search"
            },
            needed: 1,
            got: 0,
        }
        .into());
    }
    let size = super::outline::size(outline);
    let distance = crate::error::positive("tolerance", tolerance.of(size))?;
    let targets = outline
        .iter()
        .map(|c| Target::polyline(&c.points, c.closed, distance))
        .collect::<crate::Result<Vec<_>>>()?;
    let jobs: Vec<(Family, usize)> = families
        .iter()
        .flat_map(|&f| (0..targets.len()).map(move |k| (f, k)))
        .collect();
    let done = AtomicUsize::new(0);
    let results = crate::parallel::map(&jobs, |&(family, k)| {
        let found = in_stages(&targets[k], family, stages);
        progress(Progress {
            done: done.fetch_add(1, Ordering::Relaxed) + 1,
            total: jobs.len(),
            family,
        });
        found
    });
    let mut results = results.into_iter();
    let mut methods = Vec::with_capacity(families.len());
    for &family in families {
        let contours = targets
            .iter()
            .zip(results.by_ref())
            .map(|(target, found)| {
                Ok(ContourSearch {
                    target: target.clone(),
                    search: found?,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        methods.push(MethodFewest { family, contours });
    }
    Ok(Fewest {
        size,
        tolerance: distance,
        methods,
    })
}

/// `target` searched with each of `stages` in turn, each from the previous answer, the best
/// kept ([`fewest_in_stages`]).
fn in_stages(target: &Target, family: Family, stages: &[SearchOptions]) -> crate::Result<Search> {
    let mut best: Option<Search> = None;
    for stage in stages {
        let options = match &best {
            Some(b) if b.choice.within_tolerance => SearchOptions {
                max_points: stage.max_points.max(b.choice.measure.counted),
                known: Some(b.choice.clone()),
                ..stage.clone()
            },
            _ => stage.clone(),
        };
        let found = search(target, family, &options)?;
        let rank = |s: &Search| {
            (
                !s.choice.within_tolerance,
                s.choice.measure.counted,
                s.choice.measure.distances.hausdorff(),
            )
        };
        // a tie goes to the later stage, whose evidence goes further
        if best.as_ref().is_none_or(|b| rank(&found) <= rank(b)) {
            best = Some(found);
        }
    }
    Ok(best.expect("at least one stage"))
}

/// The names [`shape_outline`] takes: the paper's column names (`Ellisse 1`) and our shape
/// names (`ellipse-0.7`), one pair per Table I column.
pub fn shape_names() -> Vec<(&'static str, String)> {
    SHAPES.iter().map(|(c, s)| (*c, s.name())).collect()
}

/// The outline of the paper's shape `name` (a column name or a shape name:
/// [`shape_names`]): its reference polyline as Table I measures against
/// ([`crate::shapes::Shape::reference`] with [`REFERENCE_SEGMENTS`] segments), one contour,
/// closed for the closed shapes. [`fewest`] on it, with Table I's options, finds Table I's
/// counts (tested): the paper's shapes go through the same path as a user's outline.
///
/// # Errors
/// [`crate::Error::Parse`] for a name that is no shape of Table I (the message lists them).
pub fn shape_outline(name: &str) -> Result<Contour> {
    let (_, shape) = SHAPES
        .iter()
        .find(|(c, s)| c.eq_ignore_ascii_case(name) || s.name().eq_ignore_ascii_case(name))
        .ok_or_else(|| crate::Error::Parse {
            what: "shape name",
            line: 1,
            column: 1,
            message: format!(
                "{name:?} is no shape of Table I; the shapes are {}",
                shape_names()
                    .iter()
                    .map(|(c, s)| format!("{s} ({c})"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        })?;
    Ok(Contour {
        points: shape.reference(REFERENCE_SEGMENTS)?,
        closed: shape.is_closed(),
    })
}

/// The most points a contour is tried with by default (as counted): the letters' and the
/// coast's limit.
pub const DEFAULT_MAX_POINTS: usize = 200;

/// Error evaluations per count and start, per free coordinate, by default: the letters' and
/// the coast's budget.
pub const DEFAULT_BUDGET: usize = 10;

/// The options of `splinelab fewest` by default: the letters' and the coast's search
/// ([`crate::report::seed004::table_i::letters_and_coast`]): up to [`DEFAULT_MAX_POINTS`]
/// points, [`DEFAULT_BUDGET`] evaluations per coordinate, counts bisected (the count one below
/// the answer searched in full). [`table_i_options`] are slower and more thorough.
pub fn default_options() -> SearchOptions {
    SearchOptions {
        max_points: DEFAULT_MAX_POINTS,
        budget_per_coordinate: DEFAULT_BUDGET,
        every_count_below: false,
        ..SearchOptions::default()
    }
}

/// Table I's search options ([`crate::study::table_i::table_i`]): up to [`MAX_POINTS`]
/// points, the default budget, every count below the answer searched.
pub fn table_i_options() -> SearchOptions {
    SearchOptions {
        max_points: MAX_POINTS,
        ..SearchOptions::default()
    }
}

/// The second stage of `splinelab fewest --thorough` ([`fewest_in_stages`], after `first`):
/// Table I's budget and every count below the answer searched, as many points as `first`
/// allows (at least Table I's [`MAX_POINTS`]).
pub fn thorough_options(first: &SearchOptions) -> SearchOptions {
    SearchOptions {
        max_points: first.max_points.max(MAX_POINTS),
        ..SearchOptions::default()
    }
}

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
pub fn outline_frame(id: &str, outline: &[Contour]) -> Result<crate::report::table::Frame> {
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

/// The least sure of the contours' minimalities, in words.
fn minimality_of(m: &MethodFewest, size: f64) -> String {
    let rank = |m: &Minimality| match m {
        Minimality::MethodMinimum => 0,
        Minimality::LowerBound { .. } | Minimality::Optimum { .. } => 1,
        Minimality::Searched => 2,
        Minimality::Bisected => 3,
        Minimality::NotMet => 4,
    };
    m.contours
        .iter()
        .map(|c| &c.search.minimality)
        .max_by_key(|m| rank(m))
        .map_or_else(String::new, |m| m.describe(size))
}

/// The searches as a table (`id`): per method the points (as counted, summed over the
/// contours), the counts per contour, the chosen parameters, the largest error in % of the
/// outline's size, whether within the tolerance, and whether the count is proven the fewest.
///
/// # Errors
/// [`crate::report::Error::Table`] if the frame cannot be built (an internal error).
pub fn table(id: &str, found: &Fewest) -> Result<Table> {
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
                parameter: join(&|c| parameter(&c.search.choice.method)),
                error_pct: 100.0 * m.error() / found.size,
                within: m.within_tolerance(),
                minimality: minimality_of(m, found.size),
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
pub fn figures(found: &Fewest) -> Result<Vec<(Family, Figure)>> {
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
