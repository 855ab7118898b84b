//! metrics: the surface metrics (`matlab_norm`, `compare`, `ErrorAccumulator`) and the curve
//! metrics (`segment_distance`, `SegmentTree`, `polyline_distances`, `distances_to`,
//! `sample_pieces`, `curvature_profile`, `smoothness`)

use super::*;
use splinelab::metrics::curve::{
    curvature_profile, distances_to, polyline_distances, sample_pieces, sample_pieces_into,
    segment_distance, smoothness, SegmentTree,
};
use std::f64::consts::{PI, TAU};

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(matlab_norm_and_compare_cases());
    all.extend(accumulator_cases());
    all.extend(segment_distance_cases());
    all.extend(segment_tree_cases());
    all.extend(polyline_distance_cases());
    all.extend(sampling_and_smoothness_cases());
    all
}

/// `matlab_norm` and `compare`; NaN, ±inf in every entry.
fn matlab_norm_and_compare_cases() -> Vec<Case> {
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
        case("metrics::matlab_norm_subnormal_entries", || {
            let m = DMatrix::from_element(3, 3, 5e-324);
            let n = ok(matlab_norm(&m))?;
            ensure!(n.is_finite() && n > 0.0, "norm {n}");
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
    ]
}

/// `ErrorAccumulator`.
fn accumulator_cases() -> Vec<Case> {
    vec![
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
    ]
}

/// The distance from `p` to the segment `ab` computed independently of the library: the
/// origin moved to `a` (the differences of nearby or tiny coordinates are exact), then scaled
/// by powers of two so the larger difference is about 1, where no square under- or overflows.
fn reference_distance(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let (w, u) = (p - a, b - a);
    let m = w.amax().max(u.amax());
    if m == 0.0 {
        return 0.0;
    }
    let e = -(m.log2().floor() as i32);
    let (k1, k2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
    let (w, u) = (w * k1 * k2, u * k1 * k2);
    let len2 = u.norm_squared();
    let t = if len2 > 0.0 {
        (w.dot(&u) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (w - u * t).norm() / k1 / k2
}

/// The one-sided distance `max_{a ∈ from} min_{segments of to}` by brute force with
/// [`reference_distance`] (`to` of one point: its distance).
fn reference_one_sided(from: &[Vector2<f64>], to: &[Vector2<f64>]) -> f64 {
    from.iter()
        .map(|&p| {
            if to.len() == 1 {
                return reference_distance(p, to[0], to[0]);
            }
            to.windows(2)
                .map(|w| reference_distance(p, w[0], w[1]))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}

/// Two parallel segments `dist` apart, at `offset` and of length `len`: the curve and its
/// reference for the distance cases.
fn parallel_pair(
    offset: Vector2<f64>,
    len: f64,
    dist: f64,
) -> (Vec<Vector2<f64>>, Vec<Vector2<f64>>) {
    let u = v2(0.6, 0.8) * len;
    let n = v2(-0.8, 0.6) * dist;
    let curve = vec![offset, offset + u * 0.5, offset + u];
    let reference = vec![offset + n, offset + u + n];
    (curve, reference)
}

/// `segment_distance`.
fn segment_distance_cases() -> Vec<Case> {
    vec![
        case("metrics::segment_distance_below_1e-154", || {
            for s in [1e-155, 1e-170, 1e-200, 1e-300] {
                let (p, a, b) = (v2(2.0 * s, 3.0 * s), v2(0.0, 0.0), v2(4.0 * s, 0.0));
                close(
                    &format!("scale {s:e}"),
                    segment_distance(p, a, b),
                    reference_distance(p, a, b),
                    1e-14,
                )?;
            }
            Ok(())
        }),
        case("metrics::segment_distance_subnormal", || {
            let (p, a, b) = (v2(5e-311, 3e-311), v2(0.0, 0.0), v2(1e-310, 0.0));
            close(
                "subnormal",
                segment_distance(p, a, b),
                reference_distance(p, a, b),
                1e-9,
            )
        }),
        case("metrics::segment_distance_to_a_point_below_1e-154", || {
            let (p, a) = (v2(3e-170, 4e-170), v2(0.0, 0.0));
            close("point", segment_distance(p, a, a), 5e-170, 1e-14)
        }),
        case("metrics::segment_distance_near_1e7", || {
            // a distance of 1e-6 from a segment of length 5 at 1.2e7: the foot of the
            // perpendicular must not be rounded at the coordinates' ulp (2e-9)
            let a = v2(12_345_678.0, 23_456_789.0);
            let u = v2(3.0, 4.0);
            let n = v2(-0.8, 0.6);
            let b = a + u;
            for (f, d) in [(0.37, 1e-6), (0.5, 1e-7), (0.91, 3e-6)] {
                let p = a + u * f + n * d;
                close(
                    &format!("t = {f}, distance {d:e}"),
                    segment_distance(p, a, b),
                    reference_distance(p, a, b),
                    1e-9,
                )?;
            }
            Ok(())
        }),
        case("metrics::segment_distance_at_coordinate_limits", || {
            for m in [MAX_COORDINATE, f64::MAX / 2.0, f64::MAX] {
                let d = segment_distance(v2(0.0, m), v2(-m, 0.0), v2(m, 0.0));
                ensure!(
                    d.is_finite() && (d - m).abs() <= 1e-15 * m,
                    "{m:e}: distance {d:e}"
                );
            }
            Ok(())
        }),
    ]
}

/// `SegmentTree`: construction, `distance`, `farthest`, `farthest_below`.
fn segment_tree_cases() -> Vec<Case> {
    vec![
        case("metrics::segment_tree_empty", || {
            expect_err!(SegmentTree::new(&[]), Error::TooFewPoints { got: 0, .. })?;
            expect_err!(SegmentTree::along(&[]), Error::TooFewPoints { got: 0, .. })
        }),
        case("metrics::segment_tree_along_non_finite_and_far", || {
            sweep(6, |bad, k| {
                let mut p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 1.0)];
                p[k / 2][k % 2] = bad;
                expect_err!(SegmentTree::along(&p), Error::NonFinite { .. })
            })?;
            expect_err!(
                SegmentTree::along(&[v2(0.0, 0.0), v2(f64::MAX, 1.0)]),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("metrics::farthest_below_limits", || {
            // any limit, NaN included: the exact distance below it, at least it otherwise
            let t = ok(SegmentTree::along(&[v2(0.0, 0.0), v2(1.0, 0.0)]))?;
            let from = [v2(0.5, 3.0), v2(0.5, 1.0), v2(2.0, 0.0)];
            for limit in [f64::NAN, -1.0, 0.0, 0.5, 2.9, 3.0, 10.0, f64::INFINITY] {
                let (m, _) = t.farthest_below(&from, limit);
                if limit > 3.0 {
                    ensure!(m == 3.0, "limit {limit}: {m}");
                } else if limit <= 3.0 {
                    ensure!(m >= limit && m <= 3.0, "limit {limit}: {m}");
                }
            }
            Ok(())
        }),
        case("metrics::segment_tree_sweep_non_finite", || {
            sweep(6, |bad, k| {
                let mut p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 1.0)];
                p[k / 2][k % 2] = bad;
                expect_err!(SegmentTree::new(&p), Error::NonFinite { .. })
            })
        }),
        case("metrics::segment_tree_beyond_coordinate_limit", || {
            for bad in [2.0 * MAX_COORDINATE, f64::MAX, -f64::MAX] {
                expect_err!(
                    SegmentTree::new(&[v2(0.0, 0.0), v2(bad, 1.0)]),
                    Error::CoordinateTooLarge { .. }
                )?;
            }
            Ok(())
        }),
        risky("metrics::segment_tree_too_many_points", || {
            expect_err!(
                SegmentTree::new(&vec![v2(0.0, 0.0); MAX_ELEMENTS + 1]),
                Error::TooLarge { .. }
            )
        }),
        case("metrics::segment_tree_single_point", || {
            let t = ok(SegmentTree::new(&[v2(1.0, 1.0)]))?;
            let d = t.distance(v2(4.0, 5.0));
            ensure!(d == 5.0, "{d}");
            let (m, at) = t.farthest(&[v2(1.0, 1.0), v2(1.0, 3.0)]);
            ensure!(m == 2.0 && at == Some(1), "{m} at {at:?}");
            Ok(())
        }),
        case("metrics::segment_tree_distance_below_1e-154", || {
            for s in [1e-160, 1e-200, 1e-300] {
                let pts: Vec<Vector2<f64>> = (0..40)
                    .map(|i| v2(i as f64 * s, (i as f64 * 0.3).sin() * s))
                    .collect();
                let t = ok(SegmentTree::new(&pts))?;
                let q = v2(7.3 * s, 2.0 * s);
                close(
                    &format!("scale {s:e}"),
                    t.distance(q),
                    reference_one_sided(&[q], &pts),
                    1e-12,
                )?;
            }
            Ok(())
        }),
        case("metrics::segment_tree_distance_near_1e7", || {
            let (curve, reference) = parallel_pair(v2(1.1e7, -2.3e7), 10.0, 1e-6);
            let t = ok(SegmentTree::new(&reference))?;
            for p in &curve {
                close(
                    "vertex",
                    t.distance(*p),
                    reference_one_sided(&[*p], &reference),
                    1e-9,
                )?;
            }
            Ok(())
        }),
        case("metrics::segment_tree_at_coordinate_limit", || {
            let m = MAX_COORDINATE;
            let pts = vec![v2(-m, -m), v2(m, -m), v2(m, m), v2(-m, m), v2(-m, -m)];
            let t = ok(SegmentTree::new(&pts))?;
            let d = t.distance(v2(0.0, 0.0));
            ensure!((d - m).abs() <= 1e-15 * m, "{d:e}");
            let (f, at) = t.farthest(&[v2(0.0, 0.0), v2(m, m)]);
            ensure!(
                (f - m).abs() <= 1e-15 * m && at == Some(0),
                "{f:e} at {at:?}"
            );
            Ok(())
        }),
        case("metrics::farthest_of_no_points", || {
            let t = ok(SegmentTree::new(&four_points()))?;
            let (m, at) = t.farthest(&[]);
            ensure!(m == 0.0 && at.is_none(), "{m} at {at:?}");
            Ok(())
        }),
        case("metrics::farthest_matches_brute_force", || {
            let pts: Vec<Vector2<f64>> = (0..500)
                .map(|i| {
                    let t = i as f64 * 0.0125;
                    v2(t.cos() * (1.0 + 0.3 * (7.0 * t).sin()), t.sin())
                })
                .collect();
            let from: Vec<Vector2<f64>> = (0..300)
                .map(|i| v2((i as f64 * 0.37).sin() * 1.5, (i as f64 * 0.71).cos() * 1.5))
                .collect();
            let t = ok(SegmentTree::new(&pts))?;
            let (m, at) = t.farthest(&from);
            let brute = reference_one_sided(&from, &pts);
            ensure!(
                (m - brute).abs() <= 1e-14 * brute && at.is_some(),
                "{m} vs {brute}"
            );
            Ok(())
        }),
    ]
}

/// `polyline_distances` and `distances_to`.
fn polyline_distance_cases() -> Vec<Case> {
    vec![
        case("metrics::polyline_distances_empty", || {
            let p = four_points();
            expect_err!(polyline_distances(&[], &p), Error::TooFewPoints { .. })?;
            expect_err!(polyline_distances(&p, &[]), Error::TooFewPoints { .. })
        }),
        case("metrics::polyline_distances_sweep_non_finite", || {
            sweep(8, |bad, k| {
                let mut a = four_points();
                let b = six_points(1.0);
                a[k / 2][k % 2] = bad;
                expect_err!(polyline_distances(&a, &b), Error::NonFinite { .. })?;
                expect_err!(polyline_distances(&b, &a), Error::NonFinite { .. })
            })
        }),
        case(
            "metrics::polyline_distances_beyond_coordinate_limit",
            || {
                let mut a = four_points();
                a[2].y = -2.0 * MAX_COORDINATE;
                expect_err!(
                    polyline_distances(&a, &four_points()),
                    Error::CoordinateTooLarge { .. }
                )
            },
        ),
        case(
            "metrics::polyline_distances_identical_and_symmetric",
            || {
                let (a, b) = (six_points(1.0), four_points());
                let d = ok(polyline_distances(&a, &a))?;
                ensure!(d.hausdorff() == 0.0, "{d:?}");
                let (ab, ba) = (
                    ok(polyline_distances(&a, &b))?,
                    ok(polyline_distances(&b, &a))?,
                );
                ensure!(
                    ab.curve_to_reference == ba.reference_to_curve
                        && ab.reference_to_curve == ba.curve_to_reference,
                    "{ab:?} vs {ba:?}"
                );
                Ok(())
            },
        ),
        case("metrics::polyline_distances_below_1e-154", || {
            for s in [1e-160, 1e-200, 1e-300, 1e-310] {
                let (c, r) = parallel_pair(v2(0.0, 0.0), s, 0.01 * s);
                let d = ok(polyline_distances(&c, &r))?;
                let want = reference_one_sided(&c, &r).max(reference_one_sided(&r, &c));
                close(&format!("scale {s:e}"), d.hausdorff(), want, 1e-9)?;
            }
            Ok(())
        }),
        case("metrics::polyline_distances_near_1e7", || {
            for offset in [v2(1e7, 1e7), v2(-3.3e7, 9.9e6), v2(2.0e8, 0.0)] {
                let (c, r) = parallel_pair(offset, 5.0, 1e-6);
                let d = ok(polyline_distances(&c, &r))?;
                let want = reference_one_sided(&c, &r).max(reference_one_sided(&r, &c));
                close(&format!("offset {offset:?}"), d.hausdorff(), want, 1e-9)?;
            }
            Ok(())
        }),
        case("metrics::polyline_distances_huge_offsets", || {
            // far apart near the coordinate limit: finite
            let m = MAX_COORDINATE;
            let d = ok(polyline_distances(&[v2(-m, -m)], &[v2(m, m)]))?;
            ensure!(d.hausdorff().is_finite(), "{d:?}");
            Ok(())
        }),
        case("metrics::distances_to_non_finite_curve", || {
            let t = ok(SegmentTree::new(&four_points()))?;
            expect_err!(
                distances_to(&[v2(0.0, f64::NAN)], &t),
                Error::NonFinite { .. }
            )?;
            expect_err!(distances_to(&[], &t), Error::TooFewPoints { .. })
        }),
    ]
}

/// `sample_pieces`, `curvature_profile` and `smoothness`.
fn sampling_and_smoothness_cases() -> Vec<Case> {
    vec![
        case("metrics::sample_pieces_too_few_breaks", || {
            for breaks in [&[][..], &[0.0][..]] {
                expect_err!(
                    sample_pieces(&Shape::Circle, breaks, 8),
                    Error::TooFewPoints { .. }
                )?;
                expect_err!(
                    curvature_profile(&Shape::Circle, breaks, 8),
                    Error::TooFewPoints { .. }
                )?;
            }
            Ok(())
        }),
        case("metrics::sample_pieces_too_few_per_piece", || {
            for n in [0, 1] {
                expect_err!(
                    sample_pieces(&Shape::Circle, &[0.0, TAU], n),
                    Error::TooFewSamples { .. }
                )?;
                expect_err!(
                    curvature_profile(&Shape::Circle, &[0.0, TAU], n),
                    Error::TooFewSamples { .. }
                )?;
            }
            Ok(())
        }),
        risky("metrics::sample_pieces_usize_max", || {
            expect_err!(
                sample_pieces(&Shape::Circle, &[0.0, TAU], usize::MAX),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics::sample_pieces_product_overflows", || {
            let breaks = linspace(0.0, TAU, 1000);
            expect_err!(
                sample_pieces(&Shape::Circle, &breaks, usize::MAX / 500),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                sample_pieces(&Shape::Circle, &breaks, 1 << 40),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics::sample_pieces_max_elements_plus_one", || {
            expect_err!(
                sample_pieces(&Shape::Circle, &[0.0, TAU], MAX_ELEMENTS + 1),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics::curvature_profile_huge_counts", || {
            expect_err!(
                curvature_profile(&Shape::Circle, &[0.0, TAU], usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                curvature_profile(&Shape::Circle, &linspace(0.0, TAU, 5), 1 << 40),
                Error::TooLarge { .. }
            )
        }),
        case("metrics::sample_pieces_non_finite_breaks", || {
            for bad in NON_FINITE {
                expect_err!(
                    sample_pieces(&Shape::Parabola { half_width: 1.0 }, &[0.0, bad, 1.0], 4),
                    Error::NonFinite { .. } | Error::Overflow { .. }
                )?;
            }
            Ok(())
        }),
        case("metrics::sample_pieces_overflowing_curve", || {
            // y = x² at x = 1e200 overflows
            expect_err!(
                sample_pieces(&Shape::Parabola { half_width: 1.0 }, &[0.0, 1e200], 4),
                Error::Overflow { .. }
            )
        }),
        case("metrics::sample_pieces_into_clears_its_buffer", || {
            let mut out = vec![v2(9.0, 9.0); 3];
            expect_err!(
                sample_pieces_into(&Shape::Circle, &[0.0], 4, &mut out),
                Error::TooFewPoints { .. }
            )?;
            ensure!(out.is_empty(), "{out:?}");
            ok(sample_pieces_into(
                &Shape::Circle,
                &[0.0, PI, TAU],
                3,
                &mut out,
            ))?;
            ensure!(out.len() == 5 && finite_vecs(&out), "{out:?}");
            Ok(())
        }),
        case("metrics::sample_pieces_subnormal_breaks", || {
            let s = ok(sample_pieces(&Shape::Circle, &[0.0, 5e-324, 1e-310], 4))?;
            ensure!(s.len() == 7 && finite_vecs(&s), "{s:?}");
            Ok(())
        }),
        case("metrics::curvature_profile_of_the_circle", || {
            let p = ok(curvature_profile(&Shape::Circle, &[0.0, PI, TAU], 9))?;
            ensure!(p.len() == 2 && p.iter().all(|v| v.len() == 9), "shape");
            for &(t, k) in p.iter().flatten() {
                ensure!((k - 1.0).abs() <= 1e-12, "κ({t}) = {k}");
            }
            Ok(())
        }),
        case("metrics::smoothness_of_nothing", || {
            let s = smoothness(&[], 1.0);
            ensure!(
                s.inflections == 0
                    && s.max_jump == 0.0
                    && s.max_curvature == 0.0
                    && s.singular == 0,
                "{s:?}"
            );
            let s = smoothness(&[vec![], vec![]], 1.0);
            ensure!(s.singular == 0 && s.max_jump == 0.0, "{s:?}");
            Ok(())
        }),
        case("metrics::smoothness_counts_non_finite_as_singular", || {
            let profile = vec![
                vec![(0.0, 1.0), (0.5, f64::NAN), (1.0, 2.0)],
                vec![(1.0, f64::INFINITY), (1.5, -1.0), (2.0, f64::NEG_INFINITY)],
            ];
            let s = smoothness(&profile, 1.0);
            ensure!(s.singular == 3, "{s:?}");
            ensure!(
                s.max_curvature == 2.0 && s.max_jump.is_finite() && s.inflections == 1,
                "{s:?}"
            );
            Ok(())
        }),
        case("metrics::smoothness_extreme_lengths", || {
            let profile = ok(curvature_profile(&Shape::Circle, &[0.0, PI, TAU], 9))?;
            let s = smoothness(&profile, f64::NAN);
            ensure!(
                s.singular == 18 && s.max_curvature == 0.0,
                "NaN length {s:?}"
            );
            let s = smoothness(&profile, f64::MAX);
            ensure!(
                s.max_curvature.is_finite() && s.max_jump.is_finite(),
                "f64::MAX length {s:?}"
            );
            let s = smoothness(&profile, 5e-324);
            ensure!(
                s.inflections == 0 && s.singular == 0 && s.max_curvature <= 1e-300,
                "subnormal length {s:?}"
            );
            Ok(())
        }),
    ]
}
