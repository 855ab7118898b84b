//! A catalog of named bad-input cases for every public constructor and evaluator of the
//! mathematics (everything but the report's drawing), checked against the policy written in
//! `src/error.rs`: constructors validate what they are given *and what they derive*; an `Ok`
//! value is finite and satisfies its defining property; evaluation of a validated object at a
//! finite parameter in its domain is finite; the right end of a domain is the left limit;
//! sizes beyond `MAX_ELEMENTS` are `Error::TooLarge` without allocating; and no `try_*` or
//! `Result` API panics, hangs or aborts.
//!
//! # The catalog
//!
//! Every case is a named entry `module::case` (a function `fn() -> Result<(), String>`) that
//! asserts either one specific typed error (`matches!(…, Err(Error::Variant { .. }))`, with
//! the key field checked where it means something) or a documented finite result (the right
//! end of `[0,0,0,1,1,1,2]`, degree 2, is the left limit; a NURBS with weights 1 and 1e-15
//! evaluates the same in batch as one by one; …). Where the policy admits more than one
//! answer (an ill-conditioned problem may be refused or solved), the case accepts either a
//! typed error or an `Ok` value that it checks itself (finite, interpolates its data …).
//! The `*::sweep_non_finite_*` cases put NaN, +inf and −inf into every scalar input position
//! of each constructor; the `shorthand::*` cases check that the `new`-style shorthands panic
//! as they document (in child processes, so the expected panic messages stay out of the
//! test output).
//!
//! - **In-process cases** run in the test `catalog`, each inside `std::panic::catch_unwind`,
//!   so one failing case does not hide the others: all failures are collected and reported
//!   by name at the end.
//! - **Risky cases** (huge sizes that a regression would try to allocate, exponential
//!   recursion, SVDs of NaN, studies that could loop) run in the test
//!   `risky_cases_in_child_processes`, each in its own child process: the test binary
//!   re-invokes itself (`std::env::current_exe()`) with
//!   `--exact single_case --nocapture --test-threads=1` and the environment variable
//!   `SPLINELAB_BAD_INPUT_CASE=<case name>`, under a virtual-memory limit (`ulimit -v`) where
//!   `/bin/sh` is available, and polls it with a timeout (`CHILD_TIMEOUT`), killing it when
//!   the time is up. Every case that aborted (a signal, an allocation failure), timed out or
//!   failed is reported by name.
//!
//! # Layout
//!
//! This file is the harness (cases, child processes, the three tests) and the helpers that
//! several areas share. The rule: **the bad cases of area `X` are in `X.rs`, and each case's
//! name starts with `X::`** (one area per file, the file's `cases()` returns all of them). The
//! areas: `angular` (the Angular spline's chord-line limits), `bezier`, `blending`, `bspline`,
//! `choice` (the automatic point choice), `domain`, `fast_paths` (refit and batch evaluation),
//! `grid`, `hermite`, `input` (CSV, SVG paths, fonts), `interp` (interpolation, refit and
//! collocation), `mesh`, `methods` (seed 004's methods and point rules), `metrics` (surface and
//! curve metrics), `nurbs`, `plot` (the figure builders), `report` (files, figures, tables),
//! `seed004` (its curves and the letter "a"), `shapes`, `shorthand`, `study`, `surface`,
//! `symbolic` and `user` (the report layer's user functions); `plot`, `report` and `user` need
//! the feature `report`.
//!
//! # Running one case
//!
//! Any case, in-process or risky, can be run alone:
//!
//! ```text
//! SPLINELAB_BAD_INPUT_CASE='bspline::basis_right_end_is_left_limit' \
//!     cargo test --test bad_input -- --exact single_case --nocapture
//! ```
//!
//! With the variable set, `catalog` and `risky_cases_in_child_processes` do nothing and
//! `single_case` runs the named case, printing `BAD_INPUT_CASE_RESULT pass` or
//! `BAD_INPUT_CASE_RESULT fail: …`. `cargo test --test bad_input -- --nocapture` prints the
//! case count per area.

use nalgebra::{DMatrix, SVector, Vector1, Vector2, Vector3};
use num_dual::{DualNum, HyperDual64};
use splinelab::blending::opengl::{opengl_groups, opengl_polyline, LastGroup};
use splinelab::blending::surface::SlidingBicubic;
use splinelab::blending::window::{printed_bspline_polyline, WindowCurve};
use splinelab::interp::choice::{Choice, Measure, SearchOptions, Target};
use splinelab::interp::collocation::{
    self, interpolate_curve, schoenberg_whitney, Condition, DerivativeOrder,
};
use splinelab::interp::RESIDUAL_TOLERANCE;
use splinelab::interp::{max_interpolation_error, vandermonde_condition};
use splinelab::metrics::curve::{Distances, Smoothness};
use splinelab::metrics::ErrorAccumulator;
#[cfg(feature = "report")]
use splinelab::report::{draw::Plot2d, figure::Figure, Error as RError};
use splinelab::study::hermite_error::{
    convergence, spline_errors, uniform_spline_errors, PatchEvaluation,
};
use splinelab::tensor::{Net, HERMITE_LIMIT, NET_LIMIT};
use splinelab::Shape;
use splinelab::{
    bernstein_all, bernstein_sum, compare, de_casteljau, de_casteljau_levels,
    de_casteljau_recursive, de_casteljau_surface, fit_bspline, guide_point, hermite_basis,
    matlab_norm, partials_on_grid, partials_on_grid_into, printed_setbval, runge, tabulate,
    AngularSpline, BSplineBasis, BSplineCurve, BezierPatch, Blending, CardinalSpline, CubicEnd,
    CubicSpline, EndCondition, EndKnots, Error, ExpSurface, FnSurface, Grid, HermiteCurve,
    HermitePatch, HermiteSurface, Interpolant, Interval, KnotVector, Lagrange, Method, NodeFamily,
    NurbsCurve, ParametricCurve, Parametrization, Partials, Partition, PiecewiseLinear,
    PowerPolynomial, Rect, Sphere, SurfaceDerivatives, Torus,
};
use splinelab::{MAX_COORDINATE, MAX_ELEMENTS};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

// ---------------------------------------------------------------------------------------------
// The machinery
// ---------------------------------------------------------------------------------------------

/// What a case reports: `Err` describes what was observed instead of what the policy demands.
type CaseResult = Result<(), String>;
type CaseFn = fn() -> CaseResult;

/// The environment variable naming the one case `single_case` runs.
const CASE_ENV: &str = "SPLINELAB_BAD_INPUT_CASE";
/// The line a child prints with its verdict.
const MARKER: &str = "BAD_INPUT_CASE_RESULT";
/// How long a child may run before it is killed and reported as a hang.
const CHILD_TIMEOUT: Duration = Duration::from_secs(20);
/// Children run at the same time (the machine has 2 cores).
const CHILD_PARALLELISM: usize = 2;
/// Virtual-memory limit of a child, in KiB (`ulimit -v`): an attempt to allocate a huge
/// buffer fails (and aborts the child, which is reported) instead of exhausting the machine.
const CHILD_MEMORY_KIB: u64 = 8 * 1024 * 1024;
/// The policy's lower bound on the number of cases.
const MIN_CASES: usize = 396;

#[derive(Clone, Copy)]
struct Case {
    name: &'static str,
    run: CaseFn,
    /// Runs in a child process.
    risky: bool,
}

fn case(name: &'static str, run: CaseFn) -> Case {
    Case {
        name,
        run,
        risky: false,
    }
}

fn risky(name: &'static str, run: CaseFn) -> Case {
    Case {
        name,
        run,
        risky: true,
    }
}

/// A result described without printing a (possibly huge) `Ok` value.
fn show<T, E: std::fmt::Debug + std::fmt::Display>(r: &Result<T, E>) -> String {
    match r {
        Ok(_) => format!("Ok(<{}>)", std::any::type_name::<T>()),
        Err(e) => format!("Err({e:?}) «{e}»"),
    }
}

/// The value of an `Ok`, or the unexpected error as the case's failure.
fn ok<T, E: std::fmt::Debug + std::fmt::Display>(r: Result<T, E>) -> Result<T, String> {
    r.map_err(|e| format!("unexpected Err({e:?}) «{e}»"))
}

/// `Ok(())` if the result is an error matching the pattern (and guard), else a description.
macro_rules! expect_err {
    ($result:expr, $pattern:pat $(if $guard:expr)? $(,)?) => {{
        let result = $result;
        match &result {
            Err(e) if matches!(e, $pattern $(if $guard)?) => Ok(()),
            _ => Err(format!(
                "expected Err({}), got {}",
                stringify!($pattern $(if $guard)?),
                show(&result)
            )),
        }
    }};
}

/// Fails the case with a message unless the condition holds.
macro_rules! ensure {
    ($cond:expr, $($fmt:tt)+) => {{
        // a NaN makes every comparison false, so it fails the check
        let holds: bool = $cond;
        if !holds {
            return Err(format!($($fmt)+));
        }
    }};
}

fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "<non-string panic payload>".to_string()
    }
}

/// Runs a case, turning a panic into a failure.
fn run_guarded(case: &Case) -> CaseResult {
    match catch_unwind(AssertUnwindSafe(case.run)) {
        Ok(r) => r,
        Err(payload) => Err(format!("PANIC: {}", panic_text(payload.as_ref()))),
    }
}

fn v1(x: f64) -> Vector1<f64> {
    Vector1::new(x)
}

fn v2(x: f64, y: f64) -> Vector2<f64> {
    Vector2::new(x, y)
}

fn v3(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

fn finite_vecs<const N: usize>(v: &[SVector<f64, N>]) -> bool {
    v.iter().all(|p| p.iter().all(|x| x.is_finite()))
}

fn finite_grid(g: &Grid<Vector3<f64>>) -> bool {
    finite_vecs(g.as_slice())
}

fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|k| {
            if k + 1 == n {
                b
            } else {
                a + (b - a) * k as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// All four partials equal to `(p, p, p)`, `(d, d, d)`, … .
fn partials(p: f64, ds: f64, dt: f64, dst: f64) -> Partials {
    let v = |x: f64| v3(x, x, x);
    Partials {
        point: v(p),
        ds: v(ds),
        dt: v(dt),
        dst: v(dst),
    }
}

/// A net whose entries are `value` with alternating signs.
fn alternating_net(value: f64) -> Net {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let s = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
            v3(s * value, -s * value, s * value)
        })
    })
}

fn unit_net() -> Net {
    std::array::from_fn(|i| std::array::from_fn(|j| v3(i as f64, j as f64, (i * j) as f64)))
}

/// `count` control points alternating between `±value` in both coordinates.
fn alternating_points(count: usize, value: f64) -> Vec<Vector2<f64>> {
    (0..count)
        .map(|i| {
            let s = if i % 2 == 0 { 1.0 } else { -1.0 };
            v2(s * value, -s * value * 0.5)
        })
        .collect()
}

fn some_points(count: usize) -> Vec<Vector2<f64>> {
    (0..count)
        .map(|i| {
            let x = i as f64;
            v2(x, (0.7 * x).sin() * 3.0)
        })
        .collect()
}

fn basis(degree: usize, count: usize) -> Result<BSplineBasis, String> {
    ok(BSplineBasis::try_new(
        ok(KnotVector::open_uniform(degree, count, 0.0, 1.0))?,
        degree,
    ))
}

/// The 3-point data `(0,0), (1,0), (1,1e-20)`: steps 1 and 1e-20.
fn unequal_step_points() -> Vec<Vector2<f64>> {
    vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 1e-20)]
}

/// The policy for parameters: increasing from 0 to 1, no repeats.
fn check_parameters(t: &[f64]) -> CaseResult {
    ensure!(
        t.first() == Some(&0.0),
        "parameters start at {:?}",
        t.first()
    );
    ensure!(t.last() == Some(&1.0), "parameters end at {:?}", t.last());
    ensure!(
        t.windows(2).all(|w| w[0] < w[1]),
        "parameters not strictly increasing: {t:?}"
    );
    Ok(())
}

/// A path that is a plain file, so any folder below it cannot be created (also as root).
#[cfg(feature = "report")]
fn plain_file() -> Result<(tempfile::TempDir, PathBuf), String> {
    let dir = tempfile::tempdir().map_err(|e| format!("tempdir: {e}"))?;
    let file = dir.path().join("plain-file");
    std::fs::write(&file, "not a folder").map_err(|e| format!("write: {e}"))?;
    Ok((dir, file))
}

/// A torus written as a closure, for radii `Torus::try_new` refuses.
fn fn_torus(
    major: f64,
    minor: f64,
) -> FnSurface<impl Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64> + Sync> {
    FnSurface::new(move |s: HyperDual64, t: HyperDual64| {
        let ring = t.cos() * minor + major;
        Vector3::new(ring * s.cos(), ring * s.sin(), t.sin() * minor)
    })
}

// helpers shared by several areas

/// The policy for an interpolant `s` of `(x, y)`: finite on the domain and within
/// `RESIDUAL_TOLERANCE · max |y|` of every datum.
fn check_interpolates(x: &[f64], y: &[f64], s: impl Fn(f64) -> f64) -> CaseResult {
    let scale = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let tol = RESIDUAL_TOLERANCE * if scale > 0.0 { scale } else { 1.0 };
    for (xi, yi) in x.iter().zip(y) {
        let r = (s(*xi) - yi).abs();
        ensure!(r <= tol, "s({xi}) misses {yi} by {r:e} (> {tol:e})");
    }
    let (a, b) = (x[0], x[x.len() - 1]);
    for t in linspace(a, b, 501) {
        ensure!(
            s(t).is_finite(),
            "s({t}) = {} not finite in the domain",
            s(t)
        );
    }
    Ok(())
}

fn grid3(rows: usize, cols: usize, f: impl Fn(usize, usize) -> Vector3<f64>) -> Grid<Vector3<f64>> {
    Grid::from_fn(rows, cols, f)
}

fn nurbs_with(weights: Vec<f64>) -> Result<NurbsCurve<2>, Error> {
    let n = weights.len();
    let b = BSplineBasis::try_new(KnotVector::open_uniform(2, n, 0.0, 1.0)?, 2)?;
    NurbsCurve::try_new(b, some_points(n), weights)
}

fn sliding_grid(rows: usize, cols: usize, value: f64) -> Grid<Vector3<f64>> {
    Grid::from_fn(rows, cols, |i, j| {
        let s = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
        v3(i as f64, j as f64, s * value)
    })
}

const NON_FINITE: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// Runs `check(bad, position)` for every non-finite value and position, naming the first
/// failure.
fn sweep(positions: usize, check: impl Fn(f64, usize) -> CaseResult) -> CaseResult {
    for bad in NON_FINITE {
        for k in 0..positions {
            check(bad, k).map_err(|e| format!("value {bad} at position {k}: {e}"))?;
        }
    }
    Ok(())
}

fn put(mut v: Vec<f64>, k: usize, bad: f64) -> Vec<f64> {
    v[k] = bad;
    v
}

fn four_points() -> Vec<Vector2<f64>> {
    vec![v2(0.0, 0.0), v2(1.0, 1.0), v2(2.0, 0.0), v2(3.0, 1.0)]
}

fn angular_ok(p: Vec<Vector2<f64>>) -> CaseResult {
    let s = ok(AngularSpline::try_new(p.clone()))?;
    let line = ok(s.polyline(257))?;
    ensure!(finite_vecs(&line), "a point is not finite");
    let scale = p
        .iter()
        .map(|q| q.abs().max())
        .fold(f64::MIN_POSITIVE, f64::max);
    for j in 0..=s.pieces() {
        let e = (s.point(j as f64) - p[j + 1]).abs().max();
        ensure!(e <= 1e-14 * scale, "misses point {}: {e:e}", j + 1);
    }
    Ok(())
}

/// `Ok` if `f` panics (a `new`-style shorthand documents its panic).
fn expect_panic<T>(what: &str, f: impl FnOnce() -> T + std::panic::UnwindSafe) -> CaseResult {
    match catch_unwind(f) {
        Err(_) => Ok(()),
        Ok(_) => Err(format!("{what} did not panic on invalid input")),
    }
}

// helpers shared by the areas of seed 004's API (methods, shapes, curve metrics, point choice,
// studies, figures)

/// One method of every family, the cubic spline with each of its ends.
fn all_methods() -> Vec<Method> {
    vec![
        Method::Angular,
        Method::Cardinal { a: 0.5 },
        Method::Cubic {
            end: CubicEnd::Relaxed,
        },
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        Method::Cubic {
            end: CubicEnd::Anticyclic,
        },
        Method::BSpline { order: 3 },
        Method::Linear,
    ]
}

/// Six points without collinear triples (open or closed), times `scale`.
fn six_points(scale: f64) -> Vec<Vector2<f64>> {
    [
        (0.0, 0.0),
        (1.0, 1.0),
        (2.0, 0.0),
        (3.0, 1.0),
        (4.0, 0.5),
        (5.0, 2.0),
    ]
    .iter()
    .map(|&(x, y)| v2(x * scale, y * scale))
    .collect()
}

/// The defining property of a method's curve through `points`: finite samples, and the
/// points interpolated (the B-spline: its end control points) to `1e-13` of their scale.
fn check_curve(m: &Method, points: &[Vector2<f64>], closed: bool, c: &Interpolant) -> CaseResult {
    let line = ok(c.polyline(257))?;
    ensure!(
        finite_vecs(&line),
        "{}: a sample is not finite",
        format_args!("{:?}", m)
    );
    let all = m.prepared(points, closed);
    let scale = all
        .iter()
        .map(|p| p.amax())
        .fold(f64::MIN_POSITIVE, f64::max);
    let tol = 1e-13 * scale;
    let miss = |t: f64, p: &Vector2<f64>| (c.point(t) - p).amax();
    match m {
        Method::BSpline { .. } => {
            let (a, b) = c.domain();
            let e = miss(a, &all[0]).max(miss(b, &all[all.len() - 1]));
            ensure!(
                e <= tol,
                "{}: misses its end points by {e:e}",
                format_args!("{:?}", m)
            );
        }
        Method::Angular | Method::Cardinal { .. } => {
            for (j, p) in all[1..all.len() - 1].iter().enumerate() {
                let e = miss(j as f64, p);
                ensure!(
                    e <= tol,
                    "{}: misses point {} by {e:e}",
                    format_args!("{:?}", m),
                    j + 1
                );
            }
        }
        Method::Cubic { .. } | Method::Linear => {
            let breaks = c.breaks();
            ensure!(
                breaks.len() == all.len(),
                "{}: {} breaks for {} points",
                format_args!("{:?}", m),
                breaks.len(),
                all.len()
            );
            for (j, (t, p)) in breaks.iter().zip(&all).enumerate() {
                let e = miss(*t, p);
                ensure!(
                    e <= tol,
                    "{}: misses point {j} by {e:e}",
                    format_args!("{:?}", m)
                );
            }
        }
    }
    Ok(())
}

/// The shapes with parameters, each parameter position replaced by `bad` (the rectangle in
/// either side).
fn shapes_with(bad: f64) -> Vec<Shape> {
    vec![
        Shape::Ellipse { ratio: bad },
        Shape::Parabola { half_width: bad },
        Shape::Hyperbola { b: bad },
        Shape::Sinusoid { periods: bad },
        Shape::Rectangle {
            width: bad,
            height: 1.0,
        },
        Shape::Rectangle {
            width: 2.0,
            height: bad,
        },
    ]
}

/// `|got − want| ≤ rel · |want|`, and `want > 0` so that a zero is never mistaken for it.
fn close(what: &str, got: f64, want: f64, rel: f64) -> CaseResult {
    ensure!(
        want > 0.0 && want.is_finite(),
        "{what}: the reference is {want:e}"
    );
    ensure!(
        (got - want).abs() <= rel * want,
        "{what}: got {got:e}, the rescaled computation gives {want:e} (relative error {:e})",
        (got - want).abs() / want
    );
    Ok(())
}

/// The rectangle 2 × 1 as a closed polyline of `samples` segments, tolerance 1 % of 2.
fn rectangle_target(samples: usize) -> Result<Target, String> {
    let r = Shape::Rectangle {
        width: 2.0,
        height: 1.0,
    };
    ok(Target::polyline(&ok(r.reference(samples))?, true, 0.02))
}

/// Search options of at most `max_points` points and a small budget per coordinate.
fn options(max_points: usize) -> SearchOptions {
    SearchOptions {
        max_points,
        budget_per_coordinate: 10,
        ..SearchOptions::default()
    }
}

/// A search result that claims to meet the tolerance with `points`, counted as `counted`.
fn bogus_choice(method: Method, points: Vec<Vector2<f64>>, counted: usize) -> Choice {
    Choice {
        method,
        points,
        measure: Measure {
            distances: Distances {
                curve_to_reference: 0.0,
                reference_to_curve: 0.0,
            },
            smoothness: Smoothness {
                inflections: 0,
                max_jump: 0.0,
                max_curvature: 0.0,
                singular: 0,
            },
            counted,
        },
        within_tolerance: true,
        evaluations: 0,
        start: splinelab::interp::choice::Start::Known,
    }
}

// helpers shared by the report's areas (`report`, `plot`)

/// Blue, for the series and markers of the report's figures.
#[cfg(feature = "report")]
const BLUE: plotters::style::RGBColor = plotters::style::RGBColor(0, 0, 255);

/// A figure drawn as SVG: `Ok` (an SVG document) or a typed [`RError::Figure`] —
/// never a panic or a hang.
#[cfg(feature = "report")]
fn svg_or_refused(fig: &Figure) -> CaseResult {
    match fig.to_svg() {
        Ok(svg) => {
            ensure!(svg.contains("<svg"), "not an SVG document");
            Ok(())
        }
        Err(RError::Figure { .. }) => Ok(()),
        Err(e) => Err(format!("unexpected Err({e})")),
    }
}

/// A figure drawn both as SVG and as pixels (at a small size): `Ok` or a typed
/// [`RError::Figure`], the pixel buffer of the figure's size.
#[cfg(feature = "report")]
fn drawable(fig: Figure) -> CaseResult {
    let fig = fig.with_size(320, 240);
    svg_or_refused(&fig)?;
    match fig.to_rgb() {
        Ok(px) => {
            ensure!(px.len() == 320 * 240 * 3, "{} bytes", px.len());
            Ok(())
        }
        Err(RError::Figure { .. }) => Ok(()),
        Err(e) => Err(format!("unexpected Err({e})")),
    }
}

/// A figure that must draw (finite, ordinary data): SVG and pixels.
#[cfg(feature = "report")]
fn draws(fig: Figure) -> CaseResult {
    let fig = fig.with_size(320, 240);
    let svg = ok(fig.to_svg())?;
    ensure!(svg.contains("<svg"), "not an SVG document");
    let px = ok(fig.to_rgb())?;
    ensure!(px.len() == 320 * 240 * 3, "{} bytes", px.len());
    Ok(())
}

/// One panel of one series `points`, as a figure.
#[cfg(feature = "report")]
fn series_figure(points: Vec<(f64, f64)>) -> Figure {
    Plot2d::new("extreme data", "x", "y")
        .series("data", points)
        .figure()
}

/// The surface `(s, t, s t)`, for the builders and tables of the report.
#[cfg(feature = "report")]
fn surface() -> FnSurface<impl Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64> + Sync> {
    FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * t))
}

// ---------------------------------------------------------------------------------------------
// The tests
// ---------------------------------------------------------------------------------------------

mod angular;
mod bezier;
mod blending;
mod bspline;
mod choice;
mod domain;
mod exact;
mod fast_paths;
mod grid;
mod hermite;
mod input;
mod interp;
mod mesh;
mod methods;
mod metrics;
mod nurbs;
#[cfg(feature = "report")]
mod plot;
#[cfg(feature = "report")]
mod report;
mod seed004;
mod shapes;
mod shorthand;
mod study;
mod surface;
mod symbolic;
#[cfg(feature = "report")]
mod user;

/// Every case of every area.
fn all_cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(angular::cases());
    all.extend(bezier::cases());
    all.extend(blending::cases());
    all.extend(bspline::cases());
    all.extend(choice::cases());
    all.extend(domain::cases());
    all.extend(exact::cases());
    all.extend(fast_paths::cases());
    all.extend(grid::cases());
    all.extend(hermite::cases());
    all.extend(input::cases());
    all.extend(interp::cases());
    all.extend(mesh::cases());
    all.extend(methods::cases());
    all.extend(metrics::cases());
    all.extend(nurbs::cases());
    #[cfg(feature = "report")]
    all.extend(plot::cases());
    #[cfg(feature = "report")]
    all.extend(report::cases());
    all.extend(seed004::cases());
    all.extend(shapes::cases());
    all.extend(shorthand::cases());
    all.extend(study::cases());
    all.extend(surface::cases());
    all.extend(symbolic::cases());
    #[cfg(feature = "report")]
    all.extend(user::cases());
    all
}

fn module_of(name: &str) -> &str {
    name.split("::").next().unwrap_or(name)
}

/// Runs the in-process cases, each under `catch_unwind`, and reports every failure by name.
#[test]
fn catalog() {
    if std::env::var_os(CASE_ENV).is_some() {
        return;
    }
    let cases = all_cases();
    let mut names: Vec<&str> = cases.iter().map(|c| c.name).collect();
    names.sort_unstable();
    let duplicates: Vec<&str> = names
        .windows(2)
        .filter(|w| w[0] == w[1])
        .map(|w| w[0])
        .collect();
    assert!(
        duplicates.is_empty(),
        "duplicate case names: {duplicates:?}"
    );
    assert!(cases.len() >= MIN_CASES, "only {} cases", cases.len());

    let mut counts: Vec<(&str, usize, usize)> = Vec::new();
    for c in &cases {
        let m = module_of(c.name);
        match counts.iter_mut().find(|(n, _, _)| *n == m) {
            Some(entry) => {
                entry.1 += 1;
                entry.2 += usize::from(c.risky);
            }
            None => counts.push((m, 1, usize::from(c.risky))),
        }
    }
    println!("bad-input catalog: {} cases", cases.len());
    for (m, n, r) in &counts {
        println!("  {m:<10} {n:>4} cases ({r} in child processes)");
    }

    let start = Instant::now();
    let mut failures = Vec::new();
    for c in cases.iter().filter(|c| !c.risky) {
        let t0 = Instant::now();
        let result = run_guarded(c);
        let took = t0.elapsed();
        if took > Duration::from_secs(3) {
            println!("  slow case {}: {took:?}", c.name);
        }
        if let Err(msg) = result {
            failures.push(format!("{}: {msg}", c.name));
        }
    }
    println!(
        "in-process cases: {} run in {:?}, {} failed",
        cases.iter().filter(|c| !c.risky).count(),
        start.elapsed(),
        failures.len()
    );
    assert!(
        failures.is_empty(),
        "{} bad-input case(s) contradict the policy:\n  {}",
        failures.len(),
        failures.join("\n  ")
    );
}

/// With `SPLINELAB_BAD_INPUT_CASE` set, runs that one case and exits with its verdict;
/// without it, does nothing.
#[test]
fn single_case() {
    let Ok(name) = std::env::var(CASE_ENV) else {
        return;
    };
    let Some(c) = all_cases().into_iter().find(|c| c.name == name) else {
        println!("\n{MARKER} fail: no case named `{name}`");
        std::process::exit(2);
    };
    match run_guarded(&c) {
        Ok(()) => {
            println!("\n{MARKER} pass");
            std::process::exit(0);
        }
        Err(msg) => {
            println!("\n{MARKER} fail: {msg}");
            std::process::exit(1);
        }
    }
}

/// A child process running one risky case.
struct Running {
    name: &'static str,
    child: Child,
    started: Instant,
    stdout: PathBuf,
    stderr: PathBuf,
}

fn spawn_case(name: &'static str, dir: &Path, index: usize) -> std::io::Result<Running> {
    let exe = std::env::current_exe()?;
    let stdout = dir.join(format!("case-{index}.out"));
    let stderr = dir.join(format!("case-{index}.err"));
    let args = ["--exact", "single_case", "--nocapture", "--test-threads=1"];
    let mut cmd = if Path::new("/bin/sh").exists() {
        let mut c = Command::new("/bin/sh");
        c.arg("-c")
            .arg(format!(
                "ulimit -v {CHILD_MEMORY_KIB} 2>/dev/null; exec \"$0\" \"$@\""
            ))
            .arg(&exe)
            .args(args);
        c
    } else {
        let mut c = Command::new(&exe);
        c.args(args);
        c
    };
    let child = cmd
        .env(CASE_ENV, name)
        .env("RUST_BACKTRACE", "0")
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&stdout)?)
        .stderr(std::fs::File::create(&stderr)?)
        .spawn()?;
    Ok(Running {
        name,
        child,
        started: Instant::now(),
        stdout,
        stderr,
    })
}

fn tail(path: &Path, lines: usize) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let all: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    all[all.len().saturating_sub(lines)..].join(" | ")
}

/// The verdict of a finished child: `None` if the case passed.
fn verdict(run: &Running, status: std::process::ExitStatus) -> Option<String> {
    let out = std::fs::read_to_string(&run.stdout).unwrap_or_default();
    let marker = out
        .lines()
        .find_map(|l| l.find(MARKER).map(|i| &l[i + MARKER.len()..]))
        .map(str::trim);
    match (status.code(), marker) {
        (Some(0), Some("pass")) => None,
        (Some(_), Some(m)) => Some(m.to_string()),
        (code, _) => {
            #[cfg(unix)]
            let signal = std::os::unix::process::ExitStatusExt::signal(&status);
            #[cfg(not(unix))]
            let signal: Option<i32> = None;
            Some(format!(
                "ABORTED (exit code {code:?}, signal {signal:?}); stderr: {}",
                tail(&run.stderr, 4)
            ))
        }
    }
}

/// Runs every risky case in its own child process with a timeout; reports every case that
/// aborted, timed out or failed.
#[test]
fn risky_cases_in_child_processes() {
    if std::env::var_os(CASE_ENV).is_some() {
        return;
    }
    let dir = tempfile::tempdir().expect("temporary folder for child output");
    let risky: Vec<Case> = all_cases().into_iter().filter(|c| c.risky).collect();
    let start = Instant::now();
    let mut pending = risky.iter().enumerate();
    let mut running: Vec<Running> = Vec::new();
    let mut failures: Vec<String> = Vec::new();
    loop {
        while running.len() < CHILD_PARALLELISM {
            let Some((i, c)) = pending.next() else { break };
            match spawn_case(c.name, dir.path(), i) {
                Ok(r) => running.push(r),
                Err(e) => {
                    failures.push(format!("{}: could not start a child process: {e}", c.name))
                }
            }
        }
        if running.is_empty() {
            break;
        }
        let mut k = 0;
        while k < running.len() {
            let r = &mut running[k];
            match r.child.try_wait() {
                Ok(Some(status)) => {
                    let took = r.started.elapsed();
                    if took > Duration::from_secs(3) {
                        println!("  slow risky case {}: {took:?}", r.name);
                    }
                    if let Some(msg) = verdict(r, status) {
                        failures.push(format!("{}: {msg}", r.name));
                    }
                    running.swap_remove(k);
                    continue;
                }
                Ok(None) if r.started.elapsed() > CHILD_TIMEOUT => {
                    let _ = r.child.kill();
                    let _ = r.child.wait();
                    failures.push(format!(
                        "{}: TIMED OUT after {CHILD_TIMEOUT:?} (killed); stderr: {}",
                        r.name,
                        tail(&r.stderr, 2)
                    ));
                    running.swap_remove(k);
                    continue;
                }
                Ok(None) => {}
                Err(e) => {
                    failures.push(format!("{}: waiting for the child failed: {e}", r.name));
                    let _ = r.child.kill();
                    let _ = r.child.wait();
                    running.swap_remove(k);
                    continue;
                }
            }
            k += 1;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    println!(
        "risky cases: {} run in child processes in {:?}, {} failed",
        risky.len(),
        start.elapsed(),
        failures.len()
    );
    failures.sort();
    assert!(
        failures.is_empty(),
        "{} risky bad-input case(s) contradict the policy:\n  {}",
        failures.len(),
        failures.join("\n  ")
    );
}
