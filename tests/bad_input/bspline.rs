//! bspline: KnotVector, BSplineBasis, BSplineCurve; evaluation near coincident knots and at a
//! full-multiplicity breakpoint, and the batch evaluation (`eval_many`) against `point()` inside
//! and outside a very short domain

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(knot_vector_cases());
    all.extend(open_uniform_cases());
    all.extend(basis_cases());
    all.extend(curve_cases());
    all.extend(evaluation_cases());
    all
}

/// `KnotVector::try_new` and `KnotVector::extended_partition`.
fn knot_vector_cases() -> Vec<Case> {
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
    ]
}

/// `KnotVector::open_uniform`.
fn open_uniform_cases() -> Vec<Case> {
    vec![
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
    ]
}

/// `BSplineBasis`: construction, derivatives, the right end.
fn basis_cases() -> Vec<Case> {
    vec![
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
    ]
}

/// `BSplineCurve`: construction, `with_point`, `try_point`, `polyline`, batch evaluation;
/// NaN, ±inf in every input of the area.
fn curve_cases() -> Vec<Case> {
    vec![
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
    ]
}

fn short_domain_curve() -> Result<BSplineCurve<2>, String> {
    let knots = ok(KnotVector::try_new(vec![
        0.0,
        1.0,
        2.0,
        3.0,
        3.0 + 1e-9,
        4.0,
        5.0,
        6.0,
    ]))?;
    let basis = ok(BSplineBasis::try_new(knots, 3))?;
    ok(BSplineCurve::try_new(
        basis,
        vec![v2(0.0, 0.0), v2(1.0, 2.0), v2(2.0, -1.0), v2(3.0, 1.0)],
    ))
}

/// `eval_many` and `point` agree at `ts` to `rel` of the larger value (at least 1).
fn batch_agrees(c: &BSplineCurve<2>, ts: &[f64], rel: f64) -> CaseResult {
    let mut out = vec![v2(7.0, 7.0)];
    c.eval_many(ts, &mut out);
    ensure!(
        out.len() == ts.len(),
        "{} values for {}",
        out.len(),
        ts.len()
    );
    for (t, o) in ts.iter().zip(&out) {
        let p = c.point(*t);
        let scale = o.amax().max(p.amax()).max(1.0);
        ensure!(
            (o - p).amax() <= rel * scale,
            "at {t}: eval_many {o:?}, point {p:?}"
        );
    }
    Ok(())
}

/// Evaluation near coincident knots and at a full-multiplicity breakpoint; the batch
/// evaluation against `point()` inside and outside a very short domain.
fn evaluation_cases() -> Vec<Case> {
    vec![
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
        case("bspline::eval_many_outside_a_short_domain", || {
            let c = short_domain_curve()?;
            batch_agrees(&c, &[2.999], 1e-6)?;
            batch_agrees(
                &c,
                &[2.9, 2.99, 2.999, 2.999_999, 3.000_001, 3.001, 3.1],
                1e-6,
            )
        }),
        case("bspline::eval_many_inside_a_short_domain", || {
            let c = short_domain_curve()?;
            let ts: Vec<f64> = (0..=16).map(|k| 3.0 + 1e-9 * k as f64 / 16.0).collect();
            batch_agrees(&c, &ts, 1e-12)
        }),
        case("bspline::eval_many_empty_and_non_finite", || {
            let c = short_domain_curve()?;
            let mut out = vec![v2(1.0, 1.0)];
            c.eval_many(&[], &mut out);
            ensure!(out.is_empty(), "{out:?}");
            c.eval_many(&[f64::NAN, f64::INFINITY, 3.0], &mut out);
            ensure!(out.len() == 3, "{out:?}");
            ensure!(
                (out[2] - c.point(3.0)).amax() <= 1e-12,
                "{:?} vs {:?}",
                out[2],
                c.point(3.0)
            );
            Ok(())
        }),
        case("bspline::cox_de_boor_table_size", || {
            let basis = ok(BSplineBasis::try_new(
                ok(KnotVector::open_uniform(3, 300, 0.0, 1.0))?,
                3,
            ))?;
            expect_err!(basis.cox_de_boor_table(0.5), Error::TooLarge { .. })?;
            let small = ok(BSplineBasis::try_new(
                ok(KnotVector::try_new(vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]))?,
                2,
            ))?;
            for t in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                expect_err!(small.cox_de_boor_table(t), Error::NonFinite { .. })?;
            }
            // beyond the knots: a table of zeros
            for t in [-5.0, 7.0] {
                let table = ok(small.cox_de_boor_table(t))?;
                ensure!(table.iter().all(|v| *v == 0.0), "t = {t}: {table}");
            }
            Ok(())
        }),
    ]
}
