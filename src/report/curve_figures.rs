//! Figures of the lecture seeds 001 (B-splines, NURBS, interpolation) and 003 (de Casteljau,
//! blending functions, OpenGL evaluators), as panels of plane curves.

use crate::bezier::bernstein::bernstein_sum;
use crate::bezier::de_casteljau::{de_casteljau_levels, de_casteljau_recursive};
use crate::blending::functions::{lagrange4, uniform_bspline4};
use crate::blending::opengl::{opengl_polyline, LastGroup};
use crate::blending::window::WindowCurve;
use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::KnotVector;
use crate::curve::ParametricCurve;
use crate::domain::linspace;
use crate::error::Result;
use crate::interp::cubic::{CubicSpline, EndCondition};
use crate::interp::linear::PiecewiseLinear;
use crate::interp::param::Parametrization;
use crate::interp::polynomial::{runge, Lagrange, NodeFamily, RUNGE_INTERVAL};
use crate::nurbs::NurbsCurve;
use crate::report::curve_data as data;
use crate::report::plot2d::{Figure2d, Panel, Series, Style};
use crate::report::style::LINE_PALETTE as C;
use nalgebra::{Vector1, Vector2};
use plotters::prelude::{RGBColor, SeriesLabelPosition};

/// Samples per curve in the figures.
const SAMPLES: usize = 400;
const GREY: RGBColor = RGBColor(120, 120, 120);
const BLACK: RGBColor = RGBColor(0, 0, 0);

fn xy(points: &[Vector2<f64>]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p.x, p.y)).collect()
}

/// A control polygon: grey line with dots.
fn polygon(label: &str, points: &[Vector2<f64>]) -> Series {
    Series::line(label, xy(points), GREY)
        .width(1)
        .styled(Style::LinePoints(4))
}

/// `f` sampled at `SAMPLES` points of `[a, b]`.
fn sampled(a: f64, b: f64, f: impl Fn(f64) -> (f64, f64)) -> Vec<(f64, f64)> {
    linspace(a, b, SAMPLES).into_iter().map(f).collect()
}

/// Any plane curve sampled at `SAMPLES` parameters over its domain.
fn trace<C: ParametricCurve<2>>(c: &C) -> Result<Vec<(f64, f64)>> {
    Ok(xy(&c.polyline(SAMPLES)?))
}

/// Seed 001: the B-spline bases of degree 1 on `(0,0,1,2,3,4,5,5)` and degree 2 on
/// `(0,0,0,1,2,3,4,4,4)`.
pub fn bspline_bases() -> Result<Figure2d> {
    let mut panels = Vec::new();
    for (degree, knots) in [(1, data::BASIS_N1.to_vec()), (2, data::BASIS_N2.to_vec())] {
        let basis = BSplineBasis::try_new(KnotVector::try_new(knots)?, degree)?;
        let (a, b) = basis.domain();
        let ts = linspace(a, b, SAMPLES);
        let values: Vec<Vec<f64>> = ts.iter().map(|&t| basis.all(t)).collect();
        let mut panel = Panel::new(
            format!("degree n = {degree}, knots {}", basis.knots()),
            "t",
            "N_i,n(t)",
        )
        .y_range(-0.05, 2.1)
        .legend_at(SeriesLabelPosition::UpperMiddle);
        for i in 0..basis.len() {
            let pts = ts.iter().zip(&values).map(|(&t, v)| (t, v[i])).collect();
            panel = panel.with(Series::line(
                format!("N{},{degree}", i + 1),
                pts,
                C[i % C.len()],
            ));
        }
        panels.push(panel);
    }
    Ok(Figure2d::new(
        "B-spline bases (seed 001), Cox–de Boor, right end included",
        panels,
        (2, 1),
    ))
}

/// Seed 001: moving `P₄` of the cubic on `{0,0,0,0,¼,½,¾,1,1,1,1}` changes the curve only
/// on `[¼, 1)`.
pub fn bspline_locality() -> Result<Figure2d> {
    let curve = data::locality_curve()?;
    let moved = curve.with_point(data::LOCALITY_INDEX, data::locality_moved_point())?;
    let ts = linspace(0.0, 1.0, SAMPLES);
    let diff: Vec<(f64, f64)> = ts
        .iter()
        .map(|&t| (t, (moved.point(t) - curve.point(t)).norm()))
        .collect();
    let top = Panel::new("curves and control polygons", "x", "y")
        .equal()
        .legend_at(SeriesLabelPosition::UpperLeft)
        .with(polygon("control polygon", curve.points()))
        .with(Series::line("C(t)", trace(&curve)?, C[0]).width(3))
        .with(
            Series::line("after moving P₄", trace(&moved)?, C[1])
                .styled(Style::Dashed)
                .width(3),
        )
        .with(
            Series::line(
                "P₄ → P₄′",
                xy(&[
                    curve.points()[data::LOCALITY_INDEX],
                    data::locality_moved_point(),
                ]),
                BLACK,
            )
            .styled(Style::LinePoints(6)),
        );
    let bottom = Panel::new(
        "distance between the curves at the same t: zero on [0, 1/4]",
        "t",
        "distance",
    )
    .legend_at(SeriesLabelPosition::UpperLeft)
    .with(Series::line("|C_moved(t) − C(t)|", diff, C[1]).width(3))
    .with(
        Series::line(
            "t = 1/4",
            vec![(0.25, 0.0), (0.25, data::locality_shift())],
            GREY,
        )
        .styled(Style::Dashed),
    );
    Ok(Figure2d::new(
        "Locality: cubic B-spline, knots {0,0,0,0,¼,½,¾,1,1,1,1}, P₄ moved",
        vec![top, bottom],
        (2, 1),
    ))
}

/// Seed 001: the quadratic spline curve on `{0,0,0,1/8,…,7/8,1,1,1}`.
pub fn bspline_quadratic() -> Result<Figure2d> {
    let curve = data::quadratic_example()?;
    let knots: Vec<Vector2<f64>> = (0..=8).map(|k| curve.point(k as f64 / 8.0)).collect();
    let panel = Panel::new("10 control points, order m = 3", "x", "y")
        .equal()
        .legend_at(SeriesLabelPosition::LowerRight)
        .with(polygon("control polygon", curve.points()))
        .with(Series::line("C(t)", trace(&curve)?, C[0]).width(3))
        .with(Series::line("C(k/8): segment joints", xy(&knots), C[1]).styled(Style::Points(5)));
    Ok(Figure2d::new(
        "Quadratic B-spline curve, knots {0,0,0,1/8,…,7/8,1,1,1} (seed 001)",
        vec![panel],
        (1, 1),
    ))
}

/// Seed 001: the exact circles from 7 and 9 weighted control points.
pub fn nurbs_circles() -> Result<Figure2d> {
    let mut panels = Vec::new();
    for (name, circle) in [
        (
            "7 points, weights 1, ½, 1, …",
            NurbsCurve::circle7(Vector2::zeros(), 1.0)?,
        ),
        (
            "9 points, weights 1, √2/2, 1, …",
            NurbsCurve::circle9(Vector2::zeros(), 1.0)?,
        ),
    ] {
        let unit = BSplineCurve::try_new(circle.basis().clone(), circle.points().to_vec())?;
        panels.push(
            Panel::new(name, "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(polygon("control polygon", circle.points()))
                .with(
                    Series::line("same points, all weights 1", trace(&unit)?, C[1])
                        .styled(Style::Dashed),
                )
                .with(Series::line("NURBS", trace(&circle)?, C[0]).width(3)),
        );
    }
    Ok(Figure2d::new(
        "The exact circle as a quadratic NURBS (seed 001)",
        panels,
        (1, 2),
    )
    .shared_legend())
}

/// Seed 001: one weight as a shape parameter.
pub fn nurbs_weights() -> Result<Figure2d> {
    let base = data::weight_example()?;
    let mut panel = Panel::new(
        format!("weight w of P{} varied, all others 1", data::WEIGHT_INDEX),
        "x",
        "y",
    )
    .equal()
    .legend_at(SeriesLabelPosition::LowerRight)
    .with(polygon("control polygon", base.points()));
    for (k, &w) in data::WEIGHTS.iter().enumerate() {
        let c = base.with_weight(data::WEIGHT_INDEX, w)?;
        panel = panel.with(Series::line(format!("w = {w}"), trace(&c)?, C[k % C.len()]));
    }
    Ok(Figure2d::new(
        "NURBS: a weight pulls the curve towards its control point (seed 001)",
        vec![panel],
        (1, 1),
    ))
}

/// Seed 001: Runge's phenomenon, degree 9, equispaced vs Chebyshev nodes, and the error vs
/// degree.
pub fn runge_figure() -> Result<Figure2d> {
    let (a, b) = RUNGE_INTERVAL;
    let degree = data::RUNGE_DEGREE;
    let mut top = Panel::new(
        format!("degree {degree}: interpolants of 1/(1+x²)"),
        "x",
        "y",
    )
    .legend_at(SeriesLabelPosition::LowerMiddle)
    .with(Series::line("f(x) = 1/(1+x²)", sampled(a, b, |x| (x, runge(x))), BLACK).width(3));
    for (k, family) in [NodeFamily::Equispaced, NodeFamily::Chebyshev]
        .into_iter()
        .enumerate()
    {
        let x = family.nodes(a, b, degree)?;
        let y: Vec<f64> = x.iter().map(|&t| runge(t)).collect();
        let p = Lagrange::try_new(&x, &y)?;
        let color = C[k];
        top = top
            .with(Series::line(
                format!("p{degree}, {} nodes", family.label()),
                sampled(a, b, |t| (t, p.eval(t))),
                color,
            ))
            .with(
                Series::line("", x.iter().copied().zip(y).collect(), color)
                    .styled(Style::Points(5))
                    .unlabeled(),
            );
    }
    let mut bottom = Panel::new(
        "max |p − f| on [−5, 5] vs degree",
        "degree",
        "log₁₀ max error",
    )
    .legend_at(SeriesLabelPosition::UpperLeft);
    let rows = data::runge_rows()?;
    for (k, family) in [NodeFamily::Equispaced, NodeFamily::Chebyshev]
        .into_iter()
        .enumerate()
    {
        let pts = rows
            .iter()
            .map(|r| (r.degree as f64, r.error(family).log10()))
            .collect();
        bottom = bottom.with(
            Series::line(format!("{} nodes", family.label()), pts, C[k])
                .styled(Style::LinePoints(4)),
        );
    }
    Ok(Figure2d::new(
        "Runge's phenomenon, f(x) = 1/(1+x²) on [−5, 5] (seed 001)",
        vec![top, bottom],
        (2, 1),
    ))
}

/// Seed 001: uniform, chord-length and centripetal parameters for one data set.
pub fn parametrizations() -> Result<Figure2d> {
    let points = data::PARAM_POINTS.map(|(x, y)| Vector2::new(x, y));
    let mut panel = Panel::new(
        "natural cubic spline curves through the same points",
        "x",
        "y",
    )
    .equal()
    .legend_at(SeriesLabelPosition::UpperLeft)
    .with(Series::line("data", xy(&points), BLACK).styled(Style::Points(6)));
    for (k, param) in Parametrization::ALL.into_iter().enumerate() {
        let s = CubicSpline::curve(&points, param, EndCondition::Natural)?;
        panel = panel.with(Series::line(param.label(), trace(&s)?, C[k]).width(3));
    }
    Ok(Figure2d::new(
        "Parametrization of interpolation points (seed 001)",
        vec![panel],
        (1, 1),
    ))
}

/// Seeds 001 and 004: the four end conditions of the cubic spline on samples of `sin`.
pub fn cubic_spline_ends() -> Result<Figure2d> {
    let (x, y) = data::spline_ends_data();
    let (a, b) = (x[0], x[x.len() - 1]);
    let mut top = Panel::new("7 samples of sin x on [0, 2π]", "x", "s(x)")
        .legend_at(SeriesLabelPosition::LowerLeft)
        .with(Series::line("sin x", sampled(a, b, |t| (t, t.sin())), BLACK).width(3));
    // the error vanishes at the nodes; 1e-6 floors the logarithm there
    let log_error = |e: f64| e.abs().max(1e-6).log10();
    let mut bottom = Panel::new("error |s(x) − sin x|", "x", "log₁₀ |error|")
        .legend_at(SeriesLabelPosition::LowerLeft);
    let linear =
        PiecewiseLinear::try_new(&x, &y.iter().map(|&v| Vector1::new(v)).collect::<Vec<_>>())?;
    top = top.with(
        Series::line(
            "piecewise linear",
            sampled(a, b, |t| (t, linear.point(t).x)),
            GREY,
        )
        .styled(Style::Dashed),
    );
    for (k, end) in data::end_conditions().into_iter().enumerate() {
        let s = CubicSpline::function(&x, &y, end)?;
        // natural and periodic ends give the same spline on these data: dash the second
        let style = if matches!(end, EndCondition::Periodic) {
            Style::Dashed
        } else {
            Style::Line
        };
        top = top.with(
            Series::line(end.label(), sampled(a, b, |t| (t, s.value(t))), C[k]).styled(style),
        );
        bottom = bottom.with(
            Series::line(
                end.label(),
                sampled(a, b, |t| (t, log_error(s.value(t) - t.sin()))),
                C[k],
            )
            .styled(style),
        );
    }
    top = top.with(
        Series::line(
            "data",
            x.iter().copied().zip(y.iter().copied()).collect(),
            BLACK,
        )
        .styled(Style::Points(5))
        .unlabeled(),
    );
    Ok(Figure2d::new(
        "Cubic spline end conditions: clamped, natural, periodic, anticyclic",
        vec![top, bottom],
        (2, 1),
    )
    .shared_legend())
}

/// Seed 003: de Casteljau's construction at `u = 0.3, 0.5, 0.7`.
pub fn de_casteljau_figure() -> Result<Figure2d> {
    let points = data::CASTELJAU_POINTS.map(|(x, y)| Vector2::new(x, y));
    let curve: Vec<Vector2<f64>> = linspace(0.0, 1.0, SAMPLES)
        .into_iter()
        .map(|u| de_casteljau_recursive(&points, u))
        .collect::<Result<_>>()?;
    let curve = xy(&curve);
    let mut panels = Vec::new();
    for &u in &data::CASTELJAU_U {
        let levels = de_casteljau_levels(&points, u)?;
        let mut panel = Panel::new(format!("u = {u}"), "x", "y")
            .equal()
            .legend_at(SeriesLabelPosition::LowerMiddle)
            .with(polygon("control points", &points))
            .with(Series::line("Bézier curve", curve.clone(), C[0]).width(3));
        for (level, pts) in levels.iter().enumerate().skip(1) {
            let style = if pts.len() == 1 {
                Style::Points(7)
            } else {
                Style::LinePoints(4)
            };
            let label = if pts.len() == 1 {
                format!("P(u), level {level}")
            } else {
                format!("level {level}")
            };
            panel = panel.with(Series::line(label, xy(pts), C[level % C.len()]).styled(style));
        }
        panels.push(panel);
    }
    Ok(Figure2d::new(
        "de Casteljau: repeated linear interpolation (seed 003)",
        panels,
        (1, 3),
    )
    .shared_legend())
}

/// Seed 003: the Lagrange and uniform cubic B-spline blending functions.
pub fn blending_functions() -> Result<Figure2d> {
    let mut lag = Panel::new("Lagrange, nodes u = −1, 0, 1, 2", "u", "B_i(u)")
        .legend_at(SeriesLabelPosition::UpperMiddle);
    let mut bsp = Panel::new("uniform cubic B-spline, u ∈ [0, 1]", "u", "b_i(u)")
        .legend_at(SeriesLabelPosition::UpperMiddle)
        .y_range(-0.05, 0.8);
    for (i, &color) in C.iter().take(4).enumerate() {
        lag = lag.with(Series::line(
            format!("B{}", i + 1),
            sampled(-1.0, 2.0, |u| (u, lagrange4(u)[i])),
            color,
        ));
        bsp = bsp.with(Series::line(
            format!("b{i}"),
            sampled(0.0, 1.0, |u| (u, uniform_bspline4(u)[i])),
            color,
        ));
    }
    Ok(Figure2d::new(
        "Cubic blending functions (seed 003)",
        vec![lag, bsp],
        (1, 2),
    ))
}

/// Seed 003: the sliding Lagrange window (interpolating) vs the printed `bspline` procedure
/// (approximating) on the same points.
pub fn blending_curves() -> Result<Figure2d> {
    let points = data::four_way_points(7);
    let lagrange = trace(&WindowCurve::lagrange(&points)?)?;
    let bspline = trace(&WindowCurve::printed_bspline(&points)?)?;
    let panel = Panel::new("7 data points", "x", "y")
        .equal()
        .legend_at(SeriesLabelPosition::LowerRight)
        .with(polygon("data / control points", &points))
        .with(Series::line("Lagrange 4-point window (interpolates)", lagrange, C[0]).width(3))
        .with(Series::line("bspline procedure (approximates)", bspline, C[1]).width(3));
    Ok(Figure2d::new(
        "Sliding 4-point windows: Lagrange vs uniform cubic B-spline (seed 003)",
        vec![panel],
        (1, 1),
    ))
}

/// Seed 003: the four-way comparison for 6 and 7 control points.
pub fn four_way() -> Result<Figure2d> {
    let mut panels = Vec::new();
    for count in [6, 7] {
        let points = data::four_way_points(count);
        let cubic = trace(&WindowCurve::printed_bspline(&points)?)?;
        let opengl = opengl_polyline(&points, 5, 60, LastGroup::Truncated)?;
        let casteljau: Vec<Vector2<f64>> = linspace(0.0, 1.0, SAMPLES)
            .into_iter()
            .map(|u| de_casteljau_recursive(&points, u))
            .collect::<Result<_>>()?;
        let bezier: Vec<Vector2<f64>> = linspace(0.0, 1.0, 60)
            .into_iter()
            .filter_map(|u| bernstein_sum(&points, u).ok())
            .collect();
        panels.push(
            Panel::new(format!("{count} control points"), "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(polygon("control points", &points))
                .with(Series::line("cubic spline (bspline procedure)", cubic, C[0]).width(3))
                .with(Series::line("OpenGL spline (order 5)", xy(&opengl), C[1]).width(3))
                .with(Series::line("Casteljau", xy(&casteljau), C[2]).width(5))
                .with(
                    Series::line("Bézier (Bernstein sum, same curve)", xy(&bezier), BLACK)
                        .styled(Style::Points(3)),
                ),
        );
    }
    Ok(Figure2d::new(
        "Four curves from the same control points (seed 003)",
        panels,
        (2, 1),
    )
    .shared_legend())
}

/// Seed 003: the OpenGL-evaluator spline, intended vs as printed (stale control points in the
/// last group).
pub fn opengl_last_group() -> Result<Figure2d> {
    let points = data::four_way_points(7);
    let mut panels = Vec::new();
    for (title, last) in [
        ("last group truncated (intended)", LastGroup::Truncated),
        (
            "as printed: last group padded with stale points",
            LastGroup::AsPrinted,
        ),
    ] {
        let line = opengl_polyline(&points, 5, 60, last)?;
        panels.push(
            Panel::new(title, "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(polygon("control points", &points))
                .with(Series::line("glMap1f order 5, step 4", xy(&line), C[1]).width(3)),
        );
    }
    Ok(Figure2d::new(
        "OpenGL evaluator spline on 7 points: groups P0–P4, then P4–P6",
        panels,
        (2, 1),
    )
    .shared_legend())
}
