//! study: spline_errors, uniform_spline_errors, convergence

use super::*;

pub(super) fn cases() -> Vec<Case> {
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
