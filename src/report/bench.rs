//! Benchmark workloads of the `splinelab bench` subcommand, one JSON line each.

use crate::bezier::patch::BezierPatch;
use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::KnotVector;
use crate::curve::ParametricCurve;
use crate::domain::{linspace, Partition, Rect};
use crate::error::Result;
use crate::hermite::patch::HermitePatch;
use crate::hermite::spline_surface::HermiteSpline;
use crate::interp::angular::AngularSpline;
use crate::interp::cubic::{CubicSpline, EndCondition};
use crate::nurbs::NurbsCurve;
use crate::report::error::Error;
use crate::seeds::seed000::T6;
use crate::study::{uniform_spline_errors, PatchEvaluation, REPORT_PREC};
use crate::surface::{partials_on_grid, Torus};
use nalgebra::{Vector2, Vector3};
use std::f64::consts::TAU;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// One measured workload.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchResult {
    /// Workload id.
    pub workload: &'static str,
    /// Points (or nodes) produced by one run.
    pub points: usize,
    /// Median wall time of one run, seconds.
    pub seconds: f64,
}

impl BenchResult {
    /// Points per second.
    pub fn throughput(&self) -> f64 {
        self.points as f64 / self.seconds
    }

    /// `{"workload": …, "points": …, "seconds": …, "throughput": …}`.
    pub fn to_json(&self) -> String {
        format!(
            r#"{{"workload": "{}", "points": {}, "seconds": {:e}, "throughput": {:e}}}"#,
            self.workload,
            self.points,
            self.seconds,
            self.throughput()
        )
    }
}

/// A workload: id, description, and one run returning the number of points it produced.
pub struct Workload {
    /// Id for `bench --only`.
    pub id: &'static str,
    /// What one run does.
    pub description: &'static str,
    run: fn() -> Result<usize>,
}

fn t6_table() -> Result<usize> {
    let torus = Torus::default();
    let mut points = 0;
    for row in &T6 {
        let rect = Rect::square(0.0, row.side)?;
        let e = uniform_spline_errors(
            &torus,
            &rect,
            row.n,
            row.m,
            REPORT_PREC,
            PatchEvaluation::HermiteMatrix,
        )?;
        black_box(e);
        points += row.n * row.m * REPORT_PREC * REPORT_PREC;
    }
    Ok(points)
}

fn report_patch() -> HermitePatch {
    HermitePatch::from_surface(&Torus::default(), &Rect::unit())
}

fn patch_matrix() -> Result<usize> {
    let g = black_box(report_patch()).tabulate(REPORT_PREC, REPORT_PREC)?;
    Ok(black_box(g).as_slice().len())
}

fn patch_de_casteljau() -> Result<usize> {
    let b = BezierPatch::from_hermite(&black_box(report_patch()));
    let g = b.tabulate_de_casteljau(REPORT_PREC, REPORT_PREC)?;
    Ok(black_box(g).as_slice().len())
}

fn corner_data() -> Result<usize> {
    let nodes = linspace(0.0, TAU, 257);
    let g = partials_on_grid(&Torus::default(), &nodes, &nodes)?;
    Ok(black_box(g).as_slice().len())
}

thread_local! {
    static GRID_BUFFER: std::cell::RefCell<Vec<nalgebra::Vector3<f64>>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

fn torus_grid() -> Result<usize> {
    let spline = HermiteSpline::try_from_surface(
        &Torus::default(),
        Partition::uniform(0.0, TAU, 16)?,
        Partition::uniform(0.0, TAU, 16)?,
    )?;
    let samples = linspace(0.0, TAU, 1024);
    GRID_BUFFER.with(|buf| {
        let mut out = buf.borrow_mut();
        spline.tabulate_into(&samples, &samples, &mut out)?;
        Ok(black_box(&*out).len())
    })
}

/// Inputs of the curve workloads, built once (outside the timed runs).
struct CurveInputs {
    bspline: BSplineCurve<3>,
    bspline_params: Vec<f64>,
    spline_x: Vec<f64>,
    spline_y: Vec<f64>,
    spline: CubicSpline<1>,
    spline_params: Vec<f64>,
    circle: NurbsCurve<2>,
    circle_params: Vec<f64>,
    angular: AngularSpline,
}

/// Control points of the `bspline-curve` workload.
const BSPLINE_POINTS: usize = 60;
/// Parameters of the `bspline-curve` and `nurbs-circle` workloads.
const CURVE_PARAMS: usize = 1_000_000;
/// Data points of the `cubic-spline-build` workload.
const SPLINE_POINTS: usize = 1_000_000;
/// Points of the `angular-curve` workloads' closed ellipse.
const ANGULAR_POINTS: usize = 1000;
/// Evaluation points of the `cubic-spline-eval` workload.
const SPLINE_EVALS: usize = 10_000_000;

fn curve_inputs() -> Result<&'static CurveInputs> {
    static INPUTS: std::sync::OnceLock<Result<CurveInputs>> = std::sync::OnceLock::new();
    INPUTS
        .get_or_init(|| {
            // a helix-like polygon: degree 3, clamped knots with uniform interior
            let points: Vec<Vector3<f64>> = (0..BSPLINE_POINTS)
                .map(|i| {
                    let a = 0.4 * i as f64;
                    Vector3::new(a.cos(), a.sin(), 0.05 * i as f64)
                })
                .collect();
            let knots = KnotVector::open_uniform(3, BSPLINE_POINTS, 0.0, 1.0)?;
            let bspline = BSplineCurve::try_new(BSplineBasis::try_new(knots, 3)?, points)?;
            let spline_x = linspace(0.0, 1000.0, SPLINE_POINTS);
            let spline_y: Vec<f64> = spline_x.iter().map(|x| x.sin()).collect();
            let spline = CubicSpline::function(&spline_x, &spline_y, EndCondition::Natural)?;
            Ok(CurveInputs {
                bspline,
                bspline_params: linspace(0.0, 1.0, CURVE_PARAMS),
                spline_params: linspace(0.0, 1000.0, SPLINE_EVALS),
                spline_x,
                spline_y,
                spline,
                circle: NurbsCurve::circle9(Vector2::zeros(), 1.0)?,
                circle_params: linspace(0.0, 1.0, CURVE_PARAMS),
                angular: AngularSpline::closed(
                    &(0..ANGULAR_POINTS)
                        .map(|i| {
                            let t = TAU * i as f64 / ANGULAR_POINTS as f64;
                            Vector2::new(t.cos(), 0.5 * t.sin())
                        })
                        .collect::<Vec<_>>(),
                )?,
            })
        })
        .as_ref()
        .map_err(Clone::clone)
}

thread_local! {
    static POINTS3: std::cell::RefCell<Vec<Vector3<f64>>> = const { std::cell::RefCell::new(Vec::new()) };
    static POINTS2: std::cell::RefCell<Vec<Vector2<f64>>> = const { std::cell::RefCell::new(Vec::new()) };
    static VALUES: std::cell::RefCell<Vec<f64>> = const { std::cell::RefCell::new(Vec::new()) };
}

fn bspline_curve() -> Result<usize> {
    let inputs = curve_inputs()?;
    POINTS3.with(|buf| {
        let mut out = buf.borrow_mut();
        inputs.bspline.eval_many(&inputs.bspline_params, &mut out);
        Ok(black_box(&*out).len())
    })
}

fn cubic_spline_build() -> Result<usize> {
    let inputs = curve_inputs()?;
    let s = CubicSpline::function(
        black_box(&inputs.spline_x),
        black_box(&inputs.spline_y),
        EndCondition::Natural,
    )?;
    Ok(black_box(s).nodes().len())
}

fn cubic_spline_eval() -> Result<usize> {
    let inputs = curve_inputs()?;
    VALUES.with(|buf| {
        let mut out = buf.borrow_mut();
        inputs.spline.values_into(&inputs.spline_params, &mut out);
        Ok(black_box(&*out).len())
    })
}

fn nurbs_circle() -> Result<usize> {
    let inputs = curve_inputs()?;
    POINTS2.with(|buf| {
        let mut out = buf.borrow_mut();
        inputs.circle.eval_many(&inputs.circle_params, &mut out);
        Ok(black_box(&*out).len())
    })
}

fn angular_curve() -> Result<usize> {
    let inputs = curve_inputs()?;
    POINTS2.with(|buf| {
        let mut out = buf.borrow_mut();
        inputs.angular.polyline_into(CURVE_PARAMS, &mut out)?;
        Ok(black_box(&*out).len())
    })
}

fn angular_curve_pointwise() -> Result<usize> {
    let inputs = curve_inputs()?;
    let line = inputs.angular.polyline(CURVE_PARAMS)?;
    Ok(black_box(line).len())
}

fn table_i() -> Result<usize> {
    Ok(black_box(crate::comparison::table_i()?).len())
}

/// The twelve formulas of the torus (`X`, `X_s`, `X_t`, `X_st` by coordinate): traced
/// through `Torus::eval` on hyper-dual numbers of expressions, simplified and printed.
fn symbolic_torus() -> Result<usize> {
    let f = crate::symbolic::surface_formulas(&Torus::default(), 0.3, 0.7)?;
    let mut chars = 0;
    for part in [&f.point, &f.ds, &f.dt, &f.dst] {
        for formula in part {
            chars += black_box(formula.plain()).len();
        }
    }
    black_box(chars);
    Ok(12)
}

/// Every workload.
pub const WORKLOADS: [Workload; 13] = [
    Workload {
        id: "t6-table",
        description: "the whole T6 computation (4 rows, Hermite matrix form, all measures)",
        run: t6_table,
    },
    Workload {
        id: "patch-matrix",
        description: "one 15×15 patch tabulation by H(s)ᵀ C H(t)",
        run: patch_matrix,
    },
    Workload {
        id: "patch-decasteljau",
        description: "one 15×15 patch tabulation by de Casteljau on the Bézier net",
        run: patch_de_casteljau,
    },
    Workload {
        id: "corner-data",
        description: "point, X_s, X_t, X_st of the torus at 257×257 nodes (hyper-dual numbers, all cores)",
        run: corner_data,
    },
    Workload {
        id: "torus-grid",
        description: "whole torus as 16×16 patches, built and tabulated on 1024×1024 nodes (output buffer reused)",
        run: torus_grid,
    },
    Workload {
        id: "bspline-curve",
        description: "cubic B-spline, 60 control points in 3-D, clamped uniform knots, at 1e6 sorted parameters",
        run: bspline_curve,
    },
    Workload {
        id: "cubic-spline-build",
        description: "natural cubic spline through 1e6 points (x sorted in [0, 1000], y = sin x), O(n) build",
        run: cubic_spline_build,
    },
    Workload {
        id: "cubic-spline-eval",
        description: "that spline evaluated at 1e7 sorted points",
        run: cubic_spline_eval,
    },
    Workload {
        id: "nurbs-circle",
        description: "the 9-point NURBS circle at 1e6 parameters",
        run: nurbs_circle,
    },
    Workload {
        id: "angular-curve",
        description: "closed Angular spline through 1000 points of an ellipse, 1e6 equally spaced samples (polyline_into)",
        run: angular_curve,
    },
    Workload {
        id: "angular-curve-pointwise",
        description: "the same 1e6 samples point by point (ParametricCurve::polyline, the reference path)",
        run: angular_curve_pointwise,
    },
    Workload {
        id: "table-i",
        description: "seed 004's Table I regenerated: 36 cells, each the printed configuration, the fewest points with the paper's rule and the automatic search (all cores)",
        run: table_i,
    },
    Workload {
        id: "symbolic-torus",
        description: "the torus's 12 formulas (X, X_s, X_t, X_st by coordinate) traced through Torus::eval on hyper-dual expressions, simplified and printed (points: formulas)",
        run: symbolic_torus,
    },
];

/// Runs one workload: a warm-up, then repeated runs for at least `budget` (and at least 5),
/// reporting the median.
///
/// # Errors
/// [`Error::UnknownId`] for an unknown id; errors of the workload.
pub fn run(id: &str, budget: Duration) -> crate::report::Result<BenchResult> {
    let w = WORKLOADS
        .iter()
        .find(|w| w.id == id)
        .ok_or_else(|| Error::UnknownId {
            what: "workload",
            id: id.to_string(),
        })?;
    let points = (w.run)()?;
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < 5 || start.elapsed() < budget {
        let t = Instant::now();
        black_box((w.run)()?);
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    Ok(BenchResult {
        workload: w.id,
        points,
        seconds: times[times.len() / 2],
    })
}
