//! Tables of seed 001, the lecture slides on splines, as tables computed from scratch.

use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::{EndKnots, KnotVector};
use crate::curve::{signed_curvature, ParametricCurve};
use crate::domain::linspace;
use crate::interp::collocation;
use crate::interp::cubic::{CubicSpline, EndCondition};
use crate::interp::polynomial::{runge, Lagrange, NodeFamily, PowerPolynomial, RUNGE_INTERVAL};
use crate::nurbs::NurbsCurve;
use crate::report::error::Result;
use crate::report::legend::Legend;
use crate::report::record::frame_of;
use crate::report::table::Table;
use crate::seeds::seed000::agrees_to_printed;
use crate::seeds::seed001 as data;
use nalgebra::{Vector1, Vector2};

/// One of seed 001's knot vectors: what it is, as printed, as constructed, its degree, and
/// whether the construction equals the printed values (`None` where the example is data).
struct KnotExample {
    name: &'static str,
    printed: &'static str,
    knots: KnotVector,
    degree: usize,
    same: Option<bool>,
}

crate::record! {
    /// A row of the knot-vector table.
    struct KnotRow {
        example: String => "example",
        printed: String => "printed",
        ours: String => "ours",
        equal_to_printed: Option<bool> => "equal_to_printed",
        degree: u32 => "degree",
        open: bool => "open",
        uniform: bool => "uniform",
        basis_functions: u32 => "basis_functions",
    }
}

/// Seed 001's knot vectors: the extended partition reproduced, the examples' properties.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn knot_vectors() -> Result<Table> {
    let id = "knot-vectors";
    let extended = KnotVector::extended_partition(
        0.0,
        1.0,
        &data::EXTENDED_INTERIOR,
        &data::EXTENDED_MULTIPLICITIES,
        data::EXTENDED_ORDER,
        EndKnots::Spaced(data::EXTENDED_SPACING),
    )?;
    let cubic = KnotVector::open_uniform(3, 7, 0.0, 1.0)?;
    let examples = [
        KnotExample {
            name: "extended partition: [0,1], m = 4, Δ = {1/2, 3/4}, M = {1, 2}, end spacing 1/4",
            printed: data::EXTENDED_PRINTED,
            same: Some(extended.knots() == data::EXTENDED_PRINTED_VALUES),
            knots: extended,
            degree: 3,
        },
        KnotExample {
            name: "open, n = 2 (KnotVector::open_uniform(2, 4, 0, 1))",
            printed: "[0, 0, 0, 1/2, 1, 1, 1]",
            knots: KnotVector::open_uniform(2, 4, 0.0, 1.0)?,
            degree: 2,
            same: None,
        },
        KnotExample {
            name: "basis example n = 1",
            printed: "(0, 0, 1, 2, 3, 4, 5, 5)",
            knots: KnotVector::try_new(data::BASIS_N1.to_vec())?,
            degree: 1,
            same: None,
        },
        KnotExample {
            name: "basis example n = 2",
            printed: "(0, 0, 0, 1, 2, 3, 4, 4, 4)",
            knots: KnotVector::try_new(data::BASIS_N2.to_vec())?,
            degree: 2,
            same: None,
        },
        KnotExample {
            name: "cubic curve example (KnotVector::open_uniform(3, 7, 0, 1))",
            printed: "{0, 0, 0, 0, 1/4, 1/2, 3/4, 1, 1, 1, 1}",
            same: Some(cubic.knots() == data::LOCALITY_KNOTS),
            knots: cubic,
            degree: 3,
        },
        KnotExample {
            name: "quadratic curve example (KnotVector::open_uniform(2, 10, 0, 1))",
            printed: "{0, 0, 0, 1/8, …, 7/8, 1, 1, 1}",
            knots: KnotVector::open_uniform(2, 10, 0.0, 1.0)?,
            degree: 2,
            same: None,
        },
    ];
    let rows = examples
        .into_iter()
        .map(|e| {
            Ok(KnotRow {
                example: e.name.into(),
                printed: e.printed.into(),
                ours: e.knots.to_string(),
                equal_to_printed: e.same,
                degree: e.degree as u32,
                open: e.knots.is_open(e.degree),
                uniform: e.knots.is_uniform(),
                basis_functions: BSplineBasis::try_new(e.knots, e.degree)?.len() as u32,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Table {
        id: id.into(),
        title: "Knot vectors of seed 001: printed vs constructed, and their properties".into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "equal_to_printed: the constructed knots equal the printed ones exactly (— where the example is given as data, not constructed).".into(),
            "The slides require only t₁ ≤ … ≤ t_m = a for the extra end knots; spacing 1/4 reproduces the printed Δ* (our reading: the rule is not stated).".into(),
            "open: first and last knot of multiplicity n + 1 (seed 001 \"aperto\"); uniform: equally spaced distinct knots; basis_functions = knots − order = n + 1 + K.".into(),
        ],
    })
}

crate::record! {
    /// A row of the partition-of-unity table: one basis function, or their sum.
    struct UnityRow {
        function: String => "function",
        printed: String => "printed",
        cox_de_boor: f64 => "cox_de_boor",
        one_pass: f64 => "one_pass",
        agrees: bool => "agrees",
    }
}

/// Seed 001's partition-of-unity example: printed values vs Cox–de Boor vs the one-pass
/// evaluator.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn partition_of_unity() -> Result<Table> {
    let id = "partition-of-unity";
    let basis = BSplineBasis::try_new(
        KnotVector::try_new(data::UNITY_KNOTS.to_vec())?,
        data::UNITY_DEGREE,
    )?;
    let fast = basis.all(data::UNITY_T);
    let mut rows = Vec::new();
    for (i, text) in data::UNITY_PRINTED.iter().enumerate() {
        let c = basis.cox_de_boor(i, data::UNITY_DEGREE, data::UNITY_T);
        rows.push(UnityRow {
            function: format!("N{},2(0.6)", i + 1),
            printed: text.to_string(),
            cox_de_boor: c,
            one_pass: fast[i],
            agrees: agrees_to_printed(text, c) && agrees_to_printed(text, fast[i]),
        });
    }
    rows.push(UnityRow {
        function: "sum".into(),
        printed: "1.0".into(),
        cox_de_boor: (0..4).map(|i| basis.cox_de_boor(i, 2, data::UNITY_T)).sum(),
        one_pass: fast.iter().sum(),
        agrees: agrees_to_printed("1.0", fast.iter().sum()),
    });
    Ok(Table {
        id: id.into(),
        title: "Partition of unity: degree 2, knots (0,0,0,1,2,2,2), t = 0.6 (seed 001)".into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "cox_de_boor: the recurrence as printed (0/0 = 0); one_pass: all non-zero functions of the span at once (The NURBS Book A2.2). agrees: both round to the printed digits.".into(),
        ],
    })
}

/// Samples of the circle tables.
pub const CIRCLE_SAMPLES: usize = 10_001;

crate::record! {
    /// A row of the NURBS circle table.
    struct CircleRow {
        circle: &'static str => "circle",
        control_points: u32 => "control_points",
        max_radius_error: f64 => "max_radius_error",
        max_curvature_error: f64 => "max_curvature_error",
        max_radius_error_unit_weights: f64 => "max_radius_error_unit_weights",
        unit_weights_vs_bspline: f64 => "unit_weights_vs_bspline",
    }
}

/// Seed 001's exact circles: radius error of the NURBS, and of the same control points with
/// unit weights (a B-spline, not a circle).
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn nurbs_circle() -> Result<Table> {
    let id = "nurbs-circle";
    let center = Vector2::new(0.5, -0.25);
    let radius = 2.0;
    let mut rows = Vec::new();
    for (label, circle) in [
        ("7 control points", NurbsCurve::circle7(center, radius)?),
        ("9 control points", NurbsCurve::circle9(center, radius)?),
    ] {
        let ts = linspace(0.0, 1.0, CIRCLE_SAMPLES);
        let unit = NurbsCurve::try_new(
            circle.basis().clone(),
            circle.points().to_vec(),
            vec![1.0; circle.points().len()],
        )?;
        let bspline = BSplineCurve::try_new(circle.basis().clone(), circle.points().to_vec())?;
        let radius_error = |c: &NurbsCurve<2>| {
            ts.iter()
                .map(|&t| ((c.point(t) - center).norm() - radius).abs())
                .fold(0.0, f64::max)
        };
        rows.push(CircleRow {
            circle: label,
            control_points: circle.points().len() as u32,
            max_radius_error: radius_error(&circle),
            max_curvature_error: ts
                .iter()
                .map(|&t| {
                    let [_, d1, d2] = circle.derivatives2(t);
                    (signed_curvature(&d1, &d2) * radius - 1.0).abs()
                })
                .fold(0.0, f64::max),
            max_radius_error_unit_weights: radius_error(&unit),
            unit_weights_vs_bspline: ts
                .iter()
                .map(|&t| (unit.point(t) - bspline.point(t)).amax())
                .fold(0.0, f64::max),
        });
    }
    Ok(Table {
        id: id.into(),
        title: "The exact circle as a NURBS: radius error over 10 001 parameters (seed 001)"
            .into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "Circle of radius 2 centred at (0.5, −0.25); error = max over t of | ‖C(t) − c‖ − r |.".into(),
            "max_curvature_error: max |κ(t)·r − 1|, κ from the exact first and second derivatives (second-order dual numbers) — the parametrization is not by arc length, yet the curvature is 1/r everywhere.".into(),
            "unit_weights: the same control points with every weight 1 — a quadratic B-spline, visibly not a circle; unit_weights_vs_bspline: max |NURBS(w = 1) − B-spline|, the identity of the two.".into(),
        ],
    })
}

crate::record! {
    /// A row of the Runge table: one degree.
    struct RungeErrorRow {
        degree: u32 => "degree",
        equispaced: f64 => "max_error_equispaced",
        chebyshev: f64 => "max_error_chebyshev",
        vandermonde_condition: Option<f64> => "vandermonde_condition",
        power_vs_lagrange: Option<f64> => "power_basis_vs_lagrange",
    }
}

/// Seed 001's Runge phenomenon as a table: error vs degree for equispaced and Chebyshev
/// nodes, and what the Vandermonde route loses.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn runge_errors() -> Result<Table> {
    let id = "runge-errors";
    let (a, b) = RUNGE_INTERVAL;
    let samples = linspace(a, b, data::RUNGE_SAMPLES);
    let mut rows = Vec::new();
    for r in data::runge_rows()? {
        let x = NodeFamily::Equispaced.nodes(a, b, r.degree)?;
        let y: Vec<f64> = x.iter().map(|&t| runge(t)).collect();
        let lagrange = Lagrange::try_new(&x, &y)?;
        // None where the Vandermonde solve no longer interpolates its data (IllConditioned)
        let power_vs_lagrange = match PowerPolynomial::interpolate(&x, &y) {
            Ok(power) => Some(
                samples
                    .iter()
                    .map(|&t| (power.eval(t) - lagrange.eval(t)).abs())
                    .fold(0.0, f64::max),
            ),
            Err(
                crate::error::Error::IllConditioned { .. }
                | crate::error::Error::SingularSystem { .. },
            ) => None,
            Err(e) => return Err(e.into()),
        };
        rows.push(RungeErrorRow {
            degree: r.degree as u32,
            equispaced: r.equispaced,
            chebyshev: r.chebyshev,
            vandermonde_condition: r.vandermonde_condition,
            power_vs_lagrange,
        });
    }
    Ok(Table {
        id: id.into(),
        title: "Runge's phenomenon: max |p − f| on [−5, 5] vs degree (seed 001)".into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            format!("f(x) = 1/(1+x²); errors over {} equispaced samples of [−5, 5]; interpolants in Lagrange form.", data::RUNGE_SAMPLES),
            "Equispaced nodes: the error grows with the degree, largest near the ends (seed 001: \"l'errore aumenta all'estremità\"); Chebyshev nodes: it decreases.".into(),
            "vandermonde_condition: 2-norm condition number of V for the equispaced nodes (— where the smallest singular value is below rounding, σ_min ≤ ε σ_max: V is numerically singular, κ ≳ 4.5e15); power_basis_vs_lagrange: max difference between the Vandermonde-solved power form and the Lagrange form, the digits the power basis loses (— where the solved power form misses its own data by more than the residual tolerance, 1e-10 of the data scale, and is refused as ill-conditioned).".into(),
        ],
    })
}

crate::record! {
    /// A row of the end-condition table: one end condition.
    struct EndsRow {
        end_condition: String => "end_condition",
        interpolation: f64 => "max_interpolation_residual",
        first_condition: f64 => "first_condition_residual",
        second_condition: f64 => "second_condition_residual",
        routes: f64 => "tridiagonal_vs_collocation",
        error_vs_sin: f64 => "max_error_vs_sin",
    }
}

/// The four end conditions on samples of `sin`: interpolation and end-condition residuals,
/// and the agreement of the tridiagonal route with the B-spline collocation route.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn cubic_spline_ends() -> Result<Table> {
    let id = "cubic-spline-ends";
    let (x, y) = data::spline_ends_data();
    let yv: Vec<Vector1<f64>> = y.iter().map(|&v| Vector1::new(v)).collect();
    let fine = linspace(x[0], x[x.len() - 1], 1001);
    let mut rows = Vec::new();
    for end in data::end_conditions() {
        let s = CubicSpline::function(&x, &y, end)?;
        let b = collocation::cubic_spline(&x, &yv, end)?;
        let [d1a, d2a, d1b, d2b] = s.end_derivatives().map(|v| v.x);
        let (r1, r2) = match end {
            EndCondition::Clamped { start, end } => ((d1a - start.x).abs(), (d1b - end.x).abs()),
            EndCondition::Natural => (d2a.abs(), d2b.abs()),
            EndCondition::Periodic | EndCondition::Cyclic => ((d1a - d1b).abs(), (d2a - d2b).abs()),
            EndCondition::Anticyclic => ((d1a + d1b).abs(), (d2a + d2b).abs()),
        };
        rows.push(EndsRow {
            end_condition: end.legend().into_owned(),
            interpolation: x
                .iter()
                .zip(&y)
                .map(|(&t, &v)| (s.value(t) - v).abs())
                .fold(0.0, f64::max),
            first_condition: r1,
            second_condition: r2,
            routes: fine
                .iter()
                .map(|&t| (s.value(t) - b.point(t).x).abs())
                .fold(0.0, f64::max),
            error_vs_sin: fine
                .iter()
                .map(|&t| (s.value(t) - t.sin()).abs())
                .fold(0.0, f64::max),
        });
    }
    Ok(Table {
        id: id.into(),
        title: "Cubic spline end conditions on 7 samples of sin x, [0, 2π] (seeds 001, 004)"
            .into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "Conditions: clamped s′(x₀) = s′(x_n) = 1 (the true slopes); natural s″ = 0 at both ends; periodic s′, s″ equal at the ends; anticyclic s′(x₀) = −s′(x_n), s″(x₀) = −s″(x_n). Residuals from the exact derivatives (dual numbers) of each end piece.".into(),
            "tridiagonal_vs_collocation: max difference over 1001 points between the O(n) moment solve and the B-spline collocation system (knots at the data, two condition rows) — two independent formulations.".into(),
            "Natural and periodic ends give the same spline here: the samples are periodic and sin″ = 0 at both ends, so the natural spline already meets the periodic conditions and, the solution being unique, is the periodic one.".into(),
            "Anticyclic ends contradict sin on [0, 2π] (whose end slopes are equal), hence its larger error; they suit data such as half a period of a sinusoid (a test checks that case).".into(),
        ],
    })
}
