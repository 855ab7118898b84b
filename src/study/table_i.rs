//! Seed 004's comparison regenerated: Table I cell by cell — the printed count and parameter
//! with points placed by a stated rule, the fewest points that rule needs, and the fewest
//! points found automatically ([`crate::interp::choice`]) — the cross-method experiment
//! (points chosen for one method drawn by another), and the fewest points for shapes made of
//! several contours (the letters, the coastline).
//!
//! Every error is the symmetric Hausdorff distance to a reference of
//! [`REFERENCE_SEGMENTS`] segments, within the tolerance of 1 % of the shape's larger
//! bounding-box side ([`crate::shapes::TOLERANCE_FRACTION`], spec decision A12).

use crate::error::{Error, Result};
use crate::input::Contour;
use crate::interp::choice::{
    search, Attempt, Choice, Family, Measure, Minimality, SearchOptions, Start, Target,
};
use crate::interp::methods::{CubicEnd, Method};
#[cfg(feature = "fonts")]
use crate::seeds::letters::letter_a;
#[cfg(feature = "fonts")]
use crate::seeds::seed004::coastline;
#[cfg(feature = "fonts")]
use crate::seeds::seed004::LETTER_FIGURES;
use crate::seeds::seed004::{decimate, paper_points, PrintedCell, COAST_STEP, SHAPES, TABLE_I};
use crate::shapes::Shape;
use crate::study::outline::MethodStudy;
#[cfg(feature = "fonts")]
use crate::study::outline::{default_options, fewest, Tolerance};
use nalgebra::Vector2;

/// Segments of each shape's reference polyline.
pub const REFERENCE_SEGMENTS: usize = 2048;

/// The most points (as counted) the paper's rule and the search try.
pub const MAX_POINTS: usize = 40;

/// A curve drawn from points chosen for another method is flagged "absurd" beyond this many
/// tolerances (5 % of the shape's size: a shape visibly not the original).
pub const ABSURD: f64 = 5.0;

/// A method through given points, measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Configuration {
    /// The method and its parameter.
    pub method: Method,
    /// The distinct points.
    pub points: Vec<Vector2<f64>>,
    /// How they were placed.
    pub rule: &'static str,
    /// Error and smoothness.
    pub measure: Measure,
}

impl Configuration {
    /// As a [`Choice`] within or not within `tolerance`.
    fn choice(&self, tolerance: f64) -> Choice {
        Choice {
            method: self.method,
            points: self.points.clone(),
            measure: self.measure,
            within_tolerance: self.measure.distances.hausdorff() <= tolerance,
            evaluations: 0,
            start: Start::Known,
        }
    }
}

/// One cell of Table I regenerated.
#[derive(Debug, Clone, PartialEq)]
pub struct CellStudy {
    /// The printed cell.
    pub cell: PrintedCell,
    /// The paper's column name.
    pub column: &'static str,
    /// The shape.
    pub shape: Shape,
    /// The tolerance (1 % of the larger bounding-box side).
    pub tolerance: f64,
    /// The shape's size (its larger bounding-box side).
    pub size: f64,
    /// Inflections of the shape itself.
    pub shape_inflections: Option<usize>,
    /// The printed count and parameter, points placed by the paper's rule
    /// ([`paper_points`]).
    pub printed: Configuration,
    /// The fewest points with the paper's rule and the printed parameter that meet the
    /// tolerance (`None`: no count up to [`MAX_POINTS`] does, or the rule places no more
    /// points).
    pub paper_rule: Option<Configuration>,
    /// The fewest points found by the automatic search (parameter, end condition or order
    /// chosen too), started below [`CellStudy::paper_rule`]'s count.
    pub automatic: Choice,
    /// Every count the search tried with the full budget ([`crate::interp::choice::search`]).
    pub attempts: Vec<Attempt>,
    /// Whether the automatic count is known to be the fewest.
    pub minimality: Minimality,
}

impl CellStudy {
    /// The count one point below the automatic one, if it was searched.
    pub fn below(&self) -> Option<&Attempt> {
        crate::interp::choice::attempt_below(&self.attempts, &self.automatic)
    }
}

/// How our automatic count compares with the printed one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Verdict {
    /// The same count.
    Agrees,
    /// Fewer points than printed.
    Fewer,
    /// More points than printed.
    More,
    /// No configuration the search tried, up to its largest count, meets the tolerance: the
    /// count needed is not known (the study reports the smallest error it found).
    NoneWithin,
}

impl CellStudy {
    /// How the automatic count compares with the printed one (the words of why are the
    /// report layer's: `CellStudy::verdict`, feature `report`).
    pub fn outcome(&self) -> Verdict {
        if !self.automatic.within_tolerance {
            return Verdict::NoneWithin;
        }
        match self.automatic.measure.counted.cmp(&self.cell.points) {
            std::cmp::Ordering::Equal => Verdict::Agrees,
            std::cmp::Ordering::Less => Verdict::Fewer,
            std::cmp::Ordering::Greater => Verdict::More,
        }
    }
}

/// The study of one printed cell (module docs), with the search's `options` (its `known`
/// field is set from the paper's rule).
///
/// # Errors
/// [`Error::IndexOutOfRange`] for a cell whose column names no shape of [`SHAPES`]; the
/// errors of [`paper_points`], [`Target::shape`], [`Target::measure`] and [`search`].
pub fn study_cell(cell: &PrintedCell, options: &SearchOptions) -> Result<CellStudy> {
    let (column, shape) = *SHAPES.get(cell.column).ok_or(Error::IndexOutOfRange {
        what: "Table I shape column",
        index: cell.column,
        len: SHAPES.len(),
    })?;
    let target = Target::shape(&shape, REFERENCE_SEGMENTS)?;
    let tolerance = target.tolerance();
    let configure = |count: usize| -> Result<Configuration> {
        let set = paper_points(&shape, &cell.method, count)?;
        let measure = target.measure(&cell.method, &set.points)?;
        Ok(Configuration {
            method: cell.method,
            points: set.points,
            rule: set.rule,
            measure,
        })
    };
    let printed = configure(cell.points)?;
    let mut paper_rule = None;
    for count in 2..=MAX_POINTS {
        let Ok(c) = configure(count) else { continue };
        // a rule that cannot place `count` points places another number: skip it
        if c.measure.counted == count && c.measure.distances.hausdorff() <= tolerance {
            paper_rule = Some(c);
            break;
        }
    }
    let family = Family::of(&cell.method).unwrap_or(Family::Angular);
    let options = SearchOptions {
        known: paper_rule.as_ref().map(|c| c.choice(tolerance)),
        ..options.clone()
    };
    let found = search(&target, family, &options)?;
    Ok(CellStudy {
        cell: *cell,
        column,
        shape,
        tolerance,
        size: target.size(),
        shape_inflections: target.shape_inflections(),
        printed,
        paper_rule,
        automatic: found.choice,
        attempts: found.attempts,
        minimality: found.minimality,
    })
}

/// The 36 cells of Table I ([`TABLE_I`], row by row), studied on all cores.
///
/// # Errors
/// As [`study_cell`].
pub fn table_i() -> Result<Vec<CellStudy>> {
    let options = table_i_options();
    crate::parallel::map(&TABLE_I, |cell| study_cell(cell, &options))
        .into_iter()
        .collect()
}

/// Points chosen for one method drawn by another.
#[derive(Debug, Clone, PartialEq)]
pub struct CrossStudy {
    /// The paper's column name.
    pub column: &'static str,
    /// The method the points were chosen for (its automatic choice).
    pub source: Method,
    /// The method drawing them (with the parameter of its own automatic choice on the shape).
    pub target: Method,
    /// The points, as the drawing method counts them.
    pub points: usize,
    /// Its error, or why the method refuses the points.
    pub error: std::result::Result<f64, String>,
    /// The drawing method's error with its own automatic points.
    pub own_error: f64,
    /// The shape's size (for percentages).
    pub size: f64,
    /// Whether the curve is "absurd": refused, or beyond [`ABSURD`] tolerances.
    pub absurd: bool,
}

/// The cross-method experiment on the studied cells: for every shape, the automatic points
/// of each method on the shape fed to each other method, drawn with that method's own
/// automatic parameter (a B-spline's order capped by the points it gets). On an open shape
/// the guides go with the drawing method: the Angular and cardinal splines' guides are taken
/// off the points they chose, and a guided drawing method gets its own automatic guides; a
/// B-spline's vertices count as points on the shape.
///
/// # Errors
/// [`Error::TooFewPoints`] for cells that are not whole columns of four methods;
/// the errors of [`Target::shape`].
pub fn cross_methods(cells: &[CellStudy]) -> Result<Vec<CrossStudy>> {
    let mut out = Vec::new();
    for (column, shape) in SHAPES {
        let of_shape: Vec<&CellStudy> = cells.iter().filter(|c| c.shape == shape).collect();
        if of_shape.is_empty() {
            continue;
        }
        let target = Target::shape(&shape, REFERENCE_SEGMENTS)?;
        for source in &of_shape {
            for drawer in &of_shape {
                if std::ptr::eq(*source, *drawer) {
                    continue;
                }
                let points = &exchanged(&source.automatic, &drawer.automatic, target.is_closed());
                let mut method = drawer.automatic.method;
                if let Method::BSpline { order } = method {
                    let available = method.counted_points(points.len(), target.is_closed());
                    method = Method::BSpline {
                        order: order.min(available).max(2),
                    };
                }
                let measured = target.measure(&method, points);
                let error = measured
                    .as_ref()
                    .map(|m| m.distances.hausdorff())
                    .map_err(|e| e.to_string());
                let absurd = error
                    .as_ref()
                    .map_or(true, |&e| e > ABSURD * target.tolerance());
                out.push(CrossStudy {
                    column,
                    source: source.automatic.method,
                    target: method,
                    points: method.counted_points(points.len(), target.is_closed()),
                    error,
                    own_error: drawer.automatic.measure.distances.hausdorff(),
                    size: target.size(),
                    absurd,
                });
            }
        }
    }
    Ok(out)
}

/// The points of `source` as `drawer` takes them (see [`cross_methods`]).
fn exchanged(source: &Choice, drawer: &Choice, closed: bool) -> Vec<Vector2<f64>> {
    let guided = |m: &Method| !closed && matches!(m, Method::Angular | Method::Cardinal { .. });
    let mut on_shape = source.points.clone();
    if guided(&source.method) && on_shape.len() >= 2 {
        on_shape.pop();
        on_shape.remove(0);
    }
    if guided(&drawer.method) && drawer.points.len() >= 2 {
        on_shape.insert(0, drawer.points[0]);
        on_shape.push(drawer.points[drawer.points.len() - 1]);
    }
    on_shape
}

/// The names [`shape_outline`] takes: the paper's column names (`Ellisse 1`) and our shape
/// names (`ellipse-0.7`), one pair per Table I column.
pub fn shape_names() -> Vec<(&'static str, String)> {
    SHAPES.iter().map(|(c, s)| (*c, s.name())).collect()
}

/// The outline of the paper's shape `name` (a column name or a shape name:
/// [`shape_names`]): its reference polyline as Table I measures against
/// ([`crate::shapes::Shape::reference`] with [`REFERENCE_SEGMENTS`] segments), one contour,
/// closed for the closed shapes. [`crate::study::outline::fewest`] on it, with Table I's options, finds Table I's
/// counts (tested): the paper's shapes go through the same path as a user's outline.
///
/// # Errors
/// [`Error::Parse`] for a name that is no shape of Table I (the message lists them).
pub fn shape_outline(name: &str) -> Result<Contour> {
    let (_, shape) = SHAPES
        .iter()
        .find(|(c, s)| c.eq_ignore_ascii_case(name) || s.name().eq_ignore_ascii_case(name))
        .ok_or_else(|| Error::Parse {
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

/// Table I's search options ([`crate::study::table_i::table_i`]): up to [`MAX_POINTS`]
/// points, the default budget, every count below the answer searched.
pub fn table_i_options() -> SearchOptions {
    SearchOptions {
        max_points: MAX_POINTS,
        ..SearchOptions::default()
    }
}

/// The second stage of `splinelab fewest --thorough` ([`crate::study::outline::fewest_in_stages`], after `first`):
/// Table I's budget and every count below the answer searched, as many points as `first`
/// allows (at least Table I's [`MAX_POINTS`]).
pub fn thorough_options(first: &SearchOptions) -> SearchOptions {
    SearchOptions {
        max_points: first.max_points.max(MAX_POINTS),
        ..SearchOptions::default()
    }
}
/// The paper's coastline counts (Angular 92, cardinal 81, relaxed cubic 84) and its 1-in-50
/// decimation's methods (with linear interpolation, no printed count).
pub const COAST_PRINTED: [(Family, Option<usize>); 4] = [
    (Family::Angular, Some(92)),
    (Family::Cardinal, Some(81)),
    (Family::Cubic, Some(84)),
    (Family::Linear, None),
];

/// One method's fewest points on one of seed 004's figures made of contours (a letter, the
/// coastline), beside the paper's count.
#[derive(Debug, Clone)]
pub struct FigureStudy {
    /// The figure, in words (`letter a 1 (DejaVu Sans)`, `Sicily coastline`).
    pub figure: String,
    /// The paper's count, if it prints one.
    pub printed: Option<usize>,
    /// The figure's size (the larger side of its bounding box) and tolerance.
    pub size: f64,
    /// The tolerance, a distance: 1 % of the size.
    pub tolerance: f64,
    /// The search on every contour ([`crate::study::outline::fewest`]).
    pub study: MethodStudy,
    /// For the coastline: the error of the paper's 1-in-50 experiment under this method
    /// ([`decimated_error`]).
    pub decimated: Option<f64>,
}

/// The fewest points per method for the four letters "a" (the paper's three methods each,
/// [`LETTER_FIGURES`]) and the coastline (its four, [`COAST_PRINTED`]), each within 1 % of its
/// size: [`crate::study::outline::fewest`] with [`default_options`], the command line's
/// `fewest`, on each figure's closed contours.
///
/// # Errors
/// The errors of [`letter_a`] and of the searches.
#[cfg(feature = "fonts")]
pub fn letters_and_coast() -> Result<Vec<FigureStudy>> {
    let mut out = Vec::new();
    for (v, methods) in LETTER_FIGURES.iter().enumerate() {
        let letter = letter_a(v + 1)?;
        let contours: Vec<Contour> = letter
            .contours
            .iter()
            .map(|c| Contour {
                points: c.outline.clone(),
                closed: true,
            })
            .collect();
        let methods: Vec<_> = methods
            .iter()
            .map(|&(m, printed)| (Family::of(&m).unwrap_or(Family::Linear), Some(printed)))
            .collect();
        let name = format!("letter a {} ({})", v + 1, letter.name);
        out.extend(figure_study(&name, &contours, &methods, None)?);
    }
    let coast = coastline();
    let contour = Contour {
        points: coast.clone(),
        closed: true,
    };
    out.extend(figure_study(
        "Sicily coastline",
        &[contour],
        &COAST_PRINTED,
        Some(&coast),
    )?);
    Ok(out)
}

/// One figure of [`letters_and_coast`]: each of `methods` (a family and the paper's count)
/// searched on `contours`, with the decimated `coast`'s error where given.
#[cfg(feature = "fonts")]
fn figure_study(
    figure: &str,
    contours: &[Contour],
    methods: &[(Family, Option<usize>)],
    coast: Option<&[Vector2<f64>]>,
) -> Result<Vec<FigureStudy>> {
    let families: Vec<Family> = methods.iter().map(|m| m.0).collect();
    let found = fewest(
        contours,
        Tolerance::default(),
        &families,
        &default_options(),
        &|_| {},
    )?;
    found
        .methods
        .into_iter()
        .zip(methods)
        .map(|(study, &(family, printed))| {
            Ok(FigureStudy {
                figure: figure.into(),
                printed,
                size: found.size,
                tolerance: found.tolerance,
                decimated: coast.map(|c| decimated_error(family, c)).transpose()?,
                study,
            })
        })
        .collect()
}

/// The paper's 1-in-50 experiment on our coastline: every [`COAST_STEP`]th point of the ring
/// under the method of `family` the paper shows (the Angular, the cardinal with `a = 1`, the
/// cyclic cubic; any other family: the polygon), its symmetric Hausdorff distance to the ring.
///
/// # Errors
/// The errors of [`Target::polyline`] and [`Target::measure`] on `coast`.
pub fn decimated_error(family: Family, coast: &[Vector2<f64>]) -> Result<f64> {
    let method = match family {
        Family::Angular => Method::Angular,
        Family::Cardinal => Method::Cardinal { a: 1.0 },
        Family::Cubic => Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        _ => Method::Linear,
    };
    let target = Target::polyline(coast, true, 1.0)?;
    let points = decimate(coast, COAST_STEP);
    Ok(target.measure(&method, &points)?.distances.hausdorff())
}

/// How many pieces of `method`'s curve through `points` change when the point `index` moves
/// by `delta`: the measure of locality (the paper: "only the Angular has the local property").
/// A piece changes when any of `per_piece` samples on it moves by more than `10⁻¹²` of the
/// points' extent.
///
/// # Errors
/// [`Error::IndexOutOfRange`] for an index beyond the points; the errors of
/// [`Method::curve`] for either curve; [`Error::CountMismatch`] if the two curves'
/// pieces differ in number (a B-spline's knots do not move with its points, so they never
/// do).
pub fn pieces_changed(
    method: &Method,
    points: &[Vector2<f64>],
    closed: bool,
    index: usize,
    delta: Vector2<f64>,
) -> Result<usize> {
    if index >= points.len() {
        return Err(Error::IndexOutOfRange {
            what: "moved point",
            index,
            len: points.len(),
        });
    }
    let mut moved = points.to_vec();
    moved[index] += delta;
    let (a, b) = (method.curve(points, closed)?, method.curve(&moved, closed)?);
    let (ba, bb) = (a.breaks(), b.breaks());
    if ba.len() != bb.len() {
        return Err(Error::CountMismatch {
            what: "pieces of the moved curve",
            expected: ba.len(),
            got: bb.len(),
        });
    }
    let extent = points
        .iter()
        .map(|p| p.amax())
        .fold(0.0, f64::max)
        .max(1e-300);
    const PER_PIECE: usize = 16;
    let mut changed = 0;
    for (wa, wb) in ba.windows(2).zip(bb.windows(2)) {
        let differs = (0..=PER_PIECE).any(|k| {
            let f = k as f64 / PER_PIECE as f64;
            let pa = crate::curve::ParametricCurve::point(&a, wa[0] + (wa[1] - wa[0]) * f);
            let pb = crate::curve::ParametricCurve::point(&b, wb[0] + (wb[1] - wb[0]) * f);
            (pa - pb).amax() > 1e-12 * extent
        });
        changed += usize::from(differs);
    }
    Ok(changed)
}
