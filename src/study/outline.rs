//! The fewest points for an outline: for each method family, the fewest points with which it
//! draws every contour of an outline within a [`Tolerance`] ([`fewest`]), the one search behind
//! the command line's `fewest`, seed 004's letters and coastline
//! ([`crate::study::table_i::letters_and_coast`]) and a notebook's own outlines.
//!
//! Each contour of the outline is a [`Target::polyline`] searched on its own
//! ([`crate::interp::choice::search`]); a method's count is the sum over the contours, its error
//! the largest. The searches run on all cores, and `progress` hears of each one that ends. The
//! paper's own shapes are outlines too ([`crate::study::table_i::shape_outline`]): on them,
//! with Table I's options, the search finds `table-i`'s counts.
//!
//! ```
//! use nalgebra::Vector2;
//! use splinelab::input::Contour;
//! use splinelab::interp::choice::{Family, SearchOptions};
//! use splinelab::study::outline::{fewest, Tolerance};
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
//! # Ok::<(), splinelab::Error>(())
//! ```

use crate::error::{positive, Error, Result};
use crate::input::Contour;
use crate::interp::choice::{search, Family, Minimality, Search, SearchOptions, Target};
use crate::shapes::TOLERANCE_FRACTION;
use nalgebra::Vector2;
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
    type Err = Error;

    /// `1%` (a percentage of the size) or `0.05` (a distance); positive and finite.
    fn from_str(s: &str) -> Result<Self> {
        let text = s.trim();
        let (number, percent) = match text.strip_suffix('%') {
            Some(n) => (n.trim(), true),
            None => (text, false),
        };
        let value: f64 = number.parse().map_err(|_| Error::Parse {
            what: "tolerance",
            line: 1,
            column: 1,
            message: format!("{text:?} is neither a percentage (1%) nor a distance (0.05)"),
        })?;
        let value = positive("tolerance", value)?;
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
pub struct MethodStudy {
    /// The method family.
    pub family: Family,
    /// Each contour's search, in the outline's order.
    pub contours: Vec<ContourSearch>,
}

impl MethodStudy {
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

    /// The least sure of the contours' minimalities (`None` for no contour): a method's count
    /// is proven only where every contour's is.
    pub fn minimality(&self) -> Option<&Minimality> {
        let rank = |m: &Minimality| match m {
            Minimality::MethodMinimum => 0,
            Minimality::LowerBound { .. } | Minimality::Optimum { .. } => 1,
            Minimality::Searched | Minimality::Candidates { .. } => 2,
            Minimality::Bisected => 3,
            Minimality::NotMet => 4,
        };
        self.contours
            .iter()
            .map(|c| &c.search.minimality)
            .max_by_key(|m| rank(m))
    }
}

/// The searches of every method on one outline.
#[derive(Debug, Clone)]
pub struct OutlineStudy {
    /// The outline's size: the larger side of the bounding box of all its contours.
    pub size: f64,
    /// The tolerance, a distance.
    pub tolerance: f64,
    /// One entry per method asked for, in the order asked.
    pub methods: Vec<MethodStudy>,
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
/// [`Error::TooFewPoints`] for an outline without contours; the errors of
/// [`Target::polyline`] (a contour of fewer than 2 points, or 3 distinct when closed, or of
/// zero length; a tolerance that is not positive) and of [`search`].
pub fn fewest(
    outline: &[Contour],
    tolerance: Tolerance,
    families: &[Family],
    options: &SearchOptions,
    progress: &(dyn Fn(Progress) + Sync),
) -> Result<OutlineStudy> {
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
/// one. `splinelab fewest --thorough` is [`default_options`] then
/// [`crate::study::table_i::thorough_options`].
///
/// # Errors
/// As [`fewest`]; [`Error::TooFewPoints`] for no stage.
pub fn fewest_in_stages(
    outline: &[Contour],
    tolerance: Tolerance,
    families: &[Family],
    stages: &[SearchOptions],
    progress: &(dyn Fn(Progress) + Sync),
) -> Result<OutlineStudy> {
    if stages.is_empty() {
        return Err(Error::TooFewPoints {
            what: "search stages",
            needed: 1,
            got: 0,
        });
    }
    if outline.is_empty() || families.is_empty() {
        return Err(Error::TooFewPoints {
            what: if outline.is_empty() {
                "outline contours"
            } else {
                "methods to search"
            },
            needed: 1,
            got: 0,
        });
    }
    let size = size(outline);
    let distance = positive("tolerance", tolerance.of(size))?;
    let targets = outline
        .iter()
        .map(|c| Target::polyline(&c.points, c.closed, distance))
        .collect::<Result<Vec<_>>>()?;
    let jobs: Vec<(Family, usize)> = families
        .iter()
        .flat_map(|&f| (0..targets.len()).map(move |k| (f, k)))
        .collect();
    // the longest searches first (the cubic and Angular ones, the largest contours), so that
    // the cores end together; the results back in the jobs' order
    let mut order: Vec<usize> = (0..jobs.len()).collect();
    order.sort_by_key(|&j| {
        let (family, k) = jobs[j];
        (
            cost_rank(family),
            std::cmp::Reverse(targets[k].reference().len()),
        )
    });
    let done = AtomicUsize::new(0);
    let found = crate::parallel::map(&order, |&j| {
        let (family, k) = jobs[j];
        let found = in_stages(&targets[k], family, stages);
        progress(Progress {
            done: done.fetch_add(1, Ordering::Relaxed) + 1,
            total: jobs.len(),
            family,
        });
        found
    });
    let mut results: Vec<Option<Result<Search>>> = (0..jobs.len()).map(|_| None).collect();
    for (&j, f) in order.iter().zip(found) {
        results[j] = Some(f);
    }
    let mut results = results.into_iter().flatten();
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
        methods.push(MethodStudy { family, contours });
    }
    Ok(OutlineStudy {
        size,
        tolerance: distance,
        methods,
    })
}

/// The rank of a family's search by its usual cost on an outline, the longest first: the
/// cubic spline (three end conditions), the Angular spline, the cardinal one (two searches),
/// the B-spline's fits, the polygon's exact optimum.
fn cost_rank(family: Family) -> u8 {
    match family {
        Family::Cubic => 0,
        Family::Angular => 1,
        Family::Cardinal => 2,
        Family::BSpline => 3,
        Family::Linear => 4,
    }
}

/// `target` searched with each of `stages` in turn, each from the previous answer, the best
/// kept ([`fewest_in_stages`]).
fn in_stages(target: &Target, family: Family, stages: &[SearchOptions]) -> Result<Search> {
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

/// The most points a contour is tried with by default (as counted): the letters' and the
/// coast's limit.
pub const DEFAULT_MAX_POINTS: usize = 200;

/// Error evaluations per count and start, per free coordinate, by default: the letters' and
/// the coast's budget.
pub const DEFAULT_BUDGET: usize = 10;

/// The options of `splinelab fewest` by default: the letters' and the coast's search
/// ([`crate::study::table_i::letters_and_coast`]): up to [`DEFAULT_MAX_POINTS`]
/// points, [`DEFAULT_BUDGET`] evaluations per coordinate, counts bisected (the count one below
/// the answer searched in full). [`crate::study::table_i::table_i_options`] are slower and more
/// thorough.
pub fn default_options() -> SearchOptions {
    SearchOptions {
        max_points: DEFAULT_MAX_POINTS,
        budget_per_coordinate: DEFAULT_BUDGET,
        every_count_below: false,
        ..SearchOptions::default()
    }
}

/// The larger side of the bounding box of `contours`' points (0 for none, or for points
/// whose extent overflows): the size a [`Tolerance::Fraction`] is a fraction of.
pub fn size(contours: &[Contour]) -> f64 {
    let all = contours.iter().flat_map(|c| c.points.iter());
    let (lo, hi) = all.fold(
        (
            Vector2::repeat(f64::INFINITY),
            Vector2::repeat(f64::NEG_INFINITY),
        ),
        |(lo, hi), p| (lo.inf(p), hi.sup(p)),
    );
    let side = (hi - lo).amax();
    if side.is_finite() {
        side
    } else {
        0.0
    }
}
