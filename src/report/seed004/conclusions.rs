//! Seed 004's conclusions checked: each claim of the paper (spec §6) in its words, beside the
//! evidence of our runs — Table I's automatic counts ([`super::table_i`]), the cross-method
//! experiment, a locality measurement, the letters and the coastline ([`super::fewest`]) — and
//! a verdict by named thresholds (each claim one short function judged on the runs' evidence).

use crate::interp::methods::{CubicEnd, Method};
use crate::report::error::Result;
use crate::report::legend::{parameter_legend, Legend};
use crate::report::record::frame_of;
use crate::report::seed004::{fewest, table_i::study};
use crate::report::table::Table;
use crate::shapes::TOLERANCE_FRACTION;
use crate::study::table_i::{
    self as experiment, cross_methods, CellStudy, FigureStudy, MAX_POINTS,
};

/// The points a cell needs for the conclusions: the automatic count where it meets the
/// tolerance, else [`MAX_POINTS`]` + 1`, a lower bound (no count up to the search's largest
/// met it).
fn needed(c: &CellStudy) -> usize {
    if c.automatic.within_tolerance {
        c.automatic.measure.counted
    } else {
        MAX_POINTS + 1
    }
}

/// How a share of cases judges a claim: `≥ supported` supports it, `≤ contradicted`
/// contradicts it, between is mixed. The paper judged by eye; these bounds are ours.
#[derive(Debug, Clone, Copy)]
struct Shares {
    supported: f64,
    contradicted: f64,
}

impl Shares {
    /// Supported, contradicted or mixed, from a measured share `hits / of`.
    fn judge(self, hits: usize, of: usize) -> &'static str {
        let share = hits as f64 / of.max(1) as f64;
        if share >= self.supported {
            "supported"
        } else if share <= self.contradicted {
            "contradicted"
        } else {
            "mixed"
        }
    }
}

/// "Almost always", "on closed figures", "good": three in four cases, against at most two in
/// five.
const MOSTLY: Shares = Shares {
    supported: 0.75,
    contradicted: 0.4,
};
/// "The same on parabolas and hyperbolas", "far from satisfactory": three in four cases,
/// against at most one in four.
const CLEARLY: Shares = Shares {
    supported: 0.75,
    contradicted: 0.25,
};
/// "A poor choice gives absurd shapes": one absurd curve in four, against at most one in
/// twenty.
const OFTEN_ABSURD: Shares = Shares {
    supported: 0.25,
    contradicted: 0.05,
};
/// "Always needs very few points": the cardinal's mean within 10 % of the lowest mean.
const FEW_POINTS: f64 = 1.1;
/// "Useless for polygonal shapes": the cubic needs at least twice the points of the best
/// other method on the rectangle.
const USELESS: usize = 2;
/// "The local property": at most the 4 pieces of a four-point support change when one point
/// moves.
const LOCAL_PIECES: usize = 4;
/// "No superiority" on the coastline: the most points within 25 % of the fewest.
const NO_SUPERIORITY: f64 = 1.25;
/// The four methods of Table I; the first three interpolate.
const FAMILIES: [&str; 4] = ["Angular", "Cardinal", "Cubic", "B-spline"];

/// Supported or contradicted.
fn holds(ok: bool) -> &'static str {
    if ok {
        "supported"
    } else {
        "contradicted"
    }
}

/// What the claims are judged on: the run's studies.
struct Evidence<'a> {
    cells: &'a [CellStudy],
    fewest: &'a [FigureStudy],
    cross: Vec<experiment::CrossStudy>,
    /// Each family's mean points per shape ([`needed`]).
    means: Vec<(&'static str, f64)>,
}

impl Evidence<'_> {
    /// The cells of a family.
    fn of<'s>(&'s self, family: &'s str) -> impl Iterator<Item = &'s CellStudy> + 's {
        self.cells
            .iter()
            .filter(move |c| c.cell.method.family() == family)
    }

    /// The columns where a family met no configuration within 1 %.
    fn unmet(&self, family: &str) -> Vec<&'static str> {
        self.of(family)
            .filter(|c| !c.automatic.within_tolerance)
            .map(|c| c.column)
            .collect()
    }

    /// The interpolating family with the lowest (`min`) or highest mean.
    fn extreme(&self, min: bool) -> (&'static str, f64) {
        let interpolating = self.means[..3].iter().copied();
        let pick = if min {
            interpolating.min_by(|a, b| a.1.total_cmp(&b.1))
        } else {
            interpolating.max_by(|a, b| a.1.total_cmp(&b.1))
        };
        pick.unwrap_or(("", 0.0))
    }

    /// The means in words.
    fn means_text(&self) -> String {
        self.means
            .iter()
            .map(|&(f, m)| match self.unmet(f).as_slice() {
                [] => format!("{f} {m:.1}"),
                columns => format!(
                    "{f} ≥ {m:.1} (none within 1 % up to {MAX_POINTS} points on {}: counted as {})",
                    columns.join(", "),
                    MAX_POINTS + 1
                ),
            })
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// Cross-method curves from points of `from` drawn by `to` (on `columns`, or all): how
    /// many are within 1 %, of how many.
    fn pairs(&self, from: &str, to: &str, columns: &[&str]) -> (usize, usize) {
        let of: Vec<_> = self
            .cross
            .iter()
            .filter(|r| r.source.family() == from && r.target.family() == to)
            .filter(|r| columns.is_empty() || columns.contains(&r.column))
            .collect();
        let good = of.iter().filter(|r| within_one_percent(r)).count();
        (good, of.len())
    }

    /// Each family's total over the letters, `None` where some letter has no configuration
    /// within 1 % (it needs more than the search reached: the most of all), and how many
    /// letters missed.
    fn letter_totals(&self) -> Vec<(String, Option<usize>, usize)> {
        ["Angular", "Cardinal", "Cubic"]
            .iter()
            .map(|f| {
                let of: Vec<_> = self
                    .fewest
                    .iter()
                    .filter(|r| r.decimated.is_none() && format!("{:?}", r.study.family) == *f)
                    .map(|r| &r.study)
                    .collect();
                let missed = of.iter().filter(|r| !r.within_tolerance()).count();
                let total = (missed == 0).then(|| of.iter().map(|r| r.counted()).sum());
                (f.to_string(), total, missed)
            })
            .collect()
    }

    /// The letters' totals in words.
    fn letter_text(&self) -> String {
        let totals = self
            .letter_totals()
            .iter()
            .map(|(f, t, missed)| match t {
                Some(t) => format!("{f} {t}"),
                None => format!("{f}: none within 1 % on {missed} of the letters (the search's points lie on the outline; a G¹ curve through them cannot follow its corners and straight strokes within 1 %)"),
            })
            .collect::<Vec<_>>()
            .join(", ");
        format!("points over the four letters: {totals}")
    }

    /// The family with the fewest (`min`) or most letter points (a miss counts as the most).
    fn letter_extreme(&self, min: bool) -> String {
        let totals = self.letter_totals();
        let key = |t: &&(String, Option<usize>, usize)| t.1.unwrap_or(usize::MAX);
        let pick = if min {
            totals.iter().min_by_key(key)
        } else {
            totals.iter().max_by_key(key)
        };
        pick.map(|t| t.0.clone()).unwrap_or_default()
    }
}

/// Whether a cross-method curve is within 1 % of its shape's size.
fn within_one_percent(r: &experiment::CrossStudy) -> bool {
    r.error
        .as_ref()
        .is_ok_and(|&e| e <= TOLERANCE_FRACTION * r.size)
}

/// One of the paper's conclusions (spec §6): its words, and how our runs judge it (the
/// evidence in words and the verdict).
struct Claim {
    words: &'static str,
    judge: fn(&Evidence) -> Result<(String, &'static str)>,
}

/// The claims, in the paper's order.
const CLAIMS: [Claim; 14] = [
    Claim {
        words: "Angular: on average the fewest points",
        judge: angular_fewest,
    },
    Claim {
        words: "Cardinal: always needs very few points",
        judge: cardinal_few,
    },
    Claim {
        words: "Cubic: on average the most points",
        judge: cubic_most,
    },
    Claim {
        words: "Cubic: relaxed ends are almost always best",
        judge: relaxed_best,
    },
    Claim {
        words: "B-spline: on closed figures the best order is the highest (Bézier)",
        judge: bezier_best,
    },
    Claim {
        words: "Cubic: useless for polygonal shapes",
        judge: cubic_useless_on_polygons,
    },
    Claim {
        words: "Point sets are method-specific; a poor choice gives absurd shapes",
        judge: absurd_shapes,
    },
    Claim {
        words: "Angular-optimal points under the cardinal: the same on parabolas and hyperbolas",
        judge: angular_points_under_cardinal,
    },
    Claim {
        words: "Angular-optimal points under the cubic: far from satisfactory",
        judge: angular_points_under_cubic,
    },
    Claim {
        words: "Cubic-optimal points under the Angular: good (except the sinusoid)",
        judge: cubic_points_under_angular,
    },
    Claim {
        words: "Only the Angular spline has the local property",
        judge: only_angular_local,
    },
    Claim {
        words: "Letter a: the Angular needs the fewest points",
        judge: letters_angular_fewest,
    },
    Claim {
        words: "Letter a: the cardinal gives the worst results (many points)",
        judge: letters_cardinal_worst,
    },
    Claim {
        words: "Coastline: no method, not even linear interpolation, shows any superiority",
        judge: coast_no_superiority,
    },
];

fn angular_fewest(e: &Evidence) -> Result<(String, &'static str)> {
    let lowest = e.extreme(true);
    let verdict = if lowest.0 == "Angular" && !e.unmet("Angular").is_empty() {
        "mixed"
    } else {
        holds(lowest.0 == "Angular")
    };
    Ok((
        format!("mean automatic points per shape: {}", e.means_text()),
        verdict,
    ))
}

fn cardinal_few(e: &Evidence) -> Result<(String, &'static str)> {
    let (lowest, cardinal) = (e.extreme(true), e.means[1].1);
    Ok((
        format!(
            "Cardinal mean {cardinal:.1} vs the lowest of the interpolating methods {:.1} ({})",
            lowest.1, lowest.0
        ),
        holds(cardinal <= FEW_POINTS * lowest.1),
    ))
}

fn cubic_most(e: &Evidence) -> Result<(String, &'static str)> {
    let highest = e.extreme(false);
    let at_least = if e.unmet(highest.0).is_empty() {
        ""
    } else {
        "≥ "
    };
    Ok((
        format!(
            "the highest mean of the interpolating methods: {} {at_least}{:.1}",
            highest.0, highest.1
        ),
        holds(highest.0 == "Cubic"),
    ))
}

fn relaxed_best(e: &Evidence) -> Result<(String, &'static str)> {
    let cubic: Vec<&CellStudy> = e.of("Cubic").collect();
    let relaxed = Method::Cubic {
        end: CubicEnd::Relaxed,
    };
    let chosen = cubic
        .iter()
        .filter(|c| c.automatic.method == relaxed)
        .count();
    let ends = cubic
        .iter()
        .map(|c| format!("{} {}", c.column, parameter_legend(&c.automatic.method)))
        .collect::<Vec<_>>()
        .join(", ");
    Ok((
        format!(
            "the automatic search chose relaxed on {chosen} of {} shapes ({ends})",
            cubic.len()
        ),
        MOSTLY.judge(chosen, cubic.len()),
    ))
}

fn bezier_best(e: &Evidence) -> Result<(String, &'static str)> {
    let closed: Vec<&CellStudy> = e
        .of("B-spline")
        .filter(|c| c.shape.is_closed() && c.shape.corners().is_empty())
        .collect();
    let order = |c: &CellStudy| match c.automatic.method {
        Method::BSpline { order } => order,
        _ => 0,
    };
    let bezier = closed
        .iter()
        .filter(|c| order(c) == c.automatic.measure.counted)
        .count();
    let chosen = closed
        .iter()
        .map(|c| {
            let (k, n) = (order(c), c.automatic.measure.counted);
            format!("{} k = {k} with {n} vertices", c.column)
        })
        .collect::<Vec<_>>()
        .join(", ");
    Ok((
        format!(
            "orders chosen on the circle and ellipses: {chosen}; Bézier (order = vertices) on {bezier} of {}",
            closed.len()
        ),
        MOSTLY.judge(bezier, closed.len()),
    ))
}

fn cubic_useless_on_polygons(e: &Evidence) -> Result<(String, &'static str)> {
    let rect: Vec<&CellStudy> = e
        .cells
        .iter()
        .filter(|c| !c.shape.corners().is_empty())
        .collect();
    let is_cubic = |c: &&&CellStudy| c.cell.method.family() == "Cubic";
    let cubic = rect.iter().find(is_cubic).map_or(0, |c| needed(c));
    let best = rect
        .iter()
        .filter(|c| !is_cubic(c))
        .map(|c| needed(c))
        .min()
        .unwrap_or(0);
    let counts = rect
        .iter()
        .map(|c| {
            let family = c.cell.method.family();
            if c.automatic.within_tolerance {
                format!("{family} {}", c.automatic.measure.counted)
            } else {
                format!("{family} none within 1 % up to {MAX_POINTS}")
            }
        })
        .collect::<Vec<_>>()
        .join(", ");
    Ok((
        format!("the rectangle needs {cubic} points with the cubic, {best} with the best other method; {counts}"),
        holds(cubic >= USELESS * best),
    ))
}

fn absurd_shapes(e: &Evidence) -> Result<(String, &'static str)> {
    let absurd = e.cross.iter().filter(|r| r.absurd).count();
    let within = e.cross.iter().filter(|r| within_one_percent(r)).count();
    Ok((
        format!(
            "{absurd} of {} cross-method curves are absurd (refused or beyond 5 % of the size), {within} stay within 1 %",
            e.cross.len()
        ),
        OFTEN_ABSURD.judge(absurd, e.cross.len()),
    ))
}

fn angular_points_under_cardinal(e: &Evidence) -> Result<(String, &'static str)> {
    let conics = ["Parabola 1", "Parabola 2", "Iperbole 1", "Iperbole 2"];
    let (good, of) = e.pairs("Angular", "Cardinal", &conics);
    Ok((
        format!("within 1 % on {good} of {of} parabolas and hyperbolas"),
        CLEARLY.judge(good, of),
    ))
}

fn angular_points_under_cubic(e: &Evidence) -> Result<(String, &'static str)> {
    let (good, of) = e.pairs("Angular", "Cubic", &[]);
    Ok((
        format!("within 1 % on {good} of {of} shapes"),
        CLEARLY.judge(of - good, of),
    ))
}

fn cubic_points_under_angular(e: &Evidence) -> Result<(String, &'static str)> {
    let (good, of) = e.pairs("Cubic", "Angular", &[]);
    Ok((
        format!("within 1 % on {good} of {of} shapes"),
        MOSTLY.judge(good, of),
    ))
}

/// Locality: 12 points of the ellipse 0.4, closed, the seventh moved by (0.02, 0.02).
fn only_angular_local(_: &Evidence) -> Result<(String, &'static str)> {
    let ellipse: Vec<nalgebra::Vector2<f64>> = (0..12)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 12.0;
            nalgebra::Vector2::new(t.cos(), 0.4 * t.sin())
        })
        .collect();
    let moved = nalgebra::Vector2::new(0.02, 0.02);
    let methods = [
        Method::Angular,
        Method::Cardinal { a: 0.83 },
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        Method::BSpline { order: 4 },
    ];
    let local: Vec<(String, usize, usize)> = methods
        .iter()
        .map(|m| {
            let changed = experiment::pieces_changed(m, &ellipse, true, 6, moved)?;
            let pieces = m.curve(&ellipse, true)?.breaks().len() - 1;
            Ok((m.legend().into_owned(), changed, pieces))
        })
        .collect::<Result<_>>()?;
    let others_local = local[1..].iter().filter(|l| l.1 <= LOCAL_PIECES).count();
    let changes = local
        .iter()
        .map(|(m, c, n)| format!("{m} {c} of {n}"))
        .collect::<Vec<_>>()
        .join(", ");
    Ok((
        format!("pieces that change when one of 12 closed points moves: {changes}"),
        holds(others_local == 0),
    ))
}

fn letters_angular_fewest(e: &Evidence) -> Result<(String, &'static str)> {
    Ok((e.letter_text(), holds(e.letter_extreme(true) == "Angular")))
}

fn letters_cardinal_worst(e: &Evidence) -> Result<(String, &'static str)> {
    Ok((
        e.letter_text(),
        holds(e.letter_extreme(false) == "Cardinal"),
    ))
}

/// A method without a configuration within 1 % counts as needing the most.
fn coast_no_superiority(e: &Evidence) -> Result<(String, &'static str)> {
    let coast: Vec<(String, usize)> = e
        .fewest
        .iter()
        .filter(|r| r.decimated.is_some())
        .map(|r| {
            let n = if r.study.within_tolerance() {
                r.study.counted()
            } else {
                usize::MAX
            };
            (format!("{:?}", r.study.family), n)
        })
        .collect();
    let lo = coast.iter().map(|c| c.1).min().unwrap_or(0);
    let hi = coast.iter().map(|c| c.1).max().unwrap_or(0);
    let counts = coast
        .iter()
        .map(|(f, n)| {
            if *n == usize::MAX {
                format!("{f} none within 1 %")
            } else {
                format!("{f} {n}")
            }
        })
        .collect::<Vec<_>>()
        .join(", ");
    Ok((
        format!("fewest points within 1 %: {counts}"),
        holds(hi as f64 <= NO_SUPERIORITY * lo as f64),
    ))
}

crate::record! {
    /// A row of the conclusions table.
    struct Conclusion {
        claim: String => "claim",
        evidence: String => "evidence",
        verdict: String => "verdict",
    }
}

/// The paper's conclusions (spec §6), each beside the evidence our runs give for it: Table I's
/// automatic counts, the cross-method experiment, a locality measurement, the letters and the
/// coastline.
///
/// # Errors
/// As [`study`], [`cross_methods`], [`fewest::study`] and [`experiment::pieces_changed`]; a
/// ragged frame (an internal error).
pub fn conclusions() -> Result<Table> {
    conclusions_of(study()?, fewest::study()?)
}

/// [`conclusions`] of studies a caller holds (see [`super::table_i::table_of`]).
///
/// # Errors
/// As [`cross_methods`] and [`experiment::pieces_changed`]; a ragged frame (an internal error).
pub fn conclusions_of(cells: &[CellStudy], fewest: &[FigureStudy]) -> Result<Table> {
    let id = "table-seed004-conclusions";
    let mean = |family: &str| {
        let of: Vec<f64> = cells
            .iter()
            .filter(|c| c.cell.method.family() == family)
            .map(|c| needed(c) as f64)
            .collect();
        of.iter().sum::<f64>() / of.len().max(1) as f64
    };
    let evidence = Evidence {
        cells,
        fewest,
        cross: cross_methods(cells)?,
        means: FAMILIES.iter().map(|&f| (f, mean(f))).collect(),
    };
    let rows = CLAIMS
        .iter()
        .map(|claim| {
            let (evidence, verdict) = (claim.judge)(&evidence)?;
            Ok(Conclusion {
                claim: claim.words.into(),
                evidence,
                verdict: verdict.into(),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Table::new(
        id,
        "Seed 004: the paper's conclusions beside the evidence of our runs",
        frame_of(id, &rows)?,
    )
    .note("Claims in the paper's words (spec §6). Evidence: the automatic counts of table-i (tolerance 1 %), the cross-method table table-i-cross (within 1 % / absurd beyond 5 %), a locality measurement (study::table_i::pieces_changed: 12 points of the ellipse 0.4, closed, the seventh moved by (0.02, 0.02)), and table-seed004-fewest. Verdicts: supported / contradicted / mixed by the thresholds in report::seed004::conclusions; the paper judged by eye and ease of use as well, which no number here measures.")
    .note("Locality: the cardinal spline with Clark's tangents has the same 4-point support as the Angular spline, and a B-spline of order k < n + 1 changes k pieces; only the cubic spline is global (spec A13)."))
}
