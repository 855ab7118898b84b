//! Figures of seed 001, the lecture slides on splines (B-splines, NURBS, interpolation), as
//! panels of plane curves.

use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::KnotVector;
use crate::curve::ParametricCurve;
use crate::domain::linspace;
use crate::interp::cubic::{CubicSpline, EndCondition};
use crate::interp::linear::PiecewiseLinear;
use crate::interp::polynomial::{runge, Lagrange, NodeFamily, RUNGE_INTERVAL};
use crate::nurbs::NurbsCurve;
use crate::param::Parametrization;
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::legend::Legend;
use crate::report::plot2d::{
    sampled, trace, xy, Figure2d, Panel, Series, Style, GREY, INK as BLACK, SAMPLES,
};
use crate::report::style::LINE_PALETTE as C;
use crate::seeds::seed001 as data;
use nalgebra::{Vector1, Vector2};
use plotters::prelude::SeriesLabelPosition;

/// B-spline bases, one panel each, stacked (the seed's: degree 1 on `(0,0,1,2,3,4,5,5)` and
/// degree 2 on `(0,0,0,1,2,3,4,4,4)`, [`seed_bases`]).
///
/// # Errors
/// No basis.
pub fn bspline_bases(bases: &[BSplineBasis]) -> Result<Figure> {
    if bases.is_empty() {
        return Err(crate::report::Error::Figure {
            name: "bspline_bases".into(),
            message: "no basis to draw".into(),
        });
    }
    let mut panels = Vec::new();
    for basis in bases {
        let degree = basis.degree();
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
    let rows = panels.len();
    Ok(Figure::from(Figure2d::new(
        "B-spline bases, Cox–de Boor, right end included",
        panels,
        (rows, 1),
    )))
}

/// Seed 001's two example bases (degree 1 and 2).
///
/// # Errors
/// Never in practice.
pub fn seed_bases() -> Result<Vec<BSplineBasis>> {
    Ok(vec![
        BSplineBasis::try_new(KnotVector::try_new(data::BASIS_N1.to_vec())?, 1)?,
        BSplineBasis::try_new(KnotVector::try_new(data::BASIS_N2.to_vec())?, 2)?,
    ])
}

/// Locality: moving control point `index` of `curve` to `to` changes the curve only on the
/// support `[t_i, t_{i+p+1})` of its basis function (the seed's: `P₄` of the cubic on
/// `{0,0,0,0,¼,½,¾,1,1,1,1}`, which changes only on `[¼, 1)`).
///
/// # Errors
/// An index beyond the control points; a non-finite `to`.
pub fn bspline_locality(curve: &BSplineCurve<2>, index: usize, to: Vector2<f64>) -> Result<Figure> {
    let moved = curve.with_point(index, to)?;
    let knots = curve.basis().knots().knots();
    let p = curve.basis().degree();
    let (start, end) = (knots[index], knots[index + p + 1]);
    let (a, b) = curve.basis().domain();
    let ts = linspace(a, b, SAMPLES);
    let diff: Vec<(f64, f64)> = ts
        .iter()
        .map(|&t| (t, (moved.point(t) - curve.point(t)).norm()))
        .collect();
    let top = Panel::new("curves and control polygons", "x", "y")
        .equal()
        .legend_at(SeriesLabelPosition::UpperLeft)
        .with(Series::polygon("control polygon", curve.points()))
        .with(Series::line("C(t)", trace(curve)?, C[0]).width(3))
        .with(
            Series::line("after moving P₄", trace(&moved)?, C[1])
                .styled(Style::Dashed)
                .width(3),
        )
        .with(
            Series::line(
                format!("P{index} → P{index}′"),
                xy(&[curve.points()[index], to]),
                BLACK,
            )
            .styled(Style::LinePoints(6)),
        );
    let shift = (to - curve.points()[index]).norm();
    let mut bottom = Panel::new(
        format!("distance between the curves at the same t: zero outside [{start}, {end})"),
        "t",
        "distance",
    )
    .legend_at(SeriesLabelPosition::UpperLeft)
    .with(Series::line("|C_moved(t) − C(t)|", diff, C[1]).width(3));
    for edge in [start, end] {
        if a < edge && edge < b {
            bottom = bottom.with(
                Series::line(
                    format!("t = {edge}"),
                    vec![(edge, 0.0), (edge, shift)],
                    GREY,
                )
                .styled(Style::Dashed),
            );
        }
    }
    Ok(Figure::from(Figure2d::new(
        format!(
            "Locality: B-spline of degree {p}, knots {}, P{index} moved",
            curve.basis().knots()
        ),
        vec![top, bottom],
        (2, 1),
    )))
}

/// A spline curve with its control polygon and the joints of its pieces `C(t_k)` at the
/// distinct knots (the seed's: the quadratic on `{0,0,0,1/8,…,7/8,1,1,1}`).
///
/// # Errors
/// Never in practice (the curve is valid).
pub fn bspline_quadratic(curve: &BSplineCurve<2>) -> Result<Figure> {
    let mut distinct = curve.basis().knots().knots().to_vec();
    distinct.dedup();
    let (a, b) = curve.basis().domain();
    let knots: Vec<Vector2<f64>> = distinct
        .iter()
        .filter(|&&t| a <= t && t <= b)
        .map(|&t| curve.point(t))
        .collect();
    let panel = Panel::new(
        format!(
            "{} control points, order m = {}",
            curve.points().len(),
            curve.basis().order()
        ),
        "x",
        "y",
    )
    .equal()
    .legend_at(SeriesLabelPosition::LowerRight)
    .with(Series::polygon("control polygon", curve.points()))
    .with(Series::line("C(t)", trace(curve)?, C[0]).width(3))
    .with(Series::line("C(t_k): segment joints", xy(&knots), C[1]).styled(Style::Points(5)));
    Ok(Figure::from(Figure2d::new(
        format!(
            "B-spline curve of degree {}, knots {}",
            curve.basis().degree(),
            curve.basis().knots()
        ),
        vec![panel],
        (1, 1),
    )))
}

/// NURBS curves side by side, each beside the B-spline of its control points with all
/// weights 1 (the seed's: the exact circles from 7 and 9 weighted control points,
/// `NurbsCurve::circle7` and `circle9`).
///
/// # Errors
/// No curve.
pub fn nurbs_circles(curves: &[NurbsCurve<2>]) -> Result<Figure> {
    if curves.is_empty() {
        return Err(crate::report::Error::Figure {
            name: "nurbs_circles".into(),
            message: "no curve to draw".into(),
        });
    }
    let mut panels = Vec::new();
    for circle in curves {
        let w = circle.weights();
        let name = format!(
            "{} points, weights {}, …",
            circle.points().len(),
            w.iter()
                .take(3)
                .map(|x| format!("{x:.4}")
                    .trim_end_matches('0')
                    .trim_end_matches('.')
                    .to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
        let unit = BSplineCurve::try_new(circle.basis().clone(), circle.points().to_vec())?;
        panels.push(
            Panel::new(name.as_str(), "x", "y")
                .equal()
                .legend_at(SeriesLabelPosition::LowerRight)
                .with(Series::polygon("control polygon", circle.points()))
                .with(
                    Series::line("same points, all weights 1", trace(&unit)?, C[1])
                        .styled(Style::Dashed),
                )
                .with(Series::line("NURBS", trace(circle)?, C[0]).width(3)),
        );
    }
    let columns = panels.len();
    Ok(Figure::from(
        Figure2d::new(
            "Rational B-splines (NURBS) and their control points",
            panels,
            (1, columns),
        )
        .shared_legend(),
    ))
}

/// One weight as a shape parameter: the weight of control point `index` of `base` set to
/// each of `weights` in turn (the seed's: `P₃` of a cubic with weights 0.05 … 20).
///
/// # Errors
/// An index beyond the control points; a weight that is not positive and finite.
pub fn nurbs_weights(base: &NurbsCurve<2>, index: usize, weights: &[f64]) -> Result<Figure> {
    let mut panel = Panel::new(
        format!("weight w of P{index} varied, the others as given"),
        "x",
        "y",
    )
    .equal()
    .legend_at(SeriesLabelPosition::LowerRight)
    .with(Series::polygon("control polygon", base.points()));
    for (k, &w) in weights.iter().enumerate() {
        let c = base.with_weight(index, w)?;
        panel = panel.with(Series::line(format!("w = {w}"), trace(&c)?, C[k % C.len()]));
    }
    Ok(Figure::from(Figure2d::new(
        "NURBS: a weight pulls the curve towards its control point",
        vec![panel],
        (1, 1),
    )))
}

/// Runge's phenomenon: the interpolants of degree `degree` on equispaced and Chebyshev
/// nodes, and the largest error for each of `degrees` (the seed's: 9, and 2 … 20).
///
/// # Errors
/// A degree beyond the interpolants' limit.
pub fn runge_figure(degree: usize, degrees: &[usize]) -> Result<Figure> {
    let (a, b) = RUNGE_INTERVAL;
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
                format!("p{degree}, {} nodes", family.legend()),
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
        "max error (log scale)",
    )
    .log(false, true)
    .legend_at(SeriesLabelPosition::UpperLeft);
    let rows = data::runge_rows_for(degrees)?;
    for (k, family) in [NodeFamily::Equispaced, NodeFamily::Chebyshev]
        .into_iter()
        .enumerate()
    {
        let pts = rows
            .iter()
            .map(|r| (r.degree as f64, r.error(family)))
            .collect();
        bottom = bottom.with(
            Series::line(format!("{} nodes", family.legend()), pts, C[k])
                .styled(Style::LinePoints(4)),
        );
    }
    Ok(Figure::from(Figure2d::new(
        "Runge's phenomenon, f(x) = 1/(1+x²) on [−5, 5] (seed 001)",
        vec![top, bottom],
        (2, 1),
    )))
}

/// Uniform, chord-length and centripetal parameters for one data set: the natural cubic
/// spline curve of `points` under each (the seed's: [`data::PARAM_POINTS`], unevenly spaced).
///
/// # Errors
/// The errors of the spline (too few points, repeated points).
pub fn parametrizations(points: &[Vector2<f64>]) -> Result<Figure> {
    let mut panel = Panel::new(
        "natural cubic spline curves through the same points",
        "x",
        "y",
    )
    .equal()
    .legend_at(SeriesLabelPosition::UpperLeft)
    .with(Series::line("data", xy(points), BLACK).styled(Style::Points(6)));
    for (k, param) in Parametrization::ALL.into_iter().enumerate() {
        let s = CubicSpline::curve(points, param, EndCondition::Natural)?;
        panel = panel.with(Series::line(param.legend(), trace(&s)?, C[k]).width(3));
    }
    Ok(Figure::from(Figure2d::new(
        "Parametrization of interpolation points",
        vec![panel],
        (1, 1),
    )))
}

/// The cubic spline of samples of `f` at the nodes `x` under each of `ends`, beside the
/// piecewise-linear interpolant, and their errors (the seeds': 7 samples of `sin` on
/// `[0, 2π]`, clamped, natural, periodic and anticyclic ends).
///
/// # Errors
/// The errors of the splines (too few or unsorted nodes, ends the data cannot have).
pub fn cubic_spline_ends(
    name: &str,
    f: impl Fn(f64) -> f64,
    x: &[f64],
    ends: &[EndCondition<1>],
) -> Result<Figure> {
    let y: Vec<f64> = x.iter().map(|&t| f(t)).collect();
    let linear =
        PiecewiseLinear::try_new(x, &y.iter().map(|&v| Vector1::new(v)).collect::<Vec<_>>())?;
    let (a, b) = (x[0], x[x.len() - 1]);
    let mut top = Panel::new(
        format!(
            "{} samples of {name} on [{}, {}]",
            x.len(),
            crate::printed::rounded(a, 5),
            crate::printed::rounded(b, 5)
        ),
        "x",
        "s(x)",
    )
    .legend_at(SeriesLabelPosition::LowerLeft)
    .with(Series::line(name, sampled(a, b, |t| (t, f(t))), BLACK).width(3));
    // the error vanishes at the nodes; 1e-6 floors it there for the log axis
    let floored = |e: f64| e.abs().max(1e-6);
    let mut bottom = Panel::new(format!("error |s(x) − {name}|"), "x", "|error| (log scale)")
        .log(false, true)
        .legend_at(SeriesLabelPosition::LowerLeft);
    top = top.with(
        Series::line(
            "piecewise linear",
            sampled(a, b, |t| (t, linear.point(t).x)),
            GREY,
        )
        .styled(Style::Dashed),
    );
    for (k, &end) in ends.iter().enumerate() {
        let s = CubicSpline::function(x, &y, end)?;
        // natural and periodic ends give the same spline on these data: dash the second
        let style = if matches!(end, EndCondition::Periodic) {
            Style::Dashed
        } else {
            Style::Line
        };
        top = top.with(
            Series::line(end.legend(), sampled(a, b, |t| (t, s.value(t))), C[k]).styled(style),
        );
        bottom = bottom.with(
            Series::line(
                end.legend(),
                sampled(a, b, |t| (t, floored(s.value(t) - f(t)))),
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
    Ok(Figure::from(
        Figure2d::new("Cubic spline end conditions", vec![top, bottom], (2, 1)).shared_legend(),
    ))
}
