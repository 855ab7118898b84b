//! study: spline_errors, uniform_spline_errors, convergence; seed 004's studies
//! (`study::table_i`: study_cell, cross_methods, pieces_changed) and the outline search's size and
//! fewest (`study::outline`)

use super::*;
use splinelab::input::Contour;
use splinelab::interp::choice::Family;
use splinelab::seeds::seed004::{polygonal_a, TABLE_I};
use splinelab::study::outline::{fewest, size, Tolerance};
use splinelab::study::table_i::{cross_methods, pieces_changed, study_cell};

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(spline_errors_cases());
    all.extend(uniform_and_convergence_cases());
    all.extend(table_i_cases());
    all.extend(outline_cases());
    all.extend(request_cases());
    all
}

/// `spline_errors`.
fn spline_errors_cases() -> Vec<Case> {
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
                Error::TooFewSamples { got: 1, what } if what.starts_with("prec")
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
                Error::TooFewSamples { got: 0, what } if what.starts_with("prec")
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
        risky("study::spline_errors_too_many_patches", || {
            let u = ok(Partition::uniform(0.0, 1.0, 20_000))?;
            expect_err!(
                spline_errors(
                    &Torus::default(),
                    u.clone(),
                    u,
                    2,
                    PatchEvaluation::HermiteMatrix
                ),
                Error::TooLarge { .. }
            )
        }),
    ]
}

/// `uniform_spline_errors` and `convergence`.
fn uniform_and_convergence_cases() -> Vec<Case> {
    vec![
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
                Error::TooFewSamples { what, .. } if what.starts_with("prec")
            )?;
            // the case of the report: `ns` is a good argument, `prec` the bad one
            expect_err!(
                convergence(&Torus::default(), &Rect::unit(), &[1, 2], 1),
                Error::TooFewSamples { what, .. } if what.starts_with("prec")
            )?;
            expect_err!(
                uniform_spline_errors(
                    &Torus::default(),
                    &Rect::unit(),
                    2,
                    2,
                    1,
                    PatchEvaluation::DeCasteljau
                ),
                Error::TooFewSamples { what, .. } if what.starts_with("prec")
            )
        }),
        case("study::convergence_empty", || {
            let r = ok(convergence(&Torus::default(), &Rect::unit(), &[], 5))?;
            ensure!(r.is_empty(), "{} rows", r.len());
            Ok(())
        }),
        risky("study::convergence_huge_patch_count", || {
            expect_err!(
                convergence(&Torus::default(), &Rect::unit(), &[1, 1 << 40], 5),
                Error::TooLarge { .. }
            )
        }),
    ]
}

/// The studies of seed 004 (`study::table_i`): `study_cell`, `cross_methods`,
/// `pieces_changed`.
fn table_i_cases() -> Vec<Case> {
    vec![
        case("study::study_cell_column_out_of_range", || {
            // a cell of no column is refused, not studied as another column
            let mut cell = TABLE_I[0];
            cell.column = 99;
            expect_err!(
                study_cell(&cell, &options(12)),
                Error::IndexOutOfRange { index: 99, .. }
            )
        }),
        risky("study::study_cell_usize_max_points", || {
            let mut cell = TABLE_I[3];
            cell.points = usize::MAX;
            expect_err!(study_cell(&cell, &options(12)), Error::TooLarge { .. })
        }),
        case("study::study_cell_bspline_order_zero", || {
            let mut cell = TABLE_I[30];
            cell.method = Method::BSpline { order: 0 };
            expect_err!(study_cell(&cell, &options(12)), Error::DegreeTooLow { .. })
        }),
        case("study::study_cell_cardinal_nan_a", || {
            let mut cell = TABLE_I[12];
            cell.method = Method::Cardinal { a: f64::NAN };
            expect_err!(study_cell(&cell, &options(12)), Error::Negative { .. })
        }),
        case("study::cross_methods_of_no_cells", || {
            let c = ok(cross_methods(&[]))?;
            ensure!(c.is_empty(), "{} rows", c.len());
            Ok(())
        }),
        case("study::pieces_changed_index_out_of_range", || {
            let p = six_points(1.0);
            for index in [6, usize::MAX] {
                expect_err!(
                    pieces_changed(&Method::Angular, &p, false, index, v2(0.1, 0.0)),
                    Error::IndexOutOfRange { len: 6, .. }
                )?;
            }
            expect_err!(
                pieces_changed(&Method::Linear, &[], true, 0, v2(0.1, 0.0)),
                Error::IndexOutOfRange { len: 0, .. }
            )
        }),
        case("study::pieces_changed_sweep_non_finite_delta", || {
            sweep(2, |bad, k| {
                let mut d = [0.1, 0.1];
                d[k] = bad;
                for m in all_methods() {
                    expect_err!(
                        pieces_changed(&m, &six_points(1.0), false, 2, v2(d[0], d[1])),
                        Error::NonFinite { .. }
                    )
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", m)))?;
                }
                Ok(())
            })
        }),
        case("study::pieces_changed_huge_delta", || {
            expect_err!(
                pieces_changed(
                    &Method::Linear,
                    &six_points(1.0),
                    false,
                    2,
                    v2(2.0 * MAX_COORDINATE, 0.0)
                ),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("study::pieces_changed_zero_and_subnormal_delta", || {
            for m in all_methods() {
                let n = ok(pieces_changed(&m, &six_points(1.0), false, 2, v2(0.0, 0.0)))?;
                ensure!(
                    n == 0,
                    "{}: {n} pieces change without a move",
                    format_args!("{:?}", m)
                );
                let n = ok(pieces_changed(
                    &m,
                    &six_points(1.0),
                    true,
                    2,
                    v2(5e-324, 0.0),
                ))?;
                ensure!(
                    n == 0,
                    "{}: {n} pieces change by 5e-324",
                    format_args!("{:?}", m)
                );
            }
            Ok(())
        }),
        case("study::pieces_changed_angular_is_local", || {
            let p: Vec<Vector2<f64>> = (0..12)
                .map(|i| v2(i as f64, ((i * i) % 5) as f64))
                .collect();
            let n = ok(pieces_changed(&Method::Angular, &p, false, 6, v2(0.0, 0.3)))?;
            ensure!((1..=4).contains(&n), "{n} pieces");
            Ok(())
        }),
        case("study::pieces_changed_tiny_points", || {
            let p = six_points(1e-300);
            let n = ok(pieces_changed(
                &Method::Angular,
                &p,
                false,
                2,
                v2(1e-301, 0.0),
            ))?;
            ensure!((1..=3).contains(&n), "{n} pieces");
            Ok(())
        }),
    ]
}

/// Each point list as a closed contour.
fn closed(contours: Vec<Vec<Vector2<f64>>>) -> Vec<Contour> {
    contours
        .into_iter()
        .map(|points| Contour {
            points,
            closed: true,
        })
        .collect()
}

/// The outline search (`study::outline`): `size` and `fewest`.
fn outline_cases() -> Vec<Case> {
    vec![
        case("study::size_degenerate", || {
            ensure!(size(&[]) == 0.0, "no contours");
            ensure!(size(&closed(vec![vec![]])) == 0.0, "an empty contour");
            let inf = size(&closed(vec![vec![v2(0.0, 0.0), v2(f64::INFINITY, 1.0)]]));
            ensure!(inf == 0.0, "infinite: {inf}");
            let max = size(&closed(vec![vec![v2(-f64::MAX, 0.0), v2(f64::MAX, 1.0)]]));
            ensure!(max.is_finite() && max >= 0.0, "±f64::MAX: {max}");
            let nan = size(&closed(vec![vec![v2(0.0, 0.0), v2(f64::NAN, 1.0)]]));
            ensure!(nan.is_finite() && nan >= 0.0, "NaN: {nan}");
            Ok(())
        }),
        case("study::size_of_the_polygonal_a", || {
            let t = Tolerance::default().of(size(&closed(polygonal_a())));
            ensure!((t - 0.01).abs() < 1e-15, "{t}");
            let tiny: Vec<Vec<Vector2<f64>>> = polygonal_a()
                .into_iter()
                .map(|c| c.into_iter().map(|p| p * 1e-310).collect())
                .collect();
            let t = size(&closed(tiny));
            ensure!(t > 0.0 && t.is_finite(), "subnormal: {t:e}");
            Ok(())
        }),
        case("study::fewest_of_no_contours", || {
            expect_err!(
                fewest(
                    &[],
                    Tolerance::Absolute(0.1),
                    &[Family::Linear],
                    &options(12),
                    &|_| {}
                ),
                Error::TooFewPoints { .. }
            )
        }),
        case("study::fewest_bad_tolerance", || {
            for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                expect_err!(
                    fewest(
                        &closed(polygonal_a()),
                        Tolerance::Absolute(tol),
                        &[Family::Linear],
                        &options(12),
                        &|_| {}
                    ),
                    Error::NotPositive { .. }
                )?;
            }
            Ok(())
        }),
        case("study::fewest_bad_contours", || {
            let mut a = polygonal_a();
            a[1][2].x = f64::NAN;
            let linear = [Family::Linear];
            expect_err!(
                fewest(
                    &closed(a),
                    Tolerance::Absolute(0.01),
                    &linear,
                    &options(12),
                    &|_| {}
                ),
                Error::NonFinite { .. }
            )?;
            expect_err!(
                fewest(
                    &closed(vec![four_points()[..2].to_vec()]),
                    Tolerance::Absolute(0.01),
                    &linear,
                    &options(12),
                    &|_| {}
                ),
                Error::TooFewPoints { .. }
            )
        }),
        case("study::fewest_polygonal_a", || {
            let s = ok(fewest(
                &closed(polygonal_a()),
                Tolerance::Absolute(0.01),
                &[Family::Linear],
                &options(20),
                &|_| {},
            ))?;
            let m = &s.methods[0];
            ensure!(m.within_tolerance() && m.error() <= 0.01, "{s:?}");
            ensure!(m.counted() == 14, "{} points", m.counted());
            Ok(())
        }),
    ]
}

/// The outline search's requests: no contour, no method, bad tolerances and budgets, stages.
fn request_cases() -> Vec<Case> {
    vec![
        case("study::fewest_requests", || {
            use splinelab::input::Contour;
            use splinelab::interp::choice::Family;
            use splinelab::study::outline::{default_options, fewest, Tolerance};
            let line = Contour {
                points: vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0)],
                closed: false,
            };
            let point = Contour {
                points: vec![Vector2::new(0.0, 0.0); 5],
                closed: true,
            };
            let nan = Contour {
                points: vec![Vector2::new(0.0, 0.0), Vector2::new(f64::NAN, 1.0)],
                closed: false,
            };
            let fams = [Family::Linear];
            for (outline, tol) in [
                (vec![], Tolerance::default()),
                (vec![point], Tolerance::default()),
                (vec![nan], Tolerance::Absolute(0.1)),
                (vec![line.clone()], Tolerance::Absolute(0.0)),
                (vec![line.clone()], Tolerance::Absolute(f64::NAN)),
                (vec![line.clone()], Tolerance::Fraction(f64::INFINITY)),
            ] {
                ensure!(
                    fewest(&outline, tol, &fams, &default_options(), &|_| {}).is_err(),
                    "{outline:?} {tol:?}"
                );
            }
            let mut huge = default_options();
            huge.max_points = usize::MAX;
            huge.random_starts = usize::MAX;
            ensure!(
                fewest(&[line], Tolerance::default(), &fams, &huge, &|_| {}).is_err(),
                "options"
            );
            for t in ["", "%", "1%%", "-5", "0%", "NaN", "1e999%", "12 cm"] {
                ensure!(t.parse::<Tolerance>().is_err(), "tolerance {t:?}");
            }
            Ok(())
        }),
        case("study::fewest_in_stages_requests", || {
            use splinelab::input::Contour;
            use splinelab::interp::choice::Family;
            use splinelab::study::outline::{default_options, fewest_in_stages, Tolerance};
            use splinelab::study::table_i::thorough_options;
            let line = Contour {
                points: vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0)],
                closed: false,
            };
            let fams = [Family::Linear];
            // no stage; a later stage refused as the first would be
            ensure!(
                fewest_in_stages(
                    std::slice::from_ref(&line),
                    Tolerance::default(),
                    &fams,
                    &[],
                    &|_| {}
                )
                .is_err(),
                "no stage"
            );
            let mut huge = default_options();
            huge.random_starts = usize::MAX;
            let stages = [default_options(), huge];
            ensure!(
                fewest_in_stages(
                    std::slice::from_ref(&line),
                    Tolerance::default(),
                    &fams,
                    &stages,
                    &|_| {}
                )
                .is_err(),
                "a bad second stage"
            );
            // a thorough stage after the default one: never more points
            let stages = [default_options(), thorough_options(&default_options())];
            let two = ok(fewest_in_stages(
                &[line],
                Tolerance::default(),
                &fams,
                &stages,
                &|_| {},
            ))?;
            ensure!(
                two.methods[0].counted() == 2,
                "{}",
                two.methods[0].counted()
            );
            Ok(())
        }),
    ]
}
