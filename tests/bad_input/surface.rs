//! surface: Torus, Sphere, FnSurface, tabulate, partials_on_grid(_into)

use super::*;

pub(super) fn cases() -> Vec<Case> {
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
        case("surface::tabulate_one_sample", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 1, 5),
                Error::TooFewSamples { got: 1, .. }
            )
        }),
        case("surface::tabulate_zero_samples", || {
            expect_err!(
                tabulate(&Torus::default(), &Rect::unit(), 5, 0),
                Error::TooFewSamples { got: 0, .. }
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
    ]
}
