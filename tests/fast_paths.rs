//! The fast paths of issue 13 against their reference paths, at sizes that cross the
//! two-thread thresholds:
//!
//! - `BSplineCurve::eval_many` / `NurbsCurve::eval_many` at any degree (per-span power forms
//!   from blossoming, both cores from 65 536 parameters) against point-by-point evaluation
//!   (*The NURBS Book* A2.2), on knots with near-coincident pairs, sorted and shuffled;
//! - `CubicSpline` natural and clamped (twisted factorization, both cores from 16 384
//!   unknowns) against its defining property, `C²` continuity at every node and the end
//!   conditions, measured from evaluations on either side of each node; `refit` against a
//!   fresh build, bit for bit;
//! - `HermiteSurface::tabulate_into` (rows split between two threads from 65 536 points)
//!   against `ParametricSurface::point`.
//!
//! One tolerance policy: errors relative to the data's scale, with the documented bound of
//! each fast path (power forms in the scaled variable: `(p + 2) · 256 ε · max ‖Pᵢ‖`).

use nalgebra::{SVector, Vector1, Vector2, Vector3};
use proptest::prelude::*;
use splinelab::{
    BSplineBasis, BSplineCurve, CubicSpline, EndCondition, HermiteSurface, KnotVector, NurbsCurve,
    ParametricCurve, Partition, SurfaceDerivatives, Torus,
};

/// Batch accuracy at degree `p`, relative to the largest control point: the documented bound
/// `(p + 2) · 256 ε` of the power-form path with room, `6e-14 · p`, at least `2e-13` (see
/// tests/exact_reference.rs).
fn tol_batch(p: usize) -> f64 {
    2e-13_f64.max(6e-14 * p as f64)
}

/// A deterministic generator (xorshift), so one proptest seed makes one large case.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A clamped knot vector of degree `p` on `[0, 1]` with `interior` interior knots, some of
/// them in near-coincident pairs (gaps of 1e-7, 1e-12 and one ulp) and some repeated.
fn knots(p: usize, interior: usize, rng: &mut Rng) -> Vec<f64> {
    let mut inner: Vec<f64> = Vec::new();
    while inner.len() < interior {
        let t = 0.02 + 0.96 * rng.next();
        inner.push(t);
        match (rng.next() * 6.0) as usize {
            0 => inner.push(t + 1e-12),
            1 => inner.push(t + 1e-7),
            2 if p > 1 => inner.push(t),
            3 => inner.push(t.next_up()),
            _ => {}
        }
    }
    inner.sort_by(f64::total_cmp);
    let mut k = vec![0.0; p + 1];
    k.extend(inner);
    k.extend(vec![1.0; p + 1]);
    k
}

/// Random knots of degree `p` ([`knots`]), their basis and a control polygon in the plane.
fn plane_curve(
    p: usize,
    interior: usize,
    rng: &mut Rng,
) -> (Vec<f64>, BSplineBasis, Vec<Vector2<f64>>) {
    let k = knots(p, interior, rng);
    let basis = BSplineBasis::try_new(KnotVector::try_new(k.clone()).unwrap(), p).unwrap();
    let points = (0..basis.len())
        .map(|_| Vector2::new(rng.next() - 0.5, rng.next()))
        .collect();
    (k, basis, points)
}

/// Parameters across the domain: many sorted ones (crossing the threading threshold when
/// `n` is large), every knot and its neighbours, the ends.
fn params(k: &[f64], n: usize, shuffle: bool, rng: &mut Rng) -> Vec<f64> {
    let mut ts: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
    for &x in k {
        ts.extend([x, x.next_up().min(1.0), x.next_down().max(0.0)]);
    }
    order(&mut ts, shuffle, rng);
    ts
}

/// Shuffles `v` (Fisher–Yates from `rng`) or sorts it.
fn order(v: &mut [f64], shuffle: bool, rng: &mut Rng) {
    if shuffle {
        for i in (1..v.len()).rev() {
            let j = (rng.next() * (i + 1) as f64) as usize;
            v.swap(i, j.min(i));
        }
    } else {
        v.sort_by(f64::total_cmp);
    }
}

fn check_batch<const N: usize>(
    what: &str,
    ts: &[f64],
    out: &[SVector<f64, N>],
    point: impl Fn(f64) -> SVector<f64, N>,
    tol: f64,
) -> Result<(), TestCaseError> {
    prop_assert_eq!(out.len(), ts.len());
    for (&t, o) in ts.iter().zip(out) {
        let r = point(t);
        prop_assert!(
            (o - r).amax() <= tol,
            "{}: at t = {:e}, batch {:?} vs pointwise {:?} (tolerance {:e})",
            what,
            t,
            o,
            r,
            tol
        );
    }
    Ok(())
}

/// `cases` per property (large cases are costly), or `PROPTEST_CASES` for a soak.
fn config(cases: u32) -> ProptestConfig {
    let soak = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok());
    ProptestConfig {
        cases: soak.unwrap_or(cases),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config(24))]

    /// B-spline curves of degree 0 … 9 (array storage up to 7, `Vec` above): batch = pointwise.
    #[test]
    fn bspline_batch_equals_pointwise(seed in any::<u64>(), p in 0usize..=9, interior in 0usize..=30, big in prop::bool::weighted(0.2), shuffle in any::<bool>()) {
        let mut rng = Rng(seed | 1);
        let k = knots(p, interior, &mut rng);
        let basis = BSplineBasis::try_new(KnotVector::try_new(k.clone()).unwrap(), p).unwrap();
        let points: Vec<Vector3<f64>> = (0..basis.len())
            .map(|_| Vector3::new(rng.next() - 0.5, 10.0 * rng.next(), 1e-3 * rng.next()))
            .collect();
        let scale = points.iter().map(|v| v.amax()).fold(0.0, f64::max);
        let curve = BSplineCurve::try_new(basis, points).unwrap();
        let ts = params(&k, if big { 70_000 } else { 300 }, shuffle, &mut rng);
        let mut out = vec![Vector3::new(f64::NAN, 0.0, 0.0); 5]; // a used buffer
        curve.eval_many(&ts, &mut out);
        check_batch("B-spline", &ts, &out, |t| curve.point(t), tol_batch(p) * scale)?;
    }

    /// NURBS curves of degree 1 … 8 with weights in [0.2, 5], or over seven decades
    /// (`wild`): batch = pointwise. Both paths keep their accuracy relative to the points
    /// whatever the weights (sums of positive terms, divided by the sum of their weights), so
    /// the tolerance does not grow with the weights' ratio: twice the B-spline's, numerator
    /// and denominator.
    #[test]
    fn nurbs_batch_equals_pointwise(seed in any::<u64>(), p in 1usize..=8, interior in 0usize..=20, big in prop::bool::weighted(0.2), shuffle in any::<bool>(), wild in prop::bool::weighted(0.3)) {
        let mut rng = Rng(seed | 1);
        let (k, basis, points) = plane_curve(p, interior, &mut rng);
        let weights: Vec<f64> = (0..basis.len())
            .map(|_| if wild { 10f64.powf(7.0 * rng.next() - 1.0) } else { 0.2 + 4.8 * rng.next() })
            .collect();
        let scale = points.iter().map(|v| v.amax()).fold(0.0, f64::max);
        let curve = NurbsCurve::try_new(basis, points, weights).unwrap();
        let ts = params(&k, if big { 70_000 } else { 300 }, shuffle, &mut rng);
        let mut out = Vec::new();
        curve.eval_many(&ts, &mut out);
        check_batch("NURBS", &ts, &out, |t| curve.point(t), 2.0 * tol_batch(p) * scale)?;
    }
}

/// `C²` continuity at every interior node and the end conditions, from one-sided
/// evaluations: `s′` and `s″` just left of `xᵢ` (the left piece) against at `xᵢ` (the right
/// piece), relative to the scale of the derivatives on the neighbouring pieces.
fn check_c2<const N: usize>(
    what: &str,
    s: &CubicSpline<N>,
    end: &EndCondition<N>,
) -> Result<(), TestCaseError> {
    let x = s.nodes();
    let n = x.len() - 1;
    let d2 = |t: f64| s.derivatives2(t);
    let mut d1_scale = 0.0_f64;
    let mut d2_scale = 0.0_f64;
    for &t in x {
        let [_, a, b] = d2(t);
        d1_scale = d1_scale.max(a.amax());
        d2_scale = d2_scale.max(b.amax());
    }
    for i in 1..n {
        let h = (x[i + 1] - x[i]).max(x[i] - x[i - 1]);
        let left = x[i].next_down();
        let [_, l1, l2] = d2(left);
        let [_, r1, r2] = d2(x[i]);
        // the left value is one ulp before the node: s′ moves by ulp · s″ and s″ by
        // ulp · s‴ there, with |s‴| ≤ 2 max|s″| / hᵢ₋₁ on the left piece
        let ulp = x[i] - left;
        let tol1 = 1e-10 * (d1_scale + d2_scale * h) + 2.0 * ulp * d2_scale;
        let tol2 = 1e-10 * d2_scale + 4.0 * ulp * d2_scale / (x[i] - x[i - 1]) + 1e-300;
        prop_assert!(
            (l1 - r1).amax() <= tol1,
            "{}: s′ jumps at x[{}]: {:?} vs {:?}",
            what,
            i,
            l1,
            r1
        );
        prop_assert!(
            (l2 - r2).amax() <= tol2,
            "{}: s″ jumps at x[{}]: {:?} vs {:?}",
            what,
            i,
            l2,
            r2
        );
    }
    let [d1a, d2a, d1b, d2b] = s.end_derivatives();
    match end {
        EndCondition::Natural => {
            prop_assert!(
                d2a.amax() <= 1e-12 * d2_scale && d2b.amax() <= 1e-12 * d2_scale,
                "{}: natural ends {:?} {:?}",
                what,
                d2a,
                d2b
            );
        }
        EndCondition::Clamped { start, end } => {
            let tol = 1e-10 * (d1_scale + start.amax() + end.amax());
            prop_assert!(
                (d1a - start).amax() <= tol && (d1b - end).amax() <= tol,
                "{}: clamped ends {:?} {:?}",
                what,
                d1a,
                d1b
            );
        }
        _ => {}
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(16))]

    /// Natural and clamped splines through uneven data (gaps over six orders of magnitude),
    /// sizes on both sides of the two-thread threshold and of the huge-page advice (300 000
    /// points of 2-D values: 4.8 MB buffers): `C²` and the end conditions hold; a
    /// refit to the same data is the fresh build bit for bit, and a refit to other data (of
    /// another size) is that data's fresh build.
    #[test]
    fn cubic_spline_fast_build(seed in any::<u64>(), n in prop_oneof![6 => 3usize..=40, 1 => Just(16_385usize), 1 => Just(33_000usize), 1 => Just(300_000usize)], clamped in any::<bool>(), spread in 0.0f64..6.0) {
        let mut rng = Rng(seed | 1);
        let mut x = vec![0.0];
        for _ in 0..n {
            let gap = 10f64.powf(spread * (rng.next() - 0.5));
            x.push(x[x.len() - 1] + gap);
        }
        let y: Vec<Vector2<f64>> = x.iter().map(|&t| Vector2::new(t.sin() + rng.next(), 1e3 * rng.next())).collect();
        let end = if clamped {
            EndCondition::Clamped { start: Vector2::new(1.0, -2.0), end: Vector2::new(0.5, 3.0) }
        } else {
            EndCondition::Natural
        };
        let s = CubicSpline::try_new(&x, &y, end).unwrap();
        for (i, (&t, v)) in x.iter().zip(&y).enumerate() {
            prop_assert_eq!(s.point(t), *v, "interpolation at x[{}]", i);
        }
        check_c2("spline", &s, &end)?;
        let fresh = s.clone();
        let again = s.refit(&x, &y).unwrap();
        prop_assert!(again == fresh, "refit to the same data differs from the fresh build");
        let x2: Vec<f64> = x.iter().take(n / 2 + 2).map(|t| 2.0 * t).collect();
        let y2: Vec<Vector2<f64>> = y.iter().take(x2.len()).map(|v| v * -0.5).collect();
        let other = again.refit(&x2, &y2).unwrap();
        prop_assert!(other == CubicSpline::try_new(&x2, &y2, end).unwrap(), "refit to other data differs from its fresh build");
    }
}

/// A refit with bad data is a typed error, like a fresh build.
/// A one-ulp span beside a weight 5·10⁶ times its neighbours' (found by the random-input
/// tests in CI): at the span's start the large weight's basis function is `2·10⁻¹⁶`, and its
/// term `10⁻¹⁰` is a relative `10⁻⁹` of the value. The span's Bézier points must keep it —
/// each blossom weight `1 − α` taken from the distance to its interval's end, not from `α`.
#[test]
fn nurbs_with_a_one_ulp_span_beside_a_large_weight() {
    let k = vec![
        0.0,
        0.0,
        0.01,
        0.22925650968535213,
        2.2038453795055086,
        2.203845379505509,
        2.213845379505509,
        2.213845379505509,
    ];
    let basis = BSplineBasis::try_new(KnotVector::try_new(k.clone()).unwrap(), 2).unwrap();
    let y = -5.469846761685938;
    let points = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(0.0, y),
        Vector2::new(0.0, 0.0),
        Vector2::new(0.0, y),
        Vector2::new(0.0, 0.0),
    ];
    let weights = vec![0.1, 0.1, 533103.087850527, 0.1, 0.1];
    let curve = NurbsCurve::try_new(basis, points, weights).unwrap();
    let mut ts = vec![k[4], k[4].next_up(), k[5]];
    ts.extend((0..=100).map(|i| k[3] + (k[4] - k[3]) * i as f64 / 100.0));
    let mut out = Vec::new();
    curve.eval_many(&ts, &mut out);
    for (t, b) in ts.iter().zip(&out) {
        let s = curve.point(*t);
        assert!(
            (b - s).amax() <= 2.0 * tol_batch(2) * y.abs(),
            "t = {t:e}: batch {b:?}, pointwise {s:?}"
        );
    }
    // the value at the span's start, by hand: N₂ = (t₅ − t₄)/(t₅ − t₃), N₃ = 1 − N₂
    let n2 = (k[5] - k[4]) / (k[5] - k[3]);
    let (w2, w3) = (533103.087850527 * n2, 0.1 * (1.0 - n2));
    let expected = y * w3 / (w2 + w3);
    assert!(
        (out[0].y - expected).abs() <= 1e-15 * y.abs(),
        "{} vs {expected}",
        out[0].y
    );
}

#[test]
fn cubic_spline_refit_rejects_bad_data() {
    let x = [0.0, 1.0, 2.0, 3.0];
    let s = CubicSpline::function(&x, &[0.0, 1.0, 0.0, 1.0], EndCondition::Natural).unwrap();
    let bad = s
        .clone()
        .refit_function(&x, &[0.0, f64::NAN, 0.0, 1.0])
        .unwrap_err();
    let fresh =
        CubicSpline::function(&x, &[0.0, f64::NAN, 0.0, 1.0], EndCondition::Natural).unwrap_err();
    assert_eq!(bad.to_string(), fresh.to_string());
    assert!(s
        .clone()
        .refit_function(&[0.0, 1.0, 1.0, 3.0], &[0.0; 4])
        .is_err());
    assert!(s.refit(&[0.0], &[Vector1::new(0.0)]).is_err());
}

/// The torus as 16 × 16 patches tabulated on 300 × 301 nodes (two threads) against `point`.
#[test]
fn torus_grid_tabulation_equals_pointwise() {
    let tau = std::f64::consts::TAU;
    let spline = HermiteSurface::try_from_surface(
        &Torus::default(),
        Partition::uniform(0.0, tau, 16).unwrap(),
        Partition::uniform(0.0, tau, 16).unwrap(),
    )
    .unwrap();
    let us: Vec<f64> = (0..300).map(|i| tau * i as f64 / 299.0).collect();
    let vs: Vec<f64> = (0..301).map(|i| tau * i as f64 / 300.0).collect();
    let mut out = vec![Vector3::zeros(); 7];
    spline.tabulate_into(&us, &vs, &mut out).unwrap();
    assert_eq!(out.len(), us.len() * vs.len());
    for (i, &u) in us.iter().enumerate() {
        for (j, &v) in vs.iter().enumerate() {
            let r = spline.point(u, v);
            let o = out[i * vs.len() + j];
            assert!((o - r).amax() <= 1e-14 * 3.0, "({u}, {v}): {o:?} vs {r:?}");
        }
    }
}

/// Issue 23, class 5: outside a very short domain the span's power form was extrapolated a
/// million widths away (knots `[0,1,2,3,3+1e-9,4,5,6]`, degree 3, at 2.999: 1e-2 from
/// `point()` on the earlier code). Outside the domain the batch evaluates as the single
/// point does: the same value exactly, for B-spline and NURBS curves, sorted or not.
#[test]
fn outside_the_domain_the_batch_is_the_single_evaluation() {
    let k = vec![0.0, 1.0, 2.0, 3.0, 3.0 + 1e-9, 4.0, 5.0, 6.0];
    let basis = BSplineBasis::try_new(KnotVector::try_new(k).unwrap(), 3).unwrap();
    let points = vec![
        Vector2::new(0.0, 1.0),
        Vector2::new(2.0, -1.0),
        Vector2::new(3.0, 4.0),
        Vector2::new(-1.0, 0.5),
    ];
    let curve = BSplineCurve::try_new(basis.clone(), points.clone()).unwrap();
    let nurbs = NurbsCurve::try_new(basis, points, vec![1.0, 2.0, 0.5, 1.5]).unwrap();
    let ts = [
        2.999,
        -1e3,
        3.0,
        3.0 + 5e-10,
        3.0 + 1e-9,
        3.1,
        7.0,
        2.999,
        3.0 + 2e-10,
        1e6,
        -0.0,
    ];
    let (mut a, mut b) = (Vec::new(), Vec::new());
    curve.eval_many(&ts, &mut a);
    nurbs.eval_many(&ts, &mut b);
    for (i, &t) in ts.iter().enumerate() {
        let (lo, hi) = curve.domain();
        if !(lo..=hi).contains(&t) {
            assert_eq!(a[i], curve.point(t), "B-spline at {t}");
            assert_eq!(b[i], nurbs.point(t), "NURBS at {t}");
        } else {
            let scale = 4.0;
            assert!(
                (a[i] - curve.point(t)).amax() <= tol_batch(3) * scale,
                "B-spline at {t}"
            );
            assert!(
                (b[i] - nurbs.point(t)).amax() <= 2.0 * tol_batch(3) * scale,
                "NURBS at {t}"
            );
        }
    }
}

/// A B-spline curve in the plane on random knots ([`plane_curve`]), the NURBS curve on the same
/// basis and points with weights in [0.5, 1.5], and the distinct knots of the domain.
fn curve_pair(
    p: usize,
    interior: usize,
    rng: &mut Rng,
) -> (BSplineBasis, BSplineCurve<2>, NurbsCurve<2>, Vec<f64>) {
    let (k, basis, points) = plane_curve(p, interior, rng);
    let weights: Vec<f64> = (0..basis.len()).map(|_| 0.5 + rng.next()).collect();
    let curve = BSplineCurve::try_new(basis.clone(), points.clone()).unwrap();
    let nurbs = NurbsCurve::try_new(basis.clone(), points, weights).unwrap();
    let mut distinct = k[p..k.len() - p].to_vec();
    distinct.dedup();
    (basis, curve, nurbs, distinct)
}

/// Queries for a partition of `nodes` (issue 26): sorted with a stride that skips `skip`
/// intervals between neighbours (the galloping search's case), shuffled, and the domain's
/// ends, points outside and beyond, and non-finite values mixed in.
fn strided_queries(nodes: &[f64], skip: usize, shuffle: bool, rng: &mut Rng) -> Vec<f64> {
    let (a, b) = (nodes[0], nodes[nodes.len() - 1]);
    let mut xs: Vec<f64> = nodes
        .windows(2)
        .step_by(skip.max(1))
        .map(|w| w[0] + (w[1] - w[0]) * rng.next())
        .collect();
    xs.extend([a, b, a.next_down(), b.next_up(), a - 1e3, b + 1e3]);
    xs.extend(nodes.iter().step_by(skip.max(1)).copied());
    order(&mut xs, shuffle, rng);
    xs
}

proptest! {
    #![proptest_config(config(12))]

    /// The cubic spline's batch at queries that skip intervals (the galloping cursor, from the
    /// uniform guess or the previous interval), in any order, on nearly uniform nodes and on
    /// gaps over six decades, outside the domain and at non-finite points: the single
    /// evaluation, bit for bit (one formula, the same interval).
    #[test]
    fn cubic_spline_batch_skipping_intervals_is_the_single_evaluation(seed in any::<u64>(), n in prop_oneof![2 => 3usize..=50, 1 => Just(5_000usize), 1 => Just(120_000usize)], skip in prop_oneof![Just(1usize), Just(3usize), Just(97usize), Just(4_099usize)], shuffle in any::<bool>(), wild in any::<bool>()) {
        let mut rng = Rng(seed | 1);
        let mut x = vec![0.0];
        for _ in 1..n {
            // gaps over six decades (`wild`): the uniform guess misses, the cursor falls back
            // to the previous interval
            let last = x[x.len() - 1];
            let spread = if wild { 10f64.powf(6.0 * rng.next()) } else { 1.0 };
            x.push(last + (0.01 + rng.next()) * spread);
        }
        let y: Vec<f64> = x.iter().map(|v| (0.3 * v).sin()).collect();
        let spline = CubicSpline::function(&x, &y, EndCondition::Natural).unwrap();
        let mut xs = strided_queries(&x, skip, shuffle, &mut rng);
        xs.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY, x[n / 2]]);
        let mut out = vec![7.0; 3];
        spline.values_into(&xs, &mut out);
        prop_assert_eq!(out.len(), xs.len());
        for (&q, &v) in xs.iter().zip(&out) {
            let r = spline.value(q);
            prop_assert!(v.to_bits() == r.to_bits() || (v.is_nan() && r.is_nan()), "at {:e}: batch {:e}, single {:e}", q, v, r);
        }
    }

    /// B-spline and NURBS curves with many spans (up to 40 000) at parameters that skip
    /// spans, sorted or shuffled, repeated knots included: batch = pointwise within the
    /// batch accuracy, and the span the batch walks is `find_span`'s.
    #[test]
    fn bspline_batch_skipping_spans_equals_pointwise(seed in any::<u64>(), p in 1usize..=5, interior in prop_oneof![Just(200usize), Just(40_000usize)], skip in prop_oneof![Just(1usize), Just(13usize), Just(1_001usize)], shuffle in any::<bool>()) {
        let mut rng = Rng(seed | 1);
        let (_, curve, nurbs, distinct) = curve_pair(p, interior, &mut rng);
        let ts = strided_queries(&distinct, skip, shuffle, &mut rng);
        let (mut a, mut b) = (Vec::new(), Vec::new());
        curve.eval_many(&ts, &mut a);
        nurbs.eval_many(&ts, &mut b);
        check_batch("B-spline", &ts, &a, |t| curve.point(t), tol_batch(p))?;
        check_batch("NURBS", &ts, &b, |t| nurbs.point(t), 2.0 * tol_batch(p))?;
    }
}

/// Whether two values are the same bit for bit (NaN: any NaN).
fn same_bits<const N: usize>(a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
    a.iter()
        .zip(b.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
}

proptest! {
    #![proptest_config(config(16))]

    /// Sparse batches (issue 26): parameters in spans that hold fewer than four of the queries
    /// (`FORM_MIN_RUN`, below which no power form is made) are evaluated several at a time
    /// side by side (`Lanes`) — the same operations as the single evaluation, so the values
    /// are `ParametricCurve::point`'s bit for bit, at every degree (lanes up to 7, one at a
    /// time above), sorted or shuffled, inside and outside the domain.
    #[test]
    fn sparse_batches_are_the_single_evaluation_bit_for_bit(seed in any::<u64>(), p in 0usize..=9, interior in prop_oneof![Just(40usize), Just(5_000usize)], skip in prop_oneof![Just(1usize), Just(3usize), Just(13usize), Just(101usize)], shuffle in any::<bool>()) {
        let mut rng = Rng(seed | 1);
        let (basis, curve, nurbs, distinct) = curve_pair(p, interior, &mut rng);
        let mut ts = strided_queries(&distinct, skip, shuffle, &mut rng);
        ts.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e300, 1e300]);
        order(&mut ts, shuffle, &mut rng);
        let mut per_span = std::collections::HashMap::new();
        for &t in &ts {
            *per_span.entry(basis.find_span(t)).or_insert(0usize) += 1;
        }
        let (mut a, mut b) = (Vec::new(), Vec::new());
        curve.eval_many(&ts, &mut a);
        nurbs.eval_many(&ts, &mut b);
        let mut checked = 0;
        for (i, &t) in ts.iter().enumerate() {
            if per_span[&basis.find_span(t)] >= 4 {
                continue;
            }
            checked += 1;
            prop_assert!(same_bits(&a[i], &curve.point(t)), "B-spline at {:e}: {:?} vs {:?}", t, a[i], curve.point(t));
            prop_assert!(same_bits(&b[i], &nurbs.point(t)), "NURBS at {:e}: {:?} vs {:?}", t, b[i], nurbs.point(t));
        }
        // the check is not empty: most queries are sparse where the curve has many spans
        if distinct.len() > 100 * skip {
            prop_assert!(checked * 2 >= ts.len(), "most queries are sparse: {} of {}", checked, ts.len());
        }
    }
}
