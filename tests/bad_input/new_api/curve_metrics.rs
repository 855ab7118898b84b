//! metrics2: segment_distance, SegmentTree, distances, sampling, curvature, smoothness

use super::*;

pub(super) fn cases() -> Vec<Case> {
    vec![
        case("metrics2::segment_distance_below_1e-154", || {
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
        case("metrics2::segment_distance_subnormal", || {
            let (p, a, b) = (v2(5e-311, 3e-311), v2(0.0, 0.0), v2(1e-310, 0.0));
            close(
                "subnormal",
                segment_distance(p, a, b),
                reference_distance(p, a, b),
                1e-9,
            )
        }),
        case("metrics2::segment_distance_to_a_point_below_1e-154", || {
            let (p, a) = (v2(3e-170, 4e-170), v2(0.0, 0.0));
            close("point", segment_distance(p, a, a), 5e-170, 1e-14)
        }),
        case("metrics2::segment_distance_near_1e7", || {
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
        case("metrics2::segment_distance_at_coordinate_limits", || {
            for m in [MAX_COORDINATE, f64::MAX / 2.0, f64::MAX] {
                let d = segment_distance(v2(0.0, m), v2(-m, 0.0), v2(m, 0.0));
                ensure!(
                    d.is_finite() && (d - m).abs() <= 1e-15 * m,
                    "{m:e}: distance {d:e}"
                );
            }
            Ok(())
        }),
        case("metrics2::segment_tree_empty", || {
            expect_err!(SegmentTree::new(&[]), Error::TooFewPoints { got: 0, .. })?;
            expect_err!(SegmentTree::along(&[]), Error::TooFewPoints { got: 0, .. })
        }),
        case("metrics2::segment_tree_along_non_finite_and_far", || {
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
        case("metrics2::farthest_below_limits", || {
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
        case("metrics2::segment_tree_sweep_non_finite", || {
            sweep(6, |bad, k| {
                let mut p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 1.0)];
                p[k / 2][k % 2] = bad;
                expect_err!(SegmentTree::new(&p), Error::NonFinite { .. })
            })
        }),
        case("metrics2::segment_tree_beyond_coordinate_limit", || {
            for bad in [2.0 * MAX_COORDINATE, f64::MAX, -f64::MAX] {
                expect_err!(
                    SegmentTree::new(&[v2(0.0, 0.0), v2(bad, 1.0)]),
                    Error::CoordinateTooLarge { .. }
                )?;
            }
            Ok(())
        }),
        risky("metrics2::segment_tree_too_many_points", || {
            expect_err!(
                SegmentTree::new(&vec![v2(0.0, 0.0); MAX_ELEMENTS + 1]),
                Error::TooLarge { .. }
            )
        }),
        case("metrics2::segment_tree_single_point", || {
            let t = ok(SegmentTree::new(&[v2(1.0, 1.0)]))?;
            let d = t.distance(v2(4.0, 5.0));
            ensure!(d == 5.0, "{d}");
            let (m, at) = t.farthest(&[v2(1.0, 1.0), v2(1.0, 3.0)]);
            ensure!(m == 2.0 && at == Some(1), "{m} at {at:?}");
            Ok(())
        }),
        case("metrics2::segment_tree_distance_below_1e-154", || {
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
        case("metrics2::segment_tree_distance_near_1e7", || {
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
        case("metrics2::segment_tree_at_coordinate_limit", || {
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
        case("metrics2::farthest_of_no_points", || {
            let t = ok(SegmentTree::new(&four_points()))?;
            let (m, at) = t.farthest(&[]);
            ensure!(m == 0.0 && at.is_none(), "{m} at {at:?}");
            Ok(())
        }),
        case("metrics2::farthest_matches_brute_force", || {
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
        case("metrics2::polyline_distances_empty", || {
            let p = four_points();
            expect_err!(polyline_distances(&[], &p), Error::TooFewPoints { .. })?;
            expect_err!(polyline_distances(&p, &[]), Error::TooFewPoints { .. })
        }),
        case("metrics2::polyline_distances_sweep_non_finite", || {
            sweep(8, |bad, k| {
                let mut a = four_points();
                let b = six_points(1.0);
                a[k / 2][k % 2] = bad;
                expect_err!(polyline_distances(&a, &b), Error::NonFinite { .. })?;
                expect_err!(polyline_distances(&b, &a), Error::NonFinite { .. })
            })
        }),
        case(
            "metrics2::polyline_distances_beyond_coordinate_limit",
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
            "metrics2::polyline_distances_identical_and_symmetric",
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
        case("metrics2::polyline_distances_below_1e-154", || {
            for s in [1e-160, 1e-200, 1e-300, 1e-310] {
                let (c, r) = parallel_pair(v2(0.0, 0.0), s, 0.01 * s);
                let d = ok(polyline_distances(&c, &r))?;
                let want = reference_one_sided(&c, &r).max(reference_one_sided(&r, &c));
                close(&format!("scale {s:e}"), d.hausdorff(), want, 1e-9)?;
            }
            Ok(())
        }),
        case("metrics2::polyline_distances_near_1e7", || {
            for offset in [v2(1e7, 1e7), v2(-3.3e7, 9.9e6), v2(2.0e8, 0.0)] {
                let (c, r) = parallel_pair(offset, 5.0, 1e-6);
                let d = ok(polyline_distances(&c, &r))?;
                let want = reference_one_sided(&c, &r).max(reference_one_sided(&r, &c));
                close(&format!("offset {offset:?}"), d.hausdorff(), want, 1e-9)?;
            }
            Ok(())
        }),
        case("metrics2::polyline_distances_huge_offsets", || {
            // far apart near the coordinate limit: finite
            let m = MAX_COORDINATE;
            let d = ok(polyline_distances(&[v2(-m, -m)], &[v2(m, m)]))?;
            ensure!(d.hausdorff().is_finite(), "{d:?}");
            Ok(())
        }),
        case("metrics2::distances_to_non_finite_curve", || {
            let t = ok(SegmentTree::new(&four_points()))?;
            expect_err!(
                distances_to(&[v2(0.0, f64::NAN)], &t),
                Error::NonFinite { .. }
            )?;
            expect_err!(distances_to(&[], &t), Error::TooFewPoints { .. })
        }),
        case("metrics2::sample_pieces_too_few_breaks", || {
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
        case("metrics2::sample_pieces_too_few_per_piece", || {
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
        risky("metrics2::sample_pieces_usize_max", || {
            expect_err!(
                sample_pieces(&Shape::Circle, &[0.0, TAU], usize::MAX),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics2::sample_pieces_product_overflows", || {
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
        risky("metrics2::sample_pieces_max_elements_plus_one", || {
            expect_err!(
                sample_pieces(&Shape::Circle, &[0.0, TAU], MAX_ELEMENTS + 1),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics2::curvature_profile_huge_counts", || {
            expect_err!(
                curvature_profile(&Shape::Circle, &[0.0, TAU], usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                curvature_profile(&Shape::Circle, &linspace(0.0, TAU, 5), 1 << 40),
                Error::TooLarge { .. }
            )
        }),
        case("metrics2::sample_pieces_non_finite_breaks", || {
            for bad in NON_FINITE {
                expect_err!(
                    sample_pieces(&Shape::Parabola { half_width: 1.0 }, &[0.0, bad, 1.0], 4),
                    Error::NonFinite { .. } | Error::Overflow { .. }
                )?;
            }
            Ok(())
        }),
        case("metrics2::sample_pieces_overflowing_curve", || {
            // y = x² at x = 1e200 overflows
            expect_err!(
                sample_pieces(&Shape::Parabola { half_width: 1.0 }, &[0.0, 1e200], 4),
                Error::Overflow { .. }
            )
        }),
        case("metrics2::sample_pieces_into_clears_its_buffer", || {
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
        case("metrics2::sample_pieces_subnormal_breaks", || {
            let s = ok(sample_pieces(&Shape::Circle, &[0.0, 5e-324, 1e-310], 4))?;
            ensure!(s.len() == 7 && finite_vecs(&s), "{s:?}");
            Ok(())
        }),
        case("metrics2::curvature_profile_of_the_circle", || {
            let p = ok(curvature_profile(&Shape::Circle, &[0.0, PI, TAU], 9))?;
            ensure!(p.len() == 2 && p.iter().all(|v| v.len() == 9), "shape");
            for &(t, k) in p.iter().flatten() {
                ensure!((k - 1.0).abs() <= 1e-12, "κ({t}) = {k}");
            }
            Ok(())
        }),
        case("metrics2::smoothness_of_nothing", || {
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
        case("metrics2::smoothness_counts_non_finite_as_singular", || {
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
        case("metrics2::smoothness_extreme_lengths", || {
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
