//! Benchmark workloads of the `splinelab bench` subcommand, one JSON line each.

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
use crate::report::figure::Figure;
use crate::seeds::seed000::T6;
use crate::study::hermite_error::{uniform_spline_errors, PatchEvaluation, REPORT_PREC};
use crate::surface::{partials_on_grid_into, Torus};
use nalgebra::{Vector2, Vector3};
use std::f64::consts::TAU;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// One measured workload at one size.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchResult {
    /// Workload id.
    pub workload: &'static str,
    /// The workload's size parameter (its [`Workload::unit`]).
    pub size: usize,
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

    /// The least bytes one run moves between the processor and memory ([`traffic`]) per
    /// second, if the workload's traffic is modelled.
    pub fn bandwidth(&self) -> Option<f64> {
        traffic(self.workload, self.size).map(|b| b as f64 / self.seconds)
    }

    /// The run as a labelled one-row table (size, points, median seconds, points per
    /// second) for a notebook.
    pub fn html(&self) -> crate::report::notebook::Html {
        crate::report::notebook::values(
            self.workload,
            &["size", "points", "median time (s)", "points / s"],
            &[(
                "one run",
                &[
                    self.size as f64,
                    self.points as f64,
                    self.seconds,
                    self.throughput(),
                ],
            )],
        )
    }

    /// Shows [`BenchResult::html`] in a notebook (the evcxr kernel calls this for a cell's
    /// value).
    pub fn evcxr_display(&self) {
        self.html().evcxr_display();
    }

    /// `{"workload": …, "size": …, "points": …, "seconds": …, "throughput": …}`, with
    /// `"bytes"` and `"bytes_per_second"` where [`traffic`] models the workload.
    pub fn to_json(&self) -> String {
        let memory = match (traffic(self.workload, self.size), self.bandwidth()) {
            (Some(b), Some(bw)) => format!(r#", "bytes": {b}, "bytes_per_second": {bw:e}"#),
            _ => String::new(),
        };
        format!(
            r#"{{"workload": "{}", "size": {}, "points": {}, "seconds": {:e}, "throughput": {:e}{memory}}}"#,
            self.workload,
            self.size,
            self.points,
            self.seconds,
            self.throughput()
        )
    }
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

/// One size of a comparison with a peer library, both sides timed in alternating rounds
/// (`scripts/bench_peers.py --sweep`).
#[derive(Debug, Clone, PartialEq)]
pub struct PeerPoint {
    /// Our workload id.
    pub workload: String,
    /// Its size parameter.
    pub size: usize,
    /// Points (or nodes) one run produces.
    pub points: usize,
    /// Our median seconds per run.
    pub ours: f64,
    /// The peer's median seconds per run.
    pub peer: f64,
    /// The peer (`scipy`, say).
    pub peer_name: String,
}

impl PeerPoint {
    /// The peer's time over ours: above 1 we are faster.
    pub fn ratio(&self) -> f64 {
        self.peer / self.ours
    }
}

/// The header of a peer comparison's CSV ([`parse_peers`]).
pub const PEER_HEADER: &str = "workload,size,points,splinelab_seconds,peer_seconds,peer";

/// Parses a peer comparison's CSV (header [`PEER_HEADER`], one size per line), as
/// `scripts/bench_peers.py --sweep` writes it.
///
/// # Errors
/// [`crate::report::Error::Parse`] for a missing or different header, a line without six
/// fields, a size or point count that is not a count, or a time that is not finite and
/// positive.
pub fn parse_peers(what: &str, text: &str) -> crate::report::Result<Vec<PeerPoint>> {
    let bad = |line: usize, message: String| crate::report::Error::Parse {
        what: what.to_string(),
        line,
        message,
    };
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, h)) if h.trim() == PEER_HEADER => {}
        Some((_, h)) => return Err(bad(1, format!("header {h:?}, expected {PEER_HEADER:?}"))),
        None => return Err(bad(1, "empty: no header".into())),
    }
    let mut out = Vec::new();
    for (i, line) in lines {
        let n = i + 1;
        if line.trim().is_empty() {
            continue;
        }
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let [workload, size, points, ours, peer, name] = f[..] else {
            return Err(bad(n, format!("{} fields, expected 6", f.len())));
        };
        let count = |what: &str, v: &str| -> crate::report::Result<usize> {
            v.parse()
                .map_err(|_| bad(n, format!("{what} {v:?} is not a count")))
        };
        let (size, points) = (count("size", size)?, count("points", points)?);
        let time = |v: &str| -> crate::report::Result<f64> {
            match v.parse::<f64>() {
                Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
                _ => Err(bad(n, format!("time {v:?} is not finite and positive"))),
            }
        };
        out.push(PeerPoint {
            workload: workload.to_string(),
            size,
            points,
            ours: time(ours)?,
            peer: time(peer)?,
            peer_name: name.to_string(),
        });
    }
    Ok(out)
}

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
    setup: fn(usize) -> Result<Runner>,
}

/// Points (parameters, samples, data points) of the 1-D sweeps: 10³ … 10⁷, two per octave
/// of √10.
const POINT_SWEEP: &[usize] = &[
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
    use crate::interp::choice::Family;
    use crate::study::outline::{default_options, fewest, Tolerance};
    let outline = [crate::input::Contour {
        points: densified(&crate::seeds::seed004::coastline(), n),
        closed: true,
    }];
    let families = [
        Family::Angular,
        Family::Cardinal,
        Family::Cubic,
        Family::BSpline,
    ];
    Ok(Box::new(move || {
        let found = fewest(
            &outline,
            Tolerance::default(),
            &families,
            &default_options(),
            &|_| {},
        )?;
        Ok(black_box(found.methods.iter().map(|m| m.counted()).sum()))
    }))
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
pub const WORKLOADS: [Workload; 23] = [
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
        description: "`splinelab fewest` with its default options, the four methods, on the Sicilian coast densified to n points (default 1e4; all cores; points: the counts found)",
        unit: "outline points",
        size: 10_000,
        sweep: &[],
        setup: fewest_outline,
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

/// Runs one workload at its default size: a warm-up, then repeated runs for at least
/// `budget` (and at least 5 times, or 2 when one run outlasts the budget), reporting the median.
///
/// # Errors
/// [`Error::UnknownId`] for an unknown id; errors of the workload.
pub fn run(id: &str, budget: Duration) -> crate::report::Result<BenchResult> {
    let w = workload(id)?;
    run_sized(w, w.size, budget)
}

/// Runs workload `w` at `size` as [`run`] does (inputs prepared outside the timing).
///
/// # Errors
/// Errors of the workload (a size it cannot take among them).
pub fn run_sized(
    w: &'static Workload,
    size: usize,
    budget: Duration,
) -> crate::report::Result<BenchResult> {
    if !w.sweep.is_empty() {
        // every sized workload needs at least 1 (t6-row) or 2 points; none more than the
        // crate's element limit
        crate::error::size("bench size", size)?;
    }
    let mut runner = (w.setup)(size)?;
    let first = Instant::now();
    let points = runner()?;
    // five timed runs at least; two for a workload whose one run outlasts the budget
    let min_runs = if first.elapsed() > budget { 2 } else { 5 };
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < min_runs || start.elapsed() < budget {
        let t = Instant::now();
        black_box(runner()?);
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    Ok(BenchResult {
        workload: w.id,
        size,
        points,
        seconds: times[times.len() / 2],
    })
}

/// The sweep of one workload: [`run_sized`] at each of its [`Workload::sweep`] sizes, each
/// result passed to `each` as it comes (for printing), all returned.
///
/// # Errors
/// As [`run_sized`], and the error of `each`.
pub fn sweep(
    id: &str,
    budget: Duration,
    mut each: impl FnMut(&BenchResult) -> crate::report::Result<()>,
) -> crate::report::Result<Vec<BenchResult>> {
    let w = workload(id)?;
    let mut all = Vec::new();
    for &size in w.sweep {
        let r = run_sized(w, size, budget)?;
        each(&r)?;
        all.push(r);
    }
    Ok(all)
}

/// `fig-bench-scaling`: throughput (points per second) against size (points per run),
/// log-log, one line per workload of `results` (a [`sweep`] of each), in two panels — curves
/// and splines, surfaces and studies. A flat line is a cost proportional to the size; a line
/// that rises at small sizes is paying a fixed cost per run (setup, threads), one that falls
/// at large sizes has left the caches for main memory. With `peers` ([`parse_peers`]) a third
/// panel draws each compared workload's peer time over ours against size, parity (1) dashed:
/// where a line falls to it, the lead is gone.
pub fn scaling_figure(results: &[BenchResult], peers: &[PeerPoint], machine: &str) -> Figure {
    use crate::report::plot2d::{Figure2d, Series};
    let mut ids: Vec<&str> = Vec::new();
    for r in results {
        if !ids.contains(&r.workload) {
            ids.push(r.workload);
        }
    }
    let surfaces = [
        "t6-row",
        "patch-matrix",
        "patch-decasteljau",
        "corner-data",
        "corner-data-by-hand",
        "torus-grid",
        "torus-grid-1core",
    ];
    let mut panels = Vec::new();
    for (title, want_surfaces) in [
        ("curves and splines", false),
        ("surfaces and studies", true),
    ] {
        let mut panel =
            crate::report::plot2d::Panel::new(title, "points per run", "throughput (points / s)")
                .log(true, true)
                .legend_at(plotters::prelude::SeriesLabelPosition::LowerRight);
        let mine: Vec<&str> = ids
            .iter()
            .copied()
            .filter(|id| surfaces.contains(id) == want_surfaces)
            .collect();
        for (k, id) in mine.iter().enumerate() {
            let points = results
                .iter()
                .filter(|r| r.workload == *id)
                .map(|r| (r.points as f64, r.throughput()))
                .collect();
            let (color, style) = line_style(k);
            panel = panel.with(Series::line(*id, points, color).styled(style));
        }
        // an empty band below the data for the legend, whatever the data: the legend's share
        // of the plot's height (about 24 px per entry and 30 more of a 700-px plot) kept free
        // on the log axis
        let ys = results
            .iter()
            .filter(|r| mine.contains(&r.workload))
            .map(|r| r.throughput())
            .filter(|y| y.is_finite() && *y > 0.0);
        let (lo, hi) = ys.fold((f64::INFINITY, 0.0f64), |(lo, hi), y| {
            (lo.min(y), hi.max(y))
        });
        if lo < hi {
            let band = ((24 * mine.len() + 30) as f64 / 700.0).min(0.6);
            let decades = (hi / lo).log10().max(0.5) * 1.1;
            let below = decades * band / (1.0 - band);
            panel = panel.y_range(
                lo / 10f64.powf(below + 0.05 * decades),
                hi * 10f64.powf(0.05 * decades),
            );
        }
        panels.push(panel);
    }
    if !peers.is_empty() {
        panels.push(peer_panel(peers));
    }
    let columns = panels.len();
    Figure::from(Figure2d::new(
        format!("Throughput against size, each workload swept ({machine})"),
        panels,
        (1, columns),
    ))
    .with_size(800 * columns as u32, 800)
}

/// The colour and style of the `k`-th line of a panel: the palette, then two more colours,
/// lines with points; beyond, the same colours dashed.
fn line_style(k: usize) -> (plotters::style::RGBColor, crate::report::plot2d::Style) {
    use crate::report::plot2d::Style;
    let extra = [
        plotters::style::RGBColor(120, 120, 120),
        plotters::style::RGBColor(150, 30, 30),
    ];
    let colors: Vec<_> = crate::report::style::LINE_PALETTE
        .iter()
        .chain(&extra)
        .copied()
        .collect();
    let style = if k < colors.len() {
        Style::LinePoints(4)
    } else {
        Style::Dashed
    };
    (colors[k % colors.len()], style)
}

/// The panel of peer time over ours against size (see [`scaling_figure`]).
fn peer_panel(peers: &[PeerPoint]) -> crate::report::plot2d::Panel {
    use crate::report::plot2d::{Panel, Series, Style};
    let mut ids: Vec<(&str, &str)> = Vec::new();
    for p in peers {
        if !ids.contains(&(p.workload.as_str(), p.peer_name.as_str())) {
            ids.push((p.workload.as_str(), p.peer_name.as_str()));
        }
    }
    let mut panel = Panel::new(
        "peer time ÷ splinelab time (above 1: splinelab faster)",
        "points per run",
        "ratio",
    )
    .log(true, true)
    .legend_at(plotters::prelude::SeriesLabelPosition::UpperLeft);
    let sizes = peers.iter().map(|p| p.points as f64);
    let (lo, hi) = sizes.fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    for (k, (id, peer)) in ids.iter().enumerate() {
        let points: Vec<(f64, f64)> = peers
            .iter()
            .filter(|p| p.workload == *id && p.peer_name == *peer)
            .map(|p| (p.points as f64, p.ratio()))
            .collect();
        let (color, style) = line_style(k);
        panel = panel.with(Series::line(format!("{id} ({peer})"), points, color).styled(style));
    }
    if lo < hi {
        let grey = plotters::style::RGBColor(110, 110, 110);
        panel = panel
            .with(Series::line("parity", vec![(lo, 1.0), (hi, 1.0)], grey).styled(Style::Dashed));
    }
    panel
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

    #[test]
    fn the_scaling_figure_draws() {
        let results: Vec<BenchResult> = [("bspline-curve", 1e3), ("torus-grid", 4096.0)]
            .iter()
            .flat_map(|&(id, base)| {
                let w = workload(id).expect("known");
                (0..4).map(move |k| BenchResult {
                    workload: w.id,
                    size: k,
                    points: (base * 10f64.powi(k as i32)) as usize,
                    seconds: 1e-3 * (k + 1) as f64,
                })
            })
            .collect();
        let svg = scaling_figure(&results, &[], "test").to_svg().expect("svg");
        assert!(svg.contains("bspline-curve") && svg.contains("torus-grid"));
        let text = format!("{PEER_HEADER}\ncubic-spline-eval,1000,1000,1e-5,3e-5,scipy\ncubic-spline-eval,10000,10000,1e-4,2e-4,scipy\n");
        let peers = parse_peers("peers", &text).expect("parses");
        assert_eq!(peers.len(), 2);
        assert!((peers[0].ratio() - 3.0).abs() < 1e-12);
        let svg = scaling_figure(&results, &peers, "test")
            .to_svg()
            .expect("svg");
        assert!(svg.contains("parity") && svg.contains("cubic-spline-eval (scipy)"));
    }

    /// Every point and grid workload has a traffic model, in its JSON; the studies none;
    /// huge sizes give `None`, not an overflow.
    #[test]
    fn traffic_is_modelled_for_the_batch_workloads() {
        for w in &WORKLOADS {
            let modelled = traffic(w.id, w.size);
            let batch = w.sweep == POINT_SWEEP || matches!(w.unit, "nodes per side");
            assert_eq!(modelled.is_some(), batch, "{}", w.id);
        }
        let r = BenchResult {
            workload: "memory-copy",
            size: 1000,
            points: 1000,
            seconds: 1e-6,
        };
        assert!(r
            .to_json()
            .contains(r#""bytes": 16000, "bytes_per_second": 1.6e10"#));
        assert_eq!(traffic("corner-data", usize::MAX), None);
        assert_eq!(traffic("t6-row", 8), None);
    }

    /// A peer CSV that is not one: typed errors naming the line.
    #[test]
    fn bad_peer_files_name_the_line() {
        let bad: Vec<(String, usize)> = vec![
            (String::new(), 1),
            ("workload,size\n".into(), 1),
            (format!("{PEER_HEADER}\nx,1,1e-3\n"), 2),
            (format!("{PEER_HEADER}\nx,-1,1,1e-3,1e-3,scipy\n"), 2),
            (format!("{PEER_HEADER}\nx,1,1.5,1e-3,1e-3,scipy\n"), 2),
            (format!("{PEER_HEADER}\n\nx,10,10,NaN,1e-3,scipy\n"), 3),
            (format!("{PEER_HEADER}\nx,10,10,1e-3,0,scipy\n"), 2),
            (format!("{PEER_HEADER}\nx,10,10,1e-3,inf,scipy\n"), 2),
        ];
        for (text, line) in bad {
            match parse_peers("peers", &text) {
                Err(crate::report::Error::Parse { line: l, .. }) => assert_eq!(l, line, "{text:?}"),
                other => panic!("{text:?}: {other:?}"),
            }
        }
    }
}
