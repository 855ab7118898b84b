//! B-spline basis, curves and NURBS (seed 001): the slides' worked examples, the fast
//! evaluator against Cox–de Boor, derivatives three ways, locality, continuity at multiple
//! knots, and the exact circles.

mod common;

use common::{Rng, EXACT, FD, FD_STEP};
use nalgebra::{Matrix2, Vector2, Vector3};
use num_dual::Dual3_64;
use proptest::prelude::*;
use splinelab::seeds::seed001 as data;
use splinelab::{
    de_casteljau, BSplineBasis, BSplineCurve, EndKnots, KnotVector, NurbsCurve, ParametricCurve,
};

/// `|a − b| ≤ tol · max(1, |b|)` with a message.
#[track_caller]
fn assert_near(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(1.0),
        "{what}: got {a:e}, expected {b:e}, difference {:e}, tolerance {tol:e}",
        a - b
    );
}

#[test]
fn slides_extended_partition_is_reproduced() {
    let k = KnotVector::extended_partition(
        0.0,
        1.0,
        &data::EXTENDED_INTERIOR,
        &data::EXTENDED_MULTIPLICITIES,
        data::EXTENDED_ORDER,
        EndKnots::Spaced(data::EXTENDED_SPACING),
    )
    .expect("valid example");
    assert_eq!(k.knots(), &data::EXTENDED_PRINTED_VALUES, "Δ* of seed 001");
    assert_eq!(k.multiplicity(0.75), 2, "M = {{1, 2}}");
    // the spline space has dimension m + K = 4 + 3 = 7 (seed 001)
    let basis = BSplineBasis::new(k, 3);
    assert_eq!(basis.len(), 7);
    assert_eq!(basis.domain(), (0.0, 1.0), "t_m = a, t_{{m+K+1}} = b");
}

#[test]
fn partition_of_unity_example_gives_the_printed_values() {
    // seed 001: degree 2, knots (0,0,0,1,2,2,2), t = 0.6 → 0.16, 0.66, 0.18, 0.0
    let basis = BSplineBasis::new(KnotVector::new(data::UNITY_KNOTS.to_vec()), 2);
    let printed = [0.16, 0.66, 0.18, 0.0];
    let fast = basis.all(0.6);
    for (i, &p) in printed.iter().enumerate() {
        assert_near(
            basis.cox_de_boor(i, 2, 0.6),
            p,
            EXACT,
            &format!("Cox–de Boor N{}", i + 1),
        );
        assert_near(fast[i], p, EXACT, &format!("one-pass N{}", i + 1));
    }
    assert_near(fast.iter().sum(), 1.0, EXACT, "sum");
}

#[test]
fn right_end_of_the_domain_evaluates_correctly() {
    for (degree, knots) in [
        (1, data::BASIS_N1.to_vec()),
        (2, data::BASIS_N2.to_vec()),
        (3, data::LOCALITY_KNOTS.to_vec()),
        // unclamped: the span [b, t_{n+2}) lies outside the domain
        (3, data::EXTENDED_PRINTED_VALUES.to_vec()),
    ] {
        let basis = BSplineBasis::new(KnotVector::new(knots.clone()), degree);
        let b = basis.domain().1;
        let fast = basis.all(b);
        let cox: Vec<f64> = (0..basis.len())
            .map(|i| basis.cox_de_boor(i, degree, b))
            .collect();
        assert_near(
            fast.iter().sum(),
            1.0,
            EXACT,
            &format!("Σ N(b), knots {knots:?}"),
        );
        assert_near(
            cox.iter().sum(),
            1.0,
            EXACT,
            &format!("Σ Cox–de Boor N(b), knots {knots:?}"),
        );
        for i in 0..basis.len() {
            assert_near(fast[i], cox[i], EXACT, &format!("N{i}(b), knots {knots:?}"));
            // continuity from the left
            assert_near(basis.all(b - 1e-12)[i], fast[i], 1e-9, &format!("N{i}(b⁻)"));
        }
    }
    // clamped: the last function is 1 at b, so a curve ends at its last control point
    let basis = BSplineBasis::new(KnotVector::new(data::LOCALITY_KNOTS.to_vec()), 3);
    assert_eq!(basis.all(1.0)[6], 1.0);
    // the right end is a value, not a bit pattern: b = −0.0 evaluated at t = +0.0 (and the
    // reverse) is the right end for both evaluators (found by random_input in CI)
    for (end, t) in [(-0.0, 0.0), (0.0, -0.0)] {
        let basis = BSplineBasis::new(
            KnotVector::new(vec![-1.0, -1.0, -1.0, -1.0, end, end, end, end]),
            3,
        );
        for (i, &fast) in basis.all(t).iter().enumerate() {
            let expected = if i == 3 { 1.0 } else { 0.0 };
            assert_eq!(fast, expected, "one-pass N{i}({t:?}), b = {end:?}");
            assert_eq!(
                basis.cox_de_boor(i, 3, t),
                expected,
                "Cox–de Boor N{i}({t:?}), b = {end:?}"
            );
        }
    }
}

#[test]
fn basis_derivatives_three_ways() {
    // dual numbers vs the derivative recurrence on Cox–de Boor vs central differences:
    // N′_{i,p} = p/(t_{i+p} − tᵢ) N_{i,p−1} − p/(t_{i+p+1} − t_{i+1}) N_{i+1,p−1}  (0/0 = 0)
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 0.8, 1.0, 1.0, 1.0, 1.0];
    let p = 3;
    let basis = BSplineBasis::new(KnotVector::new(knots.clone()), p);
    let mut rng = Rng::new(11);
    for _ in 0..200 {
        let t = rng.uniform(0.0, 1.0);
        let dual = basis.all(num_dual::Dual64::from_re(t).derivative());
        let (span, jet) = basis.nonzero_derivatives(t);
        for i in 0..basis.len() {
            let term = |j: usize, d: f64| {
                if d > 0.0 {
                    p as f64 / d * basis.cox_de_boor(j, p - 1, t)
                } else {
                    0.0
                }
            };
            let closed =
                term(i, knots[i + p] - knots[i]) - term(i + 1, knots[i + p + 1] - knots[i + 1]);
            assert_near(dual[i].eps, closed, EXACT, &format!("N′{i}({t})"));
            let one_pass = if (span - p..=span).contains(&i) {
                jet[i + p - span][1]
            } else {
                0.0
            };
            assert_near(
                one_pass,
                closed,
                EXACT,
                &format!("nonzero_derivatives N′{i}({t})"),
            );
            // away from knots, where N′ is continuous
            if knots.iter().all(|k| (k - t).abs() > 10.0 * FD_STEP) {
                let fd = (basis.all(t + FD_STEP)[i] - basis.all(t - FD_STEP)[i]) / (2.0 * FD_STEP);
                assert_near(
                    dual[i].eps,
                    fd,
                    FD,
                    &format!("N′{i}({t}) vs central difference"),
                );
            }
        }
    }
}

#[test]
fn curve_tangent_from_dual_numbers_matches_central_differences() {
    let curve = data::locality_curve().expect("example");
    let mut rng = Rng::new(5);
    for _ in 0..100 {
        let t = rng.uniform(0.01, 0.99);
        if data::LOCALITY_KNOTS.iter().any(|k| (k - t).abs() < 1e-3) {
            continue;
        }
        let d = curve.derivative(t);
        let fd = (curve.point(t + FD_STEP) - curve.point(t - FD_STEP)) / (2.0 * FD_STEP);
        for k in 0..2 {
            assert_near(d[k], fd[k], FD, &format!("C′({t})[{k}]"));
        }
        let [_, d1, d2] = curve.derivatives2(t);
        let fd2 = (curve.derivative(t + FD_STEP) - curve.derivative(t - FD_STEP)) / (2.0 * FD_STEP);
        assert_near(
            (d1 - d).amax(),
            0.0,
            EXACT,
            "Dual2 first derivative = Dual first derivative",
        );
        for k in 0..2 {
            assert_near(d2[k], fd2[k], FD, &format!("C″({t})[{k}]"));
        }
    }
}

#[test]
fn moving_p4_changes_the_cubic_only_on_a_quarter_to_one() {
    // seed 001: knots {0,0,0,0,¼,½,¾,1,1,1,1}; P₄ (from 0) acts on [t₄, t₈) = [¼, 1)
    let curve = data::locality_curve().expect("example");
    let moved = curve
        .with_point(data::LOCALITY_INDEX, data::locality_moved_point())
        .expect("valid point");
    for k in 0..=2500 {
        let t = k as f64 / 10_000.0; // [0, 1/4]
        assert_eq!(moved.point(t), curve.point(t), "changed at t = {t}");
    }
    for k in 1..1000 {
        let t = 0.25 + 0.75 * k as f64 / 1000.0; // (1/4, 1)
        assert!(
            (moved.point(t) - curve.point(t)).norm() > 0.0,
            "unchanged at t = {t} inside the support"
        );
    }
    // the end point P₆ is unaffected: the curve is clamped there
    assert_eq!(moved.point(1.0), curve.point(1.0));
}

/// `(C, C′, C″, C‴)` of a curve at `t`, evaluated on span `span` (its polynomial extended).
fn jet(curve: &BSplineCurve<2>, span: usize, t: f64) -> [Vector2<f64>; 4] {
    let basis = curve.basis();
    let p = basis.degree();
    let mut n = vec![Dual3_64::from_re(0.0); p + 1];
    basis.nonzero_into(span, Dual3_64::from_re(t).derivative(), &mut n);
    let sum = n
        .iter()
        .zip(&curve.points()[span - p..=span])
        .fold(Vector2::<Dual3_64>::zeros(), |acc, (w, q)| {
            acc + q.map(Dual3_64::from) * *w
        });
    [
        sum.map(|d| d.re),
        sum.map(|d| d.v1),
        sum.map(|d| d.v2),
        sum.map(|d| d.v3),
    ]
}

#[test]
fn continuity_at_a_knot_of_multiplicity_m_is_c_p_minus_m() {
    // degree 3 with interior knots of multiplicity 1, 2, 3 at 0.25, 0.5, 0.75: the slides'
    // C^{m − mⱼ − 1} with order m = 4, i.e. C², C¹, C⁰, and the next derivative jumps.
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.5, 0.75, 0.75, 0.75, 1.0, 1.0, 1.0, 1.0,
    ];
    let basis = BSplineBasis::new(KnotVector::new(knots.clone()), 3);
    let mut rng = Rng::new(3);
    let points: Vec<Vector2<f64>> = (0..basis.len())
        .map(|_| Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)))
        .collect();
    let curve = BSplineCurve::new(basis.clone(), points);
    for (knot, mult) in [(0.25, 1), (0.5, 2), (0.75, 3)] {
        let right = basis.find_span(knot);
        let left = (3..right)
            .rev()
            .find(|&s| knots[s] < knots[s + 1])
            .expect("a span on the left");
        let (l, r) = (jet(&curve, left, knot), jet(&curve, right, knot));
        let smooth = 3 - mult; // C^{p − m_j}
        for d in 0..=smooth {
            let scale = l[d].amax().max(1.0);
            assert!(
                (l[d] - r[d]).amax() <= 1e-11 * scale,
                "derivative {d} jumps at {knot} (multiplicity {mult}): {:?} vs {:?}",
                l[d],
                r[d]
            );
        }
        assert!(
            (l[smooth + 1] - r[smooth + 1]).amax() > 1e-6,
            "derivative {} should jump at {knot} (multiplicity {mult})",
            smooth + 1
        );
    }
}

#[test]
fn clamped_bspline_without_interior_knots_is_the_bezier_curve() {
    let mut rng = Rng::new(17);
    for degree in 1..=7 {
        let points: Vec<Vector3<f64>> = (0..=degree)
            .map(|_| {
                Vector3::new(
                    rng.uniform(-2.0, 2.0),
                    rng.uniform(-2.0, 2.0),
                    rng.uniform(-2.0, 2.0),
                )
            })
            .collect();
        let basis = BSplineBasis::new(
            KnotVector::open_uniform(degree, degree + 1, 0.0, 1.0).expect("knots"),
            degree,
        );
        let curve = BSplineCurve::new(basis, points.clone());
        for k in 0..=50 {
            let t = k as f64 / 50.0;
            let bez = de_casteljau(&points, t).expect("points");
            assert!(
                (curve.point(t) - bez).amax() <= EXACT,
                "degree {degree}, t = {t}: {:?} vs {bez:?}",
                curve.point(t)
            );
        }
    }
}

#[test]
fn nurbs_with_unit_weights_is_the_bspline() {
    let mut rng = Rng::new(23);
    for degree in 1..=4 {
        let count = degree + 5;
        let basis = BSplineBasis::new(
            KnotVector::open_uniform(degree, count, 0.0, 2.0).expect("knots"),
            degree,
        );
        let points: Vec<Vector2<f64>> = (0..count)
            .map(|_| Vector2::new(rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)))
            .collect();
        let nurbs = NurbsCurve::new(basis.clone(), points.clone(), vec![1.0; count]);
        let bspline = BSplineCurve::new(basis, points);
        for k in 0..=200 {
            let t = 2.0 * k as f64 / 200.0;
            assert!(
                (nurbs.point(t) - bspline.point(t)).amax() <= EXACT,
                "degree {degree}, t = {t}"
            );
            assert!(
                (nurbs.derivative(t) - bspline.derivative(t)).amax() <= 1e-12,
                "degree {degree}, t = {t}: tangents"
            );
        }
    }
}

#[test]
fn nurbs_circles_are_exact_to_machine_precision() {
    let center = Vector2::new(1.5, -0.5);
    for r in [0.1, 1.0, 7.0] {
        for circle in [
            NurbsCurve::circle7(center, r).expect("circle"),
            NurbsCurve::circle9(center, r).expect("circle"),
        ] {
            let mut worst: f64 = 0.0;
            for k in 0..=5000 {
                let t = k as f64 / 5000.0;
                worst = worst.max(((circle.point(t) - center).norm() - r).abs());
                // curvature from exact derivatives: 1/r everywhere
                let [_, d1, d2] = circle.derivatives2(t);
                let kappa = splinelab::signed_curvature(&d1, &d2);
                assert_near(kappa * r, 1.0, 1e-12, &format!("curvature · r at t = {t}"));
            }
            assert!(
                worst <= 4.0 * f64::EPSILON * r.max(1.0) * 4.0,
                "{} points, r = {r}: radius error {worst:e}",
                circle.points().len()
            );
        }
    }
}

#[test]
fn a_larger_weight_pulls_the_curve_towards_its_point() {
    let base = data::weight_example().expect("example");
    let p = base.points()[data::WEIGHT_INDEX];
    let distance = |w: f64| {
        let c = base
            .with_weight(data::WEIGHT_INDEX, w)
            .expect("positive weight");
        (0..=1000)
            .map(|k| (c.point(k as f64 / 1000.0) - p).norm())
            .fold(f64::INFINITY, f64::min)
    };
    let d: Vec<f64> = data::WEIGHTS.iter().map(|&w| distance(w)).collect();
    assert!(
        d.windows(2).all(|w| w[1] < w[0]),
        "distances {d:?} should decrease with w"
    );
}

fn arb_knots() -> impl Strategy<Value = (usize, Vec<f64>)> {
    (
        1usize..=4,
        prop::collection::vec(0.0f64..1.0, 0..8),
        prop::collection::vec(1usize..=2, 8),
    )
        .prop_map(|(p, mut interior, mult)| {
            interior.sort_by(f64::total_cmp);
            interior.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
            interior.retain(|&x| x > 1e-3 && x < 1.0 - 1e-3);
            let mut knots = vec![0.0; p + 1];
            for (x, m) in interior.iter().zip(&mult) {
                for _ in 0..(*m).min(p) {
                    knots.push(*x);
                }
            }
            knots.extend(std::iter::repeat_n(1.0, p + 1));
            (p, knots)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn one_pass_evaluator_equals_cox_de_boor((p, knots) in arb_knots(), t in 0.0f64..=1.0) {
        let basis = BSplineBasis::new(KnotVector::new(knots), p);
        let fast = basis.all(t);
        for (i, &f) in fast.iter().enumerate() {
            let c = basis.cox_de_boor(i, p, t);
            prop_assert!((f - c).abs() <= EXACT, "N{}({}) = {} vs {}", i, t, f, c);
        }
    }

    #[test]
    fn basis_is_a_nonnegative_partition_of_unity_with_local_support((p, knots) in arb_knots(), t in 0.0f64..=1.0) {
        let basis = BSplineBasis::new(KnotVector::new(knots.clone()), p);
        let n = basis.all(t);
        prop_assert!((n.iter().sum::<f64>() - 1.0).abs() <= EXACT, "sum {}", n.iter().sum::<f64>());
        for (i, &v) in n.iter().enumerate() {
            prop_assert!(v >= 0.0, "N{}({}) = {} < 0", i, t, v);
            let inside = knots[i] <= t && t <= knots[i + p + 1];
            prop_assert!(inside || v == 0.0, "N{}({}) = {} outside [{}, {}]", i, t, v, knots[i], knots[i + p + 1]);
        }
    }

    #[test]
    fn curves_are_affine_invariant(
        (p, knots) in arb_knots(),
        seed in 0u64..1000,
        t in 0.0f64..=1.0,
        a in prop::array::uniform4(-2.0f64..2.0),
        shift in prop::array::uniform2(-5.0f64..5.0),
    ) {
        let basis = BSplineBasis::new(KnotVector::new(knots), p);
        let mut rng = Rng::new(seed);
        let points: Vec<Vector2<f64>> = (0..basis.len())
            .map(|_| Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)))
            .collect();
        let m = Matrix2::new(a[0], a[1], a[2], a[3]);
        let b = Vector2::new(shift[0], shift[1]);
        let moved: Vec<Vector2<f64>> = points.iter().map(|q| m * q + b).collect();
        let c = BSplineCurve::new(basis.clone(), points);
        let d = BSplineCurve::new(basis, moved);
        let diff = (d.point(t) - (m * c.point(t) + b)).amax();
        prop_assert!(diff <= 1e-12, "affine image differs by {}", diff);
    }
}
