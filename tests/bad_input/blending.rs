//! blending: printed_setbval, the window curves (Lagrange, printed B-spline), the OpenGL groups
//! and polyline, SlidingBicubic; the documented results of the printed procedures

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(window_cases());
    all.extend(opengl_cases());
    all.extend(sliding_cases());
    all
}

/// `printed_setbval` and the window curves (Lagrange, the printed B-spline and its
/// polyline).
fn window_cases() -> Vec<Case> {
    vec![
        case("blending::setbval_rows_sum_to_one", || {
            let b = ok(printed_setbval(6))?;
            ensure!(b.len() == 6, "{} rows", b.len());
            for row in &b {
                let s: f64 = row.iter().sum();
                ensure!(
                    row.iter().all(|x| x.is_finite() && *x >= -1e-15) && (s - 1.0).abs() < 1e-14,
                    "row {row:?}"
                );
            }
            ensure!(ok(printed_setbval(0))?.is_empty(), "nb = 0 not empty");
            Ok(())
        }),
        risky("blending::setbval_huge", || {
            expect_err!(printed_setbval(usize::MAX), Error::TooLarge { .. })?;
            expect_err!(printed_setbval(MAX_ELEMENTS + 1), Error::TooLarge { .. })
        }),
        case("blending::lagrange_window_three_points", || {
            expect_err!(
                WindowCurve::lagrange(&some_points(3)),
                Error::TooFewPoints {
                    needed: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("blending::lagrange_window_nan", || {
            let mut pts = some_points(5);
            pts[1].x = f64::NAN;
            expect_err!(WindowCurve::lagrange(&pts), Error::NonFinite { .. })
        }),
        case("blending::lagrange_window_1e308", || {
            let mut pts = some_points(5);
            pts[4].y = 1e308;
            expect_err!(
                WindowCurve::lagrange(&pts),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case(
            "blending::lagrange_window_near_max_coordinate_finite",
            || {
                let c = ok(WindowCurve::lagrange(&alternating_points(
                    7,
                    MAX_COORDINATE,
                )))?;
                ensure!(finite_vecs(&ok(c.polyline(1201))?), "polyline not finite");
                Ok(())
            },
        ),
        case("blending::lagrange_window_right_end_is_last_point", || {
            let pts = some_points(6);
            let c = ok(WindowCurve::lagrange(&pts))?;
            let (_, b) = c.domain();
            let p = ok(c.try_point(b))?;
            ensure!(
                (p - pts[5]).amax() < 1e-13,
                "C({b}) = {p:?} vs {:?}",
                pts[5]
            );
            for (k, q) in pts.iter().enumerate() {
                ensure!((c.point(k as f64) - q).amax() < 1e-13, "misses P{k}");
            }
            expect_err!(c.try_point(b + 0.5), Error::OutOfDomain { .. })
        }),
        case("blending::printed_bspline_two_points", || {
            expect_err!(
                WindowCurve::printed_bspline(&some_points(2)),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("blending::printed_bspline_inf", || {
            let mut pts = some_points(4);
            pts[0].y = f64::NEG_INFINITY;
            expect_err!(WindowCurve::printed_bspline(&pts), Error::NonFinite { .. })
        }),
        case("blending::printed_bspline_polyline_nb_zero", || {
            expect_err!(
                printed_bspline_polyline(&some_points(4), 0),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("blending::printed_bspline_polyline_huge_nb", || {
            expect_err!(
                printed_bspline_polyline(&some_points(4), usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                printed_bspline_polyline(&some_points(4), MAX_ELEMENTS / 2),
                Error::TooLarge { .. }
            )
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
        case("blending::window_try_point_nan", || {
            let c = ok(WindowCurve::lagrange(&some_points(5)))?;
            expect_err!(c.try_point(f64::NAN), Error::NonFinite { .. })?;
            let c = ok(WindowCurve::printed_bspline(&some_points(5)))?;
            expect_err!(c.try_point(f64::INFINITY), Error::NonFinite { .. })
        }),
    ]
}

/// The OpenGL groups and polyline.
fn opengl_cases() -> Vec<Case> {
    vec![
        case("blending::opengl_order_too_low", || {
            expect_err!(
                opengl_groups(&some_points(5), 1, LastGroup::Truncated),
                Error::DegreeTooLow { min: 2, got: 1 }
            )?;
            expect_err!(
                opengl_groups(&some_points(5), 0, LastGroup::AsPrinted),
                Error::DegreeTooLow { got: 0, .. }
            )
        }),
        case("blending::opengl_too_few_points", || {
            expect_err!(
                opengl_groups(&some_points(2), 3, LastGroup::Truncated),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )?;
            expect_err!(
                opengl_groups(&some_points(4), 5, LastGroup::AsPrinted),
                Error::TooFewPoints {
                    needed: 5,
                    got: 4,
                    ..
                }
            )
        }),
        case("blending::opengl_nan_point", || {
            let mut pts = some_points(6);
            pts[5].x = f64::NAN;
            expect_err!(
                opengl_groups(&pts, 3, LastGroup::Truncated),
                Error::NonFinite { .. }
            )
        }),
        risky("blending::opengl_groups_order_2_pow_40", || {
            let g = ok(opengl_groups(
                &some_points(5),
                1 << 40,
                LastGroup::Truncated,
            ))?;
            ensure!(
                g.len() == 1 && g[0].len() == 5,
                "groups {:?}",
                g.iter().map(Vec::len).collect::<Vec<_>>()
            );
            expect_err!(
                opengl_groups(&some_points(5), 1 << 40, LastGroup::AsPrinted),
                Error::TooFewPoints { needed, .. } if *needed == 1 << 40
            )
        }),
        risky("blending::opengl_groups_order_usize_max", || {
            let g = ok(opengl_groups(
                &some_points(5),
                usize::MAX,
                LastGroup::Truncated,
            ))?;
            ensure!(
                g.len() == 1 && g[0].len() == 5,
                "groups {:?}",
                g.iter().map(Vec::len).collect::<Vec<_>>()
            );
            Ok(())
        }),
        case("blending::opengl_polyline_nseg_zero", || {
            expect_err!(
                opengl_polyline(&some_points(5), 3, 0, LastGroup::Truncated),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("blending::opengl_polyline_huge_nseg", || {
            expect_err!(
                opengl_polyline(&some_points(5), 3, usize::MAX, LastGroup::Truncated),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                opengl_polyline(&some_points(5), 3, MAX_ELEMENTS, LastGroup::AsPrinted),
                Error::TooLarge { .. }
            )
        }),
        risky("blending::opengl_polyline_order_2_pow_40", || {
            let p = ok(opengl_polyline(
                &some_points(5),
                1 << 40,
                10,
                LastGroup::Truncated,
            ))?;
            ensure!(p.len() == 11 && finite_vecs(&p), "{} points", p.len());
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
    ]
}

/// `SlidingBicubic`; NaN, ±inf in every input of the area.
fn sliding_cases() -> Vec<Case> {
    vec![
        case("blending::sliding_too_small_grid", || {
            expect_err!(
                SlidingBicubic::try_new(&sliding_grid(3, 5, 1.0), Blending::Lagrange),
                Error::TooFewPoints {
                    needed: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("blending::sliding_nan_point", || {
            let mut g = sliding_grid(5, 5, 1.0);
            g.as_mut_slice()[12].z = f64::NAN;
            expect_err!(
                SlidingBicubic::try_new(&g, Blending::UniformBSpline),
                Error::NonFinite { .. }
            )
        }),
        case("blending::sliding_point_1e308", || {
            expect_err!(
                SlidingBicubic::try_new(&sliding_grid(4, 4, 1e308), Blending::Lagrange),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("blending::sliding_bad_cell", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(5, 6, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(s.tabulate_cell((2, 0), 5), Error::IndexOutOfRange { .. })?;
            expect_err!(s.tabulate_cell((0, 3), 5), Error::IndexOutOfRange { .. })
        }),
        case("blending::sliding_bad_cell_usize_max", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(5, 6, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(
                s.tabulate_cell((usize::MAX, usize::MAX), 5),
                Error::IndexOutOfRange { .. }
            )?;
            expect_err!(
                s.tabulate_cell((usize::MAX, 0), 5),
                Error::IndexOutOfRange { .. }
            )
        }),
        case("blending::sliding_too_few_samples", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(4, 4, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(
                s.tabulate_cell((0, 0), 1),
                Error::TooFewSamples { got: 1, .. }
            )
        }),
        risky("blending::sliding_huge_samples", || {
            let s = ok(SlidingBicubic::try_new(
                &sliding_grid(4, 4, 1.0),
                Blending::Lagrange,
            ))?;
            expect_err!(s.tabulate_cell((0, 0), 1 << 20), Error::TooLarge { .. })?;
            expect_err!(s.tabulate_cell((0, 0), usize::MAX), Error::TooLarge { .. })
        }),
        case("blending::sliding_near_max_coordinate_finite", || {
            for b in [Blending::Lagrange, Blending::UniformBSpline] {
                let s = ok(SlidingBicubic::try_new(
                    &sliding_grid(6, 6, MAX_COORDINATE),
                    b,
                ))?;
                for i in 0..3 {
                    for j in 0..3 {
                        ensure!(
                            finite_grid(&ok(s.tabulate_cell((i, j), 9))?),
                            "{}: cell ({i}, {j})",
                            format_args!("{:?}", b)
                        );
                    }
                }
            }
            Ok(())
        }),
        case("blending::sweep_non_finite_points", || {
            sweep(6, |bad, k| {
                let mut pts = some_points(6);
                pts[k][k % 2] = bad;
                expect_err!(WindowCurve::lagrange(&pts), Error::NonFinite { .. })?;
                expect_err!(WindowCurve::printed_bspline(&pts), Error::NonFinite { .. })?;
                expect_err!(printed_bspline_polyline(&pts, 6), Error::NonFinite { .. })?;
                expect_err!(
                    opengl_groups(&pts, 3, LastGroup::AsPrinted),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    opengl_polyline(&pts, 4, 8, LastGroup::Truncated),
                    Error::NonFinite { .. }
                )?;
                let mut g = sliding_grid(4, 6, 1.0);
                g.as_mut_slice()[k * 4][k % 3] = bad;
                expect_err!(
                    SlidingBicubic::try_new(&g, Blending::UniformBSpline),
                    Error::NonFinite { .. }
                )
            })
        }),
    ]
}
