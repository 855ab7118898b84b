//! nurbs: NurbsCurve (counts, weights at the ratio limit, points, evaluation), circle7, circle9

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(weight_cases());
    all.extend(point_and_evaluation_cases());
    all.extend(circle_cases());
    all
}

/// Counts and weights, at the ratio limit included.
fn weight_cases() -> Vec<Case> {
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
    ]
}

/// Points, `with_weight`, batch and single evaluation, the right end.
fn point_and_evaluation_cases() -> Vec<Case> {
    vec![
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
    ]
}

/// `NurbsCurve::circle7` and `circle9`; NaN, ±inf in every input of the area.
fn circle_cases() -> Vec<Case> {
    vec![
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
    ]
}
