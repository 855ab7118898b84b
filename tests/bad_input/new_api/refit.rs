//! refit: CubicSpline::refit, refit_function

use super::*;

/// The natural spline function through 4 points, to be refitted.
fn natural4() -> Result<CubicSpline<1>, String> {
    ok(CubicSpline::function(
        &[0.0, 1.0, 2.0, 3.0],
        &[0.0, 1.0, 0.0, 1.0],
        EndCondition::Natural,
    ))
}

/// A spline function reproduces its data exactly and is finite on its domain.
fn check_function(s: &CubicSpline<1>, x: &[f64], y: &[f64]) -> CaseResult {
    for (xi, yi) in x.iter().zip(y) {
        ensure!(
            s.value(*xi) == *yi,
            "s({xi:e}) = {:e}, not {yi:e}",
            s.value(*xi)
        );
    }
    let (a, b) = (x[0], x[x.len() - 1]);
    for k in 0..=64 {
        let t = a + (b - a) * (k as f64 / 64.0);
        let t = if t.is_finite() { t } else { 0.5 * a + 0.5 * b };
        ensure!(s.value(t).is_finite(), "s({t:e}) = {}", s.value(t));
    }
    Ok(())
}

pub(super) fn cases() -> Vec<Case> {
    vec![
        case("refit::sweep_non_finite_abscissa", || {
            sweep(4, |bad, k| {
                let x = put(vec![0.0, 1.0, 2.0, 3.0], k, bad);
                expect_err!(
                    natural4()?.refit_function(&x, &[0.0, 1.0, 0.0, 1.0]),
                    Error::NonFinite { .. }
                )
            })
        }),
        case("refit::sweep_non_finite_value_2d", || {
            sweep(8, |bad, k| {
                let s = ok(CubicSpline::try_new(
                    &[0.0, 1.0, 2.0, 3.0],
                    &four_points(),
                    EndCondition::Natural,
                ))?;
                let mut p = four_points();
                p[k / 2][k % 2] = bad;
                expect_err!(s.refit(&[0.0, 1.0, 2.0, 3.0], &p), Error::NonFinite { .. })
            })
        }),
        case("refit::gap_below_min_positive", || {
            for gap in [5e-324, 1e-310] {
                expect_err!(
                    natural4()?.refit_function(&[0.0, gap, 1.0], &[0.0, 1.0, 0.0]),
                    Error::GapTooSmall { .. }
                )?;
            }
            Ok(())
        }),
        case("refit::decreasing_and_repeated", || {
            expect_err!(
                natural4()?.refit_function(&[0.0, 2.0, 1.0], &[0.0; 3]),
                Error::NotIncreasing { index: 2, .. }
            )?;
            expect_err!(
                natural4()?.refit_function(&[0.0, -0.0, 1.0], &[0.0; 3]),
                Error::RepeatedParameter { index: 1, .. }
            )
        }),
        case("refit::abscissae_width_overflows", || {
            expect_err!(
                natural4()?.refit_function(&[-f64::MAX, 0.0, f64::MAX], &[0.0, 1.0, 0.0]),
                Error::Overflow { .. }
            )
        }),
        case("refit::huge_abscissae", || {
            let x = [-1e307, -1e306, 1e306, 8e307];
            let y = [0.0, 1.0, -1.0, 2.0];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("refit::values_beyond_coordinate_limit", || {
            for v in [2.0 * MAX_COORDINATE, -f64::MAX] {
                expect_err!(
                    natural4()?.refit_function(&[0.0, 1.0, 2.0], &[0.0, v, 0.0]),
                    Error::CoordinateTooLarge { .. }
                )?;
            }
            Ok(())
        }),
        case("refit::values_near_coordinate_limit", || {
            let m = MAX_COORDINATE;
            let x = [0.0, 1e-3, 2e-3, 1.0];
            let y = [m, -m, m, -m];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("refit::tiny_and_subnormal_values", || {
            for v in [1e-300, 5e-324] {
                let x = [0.0, 1.0, 2.0, 3.0];
                let y = [v, -v, 2.0 * v, 0.0];
                let s = ok(natural4()?.refit_function(&x, &y))?;
                check_function(&s, &x, &y)?;
            }
            Ok(())
        }),
        case("refit::tiny_abscissae", || {
            let x = [1e-300, 2e-300, 3e-300, 5e-300];
            let y = [0.0, 1.0, 0.0, 1.0];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("refit::periodic_mismatch_and_too_few", || {
            let p = ok(CubicSpline::function(
                &[0.0, 1.0, 2.0],
                &[0.0, 1.0, 0.0],
                EndCondition::Periodic,
            ))?;
            expect_err!(
                p.clone().refit_function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.5]),
                Error::PeriodicEndsMismatch { .. }
            )?;
            expect_err!(
                p.refit_function(&[0.0, 1.0], &[0.0, 0.0]),
                Error::TooFewPoints { needed: 3, .. }
            )
        }),
        case("refit::clamped_ends_non_finite", || {
            for bad in NON_FINITE {
                for end in [
                    EndCondition::clamped(bad, 0.0),
                    EndCondition::clamped(0.0, bad),
                ] {
                    expect_err!(
                        CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.0], end),
                        Error::NonFinite { .. }
                    )?;
                }
            }
            Ok(())
        }),
        case("refit::clamped_ends_huge", || {
            let x = [0.0, 1.0, 2.0];
            let y = [0.0, 1.0, 0.0];
            for d in [1e300, MAX_COORDINATE] {
                match CubicSpline::function(&x, &y, EndCondition::clamped(d, -d)) {
                    Ok(s) => check_function(&s, &x, &y)?,
                    Err(Error::Overflow { .. }) => {}
                    Err(e) => return Err(format!("{d:e}: unexpected {e}")),
                }
            }
            expect_err!(
                CubicSpline::function(&x, &y, EndCondition::clamped(f64::MAX, 0.0)),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("refit::larger_then_smaller_data", || {
            let x: Vec<f64> = (0..2000).map(|i| i as f64 * 0.01).collect();
            let y: Vec<f64> = x.iter().map(|t| t.sin()).collect();
            let s = ok(natural4()?.refit_function(&x, &y))?;
            check_function(&s, &x, &y)?;
            let s = ok(s.refit_function(&[0.0, 1.0], &[3.0, 4.0]))?;
            ensure!(s.nodes() == [0.0, 1.0], "{:?}", s.nodes());
            check_function(&s, &[0.0, 1.0], &[3.0, 4.0])
        }),
        case("refit::every_end_condition", || {
            let x = [0.0, 0.5, 1.5, 3.0, 3.25];
            let y = [1.0, -1.0, 2.0, 0.5, 1.0];
            for end in [
                EndCondition::Natural,
                EndCondition::Periodic,
                EndCondition::Cyclic,
                EndCondition::Anticyclic,
                EndCondition::clamped(1.0, -1.0),
            ] {
                let s = ok(CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[1.0, 0.0, 1.0],
                    end,
                ))?;
                let s = ok(s.refit_function(&x, &y))
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
                check_function(&s, &x, &y)
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
            }
            Ok(())
        }),
        case("refit::curve_2d_count_mismatch", || {
            let s = ok(CubicSpline::try_new(
                &[0.0, 1.0, 2.0, 3.0],
                &four_points(),
                EndCondition::Natural,
            ))?;
            expect_err!(
                s.refit(&[0.0, 1.0, 2.0], &four_points()),
                Error::CountMismatch {
                    expected: 3,
                    got: 4,
                    ..
                }
            )
        }),
        risky("refit::too_many_points", || {
            let x: Vec<f64> = (0..=MAX_ELEMENTS).map(|i| i as f64).collect();
            let y = vec![0.0; MAX_ELEMENTS + 1];
            expect_err!(natural4()?.refit_function(&x, &y), Error::TooLarge { .. })
        }),
    ]
}
