//! Random-input (property) tests over every public constructor and evaluator of the math
//! library, checking the policy of `src/error.rs`:
//!
//! - no panic, hang or abort through the `try_*` / `Result` APIs (every test body runs inside
//!   `std::panic::catch_unwind`; a panic is a failure carrying its message, and proptest
//!   prints the minimal failing input; the one routine whose loop count is not bounded by its
//!   allocation, `Grid::try_from_fn`, runs under a watchdog thread);
//! - an `Ok` value is finite and satisfies its defining property (partition of unity of the
//!   B-spline basis, interpolation of the data, strictly increasing partitions and parameters,
//!   Hermite patches reproducing their corner data, circles of the right radius, …);
//! - evaluation of a validated object at a finite parameter in its domain (both ends included;
//!   the right end is the left limit) is finite;
//! - every fast path agrees with its reference path (`eval_many` / `values_into` /
//!   `tabulate*` against point-by-point evaluation, de Casteljau against the Bernstein sum,
//!   the one-pass B-spline basis against Cox–de Boor, the tridiagonal cubic spline against
//!   the B-spline collocation route);
//! - sizes beyond `error::MAX_ELEMENTS` are refused (sizes are drawn from small counts and
//!   from `MAX_ELEMENTS + 1`, `2⁴⁰`, `2⁶³`, `usize::MAX`; never from sizes that would really
//!   allocate gigabytes).
//!
//! Inputs are a mix of valid and invalid data: ordinary numbers, often replaced by NaN, ±∞,
//! ±0, subnormals (`5e-324`, `1e-310`), huge values (`1e300`, `1e308`, `f64::MAX`, the
//! coordinate limits), whole data sets scaled by `1e±300`, and sorted sequences with
//! near-duplicates (`x`, `x + ulp`, `x + 1e-9`), repeats and decreases. An `Err` of any kind is
//! accepted for random input and nothing more is checked.
//!
//! # Tolerances
//! - interpolation: `|s(xᵢ) − yᵢ| ≤ 4 · interp::RESIDUAL_TOLERANCE · max |y|` (absolute when
//!   the data are all zero). The library checks `RESIDUAL_TOLERANCE` on its own arithmetic;
//!   the factor 4 leaves room for the rounding of a different evaluation path
//!   (`ParametricCurve::point` instead of the library's residual loop). For B-spline
//!   collocation (`collocation::interpolate`, `cubic_spline`, `interpolate_curve`) the data
//!   scale is the one the module documents, `max(max |yᵢ|, max |bᵢ|)` over the right-hand
//!   sides divided by the largest entry of their rows (clamped slopes and derivative
//!   conditions in value units), and the residual may also be the `8ε · max ‖Pⱼ‖` rounding
//!   of evaluating the curve at the site;
//! - partition of unity: `|Σ Nᵢ(t) − 1| ≤ 1e-12`, `Nᵢ(t) ≥ −1e-15`;
//! - batch against single evaluation, Bézier forms against each other, one-pass basis against
//!   Cox–de Boor: `1e-12 ×` the largest control-point coordinate (values of the basis: `1e-12`
//!   absolute);
//! - Hermite patches and splines at their corners / nodes: `1e-12 ×` the largest entry of the
//!   Hermite matrices (the data scale);
//! - end conditions of cubic splines and the comparison of the two cubic-spline routes are
//!   checked only on well-spaced data (gaps ≥ 10⁻³ of the width, moderate magnitudes), within
//!   `1e-8` (end conditions, relative to the derivative scale, which includes the rounding
//!   level `|y|/h` and `|y|/h²` of the data) and `1e-9` (routes, relative to the value
//!   scale);
//! - every relative comparison also accepts an absolute difference of `f64::MIN_POSITIVE`:
//!   subnormal results carry no relative precision;
//! - polynomial interpolants (Lagrange, power basis) are never NaN in their domain and
//!   infinite only where their true value overflows (the Lagrange form of the data divided by
//!   `max |y|` is infinite or, times `max |y|`, above `1e300`): the policy's Lebesgue
//!   exception;
//! - derivatives (`derivative`, `derivatives2`) are required finite only where they are
//!   certainly representable (control points ≤ 1e100, knot gaps ≥ 1e-50, width ≤ 1e50, NURBS
//!   weight ratios ≥ 1e-50; well-spaced cubic-spline data).
//!
//! # Running
//! `cargo test --test random_input` runs 256 cases per target. Every target uses
//! `ProptestConfig::default()` (with failure persistence off, so no regression files are
//! written), so the case count follows `PROPTEST_CASES`:
//! `PROPTEST_CASES=10000 cargo test --release --test random_input`.

use nalgebra::{DMatrix, SVector, Vector1, Vector2, Vector3};
use num_dual::{Dual2_64, Dual64, HyperDual64};
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::sample::{select, Index};
use proptest::test_runner::TestCaseError;
use splinelab::bezier::MAX_BERNSTEIN_DEGREE;
use splinelab::bezier::MAX_RECURSIVE_POINTS;
use splinelab::blending::opengl::{opengl_groups, opengl_polyline, LastGroup};
use splinelab::blending::surface::SlidingBicubic;
use splinelab::blending::window::{printed_bspline_polyline, WindowCurve};
use splinelab::interp::collocation::{self, Condition, DerivativeOrder};
use splinelab::interp::RESIDUAL_TOLERANCE;
use splinelab::interp::{max_interpolation_error, vandermonde_condition};
use splinelab::metrics::ErrorAccumulator;
use splinelab::study::hermite_error::{
    convergence, spline_errors, uniform_spline_errors, PatchEvaluation,
};
use splinelab::tensor::{Net, NET_LIMIT};
use splinelab::NodeFamily;
use splinelab::MIN_WEIGHT_RATIO;
use splinelab::{
    bernstein3, bernstein_all, bernstein_sum, compare, de_casteljau, de_casteljau_levels,
    de_casteljau_recursive, de_casteljau_surface, fit_bspline, guide_point, hermite_basis,
    lagrange4, matlab_norm, partials_on_grid, partials_on_grid_into, printed_setbval,
    report_codice7_net, runge, tabulate, uniform_bspline4, AngularSpline, BSplineBasis,
    BSplineCurve, BezierPatch, Blending, CardinalSpline, CubicSpline, EndCondition, EndKnots,
    ExpSurface, FnSurface, Grid, HermitePatch, HermiteSurface, Interval, KnotVector, Lagrange,
    Mesh, NurbsCurve, ParametricCurve, Parametrization, Partials, Partition, PiecewiseLinear,
    PowerPolynomial, Rect, Sphere, SurfaceDerivatives, Torus,
};
use splinelab::{MAX_COORDINATE, MAX_ELEMENTS};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

type TestResult = Result<(), TestCaseError>;

// ------------------------------------------------------------------------------------------
// tolerances
// ------------------------------------------------------------------------------------------

/// Interpolation residual allowed at the data, relative to `max |y|`.
const INTERP_TOL: f64 = 4.0 * RESIDUAL_TOLERANCE;
/// Fast path against reference path, relative to the largest control-point coordinate.
const BATCH_TOL: f64 = 1e-12;
/// Hermite corner / node data, relative to the largest Hermite-matrix entry.
const CORNER_TOL: f64 = 1e-12;
/// Partition of unity.
const UNITY_TOL: f64 = 1e-12;
/// Non-negativity of the B-spline basis.
const NONNEG_TOL: f64 = 1e-15;
/// Absolute floor of every relative comparison: results below the normal range (subnormal
/// numbers) carry no relative precision, so differences below `f64::MIN_POSITIVE` are
/// underflow, not error.
const FLOOR: f64 = f64::MIN_POSITIVE;
/// How long a call may take before it counts as a hang.
const WATCHDOG: Duration = Duration::from_secs(10);

/// Every target: the default configuration (so `PROPTEST_CASES` sets the case count), no
/// regression files.
fn config() -> ProptestConfig {
    ProptestConfig {
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

// ------------------------------------------------------------------------------------------
// panics and hangs
// ------------------------------------------------------------------------------------------

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "<non-string panic payload>".to_string())
}

/// Runs a test body, turning a panic into a failure that carries the panic message.
fn guard(body: impl FnOnce() -> TestResult) -> TestResult {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(result) => result,
        Err(payload) => Err(TestCaseError::fail(format!(
            "PANIC through a Result API: {}",
            panic_message(&*payload)
        ))),
    }
}

/// Runs a test body on its own thread with a watchdog. `hung` records a hang so that the
/// shrinking that follows does not start one spinning thread per attempt: after a hang the
/// target's remaining cases pass at once and proptest reports the input that hung.
fn guard_with_watchdog(
    hung: &'static AtomicBool,
    what: String,
    body: impl FnOnce() -> TestResult + Send + 'static,
) -> TestResult {
    if hung.load(Ordering::SeqCst) {
        return Ok(());
    }
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(catch_unwind(AssertUnwindSafe(body)));
    });
    match rx.recv_timeout(WATCHDOG) {
        Ok(Ok(result)) => result,
        Ok(Err(payload)) => Err(TestCaseError::fail(format!(
            "PANIC through a Result API: {}",
            panic_message(&*payload)
        ))),
        Err(_) => {
            hung.store(true, Ordering::SeqCst);
            Err(TestCaseError::fail(format!(
                "HANG: {what} did not return within {WATCHDOG:?}"
            )))
        }
    }
}

// ------------------------------------------------------------------------------------------
// strategies
// ------------------------------------------------------------------------------------------

/// Values that break naive code.
fn special() -> impl Strategy<Value = f64> {
    select(vec![
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        5e-324,
        -5e-324,
        1e-310,
        -1e-310,
        f64::MIN_POSITIVE,
        1e-300,
        -1e-300,
        1e-9,
        1.0,
        -1.0,
        1e15,
        1e300,
        -1e300,
        1e307,
        1e308,
        -1e308,
        f64::MAX,
        -f64::MAX,
        MAX_COORDINATE,
        -MAX_COORDINATE,
        NET_LIMIT,
        -NET_LIMIT,
    ])
}

/// Ordinary finite values of a few magnitudes.
fn ordinary() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -10.0..10.0f64,
        1 => -1e6..1e6f64,
        1 => -1e-6..1e-6f64,
    ]
}

/// A number: mostly ordinary, often special, sometimes any bit pattern.
fn num() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => ordinary(),
        3 => special(),
        1 => any::<f64>(),
    ]
}

/// A positive-looking parameter (radius, width, weight), often invalid.
fn pos() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => 0.1..5.0f64,
        3 => num(),
        1 => select(vec![MAX_COORDINATE, MAX_COORDINATE / 2.0, 1e-310, 5e-324, 1e-300, 1e300]),
    ]
}

/// A common scale for a whole data set: usually 1, sometimes near the ends of the range.
fn scale() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => Just(1.0),
        1 => select(vec![1e-300, 1e-150, 1e-20, 1e20, 1e150, 1e300, 1e306, NET_LIMIT / 10.0]),
    ]
}

/// Up to three entries of a data set to replace by arbitrary numbers.
fn corruption() -> impl Strategy<Value = Vec<(Index, f64)>> {
    prop_oneof![
        3 => Just(Vec::new()),
        1 => vec((any::<Index>(), num()), 1..=3),
    ]
}

fn corrupt(v: &mut [f64], subs: &[(Index, f64)]) {
    if v.is_empty() {
        return;
    }
    for (i, x) in subs {
        v[i.index(v.len())] = *x;
    }
}

/// Data values: ordinary numbers times a common scale, a few of them corrupted; or a constant
/// (often special) value repeated.
fn values(len: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Vec<f64>> {
    let (lo, hi) = (*len.start(), *len.end());
    prop_oneof![
        5 => (vec(ordinary(), lo..=hi), scale(), corruption()).prop_map(|(mut v, s, subs)| {
            for x in &mut v {
                *x *= s;
            }
            corrupt(&mut v, &subs);
            v
        }),
        1 => (num(), lo..=hi).prop_map(|(x, n)| vec![x; n]),
    ]
}

/// One step of a generated sequence.
#[derive(Debug, Clone, Copy)]
enum Step {
    Gap(f64),
    Ulp,
    Tiny,
    Repeat,
    Back(f64),
}

fn step(repeat_weight: u32) -> impl Strategy<Value = Step> {
    prop_oneof![
        16 => (0.01..2.0f64).prop_map(Step::Gap),
        1 => Just(Step::Ulp),
        1 => Just(Step::Tiny),
        repeat_weight => Just(Step::Repeat),
        1 => (0.0..1.0f64).prop_map(Step::Back),
    ]
}

/// A mostly increasing sequence (abscissae, nodes, knots) with near-duplicates (`x + ulp`,
/// `x + 1e-9`), repeats (weight `repeat_weight`), decreases, a common scale and corruptions.
fn seq(
    len: std::ops::RangeInclusive<usize>,
    repeat_weight: u32,
) -> impl Strategy<Value = Vec<f64>> {
    (
        ordinary(),
        vec(step(repeat_weight), len),
        scale(),
        corruption(),
    )
        .prop_map(|(start, steps, s, subs)| {
            let mut x = start * s;
            let mut out = Vec::with_capacity(steps.len());
            for st in steps {
                out.push(x);
                x = match st {
                    Step::Gap(g) => x + g * s,
                    Step::Ulp => x.next_up(),
                    Step::Tiny => x + 1e-9,
                    Step::Repeat => x,
                    Step::Back(g) => x - g * s,
                };
            }
            corrupt(&mut out, &subs);
            out
        })
}

/// How a generated point relates to the previous one.
#[derive(Debug, Clone, Copy)]
enum PointOp {
    Fresh,
    Copy,
    Ulp,
    Tiny,
}

fn point_op() -> impl Strategy<Value = PointOp> {
    prop_oneof![
        16 => Just(PointOp::Fresh),
        1 => Just(PointOp::Copy),
        1 => Just(PointOp::Ulp),
        1 => Just(PointOp::Tiny),
    ]
}

/// Points in ℝᴺ: ordinary coordinates times a common scale, with repeated and nearly repeated
/// consecutive points and a few corrupted coordinates.
fn points<const N: usize>(
    len: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = Vec<SVector<f64, N>>> {
    (
        vec((prop::array::uniform::<_, N>(ordinary()), point_op()), len),
        scale(),
        corruption(),
    )
        .prop_map(|(raw, s, subs)| {
            let mut out: Vec<SVector<f64, N>> = Vec::with_capacity(raw.len());
            for (coords, op) in raw {
                let fresh = SVector::<f64, N>::from(coords) * s;
                let p = match (op, out.last()) {
                    (PointOp::Copy, Some(q)) => *q,
                    (PointOp::Ulp, Some(q)) => q.map(f64::next_up),
                    (PointOp::Tiny, Some(q)) => q.map(|x| x + 1e-9),
                    _ => fresh,
                };
                out.push(p);
            }
            if !out.is_empty() {
                for (i, x) in subs {
                    let k = i.index(out.len() * N);
                    out[k / N][k % N] = x;
                }
            }
            out
        })
}

/// A pair of interval bounds: ordinary intervals, arbitrary pairs, near-empty ones.
fn pair() -> impl Strategy<Value = (f64, f64)> {
    prop_oneof![
        4 => (ordinary(), 0.01..10.0f64).prop_map(|(a, w)| (a, a + w)),
        2 => (num(), num()),
        1 => num().prop_map(|a| (a, a.next_up())),
        1 => num().prop_map(|a| (a, a + 1e-9)),
        1 => (ordinary(), 0.01..10.0f64, scale()).prop_map(|(a, w, s)| (a * s, (a + w) * s)),
    ]
}

/// Sizes that must be refused without allocating.
const HUGE: [usize; 4] = [MAX_ELEMENTS + 1, 1 << 40, (usize::MAX >> 1) + 1, usize::MAX];

/// A count: mostly from `small`, sometimes beyond every limit.
fn count(small: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = usize> {
    prop_oneof![
        12 => small,
        1 => select(HUGE.to_vec()),
    ]
}

/// A grid side: small, often 0 (a huge side beside an empty one allocates nothing), or huge.
fn grid_size() -> impl Strategy<Value = usize> {
    prop_oneof![
        6 => 0usize..=12,
        2 => Just(0usize),
        2 => select(HUGE.to_vec()),
    ]
}

/// Fractions of a domain at which to evaluate.
fn fracs() -> impl Strategy<Value = Vec<f64>> {
    vec(
        prop_oneof![
            4 => 0.0..=1.0f64,
            1 => Just(0.0),
            1 => Just(1.0),
            1 => Just(0.5),
        ],
        0..6,
    )
}

/// A parameter of the unit interval (often an end).
fn unit() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => 0.0..=1.0f64,
        1 => Just(0.0),
        1 => Just(1.0),
        1 => Just(1.0f64.next_down()),
        1 => Just(5e-324),
    ]
}

fn unit_pairs() -> impl Strategy<Value = Vec<(f64, f64)>> {
    vec((unit(), unit()), 0..6)
}

/// Which surface a test uses.
#[derive(Debug, Clone, Copy)]
enum Surf {
    Torus(f64, f64),
    Sphere(f64),
    Exp,
    Saddle,
}

fn surf() -> impl Strategy<Value = Surf> {
    prop_oneof![
        3 => (pos(), pos()).prop_map(|(a, b)| Surf::Torus(a, b)),
        2 => pos().prop_map(Surf::Sphere),
        1 => Just(Surf::Exp),
        1 => Just(Surf::Saddle),
    ]
}

fn saddle(s: HyperDual64, t: HyperDual64) -> Vector3<HyperDual64> {
    Vector3::new(s, t, s * t)
}

type DynSurface = Box<dyn SurfaceDerivatives + Sync>;

/// The surface, or `None` if its constructor refuses the parameters (checked finite if `Ok`).
fn build_surface(kind: Surf) -> Result<Option<DynSurface>, TestCaseError> {
    Ok(match kind {
        Surf::Torus(major, minor) => match Torus::try_new(major, minor) {
            Ok(t) => {
                prop_assert!(
                    t.major().is_finite()
                        && t.major() > 0.0
                        && t.minor().is_finite()
                        && t.minor() > 0.0,
                    "torus radii {} {}",
                    t.major(),
                    t.minor()
                );
                Some(Box::new(t))
            }
            Err(_) => None,
        },
        Surf::Sphere(r) => match Sphere::try_new(r) {
            Ok(s) => {
                prop_assert!(s.radius().is_finite() && s.radius() > 0.0);
                Some(Box::new(s))
            }
            Err(_) => None,
        },
        Surf::Exp => Some(Box::new(ExpSurface)),
        Surf::Saddle => Some(Box::new(FnSurface::new(
            saddle as fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64>,
        ))),
    })
}

fn end1() -> impl Strategy<Value = EndCondition<1>> {
    prop_oneof![
        Just(EndCondition::Natural),
        Just(EndCondition::Periodic),
        Just(EndCondition::Cyclic),
        Just(EndCondition::Anticyclic),
        (num(), num()).prop_map(|(a, b)| EndCondition::clamped(a, b)),
        (ordinary(), ordinary()).prop_map(|(a, b)| EndCondition::clamped(a, b)),
    ]
}

fn end2() -> impl Strategy<Value = EndCondition<2>> {
    prop_oneof![
        Just(EndCondition::Natural),
        Just(EndCondition::Periodic),
        Just(EndCondition::Cyclic),
        Just(EndCondition::Anticyclic),
        (prop::array::uniform2(num()), prop::array::uniform2(num())).prop_map(|(a, b)| {
            EndCondition::Clamped {
                start: Vector2::from(a),
                end: Vector2::from(b),
            }
        }),
        (
            prop::array::uniform2(ordinary()),
            prop::array::uniform2(ordinary())
        )
            .prop_map(|(a, b)| EndCondition::Clamped {
                start: Vector2::from(a),
                end: Vector2::from(b),
            }),
    ]
}

/// How far (relative to `max(1, |y₀|)`) the last value of periodic data is from the first:
/// `None` leaves the data alone.
fn periodic_delta() -> impl Strategy<Value = Option<f64>> {
    prop_oneof![
        2 => Just(None),
        3 => Just(Some(0.0)),
        1 => select(vec![1e-13, 9e-13, 2e-12]).prop_map(Some),
    ]
}

fn param() -> impl Strategy<Value = Parametrization> {
    select(Parametrization::ALL.to_vec())
}

/// Knot vectors: a mostly non-decreasing sequence with frequent repeats, optionally clamped
/// (first and last knot repeated `extra` more times).
fn knots() -> impl Strategy<Value = Vec<f64>> {
    (seq(2..=12, 5), 0usize..=4).prop_map(|(mut k, extra)| {
        if let (Some(&first), Some(&last)) = (k.first(), k.last()) {
            for _ in 0..extra {
                k.insert(0, first);
                k.push(last);
            }
        }
        k
    })
}

fn weights() -> impl Strategy<Value = Vec<f64>> {
    vec(
        prop_oneof![
            8 => 0.1..10.0f64,
            1 => select(vec![
                MIN_WEIGHT_RATIO,
                1e-281,
                1e-300,
                5e-324,
                1e-15,
                1e300,
                f64::MAX,
                0.0,
                -1.0,
                f64::NAN,
                f64::INFINITY,
            ]),
            1 => num(),
        ],
        0..=20,
    )
}

// ------------------------------------------------------------------------------------------
// helpers
// ------------------------------------------------------------------------------------------

/// NaN-propagating max.
fn nanmax(m: f64, x: f64) -> f64 {
    if x.is_nan() || x > m || m.is_nan() {
        if m.is_nan() {
            m
        } else {
            x
        }
    } else {
        m
    }
}

/// `‖v‖_∞`, NaN-propagating (nalgebra's `amax` skips NaN).
fn amax<const N: usize>(v: &SVector<f64, N>) -> f64 {
    v.iter().fold(0.0, |m, &x| nanmax(m, x.abs()))
}

fn max_norm<const N: usize>(pts: &[SVector<f64, N>]) -> f64 {
    pts.iter().map(amax).fold(0.0, nanmax)
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| nanmax(m, x.abs()))
}

fn finite<const N: usize>(v: &SVector<f64, N>) -> bool {
    v.iter().all(|x| x.is_finite())
}

fn all_finite<const N: usize>(pts: &[SVector<f64, N>]) -> bool {
    pts.iter().all(finite)
}

fn net_max(net: &Net) -> f64 {
    net.iter().flatten().map(amax).fold(0.0, nanmax)
}

/// Valid data for evaluation routines that do not validate: finite and within the coordinate
/// limit.
fn valid_points<const N: usize>(pts: &[SVector<f64, N>]) -> bool {
    pts.iter()
        .flat_map(|p| p.iter())
        .all(|x| x.is_finite() && x.abs() <= MAX_COORDINATE)
}

/// `v` resized to `len` (cycling its entries, or `fill` when it is empty).
fn fit<T: Clone>(v: &[T], len: usize, fill: T) -> Vec<T> {
    if v.is_empty() {
        return vec![fill; len];
    }
    (0..len).map(|i| v[i % v.len()].clone()).collect()
}

/// `len`, or one off it when `mismatch`.
fn maybe_off(len: usize, mismatch: bool) -> usize {
    if mismatch {
        if len.is_multiple_of(2) {
            len + 1
        } else {
            len - 1
        }
    } else {
        len
    }
}

/// MATLAB's `linspace` as the library computes it (last sample exact).
fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    let step = (b - a) / (n - 1) as f64;
    let mut v: Vec<f64> = (0..n).map(|k| a + k as f64 * step).collect();
    v[n - 1] = b;
    v
}

/// Evaluation parameters in `[a, b]`: both ends, their neighbours, fractions of the width and
/// the `extra` values that lie in the domain (knots, nodes).
fn domain_params(a: f64, b: f64, fr: &[f64], extra: &[f64]) -> Vec<f64> {
    let mut v = vec![a, b, a.next_up().min(b), b.next_down().max(a)];
    let w = b - a;
    if w.is_finite() {
        for &f in fr {
            v.push((a + f * w).clamp(a, b));
            v.push((b - f * w).clamp(a, b));
        }
    }
    for &e in extra {
        if a <= e && e <= b {
            v.push(e);
        }
    }
    v
}

/// Parameters for batch evaluation: sorted, then reversed, then as given (the span / interval
/// cursors must be right in any order), with a few outside the domain (checked for no panic
/// only).
fn batch_params(params: &[f64], a: f64, b: f64) -> (Vec<f64>, Vec<bool>) {
    let mut sorted = params.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mut ts = sorted.clone();
    ts.extend(sorted.iter().rev());
    ts.extend_from_slice(params);
    let w = b - a;
    if w.is_finite() {
        ts.insert(ts.len() / 2, a - 0.5 * w);
        ts.push(b + 0.25 * w);
    }
    let inside = ts.iter().map(|&t| a <= t && t <= b).collect();
    (ts, inside)
}

/// A strictly increasing, finite sequence whose gaps have finite reciprocals.
fn check_strict(what: &str, x: &[f64]) -> TestResult {
    prop_assert!(
        x.iter().all(|v| v.is_finite()),
        "{}: non-finite value in {:?}",
        what,
        x
    );
    for w in x.windows(2) {
        prop_assert!(w[0] < w[1], "{}: not strictly increasing: {:?}", what, x);
        let gap = w[1] - w[0];
        prop_assert!(
            gap.is_finite() && (1.0 / gap).is_finite(),
            "{}: gap {:e} (or its reciprocal) not finite in {:?}",
            what,
            gap,
            x
        );
    }
    Ok(())
}

/// Interpolation: `got(i)` reproduces `data[i]` within [`INTERP_TOL`] of `max |data|`.
fn check_interp<const N: usize>(
    what: &str,
    data: &[SVector<f64, N>],
    got: impl Fn(usize) -> SVector<f64, N>,
) -> TestResult {
    check_interp_scaled(what, data, max_norm(data), 0.0, got)
}

/// What B-spline collocation states it leaves at its data, on the curve itself:
/// `COLLOCATION_MISS` of the data scale (issue 39: the control points' size is no excuse —
/// huge control points that miss the data by O(1) are refused).
fn collocation_miss(scale: f64) -> f64 {
    splinelab::interp::collocation::COLLOCATION_MISS * scale
}

/// The data scale B-spline collocation documents for its residual: `max |yᵢ|` and every
/// right-hand side (site values and condition values) divided by the largest entry of its
/// row of the collocation matrix, i.e. derivative data in value units.
fn collocation_scale<const N: usize>(
    basis: &BSplineBasis,
    sites: &[f64],
    values: &[SVector<f64, N>],
    conditions: &[Condition<N>],
) -> f64 {
    let row_max = |terms: &[(f64, f64)], order: DerivativeOrder| {
        let k = match order {
            DerivativeOrder::Value => 0,
            DerivativeOrder::First => 1,
            DerivativeOrder::Second => 2,
        };
        let mut row = vec![0.0; basis.len()];
        for &(x, w) in terms {
            let (span, d) = basis.nonzero_derivatives(x);
            for (j, v) in d.iter().enumerate() {
                row[span - basis.degree() + j] += w * v[k];
            }
        }
        max_abs(&row)
    };
    let per_row = |value: &SVector<f64, N>, big: f64| {
        if big > 0.0 && big.is_finite() {
            amax(value) / big
        } else {
            0.0
        }
    };
    let mut scale = max_norm(values);
    for (&x, y) in sites.iter().zip(values) {
        scale = nanmax(
            scale,
            per_row(y, row_max(&[(x, 1.0)], DerivativeOrder::Value)),
        );
    }
    for c in conditions {
        scale = nanmax(scale, per_row(&c.value, row_max(&c.terms, c.order)));
    }
    scale
}

/// Interpolation: `got(i)` reproduces `data[i]` within [`INTERP_TOL`] of `scale`, plus the
/// absolute `noise` of the evaluation path (see [`collocation_miss`]).
fn check_interp_scaled<const N: usize>(
    what: &str,
    data: &[SVector<f64, N>],
    scale: f64,
    noise: f64,
    got: impl Fn(usize) -> SVector<f64, N>,
) -> TestResult {
    for (i, y) in data.iter().enumerate() {
        let g = got(i);
        prop_assert!(
            finite(&g),
            "{}: non-finite value {:?} at data point {}",
            what,
            g,
            i
        );
        let r = amax(&(g - y));
        let rel = if scale > 0.0 { r / scale } else { r };
        prop_assert!(
            rel <= INTERP_TOL || r <= FLOOR || r <= noise,
            "{}: misses data point {} ({:?}) by {:e} (relative {:e} > {:e} of the data scale {:e}); got {:?}",
            what,
            i,
            y,
            r,
            rel,
            INTERP_TOL,
            scale,
            g
        );
    }
    Ok(())
}

/// Batch evaluation against point-by-point evaluation (in-domain entries), within
/// [`BATCH_TOL`] `× scale`.
fn check_batch<const N: usize>(
    what: &str,
    ts: &[f64],
    inside: &[bool],
    batch: &[SVector<f64, N>],
    single: impl Fn(f64) -> SVector<f64, N>,
    scale: f64,
) -> TestResult {
    prop_assert_eq!(batch.len(), ts.len(), "{}: batch length", what);
    for ((&t, &ok), b) in ts.iter().zip(inside).zip(batch) {
        if !ok {
            continue;
        }
        let s = single(t);
        prop_assert!(
            finite(b) && finite(&s),
            "{}: non-finite value at t = {:e}: batch {:?}, single {:?}",
            what,
            t,
            b,
            s
        );
        let d = amax(&(b - s));
        prop_assert!(
            d <= BATCH_TOL * scale + FLOOR,
            "{}: batch {:?} vs single {:?} at t = {:e}: difference {:e} > {:e} × {:e}",
            what,
            b,
            s,
            t,
            d,
            BATCH_TOL,
            scale
        );
    }
    Ok(())
}

/// The checks every curve gets: a finite, non-empty domain; finite points at in-domain
/// parameters (and `try_point` equal to `point` there); a NaN parameter refused; a finite
/// polyline.
fn check_curve<const N: usize, C: ParametricCurve<N>>(
    what: &str,
    c: &C,
    params: &[f64],
    samples: usize,
) -> TestResult {
    let (a, b) = c.domain();
    prop_assert!(
        a.is_finite() && b.is_finite() && a < b,
        "{}: domain [{:e}, {:e}]",
        what,
        a,
        b
    );
    for &t in params {
        let p = c.point(t);
        prop_assert!(
            finite(&p),
            "{}: non-finite point {:?} at t = {:e} in [{:e}, {:e}]",
            what,
            p,
            t,
            a,
            b
        );
        let q = c.try_point(t);
        prop_assert!(
            q.as_ref().is_ok_and(|q| q == &p),
            "{}: try_point({:e}) = {:?} but point = {:?}",
            what,
            t,
            q,
            p
        );
    }
    prop_assert!(
        c.try_point(f64::NAN).is_err(),
        "{}: try_point(NaN) accepted",
        what
    );
    if let Ok(poly) = c.polyline(samples) {
        prop_assert_eq!(poly.len(), samples, "{}: polyline length", what);
        prop_assert!(
            all_finite(&poly),
            "{}: non-finite polyline {:?}",
            what,
            poly
        );
    }
    Ok(())
}

/// Derivatives up to the second at in-domain parameters are finite (called only for objects
/// whose derivatives are known to be representable).
fn check_derivatives<const N: usize, C: ParametricCurve<N>>(
    what: &str,
    c: &C,
    params: &[f64],
) -> TestResult {
    for &t in params {
        let d = c.derivatives2(t);
        prop_assert!(
            d.iter().all(finite),
            "{}: non-finite derivatives {:?} at t = {:e}",
            what,
            d,
            t
        );
        let d1 = c.derivative(t);
        prop_assert!(
            finite(&d1),
            "{}: non-finite derivative {:?} at t = {:e}",
            what,
            d1,
            t
        );
    }
    Ok(())
}

fn check_interval(what: &str, iv: &Interval, a: f64, b: f64) -> TestResult {
    prop_assert!(iv.start() == a && iv.end() == b, "{}: bounds changed", what);
    prop_assert!(
        a.is_finite() && b.is_finite() && a < b,
        "{}: [{:e}, {:e}]",
        what,
        a,
        b
    );
    let w = iv.width();
    prop_assert!(
        w.is_finite() && w > 0.0 && (1.0 / w).is_finite(),
        "{}: width {:e} of [{:e}, {:e}] (or its reciprocal) not finite",
        what,
        w,
        a,
        b
    );
    Ok(())
}

/// Partials record from 12 consecutive numbers.
fn partials_from(d: &[f64]) -> Partials {
    let v = |k: usize| Vector3::new(d[3 * k], d[3 * k + 1], d[3 * k + 2]);
    Partials {
        point: v(0),
        ds: v(1),
        dt: v(2),
        dst: v(3),
    }
}

fn net_from(d: &[f64]) -> Net {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let k = 3 * (4 * i + j);
            Vector3::new(d[k], d[k + 1], d[k + 2])
        })
    })
}

/// 48 numbers for a net or four corners: random values, or one value repeated (constant nets
/// near the coordinate limits are the hard case for derived nets).
fn net_values() -> impl Strategy<Value = Vec<f64>> {
    prop_oneof![
        3 => values(48..=48),
        1 => num().prop_map(|x| vec![x; 48]),
    ]
}

/// Data that the end-condition and cross-route checks of cubic splines accept as well
/// conditioned: gaps at least 10⁻³ of the width, moderate magnitudes.
fn well_spaced(x: &[f64], y_scale: f64, slope_scale: f64) -> bool {
    if x.len() < 3 {
        return false;
    }
    let w = x[x.len() - 1] - x[0];
    let min_gap = x
        .windows(2)
        .map(|p| p[1] - p[0])
        .fold(f64::INFINITY, f64::min);
    let offset = x[0].abs().max(x[x.len() - 1].abs());
    (1e-100..=1e100).contains(&w)
        && min_gap >= 1e-3 * w
        && offset <= 1e6 * w
        && (1e-2..=1e100).contains(&y_scale)
        && slope_scale * w <= 1e6 * y_scale
}

/// The end conditions of an interpolating cubic spline, from `[s, s′, s″]` at both ends and the
/// second derivatives at the nodes (well-spaced data only).
fn check_end_conditions<const N: usize>(
    what: &str,
    end: &EndCondition<N>,
    x: &[f64],
    y: &[SVector<f64, N>],
    d: impl Fn(f64) -> [SVector<f64, N>; 3],
) -> TestResult {
    let (a, b) = (x[0], x[x.len() - 1]);
    let (da, db) = (d(a), d(b));
    let slopes = x
        .windows(2)
        .zip(y.windows(2))
        .map(|(xw, yw)| amax(&((yw[1] - yw[0]) / (xw[1] - xw[0]))))
        .fold(0.0, nanmax);
    // the rounding of the data alone moves s′ by about ε|y|/h and s″ by ε|y|/h²: the scales
    // include |y|/h and |y|/h² so that data constant to rounding are not judged by their noise
    let h_min = x
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min);
    let y_scale = max_norm(y);
    let mut d1_scale = slopes
        .max(amax(&da[1]))
        .max(amax(&db[1]))
        .max(y_scale / h_min);
    let mut d2_scale = x.iter().map(|&xi| amax(&d(xi)[2])).fold(0.0, nanmax);
    d2_scale = d2_scale
        .max(amax(&da[2]))
        .max(amax(&db[2]))
        .max(y_scale / (h_min * h_min));
    if let EndCondition::Clamped { start, end } = end {
        d1_scale = d1_scale.max(amax(start)).max(amax(end));
    }
    let tol = 1e-8;
    let (e1, e2) = match end {
        EndCondition::Clamped { start, end } => {
            (amax(&(da[1] - start)).max(amax(&(db[1] - end))), 0.0)
        }
        EndCondition::Natural => (0.0, amax(&da[2]).max(amax(&db[2]))),
        EndCondition::Periodic | EndCondition::Cyclic => {
            (amax(&(da[1] - db[1])), amax(&(da[2] - db[2])))
        }
        EndCondition::Anticyclic => (amax(&(da[1] + db[1])), amax(&(da[2] + db[2]))),
    };
    prop_assert!(
        e1 <= tol * d1_scale && e2 <= tol * d2_scale,
        "{}: {} end condition violated: first-derivative error {:e} (scale {:e}), second {:e} (scale {:e}); ends {:?} {:?}",
        what,
        format_args!("{:?}", end),
        e1,
        d1_scale,
        e2,
        d2_scale,
        da,
        db
    );
    Ok(())
}

/// `Grid` of points from row-major numbers.
fn grid3(rows: usize, cols: usize, d: &[f64]) -> Grid<Vector3<f64>> {
    let pts: Vec<Vector3<f64>> = (0..rows * cols)
        .map(|k| {
            let f = |c: usize| {
                if d.is_empty() {
                    0.0
                } else {
                    d[(3 * k + c) % d.len()]
                }
            };
            Vector3::new(f(0), f(1), f(2))
        })
        .collect();
    Grid::from_vec(rows, cols, pts).expect("rows × cols points")
}

// ------------------------------------------------------------------------------------------
// targets
// ------------------------------------------------------------------------------------------

static GRID_HUNG: AtomicBool = AtomicBool::new(false);

/// G¹ at every joint of every Angular curve built (issue 23: no exception for straight
/// pieces or halves): each piece leaves and reaches its points along their circle tangents,
/// and adjacent pieces' one-sided directions agree.
fn check_angular_g1(c: &AngularSpline) -> Result<(), TestCaseError> {
    let mut ends: Vec<(Vector2<f64>, Vector2<f64>)> = Vec::new();
    for j in 0..c.pieces() {
        let mut dirs = [Vector2::zeros(); 2];
        for (k, (s, t)) in [(0.0, c.tangents()[j]), (1.0, c.tangents()[j + 1])]
            .into_iter()
            .enumerate()
        {
            let e = c.eval_piece(j, Dual2_64::from_re(s).derivative());
            let d = e.map(|x| x.v1);
            prop_assert!(finite(&d), "piece {} at {}: {:?}", j, s, d);
            // scaled by the largest component first, so no square overflows
            let m = d.amax();
            prop_assert!(
                m > 0.0,
                "piece {} at s = {}: a vanishing tangent {:?}",
                j,
                s,
                d
            );
            let u = (d / m).normalize();
            prop_assert!(
                u.perp(&t).abs() <= 1e-6 && u.dot(&t) > 0.0,
                "piece {} at s = {}: direction {:?} vs tangent {:?}",
                j,
                s,
                u,
                t
            );
            dirs[k] = u;
        }
        ends.push((dirs[0], dirs[1]));
    }
    for j in 1..ends.len() {
        let (l, r) = (ends[j - 1].1, ends[j].0);
        prop_assert!(
            l.perp(&r).abs() <= 2e-6 && l.dot(&r) > 0.0,
            "joint {}: {:?} vs {:?}",
            j,
            l,
            r
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    /// `Interval::try_new`, `linspace`, `to_local`; `Rect::try_new`, `Rect::square`.
    #[test]
    fn interval_and_rect((a, b) in pair(), (c, d) in pair(), n in count(0..=40), fr in fracs()) {
        guard(|| {
            if let Ok(iv) = Interval::try_new(a, b) {
                check_interval("interval", &iv, a, b)?;
                for x in domain_params(a, b, &fr, &[]) {
                    prop_assert!(iv.contains(x));
                    let l = iv.to_local(x);
                    prop_assert!(l.is_finite() && (0.0..=1.0).contains(&l), "to_local({:e}) = {:e}", x, l);
                }
                if let Ok(v) = iv.linspace(n) {
                    prop_assert_eq!(v.len(), n);
                    prop_assert!(v[0] == a && v[n - 1] == b, "linspace ends {:?}", v);
                    prop_assert!(v.iter().all(|x| x.is_finite() && a <= *x && *x <= b), "linspace outside [a, b]: {:?}", v);
                    prop_assert!(v.windows(2).all(|w| w[0] <= w[1]), "linspace decreases: {:?}", v);
                }
            }
            if let Ok(r) = Rect::try_new(a, b, c, d) {
                check_interval("rect s", &r.s, a, b)?;
                check_interval("rect t", &r.t, c, d)?;
            }
            if let Ok(r) = Rect::square(a, b) {
                check_interval("square s", &r.s, a, b)?;
                check_interval("square t", &r.t, a, b)?;
            }
            Ok(())
        })?;
    }

    /// `Mesh::try_of_surface` (issue 29) on a torus and a sphere of any radii and a scaled
    /// saddle, on any rectangle and grid: an `Ok` mesh has finite vertices on the surface,
    /// unit normals, texture coordinates in [0, 1], 2(n − 1)(m − 1) triangles of valid
    /// indices; a refusal is a typed error, never a panic.
    #[test]
    fn mesh_of_surface(
        (a, b) in pair(),
        (c, d) in pair(),
        ns in count(0..=24),
        nt in count(0..=24),
        (r0, r1) in pair(),
        which in 0usize..3,
    ) {
        guard(|| {
            let Ok(rect) = Rect::try_new(a, b, c, d) else { return Ok(()) };
            let saddle = FnSurface::new(move |s: HyperDual64, t: HyperDual64| {
                Vector3::new(s, t, s * t * r0)
            });
            let surface: Box<dyn SurfaceDerivatives + Sync> = match which {
                0 => match Torus::try_new(r0.abs(), r1.abs()) {
                    Ok(t) => Box::new(t),
                    Err(_) => return Ok(()),
                },
                1 => match Sphere::try_new(r0.abs()) {
                    Ok(s) => Box::new(s),
                    Err(_) => return Ok(()),
                },
                _ => Box::new(saddle),
            };
            let Ok(m) = Mesh::try_of_surface(surface.as_ref(), &rect, ns, nt) else {
                return Ok(());
            };
            prop_assert_eq!(m.positions().len(), ns * nt);
            prop_assert_eq!(m.triangles().len(), 2 * (ns - 1) * (nt - 1));
            let scale = m.positions().iter().fold(0.0f64, |x, p| x.max(p.amax())).max(1.0);
            for (k, p) in m.positions().iter().enumerate() {
                let (i, j) = (k / nt, k % nt);
                let (s, t) = (rect.s.linspace(ns).unwrap()[i], rect.t.linspace(nt).unwrap()[j]);
                prop_assert!(p.iter().all(|x| x.is_finite()));
                prop_assert!((p - surface.point(s, t)).amax() <= 1e-15 * scale, "vertex {} off the surface", k);
                let n = m.normals()[k];
                prop_assert!(n.iter().all(|x| x.is_finite()) && (n.norm() - 1.0).abs() < 1e-12, "normal {:?}", n);
                let uv = m.uvs()[k];
                prop_assert!(uv.iter().all(|x| (0.0..=1.0).contains(x)), "uv {:?}", uv);
            }
            prop_assert!(m.triangles().iter().flatten().all(|&q| (q as usize) < ns * nt));
            Ok(())
        })?;
    }

    /// `Partition::try_new`: strictly increasing finite nodes; `locate` and `interval`.
    #[test]
    fn partition_try_new(nodes in seq(0..=12, 1), fr in fracs()) {
        guard(|| {
            if let Ok(p) = Partition::try_new(nodes.clone()) {
                let k = p.nodes();
                prop_assert_eq!(k, &nodes[..]);
                check_strict("partition nodes", k)?;
                let last = k.len() - 1;
                prop_assert_eq!(p.len(), last);
                let span = p.span();
                check_interval("partition span", &span, k[0], k[last])?;
                for i in 0..p.len() {
                    let iv = p.interval(i);
                    check_interval("partition piece", &iv, k[i], k[i + 1])?;
                    prop_assert_eq!(p.locate(k[i]), i, "breakpoint {} belongs to the piece on its right", i);
                }
                prop_assert_eq!(p.locate(k[last]), p.len() - 1, "right end belongs to the last piece");
                for x in domain_params(k[0], k[last], &fr, k) {
                    let i = p.locate(x);
                    prop_assert!(i < p.len());
                    let iv = p.interval(i);
                    prop_assert!(iv.start() <= x && x <= iv.end(), "locate({:e}) = {} ({:?})", x, i, iv);
                    let l = iv.to_local(x);
                    prop_assert!(l.is_finite() && (0.0..=1.0).contains(&l), "to_local {:e}", l);
                }
            }
            Ok(())
        })?;
    }

    /// `Partition::uniform`: `n + 1` strictly increasing nodes from `a` to `b`.
    #[test]
    fn partition_uniform((a, b) in pair(), n in count(0..=40)) {
        guard(|| {
            if let Ok(p) = Partition::uniform(a, b, n) {
                let k = p.nodes();
                prop_assert_eq!(k.len(), n + 1);
                prop_assert!(k[0] == a && k[n] == b, "ends {:?}", k);
                check_strict("uniform partition", k)?;
            }
            Ok(())
        })?;
    }

    /// `Grid::try_from_fn` (under a watchdog: its loops run `rows × cols` times but also
    /// `rows` times) and `Grid::from_vec`.
    #[test]
    fn grid(rows in grid_size(), cols in grid_size(), extra in 0usize..3) {
        guard_with_watchdog(&GRID_HUNG, format!("Grid::try_from_fn({rows}, {cols}, _)"), move || {
            if let Ok(g) = Grid::try_from_fn(rows, cols, |i, j| (i, j)) {
                prop_assert!(rows.saturating_mul(cols) <= MAX_ELEMENTS);
                prop_assert_eq!((g.rows(), g.cols()), (rows, cols));
                prop_assert_eq!(g.as_slice().len(), rows * cols);
                for i in 0..rows.min(12) {
                    for j in 0..cols.min(12) {
                        prop_assert_eq!(*g.get(i, j), (i, j));
                    }
                }
            }
            if let Some(len) = rows.checked_mul(cols).filter(|&l| l <= 200) {
                let g = Grid::from_vec(rows, cols, vec![0u8; len + extra]);
                prop_assert_eq!(g.is_some(), extra == 0);
            }
            Ok(())
        })?;
    }

    /// `Torus::try_new`, `Sphere::try_new` (finite partials everywhere) and `tabulate` of every
    /// kind of surface.
    #[test]
    fn surface_tabulate(kind in surf(), (sa, sb) in pair(), (ta, tb) in pair(), ns in count(0..=8), nt in count(0..=8), st in vec((num(), num()), 0..4)) {
        guard(|| {
            let Some(surface) = build_surface(kind)? else { return Ok(()) };
            if matches!(kind, Surf::Torus(..) | Surf::Sphere(_)) {
                for &(s, t) in &st {
                    if s.is_finite() && t.is_finite() {
                        let p = surface.partials(s, t);
                        prop_assert!(
                            [p.point, p.ds, p.dt, p.dst].iter().all(finite),
                            "validated {:?}: non-finite partials {:?} at ({:e}, {:e})", kind, p, s, t
                        );
                    }
                }
            }
            if let Ok(rect) = Rect::try_new(sa, sb, ta, tb) {
                if let Ok(g) = tabulate(&*surface, &rect, ns, nt) {
                    prop_assert_eq!((g.rows(), g.cols()), (ns, nt));
                    prop_assert!(all_finite(g.as_slice()), "tabulate: non-finite value");
                }
            }
            Ok(())
        })?;
    }

    /// `partials_on_grid` and `partials_on_grid_into` on arbitrary node lists.
    #[test]
    fn surface_partials_grid(kind in surf(), s_nodes in values(0..=6), t_nodes in values(0..=6)) {
        guard(|| {
            let Some(surface) = build_surface(kind)? else { return Ok(()) };
            let a = partials_on_grid(&*surface, &s_nodes, &t_nodes);
            // a reused buffer, longer or shorter than the grid, full of NaN: every slot of
            // the result must be written
            let stale = Vector3::repeat(f64::NAN);
            let stale = Partials { point: stale, ds: stale, dt: stale, dst: stale };
            let mut buf = vec![stale; (s_nodes.len() * t_nodes.len() + 3) % 11];
            let b = partials_on_grid_into(&*surface, &s_nodes, &t_nodes, &mut buf);
            prop_assert_eq!(a.is_ok(), b.is_ok());
            if let Ok(g) = a {
                prop_assert_eq!((g.rows(), g.cols()), (s_nodes.len(), t_nodes.len()));
                prop_assert_eq!(g.as_slice(), &buf[..]);
                for p in g.as_slice() {
                    prop_assert!([p.point, p.ds, p.dt, p.dst].iter().all(finite), "non-finite partials {:?}", p);
                }
            }
            Ok(())
        })?;
    }

    /// `HermitePatch::try_from_corners`: interpolates its corner data (values and scaled
    /// partials), finite on `[0, 1]²`, `tabulate` = `eval`, Bézier form = Hermite form.
    #[test]
    fn hermite_patch_corners(d in net_values(), du in pos(), dv in pos(), st in unit_pairs(), ns in count(0..=6), nt in count(0..=6)) {
        guard(|| {
            let corners = [
                [partials_from(&d[0..12]), partials_from(&d[12..24])],
                [partials_from(&d[24..36]), partials_from(&d[36..48])],
            ];
            let Ok(patch) = HermitePatch::try_from_corners(&corners, du, dv) else { return Ok(()) };
            let c = patch.matrix();
            let scale = net_max(c);
            prop_assert!(scale.is_finite(), "non-finite Hermite matrix {:?}", c);
            for (a, row) in corners.iter().enumerate() {
                for (b, p) in row.iter().enumerate() {
                    let (s, t) = (a as f64, b as f64);
                    let got = SurfaceDerivatives::partials(&patch, s, t);
                    // X_st Δu Δv in either order of the products (one of them may overflow
                    // where the other does not, e.g. X_st = 0)
                    let twist = p.dst * du * dv;
                    let twist = if finite(&twist) { twist } else { p.dst * (du * dv) };
                    let want = [p.point, p.ds * du, p.dt * dv, twist];
                    for (k, (g, w)) in [got.point, got.ds, got.dt, got.dst].iter().zip(&want).enumerate() {
                        prop_assert!(finite(g), "corner ({}, {}) part {}: non-finite {:?}", a, b, k, g);
                        let e = amax(&(g - w));
                        prop_assert!(
                            e <= CORNER_TOL * scale + FLOOR,
                            "corner ({}, {}) part {} (X, X_s, X_t, X_st): got {:?}, want {:?}, error {:e} > {:e} × {:e}",
                            a, b, k, g, w, e, CORNER_TOL, scale
                        );
                    }
                }
            }
            let bezier = BezierPatch::from_hermite(&patch);
            for &(s, t) in &st {
                let h = patch.eval(s, t);
                prop_assert!(finite(&h), "non-finite eval {:?} at ({:e}, {:e})", h, s, t);
                let z = bezier.eval_bernstein(s, t);
                prop_assert!(amax(&(z - h)) <= BATCH_TOL * scale + FLOOR, "Bézier {:?} vs Hermite {:?} at ({:e}, {:e})", z, h, s, t);
            }
            if let Ok(g) = patch.tabulate(ns, nt) {
                prop_assert_eq!((g.rows(), g.cols()), (ns, nt));
                let (ss, ts) = (linspace(0.0, 1.0, ns), linspace(0.0, 1.0, nt));
                for (i, &s) in ss.iter().enumerate() {
                    for (j, &t) in ts.iter().enumerate() {
                        let (a, b) = (*g.get(i, j), patch.eval(s, t));
                        prop_assert!(finite(&a) && amax(&(a - b)) <= BATCH_TOL * scale + FLOOR, "tabulate {:?} vs eval {:?} at ({}, {})", a, b, i, j);
                    }
                }
            }
            let printed = report_codice7_net(&patch);
            prop_assert!(net_max(printed.net()).is_finite());
            Ok(())
        })?;
    }

    /// `HermitePatch::try_from_matrix`, `planes`, `tabulate` = `eval`; the Bézier nets derived
    /// from it (`BezierPatch::from_hermite`, `report_codice7_net`).
    #[test]
    fn hermite_patch_matrix(d in net_values(), st in unit_pairs(), ns in count(0..=6), nt in count(0..=6)) {
        guard(|| {
            let net = net_from(&d);
            let Ok(patch) = HermitePatch::try_from_matrix(net) else { return Ok(()) };
            prop_assert_eq!(patch.matrix(), &net);
            let scale = net_max(&net);
            prop_assert!(scale.is_finite());
            prop_assert!(patch.planes().iter().all(|m| m.iter().all(|x| x.is_finite())));
            let bezier = BezierPatch::from_hermite(&patch);
            prop_assert!(net_max(bezier.net()).is_finite(), "from_hermite: non-finite net");
            for &(s, t) in &st {
                let h = patch.eval(s, t);
                prop_assert!(finite(&h), "non-finite eval {:?} at ({:e}, {:e})", h, s, t);
                let z = bezier.eval_de_casteljau(s, t);
                prop_assert!(finite(&z) && amax(&(z - h)) <= BATCH_TOL * scale + FLOOR, "Bézier {:?} vs Hermite {:?}", z, h);
            }
            if let Ok(g) = patch.tabulate(ns, nt) {
                let (ss, ts) = (linspace(0.0, 1.0, ns), linspace(0.0, 1.0, nt));
                for (i, &s) in ss.iter().enumerate() {
                    for (j, &t) in ts.iter().enumerate() {
                        let (a, b) = (*g.get(i, j), patch.eval(s, t));
                        prop_assert!(finite(&a) && amax(&(a - b)) <= BATCH_TOL * scale + FLOOR, "tabulate {:?} vs eval {:?}", a, b);
                    }
                }
            }
            // the report's printed net (sign error included) of a valid patch
            let printed = report_codice7_net(&patch);
            for &(s, t) in &st {
                prop_assert!(finite(&printed.eval_bernstein(s, t)));
            }
            Ok(())
        })?;
    }

    /// `HermitePatch::try_from_surface`: the patch reproduces the surface at the rectangle's
    /// corners.
    #[test]
    fn hermite_patch_surface(kind in surf(), (sa, sb) in pair(), (ta, tb) in pair(), st in unit_pairs()) {
        guard(|| {
            let Some(surface) = build_surface(kind)? else { return Ok(()) };
            let Ok(rect) = Rect::try_new(sa, sb, ta, tb) else { return Ok(()) };
            let Ok(patch) = HermitePatch::try_from_surface(&*surface, &rect) else { return Ok(()) };
            let scale = net_max(patch.matrix());
            prop_assert!(scale.is_finite());
            for (s, u) in [(0.0, sa), (1.0, sb)] {
                for (t, v) in [(0.0, ta), (1.0, tb)] {
                    let (got, want) = (patch.eval(s, t), surface.point(u, v));
                    prop_assert!(
                        finite(&got) && amax(&(got - want)) <= CORNER_TOL * scale + FLOOR,
                        "corner ({}, {}): patch {:?} vs surface {:?}", s, t, got, want
                    );
                }
            }
            for &(s, t) in &st {
                prop_assert!(finite(&patch.eval(s, t)));
            }
            Ok(())
        })?;
    }

    /// `HermiteSurface::try_from_surface` and `HermiteSurface::uniform`: the spline reproduces
    /// the surface at every node; `tabulate` = `try_point`; finite on the domain.
    #[test]
    fn hermite_spline_surface(kind in surf(), u in seq(0..=5, 1), v in seq(0..=5, 1), fu in fracs(), fv in fracs(), (ra, rb) in pair(), n in count(0..=3), m in count(0..=3)) {
        guard(|| {
            let Some(surface) = build_surface(kind)? else { return Ok(()) };
            let mut splines = Vec::new();
            if let (Ok(pu), Ok(pv)) = (Partition::try_new(u), Partition::try_new(v)) {
                if let Ok(s) = HermiteSurface::try_from_surface(&*surface, pu, pv) {
                    splines.push(s);
                }
            }
            if let Ok(rect) = Rect::square(ra, rb) {
                if let Ok(s) = HermiteSurface::uniform(&*surface, &rect, n, m) {
                    prop_assert_eq!(s.patch_counts(), (n, m));
                    splines.push(s);
                }
            }
            for spline in &splines {
                check_spline_nodes(spline, &fu, &fv, |i, j| surface.point(spline.u().nodes()[i], spline.v().nodes()[j]))?;
            }
            Ok(())
        })?;
    }

    /// `HermiteSurface::try_from_node_partials`: the spline reproduces the node values.
    #[test]
    fn hermite_spline_nodes(u in seq(0..=4, 1), v in seq(0..=4, 1), d in values(0..=300), shape_off in prop::bool::weighted(0.1), fu in fracs(), fv in fracs()) {
        guard(|| {
            let (Ok(pu), Ok(pv)) = (Partition::try_new(u), Partition::try_new(v)) else { return Ok(()) };
            let rows = maybe_off(pu.nodes().len(), shape_off);
            let cols = pv.nodes().len();
            let d = if d.is_empty() { vec![0.0; 12] } else { d };
            let nodes = Grid::from_fn(rows, cols, |i, j| {
                let k = 12 * (i * cols + j);
                let chunk: Vec<f64> = (0..12).map(|c| d[(k + c) % d.len()]).collect();
                partials_from(&chunk)
            });
            let Ok(spline) = HermiteSurface::try_from_node_partials(&nodes, pu, pv) else { return Ok(()) };
            prop_assert!(!shape_off, "accepted a grid of the wrong shape");
            check_spline_nodes(&spline, &fu, &fv, |i, j| nodes.get(i, j).point)?;
            Ok(())
        })?;
    }

    /// `BezierPatch::try_from_net`: Bernstein = de Casteljau (single and tabulated), corners
    /// interpolated, finite on `[0, 1]²`.
    #[test]
    fn bezier_patch(d in net_values(), st in unit_pairs(), ns in count(0..=6), nt in count(0..=6)) {
        guard(|| {
            let net = net_from(&d);
            let Ok(patch) = BezierPatch::try_from_net(net) else { return Ok(()) };
            prop_assert_eq!(patch.net(), &net);
            let scale = net_max(&net);
            prop_assert!(scale.is_finite());
            prop_assert!(patch.planes().iter().all(|m| m.iter().all(|x| x.is_finite())));
            for (s, i) in [(0.0, 0), (1.0, 3)] {
                for (t, j) in [(0.0, 0), (1.0, 3)] {
                    let got = patch.eval_bernstein(s, t);
                    prop_assert!(amax(&(got - net[i][j])) <= BATCH_TOL * scale + FLOOR, "corner ({}, {}): {:?} vs {:?}", s, t, got, net[i][j]);
                }
            }
            for &(s, t) in &st {
                let (a, b) = (patch.eval_bernstein(s, t), patch.eval_de_casteljau(s, t));
                prop_assert!(finite(&a) && finite(&b) && amax(&(a - b)) <= BATCH_TOL * scale + FLOOR, "Bernstein {:?} vs de Casteljau {:?} at ({:e}, {:e})", a, b, s, t);
            }
            let dc = patch.tabulate_de_casteljau(ns, nt);
            let bs = patch.tabulate_bernstein(ns, nt);
            prop_assert_eq!(dc.is_ok(), bs.is_ok());
            if let (Ok(dc), Ok(bs)) = (dc, bs) {
                prop_assert_eq!((dc.rows(), dc.cols()), (ns, nt));
                prop_assert_eq!((bs.rows(), bs.cols()), (ns, nt));
                let (ss, ts) = (linspace(0.0, 1.0, ns), linspace(0.0, 1.0, nt));
                for (i, &s) in ss.iter().enumerate() {
                    for (j, &t) in ts.iter().enumerate() {
                        let e = patch.eval_bernstein(s, t);
                        let (a, b) = (*dc.get(i, j), *bs.get(i, j));
                        prop_assert!(
                            finite(&a) && finite(&b) && amax(&(a - e)) <= BATCH_TOL * scale + FLOOR && amax(&(b - e)) <= BATCH_TOL * scale + FLOOR,
                            "tabulate_de_casteljau {:?} / tabulate_bernstein {:?} vs eval {:?} at ({}, {})", a, b, e, i, j
                        );
                    }
                }
            }
            Ok(())
        })?;
    }

    /// `de_casteljau`, `de_casteljau_recursive`, `de_casteljau_levels` against `bernstein_sum`.
    #[test]
    fn bezier_curves(pts in points::<2>(0..=16), u in prop_oneof![3 => unit(), 1 => num()]) {
        guard(|| {
            let r1 = de_casteljau(&pts, u);
            let r2 = bernstein_sum(&pts, u);
            let r3 = de_casteljau_recursive(&pts, u);
            let r4 = de_casteljau_levels(&pts, u);
            if !pts.is_empty() {
                let long: Vec<Vector2<f64>> = fit(&pts, MAX_RECURSIVE_POINTS + 1, Vector2::zeros());
                prop_assert!(de_casteljau_recursive(&long, u).is_err(), "recursive de Casteljau accepted {} points", long.len());
            }
            if let Ok(levels) = &r4 {
                prop_assert_eq!(levels.len(), pts.len());
                for (k, level) in levels.iter().enumerate() {
                    prop_assert_eq!(level.len(), pts.len() - k);
                }
            }
            if !(valid_points(&pts) && (0.0..=1.0).contains(&u)) {
                return Ok(());
            }
            let scale = max_norm(&pts);
            let Ok(reference) = r2 else { return Ok(()) };
            prop_assert!(finite(&reference), "bernstein_sum non-finite {:?}", reference);
            let mut others = vec![("de_casteljau", r1.ok()), ("de_casteljau_recursive", r3.ok())];
            others.push(("de_casteljau_levels", r4.ok().and_then(|l| l.last().and_then(|l| l.first().copied()))));
            for (what, r) in others {
                if let Some(p) = r {
                    prop_assert!(
                        finite(&p) && amax(&(p - reference)) <= BATCH_TOL * scale + FLOOR,
                        "{} = {:?} vs bernstein_sum = {:?} at u = {:e}", what, p, reference, u
                    );
                }
            }
            Ok(())
        })?;
    }

    /// `de_casteljau_surface` against the tensor-product Bernstein sum.
    #[test]
    fn bezier_surface(rows in 0usize..=5, cols in 0usize..=5, d in values(0..=75), u in prop_oneof![3 => unit(), 1 => num()], v in prop_oneof![3 => unit(), 1 => num()]) {
        guard(|| {
            let net = grid3(rows, cols, &d);
            let Ok(p) = de_casteljau_surface(&net, u, v) else { return Ok(()) };
            if !(valid_points(net.as_slice()) && (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)) {
                return Ok(());
            }
            let column: Vec<Vector3<f64>> = (0..rows).map(|i| bernstein_sum(net.row(i), v).expect("non-empty row")).collect();
            let reference = bernstein_sum(&column, u).expect("non-empty column");
            let scale = max_norm(net.as_slice());
            prop_assert!(finite(&p) && amax(&(p - reference)) <= BATCH_TOL * scale + FLOOR, "de_casteljau_surface {:?} vs Bernstein {:?}", p, reference);
            Ok(())
        })?;
    }

    /// `bernstein_all`, `bernstein3`, `hermite_basis`, `lagrange4`, `uniform_bspline4`,
    /// `Blending::weights`, `printed_setbval`: sizes, partition of unity, agreement.
    #[test]
    fn basis_functions(n in prop_oneof![8 => count(0..=40), 1 => Just(MAX_BERNSTEIN_DEGREE + 1)], u in prop_oneof![3 => unit(), 1 => -1.0..=2.0f64, 1 => num()], nb in count(0..=40)) {
        guard(|| {
            if let Ok(b) = bernstein_all(n, u) {
                prop_assert!(n <= MAX_BERNSTEIN_DEGREE);
                prop_assert_eq!(b.len(), n + 1);
                if (0.0..=1.0).contains(&u) {
                    let sum: f64 = b.iter().sum();
                    prop_assert!(b.iter().all(|x| x.is_finite() && *x >= -NONNEG_TOL), "Bernstein values {:?}", b);
                    prop_assert!((sum - 1.0).abs() <= UNITY_TOL, "Bernstein sum {:e}", sum);
                }
            }
            if (0.0..=1.0).contains(&u) {
                let b3 = bernstein3(u);
                let ball = bernstein_all(3, u).expect("degree 3");
                prop_assert!(b3.iter().zip(&ball).all(|(a, b)| (a - b).abs() <= 1e-14), "bernstein3 {:?} vs bernstein_all {:?}", b3, ball);
                let h = hermite_basis(u);
                prop_assert!(h.iter().all(|x| x.is_finite()) && (h[0] + h[3] - 1.0).abs() <= 1e-14, "Hermite basis {:?}", h);
                let s = uniform_bspline4(u);
                prop_assert!(s.iter().all(|x| *x >= -NONNEG_TOL) && (s.iter().sum::<f64>() - 1.0).abs() <= UNITY_TOL, "uniform B-spline {:?}", s);
                prop_assert_eq!(Blending::UniformBSpline.weights(u), s);
            }
            if (-1.0..=2.0).contains(&u) {
                let l = lagrange4(u);
                prop_assert!(l.iter().all(|x| x.is_finite()) && (l.iter().sum::<f64>() - 1.0).abs() <= UNITY_TOL, "Lagrange blending {:?}", l);
                prop_assert_eq!(Blending::Lagrange.weights(u), l);
            }
            if let Ok(table) = printed_setbval(nb) {
                prop_assert_eq!(table.len(), nb);
                for (j, row) in table.iter().enumerate() {
                    let w = uniform_bspline4(j as f64 / nb as f64);
                    prop_assert!(row.iter().zip(&w).all(|(a, b)| (a - b).abs() <= 1e-14), "setbval row {} {:?} vs {:?}", j, row, w);
                }
            }
            Ok(())
        })?;
    }

    /// `KnotVector::try_new`: finite, non-decreasing, not all equal; breakpoints and
    /// multiplicities consistent.
    #[test]
    fn knot_vector(k in knots(), degree in 0usize..=5) {
        guard(|| {
            let Ok(kv) = KnotVector::try_new(k.clone()) else { return Ok(()) };
            let t = kv.knots();
            prop_assert_eq!(t, &k[..]);
            prop_assert!(t.iter().all(|x| x.is_finite()), "non-finite knot {:?}", t);
            prop_assert!(t.windows(2).all(|w| w[0] <= w[1]) && t[0] < t[t.len() - 1], "knots {:?}", t);
            prop_assert!((t[t.len() - 1] - t[0]).is_finite());
            let bp = kv.breakpoints();
            prop_assert_eq!(bp.iter().map(|b| b.1).sum::<usize>(), t.len());
            let xs: Vec<f64> = bp.iter().map(|b| b.0).collect();
            check_strict("breakpoints", &xs)?;
            for &(x, m) in &bp {
                prop_assert_eq!(kv.multiplicity(x), m);
            }
            let _ = (kv.is_open(degree), kv.is_uniform(), kv.to_string());
            Ok(())
        })?;
    }

    /// `KnotVector::extended_partition`: `2m + K` knots, `a` and `b` at positions `m − 1` and
    /// `m + K`, and a valid basis of degree `m − 1` on `[a, b]`.
    #[test]
    fn knot_extended_partition((a, b) in pair(), interior in seq(0..=5, 1), mults in vec(0usize..=5, 0..=6), same_len in prop::bool::weighted(0.9), order in count(0..=6), ends in prop_oneof![Just(EndKnots::Clamped), pos().prop_map(EndKnots::Spaced), (0.01..1.0f64).prop_map(EndKnots::Spaced)]) {
        guard(|| {
            let mults = if same_len { fit(&mults, interior.len(), 1) } else { mults };
            let Ok(kv) = KnotVector::extended_partition(a, b, &interior, &mults, order, ends) else { return Ok(()) };
            let t = kv.knots();
            let total: usize = mults.iter().sum::<usize>() + 2 * order;
            prop_assert_eq!(t.len(), total);
            prop_assert!(t.iter().all(|x| x.is_finite()) && t.windows(2).all(|w| w[0] <= w[1]), "knots {:?}", t);
            prop_assert!(t[order - 1] == a && t[total - order] == b, "a, b not at t_(m-1), t_(m+K): {:?}", t);
            match BSplineBasis::try_new(kv.clone(), order - 1) {
                Ok(basis) => prop_assert_eq!(basis.domain(), (a, b)),
                Err(e) => prop_assert!(false, "extended partition {:?} is not a valid basis of degree {}: {}", t, order - 1, e),
            }
            Ok(())
        })?;
    }

    /// `KnotVector::open_uniform`: open, `count + p + 1` knots, basis of `count` functions on
    /// `[a, b]`.
    #[test]
    fn knot_open_uniform(degree in count(0..=6), n in count(0..=20), (a, b) in pair()) {
        guard(|| {
            let Ok(kv) = KnotVector::open_uniform(degree, n, a, b) else { return Ok(()) };
            prop_assert_eq!(kv.len(), n + degree + 1);
            prop_assert!(kv.is_open(degree), "not open: {}", kv);
            let t = kv.knots();
            prop_assert!(t.iter().all(|x| x.is_finite()) && t.windows(2).all(|w| w[0] <= w[1]));
            match BSplineBasis::try_new(kv.clone(), degree) {
                Ok(basis) => {
                    prop_assert_eq!(basis.len(), n);
                    prop_assert_eq!(basis.domain(), (a, b));
                }
                Err(e) => prop_assert!(false, "open uniform vector {} is not a valid basis: {}", kv, e),
            }
            Ok(())
        })?;
    }

    /// `BSplineBasis::try_new` and its evaluators: partition of unity at in-domain `t` (both
    /// ends, every knot), non-empty spans with the left-limit rule at `b`, one-pass basis =
    /// Cox–de Boor, dual-number and derivative paths = plain values.
    #[test]
    fn bspline_basis(k in knots(), degree in count(0..=5), fr in fracs(), order in count(0..=3)) {
        guard(|| {
            let Ok(kv) = KnotVector::try_new(k) else { return Ok(()) };
            let Ok(basis) = BSplineBasis::try_new(kv, degree) else { return Ok(()) };
            let t = basis.knots().knots().to_vec();
            let p = basis.degree();
            prop_assert_eq!(p, degree);
            let n = basis.len() - 1;
            prop_assert_eq!(basis.len(), t.len() - p - 1);
            let (a, b) = basis.domain();
            prop_assert!(a.is_finite() && b.is_finite() && a < b, "domain [{:e}, {:e}]", a, b);
            for x in domain_params(a, b, &fr, &t) {
                let s = basis.find_span(x);
                prop_assert!(p <= s && s <= n && t[s] < t[s + 1], "find_span({:e}) = {} (empty or out of range)", x, s);
                if x < b {
                    prop_assert!(t[s] <= x && x < t[s + 1], "find_span({:e}) = {}: [{:e}, {:e})", x, s, t[s], t[s + 1]);
                } else {
                    prop_assert!(t[s] < b && b <= t[s + 1], "right end: span {} = [{:e}, {:e}] is not the last non-empty one", s, t[s], t[s + 1]);
                }
                let all = basis.all(x);
                prop_assert_eq!(all.len(), basis.len());
                let sum: f64 = all.iter().sum();
                prop_assert!(
                    all.iter().all(|v| v.is_finite() && *v >= -NONNEG_TOL) && (sum - 1.0).abs() <= UNITY_TOL,
                    "partition of unity fails at t = {:e}: sum {:e}, values {:?}", x, sum, all
                );
                let (span, nz) = basis.nonzero(x);
                prop_assert_eq!(span, s);
                for (i, &one_pass) in all.iter().enumerate() {
                    let cdb = basis.cox_de_boor(i, p, x);
                    prop_assert!((cdb - one_pass).abs() <= UNITY_TOL, "N_{}({:e}): one-pass {:e} vs Cox–de Boor {:e}", i, x, one_pass, cdb);
                }
                let (_, d1) = basis.nonzero(Dual64::from_re(x).derivative());
                let (_, d2) = basis.nonzero(Dual2_64::from_re(x).derivative());
                let (_, dd) = basis.nonzero_derivatives(x);
                for j in 0..=p {
                    prop_assert!(
                        (d1[j].re - nz[j]).abs() <= UNITY_TOL && (d2[j].re - nz[j]).abs() <= UNITY_TOL && (dd[j][0] - nz[j]).abs() <= UNITY_TOL,
                        "value of N at t = {:e}: plain {:e}, Dual64 {:e}, Dual2 {:e}, nonzero_derivatives {:e}", x, nz[j], d1[j].re, d2[j].re, dd[j][0]
                    );
                }
                if let Ok((span, ders)) = basis.derivatives(x, order) {
                    prop_assert_eq!(span, s);
                    prop_assert_eq!(ders.len(), order + 1);
                    prop_assert!(ders.iter().all(|r| r.len() == p + 1));
                    prop_assert!(ders[0].iter().zip(&nz).all(|(a, b)| (a - b).abs() <= UNITY_TOL), "derivatives row 0 {:?} vs {:?}", ders[0], nz);
                }
            }
            Ok(())
        })?;
    }

    /// `BSplineCurve::try_new`, `with_point`: finite on the domain, `eval_many` = `point`,
    /// derivatives finite for moderate data.
    #[test]
    fn bspline_curve(k in knots(), degree in count(0..=9), pts in points::<2>(0..=20), off in prop::bool::weighted(0.05), fr in fracs(), samples in count(0..=12), idx in any::<Index>(), newp in prop::array::uniform2(num())) {
        guard(|| {
            let Ok(kv) = KnotVector::try_new(k) else { return Ok(()) };
            let Ok(basis) = BSplineBasis::try_new(kv, degree) else { return Ok(()) };
            let pts = fit(&pts, maybe_off(basis.len(), off), Vector2::zeros());
            let Ok(curve) = BSplineCurve::try_new(basis.clone(), pts.clone()) else { return Ok(()) };
            prop_assert!(!off, "accepted {} points for {} basis functions", pts.len(), basis.len());
            check_bspline_curve("B-spline curve", &curve, &fr, samples)?;
            if let Ok(c2) = curve.with_point(idx.index(pts.len()), Vector2::from(newp)) {
                check_bspline_curve("B-spline curve with_point", &c2, &fr, samples)?;
            }
            Ok(())
        })?;
    }

    /// `NurbsCurve::try_new`, `with_weight`: finite on the domain, `eval_many` = `point`, equal
    /// weights = the B-spline curve.
    #[test]
    fn nurbs_curve(k in knots(), degree in count(0..=8), pts in points::<2>(0..=20), w in weights(), equal in prop::bool::weighted(0.25), off in prop::bool::weighted(0.05), fr in fracs(), idx in any::<Index>(), neww in pos()) {
        guard(|| {
            let Ok(kv) = KnotVector::try_new(k) else { return Ok(()) };
            let Ok(basis) = BSplineBasis::try_new(kv, degree) else { return Ok(()) };
            let pts = fit(&pts, basis.len(), Vector2::zeros());
            let w = if equal { vec![w.first().copied().unwrap_or(1.0); basis.len()] } else { fit(&w, maybe_off(basis.len(), off), 1.0) };
            let Ok(curve) = NurbsCurve::try_new(basis.clone(), pts.clone(), w.clone()) else { return Ok(()) };
            prop_assert!(w.len() == basis.len(), "accepted {} weights for {} basis functions", w.len(), basis.len());
            prop_assert!(w.iter().all(|x| x.is_finite() && *x > 0.0));
            check_nurbs_curve("NURBS", &curve, &fr)?;
            if equal {
                let b = BSplineCurve::try_new(basis.clone(), pts.clone()).expect("same data as the NURBS curve");
                let (a, bb) = curve.domain();
                let scale = max_norm(&pts);
                for t in domain_params(a, bb, &fr, basis.knots().knots()) {
                    let (p, q) = (curve.point(t), b.point(t));
                    prop_assert!(amax(&(p - q)) <= BATCH_TOL * scale + FLOOR, "equal weights: NURBS {:?} vs B-spline {:?} at {:e}", p, q, t);
                }
            }
            if let Ok(c2) = curve.with_weight(idx.index(w.len()), neww) {
                check_nurbs_curve("NURBS with_weight", &c2, &fr)?;
            }
            Ok(())
        })?;
    }

    /// `NurbsCurve::circle7`, `circle9`: every point at distance `r` from the centre.
    #[test]
    fn nurbs_circle(c in prop::array::uniform2(num()), r in pos(), nine in any::<bool>(), fr in fracs()) {
        guard(|| {
            let center = Vector2::from(c);
            let made = if nine { NurbsCurve::circle9(center, r) } else { NurbsCurve::circle7(center, r) };
            let Ok(circle) = made else { return Ok(()) };
            check_nurbs_curve("circle", &circle, &fr)?;
            let (a, b) = circle.domain();
            let tol = 1e-12 * (r + amax(&center)) + FLOOR;
            for t in domain_params(a, b, &fr, circle.basis().knots().knots()) {
                let p = circle.point(t);
                let d = (p.x - center.x).hypot(p.y - center.y);
                prop_assert!((d - r).abs() <= tol, "circle(centre {:?}, r = {:e}) at t = {:e}: point {:?} at distance {:e}", center, r, t, p, d);
            }
            Ok(())
        })?;
    }

    /// `CubicSpline::function` (every end condition): interpolates its data, finite on the
    /// domain, `eval_many` / `values_into` = `point` / `value`, end conditions (well-spaced data).
    #[test]
    fn cubic_spline_function(x in seq(0..=12, 1), y in values(0..=12), off in prop::bool::weighted(0.05), end in end1(), per in periodic_delta(), fr in fracs()) {
        guard(|| {
            let mut y = fit(&y, maybe_off(x.len(), off), 0.0);
            if let (Some(d), true) = (per, y.len() >= 2) {
                let last = y.len() - 1;
                y[last] = y[0] + d * y[0].abs().max(1.0);
            }
            let Ok(s) = CubicSpline::function(&x, &y, end) else { return Ok(()) };
            prop_assert!(!off, "accepted {} values for {} abscissae", y.len(), x.len());
            prop_assert_eq!(s.nodes(), &x[..]);
            let data: Vec<Vector1<f64>> = y.iter().map(|&v| Vector1::new(v)).collect();
            check_interp("cubic spline function", &data, |i| s.point(x[i]))?;
            let (a, b) = s.domain();
            let params = domain_params(a, b, &fr, &x);
            check_curve("cubic spline function", &s, &params, 7)?;
            let (ts, inside) = batch_params(&params, a, b);
            let mut out = Vec::new();
            s.eval_many(&ts, &mut out);
            let vscale = max_norm(&data).max(params.iter().map(|&t| s.value(t).abs()).fold(0.0, nanmax));
            check_batch("CubicSpline::eval_many", &ts, &inside, &out, |t| s.point(t), vscale)?;
            let mut vals = Vec::new();
            s.values_into(&ts, &mut vals);
            let vals: Vec<Vector1<f64>> = vals.into_iter().map(Vector1::new).collect();
            check_batch("CubicSpline::values_into", &ts, &inside, &vals, |t| Vector1::new(s.value(t)), vscale)?;
            let ed = s.end_derivatives();
            // never NaN; infinite only where the true slope or curvature overflows (a
            // derivative is finite wherever its true value is representable)
            prop_assert!(ed.iter().all(|v| v.iter().all(|c| !c.is_nan())), "end derivatives {:?}", ed);
            let slope_scale = match end { EndCondition::Clamped { start, end } => amax(&start).max(amax(&end)), _ => 0.0 };
            if well_spaced(&x, max_norm(&data), slope_scale) {
                check_derivatives("cubic spline function", &s, &params)?;
                check_end_conditions("cubic spline function", &end, &x, &data, |t| s.derivatives2(t))?;
            }
            Ok(())
        })?;
    }

    /// `CubicSpline::try_new` (ℝ²) and `CubicSpline::curve`: interpolation, `eval_many`.
    #[test]
    fn cubic_spline_curve(x in seq(0..=10, 1), pts in points::<2>(0..=10), end in end2(), per in periodic_delta(), pm in param(), fr in fracs()) {
        guard(|| {
            let mut pts = pts;
            if let (Some(d), true) = (per, pts.len() >= 2) {
                let last = pts.len() - 1;
                pts[last] = pts[0].map(|c| c + d * c.abs().max(1.0));
            }
            let y = fit(&pts, x.len(), Vector2::zeros());
            if let Ok(s) = CubicSpline::try_new(&x, &y, end) {
                check_interp("CubicSpline::try_new", &y, |i| s.point(x[i]))?;
                check_cubic_curve("CubicSpline::try_new", &s, &fr, &x)?;
                let slope_scale = match end { EndCondition::Clamped { start, end } => amax(&start).max(amax(&end)), _ => 0.0 };
                if well_spaced(&x, max_norm(&y), slope_scale) {
                    check_end_conditions("CubicSpline::try_new", &end, &x, &y, |t| s.derivatives2(t))?;
                }
            }
            if let Ok(s) = CubicSpline::curve(&pts, pm, end) {
                let t = pm.parameters(&pts).expect("parameters accepted by the spline");
                prop_assert_eq!(s.nodes(), &t[..]);
                check_interp("CubicSpline::curve", &pts, |i| s.point(t[i]))?;
                check_cubic_curve("CubicSpline::curve", &s, &fr, &t)?;
            }
            Ok(())
        })?;
    }

    /// `PiecewiseLinear::try_new` and `PiecewiseLinear::curve`: interpolation, values between
    /// neighbouring data, finite on the domain.
    #[test]
    fn piecewise_linear(x in seq(0..=12, 1), y in values(0..=12), pts in points::<2>(0..=10), off in prop::bool::weighted(0.05), pm in param(), fr in fracs()) {
        guard(|| {
            let y: Vec<Vector1<f64>> = fit(&y, maybe_off(x.len(), off), 0.0).into_iter().map(Vector1::new).collect();
            if let Ok(p) = PiecewiseLinear::try_new(&x, &y) {
                prop_assert!(!off);
                check_interp("PiecewiseLinear::try_new", &y, |i| p.point(x[i]))?;
                let (a, b) = p.domain();
                let params = domain_params(a, b, &fr, &x);
                check_curve("PiecewiseLinear", &p, &params, 5)?;
                let scale = max_norm(&y);
                for &t in &params {
                    let k = x.partition_point(|&xi| xi <= t).clamp(1, x.len() - 1) - 1;
                    let (lo, hi) = (y[k].x.min(y[k + 1].x), y[k].x.max(y[k + 1].x));
                    let v = p.point(t).x;
                    prop_assert!(v >= lo - 1e-12 * scale - FLOOR && v <= hi + 1e-12 * scale + FLOOR, "p({:e}) = {:e} outside [{:e}, {:e}]", t, v, lo, hi);
                }
            }
            if let Ok(p) = PiecewiseLinear::curve(&pts, pm) {
                let t = pm.parameters(&pts).expect("parameters accepted by the polygon");
                check_interp("PiecewiseLinear::curve", &pts, |i| p.point(t[i]))?;
                check_curve("PiecewiseLinear::curve", &p, &domain_params(0.0, 1.0, &fr, &t), 5)?;
            }
            Ok(())
        })?;
    }

    /// `CardinalSpline::try_new` and `closed`: interpolates its inner points, finite on the
    /// domain, C¹ tangents `a (Pᵢ₊₁ − Pᵢ₋₁)` at the joints.
    #[test]
    fn cardinal_spline(pts in points::<2>(0..=10), a in prop_oneof![4 => 0.001..2.0f64, 1 => num()], closed in prop::bool::weighted(0.3), fr in fracs()) {
        guard(|| {
            let r = if closed { CardinalSpline::closed(&pts, a) } else { CardinalSpline::try_new(pts.clone(), a) };
            if let Ok(c) = r {
                prop_assert!(a.is_finite() && a >= 0.0);
                let p = c.points().to_vec();
                let inner = &p[1..p.len() - 1];
                check_interp("CardinalSpline", inner, |i| c.point(i as f64))?;
                let (lo, hi) = c.domain();
                check_curve("CardinalSpline", &c, &domain_params(lo, hi, &fr, &[]), 5)?;
                for i in 1..c.segments() {
                    let expected = (p[i + 2] - p[i]) * a;
                    let got = c.derivative(i as f64);
                    prop_assert!(amax(&(got - expected)) <= 1e-12 * amax(&expected).max(max_norm(&p) * a) + FLOOR, "tangent {}: {:?} vs {:?}", i, got, expected);
                }
            }
            Ok(())
        })?;
    }

    /// Points on a small integer grid (exact collinear triples everywhere, reversals
    /// included): every Angular spline built is G¹ at every joint and interpolates; the rest
    /// are typed errors.
    #[test]
    fn angular_spline_on_a_grid(raw in vec((0i32..4, 0i32..4), 4..=10), closed in prop::bool::ANY) {
        let pts: Vec<Vector2<f64>> = raw.iter().map(|&(x, y)| Vector2::new(x as f64, y as f64)).collect();
        guard(|| {
            let r = if closed { AngularSpline::closed(&pts) } else { AngularSpline::try_new(pts.clone()) };
            match r {
                Ok(c) => {
                    let p = c.points().to_vec();
                    check_interp("AngularSpline", &p[1..p.len() - 1], |i| c.point(i as f64))?;
                    check_angular_g1(&c)?;
                }
                Err(e) => prop_assert!(matches!(
                    e,
                    splinelab::Error::NoSmoothPiece { .. } | splinelab::Error::RepeatedPoint { .. } | splinelab::Error::ReversedPoints { .. } | splinelab::Error::TooFewPoints { .. }
                ), "{:?}", e),
            }
            Ok(())
        })?;
    }

    /// `AngularSpline::try_new` and `closed`: interpolates its inner points, finite on the
    /// domain, tangents at the points are the unit circle tangents (G¹), errors typed.
    #[test]
    fn angular_spline(pts in points::<2>(0..=10), closed in prop::bool::weighted(0.3), fr in fracs()) {
        guard(|| {
            let r = if closed { AngularSpline::closed(&pts) } else { AngularSpline::try_new(pts.clone()) };
            if let Ok(c) = r {
                let p = c.points().to_vec();
                let inner = &p[1..p.len() - 1];
                check_interp("AngularSpline", inner, |i| c.point(i as f64))?;
                let (lo, hi) = c.domain();
                let params = domain_params(lo, hi, &fr, &[]);
                check_curve("AngularSpline", &c, &params, 5)?;
                for &u in &params {
                    let d = c.derivative(u);
                    prop_assert!(finite(&d), "C′({:e}) = {:?}", u, d);
                }
                for (k, t) in c.tangents().iter().enumerate() {
                    prop_assert!(finite(t) && (t.norm() - 1.0).abs() <= 1e-12, "tangent {}: {:?}", k, t);
                }
                // the fast polyline is the reference polyline
                let mut fast = Vec::new();
                c.polyline_into(300, &mut fast).expect("300 samples");
                let reference = c.polyline(300).expect("300 samples");
                // relative to the curve's own extent: a piece whose end tangents point nearly
                // backwards is a huge loop, ill-conditioned in its parameter
                let scale = max_norm(&p).max(max_norm(&reference));
                for (k, (a, b)) in fast.iter().zip(&reference).enumerate() {
                    prop_assert!(finite(a) && amax(&(a - b)) <= 1e-10 * scale + FLOOR, "polyline_into point {}: {:?} vs {:?}", k, a, b);
                }
                // the fast piece samples are the reference's
                let breaks: Vec<f64> = (0..=c.pieces()).map(|k| k as f64).collect();
                let reference = splinelab::metrics::curve::sample_pieces(&c, &breaks, 24);
                let fast = c.sample_pieces_into(24, &mut fast).map(|()| fast);
                match (fast, reference) {
                    (Ok(fast), Ok(reference)) => {
                        prop_assert_eq!(fast.len(), reference.len());
                        let scale = max_norm(&p).max(max_norm(&reference));
                        for (k, (a, b)) in fast.iter().zip(&reference).enumerate() {
                            // both evaluate the arc's half-angle form, which divides by sin γ,
                            // and γ carries a rounding error of a few ε: a point at distance
                            // |b| from a piece of chord L is known only to about ε|b|²/L (a
                            // huge loop of a short piece), whatever path computes it
                            let j = (k / 23).min(c.pieces() - 1);
                            let chord = amax(&(c.point((j + 1) as f64) - c.point(j as f64)));
                            let conditioning = 64.0 * f64::EPSILON * amax(b) * (amax(b) / chord.max(f64::MIN_POSITIVE));
                            prop_assert!(amax(&(a - b)) <= 1e-10 * scale + FLOOR + conditioning, "sample_pieces_into point {}: {:?} vs {:?} (the arc's conditioning {:e})", k, a, b, conditioning);
                        }
                    }
                    (Err(_), Err(_)) => {}
                    (f, r) => prop_assert!(false, "fast {:?} vs reference {:?}", f.map(|v| v.len()), r.map(|v| v.len())),
                }
                check_angular_g1(&c)?;
            }
            Ok(())
        })?;
    }

    /// `BSplineCurve::with_order` and `fit_bspline`: the curve starts and ends at the end
    /// vertices; a fit is finite and its reported distance is what its samples measure.
    #[test]
    fn bspline_order_and_fit(pts in points::<2>(0..=12), order in 0usize..8, count in 0usize..8, fr in fracs()) {
        guard(|| {
            if let Ok(c) = BSplineCurve::with_order(pts.clone(), order) {
                prop_assert!(order >= 2 && order <= pts.len());
                let (a, b) = c.domain();
                check_curve("BSplineCurve::with_order", &c, &domain_params(a, b, &fr, &[]), 5)?;
                let scale = max_norm(&pts);
                prop_assert!(amax(&(c.point(a) - pts[0])) <= 1e-12 * scale + FLOOR);
                prop_assert!(amax(&(c.point(b) - pts[pts.len() - 1])) <= 1e-12 * scale + FLOOR);
            }
            if let Ok(f) = fit_bspline(&pts, count, order, 3) {
                prop_assert!(all_finite(f.curve.points()) && f.max_distance.is_finite(), "fit {:?}", f.curve.points());
                prop_assert_eq!(f.curve.points().len(), count);
                prop_assert_eq!(f.curve.points()[0], pts[0]);
            }
            Ok(())
        })?;
    }

    /// `guide_point`: a finite guide within the coordinate limit, or a typed error.
    #[test]
    fn guide_points(p in points::<2>(3..=3)) {
        guard(|| {
            if let Ok(g) = guide_point(p[0], p[1], p[2]) {
                prop_assert!(g.iter().all(|x| x.abs() <= MAX_COORDINATE), "guide {:?}", g);
            }
            Ok(())
        })?;
    }

    /// `SegmentTree`, `polyline_distances`, `Target` and `fewest_points`: typed errors or
    /// finite results; the tree's distance equals the brute-force minimum wherever squares
    /// cannot overflow; an accepted choice is within its tolerance.
    #[test]
    fn curve_metrics_and_point_choice(
        pts in points::<2>(0..=30),
        other in points::<2>(0..=12),
        closed in prop::bool::weighted(0.4),
        tol in pos(),
        family in select(vec![0usize, 1, 2, 3, 4]),
    ) {
        guard(|| {
            use splinelab::metrics::curve::{polyline_distances, SegmentTree};
            use splinelab::interp::choice::{fewest_points, Family, SearchOptions, Target};
            if let Ok(tree) = SegmentTree::new(&pts) {
                let line = tree.points().to_vec();
                for q in &other {
                    let d = tree.distance(*q);
                    if !q.iter().all(|x| x.abs() <= MAX_COORDINATE) {
                        // a NaN query, or beyond the coordinate limit: a distance may be +∞
                        continue;
                    }
                    prop_assert!(d.is_finite() && d >= 0.0, "distance {:e} to {:?}", d, q);
                    let small = line.iter().chain([q]).all(|p| p.amax() <= 1e100);
                    if small {
                        let brute = line
                            .windows(2)
                            .map(|w| splinelab::metrics::curve::segment_distance(*q, w[0], w[1]))
                            .fold(f64::INFINITY, f64::min);
                        prop_assert_eq!(d, brute);
                    }
                }
                if let Ok(dist) = polyline_distances(&other, &pts) {
                    prop_assert!(dist.hausdorff().is_finite() && dist.hausdorff() >= 0.0, "{:?}", dist);
                }
            }
            if let Ok(target) = Target::polyline(&pts, closed, tol) {
                prop_assert!(target.length() > 0.0 && target.length().is_finite());
                let options = SearchOptions { max_points: 8, budget_per_coordinate: 2, random_starts: 1, every_count_below: false, ..SearchOptions::default() };
                let family = [Family::Angular, Family::Cardinal, Family::Cubic, Family::BSpline, Family::Linear][family];
                {
                    if let Ok(c) = fewest_points(&target, family, &options) {
                        let h = c.measure.distances.hausdorff();
                        prop_assert!(h.is_finite() && h >= 0.0, "{:?}: {:e}", family, h);
                        prop_assert_eq!(c.within_tolerance, h <= target.tolerance());
                        prop_assert!(c.points.iter().all(|p| p.iter().all(|x| x.is_finite())));
                    }
                }
            }
            Ok(())
        })?;
    }

    /// `Parametrization::parameters`: from 0 to 1, strictly increasing.
    #[test]
    fn parametrization(pts2 in points::<2>(0..=12), pts3 in points::<3>(0..=8)) {
        guard(|| {
            for pm in Parametrization::ALL {
                let results = [(pts2.len(), pm.parameters(&pts2)), (pts3.len(), pm.parameters(&pts3))];
                for (n, r) in results {
                    let Ok(t) = r else { continue };
                    prop_assert_eq!(t.len(), n);
                    prop_assert!(t[0] == 0.0 && t[n - 1] == 1.0, "{:?}: ends {:?}", pm, t);
                    check_strict("parameters", &t)?;
                    if pm == Parametrization::Uniform {
                        for (i, &ti) in t.iter().enumerate() {
                            prop_assert!((ti - i as f64 / (n - 1) as f64).abs() <= 1e-15, "uniform parameters {:?}", t);
                        }
                    }
                }
            }
            Ok(())
        })?;
    }

    /// `Lagrange::try_new`: interpolation, barycentric basis sums to 1, no NaN in the domain.
    #[test]
    fn lagrange(x in seq(0..=16, 1), y in values(0..=16), off in prop::bool::weighted(0.05), fr in fracs()) {
        guard(|| {
            let y = fit(&y, maybe_off(x.len(), off), 0.0);
            let Ok(p) = Lagrange::try_new(&x, &y) else { return Ok(()) };
            prop_assert!(!off);
            prop_assert_eq!(p.nodes(), &x[..]);
            let data: Vec<Vector1<f64>> = y.iter().map(|&v| Vector1::new(v)).collect();
            check_interp("Lagrange", &data, |i| Vector1::new(p.eval(x[i])))?;
            let (a, b) = (x[0], x[x.len() - 1]);
            let ys = max_abs(&y);
            let unit_data: Vec<f64> = y.iter().map(|v| if ys > 0.0 { v / ys } else { *v }).collect();
            let scaled = Lagrange::try_new(&x, &unit_data).ok();
            for t in domain_params(a, b, &fr, &x) {
                let v = p.eval(t);
                prop_assert!(!v.is_nan(), "Lagrange NaN at t = {:e}", t);
                if !v.is_finite() {
                    // infinite only where the true value overflows: the scaled interpolant
                    // times the scale must exceed the range
                    let u = scaled.as_ref().map(|u| u.eval(t)).unwrap_or(f64::INFINITY);
                    prop_assert!((u.abs() * ys).is_nan() || u.abs() * ys >= 1e300, "Lagrange infinite at t = {:e} although the scaled value is {:e} (scale {:e})", t, u, ys);
                }
                let l = p.basis(t);
                let sum: f64 = l.iter().sum();
                let size: f64 = l.iter().map(|v| v.abs()).sum();
                if size.is_finite() {
                    prop_assert!((sum - 1.0).abs() <= UNITY_TOL * size.max(1.0), "Lagrange basis sums to {:e} at {:e}", sum, t);
                }
            }
            Ok(())
        })?;
    }

    /// `PowerPolynomial::interpolate` and `vandermonde_condition`: finite coefficients,
    /// interpolation; no NaN in the domain, infinite only where the Lagrange form is too.
    #[test]
    fn power_polynomial(x in seq(0..=14, 1), y in values(0..=14), fr in fracs()) {
        guard(|| {
            let y = fit(&y, x.len(), 0.0);
            if let Ok(Some(k)) = vandermonde_condition(&x) {
                prop_assert!(k.is_finite() && k >= 1.0 - 1e-12, "Vandermonde condition {:e}", k);
            }
            let Ok(p) = PowerPolynomial::interpolate(&x, &y) else { return Ok(()) };
            prop_assert!(p.coefficients().iter().all(|c| c.is_finite()), "coefficients {:?}", p.coefficients());
            let data: Vec<Vector1<f64>> = y.iter().map(|&v| Vector1::new(v)).collect();
            check_interp("PowerPolynomial", &data, |i| Vector1::new(p.eval(x[i])))?;
            let reference = Lagrange::try_new(&x, &y).ok();
            for t in domain_params(x[0], x[x.len() - 1], &fr, &x) {
                let v = p.eval(t);
                prop_assert!(!v.is_nan(), "power form NaN at t = {:e}", t);
                if !v.is_finite() {
                    let r = reference.as_ref().map(|r| r.eval(t)).unwrap_or(f64::INFINITY);
                    prop_assert!(r.is_nan() || r.abs() >= 1e300, "power form infinite at t = {:e} where the Lagrange form is {:e}", t, r);
                }
            }
            Ok(())
        })?;
    }

    /// `NodeFamily::nodes` and `max_interpolation_error` (Runge's function).
    #[test]
    fn node_families((a, b) in pair(), degree in count(0..=30), samples in count(0..=30), cheb in any::<bool>()) {
        guard(|| {
            let family = if cheb { NodeFamily::Chebyshev } else { NodeFamily::Equispaced };
            if let Ok(nodes) = family.nodes(a, b, degree) {
                prop_assert_eq!(nodes.len(), degree + 1);
                let slack = 1e-12 * a.abs().max(b.abs());
                prop_assert!(
                    nodes.iter().all(|x| x.is_finite() && *x >= a - slack && *x <= b + slack),
                    "{:?} nodes on [{:e}, {:e}]: {:?}", family, a, b, nodes
                );
            }
            if let Ok(e) = max_interpolation_error(runge, (a, b), degree, family, samples) {
                prop_assert!(e.is_finite() && e >= 0.0, "max interpolation error {:e}", e);
            }
            Ok(())
        })?;
    }

    /// `collocation::interpolate` (with and without extra conditions) and
    /// `schoenberg_whitney`: the curve passes through the values at the sites.
    #[test]
    fn collocation_interpolate(k in knots(), degree in count(0..=4), greville in prop::bool::weighted(0.7), raw_sites in seq(0..=16, 1), vals in points::<2>(0..=16), nc in 0usize..=2, cond_data in vec((0usize..3, unit(), num(), prop::array::uniform2(ordinary())), 2), fr in fracs()) {
        guard(|| {
            let Ok(kv) = KnotVector::try_new(k) else { return Ok(()) };
            let Ok(basis) = BSplineBasis::try_new(kv, degree) else { return Ok(()) };
            let n = basis.len();
            let (a, b) = basis.domain();
            let t = basis.knots().knots();
            let p = basis.degree();
            let nc = nc.min(n);
            let all_sites: Vec<f64> = if greville {
                (0..n).map(|j| {
                    let g = if p == 0 { 0.5 * (t[j] + t[j + 1]) } else { t[j + 1..=j + p].iter().sum::<f64>() / p as f64 };
                    g.clamp(a, b)
                }).collect()
            } else {
                fit(&raw_sites, n, a)
            };
            if let Ok(()) = collocation::schoenberg_whitney(&basis, &all_sites) {
                for (j, &x) in all_sites.iter().enumerate() {
                    prop_assert!(basis.all(x)[j] > 0.0, "Schoenberg–Whitney accepted site {} ({:e}) where N_{} = 0", j, x, j);
                }
            }
            let sites = &all_sites[..n - nc];
            let values = fit(&vals, sites.len(), Vector2::zeros());
            let w = b - a;
            let conditions: Vec<Condition<2>> = cond_data.iter().take(nc).map(|&(o, f, c, v)| Condition {
                order: [DerivativeOrder::Value, DerivativeOrder::First, DerivativeOrder::Second][o],
                terms: vec![((a + f * w).clamp(a, b), c)],
                value: Vector2::from(v),
            }).collect();
            let Ok(curve) = collocation::interpolate(basis.clone(), sites, &values, &conditions) else { return Ok(()) };
            // the documented data scale of collocation: max |yᵢ| and every right-hand side
            // divided by the largest entry of its row (derivative data in value units)
            let scale = collocation_scale(&basis, sites, &values, &conditions);
            check_interp_scaled("collocation::interpolate", &values, scale, collocation_miss(scale), |i| curve.point(sites[i]))?;
            check_bspline_curve("collocation curve", &curve, &fr, 5)?;
            Ok(())
        })?;
    }

    /// `collocation::cubic_spline` (every end condition): interpolation, end conditions, and
    /// agreement with the tridiagonal `CubicSpline` on well-spaced data.
    #[test]
    fn collocation_cubic_spline(x in seq(0..=10, 1), y in points::<2>(0..=10), end in end2(), per in periodic_delta(), fr in fracs()) {
        guard(|| {
            let mut y = fit(&y, x.len(), Vector2::zeros());
            if let (Some(d), true) = (per, y.len() >= 2) {
                let last = y.len() - 1;
                y[last] = y[0].map(|c| c + d * c.abs().max(1.0));
            }
            let Ok(curve) = collocation::cubic_spline(&x, &y, end) else { return Ok(()) };
            // the documented data scale: the values and the clamped slopes in value units
            let (a, b) = (x[0], x[x.len() - 1]);
            let conditions = match end {
                EndCondition::Clamped { start, end } => vec![
                    Condition { order: DerivativeOrder::First, terms: vec![(a, 1.0)], value: start },
                    Condition { order: DerivativeOrder::First, terms: vec![(b, 1.0)], value: end },
                ],
                _ => Vec::new(),
            };
            let scale = collocation_scale(curve.basis(), &x, &y, &conditions);
            check_interp_scaled("collocation::cubic_spline", &y, scale, collocation_miss(scale), |i| curve.point(x[i]))?;
            check_bspline_curve("collocation::cubic_spline", &curve, &fr, 5)?;
            let slope_scale = match end { EndCondition::Clamped { start, end } => amax(&start).max(amax(&end)), _ => 0.0 };
            if well_spaced(&x, max_norm(&y), slope_scale) {
                check_end_conditions("collocation::cubic_spline", &end, &x, &y, |t| curve.derivatives2(t))?;
                if let Ok(s) = CubicSpline::try_new(&x, &y, end) {
                    let params = domain_params(x[0], x[x.len() - 1], &fr, &x);
                    let vscale = params.iter().map(|&t| amax(&s.point(t))).fold(max_norm(&y), nanmax);
                    for t in params {
                        let (p, q) = (curve.point(t), s.point(t));
                        prop_assert!(amax(&(p - q)) <= 1e-9 * vscale, "{}: B-spline route {:?} vs tridiagonal {:?} at {:e}", format_args!("{:?}", end), p, q, t);
                    }
                }
            }
            Ok(())
        })?;
    }

    /// `collocation::interpolate_curve`: the curve passes through the points at their
    /// parameters.
    #[test]
    fn collocation_interpolate_curve(pts in points::<2>(0..=12), degree in count(0..=5), pm in param(), fr in fracs()) {
        guard(|| {
            let Ok(curve) = collocation::interpolate_curve(&pts, degree, pm) else { return Ok(()) };
            let u = pm.parameters(&pts).expect("parameters accepted by the curve");
            prop_assert_eq!(curve.domain(), (0.0, 1.0));
            let scale = collocation_scale(curve.basis(), &u, &pts, &[]);
            check_interp_scaled("interpolate_curve", &pts, scale, collocation_miss(scale), |i| curve.point(u[i]))?;
            check_bspline_curve("interpolate_curve", &curve, &fr, 5)?;
            Ok(())
        })?;
    }

    /// `WindowCurve::lagrange`, `WindowCurve::printed_bspline`, `printed_bspline_polyline`.
    #[test]
    fn window_curves(pts in points::<2>(0..=12), nb in count(0..=8), fr in fracs()) {
        guard(|| {
            let scale = max_norm(&pts);
            if let Ok(c) = WindowCurve::lagrange(&pts) {
                prop_assert_eq!(c.segments(), pts.len() - 1);
                prop_assert_eq!(c.domain(), (0.0, (pts.len() - 1) as f64));
                for (k, p) in pts.iter().enumerate() {
                    let q = c.point(k as f64);
                    prop_assert!(finite(&q) && amax(&(q - p)) <= BATCH_TOL * scale + FLOOR, "Lagrange window curve at {}: {:?} vs {:?}", k, q, p);
                }
                let (a, b) = c.domain();
                check_curve("Lagrange window curve", &c, &domain_params(a, b, &fr, &[]), 6)?;
            }
            if let Ok(c) = WindowCurve::printed_bspline(&pts) {
                prop_assert_eq!(c.segments(), pts.len() + 1);
                let (a, b) = c.domain();
                let (p0, p1) = (c.point(a), c.point(b));
                prop_assert!(amax(&(p0 - pts[0])) <= BATCH_TOL * scale + FLOOR && amax(&(p1 - pts[pts.len() - 1])) <= BATCH_TOL * scale + FLOOR, "printed bspline ends {:?} {:?}", p0, p1);
                check_curve("printed bspline curve", &c, &domain_params(a, b, &fr, &[]), 6)?;
                if let Ok(poly) = printed_bspline_polyline(&pts, nb) {
                    prop_assert_eq!(poly.len(), 1 + (pts.len() + 1) * nb);
                    prop_assert!(poly[0] == pts[0]);
                    for k in 1..=pts.len() + 1 {
                        for j in 0..nb {
                            let v = poly[1 + (k - 1) * nb + j];
                            let q = c.point((k - 1) as f64 + j as f64 / nb as f64);
                            prop_assert!(finite(&v) && amax(&(v - q)) <= BATCH_TOL * scale + FLOOR, "printed polyline vertex ({}, {}) {:?} vs curve {:?}", k, j, v, q);
                        }
                    }
                }
            }
            Ok(())
        })?;
    }

    /// `opengl_groups` and `opengl_polyline`: group structure, polyline = de Casteljau of each
    /// group.
    #[test]
    fn opengl_evaluator(pts in points::<2>(0..=14), order in count(0..=8), nseg in count(0..=10), printed in any::<bool>()) {
        guard(|| {
            let last = if printed { LastGroup::AsPrinted } else { LastGroup::Truncated };
            let scale = max_norm(&pts);
            let groups = opengl_groups(&pts, order, last);
            if let Ok(g) = &groups {
                prop_assert!(!g.is_empty());
                prop_assert!(g[0][0] == pts[0]);
                for group in g {
                    prop_assert!(group.len() >= 2 && group.len() <= order, "group of {} points for order {}", group.len(), order);
                    prop_assert!(all_finite(group));
                }
            }
            if let Ok(poly) = opengl_polyline(&pts, order, nseg, last) {
                let g = groups.expect("groups of an accepted polyline");
                prop_assert_eq!(poly.len(), g.len() * (nseg + 1));
                for (gi, group) in g.iter().enumerate() {
                    for k in 0..=nseg {
                        let v = poly[gi * (nseg + 1) + k];
                        let q = de_casteljau(group, k as f64 / nseg as f64).expect("non-empty group");
                        prop_assert!(finite(&v) && amax(&(v - q)) <= BATCH_TOL * scale + FLOOR, "OpenGL polyline ({}, {}): {:?} vs de Casteljau {:?}", gi, k, v, q);
                    }
                }
            }
            Ok(())
        })?;
    }

    /// `SlidingBicubic::try_new`, `eval`, `tabulate_cell`: finite on every cell, tabulation =
    /// evaluation, the Lagrange surface interpolates the grid.
    #[test]
    fn sliding_bicubic(rows in 0usize..=7, cols in 0usize..=7, d in values(0..=147), lagrange in any::<bool>(), cell in any::<(Index, Index)>(), uv in unit_pairs(), n in count(0..=6)) {
        guard(|| {
            let points = grid3(rows, cols, &d);
            let blending = if lagrange { Blending::Lagrange } else { Blending::UniformBSpline };
            let Ok(s) = SlidingBicubic::try_new(&points, blending) else { return Ok(()) };
            prop_assert_eq!(s.cells(), (rows - 3, cols - 3));
            let scale = max_norm(points.as_slice());
            let c = (cell.0.index(rows - 3), cell.1.index(cols - 3));
            for &(u, v) in &uv {
                prop_assert!(finite(&s.eval(c, u, v)), "non-finite at cell {:?} ({:e}, {:e})", c, u, v);
            }
            if lagrange {
                for (du, dv) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                    let q = s.eval(c, du as f64, dv as f64);
                    let p = points.get(c.0 + 1 + du, c.1 + 1 + dv);
                    prop_assert!(amax(&(q - p)) <= BATCH_TOL * scale + FLOOR, "Lagrange surface at cell {:?} corner ({}, {}): {:?} vs {:?}", c, du, dv, q, p);
                }
            }
            if let Ok(g) = s.tabulate_cell(c, n) {
                let us = linspace(0.0, 1.0, n);
                for (i, &u) in us.iter().enumerate() {
                    for (j, &v) in us.iter().enumerate() {
                        let (a, b) = (*g.get(i, j), s.eval(c, u, v));
                        prop_assert!(finite(&a) && amax(&(a - b)) <= BATCH_TOL * scale + FLOOR, "tabulate_cell {:?} vs eval {:?}", a, b);
                    }
                }
            }
            prop_assert!(s.tabulate_cell((rows, 0), 3).is_err() && s.tabulate_cell((0, cols), 3).is_err());
            Ok(())
        })?;
    }

    /// `matlab_norm`, `compare`, `ErrorAccumulator`: finite, between the largest entry and the
    /// Frobenius norm.
    #[test]
    fn metrics(r in 0usize..=5, c in 0usize..=5, d in values(0..=90), e in values(0..=90), shape_off in prop::bool::weighted(0.1)) {
        guard(|| {
            let m = DMatrix::from_fn(r, c, |i, j| if d.is_empty() { 0.0 } else { d[(i * c + j) % d.len()] });
            if let Ok(norm) = matlab_norm(&m) {
                prop_assert!(norm.is_finite() && norm >= 0.0, "norm {:e}", norm);
                let big = m.iter().fold(0.0, |a: f64, x| a.max(x.abs()));
                let frob = if big > 0.0 { big * m.iter().map(|x| (x / big) * (x / big)).sum::<f64>().sqrt() } else { 0.0 };
                prop_assert!(norm >= big * (1.0 - 1e-12) && norm <= frob * (1.0 + 1e-12), "2-norm {:e} outside [max entry {:e}, Frobenius {:e}]", norm, big, frob);
            }
            let ga = grid3(r, c, &d);
            let gb = grid3(maybe_off(r, shape_off), c, &e);
            if let Ok(errs) = compare(&ga, &gb) {
                prop_assert!(ga.rows() == gb.rows() && ga.cols() == gb.cols(), "compare accepted shapes {}x{} and {}x{}", ga.rows(), ga.cols(), gb.rows(), gb.cols());
                for k in 0..3 {
                    let want = ga.as_slice().iter().zip(gb.as_slice()).map(|(a, b)| (a[k] - b[k]).abs()).fold(0.0, f64::max);
                    let (n, mx, rms) = (errs.report_norm[k], errs.max_abs[k], errs.rms[k]);
                    prop_assert!(n.is_finite() && mx.is_finite() && rms.is_finite(), "errors {:?}", errs);
                    prop_assert_eq!(mx, want);
                    prop_assert!(rms <= mx * (1.0 + 1e-12) && n >= mx * (1.0 - 1e-12), "rms {:e}, norm {:e}, max {:e}", rms, n, mx);
                }
                let mut acc = ErrorAccumulator::new();
                acc.add_patch(&ga, &gb).expect("accepted by compare");
                acc.add_patch(&gb, &ga).expect("accepted by compare");
                let twice = acc.finish();
                prop_assert_eq!(twice.max_abs, errs.max_abs);
            }
            Ok(())
        })?;
    }

    /// `spline_errors`, `uniform_spline_errors`, `convergence`: finite, non-negative measures.
    #[test]
    fn study(kind in surf(), u in seq(0..=4, 1), v in seq(0..=4, 1), prec in count(0..=6), eval in select(PatchEvaluation::ALL.to_vec()), (ra, rb) in pair(), n in count(0..=3), m in count(0..=3), ns in vec(count(0..=3), 0..=3)) {
        guard(|| {
            let Some(surface) = build_surface(kind)? else { return Ok(()) };
            let check = |what: &str, e: &splinelab::CoordErrors| -> TestResult {
                for x in e.report_norm.iter().chain(e.max_abs.iter()).chain(e.rms.iter()) {
                    prop_assert!(x.is_finite() && *x >= 0.0, "{}: error measure {:?}", what, e);
                }
                Ok(())
            };
            if let (Ok(pu), Ok(pv)) = (Partition::try_new(u), Partition::try_new(v)) {
                if let Ok(e) = spline_errors(&*surface, pu, pv, prec, eval) {
                    check("spline_errors", &e)?;
                }
            }
            if let Ok(rect) = Rect::square(ra, rb) {
                if let Ok(e) = uniform_spline_errors(&*surface, &rect, n, m, prec, eval) {
                    check("uniform_spline_errors", &e)?;
                }
                if let Ok(rows) = convergence(&*surface, &rect, &ns, prec.min(6)) {
                    prop_assert_eq!(rows.len(), ns.len());
                    for row in &rows {
                        check("convergence", &row.errors)?;
                        prop_assert!(row.h.is_finite() && row.h > 0.0);
                        if let Some(o) = &row.order {
                            for x in o.report_norm.iter().chain(o.max_abs.iter()).chain(o.rms.iter()).flatten() {
                                prop_assert!(x.is_finite(), "order {:?}", o);
                            }
                        }
                    }
                }
            }
            Ok(())
        })?;
    }
}

// ------------------------------------------------------------------------------------------
// shared checks of the curve and surface targets
// ------------------------------------------------------------------------------------------

/// A Hermite spline reproduces `node_value(i, j)` at node `(uᵢ, vⱼ)`, is finite on its
/// domain, and tabulates as it evaluates.
fn check_spline_nodes(
    spline: &HermiteSurface,
    fu: &[f64],
    fv: &[f64],
    node_value: impl Fn(usize, usize) -> Vector3<f64>,
) -> TestResult {
    let (n, m) = spline.patch_counts();
    let mut scale: f64 = 0.0;
    for i in 0..n {
        for j in 0..m {
            scale = nanmax(scale, net_max(spline.patch(i, j).matrix()));
        }
    }
    prop_assert!(scale.is_finite(), "non-finite Hermite matrix in the spline");
    let (un, vn) = (spline.u().nodes().to_vec(), spline.v().nodes().to_vec());
    let d = spline.domain();
    prop_assert!(
        d.s.start() == un[0] && d.s.end() == un[n] && d.t.start() == vn[0] && d.t.end() == vn[m]
    );
    for (i, &u) in un.iter().enumerate() {
        for (j, &v) in vn.iter().enumerate() {
            let got = spline.try_point(u, v);
            let want = node_value(i, j);
            prop_assert!(
                got.as_ref()
                    .is_ok_and(|g| finite(g) && amax(&(g - want)) <= CORNER_TOL * scale + FLOOR),
                "node ({}, {}) = ({:e}, {:e}): spline {:?} vs data {:?} (scale {:e})",
                i,
                j,
                u,
                v,
                got,
                want,
                scale
            );
        }
    }
    let us = domain_params(un[0], un[n], fu, &un);
    let vs = domain_params(vn[0], vn[m], fv, &vn);
    let g = spline.tabulate(&us, &vs);
    prop_assert!(
        g.is_ok(),
        "tabulate refused in-domain samples: {:?}",
        g.err()
    );
    let g = g.expect("checked");
    for (i, &u) in us.iter().enumerate() {
        for (j, &v) in vs.iter().enumerate() {
            let p = spline.try_point(u, v);
            let t = *g.get(i, j);
            prop_assert!(
                p.as_ref().is_ok_and(|p| finite(p)
                    && finite(&t)
                    && amax(&(p - t)) <= BATCH_TOL * scale + FLOOR),
                "tabulate {:?} vs try_point {:?} at ({:e}, {:e})",
                t,
                p,
                u,
                v
            );
        }
    }
    let mut buf = vec![Vector3::new(f64::NAN, 0.0, 0.0)];
    prop_assert!(spline.tabulate_into(&us, &vs, &mut buf).is_ok());
    prop_assert_eq!(
        &buf[..],
        g.as_slice(),
        "tabulate_into differs from tabulate"
    );
    prop_assert!(spline.try_point(f64::NAN, vn[0]).is_err());
    prop_assert!(spline.tabulate(&[f64::NAN], &vs).is_err());
    Ok(())
}

/// Whether a B-spline-based curve's derivatives are certainly representable: moderate control
/// points, knot gaps and width.
fn moderate_knots(knots: &[f64], scale: f64) -> bool {
    let w = knots[knots.len() - 1] - knots[0];
    let min_gap = knots
        .windows(2)
        .map(|p| p[1] - p[0])
        .filter(|&g| g > 0.0)
        .fold(f64::INFINITY, f64::min);
    scale <= 1e100 && w <= 1e50 && min_gap >= 1e-50
}

fn check_bspline_curve<const N: usize>(
    what: &str,
    curve: &BSplineCurve<N>,
    fr: &[f64],
    samples: usize,
) -> TestResult {
    prop_assert!(
        all_finite(curve.points()),
        "{}: non-finite control points",
        what
    );
    let (a, b) = curve.domain();
    let knots = curve.basis().knots().knots();
    let params = domain_params(a, b, fr, knots);
    check_curve(what, curve, &params, samples)?;
    let scale = max_norm(curve.points());
    let (ts, inside) = batch_params(&params, a, b);
    let mut out = Vec::new();
    curve.eval_many(&ts, &mut out);
    check_batch(
        &format!("{what}: eval_many"),
        &ts,
        &inside,
        &out,
        |t| curve.point(t),
        scale,
    )?;
    if moderate_knots(knots, scale) {
        check_derivatives(what, curve, &params)?;
    }
    Ok(())
}

fn check_nurbs_curve<const N: usize>(what: &str, curve: &NurbsCurve<N>, fr: &[f64]) -> TestResult {
    prop_assert!(
        all_finite(curve.points()),
        "{}: non-finite control points",
        what
    );
    let (a, b) = curve.domain();
    let knots = curve.basis().knots().knots();
    let params = domain_params(a, b, fr, knots);
    check_curve(what, curve, &params, 5)?;
    let scale = max_norm(curve.points());
    let (ts, inside) = batch_params(&params, a, b);
    let mut out = Vec::new();
    curve.eval_many(&ts, &mut out);
    check_batch(
        &format!("{what}: eval_many"),
        &ts,
        &inside,
        &out,
        |t| curve.point(t),
        scale,
    )?;
    let w = curve.weights();
    let ratio =
        w.iter().copied().fold(f64::INFINITY, f64::min) / w.iter().copied().fold(0.0, f64::max);
    if moderate_knots(knots, scale) && ratio >= 1e-50 {
        check_derivatives(what, curve, &params)?;
    }
    Ok(())
}

fn check_cubic_curve<const N: usize>(
    what: &str,
    s: &CubicSpline<N>,
    fr: &[f64],
    nodes: &[f64],
) -> TestResult {
    let (a, b) = s.domain();
    let params = domain_params(a, b, fr, nodes);
    check_curve(what, s, &params, 6)?;
    let (ts, inside) = batch_params(&params, a, b);
    let mut out = Vec::new();
    s.eval_many(&ts, &mut out);
    let vscale = params.iter().map(|&t| amax(&s.point(t))).fold(0.0, nanmax);
    check_batch(
        &format!("{what}: eval_many"),
        &ts,
        &inside,
        &out,
        |t| s.point(t),
        vscale,
    )?;
    Ok(())
}

// ------------------------------------------------------------------------------------------
// issue 23: distances, the point search, the figure builders
// ------------------------------------------------------------------------------------------

#[path = "common/mod.rs"]
mod common;

/// A shape (polyline) of a few points at one random magnitude, for the search target.
fn small_outline() -> impl Strategy<Value = (Vec<Vector2<f64>>, bool)> {
    (
        vec((-1.0f64..1.0, -1.0f64..1.0), 3..=7),
        -300i32..=300,
        prop::bool::ANY,
    )
        .prop_map(|(raw, e, closed)| {
            let m = 10f64.powi(e);
            (
                raw.into_iter()
                    .map(|(x, y)| Vector2::new(x, y) * m)
                    .collect(),
                closed,
            )
        })
}

#[cfg(feature = "report")]
static FIGURE_HUNG: AtomicBool = AtomicBool::new(false);

proptest! {
    #![proptest_config(config())]

    /// Distances against the exact rational reference in rescaled coordinates, at
    /// magnitudes 1e-300 … 1e300 (points anywhere, and points within 1e-6 of the segment's
    /// size from it): exact to rounding of the distance itself; the polyline distances are
    /// the brute-force minimum of the same kernel.
    #[test]
    fn distances_are_exact_at_every_magnitude(
        e in -300i32..=300,
        v in prop::array::uniform6(-1.0f64..1.0),
        near in 0.0f64..1.0,
        more in vec((-1.0f64..1.0, -1.0f64..1.0), 1..6),
    ) {
        guard(|| {
            use splinelab::metrics::curve::{segment_distance, SegmentTree};
            let m = 10f64.powi(e);
            let (a, b) = (Vector2::new(v[0], v[1]) * m, Vector2::new(v[2], v[3]) * m);
            let p = if near < 0.5 {
                a + (b - a) * (2.0 * near) + Vector2::new(v[4], v[5]) * (m * 1e-6)
            } else {
                Vector2::new(v[4], v[5]) * m
            };
            let d = segment_distance(p, a, b);
            let exact = common::exact_segment_distance(p, a, b);
            prop_assert!(common::distance_close(d, exact, 4.0 * m), "{:?} {:?} {:?}: {} vs exact {}", p, a, b, d, exact);
            let line: Vec<Vector2<f64>> = std::iter::once(a).chain(std::iter::once(b)).chain(more.iter().map(|&(x, y)| Vector2::new(x, y) * m)).collect();
            let tree = SegmentTree::new(&line).unwrap();
            let brute = line.windows(2).map(|w| segment_distance(p, w[0], w[1])).fold(f64::INFINITY, f64::min);
            prop_assert_eq!(tree.distance(p), brute);
            Ok(())
        })?;
    }

    /// `SegmentTree::farthest_below_from`, whichever point it measures first, is
    /// `farthest_below`: below the limit the same exact largest distance (the brute-force
    /// maximum of minima), at or above it a distance at least the limit.
    #[test]
    fn the_first_point_changes_no_farthest_distance(
        line in vec((-1.0f64..1.0, -1.0f64..1.0), 1..12),
        from in vec((-2.0f64..2.0, -2.0f64..2.0), 1..40),
        first in 0usize..50,
        limit in prop::option::of(0.0f64..2.0),
    ) {
        guard(|| {
            use splinelab::metrics::curve::{segment_distance, SegmentTree};
            let v = |&(x, y): &(f64, f64)| Vector2::new(x, y);
            let line: Vec<Vector2<f64>> = line.iter().map(v).collect();
            let from: Vec<Vector2<f64>> = from.iter().map(v).collect();
            let tree = SegmentTree::new(&line).unwrap();
            let limit = limit.unwrap_or(f64::INFINITY);
            let brute = from
                .iter()
                .map(|&p| {
                    if line.len() == 1 {
                        segment_distance(p, line[0], line[0])
                    } else {
                        line.windows(2).map(|w| segment_distance(p, w[0], w[1])).fold(f64::INFINITY, f64::min)
                    }
                })
                .fold(0.0, f64::max);
            let (plain, _) = tree.farthest_below(&from, limit);
            let (probed, at) = tree.farthest_below_from(&from, limit, Some(first));
            prop_assert!(at.is_some_and(|i| i < from.len()));
            if brute < limit {
                prop_assert_eq!(plain, brute);
                prop_assert_eq!(probed, brute);
            } else {
                prop_assert!(plain >= limit && probed >= limit, "{} {} vs limit {}", plain, probed, limit);
            }
            Ok(())
        })?;
    }

    /// The point search on small outlines at any magnitude: a typed error or a choice that
    /// counts at most `max_points`, valid for its method, whose reported error is what an
    /// independent measure of its curve gives (brute-force distances between the sampled
    /// curve and the outline).
    #[test]
    fn the_point_search_keeps_its_bounds((outline, closed) in small_outline(), family in 0usize..5, max_points in 0usize..9) {
        use splinelab::metrics::curve::{sample_pieces, segment_distance};
        use splinelab::interp::choice::{fewest_points, Family, SearchOptions, Target, FINAL_SAMPLES};
        let family = [Family::Angular, Family::Cardinal, Family::Cubic, Family::BSpline, Family::Linear][family];
        guard(|| {
            let size = outline.iter().map(|p| p.amax()).fold(0.0, f64::max);
            let Ok(target) = Target::polyline(&outline, closed, 0.05 * size) else {
                return Ok(());
            };
            let options = SearchOptions { max_points, budget_per_coordinate: 2, random_starts: 1, every_count_below: false, ..SearchOptions::default() };
            let Ok(c) = fewest_points(&target, family, &options) else {
                return Ok(());
            };
            prop_assert!(c.measure.counted <= max_points, "{} > {}", c.measure.counted, max_points);
            let curve = c.method.curve(&c.points, target.is_closed());
            prop_assert!(curve.is_ok(), "the chosen configuration does not build: {:?}", curve.err());
            let curve = curve.unwrap();
            let line = sample_pieces(&curve, &curve.breaks(), FINAL_SAMPLES).unwrap();
            let reference = target.reference();
            let to = |from: &[Vector2<f64>], onto: &[Vector2<f64>]| {
                from.iter()
                    .map(|&x| onto.windows(2).map(|w| segment_distance(x, w[0], w[1])).fold(f64::INFINITY, f64::min))
                    .fold(0.0, f64::max)
            };
            let brute = to(&line, reference).max(to(reference, &line));
            let reported = c.measure.distances.hausdorff();
            prop_assert!((brute - reported).abs() <= 1e-9 * brute.max(size) + FLOOR, "reported {} vs recomputed {}", reported, brute);
            prop_assert_eq!(c.within_tolerance, reported <= target.tolerance());
            Ok(())
        })?;
    }

    /// The figure builders never panic or hang on any data, finite or not: a plane figure
    /// of lines, marks and notes (any styles and sizes, fixed ranges, log axes, equal
    /// aspect) and a 3-D scene each draw as SVG or return a typed error.
    #[cfg(feature = "report")]
    #[test]
    fn figures_draw_any_data(
        pts in vec((num(), num()), 0..12),
        range in prop::option::of((num(), num())),
        flags in prop::array::uniform4(prop::bool::ANY),
        mark in prop_oneof![Just(0u32), 1u32..20, Just(u32::MAX)],
        size in (0u32..20_000, 0u32..20_000),
        layout in (0usize..4, 0usize..4),
        view in prop::array::uniform3(num()),
    ) {
        use plotters::prelude::RGBColor;
        use splinelab::report::figure::{Drawing, Figure};
        use splinelab::report::plot2d::{Figure2d, Panel, Series, Style};
        use splinelab::report::render3d::{Figure3d, Marker, Quad, Scene, Segment, View};
        let what = format!("figures over {pts:?}");
        guard_with_watchdog(&FIGURE_HUNG, what, move || {
            let mut panel = Panel::new("random", "x", "y")
                .with(Series::line("l", pts.clone(), RGBColor(0, 0, 0)).width(mark))
                .with(Series::line("p", pts.clone(), RGBColor(9, 9, 9)).styled(Style::Points(mark)))
                .with(Series::line("c", pts.clone(), RGBColor(9, 9, 9)).styled(Style::Crosses(mark)))
                .with(Series::line("d", pts.clone(), RGBColor(9, 9, 9)).styled(Style::Dashed))
                .log(flags[0], flags[1]);
            if flags[2] {
                panel = panel.equal();
            }
            if let Some((lo, hi)) = range {
                panel = panel.x_range(lo, hi).y_range(hi, lo);
            }
            for &(x, y) in pts.iter().take(2) {
                panel = panel.note(x, y, "n");
            }
            let mut plane = Figure2d::new("random", vec![panel.clone(), panel], layout);
            if flags[3] {
                plane = plane.shared_legend();
            }
            let fig = Figure::new(Drawing::Plane(plane)).with_size(size.0, size.1);
            match fig.to_svg() {
                Ok(svg) => prop_assert!(svg.contains("<svg")),
                Err(e) => prop_assert!(matches!(e, splinelab::report::Error::Figure { .. }), "{:?}", e),
            }
            // rasterised too (the bitmap backend loops over pixels), small
            if let Err(e) = fig.clone().with_size(120, 90).to_rgb() {
                prop_assert!(matches!(e, splinelab::report::Error::Figure { .. }), "{:?}", e);
            }
            let p3 = |k: usize| {
                let (x, y) = pts.get(k % pts.len().max(1)).copied().unwrap_or((0.0, 1.0));
                Vector3::new(x, y, x - y)
            };
            let mut scene = Scene::default();
            scene.quads.push(Quad { corners: [p3(0), p3(1), p3(2), p3(3)], color: RGBColor(1, 2, 3), alpha: 0.5 });
            scene.segments.push(Segment { a: p3(4), b: p3(5), color: RGBColor(1, 2, 3), width: mark, arrow: true });
            scene.markers.push(Marker { at: p3(6), color: RGBColor(1, 2, 3), radius: mark });
            let view = View { yaw: view[0], pitch: view[1], scale: view[2] };
            let fig = Figure::new(Drawing::Scene(Figure3d { title: "random".into(), scene, view }));
            match fig.to_svg() {
                Ok(svg) => prop_assert!(svg.contains("<svg")),
                Err(e) => prop_assert!(matches!(e, splinelab::report::Error::Figure { .. }), "{:?}", e),
            }
            if let Err(e) = fig.with_size(120, 90).to_rgb() {
                prop_assert!(matches!(e, splinelab::report::Error::Figure { .. }), "{:?}", e);
            }
            Ok(())
        })?;
    }
}
