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

/// Seed 001: the B-spline bases of degree 1 on `(0,0,1,2,3,4,5,5)` and degree 2 on
/// `(0,0,0,1,2,3,4,4,4)`.
pub fn bspline_bases() -> Result<Figure> {
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
    Ok(Figure::from(Figure2d::new(
        "B-spline bases (seed 001), Cox–de Boor, right end included",
        panels,
        (2, 1),
    )))
}

/// Seed 001: moving `P₄` of the cubic on `{0,0,0,0,¼,½,¾,1,1,1,1}` changes the curve only
/// on `[¼, 1)`.
pub fn bspline_locality() -> Result<Figure> {
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
        .with(Series::polygon("control polygon", curve.points()))
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
    Ok(Figure::from(Figure2d::new(
        "Locality: cubic B-spline, knots {0,0,0,0,¼,½,¾,1,1,1,1}, P₄ moved",
        vec![top, bottom],
        (2, 1),
    )))
}

/// Seed 001: the quadratic spline curve on `{0,0,0,1/8,…,7/8,1,1,1}`.
pub fn bspline_quadratic() -> Result<Figure> {
    let curve = data::quadratic_example()?;
    let knots: Vec<Vector2<f64>> = (0..=8).map(|k| curve.point(k as f64 / 8.0)).collect();
    let panel = Panel::new("10 control points, order m = 3", "x", "y")
        .equal()
        .legend_at(SeriesLabelPosition::LowerRight)
        .with(Series::polygon("control polygon", curve.points()))
        .with(Series::line("C(t)", trace(&curve)?, C[0]).width(3))
        .with(Series::line("C(k/8): segment joints", xy(&knots), C[1]).styled(Style::Points(5)));
    Ok(Figure::from(Figure2d::new(
        "Quadratic B-spline curve, knots {0,0,0,1/8,…,7/8,1,1,1} (seed 001)",
        vec![panel],
        (1, 1),
    )))
}

/// Seed 001: the exact circles from 7 and 9 weighted control points.
pub fn nurbs_circles() -> Result<Figure> {
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
                .with(Series::polygon("control polygon", circle.points()))
                .with(
                    Series::line("same points, all weights 1", trace(&unit)?, C[1])
                        .styled(Style::Dashed),
                )
                .with(Series::line("NURBS", trace(&circle)?, C[0]).width(3)),
        );
    }
    Ok(Figure::from(
        Figure2d::new(
            "The exact circle as a quadratic NURBS (seed 001)",
            panels,
            (1, 2),
        )
        .shared_legend(),
    ))
}

/// Seed 001: one weight as a shape parameter.
pub fn nurbs_weights() -> Result<Figure> {
    let base = data::weight_example()?;
    let mut panel = Panel::new(
        format!("weight w of P{} varied, all others 1", data::WEIGHT_INDEX),
        "x",
        "y",
    )
    .equal()
    .legend_at(SeriesLabelPosition::LowerRight)
    .with(Series::polygon("control polygon", base.points()));
    for (k, &w) in data::WEIGHTS.iter().enumerate() {
        let c = base.with_weight(data::WEIGHT_INDEX, w)?;
        panel = panel.with(Series::line(format!("w = {w}"), trace(&c)?, C[k % C.len()]));
    }
    Ok(Figure::from(Figure2d::new(
        "NURBS: a weight pulls the curve towards its control point (seed 001)",
        vec![panel],
        (1, 1),
    )))
}

/// Seed 001: Runge's phenomenon, degree 9, equispaced vs Chebyshev nodes, and the error vs
/// degree.
pub fn runge_figure() -> Result<Figure> {
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
    let rows = data::runge_rows()?;
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

/// Seed 001: uniform, chord-length and centripetal parameters for one data set.
pub fn parametrizations() -> Result<Figure> {
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
        panel = panel.with(Series::line(param.legend(), trace(&s)?, C[k]).width(3));
    }
    Ok(Figure::from(Figure2d::new(
        "Parametrization of interpolation points (seed 001)",
        vec![panel],
        (1, 1),
    )))
}

/// Seeds 001 and 004: the four end conditions of the cubic spline on samples of `sin`.
pub fn cubic_spline_ends() -> Result<Figure> {
    let (x, y) = data::spline_ends_data();
    let (a, b) = (x[0], x[x.len() - 1]);
    let mut top = Panel::new("7 samples of sin x on [0, 2π]", "x", "s(x)")
        .legend_at(SeriesLabelPosition::LowerLeft)
        .with(Series::line("sin x", sampled(a, b, |t| (t, t.sin())), BLACK).width(3));
    // the error vanishes at the nodes; 1e-6 floors it there for the log axis
    let floored = |e: f64| e.abs().max(1e-6);
    let mut bottom = Panel::new("error |s(x) − sin x|", "x", "|error| (log scale)")
        .log(false, true)
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
            Series::line(end.legend(), sampled(a, b, |t| (t, s.value(t))), C[k]).styled(style),
        );
        bottom = bottom.with(
            Series::line(
                end.legend(),
                sampled(a, b, |t| (t, floored(s.value(t) - t.sin()))),
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
        Figure2d::new(
            "Cubic spline end conditions: clamped, natural, periodic, anticyclic",
            vec![top, bottom],
            (2, 1),
        )
        .shared_legend(),
    ))
}
