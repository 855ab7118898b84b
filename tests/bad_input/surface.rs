//! surface: Torus, Sphere, FnSurface, tabulate, partials_on_grid(_into) and its threaded path

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(torus_and_sphere_cases());
    all.extend(tabulate_cases());
    all.extend(partials_on_grid_cases());
    all
}

/// `Torus` and `Sphere`.
fn torus_and_sphere_cases() -> Vec<Case> {
    vec![
        case(
            "surface::torus_zero_major",
            || expect_err!(Torus::try_new(0.0, 1.0), Error::NotPositive { value, .. } if *value == 0.0),
        ),
        case(
            "surface::torus_negative_minor",
            || expect_err!(Torus::try_new(2.0, -1.0), Error::NotPositive { value, .. } if *value == -1.0),
        ),
        case("surface::torus_nan_major", || {
            expect_err!(Torus::try_new(f64::NAN, 1.0), Error::NotPositive { .. })
        }),
        case("surface::torus_inf_major", || {
            expect_err!(
                Torus::try_new(f64::INFINITY, 1.0),
                Error::NotPositive { .. }
            )
        }),
        case("surface::torus_neg_inf_minor", || {
            expect_err!(
                Torus::try_new(2.0, f64::NEG_INFINITY),
                Error::NotPositive { .. }
            )
        }),
        case("surface::torus_radii_1e308_sum_overflows", || {
            // R + r = inf from finite radii: a derived quantity, not a non-finite input
            expect_err!(
                Torus::try_new(1e308, 1e308),
                Error::CoordinateTooLarge { .. } | Error::Overflow { .. }
            )
        }),
        case("surface::torus_radii_beyond_max_coordinate", || {
            expect_err!(
                Torus::try_new(2e306, 1e306),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("surface::torus_near_limit_partials_finite", || {
            let t = ok(Torus::try_new(1.3e306, 1.3e306))?;
            for (s, u) in [(0.0, 0.0), (0.3, 2.1), (1.0, 1.0), (6.0, 3.0)] {
                let p = t.partials(s, u);
                ensure!(
                    finite_vecs(&[p.point, p.ds, p.dt, p.dst]),
                    "partials at ({s}, {u}) not finite: {p:?}"
                );
            }
            Ok(())
        }),
        case("surface::sphere_zero_radius", || {
            expect_err!(Sphere::try_new(0.0), Error::NotPositive { .. })
        }),
        case("surface::sphere_nan_radius", || {
            expect_err!(Sphere::try_new(f64::NAN), Error::NotPositive { .. })
        }),
        case("surface::sphere_neg_inf_radius", || {
            expect_err!(
                Sphere::try_new(f64::NEG_INFINITY),
                Error::NotPositive { .. }
            )
        }),
        case("surface::sphere_radius_1e308", || {
            expect_err!(Sphere::try_new(1e308), Error::CoordinateTooLarge { .. })
        }),
        case("surface::sweep_non_finite_radii", || {
            sweep(2, |bad, k| {
                let r = put(vec![2.0, 1.0], k, bad);
                expect_err!(Torus::try_new(r[0], r[1]), Error::NotPositive { .. })?;
                expect_err!(Sphere::try_new(bad), Error::NotPositive { .. })
            })
        }),
    ]
}

/// `tabulate`.
fn tabulate_cases() -> Vec<Case> {
    vec![
        case("surface::tabulate_one_sample", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 1, 5),
                Error::TooFewSamples { got: 1, what } if *what == "ns"
            )
        }),
        case("surface::tabulate_zero_samples", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 5, 0),
                Error::TooFewSamples { got: 0, what } if *what == "nt"
            )
        }),
        risky("surface::tabulate_100000_squared", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 100_000, 100_000),
                Error::TooLarge { .. }
            )
        }),
        risky("surface::tabulate_usize_max", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), usize::MAX, 2),
                Error::TooLarge { .. }
            )
        }),
        case("surface::tabulate_fn_surface_nan", || {
            let nan =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * f64::NAN));
            expect_err!(
                tabulate(&nan, &Rect::unit(), 3, 3),
                Error::NonFiniteSurface { .. }
            )
        }),
        case("surface::tabulate_fn_surface_1e308_times_s", || {
            let big =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s * 1e308, t, t));
            let rect = ok(Rect::try_new(0.0, 2.0, 0.0, 1.0))?;
            expect_err!(
                tabulate(&big, &rect, 3, 2),
                Error::NonFiniteSurface { s, .. } if *s == 2.0
            )
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
    ]
}

/// `partials_on_grid` and `partials_on_grid_into`, the threaded path included.
fn partials_on_grid_cases() -> Vec<Case> {
    vec![
        case("surface::partials_on_grid_nan_at_one_node", || {
            let spot = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                let bad = if s.re > 0.4 && s.re < 0.6 && t.re == 0.0 {
                    f64::NAN
                } else {
                    1.0
                };
                Vector3::new(s * bad, t, s * t)
            });
            expect_err!(
                partials_on_grid(&spot, &[0.0, 0.5, 1.0], &[0.0, 1.0]),
                Error::NonFiniteSurface { s, t } if *s == 0.5 && *t == 0.0
            )
        }),
        case("surface::partials_on_grid_nan_parameter", || {
            expect_err!(
                partials_on_grid(&Torus::default(), &[f64::NAN], &[0.0]),
                Error::NonFiniteSurface { .. }
            )
        }),
        case(
            "surface::partials_on_grid_into_inf_parameter_reused_buffer",
            || {
                let mut out = vec![partials(7.0, 7.0, 7.0, 7.0); 10];
                expect_err!(
                    partials_on_grid_into(
                        &Torus::default(),
                        &[0.0, f64::INFINITY],
                        &[0.0, 1.0],
                        &mut out
                    ),
                    Error::NonFiniteSurface { .. }
                )
            },
        ),
        case("surface::partials_on_grid_fn_surface_overflow", || {
            let big =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s * s * 1e308, t, t));
            // at s = 2 the point is 4e308 = inf
            expect_err!(
                partials_on_grid(&big, &[0.0, 2.0], &[0.0]),
                Error::NonFiniteSurface { s, .. } if *s == 2.0
            )
        }),
        case("surface::partials_on_grid_empty_nodes", || {
            let g = ok(partials_on_grid(&Torus::default(), &[], &[0.0, 1.0]))?;
            ensure!(g.as_slice().is_empty(), "cells for no nodes");
            let g = ok(partials_on_grid(&Torus::default(), &[0.0, 1.0], &[]))?;
            ensure!(g.as_slice().is_empty(), "cells for no nodes");
            Ok(())
        }),
        risky("surface::partials_on_grid_too_many_nodes", || {
            let s = vec![0.0; 1 << 14];
            let t = vec![0.0; 1 << 14];
            expect_err!(
                partials_on_grid(&Torus::default(), &s, &t),
                Error::TooLarge { .. }
            )
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
        case("surface::sweep_non_finite_parameters", || {
            sweep(2, |bad, k| {
                let st = put(vec![0.3, 0.7], k, bad);
                expect_err!(
                    partials_on_grid(&Sphere::default(), &[st[0]], &[st[1]]),
                    Error::NonFiniteSurface { .. }
                )
            })
        }),
    ]
}
