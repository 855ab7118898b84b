//! hermite: hermite_basis, HermitePatch, HermiteSurface

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(basis_and_matrix_cases());
    all.extend(patch_cases());
    all.extend(spline_construction_cases());
    all.extend(spline_evaluation_cases());
    all
}

/// `hermite_basis` and `HermitePatch::try_from_matrix`; NaN, ±inf in every datum of a
/// patch.
fn basis_and_matrix_cases() -> Vec<Case> {
    vec![
        case("hermite::basis_documented_values", || {
            ensure!(
                hermite_basis(0.5_f64) == [0.5, 0.125, -0.125, 0.5],
                "H(0.5) = {:?}",
                hermite_basis(0.5_f64)
            );
            for k in 0..=20 {
                let t = k as f64 / 20.0;
                let h = hermite_basis(t);
                ensure!(h.iter().all(|x| x.is_finite()), "H({t}) not finite");
                ensure!(
                    (h[0] + h[3] - 1.0).abs() <= 4.0 * f64::EPSILON,
                    "H0 + H3 ≠ 1 at {t}"
                );
            }
            Ok(())
        }),
        case("hermite::patch_matrix_nan", || {
            let mut c = unit_net();
            c[1][2].y = f64::NAN;
            expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { value, .. } if value.is_nan())
        }),
        case("hermite::patch_matrix_inf", || {
            let mut c = unit_net();
            c[3][3].z = f64::INFINITY;
            expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { .. })
        }),
        case("hermite::patch_matrix_neg_inf", || {
            let mut c = unit_net();
            c[0][0].x = f64::NEG_INFINITY;
            expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { .. })
        }),
        case("hermite::patch_matrix_f64_max", || {
            let mut c = unit_net();
            c[2][1].x = f64::MAX;
            expect_err!(
                HermitePatch::try_from_matrix(c),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case(
            "hermite::patch_matrix_at_hermite_limit_tabulates_finitely",
            || {
                let p = ok(HermitePatch::try_from_matrix(alternating_net(
                    HERMITE_LIMIT,
                )))?;
                let g = ok(p.tabulate(21, 21))?;
                ensure!(finite_grid(&g), "tabulation of a valid matrix not finite");
                let x = p.eval(0.37_f64, 0.81_f64);
                ensure!(finite_vecs(&[x]), "eval not finite: {x:?}");
                Ok(())
            },
        ),
        case("hermite::sweep_non_finite_data", || {
            sweep(16 * 3, |bad, k| {
                let mut c = unit_net();
                c[k / 12][(k / 3) % 4][k % 3] = bad;
                expect_err!(HermitePatch::try_from_matrix(c), Error::NonFinite { .. })?;
                let mut corners = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
                let p = &mut corners[k % 2][(k / 2) % 2];
                match (k / 4) % 4 {
                    0 => p.point[k % 3] = bad,
                    1 => p.ds[k % 3] = bad,
                    2 => p.dt[k % 3] = bad,
                    _ => p.dst[k % 3] = bad,
                }
                expect_err!(
                    HermitePatch::try_from_corners(&corners, 1.0, 1.0),
                    Error::NonFinite { .. }
                )
            })
        }),
    ]
}

/// `HermitePatch::try_from_corners`, `from_surface` and `tabulate`.
fn patch_cases() -> Vec<Case> {
    vec![
        case("hermite::corners_zero_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(HermitePatch::try_from_corners(&c, 0.0, 1.0), Error::NotPositive { value, .. } if *value == 0.0)
        }),
        case("hermite::corners_negative_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, -0.5),
                Error::NotPositive { .. }
            )
        }),
        case("hermite::corners_nan_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, f64::NAN, 1.0),
                Error::NotPositive { .. }
            )
        }),
        case("hermite::corners_inf_width", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, f64::INFINITY),
                Error::NotPositive { .. }
            )
        }),
        case("hermite::corners_nan_datum", || {
            let mut c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            c[1][0].dt.y = f64::NAN;
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, 1.0),
                Error::NonFinite { .. }
            )
        }),
        case("hermite::corners_inf_datum", || {
            let mut c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            c[0][1].point.x = f64::INFINITY;
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, 1.0),
                Error::NonFinite { .. }
            )
        }),
        case("hermite::corners_datum_beyond_max_coordinate", || {
            let mut c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            c[1][1].point.z = 1e307;
            expect_err!(
                HermitePatch::try_from_corners(&c, 1.0, 1.0),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("hermite::corners_scaled_beyond_max_coordinate", || {
            // X_s = 1e300 times Δu = 1e7: 1e307 > MAX_COORDINATE, finite
            let c = [[partials(1.0, 1e300, 1.0, 0.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1e7, 1.0),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("hermite::corners_scaled_overflows_to_inf", || {
            // X_s = 1e300 times Δu = 1e10 = inf: derived from finite data
            let c = [[partials(1.0, 1e300, 1.0, 0.0); 2]; 2];
            expect_err!(
                HermitePatch::try_from_corners(&c, 1e10, 1.0),
                Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
            )
        }),
        case(
            "hermite::corners_width_product_overflows_zero_twist",
            || {
                // Δu Δv = 1e400 overflows; the twist is 0, so the true entry is 0
                let c = [[partials(1.0, 0.0, 0.0, 0.0); 2]; 2];
                match HermitePatch::try_from_corners(&c, 1e200, 1e200) {
                    Ok(p) => {
                        let m = p.matrix();
                        ensure!(
                            m.iter().flatten().all(|v| v.iter().all(|x| x.is_finite())),
                            "Ok matrix with a non-finite entry: {m:?}"
                        );
                        ensure!(
                            m[1][1] == Vector3::zeros(),
                            "twist entry {:?}, expected 0",
                            m[1][1]
                        );
                        Ok(())
                    }
                    Err(Error::Overflow { .. } | Error::CoordinateTooLarge { .. }) => Ok(()),
                    Err(e) => Err(format!("misleading error for finite data: {e:?} «{e}»")),
                }
            },
        ),
        case(
            "hermite::corners_width_product_overflows_unit_twist",
            || {
                let c = [[partials(1.0, 0.0, 0.0, 1.0); 2]; 2];
                expect_err!(
                    HermitePatch::try_from_corners(&c, 1e200, 1e200),
                    Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
                )
            },
        ),
        case("hermite::patch_from_surface_nan", || {
            let nan =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, (s - 1.0).ln()));
            // ln(0) at s = 1 is −inf; ln of a negative number at s = 0 is NaN
            expect_err!(
                HermitePatch::try_from_surface(&nan, &Rect::unit()),
                Error::NonFiniteSurface { .. }
            )
        }),
        case("hermite::patch_from_surface_1e308_times_s", || {
            let big =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s * 1e308, t, t));
            expect_err!(
                HermitePatch::try_from_surface(&big, &Rect::unit()),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("hermite::patch_from_surface_huge_rect", || {
            // widths 1e300: X_s Δu fits, X_st Δu Δv does not
            let rect = ok(Rect::try_new(0.0, 1e300, 0.0, 1e300))?;
            expect_err!(
                HermitePatch::try_from_surface(&Torus::default(), &rect),
                Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
            )
        }),
        case("hermite::patch_tabulate_too_few", || {
            let p = ok(HermitePatch::try_from_matrix(unit_net()))?;
            expect_err!(p.tabulate(1, 5), Error::TooFewSamples { got: 1, .. })?;
            expect_err!(p.tabulate(0, 0), Error::TooFewSamples { got: 0, .. })
        }),
        risky("hermite::patch_tabulate_100000_squared", || {
            let p = ok(HermitePatch::try_from_matrix(unit_net()))?;
            expect_err!(p.tabulate(100_000, 100_000), Error::TooLarge { .. })
        }),
        risky("hermite::patch_tabulate_usize_max", || {
            let p = ok(HermitePatch::try_from_matrix(unit_net()))?;
            expect_err!(p.tabulate(usize::MAX, usize::MAX), Error::TooLarge { .. })?;
            expect_err!(p.tabulate(usize::MAX, 2), Error::TooLarge { .. })
        }),
    ]
}

/// `HermiteSurface`: construction.
fn spline_construction_cases() -> Vec<Case> {
    vec![
        case("hermite::spline_from_surface_nan_node", || {
            let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                let bad = if s.re > 0.4 && s.re < 0.6 {
                    f64::NAN
                } else {
                    1.0
                };
                Vector3::new(s * bad, t, s * t)
            });
            let u = ok(Partition::try_new(vec![0.0, 0.5, 1.0]))?;
            let v = ok(Partition::try_new(vec![0.0, 1.0]))?;
            expect_err!(
                HermiteSurface::try_from_surface(&spot, u, v),
                Error::NonFiniteSurface { s, t } if *s == 0.5 && *t == 0.0
            )
        }),
        case("hermite::spline_node_partials_shape_mismatch", || {
            let nodes =
                Grid::from_vec(2, 2, vec![partials(0.0, 1.0, 1.0, 0.0); 4]).ok_or("grid")?;
            let u = ok(Partition::try_new(vec![0.0, 0.5, 1.0]))?;
            let v = ok(Partition::try_new(vec![0.0, 1.0]))?;
            expect_err!(
                HermiteSurface::try_from_node_partials(&nodes, u, v),
                Error::ShapeMismatch {
                    left_rows: 2,
                    left_cols: 2,
                    right_rows: 3,
                    right_cols: 2
                }
            )
        }),
        case("hermite::spline_node_partials_nan", || {
            let mut data = vec![partials(0.0, 1.0, 1.0, 0.0); 9];
            data[4].dst.x = f64::NAN;
            let nodes = Grid::from_vec(3, 3, data).ok_or("grid")?;
            let u = ok(Partition::uniform(0.0, 1.0, 2))?;
            let v = ok(Partition::uniform(0.0, 1.0, 2))?;
            expect_err!(
                HermiteSurface::try_from_node_partials(&nodes, u, v),
                Error::NonFinite { .. }
            )
        }),
        case(
            "hermite::spline_node_partials_at_max_coordinate_tabulate_finitely",
            || {
                let data: Vec<Partials> = (0..9)
                    .map(|k| {
                        let s = if k % 2 == 0 {
                            MAX_COORDINATE
                        } else {
                            -MAX_COORDINATE
                        };
                        partials(s, -s, s, -s)
                    })
                    .collect();
                let nodes = Grid::from_vec(3, 3, data).ok_or("grid")?;
                let u = ok(Partition::try_new(vec![0.0, 0.25, 1.0]))?;
                let v = ok(Partition::try_new(vec![0.0, 0.75, 1.0]))?;
                let sp = ok(HermiteSurface::try_from_node_partials(&nodes, u, v))?;
                let xs = linspace(0.0, 1.0, 41);
                let g = ok(sp.tabulate(&xs, &xs))?;
                ensure!(finite_grid(&g), "tabulation of a valid spline not finite");
                Ok(())
            },
        ),
        case("hermite::spline_uniform_zero_patches", || {
            expect_err!(
                HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 0, 3),
                Error::ZeroPatches { .. }
            )
        }),
        risky("hermite::spline_uniform_1e6_squared_patches", || {
            expect_err!(
                HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 1_000_000, 1_000_000),
                Error::TooLarge { .. }
            )
        }),
        risky("hermite::spline_uniform_usize_max_patches", || {
            expect_err!(
                HermiteSurface::uniform(&Torus::default(), &Rect::unit(), usize::MAX, 1),
                Error::TooLarge { .. }
            )
        }),
    ]
}

/// `HermiteSurface`: evaluation and tabulation; NaN, ±inf in its parameters.
fn spline_evaluation_cases() -> Vec<Case> {
    vec![
        case("hermite::spline_try_point_nan", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            expect_err!(sp.try_point(f64::NAN, 0.5), Error::NonFinite { .. })?;
            expect_err!(sp.try_point(0.5, f64::INFINITY), Error::NonFinite { .. })
        }),
        case("hermite::spline_try_point_out_of_domain", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            expect_err!(sp.try_point(1.0 + 1e-12, 0.5), Error::OutOfDomain { value, .. } if *value == 1.0 + 1e-12)?;
            expect_err!(sp.try_point(0.5, -0.1), Error::OutOfDomain { .. })
        }),
        case("hermite::spline_right_end_is_left_limit", || {
            let torus = Torus::default();
            let sp = ok(HermiteSurface::uniform(&torus, &Rect::unit(), 2, 2))?;
            let p = ok(sp.try_point(1.0, 1.0))?;
            let last = sp.patch(1, 1).eval(1.0_f64, 1.0_f64);
            ensure!(p == last, "right end {p:?} vs last patch {last:?}");
            let exact = torus.point(1.0, 1.0);
            ensure!(
                (p - exact).amax() < 1e-13,
                "corner not interpolated: {p:?} vs {exact:?}"
            );
            Ok(())
        }),
        case("hermite::spline_tabulate_bad_samples", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            expect_err!(
                sp.tabulate(&[0.0, f64::NAN], &[0.5]),
                Error::NonFinite { .. }
            )?;
            expect_err!(sp.tabulate(&[0.5], &[0.0, 2.0]), Error::OutOfDomain { value, .. } if *value == 2.0)
        }),
        risky("hermite::spline_tabulate_too_many_samples", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            let xs = vec![0.5; 1 << 14];
            expect_err!(sp.tabulate(&xs, &xs), Error::TooLarge { .. })
        }),
        case(
            "hermite::spline_torus_near_max_coordinate_evaluates_finitely",
            || {
                let torus = ok(Torus::try_new(1.3e306, 1.3e306))?;
                let sp = ok(HermiteSurface::uniform(&torus, &Rect::unit(), 2, 2))?;
                let xs = linspace(0.0, 1.0, 21);
                let g = ok(sp.tabulate(&xs, &xs))?;
                ensure!(finite_grid(&g), "tabulation not finite");
                Ok(())
            },
        ),
        case("hermite::sweep_non_finite_spline_parameters", || {
            let sp = ok(HermiteSurface::uniform(
                &Torus::default(),
                &Rect::unit(),
                2,
                2,
            ))?;
            sweep(2, |bad, k| {
                let uv = put(vec![0.5, 0.5], k, bad);
                expect_err!(sp.try_point(uv[0], uv[1]), Error::NonFinite { .. })?;
                expect_err!(
                    sp.tabulate(&[0.0, uv[0]], &[uv[1], 1.0]),
                    Error::NonFinite { .. }
                )
            })
        }),
    ]
}
