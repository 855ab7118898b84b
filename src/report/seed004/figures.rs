//! Figures of seed 004 (Barsi & Milanesi 1986). The paper's figures are lost; only captions
//! and panel labels survive (`spec/seed004.md` §3), so these are drawn from the methods with
//! the stated point rules of [`crate::seeds::seed004`]. Every figure is a thin call of the
//! public drawing API ([`draw::methods`], [`draw::interpolation`], [`Plot2d`]).

use crate::bspline::curve::BSplineCurve;
use crate::curve::ParametricCurve;
use crate::interp::angular::{circumcircle, AngularSpline};
use crate::interp::methods::{CubicEnd, Method};
use crate::report::draw::{self, Plot2d};
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::legend::Legend;
use crate::report::plot2d::{xy, Figure2d, Panel, Series, Style, GREY, INK};
use crate::report::style::LINE_PALETTE as C;
use crate::seeds::letters::{letter_a, Letter};
use crate::seeds::seed004::{self as data, paper_points, TABLE_I};
use crate::shapes::Shape;
use nalgebra::Vector2;
use std::f64::consts::TAU;

type V = Vector2<f64>;

fn v(x: f64, y: f64) -> V {
    V::new(x, y)
}

/// Samples of the dense reference shapes drawn under the curves.
const REFERENCE: usize = 1200;

/// The control polygon of Figs 1 and 2 (the paper's is lost).
pub const POLYGON: [(f64, f64); 6] = [
    (0.0, 0.0),
    (1.0, 2.2),
    (3.0, 2.6),
    (4.0, 0.4),
    (6.0, 0.0),
    (7.0, 2.0),
];

/// Rows and columns for `n` panels, at most `columns` a row.
fn layout(n: usize, columns: usize) -> Result<(usize, usize)> {
    if n == 0 {
        return Err(crate::report::Error::Figure {
            name: "seed 004".into(),
            message: "no panel to draw: give at least one case".into(),
        });
    }
    Ok((n.div_ceil(columns), n.min(columns)))
}

/// Fig. 1: a Bézier curve and its defining polygon; the curve passes through the first and
/// last vertices only (the seed's: `bezier(&plane_points(&POLYGON))`, [`crate::curve::plane_points`]).
///
/// # Errors
/// As [`BSplineCurve::with_order`] (fewer than two vertices, non-finite ones).
pub fn bezier(polygon: &[V]) -> Result<Figure> {
    let p = polygon.to_vec();
    let curve = BSplineCurve::with_order(p.clone(), p.len())?;
    Ok(Plot2d::new(
        "Fig. 1: a Bézier curve and its polygon (seed 004)",
        "x",
        "y",
    )
    .control_polygon("defining polygon", &p)
    .curve("Bézier curve (B-spline of order n + 1)", &curve)?
    .figure())
}

/// Fig. 2: one polygon drawn as B-splines of every order, from the polygon itself (`k = 2`)
/// to the Bézier curve (`k = n + 1`).
///
/// # Errors
/// As [`BSplineCurve::with_order`] (fewer than two vertices, non-finite ones).
pub fn bspline_orders(polygon: &[V]) -> Result<Figure> {
    let p = polygon.to_vec();
    BSplineCurve::with_order(p.clone(), 2)?;
    let mut plot = Plot2d::new(
        format!(
            "Fig. 2: one polygon, B-splines of order k = 2 … {} (seed 004)",
            p.len()
        ),
        "x",
        "y",
    )
    .control_polygon("polygon", &p);
    for k in 2..=p.len() {
        let label = match k {
            2 => "k = 2 (the polygon)".to_string(),
            k if k == p.len() => format!("k = {k} (Bézier)"),
            k => format!("k = {k}"),
        };
        plot = plot.curve(&label, &BSplineCurve::with_order(p.clone(), k)?)?;
    }
    Ok(plot.figure())
}

/// A full circle through `c` of radius `r`, as a series.
fn full_circle(label: &str, c: V, r: f64, color: plotters::style::RGBColor) -> Series {
    let pts = (0..=240)
        .map(|i| {
            let a = TAU * i as f64 / 240.0;
            (c.x + r * a.cos(), c.y + r * a.sin())
        })
        .collect();
    Series::line(label, pts, color)
        .styled(Style::Dashed)
        .width(1)
}

/// The panel of one Angular piece `P_i → P_{i+1}` with its guides, circles, centres and end
/// tangents, in the piece's local frame.
fn frame_panel(title: &str, guides: (V, V), annotate: bool) -> Result<Panel> {
    let (pi, pj) = (v(-1.0, 0.0), v(1.0, 0.0));
    let pts = vec![guides.0, pi, pj, guides.1];
    let spline = AngularSpline::try_new(pts.clone())?;
    let mut panel = Panel::new(title, "x (on the chord)", "y")
        .equal()
        .with(
            Series::line("", vec![(-2.2, 0.0), (2.2, 0.0)], GREY)
                .width(1)
                .unlabeled(),
        )
        .with(
            Series::line("", vec![(0.0, -1.6), (0.0, 1.6)], GREY)
                .width(1)
                .unlabeled(),
        );
    for (k, (a, b, c)) in [(guides.0, pi, pj), (pi, pj, guides.1)]
        .into_iter()
        .enumerate()
    {
        if let Some((centre, r)) = circumcircle(a, b, c) {
            if r < 6.0 {
                let name = if k == 0 { "C_i" } else { "C_i+1" };
                panel = panel.with(full_circle(name, centre, r, C[1 + k]));
                let end = if k == 0 { pi } else { pj };
                panel = panel.with(
                    Series::line("", xy(&[centre, end]), C[1 + k])
                        .width(1)
                        .unlabeled(),
                );
                panel = panel.with(
                    Series::line("", xy(&[centre]), C[1 + k])
                        .styled(Style::Points(4))
                        .unlabeled(),
                );
                if annotate {
                    let label = if k == 0 { "(0, c_i)" } else { "(0, c_i+1)" };
                    panel = panel.note(centre.x + 0.06, centre.y, label);
                    let mid = (centre + end) * 0.5;
                    let angle = if k == 0 {
                        "radius at ϑ_i"
                    } else {
                        "radius at ϑ_i+1"
                    };
                    panel = panel.note(mid.x, mid.y + 0.12, angle);
                }
            }
        }
    }
    let kind = spline.kinds()[0];
    let title_kind = format!("{title} [{kind:?}]");
    panel.title = if annotate {
        title.to_string()
    } else {
        title_kind
    };
    panel = panel.with(Series::line(
        "Angular piece",
        xy(&spline.polyline(400)?),
        C[0],
    ));
    // tangent arrows at both ends
    let drawn = Plot2d::new("", "", "")
        .tangents(&spline, &[0.0, 1.0], 0.35)
        .panel();
    for s in drawn.series {
        panel = panel.with(s);
    }
    panel = panel.with(Series::line("P_i-1 … P_i+2", xy(&pts), INK).styled(Style::Crosses(5)));
    if annotate {
        for (p, name) in pts.iter().zip(["P_i-1", "P_i", "P_i+1", "P_i+2"]) {
            panel = panel.note(p.x + 0.05, p.y - 0.05, name);
        }
    }
    Ok(panel)
}

/// The guides of Fig. 3 (ours; the paper's are not stated): below the chord.
pub const FRAME_GUIDES: (V, V) = (V::new(-0.845, -0.841), V::new(1.072, -0.94));
/// The guides of Fig. 4: those of Fig. 3 mirrored above the chord.
pub const REFLECTION_GUIDES: (V, V) = (V::new(-0.845, 0.841), V::new(1.072, 0.94));

/// Fig. 3: the Angular spline's local frame: the chord on the x-axis with its midpoint at the
/// origin, the circles `C_i`, `C_{i+1}` through three consecutive points with centres on the
/// y-axis, the radii at `P_i`, `P_{i+1}` and the end tangents, for the guides `P_{i−1}`,
/// `P_{i+2}` of the chord `(−1, 0) → (1, 0)` (the seed's figure: `(−0.845, −0.841)`,
/// `(1.072, −0.94)`).
///
/// # Errors
/// As [`AngularSpline::try_new`].
pub fn angular_frame(guides: (V, V)) -> Result<Figure> {
    let panel = frame_panel(
        "Fig. 3: the local frame of an Angular piece (guides below: the standard case)",
        guides,
        true,
    )?;
    Ok(Figure2d::new("", vec![panel], (1, 1)).into())
}

/// Fig. 4: the reflection case: both guides above the chord; the piece is the standard piece
/// of the mirrored guides `P′_{i−1}`, `P′_{i+2}`, mirrored back (the seed's figure: the guides
/// of [`angular_frame`] mirrored, `(−0.845, 0.841)`, `(1.072, 0.94)`).
///
/// # Errors
/// As [`AngularSpline::try_new`].
pub fn angular_reflection(above: (V, V)) -> Result<Figure> {
    let mirrored = (
        above.0.component_mul(&v(1.0, -1.0)),
        above.1.component_mul(&v(1.0, -1.0)),
    );
    let mut panel = frame_panel(
        "Fig. 4: guides above the chord (the reflection case)",
        above,
        true,
    )?;
    let standard = AngularSpline::try_new(vec![mirrored.0, v(-1.0, 0.0), v(1.0, 0.0), mirrored.1])?;
    panel = panel
        .with(
            Series::line(
                "standard piece of the mirrored guides",
                xy(&standard.polyline(400)?),
                GREY,
            )
            .styled(Style::Dashed),
        )
        .with(
            Series::line("P′_i-1, P′_i+2", xy(&[mirrored.0, mirrored.1]), GREY)
                .styled(Style::Crosses(5)),
        )
        .note(mirrored.0.x + 0.05, mirrored.0.y - 0.05, "P′_i-1")
        .note(mirrored.1.x + 0.05, mirrored.1.y - 0.05, "P′_i+2")
        .y_range(-1.7, 2.6);
    Ok(Figure2d::new("", vec![panel], (1, 1)).into())
}

/// Fig. 5 a–f: single Angular pieces on one chord for six pairs of guides: symmetric (an arc
/// of a circle), asymmetric, both above (reflected), opposite sides (an inflection, rule A1),
/// a guide near the chord's line (the turn gathers at the far end: on the line itself the
/// limit has a corner, and the spline refuses it), guides inside the chord's circle (a major
/// arc). The paper's six configurations are not stated (spec A18); [`angular_cases`] are ours.
/// Each case is a short title (the piece's case follows it in brackets) and the two guides.
///
/// # Errors
/// No case; the errors of [`AngularSpline::try_new`].
pub fn angular_pieces(cases: &[(&str, V, V)]) -> Result<Figure> {
    let panels = cases
        .iter()
        .map(|&(title, a, b)| frame_panel(title, (a, b), false))
        .collect::<Result<Vec<_>>>()?;
    let layout = layout(panels.len(), 3)?;
    Ok(Figure2d::new(
        format!(
            "Fig. 5: Angular pieces from P_i = (−1, 0) to P_i+1 = (1, 0) for {} pairs of guides",
            panels.len()
        ),
        panels,
        layout,
    )
    .shared_legend()
    .into())
}

/// The six pairs of guides of Fig. 5 (ours; the paper's are not stated).
pub fn angular_cases() -> Vec<(&'static str, V, V)> {
    vec![
        ("a) symmetric: an arc", v(-1.8, -1.2), v(1.8, -1.2)),
        ("b) asymmetric", v(-1.6, -0.8), v(1.2, -1.5)),
        ("c) both above", v(-1.8, 1.2), v(1.6, 0.8)),
        ("d) opposite sides", v(-1.8, -1.0), v(1.8, 1.0)),
        ("e) guide near the line", v(-2.0, -0.15), v(1.8, -1.0)),
        ("f) guides inside", v(0.0, -0.5), v(0.0, -0.5)),
    ]
}

/// The cardinal spline's parameter on `count` points equally spaced round a closed `shape`,
/// one panel per value of `a` (the seed's: the 4-point circle with the polygon-like `a → 0`,
/// Catmull–Rom `a = ½`, the paper's 0.83 and a swollen 1.2).
///
/// # Errors
/// An open shape, no value of `a`; the errors of the shape and of the cardinal spline.
pub fn cardinal_a(shape: &Shape, count: usize, a_values: &[f64]) -> Result<Figure> {
    let shape = shape.validated()?;
    if !shape.is_closed() {
        return Err(crate::error::Error::Degenerate {
            what: "cardinal_a's shape",
            reason: "the shape is open; the figure goes round a closed shape",
        }
        .into());
    }
    crate::error::size("points", count)?;
    let q: Vec<V> = (0..count)
        .map(|i| shape.point(TAU * i as f64 / count as f64))
        .collect();
    let cases: Vec<(Method, Vec<V>, bool)> = a_values
        .iter()
        .map(|&a| (Method::Cardinal { a }, q.clone(), true))
        .collect();
    draw::methods(
        format!(
            "The cardinal spline's a on {count} points of the {}",
            shape.name()
        ),
        &shape.reference(REFERENCE)?,
        &cases,
        layout(cases.len(), 2)?,
    )
}

/// One shape under several methods, each with its own count of points placed by the seed's
/// rule ([`paper_points`]); a count the method cannot have (the paper's Angular "5 (?)" on
/// the ellipse) is drawn with the count the points give, and the title says so. Table I's
/// column `c` is `shape_methods(&SHAPES[c].1, &cells)` with the column's printed cells.
///
/// # Errors
/// No cell; the errors of the point rules and the methods.
pub fn shape_methods(shape: &Shape, cells: &[(Method, usize)]) -> Result<Figure> {
    let mut cases = Vec::with_capacity(cells.len());
    let mut flagged = String::new();
    for &(method, count) in cells {
        let set = paper_points(shape, &method, count)?;
        let drawn = method.counted_points(set.points.len(), set.closed);
        if drawn != count {
            flagged += &format!(" (printed {} {count}, drawn with {drawn})", method.legend());
        }
        cases.push((method, set.points, set.closed));
    }
    draw::methods(
        format!("Seed 004, the {}: four methods{flagged}", shape.name()),
        &shape.reference(REFERENCE)?,
        &cases,
        layout(cases.len(), 2)?,
    )
}

/// The printed cells of Table I's column `column` (0–8), as `(method, count)`.
///
/// # Errors
/// [`crate::report::Error::UnknownId`] for a column beyond the nine.
pub fn printed_column(column: usize) -> Result<(Shape, Vec<(Method, usize)>)> {
    let &(_, shape) = data::SHAPES
        .get(column)
        .ok_or_else(|| crate::report::Error::UnknownId {
            what: "Table I column (0–8)",
            id: column.to_string(),
        })?;
    let cells = TABLE_I
        .iter()
        .filter(|c| c.column == column)
        .map(|c| (c.method, c.points))
        .collect();
    Ok((shape, cells))
}

/// Table I's column `column` (0–8): its shape under the four methods with the printed counts.
///
/// # Errors
/// As [`printed_column`] and [`shape_methods`].
pub fn shape_column(column: usize) -> Result<Figure> {
    let (shape, cells) = printed_column(column)?;
    shape_methods(&shape, &cells)
}

macro_rules! column_figures {
    ($($name:ident = $col:expr, $doc:expr;)*) => {
        $(
            #[doc = $doc]
            pub fn $name() -> Result<Figure> {
                shape_column($col)
            }
        )*
    };
}

column_figures! {
    circle = 0, "Table I's circle column: Angular 6, cardinal 7 (a = 0.83), cubic relaxed 11, Bézier 9.";
    ellipse_07 = 1, "Table I's ellipse 0.7 column (the printed Angular \"5 (?)\" drawn with 7).";
    ellipse_04 = 2, "Table I's ellipse 0.4 column.";
    parabola_2 = 3, "Table I's more closed parabola (`|x| ≤ 2`).";
    parabola_1 = 4, "Table I's more open parabola (`|x| ≤ 1`).";
    hyperbola_2 = 5, "Table I's more closed hyperbola (`b = 2`).";
    hyperbola_05 = 6, "Table I's more open hyperbola (`b = ½`).";
    sinusoid = 7, "Table I's sinusoid column.";
    rectangle = 8, "Table I's rectangle column.";
}

/// Points placed for one method fed to others (Figs 6–8: "points optimal for one method,
/// interpolated with another"): `source` is the method and count whose points (by the seed's
/// rule, [`paper_points`]) every method of `targets` then draws.
///
/// # Errors
/// The errors of the point rule and the methods.
pub fn cross_methods(
    title: &str,
    shape: &Shape,
    source: (Method, usize),
    targets: &[Method],
) -> Result<Figure> {
    let set = paper_points(shape, &source.0, source.1)?;
    let (points, closed) = (set.points, set.closed);
    let mut cases = vec![(source.0, points.clone(), closed)];
    cases.extend(targets.iter().map(|&m| (m, points.clone(), closed)));
    // wide shapes stacked, the others side by side
    let (x0, x1, y0, y1) = shape.bounding_box();
    let layout = if x1 - x0 > 1.5 * (y1 - y0) {
        (cases.len(), 1)
    } else {
        (1, cases.len())
    };
    draw::methods(title, &shape.reference(REFERENCE)?, &cases, layout)
}

/// A cross figure whose source is Table I's printed cell of `family` in `column`.
fn cross(title: &str, column: usize, source: Method, targets: &[Method]) -> Result<Figure> {
    let (shape, cells) = printed_column(column)?;
    let count = cells
        .iter()
        .find(|(m, _)| m.family() == source.family())
        .map_or(0, |&(_, n)| n);
    cross_methods(title, &shape, (source, count), targets)
}

/// Fig. 6: the circle's Angular points (3, closed) under the cardinal spline with `a = 0.9` and
/// the relaxed cubic — "the circle is a case apart".
pub fn cross_circle() -> Result<Figure> {
    cross(
        "Fig. 6: the circle's Angular points under the cardinal and the cubic",
        0,
        Method::Angular,
        &[
            Method::Cardinal { a: 0.9 },
            Method::Cubic {
                end: CubicEnd::Relaxed,
            },
        ],
    )
}

/// Fig. 7: the rectangle's cardinal points (its 4 corners) under the Angular spline (the
/// circumscribed circle, an "absurd shape") and the relaxed cubic.
pub fn cross_rectangle() -> Result<Figure> {
    cross(
        "Fig. 7: the rectangle's cardinal points under the Angular and the cubic",
        8,
        Method::Cardinal { a: 0.001 },
        &[
            Method::Angular,
            Method::Cubic {
                end: CubicEnd::Relaxed,
            },
        ],
    )
}

/// Fig. 8 a–b: the sinusoid's cubic points (5, equally spaced) under the Angular spline and the
/// cardinal spline with `a = 0.7` (their first and last points become guides).
pub fn cross_sinusoid() -> Result<Figure> {
    cross(
        "Fig. 8 a–b: the sinusoid's cubic points under the Angular and the cardinal",
        7,
        Method::Cubic {
            end: CubicEnd::Relaxed,
        },
        &[Method::Angular, Method::Cardinal { a: 0.7 }],
    )
}

/// Fig. 8 c–d: the more closed parabola's cubic points (7) under the Angular spline and the
/// cardinal spline with `a = 0.7`.
pub fn cross_parabola() -> Result<Figure> {
    cross(
        "Fig. 8 c–d: the parabola's cubic points under the Angular and the cardinal",
        3,
        Method::Cubic {
            end: CubicEnd::Relaxed,
        },
        &[Method::Angular, Method::Cardinal { a: 0.7 }],
    )
}

/// The three panels of one method on a letter: a) the original outline with the points,
/// b) the curve over the original, c) the curve alone.
fn letter_panels(
    letter: &Letter,
    method: Method,
    printed: usize,
    fig: usize,
) -> Result<Vec<Panel>> {
    let mut curves = Vec::new();
    let mut counted = 0;
    for contour in &letter.contours {
        let curve = method.curve(&contour.points, true)?;
        counted += method.counted_points(contour.points.len(), true);
        curves.push(xy(&curve.polyline(800)?));
    }
    let a = Panel::new(
        format!(
            "Fig. {fig} a) {}: {counted} pts (paper {printed})",
            method.legend()
        ),
        "",
        "",
    )
    .equal();
    let mut a = a;
    let mut b = Panel::new("b) over the original", "", "").equal();
    let mut c = Panel::new("c) curve alone", "", "").equal();
    for (k, contour) in letter.contours.iter().enumerate() {
        let outline = Series::line("original", xy(&contour.outline), GREY)
            .styled(Style::Dashed)
            .width(1);
        let outline = if k == 0 { outline } else { outline.unlabeled() };
        let points = Series::line("points", xy(&contour.points), INK).styled(Style::Crosses(4));
        let points = if k == 0 { points } else { points.unlabeled() };
        let curve = Series::line("interpolated", curves[k].clone(), C[0]);
        let curve = if k == 0 { curve } else { curve.unlabeled() };
        a = a.with(outline.clone()).with(points);
        b = b.with(outline).with(curve.clone());
        c = c.with(curve);
    }
    Ok(vec![a, b, c])
}

/// Figs 9–20 for one version of the letter "a": Angular, cardinal and relaxed cubic, each with
/// the original and its points, the curve over the original and the curve alone. The points are
/// the outline's on-curve points, so the counts are ours; the paper's are in the titles.
pub fn letter(version: usize) -> Result<Figure> {
    let l = letter_a(version)?;
    let mut panels = Vec::new();
    for (k, &(method, printed)) in data::LETTER_FIGURES[version - 1].iter().enumerate() {
        panels.extend(letter_panels(
            &l,
            method,
            printed,
            9 + 3 * (version - 1) + k,
        )?);
    }
    Ok(Figure::from(
        Figure2d::new(
            format!("Seed 004, letter \"a\" version {version} ({})", l.name),
            panels,
            (3, 3),
        )
        .shared_legend(),
    )
    .with_size(1200, 1250))
}

macro_rules! letter_figures {
    ($($name:ident = $v:expr;)*) => {
        $(
            #[doc = concat!("The letter \"a\", version ", stringify!($v), " (see [`letter`]).")]
            pub fn $name() -> Result<Figure> {
                letter($v)
            }
        )*
    };
}

letter_figures! {
    letter_a_1 = 1;
    letter_a_2 = 2;
    letter_a_3 = 3;
    letter_a_4 = 4;
}

fn coast_reference() -> Vec<V> {
    let mut coast = data::coastline();
    coast.push(coast[0]);
    coast
}

/// The coastline panels of the decimation experiment: 1 in `step` points of the coast under
/// each of `methods` (the seed's: 1 in 7 of our 357, about 50, as the paper took 1 in 50 of
/// about 2500, under the Angular, the cardinal with `a = 1`, the cyclic cubic and linear
/// interpolation — "no method shows any superiority").
///
/// # Errors
/// No method; the errors of the methods.
pub fn sicily_decimated(step: usize, methods: &[Method]) -> Result<Figure> {
    let points = data::decimate(&data::coastline(), step);
    let cases: Vec<(Method, Vec<V>, bool)> =
        methods.iter().map(|&m| (m, points.clone(), true)).collect();
    draw::methods(
        format!(
            "Sicily: {} points, 1 in {} of the coastline (x, y in km)",
            points.len(),
            step.max(1)
        ),
        &coast_reference(),
        &cases,
        layout(cases.len(), 2)?,
    )
}

/// The seed's decimation methods: Angular, cardinal `a = 1`, cyclic cubic, linear.
pub const SICILY_METHODS: [Method; 4] = [
    Method::Angular,
    Method::Cardinal { a: 1.0 },
    Method::Cubic {
        end: CubicEnd::Cyclic,
    },
    Method::Linear,
];

/// The coastline with the paper's larger counts (Angular 92, cardinal 81 with `a = 0.9`,
/// relaxed cubic 84), points evenly spaced along our ring as the stand-in for the paper's
/// hand-chosen ones.
pub fn sicily_chosen() -> Result<Figure> {
    let coast = data::coastline();
    let reference = coast_reference();
    let mut panels = Vec::new();
    for (method, count) in [
        (Method::Angular, 92),
        (Method::Cardinal { a: 0.9 }, 81),
        (
            Method::Cubic {
                end: CubicEnd::Relaxed,
            },
            84,
        ),
    ] {
        let distinct = count - (method.counted_points(0, true));
        let points = data::evenly_spaced(&coast, distinct);
        let curve = method.curve(&points, true)?;
        let drawn = method.prepared(&points, true);
        panels.push(draw::interpolation(
            format!("{}: {count} points, over the coast", method.legend()),
            &reference,
            &drawn,
            false,
            &curve,
        )?);
        panels.push(
            Panel::new(format!("{}: the curve alone", method.legend()), "x", "y")
                .equal()
                .with(Series::line("curve", xy(&curve.polyline(3000)?), C[0])),
        );
    }
    Ok(Figure::from(
        Figure2d::new(
            "Sicily with the paper's counts (points evenly spaced along the coast; x, y in km)",
            panels,
            (3, 2),
        )
        .shared_legend(),
    )
    .with_size(1100, 1250))
}
