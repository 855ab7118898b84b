//! More combinations: batch evaluation in any order, the threaded partials path, documented
//! results of the printed procedures, weights at the ratio limit, overflowing widths

use super::*;

/// Parameters in no particular order, inside and slightly outside `[a, b]`, ends included.
fn scrambled(a: f64, b: f64) -> Vec<f64> {
    let mut ts: Vec<f64> = (0..97)
        .map(|k| a + (b - a) * ((k * 37) % 97) as f64 / 96.0)
        .collect();
    ts.extend([
        b,
        a,
        b,
        0.5 * (a + b),
        a - 0.01 * (b - a),
        b + 0.01 * (b - a),
        b,
    ]);
    ts
}

pub(super) fn cases() -> Vec<Case> {
    vec![
        case("bspline::eval_many_any_order_equals_point", || {
            let c = ok(BSplineCurve::try_new(basis(3, 9)?, some_points(9)))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (t, q) in ts.iter().zip(&out) {
                let p = c.point(*t);
                ensure!(finite_vecs(&[p, *q]), "t = {t}");
                ensure!(
                    (p - q).amax() <= 1e-12,
                    "t = {t}: point {p:?} vs batch {q:?}"
                );
            }
            Ok(())
        }),
        case("nurbs::eval_many_any_order_equals_point", || {
            let c = ok(NurbsCurve::circle7(v2(1.0, -2.0), 3.0))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (t, q) in ts.iter().zip(&out) {
                let p = c.point(*t);
                ensure!(finite_vecs(&[p, *q]), "t = {t}");
                ensure!(
                    (p - q).amax() <= 1e-12,
                    "t = {t}: point {p:?} vs batch {q:?}"
                );
            }
            Ok(())
        }),
        case("interp::cubic_eval_many_any_order_equals_point", || {
            let x = [0.0, 0.1, 0.5, 0.55, 1.0];
            let y = [1.0, -1.0, 2.0, 0.0, 1.0];
            let s = ok(CubicSpline::function(&x, &y, EndCondition::Periodic))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            s.values_into(&ts, &mut out);
            let mut many = Vec::new();
            s.eval_many(&ts, &mut many);
            for ((t, q), m) in ts.iter().zip(&out).zip(&many) {
                let p = s.value(*t);
                ensure!(p.is_finite() && q.is_finite(), "t = {t}");
                ensure!(
                    (p - q).abs() <= 1e-12 && (p - m.x).abs() <= 1e-12,
                    "t = {t}: {p} vs {q} / {}",
                    m.x
                );
            }
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
            "surface::partials_on_grid_threaded_first_nan_in_row_major",
            || {
                // 200 × 100 nodes take the multi-threaded path; NaN at (s₁₅₀, t₃₀) and later
                let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                    let bad = if s.re >= 150.0 && t.re >= 30.0 {
                        f64::NAN
                    } else {
                        1.0
                    };
                    Vector3::new(s * bad, t, s * t)
                });
                let s_nodes: Vec<f64> = (0..200).map(f64::from).collect();
                let t_nodes: Vec<f64> = (0..100).map(f64::from).collect();
                expect_err!(
                    partials_on_grid(&spot, &s_nodes, &t_nodes),
                    Error::NonFiniteSurface { s, t } if *s == 150.0 && *t == 30.0
                )
            },
        ),
        case("surface::partials_on_grid_threaded_finite", || {
            let s_nodes = linspace(0.0, 6.0, 200);
            let t_nodes = linspace(0.0, 6.0, 100);
            let g = ok(partials_on_grid(&Torus::default(), &s_nodes, &t_nodes))?;
            ensure!(
                g.rows() == 200 && g.cols() == 100,
                "shape {}×{}",
                g.rows(),
                g.cols()
            );
            let p = g.get(123, 45);
            let q = Torus::default().partials(s_nodes[123], t_nodes[45]);
            ensure!(*p == q, "threaded {p:?} vs direct {q:?}");
            Ok(())
        }),
        case("surface::exp_surface_overflows_on_large_rect", || {
            let rect = ok(Rect::try_new(0.0, 1000.0, 0.0, 1000.0))?;
            expect_err!(
                tabulate(&ExpSurface, &rect, 3, 3),
                Error::NonFiniteSurface { .. }
            )?;
            expect_err!(
                HermiteSurface::uniform(&ExpSurface, &rect, 2, 2),
                Error::NonFiniteSurface { .. } | Error::CoordinateTooLarge { .. }
            )
        }),
        case("surface::sphere_near_limit_tabulates_finitely", || {
            let sphere = ok(Sphere::try_new(MAX_COORDINATE))?;
            let g = ok(tabulate(
                &sphere,
                &ok(Rect::try_new(0.0, 6.3, -1.6, 1.6))?,
                9,
                9,
            ))?;
            ensure!(finite_grid(&g), "not finite");
            Ok(())
        }),
        case("interp::lagrange_nodes_width_overflows", || {
            expect_err!(
                Lagrange::try_new(&[-1e308, 0.0, 1e308], &[1.0, 2.0, 3.0]),
                Error::Overflow { .. }
            )
        }),
        case("interp::linear_abscissae_width_overflows", || {
            expect_err!(
                PiecewiseLinear::try_new(&[-1e308, 1e308], &[v1(0.0), v1(1.0)]),
                Error::Overflow { .. }
            )
        }),
        case("interp::cubic_abscissae_width_overflows", || {
            expect_err!(
                CubicSpline::function(
                    &[-1e308, 0.0, 1e308],
                    &[0.0, 1.0, 0.0],
                    EndCondition::Natural
                ),
                Error::Overflow { .. }
            )
        }),
        case("interp::power_offset_nodes_refused_or_interpolates", || {
            let x: Vec<f64> = (0..12).map(|k| 1e6 + k as f64).collect();
            let y: Vec<f64> = x.iter().map(|v| (v - 1e6).sqrt()).collect();
            match PowerPolynomial::interpolate(&x, &y) {
                Err(
                    Error::IllConditioned { .. }
                    | Error::SingularSystem { .. }
                    | Error::Overflow { .. },
                ) => Ok(()),
                Err(e) => Err(format!("unexpected error {e:?}")),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        case(
            "interp::cubic_clamped_huge_slopes_refused_or_interpolates",
            || {
                // end slopes of 1e306 on unit data: the moments are representable
                let x = [0.0, 1.0, 2.0];
                let y = [0.0, 1.0, 0.0];
                match CubicSpline::function(&x, &y, EndCondition::clamped(1e306, -1e306)) {
                    Err(Error::Overflow { .. } | Error::IllConditioned { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(s) => check_interpolates(&x, &y, |t| s.value(t)),
                }
            },
        ),
        case("interp::collocation_cubic_matches_tridiagonal", || {
            let x = [0.0, 0.3, 0.35, 0.8, 1.0];
            let y = [0.0, 1.0, -1.0, 0.5, 0.0];
            let yv: Vec<Vector1<f64>> = y.iter().map(|v| v1(*v)).collect();
            for end in [
                EndCondition::Natural,
                EndCondition::Anticyclic,
                EndCondition::Periodic,
                EndCondition::clamped(1.0, -1.0),
            ] {
                let a = ok(CubicSpline::function(&x, &y, end))?;
                let b = ok(collocation::cubic_spline(&x, &yv, end))?;
                for t in linspace(0.0, 1.0, 101) {
                    let (u, v) = (a.value(t), b.point(t).x);
                    ensure!(
                        (u - v).abs() < 1e-9,
                        "{}: t = {t}: {u} vs {v}",
                        format_args!("{:?}", end)
                    );
                }
            }
            Ok(())
        }),
        case("blending::opengl_as_printed_nine_points_documented", || {
            let pts = some_points(9);
            let g = ok(opengl_groups(&pts, 5, LastGroup::AsPrinted))?;
            ensure!(g.len() == 3, "{} groups", g.len());
            ensure!(g[0] == pts[0..5] && g[1] == pts[4..9], "first groups {g:?}");
            let third = vec![pts[8], pts[5], pts[6], pts[7], pts[8]];
            ensure!(
                g[2] == third,
                "third group {:?}, printed P8, P5, P6, P7, P8",
                g[2]
            );
            let t = ok(opengl_groups(&pts, 5, LastGroup::Truncated))?;
            ensure!(
                t.len() == 2,
                "truncated: {} groups (a 1-point group is dropped)",
                t.len()
            );
            Ok(())
        }),
        case("blending::printed_bspline_ends_documented", || {
            let pts = some_points(6);
            let c = ok(WindowCurve::printed_bspline(&pts))?;
            let (a, b) = c.domain();
            ensure!(
                (ok(c.try_point(a))? - pts[0]).amax() < 1e-14,
                "does not start at P0"
            );
            ensure!(
                (ok(c.try_point(b))? - pts[5]).amax() < 1e-14,
                "does not end at the last point"
            );
            let poly = ok(printed_bspline_polyline(&pts, 6))?;
            ensure!(poly.len() == 1 + 7 * 6, "{} vertices", poly.len());
            ensure!(
                finite_vecs(&poly) && poly[0] == pts[0],
                "polyline start {:?}",
                poly[0]
            );
            Ok(())
        }),
        case("metrics::matlab_norm_subnormal_entries", || {
            let m = DMatrix::from_element(3, 3, 5e-324);
            let n = ok(matlab_norm(&m))?;
            ensure!(n.is_finite() && n > 0.0, "norm {n}");
            Ok(())
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
        case("blending::window_try_point_nan", || {
            let c = ok(WindowCurve::lagrange(&some_points(5)))?;
            expect_err!(c.try_point(f64::NAN), Error::NonFinite { .. })?;
            let c = ok(WindowCurve::printed_bspline(&some_points(5)))?;
            expect_err!(c.try_point(f64::INFINITY), Error::NonFinite { .. })
        }),
        case("domain::rect_subnormal_side", || {
            expect_err!(
                Rect::try_new(0.0, 1.0, 0.0, 1e-310),
                Error::GapTooSmall { .. }
            )
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
        risky("study::convergence_huge_patch_count", || {
            expect_err!(
                convergence(&Torus::default(), &Rect::unit(), &[1, 1 << 40], 5),
                Error::TooLarge { .. }
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
        risky("grid::from_fn_shorthand_panics_without_allocating", || {
            let r = catch_unwind(|| Grid::from_fn(usize::MAX, 2, |_, _| 0u8).rows());
            ensure!(r.is_err(), "Grid::from_fn(usize::MAX, 2) did not panic");
            Ok(())
        }),
    ]
}
