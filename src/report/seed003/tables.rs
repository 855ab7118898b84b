//! Tables of seed 003, the lecture notes on curves, as tables computed from scratch.

use crate::bezier::bernstein::bernstein_sum;
use crate::bezier::de_casteljau::{de_casteljau, de_casteljau_recursive};
use crate::blending::functions::{lagrange4, printed_setbval, uniform_bspline4};
use crate::blending::opengl::{opengl_groups, LastGroup};
use crate::blending::window::printed_bspline_polyline;
use crate::bspline::basis::BSplineBasis;
use crate::bspline::knots::KnotVector;
use crate::domain::linspace;
use crate::report::error::Result;
use crate::report::record::frame_of;
use crate::report::table::Table;
use crate::seeds::seed003 as data;
use nalgebra::Vector2;

crate::record! {
    /// A row of the de Casteljau table: one parameter.
    struct CasteljauRow {
        u: f64 => "u",
        x: f64 => "x",
        y: f64 => "y",
        recursive_vs_iterative: f64 => "recursive_vs_iterative",
        recursive_vs_bernstein: f64 => "recursive_vs_bernstein",
    }
}

/// Seed 003's de Casteljau examples (`u = 0.3, 0.5, 0.7`): recursive as printed vs iterative
/// vs Bernstein sum.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn de_casteljau_table() -> Result<Table> {
    let id = "de-casteljau";
    let points = data::CASTELJAU_POINTS.map(|(x, y)| Vector2::new(x, y));
    let mut rows = Vec::new();
    for &u in &data::CASTELJAU_U {
        let rec = de_casteljau_recursive(&points, u)?;
        let it = de_casteljau(&points, u)?;
        let bern = bernstein_sum(&points, u)?;
        rows.push(CasteljauRow {
            u,
            x: rec.x,
            y: rec.y,
            recursive_vs_iterative: (rec - it).amax(),
            recursive_vs_bernstein: (rec - bern).amax(),
        });
    }
    Ok(Table {
        id: id.into(),
        title: "de Casteljau on 4 control points at u = 0.3, 0.5, 0.7 (seed 003)".into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "x, y: the printed recursive castel; the iterative form (Codice 12 of seed 000) and the Bernstein sum give the same point to rounding.".into(),
        ],
    })
}

crate::record! {
    /// A row of the checks of seed 003's listings: what was run, the value, what it means.
    struct Check {
        check: &'static str => "check",
        value: String => "value",
        meaning: &'static str => "meaning",
    }
}

/// Seed 003's listings checked: what each printed procedure computes, and where it departs
/// from its intent.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn seed003_checks() -> Result<Table> {
    let id = "seed003-checks";
    let grid = linspace(0.0, 1.0, 101);
    let setbval = printed_setbval(6)?
        .iter()
        .enumerate()
        .map(|(j, b)| {
            let f = uniform_bspline4(j as f64 / 6.0);
            (0..4).map(|i| (b[i] - f[i]).abs()).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max);
    // the uniform B-splines on integer knots: on [3, 4), N_{i,3}(3 + u) = b_i(u)
    let integer = BSplineBasis::try_new(KnotVector::try_new((0..8).map(f64::from).collect())?, 3)?;
    let cox = grid
        .iter()
        .map(|&u| {
            let b = uniform_bspline4(u);
            (0..4)
                .map(|i| (integer.cox_de_boor(i, 3, 3.0 + u) - b[i]).abs())
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max);
    let lagrange_unity = linspace(-1.0, 2.0, 301)
        .iter()
        .map(|&u| (lagrange4(u).iter().sum::<f64>() - 1.0).abs())
        .fold(0.0, f64::max);
    // B₄ with the printed denominator (3)(2)(−1) = −6 at its own node u = 2
    const PRINTED_B4_DENOMINATOR: f64 = -6.0;
    let printed_b4 = |u: f64| (u + 1.0) * u * (u - 1.0) / PRINTED_B4_DENOMINATOR;
    let four = data::four_way_points(7);
    let casteljau = grid
        .iter()
        .map(|&u| {
            let a = de_casteljau_recursive(&four, u)?;
            let b = bernstein_sum(&four, u)?;
            Ok((a - b).amax())
        })
        .collect::<Result<Vec<f64>>>()?
        .into_iter()
        .fold(0.0, f64::max);
    let polyline = printed_bspline_polyline(&four, 6)?;
    let end_gap = polyline
        .last()
        .map_or(0.0, |p| (p - four[four.len() - 1]).norm());
    let stale = opengl_groups(&four, 5, LastGroup::AsPrinted)?;
    let last_group = stale.last().map_or(String::new(), |g| {
        g.iter()
            .map(|p| {
                four.iter()
                    .position(|q| q == p)
                    .map_or("?".to_string(), |i| format!("P{i}"))
            })
            .collect::<Vec<_>>()
            .join(", ")
    });
    let rows = [
        Check {
            check: "printed setbval (nb = 6, Horner b₂, b₁ = 1 − b₀ − b₂ − b₃) vs the closed forms",
            value: format!("{setbval:.3e}"),
            meaning: "max |difference|: the listing computes the uniform cubic B-spline blending",
        },
        Check {
            check: "uniform blending vs Cox–de Boor on integer knots",
            value: format!("{cox:.3e}"),
            meaning: "max |b_i(u) − N_{i,3}(3 + u)| on integer knots: the same functions",
        },
        Check {
            check: "Lagrange blending, Σ B_i(u) − 1 on [−1, 2]",
            value: format!("{lagrange_unity:.3e}"),
            meaning: "partition of unity with B₄'s denominator (3)(2)(1) = 6",
        },
        Check {
            check: "B₄(2) with the printed denominator (3)(2)(−1)",
            value: format!("{}", printed_b4(2.0)),
            meaning: "−1 instead of 1: a sign typo in the notes (printed twice)",
        },
        Check {
            check: "recursive castel vs Bernstein sum, 7 points",
            value: format!("{casteljau:.3e}"),
            meaning: "max |difference| over 101 parameters: \"Casteljau\" and \"Bezier\" of the comparison are one curve",
        },
        Check {
            check: "printed bspline polyline: distance from its last vertex to the last point",
            value: format!("{end_gap:.3e}"),
            meaning: "make_one samples u = j/nb, j < nb, so u = 1 of the last segment is never drawn",
        },
        Check {
            check: "OpenGL spline as printed, 7 points: control points of the last group",
            value: last_group,
            meaning: "glMap1f always reads 5 points; entries beyond the 3 fresh ones are stale from the previous group",
        },
    ];
    Ok(Table {
        id: id.into(),
        title: "Seed 003's printed procedures, checked".into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "Every value is computed by running the procedure; the points are those of the four-way figure.".into(),
        ],
    })
}
