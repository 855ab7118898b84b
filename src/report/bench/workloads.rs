//! The workloads of `splinelab bench` ([`WORKLOADS`]): each prepares a run at a size (inputs
//! and output buffers built outside the timing) and reports the points it produced; and the
//! least memory traffic of the batch workloads ([`traffic`]).

use crate::bezier::patch::BezierPatch;
use crate::bspline::basis::BSplineBasis;
use crate::bspline::curve::BSplineCurve;
use crate::bspline::knots::KnotVector;
use crate::curve::ParametricCurve;
use crate::domain::{linspace, Partition, Rect};
use crate::error::Result;
use crate::hermite::patch::HermitePatch;
use crate::hermite::spline_surface::HermiteSurface;
use crate::interp::angular::AngularSpline;
use crate::interp::cubic::{CubicSpline, EndCondition};
use crate::nurbs::NurbsCurve;
use crate::report::error::Error;
use crate::seeds::seed000::T6;
use crate::study::hermite_error::{uniform_spline_errors, PatchEvaluation, REPORT_PREC};
use crate::surface::{partials_on_grid_into, Torus};
use nalgebra::{Vector2, Vector3};
use std::f64::consts::TAU;
use std::hint::black_box;

/// One prepared run of a workload: inputs and output buffers built, so that timing it
/// measures the work alone. Returns the number of points produced.
pub type Runner = Box<dyn FnMut() -> Result<usize>>;

/// A workload: id, description, its size parameter, and how to prepare a run at a size.
pub struct Workload {
    /// Id for `bench --only`.
    pub id: &'static str,
    /// What one run does (at the default size).
    pub description: &'static str,
    /// What the size counts.
    pub unit: &'static str,
    /// The size of a plain `bench` run.
    pub size: usize,
    /// The sizes of `bench --sweep` (empty: a fixed computation with no size to vary).
    pub sweep: &'static [usize],
    pub(super) setup: fn(usize) -> Result<Runner>,
}

/// Points (parameters, samples, data points) of the 1-D sweeps: 10³ … 10⁷, two per octave
/// of √10.
pub(super) const POINT_SWEEP: &[usize] = &[
    1_000, 3_162, 10_000, 31_623, 100_000, 316_228, 1_000_000, 3_162_278, 10_000_000,
];

fn t6_table(_: usize) -> Result<Runner> {
    let torus = Torus::default();
    Ok(Box::new(move || {
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
    }))
}

fn t6_row(n: usize) -> Result<Runner> {
    if n == 0 {
        return Err(crate::error::Error::TooFewSamples {
            what: "t6-row patches per side",
            got: 0,
        });
    }
    let torus = Torus::default();
    let rect = Rect::unit();
    Ok(Box::new(move || {
        let e = uniform_spline_errors(
            &torus,
            &rect,
            n,
            n,
            REPORT_PREC,
            PatchEvaluation::HermiteMatrix,
        )?;
        black_box(e);
        Ok(n * n * REPORT_PREC * REPORT_PREC)
    }))
}

fn report_patch() -> HermitePatch {
    HermitePatch::from_surface(&Torus::default(), &Rect::unit())
}

fn patch_matrix(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let patch = report_patch();
    Ok(Box::new(move || {
        let g = black_box(&patch).tabulate(k, k)?;
        Ok(black_box(g).as_slice().len())
    }))
}

fn patch_de_casteljau(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let patch = report_patch();
    Ok(Box::new(move || {
        let b = BezierPatch::from_hermite(black_box(&patch));
        let g = b.tabulate_de_casteljau(k, k)?;
        Ok(black_box(g).as_slice().len())
    }))
}

fn corner_data(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let nodes = linspace(0.0, TAU, k);
    let torus = Torus::default();
    let mut out = Vec::new();
    Ok(Box::new(move || {
        partials_on_grid_into(&torus, &nodes, &nodes, &mut out)?;
        Ok(black_box(&out).len())
    }))
}

/// The report's torus (`R = 2`, `r = 1`) with its partials written out by hand (the closed
/// forms of [`Torus`]'s documentation, one `sin_cos` of `s` and one of `t` per node): the
/// same twelve numbers as [`Torus`] without hyper-dual arithmetic — `corner-data`'s floor for
/// any evaluation that calls libm per node.
struct HandWrittenTorus;

impl crate::surface::SurfaceDerivatives for HandWrittenTorus {
    fn point(&self, s: f64, t: f64) -> Vector3<f64> {
        self.partials(s, t).point
    }

    fn partials(&self, s: f64, t: f64) -> crate::surface::Partials {
        let ((sin_s, cos_s), (sin_t, cos_t)) = (s.sin_cos(), t.sin_cos());
        let ring = 2.0 + cos_t;
        crate::surface::Partials {
            point: Vector3::new(ring * cos_s, ring * sin_s, sin_t),
            ds: Vector3::new(-ring * sin_s, ring * cos_s, 0.0),
            dt: Vector3::new(-sin_t * cos_s, -sin_t * sin_s, cos_t),
            dst: Vector3::new(sin_t * sin_s, -sin_t * cos_s, 0.0),
        }
    }
}

fn corner_data_by_hand(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let nodes = linspace(0.0, TAU, k);
    let mut out = Vec::new();
    Ok(Box::new(move || {
        partials_on_grid_into(&HandWrittenTorus, &nodes, &nodes, &mut out)?;
        Ok(black_box(&out).len())
    }))
}

fn torus_grid_on(k: usize, parallel: bool) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let samples = linspace(0.0, TAU, k);
    let mut out = Vec::new();
    Ok(Box::new(move || {
        let spline = HermiteSurface::try_from_surface(
            &Torus::default(),
            Partition::uniform(0.0, TAU, 16)?,
            Partition::uniform(0.0, TAU, 16)?,
        )?;
        spline.tabulate_into_on(&samples, &samples, &mut out, parallel)?;
        Ok(black_box(&out).len())
    }))
}

fn torus_grid(k: usize) -> Result<Runner> {
    torus_grid_on(k, true)
}

fn torus_grid_one_core(k: usize) -> Result<Runner> {
    torus_grid_on(k, false)
}

/// Control points of the B-spline workloads.
const BSPLINE_POINTS: usize = 60;
/// Points of the `angular-curve` workloads' closed ellipse.
const ANGULAR_POINTS: usize = 1000;
/// Data points of the spline of `cubic-spline-eval`.
const SPLINE_POINTS: usize = 1_000_000;

/// Spans of the `bspline-curve-spans` workload's curve.
const MANY_SPANS: usize = 1_000_000;

/// The helix-like polygon of the B-spline workloads: degree `p`, `n` control points, clamped
/// knots with uniform interior.
fn helix(p: usize, n: usize) -> Result<BSplineCurve<3>> {
    let points: Vec<Vector3<f64>> = (0..n)
        .map(|i| {
            let a = 0.4 * i as f64;
            Vector3::new(a.cos(), a.sin(), 0.05 * i as f64)
        })
        .collect();
    let knots = KnotVector::open_uniform(p, n, 0.0, 1.0)?;
    BSplineCurve::try_new(BSplineBasis::try_new(knots, p)?, points)
}

fn bspline_curve_of_degree(p: usize, k: usize) -> Result<Runner> {
    bspline_curve_with(p, BSPLINE_POINTS, k)
}

fn bspline_curve_with(p: usize, n: usize, k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let curve = helix(p, n)?;
    let params = linspace(0.0, 1.0, k);
    let mut out = Vec::new();
    Ok(Box::new(move || {
        curve.eval_many(&params, &mut out);
        Ok(black_box(&out).len())
    }))
}

fn bspline_curve(k: usize) -> Result<Runner> {
    bspline_curve_of_degree(3, k)
}

fn bspline_curve_deg5(k: usize) -> Result<Runner> {
    bspline_curve_of_degree(5, k)
}

fn bspline_curve_deg7(k: usize) -> Result<Runner> {
    bspline_curve_of_degree(7, k)
}

fn bspline_curve_spans(k: usize) -> Result<Runner> {
    bspline_curve_with(3, MANY_SPANS + 3, k)
}

/// `k` points `x` equally spaced in `[0, 1000]` with `y = sin x`.
fn sine_data(k: usize) -> (Vec<f64>, Vec<f64>) {
    let x = linspace(0.0, 1000.0, k);
    let y = x.iter().map(|x| x.sin()).collect();
    (x, y)
}

fn cubic_spline_build(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let (x, y) = sine_data(k);
    Ok(Box::new(move || {
        let s = CubicSpline::function(black_box(&x), black_box(&y), EndCondition::Natural)?;
        Ok(black_box(s).nodes().len())
    }))
}

fn cubic_spline_refit(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let (x, y) = sine_data(k);
    let mut spline = Some(CubicSpline::function(&x, &y, EndCondition::Natural)?);
    Ok(Box::new(move || {
        let s = spline.take().ok_or(crate::error::Error::Degenerate {
            what: "cubic-spline-refit workload",
            reason: "a previous run failed and freed the spline",
        })?;
        let s = s.refit_function(black_box(&x), black_box(&y))?;
        let nodes = black_box(&s).nodes().len();
        spline = Some(s);
        Ok(nodes)
    }))
}

fn cubic_spline_eval(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let (x, y) = sine_data(SPLINE_POINTS);
    let spline = CubicSpline::function(&x, &y, EndCondition::Natural)?;
    let params = linspace(0.0, 1000.0, k);
    let mut out = Vec::new();
    Ok(Box::new(move || {
        spline.values_into(&params, &mut out);
        Ok(black_box(&out).len())
    }))
}

fn nurbs_circle(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let circle = NurbsCurve::circle9(Vector2::zeros(), 1.0)?;
    let params = linspace(0.0, 1.0, k);
    let mut out = Vec::new();
    Ok(Box::new(move || {
        circle.eval_many(&params, &mut out);
        Ok(black_box(&out).len())
    }))
}

fn ellipse() -> Result<AngularSpline> {
    AngularSpline::closed(
        &(0..ANGULAR_POINTS)
            .map(|i| {
                let t = TAU * i as f64 / ANGULAR_POINTS as f64;
                Vector2::new(t.cos(), 0.5 * t.sin())
            })
            .collect::<Vec<_>>(),
    )
}

fn angular_curve(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let angular = ellipse()?;
    let mut out = Vec::new();
    Ok(Box::new(move || {
        angular.polyline_into(k, &mut out)?;
        Ok(black_box(&out).len())
    }))
}

fn angular_curve_pointwise(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let angular = ellipse()?;
    Ok(Box::new(move || {
        let line = angular.polyline(k)?;
        Ok(black_box(line).len())
    }))
}

fn table_i(_: usize) -> Result<Runner> {
    Ok(Box::new(|| {
        Ok(black_box(crate::study::table_i::table_i()?).len())
    }))
}

/// `n` points along the closed ring `ring` (about: each side gets its share by length), the
/// first repeated at the end: a dense digitised outline.
fn densified(ring: &[nalgebra::Vector2<f64>], n: usize) -> Vec<nalgebra::Vector2<f64>> {
    let sides: Vec<(nalgebra::Vector2<f64>, nalgebra::Vector2<f64>)> = ring
        .iter()
        .zip(ring.iter().cycle().skip(1))
        .map(|(a, b)| (*a, *b))
        .collect();
    let total: f64 = sides.iter().map(|(a, b)| (b - a).norm()).sum();
    let mut out = Vec::with_capacity(n + sides.len() + 1);
    for (a, b) in sides {
        let k = ((n as f64 * (b - a).norm() / total).round() as usize).max(1);
        out.extend((0..k).map(|j| a + (b - a) * (j as f64 / k as f64)));
    }
    out.push(out[0]);
    out
}

/// `splinelab fewest`'s search with its default options, every method, on the coast of
/// Sicily densified to `n` points (a digitised outline).
fn fewest_outline(n: usize) -> Result<Runner> {
    Ok(fewest_runner(vec![crate::input::Contour {
        points: densified(&crate::seeds::seed004::coastline(), n),
        closed: true,
    }]))
}

/// The world map of the SVG corpus (`@svg-maps/world`, 1 533 contours, 95 513 points), read
/// as `splinelab fewest` reads it.
fn world_map() -> Result<Vec<crate::input::Contour>> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/svg_corpus/svg-maps-world.svg");
    crate::report::user::outline::read_outline(&path, &Default::default()).map_err(|e| match e {
        Error::Core(e) => e,
        other => crate::error::Error::Parse {
            what: "world map of the SVG corpus",
            line: 1,
            column: 1,
            message: other.to_string(),
        },
    })
}

/// `splinelab fewest`'s search with its default options, every method, on the whole world map.
fn fewest_world(_: usize) -> Result<Runner> {
    Ok(fewest_runner(world_map()?))
}

/// `splinelab fewest`'s search with its default options, every method, on the world map's
/// contour with the most vertices (a real digitised coast).
fn fewest_country(_: usize) -> Result<Runner> {
    let largest = world_map()?
        .into_iter()
        .max_by_key(|c| c.points.len())
        .ok_or(crate::error::Error::TooFewPoints {
            what: "contours of the world map",
            needed: 1,
            got: 0,
        })?;
    Ok(fewest_runner(vec![largest]))
}

/// One run of `splinelab fewest`'s search with its default options and every method on
/// `outline`: the points counted, summed over the methods.
fn fewest_runner(outline: Vec<crate::input::Contour>) -> Runner {
    use crate::interp::choice::Family;
    use crate::study::outline::{default_options, fewest, Tolerance};
    let families = Family::ALL;
    Box::new(move || {
        let found = fewest(
            &outline,
            Tolerance::default(),
            &families,
            &default_options(),
            &|_| {},
        )?;
        Ok(black_box(found.methods.iter().map(|m| m.counted()).sum()))
    })
}

/// The polygon's exact fewest points ([`crate::interp::choice::search`], linear) on the coast
/// of Sicily densified to `n` points, within 1 % of its size.
fn polygon_optimum(n: usize) -> Result<Runner> {
    use crate::interp::choice::{search, Family, SearchOptions, Target};
    let coast = densified(&crate::seeds::seed004::coastline(), n);
    let target = Target::polyline(&coast, true, 1.0)?;
    let target = target.clone().with_tolerance(0.01 * target.size())?;
    Ok(Box::new(move || {
        let found = search(&target, Family::Linear, &SearchOptions::default())?;
        Ok(black_box(found.choice.measure.counted))
    }))
}

/// The twelve formulas of the torus (`X`, `X_s`, `X_t`, `X_st` by coordinate): traced
/// through `Torus::eval` on hyper-dual numbers of expressions, simplified and printed.
fn symbolic_torus(_: usize) -> Result<Runner> {
    Ok(Box::new(|| {
        let f = crate::symbolic::surface_formulas(&Torus::default(), 0.3, 0.7)?;
        let mut chars = 0;
        for part in [&f.point, &f.ds, &f.dt, &f.dst] {
            for formula in part {
                chars += black_box(formula.plain()).len();
            }
        }
        black_box(chars);
        Ok(12)
    }))
}

/// Every workload.
pub const WORKLOADS: [Workload; 25] = [
    Workload {
        id: "t6-table",
        description: "the whole T6 computation (4 rows, Hermite matrix form, all measures); swept as t6-row",
        unit: "T6 table",
        size: 1,
        sweep: &[],
        setup: t6_table,
    },
    Workload {
        id: "t6-row",
        description: "one T6-style row: n × n Hermite patches of the torus on [0,1]², 15×15 points each, all measures (size: n, patches per side)",
        unit: "patches per side",
        size: 8,
        sweep: &[1, 2, 4, 8, 16, 32, 64, 128, 256],
        setup: t6_row,
    },
    Workload {
        id: "patch-matrix",
        description: "one patch tabulated by H(s)ᵀ C H(t) on k × k points (default 15 × 15, the report's)",
        unit: "points per side",
        size: REPORT_PREC,
        sweep: &[4, 8, 15, 32, 64, 128, 256, 512, 1024],
        setup: patch_matrix,
    },
    Workload {
        id: "patch-decasteljau",
        description: "one patch tabulated by de Casteljau on the Bézier net, k × k points (default 15 × 15)",
        unit: "points per side",
        size: REPORT_PREC,
        sweep: &[4, 8, 15, 32, 64, 128, 256, 512, 1024],
        setup: patch_de_casteljau,
    },
    Workload {
        id: "corner-data",
        description: "point, X_s, X_t, X_st of the torus at k × k nodes (default 257; hyper-dual numbers, all cores)",
        unit: "nodes per side",
        size: 257,
        sweep: &[16, 32, 64, 128, 257, 512, 1024, 2048],
        setup: corner_data,
    },
    Workload {
        id: "corner-data-by-hand",
        description: "the same with the torus's partials written out by hand (libm sin_cos per node, no hyper-duals): the floor of corner-data's per-node evaluation",
        unit: "nodes per side",
        size: 257,
        sweep: &[16, 32, 64, 128, 257, 512, 1024, 2048],
        setup: corner_data_by_hand,
    },
    Workload {
        id: "torus-grid",
        description: "whole torus as 16×16 patches, built and tabulated on k × k nodes (default 1024; output buffer reused; both cores from 65 536 points)",
        unit: "nodes per side",
        size: 1024,
        sweep: &[32, 64, 128, 256, 512, 1024, 2048, 4096],
        setup: torus_grid,
    },
    Workload {
        id: "torus-grid-1core",
        description: "the same on one core",
        unit: "nodes per side",
        size: 1024,
        sweep: &[32, 64, 128, 256, 512, 1024, 2048, 4096],
        setup: torus_grid_one_core,
    },
    Workload {
        id: "bspline-curve",
        description: "cubic B-spline, 60 control points in 3-D, clamped uniform knots, at k sorted parameters (default 1e6)",
        unit: "parameters",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: bspline_curve,
    },
    Workload {
        id: "bspline-curve-deg5",
        description: "the same at degree 5",
        unit: "parameters",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: bspline_curve_deg5,
    },
    Workload {
        id: "bspline-curve-deg7",
        description: "the same at degree 7",
        unit: "parameters",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: bspline_curve_deg7,
    },
    Workload {
        id: "bspline-curve-spans",
        description: "cubic B-spline with 10⁶ spans (10⁶ + 3 control points in 3-D, 24 MB; clamped uniform knots) at k sorted parameters (default 1e6): each parameter in its own span up to 10⁶",
        unit: "parameters",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: bspline_curve_spans,
    },
    Workload {
        id: "cubic-spline-build",
        description: "natural cubic spline through k points (default 1e6; x sorted in [0, 1000], y = sin x), validation included, a new spline each run",
        unit: "data points",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: cubic_spline_build,
    },
    Workload {
        id: "cubic-spline-refit",
        description: "the same rebuilt in the buffers of the previous run's spline (CubicSpline::refit_function)",
        unit: "data points",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: cubic_spline_refit,
    },
    Workload {
        id: "cubic-spline-eval",
        description: "the 1e6-point spline evaluated at k sorted points (default 1e7)",
        unit: "evaluation points",
        size: 10_000_000,
        sweep: POINT_SWEEP,
        setup: cubic_spline_eval,
    },
    Workload {
        id: "nurbs-circle",
        description: "the 9-point NURBS circle at k parameters (default 1e6)",
        unit: "parameters",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: nurbs_circle,
    },
    Workload {
        id: "angular-curve",
        description: "closed Angular spline through 1000 points of an ellipse, k equally spaced samples (default 1e6; polyline_into)",
        unit: "samples",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: angular_curve,
    },
    Workload {
        id: "angular-curve-pointwise",
        description: "the same samples point by point (ParametricCurve::polyline, the reference path)",
        unit: "samples",
        size: 1_000_000,
        sweep: POINT_SWEEP,
        setup: angular_curve_pointwise,
    },
    Workload {
        id: "memory-copy",
        description: "k numbers copied between two buffers (default 1e7; both cores from 65 536): the memory bandwidth beside which the traffic of the other workloads is read (bench::traffic)",
        unit: "numbers",
        size: 10_000_000,
        sweep: POINT_SWEEP,
        setup: memory_copy,
    },
    Workload {
        id: "table-i",
        description: "seed 004's Table I regenerated: 36 cells, each the printed configuration, the fewest points with the paper's rule and the automatic search (all cores; a fixed study, not swept)",
        unit: "Table I",
        size: 1,
        sweep: &[],
        setup: table_i,
    },
    Workload {
        id: "fewest-outline",
        description: "`splinelab fewest` with its default options, the five methods, on the Sicilian coast densified to n points (default 1e4; all cores; points: the counts found)",
        unit: "outline points",
        size: 10_000,
        sweep: &[],
        setup: fewest_outline,
    },
    Workload {
        id: "fewest-country",
        description: "`splinelab fewest` with its default options, the five methods, on the contour of the world map (tests/data/svg_corpus/svg-maps-world.svg) with the most vertices, 4 897 (all cores; points: the counts found)",
        unit: "outline",
        size: 1,
        sweep: &[],
        setup: fewest_country,
    },
    Workload {
        id: "fewest-world",
        description: "`splinelab fewest` with its default options, the five methods, on the whole world map (tests/data/svg_corpus/svg-maps-world.svg: 1 533 contours, 95 513 points; all cores; points: the counts found)",
        unit: "map",
        size: 1,
        sweep: &[],
        setup: fewest_world,
    },
    Workload {
        id: "polygon-optimum",
        description: "the polygon's exact fewest points within 1 % on the Sicilian coast densified to n points (default 1e4; one core; points: the count)",
        unit: "outline points",
        size: 10_000,
        sweep: &[1_000, 10_000, 100_000],
        setup: polygon_optimum,
    },
    Workload {
        id: "symbolic-torus",
        description: "the torus's 12 formulas (X, X_s, X_t, X_st by coordinate) traced through Torus::eval on hyper-dual expressions, simplified and printed (points: formulas; fixed, not swept)",
        unit: "formula set",
        size: 1,
        sweep: &[],
        setup: symbolic_torus,
    },
];

/// The workload of id `id`.
///
/// # Errors
/// [`Error::UnknownId`] for an unknown id.
pub fn workload(id: &str) -> crate::report::Result<&'static Workload> {
    WORKLOADS
        .iter()
        .find(|w| w.id == id)
        .ok_or_else(|| Error::UnknownId {
            what: "workload",
            id: id.to_string(),
        })
}

/// The least bytes one run of workload `id` at `size` must move between the processor and
/// memory when its data exceed the caches: its inputs read once and its outputs written
/// once (8 bytes a number), plus, where the queries touch only part of a large object,
/// a 64-byte line per array and query. `None` for workloads not modelled (the studies, the
/// patches, which live in the caches). Against [`WORKLOADS`]' `memory-copy` of the same size
/// (16 bytes a number: read and written), it says how far a workload is from the memory
/// limit.
///
/// | workload | bytes |
/// |---|---|
/// | `memory-copy` | `16 k` |
/// | `cubic-spline-build`, `-refit` | `16 k` read (x, y) + `24 k` written (nodes, values, moments) |
/// | `cubic-spline-eval` | `16 k` (queries, values) + `min(24 n, 3 · 64 k)` of the `n = 10⁶`-node spline |
/// | `bspline-curve`, `-deg5`, `-deg7` | `8 k` + `24 k` (parameters, 3-D points) |
/// | `bspline-curve-spans` | `32 k` + `min(24 m + 8 m, 2 · 64 k)` of the `m ≈ 10⁶`-span curve's points and knots |
/// | `nurbs-circle` | `8 k` + `16 k` |
/// | `angular-curve`, `-pointwise` | `16 k` (2-D samples) |
/// | `torus-grid`, `-1core` | `24 k²` (3-D points) |
/// | `corner-data`, `-by-hand` | `96 k²` (point and three partials) |
pub fn traffic(id: &str, size: usize) -> Option<u64> {
    let k = u64::try_from(size).ok()?;
    let line = 64u64;
    let per = |bytes: u64| bytes.checked_mul(k);
    match id {
        "memory-copy" => per(16),
        "cubic-spline-build" | "cubic-spline-refit" => per(40),
        "cubic-spline-eval" => {
            per(16)?.checked_add((24 * SPLINE_POINTS as u64).min(per(3 * line)?))
        }
        "bspline-curve" | "bspline-curve-deg5" | "bspline-curve-deg7" => per(32),
        "bspline-curve-spans" => per(32)?.checked_add((32 * MANY_SPANS as u64).min(per(2 * line)?)),
        "nurbs-circle" => per(24),
        "angular-curve" | "angular-curve-pointwise" => per(16),
        "torus-grid" | "torus-grid-1core" => per(24)?.checked_mul(k),
        "corner-data" | "corner-data-by-hand" => per(96)?.checked_mul(k),
        _ => None,
    }
}

/// `memory-copy`: `k` numbers copied from one buffer into another (both allocated and
/// touched before the timing), in two halves on two threads from the batch threshold as the
/// batch evaluations are — the machine's bandwidth at that size.
fn memory_copy(k: usize) -> Result<Runner> {
    crate::error::samples("bench size", k)?;
    let from = linspace(0.0, 1.0, k);
    let mut to = vec![0.0; k];
    let parallel = k >= crate::bspline::curve::EVAL_PARALLEL_MIN;
    Ok(Box::new(move || {
        crate::parallel::fill_halves(black_box(&from), &mut to, 0.0, parallel, |a, b| {
            b.copy_from_slice(a)
        });
        Ok(black_box(&to).len())
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every swept workload prepares and runs at its smallest size, producing the points its
    /// size says; ids are unique.
    #[test]
    fn every_workload_runs_at_its_smallest_size() {
        for (i, w) in WORKLOADS.iter().enumerate() {
            assert!(
                WORKLOADS[..i].iter().all(|o| o.id != w.id),
                "{} twice",
                w.id
            );
            let Some(&size) = w.sweep.first() else {
                continue;
            };
            let mut runner = (w.setup)(size).unwrap_or_else(|e| panic!("{}: {e}", w.id));
            let points = runner().unwrap_or_else(|e| panic!("{}: {e}", w.id));
            assert!(points > 0, "{}", w.id);
            assert_eq!(points, runner().expect("second run"), "{}", w.id);
        }
    }

    /// The hand-written torus of `corner-data-by-hand` is the hyper-dual [`Torus`]'s
    /// partials (so the two workloads compute the same numbers): within a few ulps of the
    /// coordinate bound `R + r = 3`, at nodes over several turns.
    #[test]
    fn the_hand_written_torus_is_the_hyper_dual_one() {
        use crate::surface::SurfaceDerivatives;
        let tol = 8.0 * f64::EPSILON * 3.0;
        for s in linspace(-20.0, 20.0, 41) {
            for t in linspace(-7.0, 13.0, 37) {
                let (a, b) = (
                    Torus::default().partials(s, t),
                    HandWrittenTorus.partials(s, t),
                );
                for (x, y) in [
                    (a.point, b.point),
                    (a.ds, b.ds),
                    (a.dt, b.dt),
                    (a.dst, b.dst),
                ] {
                    assert!((x - y).amax() <= tol, "({s}, {t}): {x} vs {y}");
                }
                assert_eq!(HandWrittenTorus.point(s, t), b.point);
            }
        }
    }
}
