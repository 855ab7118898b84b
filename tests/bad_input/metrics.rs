//! metrics: matlab_norm, compare, ErrorAccumulator

use super::*;

pub(super) fn cases() -> Vec<Case> {
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
