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
//! case count per module.

use nalgebra::{DMatrix, SVector, Vector1, Vector2, Vector3};
use num_dual::{DualNum, HyperDual64};
use splinelab::blending::opengl::{opengl_groups, opengl_polyline, LastGroup};
use splinelab::blending::surface::SlidingBicubic;
use splinelab::blending::window::{printed_bspline_polyline, WindowCurve};
use splinelab::error::{MAX_COORDINATE, MAX_ELEMENTS};
use splinelab::interp::collocation::{
    self, interpolate_curve, schoenberg_whitney, Condition, DerivativeOrder,
};
use splinelab::interp::polynomial::{max_interpolation_error, vandermonde_condition};
use splinelab::interp::RESIDUAL_TOLERANCE;
use splinelab::metrics::surface::ErrorAccumulator;
use splinelab::tensor::{Net, HERMITE_LIMIT, NET_LIMIT};
use splinelab::{
    bernstein_all, bernstein_sum, compare, convergence, de_casteljau, de_casteljau_levels,
    de_casteljau_recursive, de_casteljau_surface, fit_bspline, guide_point, hermite_basis,
    matlab_norm, partials_on_grid, partials_on_grid_into, printed_setbval, runge, spline_errors,
    tabulate, uniform_spline_errors, AngularSpline, BSplineBasis, BSplineCurve, BezierPatch,
    Blending, CardinalSpline, CubicSpline, EndCondition, EndKnots, Error, ExpSurface, FnSurface,
    Grid, HermiteCurve, HermitePatch, HermiteSurface, Interval, KnotVector, Lagrange, NodeFamily,
    NurbsCurve, ParametricCurve, Parametrization, Partials, Partition, PatchEvaluation,
    PiecewiseLinear, PowerPolynomial, Rect, Sphere, SurfaceDerivatives, Torus,
};
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

// ---------------------------------------------------------------------------------------------
// domain: Interval, Rect, Partition
// ---------------------------------------------------------------------------------------------

fn domain_cases() -> Vec<Case> {
    vec![
        case(
            "domain::interval_nan_start",
            || expect_err!(Interval::try_new(f64::NAN, 1.0), Error::NonFinite { value, .. } if value.is_nan()),
        ),
        case(
            "domain::interval_pos_inf_end",
            || expect_err!(Interval::try_new(0.0, f64::INFINITY), Error::NonFinite { value, .. } if *value == f64::INFINITY),
        ),
        case(
            "domain::interval_neg_inf_start",
            || expect_err!(Interval::try_new(f64::NEG_INFINITY, 0.0), Error::NonFinite { value, .. } if *value == f64::NEG_INFINITY),
        ),
        case(
            "domain::interval_empty",
            || expect_err!(Interval::try_new(1.0, 1.0), Error::EmptyInterval { start, end, .. } if *start == 1.0 && *end == 1.0),
        ),
        case("domain::interval_decreasing", || {
            expect_err!(Interval::try_new(2.0, 1.0), Error::EmptyInterval { .. })
        }),
        case(
            "domain::interval_width_overflows",
            || expect_err!(Interval::try_new(-1e308, 1e308), Error::Overflow { value, .. } if value.is_infinite()),
        ),
        case("domain::interval_subnormal_width", || {
            expect_err!(Interval::try_new(0.0, 1e-310), Error::GapTooSmall { .. })
        }),
        case("domain::interval_linspace_too_few", || {
            let i = ok(Interval::try_new(0.0, 1.0))?;
            expect_err!(i.linspace(1), Error::TooFewSamples { got: 1, .. })?;
            expect_err!(i.linspace(0), Error::TooFewSamples { got: 0, .. })
        }),
        risky("domain::interval_linspace_usize_max", || {
            let i = ok(Interval::try_new(0.0, 1.0))?;
            expect_err!(i.linspace(usize::MAX), Error::TooLarge { .. })
        }),
        risky("domain::interval_linspace_max_elements_plus_one", || {
            let i = ok(Interval::try_new(0.0, 1.0))?;
            expect_err!(i.linspace(MAX_ELEMENTS + 1), Error::TooLarge { got, .. } if *got == MAX_ELEMENTS + 1)
        }),
        case("domain::interval_linspace_ends_exact", || {
            let i = ok(Interval::try_new(0.1, 0.7))?;
            let v = ok(i.linspace(8))?;
            ensure!(v[0] == 0.1 && v[7] == 0.7, "ends not exact: {v:?}");
            Ok(())
        }),
        case("domain::rect_nan_bound", || {
            expect_err!(
                Rect::try_new(0.0, 1.0, f64::NAN, 1.0),
                Error::NonFinite { .. }
            )
        }),
        case(
            "domain::rect_empty_t_side",
            || expect_err!(Rect::try_new(0.0, 1.0, 2.0, 1.0), Error::EmptyInterval { what, .. } if what.contains('t')),
        ),
        case("domain::rect_width_overflows", || {
            expect_err!(
                Rect::try_new(-1e308, 1e308, 0.0, 1.0),
                Error::Overflow { .. }
            )
        }),
        case("domain::rect_square_infinite", || {
            expect_err!(Rect::square(0.0, f64::INFINITY), Error::NonFinite { .. })
        }),
        case("domain::partition_empty", || {
            expect_err!(
                Partition::try_new(vec![]),
                Error::PartitionTooShort { got: 0, .. }
            )
        }),
        case("domain::partition_single_node", || {
            expect_err!(
                Partition::try_new(vec![0.5]),
                Error::PartitionTooShort { got: 1, .. }
            )
        }),
        case("domain::partition_nan_node", || {
            expect_err!(
                Partition::try_new(vec![0.0, f64::NAN, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("domain::partition_inf_node", || {
            expect_err!(
                Partition::try_new(vec![0.0, 1.0, f64::INFINITY]),
                Error::NonFinite { .. }
            )
        }),
        case("domain::partition_repeated_node", || {
            expect_err!(
                Partition::try_new(vec![0.0, 0.5, 0.5, 1.0]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("domain::partition_decreasing", || {
            expect_err!(
                Partition::try_new(vec![0.0, 1.0, 0.9]),
                Error::NotIncreasing { index: 2, .. }
            )
        }),
        case("domain::partition_subnormal_gap", || {
            expect_err!(
                Partition::try_new(vec![0.0, 1e-310, 1.0]),
                Error::GapTooSmall { index: 1, .. }
            )
        }),
        case("domain::partition_total_width_overflows", || {
            expect_err!(
                Partition::try_new(vec![-1e308, 0.0, 1e308]),
                Error::Overflow { .. }
            )
        }),
        case("domain::partition_uniform_zero", || {
            expect_err!(Partition::uniform(0.0, 1.0, 0), Error::ZeroPatches { .. })
        }),
        risky("domain::partition_uniform_usize_max", || {
            expect_err!(
                Partition::uniform(0.0, 1.0, usize::MAX),
                Error::TooLarge { .. }
            )
        }),
        risky("domain::partition_uniform_max_elements", || {
            expect_err!(
                Partition::uniform(0.0, 1.0, MAX_ELEMENTS),
                Error::TooLarge { .. }
            )
        }),
        case("domain::partition_uniform_unresolvable_width", || {
            expect_err!(
                Partition::uniform(1.0, 1.0 + f64::EPSILON, 4),
                Error::RepeatedParameter { .. }
                    | Error::NotIncreasing { .. }
                    | Error::GapTooSmall { .. }
            )
        }),
        case("domain::partition_uniform_subnormal_steps", || {
            expect_err!(
                Partition::uniform(0.0, 1e-307, 1000),
                Error::RepeatedParameter { .. }
                    | Error::NotIncreasing { .. }
                    | Error::GapTooSmall { .. }
            )
        }),
        case("domain::partition_uniform_width_overflows", || {
            expect_err!(Partition::uniform(-1e308, 1e308, 2), Error::Overflow { .. })
        }),
        case("domain::partition_uniform_nan", || {
            expect_err!(
                Partition::uniform(f64::NAN, 1.0, 3),
                Error::NonFinite { .. }
            )
        }),
        case("domain::partition_right_end_in_last_piece", || {
            let p = ok(Partition::try_new(vec![0.0, 0.5, 1.0]))?;
            ensure!(p.locate(1.0) == 1, "right end in piece {}", p.locate(1.0));
            ensure!(
                p.locate(0.5) == 1,
                "interior node in piece {}",
                p.locate(0.5)
            );
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// grid
// ---------------------------------------------------------------------------------------------

fn grid_cases() -> Vec<Case> {
    vec![
        risky("grid::try_from_fn_usize_max", || {
            expect_err!(
                Grid::try_from_fn(usize::MAX, 2, |_, _| -> u8 {
                    panic!("f must not be called")
                }),
                Error::TooLarge { .. }
            )
        }),
        risky("grid::try_from_fn_max_elements_plus_one", || {
            expect_err!(
                Grid::try_from_fn(MAX_ELEMENTS + 1, 1, |_, _| -> u8 { panic!("f must not be called") }),
                Error::TooLarge { got, .. } if *got == MAX_ELEMENTS + 1
            )
        }),
        risky("grid::try_from_fn_2_pow_40", || {
            expect_err!(
                Grid::try_from_fn(1 << 20, 1 << 20, |_, _| -> u8 {
                    panic!("f must not be called")
                }),
                Error::TooLarge { .. }
            )
        }),
        case("grid::from_vec_wrapping_shape", || {
            // 2³² · 2³² wraps to 0 = the length of an empty vector
            let g = Grid::<u8>::from_vec(1 << 32, 1 << 32, Vec::new());
            ensure!(g.is_none(), "a wrapping shape was accepted");
            let g = Grid::<u8>::from_vec(usize::MAX, 2, vec![0; 6]);
            ensure!(g.is_none(), "an overflowing shape was accepted");
            Ok(())
        }),
        case("grid::from_vec_length_mismatch", || {
            ensure!(
                Grid::from_vec(2, 2, vec![1u8; 3]).is_none(),
                "3 values for 2×2 accepted"
            );
            ensure!(
                Grid::from_vec(2, 2, vec![1u8; 4]).is_some(),
                "4 values for 2×2 refused"
            );
            Ok(())
        }),
        case("grid::try_from_fn_zero_rows", || {
            let g = ok(Grid::try_from_fn(0, 5, |_, _| -> u8 {
                panic!("f must not be called")
            }))?;
            ensure!(g.rows() == 0 && g.as_slice().is_empty(), "not empty");
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// surface: Torus, Sphere, FnSurface, tabulate, partials_on_grid(_into)
// ---------------------------------------------------------------------------------------------

fn surface_cases() -> Vec<Case> {
    vec![
        case(
            "surface::torus_zero_major",
            || expect_err!(Torus::try_new(0.0, 1.0), Error::NotPositive { value, .. } if *value == 0.0),
        ),
        case(
            "surface::torus_negative_minor",
            || expect_err!(Torus::try_new(2.0, -1.0), Error::NotPositive { value, .. } if *value == -1.0),
        ),
        case("surface::torus_nan_major", || {
            expect_err!(Torus::try_new(f64::NAN, 1.0), Error::NotPositive { .. })
        }),
        case("surface::torus_inf_major", || {
            expect_err!(
                Torus::try_new(f64::INFINITY, 1.0),
                Error::NotPositive { .. }
            )
        }),
        case("surface::torus_neg_inf_minor", || {
            expect_err!(
                Torus::try_new(2.0, f64::NEG_INFINITY),
                Error::NotPositive { .. }
            )
        }),
        case("surface::torus_radii_1e308_sum_overflows", || {
            // R + r = inf from finite radii: a derived quantity, not a non-finite input
            expect_err!(
                Torus::try_new(1e308, 1e308),
                Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
            )
        }),
        case("surface::torus_radii_beyond_max_coordinate", || {
            expect_err!(
                Torus::try_new(2e306, 1e306),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("surface::torus_near_limit_partials_finite", || {
            let t = ok(Torus::try_new(1.3e306, 1.3e306))?;
            for (s, u) in [(0.0, 0.0), (0.3, 2.1), (1.0, 1.0), (6.0, 3.0)] {
                let p = t.partials(s, u);
                ensure!(
                    finite_vecs(&[p.point, p.ds, p.dt, p.dst]),
                    "partials at ({s}, {u}) not finite: {p:?}"
                );
            }
            Ok(())
        }),
        case("surface::sphere_zero_radius", || {
            expect_err!(Sphere::try_new(0.0), Error::NotPositive { .. })
        }),
        case("surface::sphere_nan_radius", || {
            expect_err!(Sphere::try_new(f64::NAN), Error::NotPositive { .. })
        }),
        case("surface::sphere_neg_inf_radius", || {
            expect_err!(
                Sphere::try_new(f64::NEG_INFINITY),
                Error::NotPositive { .. }
            )
        }),
        case("surface::sphere_radius_1e308", || {
            expect_err!(Sphere::try_new(1e308), Error::CoordinateTooLarge { .. })
        }),
        case("surface::tabulate_one_sample", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 1, 5),
                Error::TooFewSamples { got: 1, .. }
            )
        }),
        case("surface::tabulate_zero_samples", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 5, 0),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("surface::tabulate_100000_squared", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 100_000, 100_000),
                Error::TooLarge { .. }
            )
        }),
        risky("surface::tabulate_usize_max", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), usize::MAX, 2),
                Error::TooLarge { .. }
            )
        }),
        case("surface::tabulate_fn_surface_nan", || {
            let nan =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * f64::NAN));
            expect_err!(
                tabulate(&nan, &Rect::unit(), 3, 3),
                Error::NonFiniteSurface { .. }
            )
        }),
        case("surface::tabulate_fn_surface_1e308_times_s", || {
            let big =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s * 1e308, t, t));
            let rect = ok(Rect::try_new(0.0, 2.0, 0.0, 1.0))?;
            expect_err!(
                tabulate(&big, &rect, 3, 2),
                Error::NonFiniteSurface { s, .. } if *s == 2.0
            )
        }),
        case("surface::partials_on_grid_nan_at_one_node", || {
            let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                let bad = if s.re > 0.4 && s.re < 0.6 && t.re == 0.0 {
                    f64::NAN
                } else {
                    1.0
                };
                Vector3::new(s * bad, t, s * t)
            });
            expect_err!(
                partials_on_grid(&spot, &[0.0, 0.5, 1.0], &[0.0, 1.0]),
                Error::NonFiniteSurface { s, t } if *s == 0.5 && *t == 0.0
            )
        }),
        case("surface::partials_on_grid_nan_parameter", || {
            expect_err!(
                partials_on_grid(&Torus::default(), &[f64::NAN], &[0.0]),
                Error::NonFiniteSurface { .. }
            )
        }),
        case(
            "surface::partials_on_grid_into_inf_parameter_reused_buffer",
            || {
                let mut out = vec![partials(7.0, 7.0, 7.0, 7.0); 10];
                expect_err!(
                    partials_on_grid_into(
                        &Torus::default(),
                        &[0.0, f64::INFINITY],
                        &[0.0, 1.0],
                        &mut out
                    ),
                    Error::NonFiniteSurface { .. }
                )
            },
        ),
        case("surface::partials_on_grid_fn_surface_overflow", || {
            let big =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s * s * 1e308, t, t));
            // at s = 2 the point is 4e308 = inf
            expect_err!(
                partials_on_grid(&big, &[0.0, 2.0], &[0.0]),
                Error::NonFiniteSurface { s, .. } if *s == 2.0
            )
        }),
        case("surface::partials_on_grid_empty_nodes", || {
            let g = ok(partials_on_grid(&Torus::default(), &[], &[0.0, 1.0]))?;
            ensure!(g.as_slice().is_empty(), "cells for no nodes");
            let g = ok(partials_on_grid(&Torus::default(), &[0.0, 1.0], &[]))?;
            ensure!(g.as_slice().is_empty(), "cells for no nodes");
            Ok(())
        }),
        risky("surface::partials_on_grid_too_many_nodes", || {
            let s = vec![0.0; 1 << 14];
            let t = vec![0.0; 1 << 14];
            expect_err!(
                partials_on_grid(&Torus::default(), &s, &t),
                Error::TooLarge { .. }
            )
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// hermite: hermite_basis, HermitePatch, HermiteSurface
// ---------------------------------------------------------------------------------------------

fn hermite_cases() -> Vec<Case> {
    vec![
        case("hermite::basis_documented_values", || {
            ensure!(
                hermite_basis(0.5_f64) == [0.5, 0.125, -0.125, 0.5],
                "H(0.5) = {:?}",
                hermite_basis(0.5_f64)
            );
            for k in 0..=20 {
                let t = k as f64 / 20.0;
                let h = hermite_basis(t);
                ensure!(h.iter().all(|x| x.is_finite()), "H({t}) not finite");
                ensure!(
                    (h[0] + h[3] - 1.0).abs() <= 4.0 * f64::EPSILON,
                    "H0 + H3 ≠ 1 at {t}"
                );
            }
            Ok(())
        }),
        case("hermite::patch_matrix_nan", || {
            let mut c = unit_net();
            c[1][2].y = f64::NAN;
            expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { value, .. } if value.is_nan())
        }),
        case("hermite::patch_matrix_inf", || {
            let mut c = unit_net();
            c[3][3].z = f64::INFINITY;
            expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { .. })
        }),
        case("hermite::patch_matrix_neg_inf", || {
            let mut c = unit_net();
            c[0][0].x = f64::NEG_INFINITY;
            expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { .. })
        }),
        case("hermite::patch_matrix_f64_max", || {
            let mut c = unit_net();
            c[2][1].x = f64::MAX;
            expect_err!(
                HermitePatch::try_from_matrix(c),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case(
            "hermite::patch_matrix_at_hermite_limit_tabulates_finitely",
            || {
                let p = ok(HermitePatch::try_from_matrix(alternating_net(
                    HERMITE_LIMIT,
                )))?;
                let g = ok(p.tabulate(21, 21))?;
                ensure!(finite_grid(&g), "tabulation of a valid matrix not finite");
                let x = p.eval(0.37_f64, 0.81_f64);
                ensure!(finite_vecs(&[x]), "eval not finite: {x:?}");
                Ok(())
            },
        ),
        case("hermite::corners_zero_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(HermitePatch::try_from_corners(&c, 0.0, 1.0), Error::NotPositive { value, .. } if *value == 0.0)
        }),
        case("hermite::corners_negative_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, -0.5),
                Error::NotPositive { .. }
            )
        }),
        case("hermite::corners_nan_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, f64::NAN, 1.0),
                Error::NotPositive { .. }
            )
        }),
        case("hermite::corners_inf_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, f64::INFINITY),
                Error::NotPositive { .. }
            )
        }),
        case("hermite::corners_nan_datum", || {
            let mut c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            c[1][0].dt.y = f64::NAN;
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, 1.0),
                Error::NonFinite { .. }
            )
        }),
        case("hermite::corners_inf_datum", || {
            let mut c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            c[0][1].point.x = f64::INFINITY;
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, 1.0),
                Error::NonFinite { .. }
            )
        }),
        case("hermite::corners_datum_beyond_max_coordinate", || {
            let mut c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            c[1][1].point.z = 1e307;
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, 1.0),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("hermite::corners_scaled_beyond_max_coordinate", || {
            // X_s = 1e300 times Δu = 1e7: 1e307 > MAX_COORDINATE, finite
            let c = [[partials(1.0, 1e300, 1.0, 0.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1e7, 1.0),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("hermite::corners_scaled_overflows_to_inf", || {
            // X_s = 1e300 times Δu = 1e10 = inf: derived from finite data
            let c = [[partials(1.0, 1e300, 1.0, 0.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1e10, 1.0),
                Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
            )
        }),
        case(
            "hermite::corners_width_product_overflows_zero_twist",
            || {
                // Δu Δv = 1e400 overflows; the twist is 0, so the true entry is 0
                let c = [[partials(1.0, 0.0, 0.0, 0.0); 2]; 2];
                match HermitePatch::try_from_corners(&c, 1e200, 1e200) {
                    Ok(p) => {
                        let m = p.matrix();
                        ensure!(
                            m.iter().flatten().all(|v| v.iter().all(|x| x.is_finite())),
                            "Ok matrix with a non-finite entry: {m:?}"
                        );
                        ensure!(
                            m[1][1] == Vector3::zeros(),
                            "twist entry {:?}, expected 0",
                            m[1][1]
                        );
                        Ok(())
                    }
                    Err(Error::Overflow { .. } | Error::CoordinateTooLarge { .. }) => Ok(()),
                    Err(e) => Err(format!("misleading error for finite data: {e:?} «{e}»")),
                }
            },
        ),
        case(
            "hermite::corners_width_product_overflows_unit_twist",
            || {
                let c = [[partials(1.0, 0.0, 0.0, 1.0); 2]; 2];
                expect_err!(
                    HermitePatch::try_from_corners(&c, 1e200, 1e200),
                    Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
                )
            },
        ),
        case("hermite::patch_from_surface_nan", || {
            let nan =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, (s - 1.0).ln()));
            // ln(0) at s = 1 is −inf; ln of a negative number at s = 0 is NaN
            expect_err!(
                HermitePatch::try_from_surface(&nan, &Rect::unit()),
                Error::NonFiniteSurface { .. }
            )
        }),
        case("hermite::patch_from_surface_1e308_times_s", || {
            let big =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s * 1e308, t, t));
            expect_err!(
                HermitePatch::try_from_surface(&big, &Rect::unit()),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("hermite::patch_from_surface_huge_rect", || {
            // widths 1e300: X_s Δu fits, X_st Δu Δv does not
            let rect = ok(Rect::try_new(0.0, 1e300, 0.0, 1e300))?;
            expect_err!(
                HermitePatch::try_from_surface(&Torus::default(), &rect),
                Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
            )
        }),
        case("hermite::patch_tabulate_too_few", || {
            let p = ok(HermitePatch::try_from_matrix(unit_net()))?;
            expect_err!(p.tabulate(1, 5), Error::TooFewSamples { got: 1, .. })?;
            expect_err!(p.tabulate(0, 0), Error::TooFewSamples { got: 0, .. })
        }),
        risky("hermite::patch_tabulate_100000_squared", || {
            let p = ok(HermitePatch::try_from_matrix(unit_net()))?;
            expect_err!(p.tabulate(100_000, 100_000), Error::TooLarge { .. })
        }),
        risky("hermite::patch_tabulate_usize_max", || {
            let p = ok(HermitePatch::try_from_matrix(unit_net()))?;
            expect_err!(p.tabulate(usize::MAX, usize::MAX), Error::TooLarge { .. })?;
            expect_err!(p.tabulate(usize::MAX, 2), Error::TooLarge { .. })
        }),
        case("hermite::spline_from_surface_nan_node", || {
            let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                let bad = if s.re > 0.4 && s.re < 0.6 {
                    f64::NAN
                } else {
                    1.0
                };
                Vector3::new(s * bad, t, s * t)
            });
            let u = ok(Partition::try_new(vec![0.0, 0.5, 1.0]))?;
            let v = ok(Partition::try_new(vec![0.0, 1.0]))?;
            expect_err!(
                HermiteSurface::try_from_surface(&spot, u, v),
                Error::NonFiniteSurface { s, t } if *s == 0.5 && *t == 0.0
            )
        }),
        case("hermite::spline_node_partials_shape_mismatch", || {
            let nodes =
                Grid::from_vec(2, 2, vec![partials(0.0, 1.0, 1.0, 0.0); 4]).ok_or("grid")?;
            let u = ok(Partition::try_new(vec![0.0, 0.5, 1.0]))?;
            let v = ok(Partition::try_new(vec![0.0, 1.0]))?;
            expect_err!(
                HermiteSurface::try_from_node_partials(&nodes, u, v),
                Error::ShapeMismatch {
                    left_rows: 2,
                    left_cols: 2,
                    right_rows: 3,
                    right_cols: 2
                }
            )
        }),
        case("hermite::spline_node_partials_nan", || {
            let mut data = vec![partials(0.0, 1.0, 1.0, 0.0); 9];
            data[4].dst.x = f64::NAN;
            let nodes = Grid::from_vec(3, 3, data).ok_or("grid")?;
            let u = ok(Partition::uniform(0.0, 1.0, 2))?;
            let v = ok(Partition::uniform(0.0, 1.0, 2))?;
            expect_err!(
                HermiteSurface::try_from_node_partials(&nodes, u, v),
                Error::NonFinite { .. }
            )
        }),
        case(
            "hermite::spline_node_partials_at_max_coordinate_tabulate_finitely",
            || {
                let data: Vec<Partials> = (0..9)
                    .map(|k| {
                        let s = if k % 2 == 0 {
                            MAX_COORDINATE
                        } else {
                            -MAX_COORDINATE
                        };
                        partials(s, -s, s, -s)
                    })
                    .collect();
                let nodes = Grid::from_vec(3, 3, data).ok_or("grid")?;
                let u = ok(Partition::try_new(vec![0.0, 0.25, 1.0]))?;
                let v = ok(Partition::try_new(vec![0.0, 0.75, 1.0]))?;
                let sp = ok(HermiteSurface::try_from_node_partials(&nodes, u, v))?;
                let xs = linspace(0.0, 1.0, 41);
                let g = ok(sp.tabulate(&xs, &xs))?;
                ensure!(finite_grid(&g), "tabulation of a valid spline not finite");
                Ok(())
            },
        ),
        case("hermite::spline_uniform_zero_patches", || {
            expect_err!(
                HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 0, 3),
                Error::ZeroPatches { .. }
            )
        }),
        risky("hermite::spline_uniform_1e6_squared_patches", || {
            expect_err!(
                HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 1_000_000, 1_000_000),
                Error::TooLarge { .. }
            )
        }),
        risky("hermite::spline_uniform_usize_max_patches", || {
            expect_err!(
                HermiteSurface::uniform(&Torus::default(), &Rect::unit(), usize::MAX, 1),
                Error::TooLarge { .. }
            )
        }),
        case("hermite::spline_try_point_nan", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            expect_err!(sp.try_point(f64::NAN, 0.5), Error::NonFinite { .. })?;
            expect_err!(sp.try_point(0.5, f64::INFINITY), Error::NonFinite { .. })
        }),
        case("hermite::spline_try_point_out_of_domain", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            expect_err!(sp.try_point(1.0 + 1e-12, 0.5), Error::OutOfDomain { value, .. } if *value == 1.0 + 1e-12)?;
            expect_err!(sp.try_point(0.5, -0.1), Error::OutOfDomain { .. })
        }),
        case("hermite::spline_right_end_is_left_limit", || {
            let torus = Torus::default();
            let sp = ok(HermiteSurface::uniform(&torus, &Rect::unit(), 2, 2))?;
            let p = ok(sp.try_point(1.0, 1.0))?;
            let last = sp.patch(1, 1).eval(1.0_f64, 1.0_f64);
            ensure!(p == last, "right end {p:?} vs last patch {last:?}");
            let exact = torus.point(1.0, 1.0);
            ensure!(
                (p - exact).amax() < 1e-13,
                "corner not interpolated: {p:?} vs {exact:?}"
            );
            Ok(())
        }),
        case("hermite::spline_tabulate_bad_samples", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            expect_err!(
                sp.tabulate(&[0.0, f64::NAN], &[0.5]),
                Error::NonFinite { .. }
            )?;
            expect_err!(sp.tabulate(&[0.5], &[0.0, 2.0]), Error::OutOfDomain { value, .. } if *value == 2.0)
        }),
        risky("hermite::spline_tabulate_too_many_samples", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            let xs = vec![0.5; 1 << 14];
            expect_err!(sp.tabulate(&xs, &xs), Error::TooLarge { .. })
        }),
        case(
            "hermite::spline_torus_near_max_coordinate_evaluates_finitely",
            || {
                let torus = ok(Torus::try_new(1.3e306, 1.3e306))?;
                let sp = ok(HermiteSurface::uniform(&torus, &Rect::unit(), 2, 2))?;
                let xs = linspace(0.0, 1.0, 21);
                let g = ok(sp.tabulate(&xs, &xs))?;
                ensure!(finite_grid(&g), "tabulation not finite");
                Ok(())
            },
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// bezier
// ---------------------------------------------------------------------------------------------

fn bezier_cases() -> Vec<Case> {
    vec![
        case("bezier::bernstein_all_sums_to_one", || {
            let b = ok(bernstein_all(50, 0.3_f64))?;
            ensure!(b.len() == 51, "{} values", b.len());
            ensure!(
                b.iter().all(|x| x.is_finite() && *x >= 0.0),
                "negative or non-finite value"
            );
            let sum: f64 = b.iter().sum();
            ensure!((sum - 1.0).abs() < 1e-13, "sum {sum}");
            ensure!(
                ok(bernstein_all(0, 0.7_f64))? == vec![1.0],
                "degree 0 is not [1]"
            );
            Ok(())
        }),
        risky("bezier::bernstein_all_usize_max", || {
            expect_err!(bernstein_all(usize::MAX, 0.5_f64), Error::TooLarge { .. })
        }),
        risky("bezier::bernstein_all_above_max_degree", || {
            let n = splinelab::bezier::bernstein::MAX_BERNSTEIN_DEGREE + 1;
            expect_err!(bernstein_all(n, 0.5_f64), Error::TooLarge { .. })
        }),
        case("bezier::bernstein_sum_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                bernstein_sum(&none, 0.5_f64),
                Error::TooFewPoints {
                    needed: 1,
                    got: 0,
                    ..
                }
            )
        }),
        risky("bezier::bernstein_sum_too_many_points", || {
            let pts = vec![1.0_f64; 1 << 15];
            expect_err!(bernstein_sum(&pts, 0.5_f64), Error::TooLarge { .. })
        }),
        case("bezier::sums_of_points_at_max_coordinate_finite", || {
            let pts = alternating_points(6, MAX_COORDINATE);
            for k in 0..=20 {
                let u = k as f64 / 20.0;
                let a = ok(bernstein_sum(&pts, u))?;
                let b = ok(de_casteljau(&pts, u))?;
                ensure!(finite_vecs(&[a, b]), "u = {u}: {a:?} {b:?}");
            }
            Ok(())
        }),
        case("bezier::points_1e308_apart_finite", || {
            let pts = [v2(-1e308, 1e308), v2(1e308, -1e308)];
            let a = ok(bernstein_sum(&pts, 0.5_f64))?;
            let b = ok(de_casteljau(&pts, 0.5_f64))?;
            ensure!(finite_vecs(&[a, b]), "{a:?} {b:?}");
            Ok(())
        }),
        case("bezier::de_casteljau_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                de_casteljau(&none, 0.5_f64),
                Error::TooFewPoints { got: 0, .. }
            )
        }),
        case("bezier::de_casteljau_single_point", || {
            let p = ok(de_casteljau(&[v2(3.0, 4.0)], 0.3_f64))?;
            ensure!(p == v2(3.0, 4.0), "{p:?}");
            Ok(())
        }),
        case("bezier::de_casteljau_recursive_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                de_casteljau_recursive(&none, 0.5_f64),
                Error::TooFewPoints { got: 0, .. }
            )
        }),
        case("bezier::de_casteljau_recursive_single_point", || {
            expect_err!(
                de_casteljau_recursive(&[v2(1.0, 1.0)], 0.5_f64),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        risky("bezier::de_casteljau_recursive_25_points", || {
            let pts = some_points(25);
            expect_err!(
                de_casteljau_recursive(&pts, 0.5_f64),
                Error::TooLarge { got: 25, .. }
            )
        }),
        risky("bezier::de_casteljau_recursive_1e6_points", || {
            let pts = vec![1.0_f64; 1_000_000];
            expect_err!(
                de_casteljau_recursive(&pts, 0.5_f64),
                Error::TooLarge { got: 1_000_000, .. }
            )
        }),
        case(
            "bezier::de_casteljau_recursive_18_points_matches_iterative",
            || {
                let pts = some_points(18);
                let a = ok(de_casteljau_recursive(&pts, 0.3_f64))?;
                let b = ok(de_casteljau(&pts, 0.3_f64))?;
                ensure!((a - b).amax() < 1e-12, "{a:?} vs {b:?}");
                Ok(())
            },
        ),
        case("bezier::de_casteljau_levels_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                de_casteljau_levels(&none, 0.5_f64),
                Error::TooFewPoints { .. }
            )
        }),
        case("bezier::de_casteljau_levels_single_point", || {
            let l = ok(de_casteljau_levels(&[v2(1.0, 2.0)], 0.5_f64))?;
            ensure!(l == vec![vec![v2(1.0, 2.0)]], "{l:?}");
            Ok(())
        }),
        risky("bezier::de_casteljau_levels_too_many_points", || {
            let pts = vec![1.0_f64; 20_000];
            expect_err!(de_casteljau_levels(&pts, 0.5_f64), Error::TooLarge { .. })
        }),
        case("bezier::de_casteljau_surface_empty_net", || {
            let empty: Grid<Vector3<f64>> = Grid::from_vec(0, 0, vec![]).ok_or("grid")?;
            expect_err!(
                de_casteljau_surface(&empty, 0.5_f64, 0.5_f64),
                Error::TooFewPoints { .. }
            )?;
            let no_cols: Grid<Vector3<f64>> = Grid::from_vec(3, 0, vec![]).ok_or("grid")?;
            expect_err!(
                de_casteljau_surface(&no_cols, 0.5_f64, 0.5_f64),
                Error::TooFewPoints { .. }
            )
        }),
        case("bezier::de_casteljau_surface_single_point", || {
            let one = Grid::from_vec(1, 1, vec![v3(1.0, 2.0, 3.0)]).ok_or("grid")?;
            let p = ok(de_casteljau_surface(&one, 0.2_f64, 0.9_f64))?;
            ensure!(p == v3(1.0, 2.0, 3.0), "{p:?}");
            Ok(())
        }),
        case("bezier::patch_net_nan", || {
            let mut m = unit_net();
            m[0][3].y = f64::NAN;
            expect_err!(BezierPatch::try_from_net(m), Error::NonFinite { .. })
        }),
        case("bezier::patch_net_inf", || {
            let mut m = unit_net();
            m[2][2].x = f64::NEG_INFINITY;
            expect_err!(BezierPatch::try_from_net(m), Error::NonFinite { .. })
        }),
        case("bezier::patch_net_f64_max", || {
            let mut m = unit_net();
            m[1][1].z = -f64::MAX;
            expect_err!(
                BezierPatch::try_from_net(m),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("bezier::patch_tabulate_too_few", || {
            let p = ok(BezierPatch::try_from_net(unit_net()))?;
            expect_err!(
                p.tabulate_de_casteljau(1, 2),
                Error::TooFewSamples { got: 1, .. }
            )?;
            expect_err!(
                p.tabulate_bernstein(5, 0),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("bezier::patch_tabulate_100000_squared", || {
            let p = ok(BezierPatch::try_from_net(unit_net()))?;
            expect_err!(
                p.tabulate_de_casteljau(100_000, 100_000),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                p.tabulate_bernstein(100_000, 100_000),
                Error::TooLarge { .. }
            )
        }),
        risky("bezier::patch_tabulate_usize_max", || {
            let p = ok(BezierPatch::try_from_net(unit_net()))?;
            expect_err!(
                p.tabulate_de_casteljau(usize::MAX, 3),
                Error::TooLarge { .. }
            )?;
            expect_err!(p.tabulate_bernstein(3, usize::MAX), Error::TooLarge { .. })
        }),
        case("bezier::patch_at_net_limit_tabulates_finitely", || {
            let p = ok(BezierPatch::try_from_net(alternating_net(NET_LIMIT)))?;
            ensure!(
                finite_grid(&ok(p.tabulate_de_casteljau(17, 17))?),
                "de Casteljau not finite"
            );
            ensure!(
                finite_grid(&ok(p.tabulate_bernstein(17, 17))?),
                "Bernstein not finite"
            );
            Ok(())
        }),
        case("bezier::from_hermite_at_hermite_limit_finite", || {
            let h = ok(HermitePatch::try_from_matrix(alternating_net(
                HERMITE_LIMIT,
            )))?;
            let b = BezierPatch::from_hermite(&h);
            // the printed Codice 7 net of the same matrix is a valid net too
            let _ = splinelab::report_codice7_net(&h);
            ensure!(
                b.net()
                    .iter()
                    .flatten()
                    .all(|v| v.iter().all(|x| x.is_finite())),
                "net not finite"
            );
            ensure!(
                finite_grid(&ok(b.tabulate_bernstein(9, 9))?),
                "tabulation not finite"
            );
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// bspline: KnotVector, BSplineBasis, BSplineCurve
// ---------------------------------------------------------------------------------------------

fn bspline_cases() -> Vec<Case> {
    vec![
        case("bspline::knots_empty", || {
            expect_err!(
                KnotVector::try_new(vec![]),
                Error::TooFewKnots { needed: 2, got: 0 }
            )
        }),
        case("bspline::knots_single", || {
            expect_err!(
                KnotVector::try_new(vec![1.0]),
                Error::TooFewKnots { got: 1, .. }
            )
        }),
        case("bspline::knots_nan", || {
            expect_err!(
                KnotVector::try_new(vec![0.0, f64::NAN, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("bspline::knots_inf", || {
            expect_err!(
                KnotVector::try_new(vec![0.0, 1.0, f64::INFINITY]),
                Error::NonFinite { .. }
            )
        }),
        case("bspline::knots_neg_inf", || {
            expect_err!(
                KnotVector::try_new(vec![f64::NEG_INFINITY, 0.0, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("bspline::knots_decreasing", || {
            expect_err!(
                KnotVector::try_new(vec![0.0, 1.0, 0.5]),
                Error::KnotsNotSorted { index: 2, value, prev } if *value == 0.5 && *prev == 1.0
            )
        }),
        case("bspline::knots_all_equal", || {
            expect_err!(
                KnotVector::try_new(vec![2.0; 5]),
                Error::EmptyInterval { .. }
            )
        }),
        case("bspline::knots_width_overflows", || {
            expect_err!(
                KnotVector::try_new(vec![-1e308, 0.0, 1e308]),
                Error::Overflow { .. }
            )
        }),
        case("bspline::knots_span_1e-310", || {
            expect_err!(
                KnotVector::try_new(vec![0.0, 0.0, 1e-310, 1.0, 1.0]),
                Error::GapTooSmall { index: 2, .. }
            )
        }),
        case("bspline::extended_partition_zero_order", || {
            expect_err!(
                KnotVector::extended_partition(0.0, 1.0, &[], &[], 0, EndKnots::Clamped),
                Error::ZeroOrder
            )
        }),
        case("bspline::extended_partition_count_mismatch", || {
            expect_err!(
                KnotVector::extended_partition(0.0, 1.0, &[0.5], &[1, 1], 3, EndKnots::Clamped),
                Error::CountMismatch {
                    expected: 1,
                    got: 2,
                    ..
                }
            )
        }),
        case("bspline::extended_partition_zero_multiplicity", || {
            expect_err!(
                KnotVector::extended_partition(0.0, 1.0, &[0.5], &[0], 3, EndKnots::Clamped),
                Error::MultiplicityTooHigh {
                    index: 0,
                    multiplicity: 0,
                    max: 3
                }
            )
        }),
        case(
            "bspline::extended_partition_multiplicity_above_order",
            || {
                expect_err!(
                    KnotVector::extended_partition(0.0, 1.0, &[0.5], &[5], 4, EndKnots::Clamped),
                    Error::MultiplicityTooHigh {
                        multiplicity: 5,
                        max: 4,
                        ..
                    }
                )
            },
        ),
        case("bspline::extended_partition_interior_outside", || {
            expect_err!(
                KnotVector::extended_partition(0.0, 1.0, &[1.5], &[1], 3, EndKnots::Clamped),
                Error::NotIncreasing { .. }
            )
        }),
        case("bspline::extended_partition_interior_nan", || {
            expect_err!(
                KnotVector::extended_partition(0.0, 1.0, &[f64::NAN], &[1], 3, EndKnots::Clamped),
                Error::NonFinite { .. }
            )
        }),
        case("bspline::extended_partition_empty_interval", || {
            expect_err!(
                KnotVector::extended_partition(1.0, 1.0, &[], &[], 3, EndKnots::Clamped),
                Error::EmptyInterval { .. }
            )
        }),
        case("bspline::extended_partition_bad_spacing", || {
            for h in [0.0, -0.25, f64::NAN, f64::INFINITY] {
                expect_err!(
                    KnotVector::extended_partition(0.0, 1.0, &[0.5], &[1], 4, EndKnots::Spaced(h)),
                    Error::NotPositive { .. }
                )
                .map_err(|e| format!("h = {h}: {e}"))?;
            }
            Ok(())
        }),
        case("bspline::extended_partition_spacing_overflows", || {
            // the outer knot 0 − 2·1e308 overflows
            expect_err!(
                KnotVector::extended_partition(0.0, 1.0, &[], &[], 4, EndKnots::Spaced(1e308)),
                Error::Overflow { .. }
            )
        }),
        risky("bspline::extended_partition_usize_max_order", || {
            expect_err!(
                KnotVector::extended_partition(
                    0.0,
                    1.0,
                    &[0.5],
                    &[1],
                    usize::MAX,
                    EndKnots::Clamped
                ),
                Error::TooLarge { .. }
            )
        }),
        risky("bspline::extended_partition_knot_count_too_large", || {
            expect_err!(
                KnotVector::extended_partition(
                    0.0,
                    1.0,
                    &[0.5],
                    &[MAX_ELEMENTS],
                    MAX_ELEMENTS,
                    EndKnots::Clamped
                ),
                Error::TooLarge { .. }
            )
        }),
        case("bspline::open_uniform_count_le_degree", || {
            expect_err!(
                KnotVector::open_uniform(3, 3, 0.0, 1.0),
                Error::TooFewPoints {
                    needed: 4,
                    got: 3,
                    ..
                }
            )
        }),
        risky("bspline::open_uniform_usize_max_degree", || {
            expect_err!(
                KnotVector::open_uniform(usize::MAX, 5, 0.0, 1.0),
                Error::TooLarge { .. }
            )
        }),
        risky("bspline::open_uniform_usize_max_count", || {
            expect_err!(
                KnotVector::open_uniform(3, usize::MAX, 0.0, 1.0),
                Error::TooLarge { .. }
            )
        }),
        risky("bspline::open_uniform_2_pow_40_count", || {
            expect_err!(
                KnotVector::open_uniform(2, 1 << 40, 0.0, 1.0),
                Error::TooLarge { .. }
            )
        }),
        case("bspline::open_uniform_nan_bound", || {
            expect_err!(
                KnotVector::open_uniform(2, 5, f64::NAN, 1.0),
                Error::NonFinite { .. }
            )
        }),
        case("bspline::open_uniform_empty_interval", || {
            expect_err!(
                KnotVector::open_uniform(2, 5, 1.0, 0.0),
                Error::EmptyInterval { .. }
            )
        }),
        case("bspline::open_uniform_unresolvable_width", || {
            expect_err!(
                KnotVector::open_uniform(1, 10, 1.0, 1.0 + 4.0 * f64::EPSILON),
                Error::RepeatedParameter { .. }
                    | Error::NotIncreasing { .. }
                    | Error::GapTooSmall { .. }
            )
        }),
        case("bspline::basis_too_few_knots", || {
            let k = ok(KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]))?;
            expect_err!(
                BSplineBasis::try_new(k, 2),
                Error::TooFewKnots { needed: 6, got: 4 }
            )
        }),
        case("bspline::basis_multiplicity_too_high", || {
            let k = ok(KnotVector::try_new(vec![
                0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0,
            ]))?;
            expect_err!(
                BSplineBasis::try_new(k, 2),
                Error::MultiplicityTooHigh {
                    index: 0,
                    multiplicity: 4,
                    max: 3
                }
            )
        }),
        case("bspline::basis_empty_domain", || {
            let k = ok(KnotVector::try_new(vec![0.0, 1.0, 1.0, 1.0, 2.0, 3.0]))?;
            expect_err!(BSplineBasis::try_new(k, 2), Error::EmptyInterval { .. })
        }),
        case("bspline::basis_usize_max_degree_message", || {
            let k = ok(KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]))?;
            let r = BSplineBasis::try_new(k, usize::MAX);
            let Err(e) = &r else {
                return Err(format!("expected an error, got {}", show(&r)));
            };
            let text = e.to_string();
            ensure!(!text.contains("1..=0"), "misleading message: {text}");
            ensure!(
                matches!(e, Error::TooLarge { .. } | Error::TooFewKnots { .. }),
                "expected TooLarge or TooFewKnots, got {e:?} «{text}»"
            );
            ensure!(
                text.contains("degree") || text.contains("knots"),
                "message does not name the cause: {text}"
            );
            Ok(())
        }),
        case("bspline::basis_half_usize_degree_message", || {
            let k = ok(KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]))?;
            let r = BSplineBasis::try_new(k, usize::MAX / 2);
            let Err(e) = &r else {
                return Err(format!("expected an error, got {}", show(&r)));
            };
            let text = e.to_string();
            ensure!(
                !text.contains("1..=0") && !text.contains("needed 0"),
                "misleading message: {text}"
            );
            ensure!(
                matches!(e, Error::TooLarge { .. } | Error::TooFewKnots { .. }),
                "expected TooLarge or TooFewKnots, got {e:?} «{text}»"
            );
            Ok(())
        }),
        case("bspline::basis_degree_max_elements_too_few_knots", || {
            let k = ok(KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]))?;
            expect_err!(
                BSplineBasis::try_new(k, MAX_ELEMENTS),
                Error::TooFewKnots { needed, got: 4 } if *needed == 2 * (MAX_ELEMENTS + 1)
            )
        }),
        risky("bspline::basis_derivatives_usize_max_order", || {
            let b = basis(2, 5)?;
            expect_err!(b.derivatives(0.5, usize::MAX), Error::TooLarge { .. })
        }),
        case("bspline::basis_derivatives_above_degree_are_zero", || {
            let b = basis(2, 5)?;
            let (_, d) = ok(b.derivatives(0.4, 5))?;
            ensure!(d.len() == 6, "{} rows", d.len());
            ensure!(
                d.iter().flatten().all(|x| x.is_finite()),
                "not finite: {d:?}"
            );
            ensure!(
                d[3..].iter().flatten().all(|x| *x == 0.0),
                "rows above the degree not zero: {d:?}"
            );
            Ok(())
        }),
        case("bspline::basis_right_end_is_left_limit", || {
            // knots (0,0,0,1,1,1,2), degree 2: domain [0, 1], b = 1 repeated without clamping
            let b = ok(BSplineBasis::try_new(
                ok(KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0]))?,
                2,
            ))?;
            ensure!(b.domain() == (0.0, 1.0), "domain {:?}", b.domain());
            let n = b.all(1.0_f64);
            let limit = [0.0, 0.0, 1.0, 0.0];
            ensure!(
                n.len() == 4 && n.iter().zip(limit).all(|(a, b)| (a - b).abs() <= 1e-15),
                "N(1) = {n:?}, left limit is (0, 0, 1, 0)"
            );
            let (span, d) = ok(b.derivatives(1.0, 2))?;
            ensure!(span == 2, "span {span}");
            let expect = [[0.0, 0.0, 1.0], [0.0, -2.0, 2.0], [2.0, -4.0, 2.0]];
            for k in 0..3 {
                for j in 0..3 {
                    ensure!(
                        (d[k][j] - expect[k][j]).abs() < 1e-12,
                        "N^({k})_{j}(1) = {}, left limit {}",
                        d[k][j],
                        expect[k][j]
                    );
                }
            }
            let pts = vec![v2(0.0, 0.0), v2(1.0, 2.0), v2(3.0, 1.0), v2(7.0, 7.0)];
            let c = ok(BSplineCurve::try_new(b, pts))?;
            let p = ok(c.try_point(1.0))?;
            ensure!(
                (p - v2(3.0, 1.0)).amax() < 1e-15,
                "C(1) = {p:?}, left limit (3, 1)"
            );
            let [_, d1, d2] = c.derivatives2(1.0);
            ensure!(
                (d1 - v2(4.0, -2.0)).amax() < 1e-12,
                "C'(1) = {d1:?}, left limit (4, −2)"
            );
            ensure!(
                (d2 - v2(2.0, -6.0)).amax() < 1e-12,
                "C''(1) = {d2:?}, left limit (2, −6)"
            );
            let mut out = Vec::new();
            c.eval_many(&[0.0, 0.5, 1.0], &mut out);
            ensure!(
                (out[2] - p).amax() < 1e-15,
                "eval_many(1) = {:?} vs point {p:?}",
                out[2]
            );
            Ok(())
        }),
        case("bspline::curve_count_mismatch", || {
            expect_err!(
                BSplineCurve::try_new(basis(2, 5)?, some_points(4)),
                Error::CountMismatch {
                    expected: 5,
                    got: 4,
                    ..
                }
            )
        }),
        case("bspline::curve_nan_point", || {
            let mut pts = some_points(5);
            pts[2].y = f64::NAN;
            expect_err!(
                BSplineCurve::try_new(basis(2, 5)?, pts),
                Error::NonFinite { .. }
            )
        }),
        case("bspline::curve_inf_point", || {
            let mut pts = some_points(5);
            pts[4].x = f64::INFINITY;
            expect_err!(
                BSplineCurve::try_new(basis(2, 5)?, pts),
                Error::NonFinite { .. }
            )
        }),
        case("bspline::curve_point_1e308", || {
            let mut pts = some_points(5);
            pts[0].x = 1e308;
            expect_err!(
                BSplineCurve::try_new(basis(2, 5)?, pts),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("bspline::curve_with_point_out_of_range", || {
            let c = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
            expect_err!(
                c.with_point(5, v2(0.0, 0.0)),
                Error::IndexOutOfRange {
                    index: 5,
                    len: 5,
                    ..
                }
            )?;
            expect_err!(
                c.with_point(usize::MAX, v2(0.0, 0.0)),
                Error::IndexOutOfRange { .. }
            )
        }),
        case("bspline::curve_with_point_nan", || {
            let c = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
            expect_err!(c.with_point(1, v2(f64::NAN, 0.0)), Error::NonFinite { .. })
        }),
        case("bspline::curve_try_point_bad_parameter", || {
            let c = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
            expect_err!(c.try_point(f64::NAN), Error::NonFinite { .. })?;
            expect_err!(c.try_point(f64::NEG_INFINITY), Error::NonFinite { .. })?;
            expect_err!(c.try_point(1.5), Error::OutOfDomain { value, .. } if *value == 1.5)
        }),
        case("bspline::curve_polyline_too_few", || {
            let c = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
            expect_err!(c.polyline(1), Error::TooFewSamples { got: 1, .. })?;
            expect_err!(c.polyline(0), Error::TooFewSamples { got: 0, .. })
        }),
        risky("bspline::curve_polyline_huge", || {
            let c = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
            expect_err!(c.polyline(usize::MAX), Error::TooLarge { .. })?;
            expect_err!(c.polyline(MAX_ELEMENTS + 1), Error::TooLarge { .. })
        }),
        case(
            "bspline::curve_near_max_coordinate_batch_equals_single",
            || {
                let pts = alternating_points(8, MAX_COORDINATE);
                let c = ok(BSplineCurve::try_new(basis(3, 8)?, pts))?;
                let ts = linspace(0.0, 1.0, 401);
                let mut out = Vec::new();
                c.eval_many(&ts, &mut out);
                ensure!(finite_vecs(&out), "eval_many not finite");
                for (t, q) in ts.iter().zip(&out) {
                    let p = c.point(*t);
                    ensure!(finite_vecs(&[p]), "point({t}) not finite");
                    ensure!(
                        (p - q).amax() <= 1e-12 * MAX_COORDINATE,
                        "t = {t}: {p:?} vs {q:?}"
                    );
                }
                ensure!(finite_vecs(&ok(c.polyline(101))?), "polyline not finite");
                Ok(())
            },
        ),
        case("bspline::curve_tiny_knot_span_evaluates_finitely", || {
            let k = ok(KnotVector::try_new(vec![
                0.0, 0.0, 0.0, 1e-307, 1.0, 1.0, 1.0,
            ]))?;
            let c = ok(BSplineCurve::try_new(
                ok(BSplineBasis::try_new(k, 2))?,
                some_points(4),
            ))?;
            let mut ts = linspace(0.0, 1.0, 101);
            ts.extend([5e-308, 1e-307, 2e-307]);
            ts.sort_by(f64::total_cmp);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            ensure!(finite_vecs(&out), "eval_many not finite: {out:?}");
            for (t, q) in ts.iter().zip(&out) {
                let p = ok(c.try_point(*t))?;
                ensure!((p - q).amax() <= 1e-12 * 10.0, "t = {t}: {p:?} vs {q:?}");
            }
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// nurbs
// ---------------------------------------------------------------------------------------------

fn nurbs_with(weights: Vec<f64>) -> Result<NurbsCurve<2>, Error> {
    let n = weights.len();
    let b = BSplineBasis::try_new(KnotVector::open_uniform(2, n, 0.0, 1.0)?, 2)?;
    NurbsCurve::try_new(b, some_points(n), weights)
}

fn nurbs_cases() -> Vec<Case> {
    vec![
        case("nurbs::point_count_mismatch", || {
            expect_err!(
                NurbsCurve::try_new(basis(2, 5)?, some_points(4), vec![1.0; 5]),
                Error::CountMismatch {
                    expected: 5,
                    got: 4,
                    ..
                }
            )
        }),
        case("nurbs::weight_count_mismatch", || {
            expect_err!(
                NurbsCurve::try_new(basis(2, 5)?, some_points(5), vec![1.0; 6]),
                Error::CountMismatch {
                    expected: 5,
                    got: 6,
                    ..
                }
            )
        }),
        case("nurbs::weight_zero", || {
            expect_err!(
                nurbs_with(vec![1.0, 0.0, 1.0, 1.0]),
                Error::NonPositiveWeight { index: 1, .. }
            )
        }),
        case("nurbs::weight_negative", || {
            expect_err!(
                nurbs_with(vec![1.0, 1.0, -2.0, 1.0]),
                Error::NonPositiveWeight { index: 2, .. }
            )
        }),
        case("nurbs::weight_nan", || {
            expect_err!(
                nurbs_with(vec![f64::NAN, 1.0, 1.0, 1.0]),
                Error::NonPositiveWeight { index: 0, .. }
            )
        }),
        case("nurbs::weight_inf", || {
            expect_err!(
                nurbs_with(vec![1.0, 1.0, 1.0, f64::INFINITY]),
                Error::NonPositiveWeight { index: 3, .. }
            )
        }),
        case("nurbs::weight_5e-324_beside_1", || {
            expect_err!(
                nurbs_with(vec![1.0, 5e-324, 1.0, 1.0]),
                Error::WeightRatio { index: 1, .. }
            )
        }),
        case("nurbs::weight_ratio_1e-300", || {
            expect_err!(
                nurbs_with(vec![1.0, 1.0, 1e-300, 1.0]),
                Error::WeightRatio { index: 2, .. }
            )
        }),
        case("nurbs::weights_1e308_and_1", || {
            expect_err!(
                nurbs_with(vec![1e308, 1.0, 1.0, 1e308]),
                Error::WeightRatio { .. }
            )
        }),
        case("nurbs::all_weights_subnormal_equal_bspline", || {
            let c = ok(nurbs_with(vec![5e-324; 5]))?;
            let b = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
            for t in linspace(0.0, 1.0, 51) {
                let (p, q) = (c.point(t), b.point(t));
                ensure!(finite_vecs(&[p]), "t = {t}: {p:?}");
                ensure!(
                    (p - q).amax() < 1e-12,
                    "t = {t}: NURBS {p:?} vs B-spline {q:?}"
                );
            }
            Ok(())
        }),
        case("nurbs::all_weights_f64_max_finite", || {
            let c = ok(nurbs_with(vec![f64::MAX; 5]))?;
            let mut out = Vec::new();
            c.eval_many(&linspace(0.0, 1.0, 51), &mut out);
            ensure!(finite_vecs(&out), "not finite: {out:?}");
            Ok(())
        }),
        case("nurbs::nan_point", || {
            let mut pts = some_points(5);
            pts[3].x = f64::NAN;
            expect_err!(
                NurbsCurve::try_new(basis(2, 5)?, pts, vec![1.0; 5]),
                Error::NonFinite { .. }
            )
        }),
        case("nurbs::point_1e308", || {
            let mut pts = some_points(5);
            pts[3].y = -1e308;
            expect_err!(
                NurbsCurve::try_new(basis(2, 5)?, pts, vec![1.0; 5]),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("nurbs::with_weight_out_of_range", || {
            let c = ok(nurbs_with(vec![1.0; 5]))?;
            expect_err!(
                c.with_weight(5, 1.0),
                Error::IndexOutOfRange {
                    index: 5,
                    len: 5,
                    ..
                }
            )
        }),
        case("nurbs::with_weight_nan", || {
            let c = ok(nurbs_with(vec![1.0; 5]))?;
            expect_err!(
                c.with_weight(2, f64::NAN),
                Error::NonPositiveWeight { index: 2, .. }
            )
        }),
        case("nurbs::with_weight_tiny_ratio", || {
            let c = ok(nurbs_with(vec![1.0; 5]))?;
            expect_err!(
                c.with_weight(2, 1e-300),
                Error::WeightRatio { index: 2, .. }
            )
        }),
        case("nurbs::weights_1_and_1e-15_batch_equals_single", || {
            let w = vec![1.0, 1e-15, 1.0, 1e-15, 1.0, 1e-15, 1.0];
            let b = ok(BSplineBasis::try_new(
                ok(KnotVector::open_uniform(3, 7, 0.0, 1.0))?,
                3,
            ))?;
            let pts = some_points(7);
            let scale = pts.iter().map(|p| p.amax()).fold(0.0, f64::max);
            let c = ok(NurbsCurve::try_new(b, pts, w))?;
            let ts = linspace(0.0, 1.0, 201);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (t, q) in ts.iter().zip(&out) {
                let p = c.point(*t);
                ensure!(finite_vecs(&[p, *q]), "t = {t}: {p:?} {q:?}");
                ensure!(
                    (p - q).amax() <= 1e-12 * scale,
                    "t = {t}: single {p:?} vs batch {q:?}"
                );
            }
            Ok(())
        }),
        case("nurbs::near_max_coordinate_batch_equals_single", || {
            let b = ok(BSplineBasis::try_new(
                ok(KnotVector::open_uniform(3, 8, 0.0, 1.0))?,
                3,
            ))?;
            let w = vec![1.0, 0.5, 2.0, 1.0, 3.0, 1.0, 0.25, 1.0];
            let c = ok(NurbsCurve::try_new(
                b,
                alternating_points(8, MAX_COORDINATE),
                w,
            ))?;
            let ts = linspace(0.0, 1.0, 201);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (t, q) in ts.iter().zip(&out) {
                let p = c.point(*t);
                ensure!(finite_vecs(&[p, *q]), "t = {t}: {p:?} {q:?}");
                ensure!(
                    (p - q).amax() <= 1e-12 * MAX_COORDINATE,
                    "t = {t}: {p:?} vs {q:?}"
                );
            }
            Ok(())
        }),
        case("nurbs::right_end_is_last_point", || {
            let c = ok(nurbs_with(vec![1.0, 2.0, 0.5, 1.0, 3.0]))?;
            let p = ok(c.try_point(1.0))?;
            let last = some_points(5)[4];
            ensure!((p - last).amax() < 1e-14, "C(1) = {p:?}, expected {last:?}");
            Ok(())
        }),
        case("nurbs::circle7_bad_radius", || {
            for r in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                expect_err!(
                    NurbsCurve::circle7(v2(0.0, 0.0), r),
                    Error::NotPositive { .. }
                )
                .map_err(|e| format!("r = {r}: {e}"))?;
            }
            Ok(())
        }),
        case("nurbs::circle9_bad_radius", || {
            for r in [0.0, -2.0, f64::NAN, f64::NEG_INFINITY] {
                expect_err!(
                    NurbsCurve::circle9(v2(0.0, 0.0), r),
                    Error::NotPositive { .. }
                )
                .map_err(|e| format!("r = {r}: {e}"))?;
            }
            Ok(())
        }),
        case("nurbs::circle9_nan_centre", || {
            expect_err!(
                NurbsCurve::circle9(v2(f64::NAN, 0.0), 1.0),
                Error::NonFinite { .. }
            )
        }),
        case("nurbs::circle7_inf_centre", || {
            expect_err!(
                NurbsCurve::circle7(v2(0.0, f64::INFINITY), 1.0),
                Error::NonFinite { .. }
            )
        }),
        case("nurbs::circle9_radius_1e308", || {
            // the square's corners lie at r·√2: beyond every limit
            expect_err!(
                NurbsCurve::circle9(v2(0.0, 0.0), 1e308),
                Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
            )
        }),
        case("nurbs::circle7_vertices_beyond_max_coordinate", || {
            // radius 2e306 is a valid coordinate; the triangle's vertices at 2r are not
            expect_err!(
                NurbsCurve::circle7(v2(0.0, 0.0), 2e306),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("nurbs::circle9_centre_1e308", || {
            expect_err!(
                NurbsCurve::circle9(v2(1e308, 0.0), 1.0),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("nurbs::circle9_near_limit_is_a_circle", || {
            let r = 1e306;
            let c = ok(NurbsCurve::circle9(v2(0.0, 0.0), r))?;
            let mut out = Vec::new();
            c.eval_many(&linspace(0.0, 1.0, 101), &mut out);
            for p in &out {
                ensure!(finite_vecs(&[*p]), "not finite: {p:?}");
                // |C| / r computed on C / r: the squares of 1e306 overflow
                let ratio = (p / r).norm();
                ensure!((ratio - 1.0).abs() < 1e-13, "|C| / r = {ratio}");
            }
            Ok(())
        }),
        case(
            "nurbs::circle9_subnormal_radius_is_a_circle_or_refused",
            || {
                let r = 1e-320;
                match NurbsCurve::circle9(v2(0.0, 0.0), r) {
                    Err(_) => Ok(()),
                    Ok(c) => {
                        for t in linspace(0.0, 1.0, 41) {
                            let p = c.point(t);
                            ensure!(finite_vecs(&[p]), "t = {t}: {p:?}");
                            // on C / r: the squares of 1e-320 underflow
                            let ratio = (p / r).norm();
                            ensure!(
                                (ratio - 1.0).abs() < 1e-9,
                                "t = {t}: |C| / r = {ratio} (an Ok circle off its radius)"
                            );
                        }
                        Ok(())
                    }
                }
            },
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// interp: polynomial, nodes, parametrization, piecewise linear, cubic, collocation
// ---------------------------------------------------------------------------------------------

/// The anticyclic data of the brief: an interval of 1e-8 at the end, `y = sin 2x`.
fn anticyclic_data() -> (Vec<f64>, Vec<f64>) {
    let x = vec![0.0, 0.25, 0.5, 0.5 + 1e-8];
    let y = x.iter().map(|v: &f64| (2.0 * v).sin()).collect();
    (x, y)
}

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

fn interp_cases() -> Vec<Case> {
    let mut cases = vec![
        case("interp::power_empty", || {
            expect_err!(
                PowerPolynomial::interpolate(&[], &[]),
                Error::TooFewPoints { got: 0, .. }
            )
        }),
        case("interp::power_count_mismatch", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0], &[1.0]),
                Error::CountMismatch {
                    expected: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::power_nan_node", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, f64::NAN], &[1.0, 2.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::power_inf_value", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0], &[1.0, f64::INFINITY]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::power_repeated_node", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0, 1.0], &[1.0, 2.0, 3.0]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::power_decreasing_nodes", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 2.0, 1.0], &[1.0, 2.0, 3.0]),
                Error::NotIncreasing { index: 2, .. }
            )
        }),
        case("interp::power_nodes_1e-310_apart", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1e-310], &[1.0, 2.0]),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::power_vandermonde_entry_overflows", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0, 1e200], &[1.0, 2.0, 3.0]),
                Error::Overflow { .. }
            )
        }),
        case("interp::power_single_point", || {
            let p = ok(PowerPolynomial::interpolate(&[0.5], &[3.0]))?;
            ensure!(
                p.eval(7.0_f64) == 3.0,
                "constant interpolant {}",
                p.eval(7.0_f64)
            );
            Ok(())
        }),
        case(
            "interp::power_30_equispaced_refused_or_interpolates",
            || {
                let x = linspace(0.0, 1.0, 30);
                let y: Vec<f64> = x.iter().map(|v| (3.0 * v).sin()).collect();
                match PowerPolynomial::interpolate(&x, &y) {
                    Err(Error::IllConditioned { .. } | Error::SingularSystem { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(p) => {
                        ensure!(
                            p.coefficients().iter().all(|c| c.is_finite()),
                            "non-finite coefficient"
                        );
                        check_interpolates(&x, &y, |t| p.eval(t))
                    }
                }
            },
        ),
        case("interp::power_values_f64_max", || {
            let x = [0.0, 1.0, 2.0, 3.0];
            let y = [f64::MAX, -f64::MAX, f64::MAX, -f64::MAX];
            match PowerPolynomial::interpolate(&x, &y) {
                Err(_) => Ok(()),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        risky("interp::power_too_many_nodes", || {
            let x = linspace(0.0, 1.0, 11_586);
            let y = vec![0.0; x.len()];
            expect_err!(PowerPolynomial::interpolate(&x, &y), Error::TooLarge { .. })
        }),
        risky("interp::vandermonde_condition_nan", || {
            expect_err!(
                vandermonde_condition(&[f64::NAN, 1.0, 2.0]),
                Error::NonFinite { .. }
            )
        }),
        risky("interp::vandermonde_condition_inf", || {
            expect_err!(
                vandermonde_condition(&[0.0, f64::INFINITY, 2.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::vandermonde_condition_empty", || {
            let r = vandermonde_condition(&[]);
            ensure!(r == Ok(None), "empty nodes: {}", show(&r));
            Ok(())
        }),
        case("interp::vandermonde_condition_well_posed", || {
            let k = ok(vandermonde_condition(&[0.0, 1.0, 2.0]))?;
            ensure!(
                matches!(k, Some(k) if k.is_finite() && k >= 1.0),
                "κ = {k:?}"
            );
            Ok(())
        }),
        case(
            "interp::vandermonde_condition_repeated_nodes_singular",
            || {
                let r = vandermonde_condition(&[1.0, 1.0, 1.0]);
                ensure!(r == Ok(None), "repeated nodes: {}", show(&r));
                Ok(())
            },
        ),
        case("interp::vandermonde_condition_power_overflows", || {
            expect_err!(
                vandermonde_condition(&[0.0, 1e200, 2e200]),
                Error::Overflow { .. }
            )
        }),
        risky("interp::vandermonde_condition_30_equispaced", || {
            let r = vandermonde_condition(&linspace(0.0, 1.0, 30));
            match r {
                Ok(None) => Ok(()),
                Ok(Some(k)) if k.is_finite() && k > 1e10 => Ok(()),
                other => Err(format!("30 equispaced nodes: {}", show(&other))),
            }
        }),
        risky("interp::vandermonde_condition_too_many_nodes", || {
            expect_err!(
                vandermonde_condition(&vec![0.5; 11_586]),
                Error::TooLarge { .. }
            )
        }),
        case("interp::lagrange_empty", || {
            expect_err!(Lagrange::try_new(&[], &[]), Error::TooFewPoints { .. })
        }),
        case("interp::lagrange_nan_value", || {
            expect_err!(
                Lagrange::try_new(&[0.0, 1.0], &[f64::NAN, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::lagrange_repeated_node", || {
            expect_err!(
                Lagrange::try_new(&[0.0, 0.0], &[1.0, 1.0]),
                Error::RepeatedParameter { index: 1, .. }
            )
        }),
        case("interp::lagrange_count_mismatch", || {
            expect_err!(
                Lagrange::try_new(&[0.0, 1.0, 2.0], &[1.0]),
                Error::CountMismatch { .. }
            )
        }),
        case("interp::lagrange_nodes_1e-310_apart", || {
            expect_err!(
                Lagrange::try_new(&[1.0, 2.0, 2.0 + 1e-310], &[1.0, 2.0, 3.0]),
                Error::RepeatedParameter { .. } | Error::GapTooSmall { .. }
            )?;
            expect_err!(
                Lagrange::try_new(&[0.0, 1e-310], &[1.0, 2.0]),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::lagrange_150_equispaced_on_0_1000", || {
            let x = linspace(0.0, 1000.0, 150);
            let y: Vec<f64> = x.iter().map(|v| (v / 100.0).sin()).collect();
            let p = ok(Lagrange::try_new(&x, &y))?;
            check_interpolates(&x, &y, |t| p.eval(t))?;
            for t in linspace(0.0, 1000.0, 2001) {
                ensure!(p.eval(t).is_finite(), "p({t}) = {}", p.eval(t));
            }
            Ok(())
        }),
        case(
            "interp::lagrange_1500_equispaced_overflow_or_interpolates",
            || {
                let x = linspace(0.0, 1.0, 1500);
                let y: Vec<f64> = x.iter().map(|v| (3.0 * v).cos()).collect();
                match Lagrange::try_new(&x, &y) {
                    Err(Error::Overflow { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
                }
            },
        ),
        case("interp::lagrange_values_1e300_tiny_gaps_finite", || {
            let x = [0.0, 1e-300, 2e-300, 3e-300];
            let y = [1e300, -1e300, 1e300, -1e300];
            match Lagrange::try_new(&x, &y) {
                Err(_) => Ok(()),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        case("interp::lagrange_values_f64_max_evaluate_finitely", || {
            // the cubic through alternating ±MAX overshoots to 1.19·MAX near x = 0.74
            let x = [0.0, 1.0, 2.0, 3.0];
            let y = [f64::MAX, -f64::MAX, f64::MAX, -f64::MAX];
            match Lagrange::try_new(&x, &y) {
                Err(Error::CoordinateTooLarge { .. } | Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected error {e:?}")),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        risky("interp::lagrange_too_many_nodes", || {
            let x = linspace(0.0, 1.0, 11_586);
            let y = vec![0.0; x.len()];
            expect_err!(Lagrange::try_new(&x, &y), Error::TooLarge { .. })
        }),
        case("interp::nodes_nan_bound", || {
            expect_err!(
                NodeFamily::Chebyshev.nodes(f64::NAN, 1.0, 3),
                Error::NonFinite { .. }
            )
        }),
        case("interp::nodes_empty_interval", || {
            expect_err!(
                NodeFamily::Equispaced.nodes(1.0, 0.0, 3),
                Error::EmptyInterval { .. }
            )
        }),
        case("interp::nodes_width_overflows", || {
            expect_err!(
                NodeFamily::Equispaced.nodes(-1e308, 1e308, 3),
                Error::Overflow { .. }
            )
        }),
        risky("interp::nodes_usize_max_degree", || {
            expect_err!(
                NodeFamily::Chebyshev.nodes(0.0, 1.0, usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                NodeFamily::Equispaced.nodes(0.0, 1.0, MAX_ELEMENTS),
                Error::TooLarge { .. }
            )
        }),
        case("interp::nodes_degree_zero", || {
            let e = ok(NodeFamily::Equispaced.nodes(1.0, 3.0, 0))?;
            let c = ok(NodeFamily::Chebyshev.nodes(1.0, 3.0, 0))?;
            ensure!(e == vec![2.0], "equispaced {e:?}");
            ensure!(
                c.len() == 1 && (c[0] - 2.0).abs() < 1e-15,
                "Chebyshev {c:?}"
            );
            Ok(())
        }),
        case(
            "interp::nodes_unresolvable_width_distinct_or_refused",
            || {
                for family in [NodeFamily::Equispaced, NodeFamily::Chebyshev] {
                    match family.nodes(1.0, 1.0 + 4.0 * f64::EPSILON, 10) {
                        Err(_) => {}
                        Ok(x) => ensure!(
                            x.windows(2).all(|w| w[0] < w[1]),
                            "{} nodes repeat: {x:?}",
                            format_args!("{:?}", family)
                        ),
                    }
                }
                Ok(())
            },
        ),
        case("interp::max_error_function_nan", || {
            expect_err!(
                max_interpolation_error(|_| f64::NAN, (0.0, 1.0), 4, NodeFamily::Equispaced, 11),
                Error::NonFinite { .. } | Error::Overflow { .. }
            )
        }),
        case("interp::max_error_function_nan_between_nodes", || {
            let f = |x: f64| {
                if x > 0.55 && x < 0.56 {
                    f64::NAN
                } else {
                    x * x
                }
            };
            expect_err!(
                max_interpolation_error(f, (0.0, 1.0), 2, NodeFamily::Equispaced, 1001),
                Error::Overflow { value, .. } if value.is_nan()
            )
        }),
        case("interp::max_error_too_few_samples", || {
            expect_err!(
                max_interpolation_error(runge, (-5.0, 5.0), 4, NodeFamily::Chebyshev, 1),
                Error::TooFewSamples { got: 1, .. }
            )
        }),
        risky("interp::max_error_huge_sizes", || {
            expect_err!(
                max_interpolation_error(runge, (-5.0, 5.0), 4, NodeFamily::Chebyshev, usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                max_interpolation_error(runge, (-5.0, 5.0), 1 << 40, NodeFamily::Chebyshev, 11),
                Error::TooLarge { .. }
            )
        }),
        case("interp::max_error_runge_documented", || {
            let e = ok(max_interpolation_error(
                runge,
                (-5.0, 5.0),
                10,
                NodeFamily::Equispaced,
                2001,
            ))?;
            ensure!(
                e.is_finite() && e > 1.0,
                "Runge's phenomenon at degree 10: {e}"
            );
            let c = ok(max_interpolation_error(
                runge,
                (-5.0, 5.0),
                10,
                NodeFamily::Chebyshev,
                2001,
            ))?;
            ensure!(c.is_finite() && c < e, "Chebyshev {c} vs equispaced {e}");
            Ok(())
        }),
        case("interp::param_one_point", || {
            expect_err!(
                Parametrization::ChordLength.parameters(&[v2(0.0, 0.0)]),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::param_nan_coordinate", || {
            expect_err!(
                Parametrization::Centripetal.parameters(&[v2(0.0, 0.0), v2(f64::NAN, 1.0)]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::param_coordinate_1e308", || {
            expect_err!(
                Parametrization::Uniform.parameters(&[v2(0.0, 0.0), v2(1e308, 1.0)]),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("interp::param_repeated_point", || {
            expect_err!(
                Parametrization::ChordLength.parameters(&[
                    v2(0.0, 0.0),
                    v2(1.0, 1.0),
                    v2(1.0, 1.0)
                ]),
                Error::RepeatedPoint { index: 2 }
            )
        }),
        case("interp::param_steps_1_and_1e-20", || {
            for p in Parametrization::ALL {
                match p.parameters(&unequal_step_points()) {
                    Err(Error::RepeatedParameter { .. }) => {}
                    Err(e) => return Err(format!("{}: unexpected {e:?}", format_args!("{:?}", p))),
                    Ok(t) => check_parameters(&t)
                        .map_err(|e| format!("{}: {e}", format_args!("{:?}", p)))?,
                }
            }
            Ok(())
        }),
        case("interp::param_points_1e306_apart", || {
            let pts = [v2(-1e306, 0.0), v2(1e306, 0.0), v2(1e306, 2e306)];
            for p in Parametrization::ALL {
                let t = ok(p.parameters(&pts))?;
                check_parameters(&t).map_err(|e| format!("{}: {e}", format_args!("{:?}", p)))?;
            }
            Ok(())
        }),
        case("interp::param_subnormal_coordinates", || {
            let pts = [v2(0.0, 0.0), v2(5e-324, 0.0), v2(1e-323, 0.0)];
            for p in Parametrization::ALL {
                let t = ok(p.parameters(&pts))?;
                check_parameters(&t).map_err(|e| format!("{}: {e}", format_args!("{:?}", p)))?;
            }
            Ok(())
        }),
        case("interp::linear_count_mismatch", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1.0], &[v1(0.0)]),
                Error::CountMismatch { .. }
            )
        }),
        case("interp::linear_single_point", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0], &[v1(0.0)]),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::linear_nan_abscissa", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, f64::NAN], &[v1(0.0), v1(1.0)]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::linear_repeated_abscissa", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1.0, 1.0], &[v1(0.0), v1(1.0), v1(2.0)]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::linear_abscissae_1e-310_apart", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1e-310], &[v1(0.0), v1(1.0)]),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::linear_slope_overflows_values_stay_exact", || {
            // the slope 1e600 is not representable, but the polygon is: its convex form
            // reproduces both ends and stays finite in between; only the derivative overflows
            let p = ok(PiecewiseLinear::try_new(
                &[0.0, 1e-300],
                &[v1(0.0), v1(1e300)],
            ))?;
            ensure!(
                p.point(1e-300).x == 1e300,
                "right end {:?}",
                p.point(1e-300)
            );
            ensure!(p.point(0.0).x == 0.0, "left end {:?}", p.point(0.0));
            let mid = p.point(0.5e-300).x;
            ensure!(
                mid.is_finite() && (mid / 0.5e300 - 1.0).abs() < 1e-15,
                "middle {mid:e}"
            );
            Ok(())
        }),
        case("interp::linear_value_beyond_max_coordinate", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1.0], &[v1(0.0), v1(f64::MAX)]),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("interp::linear_right_end_exact", || {
            let p = ok(PiecewiseLinear::try_new(
                &[0.0, 0.3, 1.0],
                &[v1(1.0), v1(-MAX_COORDINATE), v1(MAX_COORDINATE)],
            ))?;
            let end = ok(p.try_point(1.0))?;
            ensure!(
                (end.x - MAX_COORDINATE).abs() <= 4.0 * f64::EPSILON * MAX_COORDINATE,
                "p(1) = {}",
                end.x
            );
            for t in linspace(0.0, 1.0, 101) {
                ensure!(p.point(t).x.is_finite(), "p({t}) not finite");
            }
            Ok(())
        }),
        case("interp::linear_curve_repeated_point", || {
            expect_err!(
                PiecewiseLinear::curve(&[v2(0.0, 0.0), v2(0.0, 0.0)], Parametrization::ChordLength),
                Error::RepeatedPoint { index: 1 }
            )
        }),
        case(
            "interp::linear_curve_steps_1_and_1e-20",
            || match PiecewiseLinear::curve(&unequal_step_points(), Parametrization::ChordLength) {
                Err(_) => Ok(()),
                Ok(c) => {
                    let (a, b) = c.domain();
                    ensure!(a == 0.0 && b == 1.0, "domain {a} {b}");
                    Ok(())
                }
            },
        ),
        case("interp::cubic_count_mismatch", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0], EndCondition::Natural),
                Error::CountMismatch {
                    expected: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("interp::cubic_single_point", || {
            expect_err!(
                CubicSpline::function(&[0.0], &[1.0], EndCondition::Natural),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::cubic_periodic_two_points", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0], &[1.0, 1.0], EndCondition::Periodic),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("interp::cubic_nan_abscissa", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, f64::NAN, 2.0],
                    &[0.0, 1.0, 0.0],
                    EndCondition::Natural
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::cubic_inf_value", || {
            expect_err!(
                CubicSpline::try_new(
                    &[0.0, 1.0, 2.0],
                    &[v2(0.0, 0.0), v2(f64::INFINITY, 0.0), v2(0.0, 1.0)],
                    EndCondition::Natural
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::cubic_repeated_abscissa", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0, 1.0], &[0.0, 1.0, 0.0], EndCondition::Natural),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::cubic_decreasing_abscissae", || {
            expect_err!(
                CubicSpline::function(&[0.0, 2.0, 1.0], &[0.0, 1.0, 0.0], EndCondition::Natural),
                Error::NotIncreasing { index: 2, .. }
            )
        }),
        case("interp::cubic_knots_at_1e-310", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1e-310, 1.0], &[0.0, 1.0, 0.0], EndCondition::Natural),
                Error::GapTooSmall { index: 1, .. }
            )
        }),
        case("interp::cubic_slopes_overflow", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1e-10, 1.0],
                    &[1e300, -1e300, 1e300],
                    EndCondition::Natural
                ),
                Error::Overflow { .. } | Error::IllConditioned { .. }
            )
        }),
        case("interp::cubic_moments_overflow", || {
            // slopes of 1e300 fit, moments of 1e600 do not
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1e-300, 2e-300],
                    &[0.0, 1.0, 0.0],
                    EndCondition::Natural
                ),
                Error::Overflow { .. } | Error::IllConditioned { .. }
            )
        }),
        case("interp::cubic_periodic_ends_mismatch", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.5], EndCondition::Periodic),
                Error::PeriodicEndsMismatch { distance } if (*distance - 0.5).abs() < 1e-15
            )
        }),
        case("interp::cubic_clamped_nan_derivative", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[0.0, 1.0, 0.0],
                    EndCondition::clamped(f64::NAN, 0.0)
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::cubic_clamped_huge_derivative", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[0.0, 1.0, 0.0],
                    EndCondition::clamped(0.0, f64::MAX)
                ),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("interp::cubic_value_beyond_max_coordinate", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[0.0, f64::MAX, 0.0],
                    EndCondition::Natural
                ),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case(
            "interp::cubic_anticyclic_tiny_interval_refused_or_interpolates",
            || {
                let (x, y) = anticyclic_data();
                match CubicSpline::function(&x, &y, EndCondition::Anticyclic) {
                    Err(Error::IllConditioned { .. } | Error::Overflow { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(s) => check_interpolates(&x, &y, |t| s.value(t)),
                }
            },
        ),
        case(
            "interp::cubic_near_max_coordinate_evaluates_finitely",
            || {
                let x = [0.0, 1.0, 2.0, 3.0, 4.0];
                let y = [
                    MAX_COORDINATE,
                    -MAX_COORDINATE,
                    MAX_COORDINATE,
                    -MAX_COORDINATE,
                    MAX_COORDINATE,
                ];
                for end in [
                    EndCondition::Natural,
                    EndCondition::Periodic,
                    EndCondition::Anticyclic,
                    EndCondition::clamped(0.0, 0.0),
                ] {
                    let s = ok(CubicSpline::function(&x, &y, end))?;
                    let xs = linspace(0.0, 4.0, 401);
                    let mut out = Vec::new();
                    s.values_into(&xs, &mut out);
                    ensure!(
                        out.iter().all(|v| v.is_finite()),
                        "{}: values_into not finite",
                        format_args!("{:?}", end)
                    );
                    check_interpolates(&x, &y, |t| s.value(t))
                        .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
                }
                Ok(())
            },
        ),
        case("interp::cubic_right_end_is_left_limit", || {
            let x = [0.0, 0.5, 0.9, 1.0];
            let y = [0.0, 1.0, -1.0, 2.0];
            let s = ok(CubicSpline::function(&x, &y, EndCondition::Natural))?;
            let end = ok(s.try_point(1.0))?;
            ensure!((end.x - 2.0).abs() <= 1e-14, "s(1) = {}", end.x);
            let m = s.second_derivative(1.0);
            ensure!(m.abs() <= 1e-10, "natural end: s''(1) = {m}");
            let mut out = Vec::new();
            s.eval_many(&[0.0, 1.0], &mut out);
            ensure!(
                (out[1].x - end.x).abs() <= 1e-14,
                "eval_many(1) = {}",
                out[1].x
            );
            Ok(())
        }),
        case("interp::cubic_curve_repeated_point", || {
            expect_err!(
                CubicSpline::curve(
                    &[v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 0.0)],
                    Parametrization::Centripetal,
                    EndCondition::Natural
                ),
                Error::RepeatedPoint { index: 2 }
            )
        }),
        case(
            "interp::cubic_curve_steps_1_and_1e-20",
            || match CubicSpline::curve(
                &unequal_step_points(),
                Parametrization::ChordLength,
                EndCondition::Natural,
            ) {
                Err(_) => Ok(()),
                Ok(s) => {
                    let pts = unequal_step_points();
                    let t = s.nodes().to_vec();
                    check_parameters(&t)?;
                    for (ti, p) in t.iter().zip(&pts) {
                        ensure!(
                            (s.point(*ti) - p).amax() <= RESIDUAL_TOLERANCE,
                            "misses {p:?}"
                        );
                    }
                    Ok(())
                }
            },
        ),
    ];
    cases.extend(collocation_cases());
    cases
}

fn collocation_cases() -> Vec<Case> {
    vec![
        case("interp::collocation_values_mismatch", || {
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.3, 0.6, 1.0], &[v1(0.0); 3], &[]),
                Error::CountMismatch {
                    expected: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("interp::collocation_sites_count_mismatch", || {
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[]),
                Error::CountMismatch {
                    expected: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("interp::collocation_nan_site", || {
            expect_err!(
                collocation::interpolate(
                    basis(2, 4)?,
                    &[0.0, f64::NAN, 0.6, 1.0],
                    &[v1(0.0); 4],
                    &[]
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_site_outside_domain", || {
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.3, 0.6, 1.5], &[v1(0.0); 4], &[]),
                Error::OutOfDomain { value, .. } if *value == 1.5
            )
        }),
        case("interp::collocation_schoenberg_whitney_fails", || {
            expect_err!(
                collocation::interpolate(
                    basis(2, 4)?,
                    &[0.0, 0.01, 0.02, 0.03],
                    &[v1(1.0); 4],
                    &[]
                ),
                Error::SchoenbergWhitney { .. }
            )
        }),
        case("interp::collocation_nan_value", || {
            expect_err!(
                collocation::interpolate(
                    basis(2, 4)?,
                    &[0.0, 0.3, 0.6, 1.0],
                    &[v1(0.0), v1(f64::NAN), v1(0.0), v1(0.0)],
                    &[]
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_condition_nan_site", || {
            let c = Condition {
                order: DerivativeOrder::First,
                terms: vec![(f64::NAN, 1.0)],
                value: v1(0.0),
            };
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[c]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_condition_inf_coefficient", || {
            let c = Condition {
                order: DerivativeOrder::Second,
                terms: vec![(0.0, f64::INFINITY)],
                value: v1(0.0),
            };
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[c]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_condition_site_outside", || {
            let c = Condition {
                order: DerivativeOrder::First,
                terms: vec![(2.0, 1.0)],
                value: v1(0.0),
            };
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[c]),
                Error::OutOfDomain { .. }
            )
        }),
        risky("interp::collocation_too_large_system", || {
            let n = 11_600;
            let sites = linspace(0.0, 1.0, n);
            let values = vec![v1(0.0); n];
            expect_err!(
                collocation::interpolate(basis(1, n)?, &sites, &values, &[]),
                Error::TooLarge { .. }
            )
        }),
        case(
            "interp::schoenberg_whitney_more_sites_than_functions",
            || {
                expect_err!(
                    schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.2, 0.4, 0.6, 1.0]),
                    Error::CountMismatch {
                        expected: 4,
                        got: 5,
                        ..
                    }
                )
            },
        ),
        case("interp::schoenberg_whitney_nan_site", || {
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.2, f64::NAN, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::schoenberg_whitney_site_outside", || {
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[-0.5, 0.2, 0.4, 1.0]),
                Error::OutOfDomain { .. }
            )
        }),
        case("interp::schoenberg_whitney_repeated_site", || {
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.2, 0.2, 1.0]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::schoenberg_whitney_fails_index", || {
            // N₃ is supported on [0.5, 1]: the site 0.4 lies outside it
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.1, 0.2, 0.4]),
                Error::SchoenbergWhitney { index: 3, .. }
            )
        }),
        case("interp::schoenberg_whitney_valid", || {
            ok(schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.3, 0.7, 1.0]))
        }),
        case(
            "interp::collocation_anticyclic_tiny_interval_refused_or_interpolates",
            || {
                let (x, y) = anticyclic_data();
                let yv: Vec<Vector1<f64>> = y.iter().map(|v| v1(*v)).collect();
                match collocation::cubic_spline(&x, &yv, EndCondition::Anticyclic) {
                    Err(Error::IllConditioned { .. } | Error::SingularSystem { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(c) => check_interpolates(&x, &y, |t| c.point(t).x),
                }
            },
        ),
        case("interp::collocation_cubic_knots_at_1e-310", || {
            expect_err!(
                collocation::cubic_spline(
                    &[0.0, 1e-310, 1.0],
                    &[v1(0.0), v1(1.0), v1(0.0)],
                    EndCondition::Natural
                ),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::collocation_cubic_periodic_mismatch", || {
            expect_err!(
                collocation::cubic_spline(
                    &[0.0, 0.5, 1.0],
                    &[v1(0.0), v1(1.0), v1(0.3)],
                    EndCondition::Periodic
                ),
                Error::PeriodicEndsMismatch { .. }
            )
        }),
        case("interp::collocation_cubic_too_few", || {
            expect_err!(
                collocation::cubic_spline(
                    &[0.0, 1.0],
                    &[v1(0.0), v1(0.0)],
                    EndCondition::Anticyclic
                ),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("interp::curve_degree_zero", || {
            expect_err!(
                interpolate_curve(&some_points(5), 0, Parametrization::Uniform),
                Error::DegreeTooLow { min: 1, got: 0 }
            )
        }),
        case("interp::curve_degree_usize_max", || {
            expect_err!(
                interpolate_curve(&some_points(5), usize::MAX, Parametrization::Uniform),
                Error::TooFewPoints { .. } | Error::TooLarge { .. }
            )
        }),
        case("interp::curve_too_few_points", || {
            expect_err!(
                interpolate_curve(&some_points(3), 3, Parametrization::ChordLength),
                Error::TooFewPoints {
                    needed: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("interp::curve_repeated_points", || {
            let mut pts = some_points(5);
            pts[3] = pts[2];
            expect_err!(
                interpolate_curve(&pts, 3, Parametrization::ChordLength),
                Error::RepeatedPoint { index: 3 }
            )
        }),
        case("interp::curve_steps_1_and_1e-20", || {
            let pts = unequal_step_points();
            match interpolate_curve(&pts, 2, Parametrization::ChordLength) {
                Err(_) => Ok(()),
                Ok(c) => {
                    let t = ok(Parametrization::ChordLength.parameters(&pts))?;
                    check_parameters(&t)?;
                    for (ti, p) in t.iter().zip(&pts) {
                        ensure!(
                            (c.point(*ti) - p).amax() <= RESIDUAL_TOLERANCE,
                            "misses {p:?}"
                        );
                    }
                    Ok(())
                }
            }
        }),
        case("interp::curve_interpolates", || {
            let pts = some_points(7);
            let c = ok(interpolate_curve(&pts, 3, Parametrization::Centripetal))?;
            let t = ok(Parametrization::Centripetal.parameters(&pts))?;
            for (ti, p) in t.iter().zip(&pts) {
                let q = c.point(*ti);
                ensure!(
                    (q - p).amax() <= RESIDUAL_TOLERANCE * 3.0,
                    "C({ti}) = {q:?} vs {p:?}"
                );
            }
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// metrics: matlab_norm, compare, ErrorAccumulator
// ---------------------------------------------------------------------------------------------

fn grid3(rows: usize, cols: usize, f: impl Fn(usize, usize) -> Vector3<f64>) -> Grid<Vector3<f64>> {
    Grid::from_fn(rows, cols, f)
}

fn metrics_cases() -> Vec<Case> {
    vec![
        risky("metrics::matlab_norm_nan", || {
            let m = DMatrix::from_row_slice(2, 2, &[1.0, f64::NAN, 0.0, 1.0]);
            expect_err!(matlab_norm(&m), Error::NonFinite { .. })
        }),
        risky("metrics::matlab_norm_inf", || {
            let m = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, f64::INFINITY, 1.0]);
            expect_err!(matlab_norm(&m), Error::NonFinite { .. })
        }),
        risky("metrics::matlab_norm_large_nan_matrix_quick", || {
            let mut m = DMatrix::from_element(300, 300, 1.0);
            m[(299, 299)] = f64::NAN;
            let start = Instant::now();
            expect_err!(matlab_norm(&m), Error::NonFinite { .. })?;
            ensure!(
                start.elapsed() < Duration::from_secs(2),
                "took {:?}",
                start.elapsed()
            );
            Ok(())
        }),
        case("metrics::matlab_norm_neg_inf", || {
            let m = DMatrix::from_element(3, 3, f64::NEG_INFINITY);
            expect_err!(matlab_norm(&m), Error::NonFinite { .. })
        }),
        case("metrics::matlab_norm_empty", || {
            let m = DMatrix::<f64>::zeros(0, 3);
            let r = matlab_norm(&m);
            ensure!(r == Ok(0.0), "{}", show(&r));
            Ok(())
        }),
        case("metrics::matlab_norm_overflows", || {
            let m = DMatrix::from_element(3, 3, 1e308);
            expect_err!(matlab_norm(&m), Error::Overflow { .. })
        }),
        case("metrics::matlab_norm_near_overflow_finite", || {
            let m = DMatrix::from_element(3, 3, 1e307);
            let n = ok(matlab_norm(&m))?;
            ensure!((n / 3e307 - 1.0).abs() < 1e-12, "norm {n}");
            Ok(())
        }),
        case("metrics::compare_shape_mismatch", || {
            let a = grid3(2, 3, |_, _| Vector3::zeros());
            let b = grid3(3, 2, |_, _| Vector3::zeros());
            expect_err!(
                compare(&a, &b),
                Error::ShapeMismatch {
                    left_rows: 2,
                    left_cols: 3,
                    right_rows: 3,
                    right_cols: 2
                }
            )
        }),
        risky("metrics::compare_nan_entry", || {
            let a = grid3(15, 15, |i, j| {
                if i == 7 && j == 7 {
                    v3(f64::NAN, 0.0, 0.0)
                } else {
                    Vector3::zeros()
                }
            });
            let b = grid3(15, 15, |_, _| Vector3::zeros());
            expect_err!(compare(&a, &b), Error::NonFinite { .. })
        }),
        risky("metrics::compare_inf_entry", || {
            let a = grid3(4, 4, |_, _| Vector3::zeros());
            let b = grid3(4, 4, |i, _| {
                if i == 3 {
                    v3(0.0, f64::INFINITY, 0.0)
                } else {
                    Vector3::zeros()
                }
            });
            expect_err!(compare(&a, &b), Error::NonFinite { .. })
        }),
        case("metrics::compare_difference_overflows", || {
            let a = grid3(2, 2, |_, _| v3(1e308, 0.0, 0.0));
            let b = grid3(2, 2, |_, _| v3(-1e308, 0.0, 0.0));
            expect_err!(
                compare(&a, &b),
                Error::NonFinite { .. } | Error::Overflow { .. }
            )
        }),
        case("metrics::compare_norm_overflows", || {
            let a = grid3(3, 3, |_, _| v3(1e308, 0.0, 0.0));
            let b = grid3(3, 3, |_, _| Vector3::zeros());
            expect_err!(compare(&a, &b), Error::Overflow { .. })
        }),
        case("metrics::accumulator_error_keeps_state", || {
            let good_a = grid3(3, 3, |i, j| v3(0.1 * i as f64, 0.2 * j as f64, 0.0));
            let zero = grid3(3, 3, |_, _| Vector3::zeros());
            let bad = grid3(3, 3, |i, _| {
                if i == 1 {
                    v3(0.0, 0.0, f64::NAN)
                } else {
                    Vector3::zeros()
                }
            });
            let mut acc = ErrorAccumulator::new();
            ok(acc.add_patch(&good_a, &zero))?;
            let before = acc.finish();
            expect_err!(acc.add_patch(&bad, &zero), Error::NonFinite { .. })?;
            let after = acc.finish();
            ensure!(
                before == after,
                "a refused patch changed the result: {before:?} → {after:?}"
            );
            ensure!(
                [after.report_norm, after.max_abs, after.rms]
                    .iter()
                    .all(|v| v.iter().all(|x| x.is_finite())),
                "not finite: {after:?}"
            );
            Ok(())
        }),
        case("metrics::accumulator_empty_finish_zero", || {
            let e = ErrorAccumulator::new().finish();
            ensure!(
                e.report_norm == Vector3::zeros()
                    && e.max_abs == Vector3::zeros()
                    && e.rms == Vector3::zeros(),
                "{e:?}"
            );
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// study: spline_errors, uniform_spline_errors, convergence
// ---------------------------------------------------------------------------------------------

fn study_cases() -> Vec<Case> {
    vec![
        case("study::spline_errors_prec_one", || {
            let u = ok(Partition::uniform(0.0, 1.0, 1))?;
            expect_err!(
                spline_errors(
                    &Torus::default(),
                    u.clone(),
                    u,
                    1,
                    PatchEvaluation::HermiteMatrix
                ),
                Error::TooFewSamples { got: 1, .. }
            )
        }),
        case("study::spline_errors_prec_zero", || {
            let u = ok(Partition::uniform(0.0, 1.0, 2))?;
            expect_err!(
                spline_errors(
                    &Torus::default(),
                    u.clone(),
                    u,
                    0,
                    PatchEvaluation::DeCasteljau
                ),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("study::spline_errors_prec_huge", || {
            let u = ok(Partition::uniform(0.0, 1.0, 1))?;
            expect_err!(
                spline_errors(
                    &Torus::default(),
                    u.clone(),
                    u.clone(),
                    1 << 40,
                    PatchEvaluation::HermiteMatrix
                ),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                spline_errors(
                    &Torus::default(),
                    u.clone(),
                    u,
                    usize::MAX,
                    PatchEvaluation::ReportListing
                ),
                Error::TooLarge { .. }
            )
        }),
        case("study::spline_errors_nan_surface", || {
            let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                let bad = if s.re > 0.4 && s.re < 0.6 {
                    f64::NAN
                } else {
                    1.0
                };
                Vector3::new(s * bad, t, s * t)
            });
            let u = ok(Partition::uniform(0.0, 1.0, 2))?;
            expect_err!(
                spline_errors(&spot, u.clone(), u, 5, PatchEvaluation::HermiteMatrix),
                Error::NonFiniteSurface { .. }
            )
        }),
        case("study::spline_errors_nan_between_nodes", || {
            // finite at the nodes, NaN at interior samples: the measure must not drop it
            let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                let bad = if s.re > 0.22 && s.re < 0.28 {
                    f64::NAN
                } else {
                    1.0
                };
                Vector3::new(s * bad, t, s * t)
            });
            let u = ok(Partition::uniform(0.0, 1.0, 1))?;
            expect_err!(
                spline_errors(&spot, u.clone(), u, 21, PatchEvaluation::HermiteMatrix),
                Error::NonFiniteSurface { .. } | Error::NonFinite { .. }
            )
        }),
        case("study::uniform_zero_patches", || {
            expect_err!(
                uniform_spline_errors(
                    &Torus::default(),
                    &Rect::unit(),
                    0,
                    1,
                    15,
                    PatchEvaluation::HermiteMatrix
                ),
                Error::ZeroPatches { .. }
            )
        }),
        risky("study::uniform_torus_near_limit_radii", || {
            let torus = ok(Torus::try_new(1.3e306, 1.3e306))?;
            match uniform_spline_errors(
                &torus,
                &Rect::unit(),
                2,
                2,
                15,
                PatchEvaluation::HermiteMatrix,
            ) {
                Err(_) => Ok(()),
                Ok(e) => {
                    ensure!(
                        [e.report_norm, e.max_abs, e.rms]
                            .iter()
                            .all(|v| v.iter().all(|x| x.is_finite())),
                        "Ok with a non-finite measure: {e:?}"
                    );
                    Ok(())
                }
            }
        }),
        risky("study::uniform_fn_torus_radii_1e308", || {
            let torus = fn_torus(1e308, 1e308);
            expect_err!(
                uniform_spline_errors(
                    &torus,
                    &Rect::unit(),
                    2,
                    2,
                    15,
                    PatchEvaluation::HermiteMatrix
                ),
                Error::NonFiniteSurface { .. }
                    | Error::CoordinateTooLarge { .. }
                    | Error::Overflow { .. }
            )
        }),
        risky("study::uniform_rect_1e308", || {
            expect_err!(
                Rect::try_new(-1e308, 1e308, -1e308, 1e308),
                Error::Overflow { .. }
            )?;
            let rect = ok(Rect::try_new(-1e307, 1e307, -1e307, 1e307))?;
            for eval in PatchEvaluation::ALL {
                let r = uniform_spline_errors(&Torus::default(), &rect, 2, 2, 15, eval);
                match r {
                    Err(_) => {}
                    Ok(e) => ensure!(
                        [e.report_norm, e.max_abs, e.rms]
                            .iter()
                            .all(|v| v.iter().all(|x| x.is_finite())),
                        "{}: Ok with a non-finite measure: {e:?}",
                        format_args!("{:?}", eval)
                    ),
                }
            }
            Ok(())
        }),
        case("study::convergence_not_increasing", || {
            expect_err!(
                convergence(&Torus::default(), &Rect::unit(), &[2, 1], 5),
                Error::NotIncreasing { index: 1, .. }
            )
        }),
        case("study::convergence_zero_patches", || {
            expect_err!(
                convergence(&Torus::default(), &Rect::unit(), &[0, 1], 5),
                Error::ZeroPatches { .. }
            )
        }),
        case("study::convergence_prec_one", || {
            expect_err!(
                convergence(&Torus::default(), &Rect::unit(), &[1], 1),
                Error::TooFewSamples { .. }
            )
        }),
        case("study::convergence_empty", || {
            let r = ok(convergence(&Torus::default(), &Rect::unit(), &[], 5))?;
            ensure!(r.is_empty(), "{} rows", r.len());
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// blending
// ---------------------------------------------------------------------------------------------

fn sliding_grid(rows: usize, cols: usize, value: f64) -> Grid<Vector3<f64>> {
    Grid::from_fn(rows, cols, |i, j| {
        let s = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
        v3(i as f64, j as f64, s * value)
    })
}

fn blending_cases() -> Vec<Case> {
    vec![
        case("blending::setbval_rows_sum_to_one", || {
            let b = ok(printed_setbval(6))?;
            ensure!(b.len() == 6, "{} rows", b.len());
            for row in &b {
                let s: f64 = row.iter().sum();
                ensure!(
                    row.iter().all(|x| x.is_finite() && *x >= -1e-15) && (s - 1.0).abs() < 1e-14,
                    "row {row:?}"
                );
            }
            ensure!(ok(printed_setbval(0))?.is_empty(), "nb = 0 not empty");
            Ok(())
        }),
        risky("blending::setbval_huge", || {
            expect_err!(printed_setbval(usize::MAX), Error::TooLarge { .. })?;
            expect_err!(printed_setbval(MAX_ELEMENTS + 1), Error::TooLarge { .. })
        }),
        case("blending::lagrange_window_three_points", || {
            expect_err!(
                WindowCurve::lagrange(&some_points(3)),
                Error::TooFewPoints {
                    needed: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("blending::lagrange_window_nan", || {
            let mut pts = some_points(5);
            pts[1].x = f64::NAN;
            expect_err!(WindowCurve::lagrange(&pts), Error::NonFinite { .. })
        }),
        case("blending::lagrange_window_1e308", || {
            let mut pts = some_points(5);
            pts[4].y = 1e308;
            expect_err!(
                WindowCurve::lagrange(&pts),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case(
            "blending::lagrange_window_near_max_coordinate_finite",
            || {
                let c = ok(WindowCurve::lagrange(&alternating_points(
                    7,
                    MAX_COORDINATE,
                )))?;
                ensure!(finite_vecs(&ok(c.polyline(1201))?), "polyline not finite");
                Ok(())
            },
        ),
        case("blending::lagrange_window_right_end_is_last_point", || {
            let pts = some_points(6);
            let c = ok(WindowCurve::lagrange(&pts))?;
            let (_, b) = c.domain();
            let p = ok(c.try_point(b))?;
            ensure!(
                (p - pts[5]).amax() < 1e-13,
                "C({b}) = {p:?} vs {:?}",
                pts[5]
            );
            for (k, q) in pts.iter().enumerate() {
                ensure!((c.point(k as f64) - q).amax() < 1e-13, "misses P{k}");
            }
            expect_err!(c.try_point(b + 0.5), Error::OutOfDomain { .. })
        }),
        case("blending::printed_bspline_two_points", || {
            expect_err!(
                WindowCurve::printed_bspline(&some_points(2)),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("blending::printed_bspline_inf", || {
            let mut pts = some_points(4);
            pts[0].y = f64::NEG_INFINITY;
            expect_err!(WindowCurve::printed_bspline(&pts), Error::NonFinite { .. })
        }),
        case("blending::printed_bspline_polyline_nb_zero", || {
            expect_err!(
                printed_bspline_polyline(&some_points(4), 0),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("blending::printed_bspline_polyline_huge_nb", || {
            expect_err!(
                printed_bspline_polyline(&some_points(4), usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                printed_bspline_polyline(&some_points(4), MAX_ELEMENTS / 2),
                Error::TooLarge { .. }
            )
        }),
        case("blending::opengl_order_too_low", || {
            expect_err!(
                opengl_groups(&some_points(5), 1, LastGroup::Truncated),
                Error::DegreeTooLow { min: 2, got: 1 }
            )?;
            expect_err!(
                opengl_groups(&some_points(5), 0, LastGroup::AsPrinted),
                Error::DegreeTooLow { got: 0, .. }
            )
        }),
        case("blending::opengl_too_few_points", || {
            expect_err!(
                opengl_groups(&some_points(2), 3, LastGroup::Truncated),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )?;
            expect_err!(
                opengl_groups(&some_points(4), 5, LastGroup::AsPrinted),
                Error::TooFewPoints {
                    needed: 5,
                    got: 4,
                    ..
                }
            )
        }),
        case("blending::opengl_nan_point", || {
            let mut pts = some_points(6);
            pts[5].x = f64::NAN;
            expect_err!(
                opengl_groups(&pts, 3, LastGroup::Truncated),
                Error::NonFinite { .. }
            )
        }),
        risky("blending::opengl_groups_order_2_pow_40", || {
            let g = ok(opengl_groups(
                &some_points(5),
                1 << 40,
                LastGroup::Truncated,
            ))?;
            ensure!(
                g.len() == 1 && g[0].len() == 5,
                "groups {:?}",
                g.iter().map(Vec::len).collect::<Vec<_>>()
            );
            expect_err!(
                opengl_groups(&some_points(5), 1 << 40, LastGroup::AsPrinted),
                Error::TooFewPoints { needed, .. } if *needed == 1 << 40
            )
        }),
        risky("blending::opengl_groups_order_usize_max", || {
            let g = ok(opengl_groups(
                &some_points(5),
                usize::MAX,
                LastGroup::Truncated,
            ))?;
            ensure!(
                g.len() == 1 && g[0].len() == 5,
                "groups {:?}",
                g.iter().map(Vec::len).collect::<Vec<_>>()
            );
            Ok(())
        }),
        case("blending::opengl_polyline_nseg_zero", || {
            expect_err!(
                opengl_polyline(&some_points(5), 3, 0, LastGroup::Truncated),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("blending::opengl_polyline_huge_nseg", || {
            expect_err!(
                opengl_polyline(&some_points(5), 3, usize::MAX, LastGroup::Truncated),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                opengl_polyline(&some_points(5), 3, MAX_ELEMENTS, LastGroup::AsPrinted),
                Error::TooLarge { .. }
            )
        }),
        risky("blending::opengl_polyline_order_2_pow_40", || {
            let p = ok(opengl_polyline(
                &some_points(5),
                1 << 40,
                10,
                LastGroup::Truncated,
            ))?;
            ensure!(p.len() == 11 && finite_vecs(&p), "{} points", p.len());
            Ok(())
        }),
        case("blending::sliding_too_small_grid", || {
            expect_err!(
                SlidingBicubic::try_new(&sliding_grid(3, 5, 1.0), Blending::Lagrange),
                Error::TooFewPoints {
                    needed: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("blending::sliding_nan_point", || {
            let mut g = sliding_grid(5, 5, 1.0);
            g.as_mut_slice()[12].z = f64::NAN;
            expect_err!(
                SlidingBicubic::try_new(&g, Blending::UniformBSpline),
                Error::NonFinite { .. }
            )
        }),
        case("blending::sliding_point_1e308", || {
            expect_err!(
                SlidingBicubic::try_new(&sliding_grid(4, 4, 1e308), Blending::Lagrange),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("blending::sliding_bad_cell", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(5, 6, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(s.tabulate_cell((2, 0), 5), Error::IndexOutOfRange { .. })?;
            expect_err!(s.tabulate_cell((0, 3), 5), Error::IndexOutOfRange { .. })
        }),
        case("blending::sliding_bad_cell_usize_max", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(5, 6, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(
                s.tabulate_cell((usize::MAX, usize::MAX), 5),
                Error::IndexOutOfRange { .. }
            )?;
            expect_err!(
                s.tabulate_cell((usize::MAX, 0), 5),
                Error::IndexOutOfRange { .. }
            )
        }),
        case("blending::sliding_too_few_samples", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(4, 4, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(
                s.tabulate_cell((0, 0), 1),
                Error::TooFewSamples { got: 1, .. }
            )
        }),
        risky("blending::sliding_huge_samples", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(4, 4, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(s.tabulate_cell((0, 0), 1 << 20), Error::TooLarge { .. })?;
            expect_err!(s.tabulate_cell((0, 0), usize::MAX), Error::TooLarge { .. })
        }),
        case("blending::sliding_near_max_coordinate_finite", || {
            for b in [Blending::Lagrange, Blending::UniformBSpline] {
                let s = ok(SlidingBicubic::try_new(
                    &sliding_grid(6, 6, MAX_COORDINATE),
                    b,
                ))?;
                for i in 0..3 {
                    for j in 0..3 {
                        ensure!(
                            finite_grid(&ok(s.tabulate_cell((i, j), 9))?),
                            "{}: cell ({i}, {j})",
                            format_args!("{:?}", b)
                        );
                    }
                }
            }
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// report: the file layer's typed errors
// ---------------------------------------------------------------------------------------------

// ---------------------------------------------------------------------------------------------
// More combinations: batch evaluation in any order, the threaded partials path, documented
// results of the printed procedures, weights at the ratio limit, overflowing widths
// ---------------------------------------------------------------------------------------------

/// Parameters in no particular order, inside and slightly outside `[a, b]`, ends included.
fn scrambled(a: f64, b: f64) -> Vec<f64> {
    let mut ts: Vec<f64> = (0..97)
        .map(|k| a + (b - a) * ((k * 37) % 97) as f64 / 96.0)
        .collect();
    ts.extend([
        b,
        a,
        b,
        0.5 * (a + b),
        a - 0.01 * (b - a),
        b + 0.01 * (b - a),
        b,
    ]);
    ts
}

fn more_cases() -> Vec<Case> {
    vec![
        case("bspline::eval_many_any_order_equals_point", || {
            let c = ok(BSplineCurve::try_new(basis(3, 9)?, some_points(9)))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (t, q) in ts.iter().zip(&out) {
                let p = c.point(*t);
                ensure!(finite_vecs(&[p, *q]), "t = {t}");
                ensure!(
                    (p - q).amax() <= 1e-12,
                    "t = {t}: point {p:?} vs batch {q:?}"
                );
            }
            Ok(())
        }),
        case("nurbs::eval_many_any_order_equals_point", || {
            let c = ok(NurbsCurve::circle7(v2(1.0, -2.0), 3.0))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (t, q) in ts.iter().zip(&out) {
                let p = c.point(*t);
                ensure!(finite_vecs(&[p, *q]), "t = {t}");
                ensure!(
                    (p - q).amax() <= 1e-12,
                    "t = {t}: point {p:?} vs batch {q:?}"
                );
            }
            Ok(())
        }),
        case("interp::cubic_eval_many_any_order_equals_point", || {
            let x = [0.0, 0.1, 0.5, 0.55, 1.0];
            let y = [1.0, -1.0, 2.0, 0.0, 1.0];
            let s = ok(CubicSpline::function(&x, &y, EndCondition::Periodic))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            s.values_into(&ts, &mut out);
            let mut many = Vec::new();
            s.eval_many(&ts, &mut many);
            for ((t, q), m) in ts.iter().zip(&out).zip(&many) {
                let p = s.value(*t);
                ensure!(p.is_finite() && q.is_finite(), "t = {t}");
                ensure!(
                    (p - q).abs() <= 1e-12 && (p - m.x).abs() <= 1e-12,
                    "t = {t}: {p} vs {q} / {}",
                    m.x
                );
            }
            Ok(())
        }),
        case(
            "nurbs::right_end_of_unclamped_repeated_end_is_left_limit",
            || {
                let b = ok(BSplineBasis::try_new(
                    ok(KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0]))?,
                    2,
                ))?;
                let pts = vec![v2(0.0, 0.0), v2(1.0, 2.0), v2(3.0, 1.0), v2(7.0, 7.0)];
                let c = ok(NurbsCurve::try_new(b, pts, vec![1.0, 2.0, 3.0, 4.0]))?;
                let p = ok(c.try_point(1.0))?;
                ensure!(
                    (p - v2(3.0, 1.0)).amax() < 1e-14,
                    "C(1) = {p:?}, left limit (3, 1)"
                );
                let mut out = Vec::new();
                c.eval_many(&[1.0, 0.0, 1.0], &mut out);
                ensure!(
                    out.iter().step_by(2).all(|q| (q - p).amax() < 1e-14),
                    "batch {out:?}"
                );
                Ok(())
            },
        ),
        case(
            "nurbs::weight_ratio_just_above_limit_evaluates_finitely",
            || {
                let w = vec![1.0, 2e-280, 1.0, 2e-280, 1.0];
                let c = ok(nurbs_with(w))?;
                let ts = linspace(0.0, 1.0, 101);
                let mut out = Vec::new();
                c.eval_many(&ts, &mut out);
                for (t, q) in ts.iter().zip(&out) {
                    let p = c.point(*t);
                    ensure!(finite_vecs(&[p, *q]), "t = {t}: {p:?} {q:?}");
                    ensure!((p - q).amax() <= 1e-12 * 4.0, "t = {t}: {p:?} vs {q:?}");
                }
                Ok(())
            },
        ),
        case("bspline::near_coincident_knots_derivatives_finite", || {
            let k = ok(KnotVector::try_new(vec![
                0.0,
                0.0,
                0.0,
                0.5,
                0.5 + 1e-9,
                1.0,
                1.0,
                1.0,
            ]))?;
            let c = ok(BSplineCurve::try_new(
                ok(BSplineBasis::try_new(k, 2))?,
                some_points(5),
            ))?;
            for t in [0.25, 0.5, 0.5 + 5e-10, 0.5 + 1e-9, 0.75, 1.0] {
                let [p, d1, d2] = c.derivatives2(t);
                ensure!(finite_vecs(&[p, d1, d2]), "t = {t}: {p:?} {d1:?} {d2:?}");
            }
            Ok(())
        }),
        case(
            "surface::partials_on_grid_threaded_first_nan_in_row_major",
            || {
                // 200 × 100 nodes take the multi-threaded path; NaN at (s₁₅₀, t₃₀) and later
                let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                    let bad = if s.re >= 150.0 && t.re >= 30.0 {
                        f64::NAN
                    } else {
                        1.0
                    };
                    Vector3::new(s * bad, t, s * t)
                });
                let s_nodes: Vec<f64> = (0..200).map(f64::from).collect();
                let t_nodes: Vec<f64> = (0..100).map(f64::from).collect();
                expect_err!(
                    partials_on_grid(&spot, &s_nodes, &t_nodes),
                    Error::NonFiniteSurface { s, t } if *s == 150.0 && *t == 30.0
                )
            },
        ),
        case("surface::partials_on_grid_threaded_finite", || {
            let s_nodes = linspace(0.0, 6.0, 200);
            let t_nodes = linspace(0.0, 6.0, 100);
            let g = ok(partials_on_grid(&Torus::default(), &s_nodes, &t_nodes))?;
            ensure!(
                g.rows() == 200 && g.cols() == 100,
                "shape {}×{}",
                g.rows(),
                g.cols()
            );
            let p = g.get(123, 45);
            let q = Torus::default().partials(s_nodes[123], t_nodes[45]);
            ensure!(*p == q, "threaded {p:?} vs direct {q:?}");
            Ok(())
        }),
        case("surface::exp_surface_overflows_on_large_rect", || {
            let rect = ok(Rect::try_new(0.0, 1000.0, 0.0, 1000.0))?;
            expect_err!(
                tabulate(&ExpSurface, &rect, 3, 3),
                Error::NonFiniteSurface { .. }
            )?;
            expect_err!(
                HermiteSurface::uniform(&ExpSurface, &rect, 2, 2),
                Error::NonFiniteSurface { .. } | Error::CoordinateTooLarge { .. }
            )
        }),
        case("surface::sphere_near_limit_tabulates_finitely", || {
            let sphere = ok(Sphere::try_new(MAX_COORDINATE))?;
            let g = ok(tabulate(
                &sphere,
                &ok(Rect::try_new(0.0, 6.3, -1.6, 1.6))?,
                9,
                9,
            ))?;
            ensure!(finite_grid(&g), "not finite");
            Ok(())
        }),
        case("interp::lagrange_nodes_width_overflows", || {
            expect_err!(
                Lagrange::try_new(&[-1e308, 0.0, 1e308], &[1.0, 2.0, 3.0]),
                Error::Overflow { .. }
            )
        }),
        case("interp::linear_abscissae_width_overflows", || {
            expect_err!(
                PiecewiseLinear::try_new(&[-1e308, 1e308], &[v1(0.0), v1(1.0)]),
                Error::Overflow { .. }
            )
        }),
        case("interp::cubic_abscissae_width_overflows", || {
            expect_err!(
                CubicSpline::function(
                    &[-1e308, 0.0, 1e308],
                    &[0.0, 1.0, 0.0],
                    EndCondition::Natural
                ),
                Error::Overflow { .. }
            )
        }),
        case("interp::power_offset_nodes_refused_or_interpolates", || {
            let x: Vec<f64> = (0..12).map(|k| 1e6 + k as f64).collect();
            let y: Vec<f64> = x.iter().map(|v| (v - 1e6).sqrt()).collect();
            match PowerPolynomial::interpolate(&x, &y) {
                Err(
                    Error::IllConditioned { .. }
                    | Error::SingularSystem { .. }
                    | Error::Overflow { .. },
                ) => Ok(()),
                Err(e) => Err(format!("unexpected error {e:?}")),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        case(
            "interp::cubic_clamped_huge_slopes_refused_or_interpolates",
            || {
                // end slopes of 1e306 on unit data: the moments are representable
                let x = [0.0, 1.0, 2.0];
                let y = [0.0, 1.0, 0.0];
                match CubicSpline::function(&x, &y, EndCondition::clamped(1e306, -1e306)) {
                    Err(Error::Overflow { .. } | Error::IllConditioned { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(s) => check_interpolates(&x, &y, |t| s.value(t)),
                }
            },
        ),
        case("interp::collocation_cubic_matches_tridiagonal", || {
            let x = [0.0, 0.3, 0.35, 0.8, 1.0];
            let y = [0.0, 1.0, -1.0, 0.5, 0.0];
            let yv: Vec<Vector1<f64>> = y.iter().map(|v| v1(*v)).collect();
            for end in [
                EndCondition::Natural,
                EndCondition::Anticyclic,
                EndCondition::Periodic,
                EndCondition::clamped(1.0, -1.0),
            ] {
                let a = ok(CubicSpline::function(&x, &y, end))?;
                let b = ok(collocation::cubic_spline(&x, &yv, end))?;
                for t in linspace(0.0, 1.0, 101) {
                    let (u, v) = (a.value(t), b.point(t).x);
                    ensure!(
                        (u - v).abs() < 1e-9,
                        "{}: t = {t}: {u} vs {v}",
                        format_args!("{:?}", end)
                    );
                }
            }
            Ok(())
        }),
        case("blending::opengl_as_printed_nine_points_documented", || {
            let pts = some_points(9);
            let g = ok(opengl_groups(&pts, 5, LastGroup::AsPrinted))?;
            ensure!(g.len() == 3, "{} groups", g.len());
            ensure!(g[0] == pts[0..5] && g[1] == pts[4..9], "first groups {g:?}");
            let third = vec![pts[8], pts[5], pts[6], pts[7], pts[8]];
            ensure!(
                g[2] == third,
                "third group {:?}, printed P8, P5, P6, P7, P8",
                g[2]
            );
            let t = ok(opengl_groups(&pts, 5, LastGroup::Truncated))?;
            ensure!(
                t.len() == 2,
                "truncated: {} groups (a 1-point group is dropped)",
                t.len()
            );
            Ok(())
        }),
        case("blending::printed_bspline_ends_documented", || {
            let pts = some_points(6);
            let c = ok(WindowCurve::printed_bspline(&pts))?;
            let (a, b) = c.domain();
            ensure!(
                (ok(c.try_point(a))? - pts[0]).amax() < 1e-14,
                "does not start at P0"
            );
            ensure!(
                (ok(c.try_point(b))? - pts[5]).amax() < 1e-14,
                "does not end at the last point"
            );
            let poly = ok(printed_bspline_polyline(&pts, 6))?;
            ensure!(poly.len() == 1 + 7 * 6, "{} vertices", poly.len());
            ensure!(
                finite_vecs(&poly) && poly[0] == pts[0],
                "polyline start {:?}",
                poly[0]
            );
            Ok(())
        }),
        case("metrics::matlab_norm_subnormal_entries", || {
            let m = DMatrix::from_element(3, 3, 5e-324);
            let n = ok(matlab_norm(&m))?;
            ensure!(n.is_finite() && n > 0.0, "norm {n}");
            Ok(())
        }),
        case("metrics::compare_empty_grids", || {
            let a: Grid<Vector3<f64>> = Grid::from_vec(0, 0, vec![]).ok_or("grid")?;
            match compare(&a, &a) {
                Err(_) => Ok(()),
                Ok(e) => {
                    ensure!(
                        e.max_abs == Vector3::zeros() && e.rms == Vector3::zeros(),
                        "{e:?}"
                    );
                    Ok(())
                }
            }
        }),
        case("metrics::compare_rms_overflows", || {
            // differences of 1e200: their squares overflow, the RMS (1e200) does not
            let a = grid3(2, 2, |_, _| v3(1e200, 0.0, 0.0));
            let b = grid3(2, 2, |_, _| Vector3::zeros());
            match compare(&a, &b) {
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected error {e:?}")),
                Ok(e) => {
                    ensure!(
                        [e.report_norm, e.max_abs, e.rms]
                            .iter()
                            .all(|v| v.iter().all(|x| x.is_finite())),
                        "Ok with a non-finite measure: {e:?}"
                    );
                    ensure!(
                        (e.rms.x / 1e200 - 1.0).abs() < 1e-12,
                        "rms {:e}, expected 1e200",
                        e.rms.x
                    );
                    Ok(())
                }
            }
        }),
        case("metrics::accumulator_norm_sum_overflows", || {
            // two patches of norm 1.5e308 each: the mean is finite, the sum is not
            let a = grid3(3, 3, |_, _| v3(5e307, 0.0, 0.0));
            let b = grid3(3, 3, |_, _| Vector3::zeros());
            let mut acc = ErrorAccumulator::new();
            let first = acc.add_patch(&a, &b);
            let second = acc.add_patch(&a, &b);
            match (first, second) {
                (Ok(()), Ok(())) => {
                    let e = acc.finish();
                    ensure!(
                        [e.report_norm, e.max_abs, e.rms]
                            .iter()
                            .all(|v| v.iter().all(|x| x.is_finite())),
                        "Ok with a non-finite measure: {e:?}"
                    );
                    Ok(())
                }
                (Ok(()), Err(Error::Overflow { .. })) => Ok(()),
                other => Err(format!("unexpected {other:?}")),
            }
        }),
        case("blending::window_try_point_nan", || {
            let c = ok(WindowCurve::lagrange(&some_points(5)))?;
            expect_err!(c.try_point(f64::NAN), Error::NonFinite { .. })?;
            let c = ok(WindowCurve::printed_bspline(&some_points(5)))?;
            expect_err!(c.try_point(f64::INFINITY), Error::NonFinite { .. })
        }),
        case("domain::rect_subnormal_side", || {
            expect_err!(
                Rect::try_new(0.0, 1.0, 0.0, 1e-310),
                Error::GapTooSmall { .. }
            )
        }),
        case(
            "bspline::interior_full_multiplicity_breakpoint_is_right_piece",
            || {
                let k = ok(KnotVector::try_new(vec![
                    0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0,
                ]))?;
                let pts = some_points(6);
                let c = ok(BSplineCurve::try_new(
                    ok(BSplineBasis::try_new(k, 2))?,
                    pts.clone(),
                ))?;
                let p = ok(c.try_point(0.5))?;
                ensure!(
                    (p - pts[3]).amax() < 1e-14,
                    "C(0.5) = {p:?}, the right piece starts at P3 = {:?}",
                    pts[3]
                );
                let mut out = Vec::new();
                c.eval_many(&[0.25, 0.5], &mut out);
                ensure!(
                    (out[1] - pts[3]).amax() < 1e-14,
                    "eval_many(0.5) = {:?}",
                    out[1]
                );
                let left = c.point(0.5 - 1e-13);
                ensure!(
                    (left - pts[2]).amax() < 1e-9,
                    "left limit {left:?} vs P2 {:?}",
                    pts[2]
                );
                Ok(())
            },
        ),
        risky("study::convergence_huge_patch_count", || {
            expect_err!(
                convergence(&Torus::default(), &Rect::unit(), &[1, 1 << 40], 5),
                Error::TooLarge { .. }
            )
        }),
        risky("study::spline_errors_too_many_patches", || {
            let u = ok(Partition::uniform(0.0, 1.0, 20_000))?;
            expect_err!(
                spline_errors(
                    &Torus::default(),
                    u.clone(),
                    u,
                    2,
                    PatchEvaluation::HermiteMatrix
                ),
                Error::TooLarge { .. }
            )
        }),
        risky("grid::from_fn_shorthand_panics_without_allocating", || {
            let r = catch_unwind(|| Grid::from_fn(usize::MAX, 2, |_, _| 0u8).rows());
            ensure!(r.is_err(), "Grid::from_fn(usize::MAX, 2) did not panic");
            Ok(())
        }),
    ]
}

/// `Ok` if `f` panics (a `new`-style shorthand documents its panic).
fn expect_panic<T>(what: &str, f: impl FnOnce() -> T + std::panic::UnwindSafe) -> CaseResult {
    match catch_unwind(f) {
        Err(_) => Ok(()),
        Ok(_) => Err(format!("{what} did not panic on invalid input")),
    }
}

fn shorthand_cases() -> Vec<Case> {
    vec![
        risky("shorthand::interval_new_panics", || {
            expect_panic("Interval::new(1, 0)", || Interval::new(1.0, 0.0))
        }),
        risky("shorthand::rect_new_panics", || {
            expect_panic("Rect::new(NaN…)", || Rect::new(f64::NAN, 1.0, 0.0, 1.0))
        }),
        risky("shorthand::partition_new_panics", || {
            expect_panic("Partition::new([1])", || Partition::new(vec![1.0]))
        }),
        risky("shorthand::torus_new_panics", || {
            expect_panic("Torus::new(0, 1)", || Torus::new(0.0, 1.0))
        }),
        risky("shorthand::sphere_new_panics", || {
            expect_panic("Sphere::new(−1)", || Sphere::new(-1.0))
        }),
        risky("shorthand::knot_vector_new_panics", || {
            expect_panic("KnotVector::new([])", || KnotVector::new(vec![]))
        }),
        risky("shorthand::basis_new_panics", || {
            let k = ok(KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]))?;
            expect_panic("BSplineBasis::new(k, 5)", move || BSplineBasis::new(k, 5))
        }),
        risky("shorthand::curve_new_panics", || {
            let b = basis(2, 5)?;
            expect_panic("BSplineCurve::new mismatch", move || {
                BSplineCurve::new(b, some_points(4))
            })
        }),
        risky("shorthand::nurbs_new_panics", || {
            let b = basis(2, 5)?;
            expect_panic("NurbsCurve::new zero weight", move || {
                NurbsCurve::new(b, some_points(5), vec![0.0; 5])
            })
        }),
        risky("shorthand::hermite_from_matrix_panics", || {
            let mut c = unit_net();
            c[0][0].x = f64::NAN;
            expect_panic("HermitePatch::from_matrix(NaN)", move || {
                HermitePatch::from_matrix(c)
            })
        }),
        risky("shorthand::bezier_from_net_panics", || {
            let mut m = unit_net();
            m[3][0].y = f64::INFINITY;
            expect_panic("BezierPatch::from_net(inf)", move || {
                BezierPatch::from_net(m)
            })
        }),
        risky("shorthand::hermite_from_corners_panics", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_panic("HermitePatch::from_corners(Δu = 0)", move || {
                HermitePatch::from_corners(&c, 0.0, 1.0)
            })
        }),
        risky("shorthand::spline_from_surface_panics", || {
            let nan =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * f64::NAN));
            let u = ok(Partition::try_new(vec![0.0, 1.0]))?;
            expect_panic("HermiteSurface::from_surface(NaN)", move || {
                HermiteSurface::from_surface(&nan, u.clone(), u)
            })
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// Sweeps: NaN, +inf and −inf in every scalar input position of each constructor
// ---------------------------------------------------------------------------------------------

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

fn sweep_cases() -> Vec<Case> {
    vec![
        case("domain::sweep_non_finite", || {
            sweep(4, |bad, k| {
                let b = put(vec![0.0, 1.0, 2.0, 3.0], k, bad);
                expect_err!(
                    Rect::try_new(b[0], b[1], b[2], b[3]),
                    Error::NonFinite { .. }
                )?;
                expect_err!(Partition::try_new(b.clone()), Error::NonFinite { .. })?;
                if k < 2 {
                    expect_err!(Interval::try_new(b[0], b[1]), Error::NonFinite { .. })?;
                    expect_err!(Partition::uniform(b[0], b[1], 3), Error::NonFinite { .. })?;
                    expect_err!(Rect::square(b[0], b[1]), Error::NonFinite { .. })?;
                }
                Ok(())
            })
        }),
        case("surface::sweep_non_finite_radii", || {
            sweep(2, |bad, k| {
                let r = put(vec![2.0, 1.0], k, bad);
                expect_err!(Torus::try_new(r[0], r[1]), Error::NotPositive { .. })?;
                expect_err!(Sphere::try_new(bad), Error::NotPositive { .. })
            })
        }),
        case("surface::sweep_non_finite_parameters", || {
            sweep(2, |bad, k| {
                let st = put(vec![0.3, 0.7], k, bad);
                expect_err!(
                    partials_on_grid(&Sphere::default(), &[st[0]], &[st[1]]),
                    Error::NonFiniteSurface { .. }
                )
            })
        }),
        case("hermite::sweep_non_finite_data", || {
            sweep(16 * 3, |bad, k| {
                let mut c = unit_net();
                c[k / 12][(k / 3) % 4][k % 3] = bad;
                expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { .. })?;
                let mut corners = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
                let p = &mut corners[k % 2][(k / 2) % 2];
                match (k / 4) % 4 {
                    0 => p.point[k % 3] = bad,
                    1 => p.ds[k % 3] = bad,
                    2 => p.dt[k % 3] = bad,
                    _ => p.dst[k % 3] = bad,
                }
                expect_err!(
                    HermitePatch::try_from_corners(&corners, 1.0, 1.0),
                    Error::NonFinite { .. }
                )
            })
        }),
        case("hermite::sweep_non_finite_spline_parameters", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            sweep(2, |bad, k| {
                let uv = put(vec![0.5, 0.5], k, bad);
                expect_err!(sp.try_point(uv[0], uv[1]), Error::NonFinite { .. })?;
                expect_err!(
                    sp.tabulate(&[0.0, uv[0]], &[uv[1], 1.0]),
                    Error::NonFinite { .. }
                )
            })
        }),
        case("bezier::sweep_non_finite_net", || {
            sweep(16 * 3, |bad, k| {
                let mut m = unit_net();
                m[k / 12][(k / 3) % 4][k % 3] = bad;
                expect_err!(BezierPatch::try_from_net(m), Error::NonFinite { .. })
            })
        }),
        case("bspline::sweep_non_finite_inputs", || {
            sweep(5, |bad, k| {
                expect_err!(
                    KnotVector::try_new(put(vec![0.0, 0.0, 0.5, 1.0, 1.0], k, bad)),
                    Error::NonFinite { .. }
                )?;
                let mut pts = some_points(5);
                pts[k][k % 2] = bad;
                expect_err!(
                    BSplineCurve::try_new(basis(2, 5)?, pts),
                    Error::NonFinite { .. }
                )?;
                let c = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
                expect_err!(c.with_point(k, v2(bad, 0.0)), Error::NonFinite { .. })?;
                expect_err!(c.try_point(bad), Error::NonFinite { .. })?;
                if k < 2 {
                    let ab = put(vec![0.0, 1.0], k, bad);
                    expect_err!(
                        KnotVector::open_uniform(2, 5, ab[0], ab[1]),
                        Error::NonFinite { .. }
                    )?;
                    expect_err!(
                        KnotVector::extended_partition(
                            ab[0],
                            ab[1],
                            &[0.5],
                            &[1],
                            3,
                            EndKnots::Clamped
                        ),
                        Error::NonFinite { .. }
                    )?;
                }
                Ok(())
            })
        }),
        case("nurbs::sweep_non_finite_inputs", || {
            sweep(5, |bad, k| {
                expect_err!(
                    nurbs_with(put(vec![1.0; 5], k, bad)),
                    Error::NonPositiveWeight { index, .. } if *index == k
                )?;
                let mut pts = some_points(5);
                pts[k][k % 2] = bad;
                expect_err!(
                    NurbsCurve::try_new(basis(2, 5)?, pts, vec![1.0; 5]),
                    Error::NonFinite { .. }
                )?;
                let c = ok(nurbs_with(vec![1.0; 5]))?;
                expect_err!(c.with_weight(k, bad), Error::NonPositiveWeight { .. })?;
                expect_err!(c.try_point(bad), Error::NonFinite { .. })?;
                if k < 2 {
                    let mut centre = v2(0.0, 0.0);
                    centre[k] = bad;
                    expect_err!(NurbsCurve::circle7(centre, 1.0), Error::NonFinite { .. })?;
                    expect_err!(
                        NurbsCurve::circle9(v2(0.0, 0.0), bad),
                        Error::NotPositive { .. }
                    )?;
                }
                Ok(())
            })
        }),
        case("interp::sweep_non_finite_data", || {
            sweep(4, |bad, k| {
                let x = vec![0.0, 1.0, 2.0, 3.0];
                let y = vec![1.0, -1.0, 2.0, 1.0];
                let (bx, by) = (put(x.clone(), k, bad), put(y.clone(), k, bad));
                expect_err!(
                    PowerPolynomial::interpolate(&bx, &y),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    PowerPolynomial::interpolate(&x, &by),
                    Error::NonFinite { .. }
                )?;
                expect_err!(Lagrange::try_new(&bx, &y), Error::NonFinite { .. })?;
                expect_err!(Lagrange::try_new(&x, &by), Error::NonFinite { .. })?;
                let yv: Vec<Vector1<f64>> = y.iter().map(|v| v1(*v)).collect();
                let byv: Vec<Vector1<f64>> = by.iter().map(|v| v1(*v)).collect();
                expect_err!(PiecewiseLinear::try_new(&bx, &yv), Error::NonFinite { .. })?;
                expect_err!(PiecewiseLinear::try_new(&x, &byv), Error::NonFinite { .. })?;
                for end in [EndCondition::Natural, EndCondition::Anticyclic] {
                    expect_err!(CubicSpline::function(&bx, &y, end), Error::NonFinite { .. })?;
                    expect_err!(CubicSpline::function(&x, &by, end), Error::NonFinite { .. })?;
                    expect_err!(
                        collocation::cubic_spline(&bx, &yv, end),
                        Error::NonFinite { .. }
                    )?;
                    expect_err!(
                        collocation::cubic_spline(&x, &byv, end),
                        Error::NonFinite { .. }
                    )?;
                }
                expect_err!(
                    CubicSpline::function(
                        &x,
                        &y,
                        EndCondition::clamped(
                            if k % 2 == 0 { bad } else { 0.0 },
                            if k % 2 == 1 { bad } else { 0.0 }
                        )
                    ),
                    Error::NonFinite { .. }
                )?;
                expect_err!(vandermonde_condition(&bx), Error::NonFinite { .. })?;
                let sites = put(vec![0.0, 0.3, 0.7, 1.0], k, bad);
                expect_err!(
                    schoenberg_whitney(&basis(2, 4)?, &sites),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    collocation::interpolate(basis(2, 4)?, &sites, &[v1(0.0); 4], &[]),
                    Error::NonFinite { .. }
                )?;
                let mut pts = some_points(4);
                pts[k][k % 2] = bad;
                for p in Parametrization::ALL {
                    expect_err!(p.parameters(&pts), Error::NonFinite { .. })?;
                }
                expect_err!(
                    interpolate_curve(&pts, 2, Parametrization::ChordLength),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    CubicSpline::curve(&pts, Parametrization::Uniform, EndCondition::Natural),
                    Error::NonFinite { .. }
                )?;
                if k < 2 {
                    let ab = put(vec![-1.0, 1.0], k, bad);
                    for family in [NodeFamily::Equispaced, NodeFamily::Chebyshev] {
                        expect_err!(family.nodes(ab[0], ab[1], 4), Error::NonFinite { .. })?;
                    }
                }
                Ok(())
            })
        }),
        case("metrics::sweep_non_finite_entries", || {
            sweep(9, |bad, k| {
                let m = DMatrix::from_fn(3, 3, |i, j| if i * 3 + j == k { bad } else { 1.0 });
                expect_err!(matlab_norm(&m), Error::NonFinite { .. })?;
                let a = grid3(3, 3, |i, j| {
                    if i * 3 + j == k {
                        v3(0.0, bad, 0.0)
                    } else {
                        Vector3::zeros()
                    }
                });
                let z = grid3(3, 3, |_, _| Vector3::zeros());
                expect_err!(compare(&a, &z), Error::NonFinite { .. })?;
                expect_err!(compare(&z, &a), Error::NonFinite { .. })
            })
        }),
        case("blending::sweep_non_finite_points", || {
            sweep(6, |bad, k| {
                let mut pts = some_points(6);
                pts[k][k % 2] = bad;
                expect_err!(WindowCurve::lagrange(&pts), Error::NonFinite { .. })?;
                expect_err!(WindowCurve::printed_bspline(&pts), Error::NonFinite { .. })?;
                expect_err!(printed_bspline_polyline(&pts, 6), Error::NonFinite { .. })?;
                expect_err!(
                    opengl_groups(&pts, 3, LastGroup::AsPrinted),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    opengl_polyline(&pts, 4, 8, LastGroup::Truncated),
                    Error::NonFinite { .. }
                )?;
                let mut g = sliding_grid(4, 6, 1.0);
                g.as_mut_slice()[k * 4][k % 3] = bad;
                expect_err!(
                    SlidingBicubic::try_new(&g, Blending::UniformBSpline),
                    Error::NonFinite { .. }
                )
            })
        }),
    ]
}

#[cfg(not(feature = "report"))]
fn report_cases() -> Vec<Case> {
    Vec::new()
}

#[cfg(feature = "report")]
fn report_cases() -> Vec<Case> {
    use splinelab::report::draw::{self, Plot2d, Plot3d};
    use splinelab::report::{self, Error as RError};
    vec![
        case("report::write_only_unknown_id", || {
            let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
            expect_err!(
                report::write_only(dir.path(), "no-such-output"),
                RError::UnknownId { id, .. } if id == "no-such-output"
            )?;
            expect_err!(report::write_only(dir.path(), ""), RError::UnknownId { .. })
        }),
        case("report::table_write_unwritable_folder", || {
            let (_dir, file) = plain_file()?;
            let table = ok(report::table("torus-partials"))?;
            expect_err!(table.write(&file), RError::Io { path, .. } if path.starts_with(&file))
        }),
        case("report::figure_save_unwritable_folder", || {
            let (_dir, file) = plain_file()?;
            let fig = ok(report::figure("fig2-torus"))?;
            expect_err!(fig.save(&file, "fig2-torus"), RError::Io { .. })
        }),
        case("report::write_only_unwritable_folder", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                report::write_only(&file, "torus-partials"),
                RError::Io { .. }
            )
        }),
        case("report::write_only_folder_below_a_file", || {
            // a folder below a file below a folder: never a panic
            let (_dir, file) = plain_file()?;
            let deeper: &Path = &file.join("a").join("b");
            expect_err!(
                report::write_only(deeper, "torus-partials"),
                RError::Io { .. }
            )
        }),
        case("report::figure_and_table_of_the_wrong_kind", || {
            expect_err!(report::figure("t3-error"), RError::UnknownId { .. })?;
            expect_err!(report::table("fig2-torus"), RError::UnknownId { .. })
        }),
        case("draw::surface_too_few_or_too_many_samples", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            for n in [0, 1] {
                expect_err!(
                    Plot3d::new("x").surface(&f, &Rect::unit(), n),
                    RError::Core(Error::TooFewSamples { .. })
                )?;
            }
            expect_err!(
                Plot3d::new("x").surface(&f, &Rect::unit(), 1 << 20),
                RError::Core(Error::TooLarge { .. })
            )
        }),
        case("draw::surface_nan_anywhere", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, (s - 0.5).ln()));
            expect_err!(
                Plot3d::new("x").surface(&f, &Rect::unit(), 11),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("draw::error_map_bad_samples_and_nan_surface", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            let spline = ok(HermiteSurface::uniform(&f, &Rect::unit(), 2, 2))?;
            expect_err!(
                draw::error_map(&f, &spline, 1),
                RError::Core(Error::TooFewSamples { .. })
            )?;
            let g = FnSurface::new(|s, t| Vector3::new(s, t, (s - 0.3).sqrt()));
            expect_err!(
                draw::error_map(&g, &spline, 11),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("draw::degenerate_data_draws_without_panic", || {
            // empty, NaN, infinite and single-point series; empty studies and scenes
            let nan = Plot2d::new("nan", "x", "y")
                .series("empty", vec![])
                .series(
                    "nan",
                    vec![(f64::NAN, 1.0), (f64::INFINITY, 2.0), (1.0, f64::NAN)],
                )
                .series("one", vec![(1.0, 1.0)])
                .log(true, true)
                .figure();
            ok(nan.to_svg())?;
            ok(draw::convergence(&[], "empty").to_svg())?;
            ok(Plot3d::new("empty scene").figure().to_svg())?;
            ok(Plot3d::new("one point")
                .points(
                    &[Vector3::new(f64::NAN, 0.0, 1.0), Vector3::zeros()],
                    RGB_BLACK,
                    "p",
                )
                .figure()
                .to_svg())
            .map(|_| ())
        }),
        case(
            "figure::huge_size_is_clamped_and_drawn_within_memory",
            || {
                let fig = ok(report::figure("fig-bspline-bases"))?.with_size(u32::MAX, 0);
                if fig.size() != (splinelab::report::figure::MAX_SIDE, 64) {
                    return Err(format!("size {:?}", fig.size()));
                }
                ok(fig.to_rgb()).map(drop)
            },
        ),
        case("table::tabulation_bad_samples", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            expect_err!(
                report::table::tabulation(&f, &Rect::unit(), 1, 5),
                RError::Core(Error::TooFewSamples { .. })
            )?;
            expect_err!(
                report::table::tabulation(&f, &Rect::unit(), 1 << 14, 1 << 14),
                RError::Core(Error::TooLarge { .. })
            )
        }),
    ]
}

/// Black, for markers in the report cases.
#[cfg(feature = "report")]
const RGB_BLACK: plotters::style::RGBColor = plotters::style::RGBColor(0, 0, 0);

// ---------------------------------------------------------------------------------------------
// The tests
// ---------------------------------------------------------------------------------------------

// ---------------------------------------------------------------------------------------------
// seed 004: Hermite curve, cardinal and Angular splines, guide points

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

fn seed004_cases() -> Vec<Case> {
    vec![
        case("seed004::hermite_curve_one_point", || {
            expect_err!(
                HermiteCurve::try_new(vec![0.0], vec![v2(0.0, 0.0)], vec![v2(1.0, 0.0)]),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::hermite_curve_count_mismatch", || {
            expect_err!(
                HermiteCurve::try_new(
                    vec![0.0, 1.0],
                    vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                    vec![v2(1.0, 0.0)]
                ),
                Error::CountMismatch { .. }
            )
        }),
        case("seed004::hermite_curve_repeated_knot", || {
            expect_err!(
                HermiteCurve::try_new(
                    vec![0.0, 0.0],
                    vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                    vec![v2(1.0, 0.0); 2]
                ),
                Error::RepeatedParameter { .. }
            )
        }),
        case("seed004::hermite_curve_nan_tangent", || {
            expect_err!(
                HermiteCurve::try_new(
                    vec![0.0, 1.0],
                    vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                    vec![v2(f64::NAN, 0.0); 2]
                ),
                Error::NonFinite { .. }
            )
        }),
        case(
            "seed004::hermite_curve_tangent_times_width_too_large",
            || {
                expect_err!(
                    HermiteCurve::try_new(
                        vec![0.0, 1e300],
                        vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                        vec![v2(1e300, 0.0); 2]
                    ),
                    Error::CoordinateTooLarge { .. } | Error::NonFinite { .. }
                )
            },
        ),
        case("seed004::cardinal_three_points", || {
            expect_err!(
                CardinalSpline::try_new(four_points()[..3].to_vec(), 0.5),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::cardinal_a_zero", || {
            expect_err!(
                CardinalSpline::try_new(four_points(), 0.0),
                Error::NotPositive { .. }
            )
        }),
        case("seed004::cardinal_a_negative", || {
            expect_err!(
                CardinalSpline::try_new(four_points(), -0.5),
                Error::NotPositive { .. }
            )
        }),
        case("seed004::cardinal_a_nan", || {
            expect_err!(
                CardinalSpline::try_new(four_points(), f64::NAN),
                Error::NotPositive { .. }
            )
        }),
        case("seed004::cardinal_a_huge_overflows_tangent", || {
            let p = vec![v2(0.0, 0.0), v2(1.0, 1.0), v2(1e300, 0.0), v2(3.0, 1.0)];
            expect_err!(
                CardinalSpline::try_new(p, 1e10),
                Error::CoordinateTooLarge { .. } | Error::NonFinite { .. }
            )
        }),
        case("seed004::cardinal_nan_point", || {
            let mut p = four_points();
            p[2].x = f64::NAN;
            expect_err!(CardinalSpline::try_new(p, 0.5), Error::NonFinite { .. })
        }),
        case("seed004::cardinal_closed_two_points", || {
            expect_err!(
                CardinalSpline::closed(&four_points()[..2], 0.5),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::cardinal_repeated_points_are_fine", || {
            // the cardinal spline has no chord: equal consecutive points are a valid stop
            let p = vec![v2(0.0, 0.0), v2(1.0, 1.0), v2(1.0, 1.0), v2(3.0, 1.0)];
            let s = ok(CardinalSpline::try_new(p, 0.5))?;
            ensure!(finite_vecs(&ok(s.polyline(33))?), "not finite");
            Ok(())
        }),
        case("seed004::angular_three_points", || {
            expect_err!(
                AngularSpline::try_new(four_points()[..3].to_vec()),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::angular_empty", || {
            expect_err!(AngularSpline::try_new(vec![]), Error::TooFewPoints { .. })
        }),
        case("seed004::angular_repeated_point", || {
            let mut p = four_points();
            p[2] = p[1];
            expect_err!(AngularSpline::try_new(p), Error::RepeatedPoint { index: 2 })
        }),
        case("seed004::angular_repeated_guide", || {
            let mut p = four_points();
            p[1] = p[0];
            expect_err!(AngularSpline::try_new(p), Error::RepeatedPoint { index: 1 })
        }),
        case("seed004::angular_repeated_signed_zero", || {
            let p = vec![v2(0.0, 0.0), v2(-0.0, -0.0), v2(2.0, 0.0), v2(3.0, 1.0)];
            expect_err!(AngularSpline::try_new(p), Error::RepeatedPoint { index: 1 })
        }),
        case("seed004::angular_reversal", || {
            let mut p = four_points();
            p[2] = p[0];
            expect_err!(
                AngularSpline::try_new(p),
                Error::ReversedPoints { index: 1 }
            )
        }),
        case("seed004::angular_nan", || {
            let mut p = four_points();
            p[3].y = f64::NAN;
            expect_err!(AngularSpline::try_new(p), Error::NonFinite { .. })
        }),
        case("seed004::angular_infinite", || {
            let mut p = four_points();
            p[0].x = f64::NEG_INFINITY;
            expect_err!(AngularSpline::try_new(p), Error::NonFinite { .. })
        }),
        case("seed004::angular_beyond_coordinate_limit", || {
            let mut p = four_points();
            p[0].x = 2.0 * MAX_COORDINATE;
            expect_err!(AngularSpline::try_new(p), Error::CoordinateTooLarge { .. })
        }),
        case("seed004::angular_at_coordinate_limit", || {
            let m = MAX_COORDINATE / 4.0;
            let p = vec![v2(-m, -m), v2(-m, m), v2(m, m), v2(m, -m)];
            angular_ok(p)
        }),
        case("seed004::angular_subnormal_spacing", || {
            let e = 1e-310;
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(e, e),
                v2(2.0 * e, 0.0),
                v2(3.0 * e, e),
            ])
        }),
        case("seed004::angular_mixed_scales", || {
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1e-300, 0.0),
                v2(1e300, 1e300),
                v2(-1e300, 1e300),
                v2(0.0, 1.0),
            ])
        }),
        case("seed004::angular_near_reversal", || {
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1.0, 0.0),
                v2(1e-12, 1e-15),
                v2(-1.0, 1.0),
            ])
        }),
        case("seed004::angular_collinear", || {
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1.0, 0.0),
                v2(2.0, 0.0),
                v2(3.0, 0.0),
                v2(4.0, 0.0),
            ])
        }),
        case("seed004::angular_backtrack_on_line", || {
            // P₀ lies on the chord between P₁ and P₂: the tangent at P₁ points back along the
            // chord (φ = π), a spike in the limit, no G¹ piece (issue 23: it was a straight
            // piece meeting its neighbour at a cusp)
            expect_err!(
                AngularSpline::try_new(vec![
                    v2(0.5, 0.0),
                    v2(0.0, 0.0),
                    v2(1.0, 0.0),
                    v2(2.0, 1.0)
                ]),
                Error::NoSmoothPiece { point: 1, .. }
            )
        }),
        case("seed004::angular_closed_two_points", || {
            expect_err!(
                AngularSpline::closed(&four_points()[..2]),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::angular_closed_seam_repeats", || {
            let q = [v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 1.0), v2(0.0, 0.0)];
            expect_err!(AngularSpline::closed(&q), Error::RepeatedPoint { .. })
        }),
        case("seed004::angular_eval_nan_and_outside", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            expect_err!(s.try_point(f64::NAN), Error::NonFinite { .. })?;
            expect_err!(s.try_point(1.5), Error::OutOfDomain { .. })?;
            let outside = s.point(7.0);
            ensure!(
                outside == s.point(1.0),
                "outside the domain the end point, got {outside:?}"
            );
            Ok(())
        }),
        risky("seed004::angular_too_many_points", || {
            expect_err!(
                AngularSpline::closed(&vec![v2(0.0, 0.0); MAX_ELEMENTS]),
                Error::TooLarge { .. }
            )
        }),
        case("seed004::bspline_order_one", || {
            expect_err!(
                BSplineCurve::with_order(four_points(), 1),
                Error::DegreeTooLow { .. }
            )
        }),
        case("seed004::bspline_order_above_count", || {
            expect_err!(
                BSplineCurve::with_order(four_points(), 5),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::bspline_order_empty", || {
            expect_err!(
                BSplineCurve::<2>::with_order(vec![], 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::bspline_order_nan", || {
            let mut p = four_points();
            p[1].x = f64::NAN;
            expect_err!(BSplineCurve::with_order(p, 3), Error::NonFinite { .. })
        }),
        case("seed004::bspline_order_huge", || {
            let mut p = four_points();
            p[1].x = 2.0 * MAX_COORDINATE;
            expect_err!(
                BSplineCurve::with_order(p, 3),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("seed004::fit_fewer_samples_than_vertices", || {
            expect_err!(
                fit_bspline(&four_points(), 5, 3, 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::fit_one_sample", || {
            expect_err!(
                fit_bspline(&four_points()[..1], 1, 2, 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::fit_bad_order", || {
            expect_err!(
                fit_bspline(&four_points(), 3, 4, 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::fit_repeated_samples", || {
            let p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 0.0), v2(2.0, 1.0)];
            expect_err!(fit_bspline(&p, 3, 2, 2), Error::RepeatedPoint { .. })
        }),
        case("seed004::fit_undetermined_vertex", || {
            let mut p: Vec<Vector2<f64>> = (0..30).map(|i| v2(i as f64 * 1e-3, 0.0)).collect();
            p.push(v2(50.0, 1.0));
            expect_err!(fit_bspline(&p, 10, 4, 2), Error::IllConditioned { .. })
        }),
        case("seed004::fit_huge_coordinates", || {
            let m = MAX_COORDINATE / 2.0;
            let p = vec![
                v2(-m, 0.0),
                v2(0.0, m),
                v2(m, 0.0),
                v2(0.0, -m),
                v2(-m * 0.9, 0.1),
            ];
            match fit_bspline(&p, 4, 3, 5) {
                Ok(f) => {
                    ensure!(
                        finite_vecs(f.curve.points()) && f.max_distance.is_finite(),
                        "{:?}",
                        f.curve.points()
                    );
                    Ok(())
                }
                Err(
                    Error::Overflow { .. }
                    | Error::CoordinateTooLarge { .. }
                    | Error::IllConditioned { .. },
                ) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        risky("seed004::fit_too_large", || {
            let p = vec![v2(0.0, 0.0), v2(1.0, 1.0)];
            expect_err!(
                fit_bspline(&p, usize::MAX, 2, 1),
                Error::TooFewPoints { .. } | Error::TooLarge { .. }
            )
        }),
        case("seed004::shape_nan_ratio_reference", || {
            expect_err!(
                splinelab::Shape::Ellipse { ratio: f64::NAN }.reference(100),
                Error::NotPositive { .. }
            )
        }),
        case("seed004::shape_zero_rectangle_reference", || {
            let r = splinelab::Shape::Rectangle {
                width: 0.0,
                height: 1.0,
            };
            expect_err!(r.reference(100), Error::NotPositive { .. })
        }),
        case("seed004::paper_points_invalid_shape", || {
            let bad = splinelab::Shape::Parabola { half_width: -2.0 };
            expect_err!(
                splinelab::seeds::seed004::paper_points(&bad, &splinelab::Method::Angular, 5),
                Error::NotPositive { .. }
            )
        }),
        case("seed004::paper_points_tiny_counts", || {
            for (_, shape) in splinelab::seeds::seed004::SHAPES {
                for m in [
                    splinelab::Method::Angular,
                    splinelab::Method::Cardinal { a: 0.5 },
                    splinelab::Method::Linear,
                ] {
                    for count in [0, 1, 2, 3] {
                        let set = ok(splinelab::seeds::seed004::paper_points(&shape, &m, count))?;
                        let c = m.curve(&set.points, set.closed);
                        ensure!(
                            c.is_ok(),
                            "{} on {} with {count}: {}",
                            format_args!("{:?}", m),
                            shape.name(),
                            show(&c)
                        );
                    }
                }
            }
            Ok(())
        }),
        case("seed004::error_messages_at_index_zero", || {
            let text = format!(
                "{} {}",
                Error::RepeatedPoint { index: 0 },
                Error::ReversedPoints { index: 0 }
            );
            ensure!(text.contains("point 0"), "{text}");
            Ok(())
        }),
        case("seed004::method_closed_two_points", || {
            let two = [v2(0.0, 0.0), v2(1.0, 0.0)];
            expect_err!(
                splinelab::Method::Angular.curve(&two, true),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::guide_repeated", || {
            expect_err!(
                guide_point(v2(1.0, 1.0), v2(1.0, 1.0), v2(1.0, 0.0)),
                Error::RepeatedPoint { .. }
            )
        }),
        case("seed004::guide_zero_tangent", || {
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 1.0), v2(0.0, 0.0)),
                Error::Degenerate { .. }
            )
        }),
        case("seed004::guide_tangent_away", || {
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 0.0), v2(-2.0, 0.0)),
                Error::Degenerate { .. }
            )
        }),
        case("seed004::guide_nan", || {
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 0.0), v2(f64::NAN, 0.0)),
                Error::NonFinite { .. }
            )
        }),
        case("seed004::guide_nearly_away_is_far", || {
            // almost straight away: a huge circle; the guide is far but finite, or refused
            let r = guide_point(v2(0.0, 0.0), v2(1.0, 0.0), v2(-1.0, 1e-8));
            match r {
                Ok(g) => ensure!(g.iter().all(|x| x.is_finite()), "{g:?}"),
                Err(Error::Degenerate { .. } | Error::CoordinateTooLarge { .. }) => {}
                Err(e) => return Err(format!("unexpected {e}")),
            }
            Ok(())
        }),
        case("seed004::guide_at_coordinate_limit", || {
            let m = MAX_COORDINATE;
            let r = guide_point(v2(-m, 0.0), v2(m, 0.0), v2(-1.0, 0.5));
            match r {
                Ok(g) => ensure!(g.iter().all(|x| x.abs() <= MAX_COORDINATE), "{g:?}"),
                Err(Error::CoordinateTooLarge { .. }) => {}
                Err(e) => return Err(format!("unexpected {e}")),
            }
            Ok(())
        }),
    ]
}

// the cases of the API added with seed 004 and issue 13 (methods, shapes, curve metrics,
// point choice, comparison, refit, figures), in their own file
#[path = "bad_input/new_api.rs"]
mod new_api;

fn all_cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(domain_cases());
    all.extend(grid_cases());
    all.extend(surface_cases());
    all.extend(hermite_cases());
    all.extend(bezier_cases());
    all.extend(bspline_cases());
    all.extend(nurbs_cases());
    all.extend(interp_cases());
    all.extend(metrics_cases());
    all.extend(study_cases());
    all.extend(blending_cases());
    all.extend(report_cases());
    all.extend(more_cases());
    all.extend(shorthand_cases());
    all.extend(sweep_cases());
    all.extend(seed004_cases());
    all.extend(symbolic_cases());
    all.extend(fast_path_cases());
    all.extend(new_api::cases());
    all
}

/// Issue 13's fast paths: `CubicSpline::refit` / `refit_function` (the same checks as a fresh
/// build; the twisted solve's pivots that overflow), and the any-degree batch evaluation on
/// control points whose power forms overflow (the span falls back to the basis form).
fn fast_path_cases() -> Vec<Case> {
    fn natural() -> CubicSpline<1> {
        CubicSpline::function(
            &[0.0, 1.0, 2.0, 3.0],
            &[0.0, 1.0, 0.0, 1.0],
            EndCondition::Natural,
        )
        .expect("valid")
    }
    vec![
        case("fast::batch_degree_3000_declines_the_power_form", || {
            // a degree far beyond any power form: one parameter evaluated without building one
            // (it would need p(p+1)/2 weights and p³/2 ≈ 10¹⁰ operations per span)
            let p = 3000;
            let basis = BSplineBasis::try_new(
                KnotVector::open_uniform(p, p + 1, 0.0, 1.0).expect("knots"),
                p,
            )
            .expect("basis");
            let c = BSplineCurve::try_new(basis, vec![v2(1.0, 2.0); p + 1]).expect("points");
            let mut out = Vec::new();
            c.eval_many(&[0.5], &mut out);
            ensure!(
                out.len() == 1 && (out[0] - v2(1.0, 2.0)).amax() < 1e-9,
                "{out:?}"
            );
            Ok(())
        }),
        case("fast::refit_count_mismatch", || {
            expect_err!(
                natural().refit_function(&[0.0, 1.0, 2.0], &[0.0, 1.0]),
                Error::CountMismatch {
                    expected: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("fast::refit_single_point", || {
            expect_err!(
                natural().refit(&[0.0], &[nalgebra::Vector1::new(1.0)]),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("fast::refit_nan_value", || {
            expect_err!(
                natural().refit_function(&[0.0, 1.0, 2.0], &[0.0, f64::NAN, 0.0]),
                Error::NonFinite { .. }
            )
        }),
        case("fast::refit_repeated_abscissa", || {
            expect_err!(
                natural().refit_function(&[0.0, 1.0, 1.0, 2.0, 3.0], &[0.0; 5]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("fast::refit_empty", || {
            expect_err!(
                natural().refit_function(&[], &[]),
                Error::TooFewPoints { .. }
            )
        }),
        case("fast::twisted_pivot_overflow", || {
            // two neighbouring gaps of 8.8e307: the diagonal 2(hᵢ₋₁ + hᵢ) overflows
            let x = [
                -9e307, -8.99e307, -8.98e307, -8.97e307, -8.96e307, -8e306, 8e307, 8.9e307,
                8.91e307,
            ];
            let y = [0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0];
            for end in [EndCondition::Natural, EndCondition::clamped(0.0, 0.0)] {
                match CubicSpline::function(&x, &y, end) {
                    Err(Error::SingularSystem { .. } | Error::Overflow { .. }) => {}
                    Err(e) => ensure!(false, "unexpected error {e}"),
                    Ok(s) => {
                        let v = s.value(0.0);
                        ensure!(v.is_finite(), "accepted spline with value {v}");
                    }
                }
            }
            Ok(())
        }),
        case("fast::twisted_slopes_overflow", || {
            // a slope Δy/h of 1e306/1e-300: the moments overflow, a typed error
            let mut x: Vec<f64> = (0..40).map(|i| i as f64).collect();
            x[1] = 1e-300;
            let y: Vec<f64> = (0..40).map(|i| if i == 1 { 1e306 } else { 0.0 }).collect();
            expect_err!(
                CubicSpline::function(&x, &y, EndCondition::Natural),
                Error::Overflow { .. }
            )
        }),
        case("fast::batch_degree9_overflowing_power_form", || {
            // alternating ±MAX_COORDINATE: the power form's coefficients (up to 3⁹ times the
            // points) overflow, every span falls back to the basis form
            let p = 9;
            let basis =
                BSplineBasis::try_new(KnotVector::open_uniform(p, 14, 0.0, 1.0).expect("knots"), p)
                    .expect("basis");
            let pts: Vec<Vector2<f64>> = (0..14)
                .map(|i| {
                    let s = if i % 2 == 0 { 1.0 } else { -1.0 };
                    v2(s * splinelab::error::MAX_COORDINATE, 0.0)
                })
                .collect();
            let c = BSplineCurve::try_new(basis, pts).expect("finite points");
            let ts: Vec<f64> = (0..=200).map(|i| i as f64 / 200.0).collect();
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (&t, o) in ts.iter().zip(&out) {
                let r = c.point(t);
                ensure!(o.iter().all(|v| v.is_finite()), "not finite at {t}: {o:?}");
                ensure!(
                    (o - r).amax() <= 1e-12 * splinelab::error::MAX_COORDINATE,
                    "{o:?} vs {r:?}"
                );
            }
            Ok(())
        }),
    ]
}

fn symbolic_cases() -> Vec<Case> {
    use splinelab::symbolic::{
        bernstein_formulas, bspline_basis_formulas, curve_formulas, surface_formulas, trace, Trace,
        MAX_FORMULA_DEPTH, MAX_NODES,
    };
    vec![
        case("symbolic::surface_nan_point", || {
            expect_err!(
                surface_formulas(&Torus::default(), f64::NAN, 0.0),
                Error::NonFinite { .. }
            )
        }),
        case("symbolic::surface_infinite_point", || {
            expect_err!(
                surface_formulas(&Torus::default(), 0.0, f64::NEG_INFINITY),
                Error::NonFinite { .. }
            )
        }),
        case("symbolic::curve_nan_parameter", || {
            let c = NurbsCurve::circle9(v2(0.0, 0.0), 1.0).map_err(|e| e.to_string())?;
            expect_err!(curve_formulas(&c, f64::NAN), Error::NonFinite { .. })
        }),
        case("symbolic::bspline_basis_infinite_parameter", || {
            expect_err!(
                bspline_basis_formulas(&basis(2, 5)?, f64::INFINITY),
                Error::NonFinite { .. }
            )
        }),
        case(
            "symbolic::bspline_basis_outside_domain_is_its_end_span",
            || {
                // outside the domain the end span's polynomial (the curve extrapolates it)
                let b = bspline_basis_formulas(&basis(2, 5)?, -3.0).map_err(|e| e.to_string())?;
                ensure!(b.first == 0, "first function {}", b.first);
                ensure!(
                    b.functions.iter().all(|f| f.eval(&[-3.0]).is_finite()),
                    "finite"
                );
                Ok(())
            },
        ),
        case("symbolic::bernstein_degree_too_large", || {
            expect_err!(bernstein_formulas(10_000), Error::TooLarge { .. })
        }),
        case("symbolic::bernstein_degree_zero_is_one", || {
            let b = bernstein_formulas(0).map_err(|e| e.to_string())?;
            ensure!(b.len() == 1 && b[0].plain() == "1", "{:?}", b[0].plain());
            Ok(())
        }),
        case("symbolic::nesting_too_deep", || {
            let deep = trace([("x", 0.1)], |[x]| {
                let mut e = x;
                for _ in 0..=MAX_FORMULA_DEPTH {
                    e = e.cos();
                }
                vec![e]
            });
            expect_err!(deep, Error::TooLarge { .. })
        }),
        case("symbolic::nan_and_infinite_constants_are_kept", || {
            let out = trace([("x", 0.5)], |[x]| {
                vec![x + f64::NAN, x * f64::INFINITY, x / 0.0]
            })
            .map_err(|e| e.to_string())?;
            ensure!(out.formulas[0].eval(&[1.0]).is_nan(), "NaN");
            ensure!(out.formulas[1].eval(&[1.0]) == f64::INFINITY, "inf");
            ensure!(out.formulas[2].eval(&[1.0]) == f64::INFINITY, "x/0");
            Ok(())
        }),
        case("symbolic::stale_handle", || {
            let mut first = Trace::new();
            let x = first.var("x", 1.0);
            drop(first);
            let second = Trace::new();
            expect_err!(second.formula(&x), Error::Degenerate { .. })
        }),
        case("symbolic::remainder_is_opaque", || {
            let out = trace([("x", 2.5)], |[x]| vec![x % 1.0]).map_err(|e| e.to_string())?;
            ensure!(
                out.formulas[0].plain().starts_with("rem["),
                "{}",
                out.formulas[0]
            );
            ensure!(out.formulas[0].eval(&[9.0]) == 0.5, "the traced value");
            Ok(())
        }),
        case("symbolic::node_limit", || {
            let mut trace = Trace::new();
            let x = trace.var("x", 0.1);
            let mut e = x;
            // three new nodes a step (a constant, a product, a sum): past the limit halfway
            for k in 0..MAX_NODES / 2 + 10 {
                e += x * (k as f64 + 2.0);
            }
            expect_err!(trace.formula(&e), Error::TooLarge { .. })
        }),
        risky("symbolic::huge_power_not_multiplied_out", || {
            let out = trace([("x", 0.1)], |[x]| vec![(x + 1.0).powi(i32::MAX)])
                .map_err(|e| e.to_string())?;
            expect_err!(out.formulas[0].expanded(), Error::TooLarge { .. })
        }),
    ]
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
