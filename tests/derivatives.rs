//! Exact partials from hyper-dual numbers, checked three ways: closed forms, central
//! differences, and user closures.

mod common;
use common::*;
use nalgebra::Vector3;
use num_dual::{DualNum, HyperDual64};
use splinelab::{ExpSurface, FnSurface, Partials, Sphere, SurfaceDerivatives, Torus};

/// Closed-form partials of the torus (seed 000 §2; R major, r minor radius).
fn torus_closed_form(big_r: f64, r: f64, s: f64, t: f64) -> Partials {
    let (ss, cs, st, ct) = (s.sin(), s.cos(), t.sin(), t.cos());
    let ring = big_r + r * ct;
    Partials {
        point: Vector3::new(ring * cs, ring * ss, r * st),
        // X_s = (−(R + r cos t) sin s, (R + r cos t) cos s, 0)
        ds: Vector3::new(-ring * ss, ring * cs, 0.0),
        // X_t = (−r sin t cos s, −r sin t sin s, r cos t)
        dt: Vector3::new(-r * st * cs, -r * st * ss, r * ct),
        // X_st = (r sin t sin s, −r sin t cos s, 0)
        dst: Vector3::new(r * st * ss, -r * st * cs, 0.0),
    }
}

fn assert_partials(got: &Partials, want: &Partials, tol: f64, at: &str) {
    assert_close(&got.point, &want.point, tol, &format!("X at {at}"));
    assert_close(&got.ds, &want.ds, tol, &format!("X_s at {at}"));
    assert_close(&got.dt, &want.dt, tol, &format!("X_t at {at}"));
    assert_close(&got.dst, &want.dst, tol, &format!("X_st at {at}"));
}

#[test]
fn torus_partials_match_closed_forms_at_2000_random_points() {
    let mut rng = Rng::new(1);
    for (big_r, r) in [(2.0, 1.0), (3.5, 0.25)] {
        let torus = Torus::new(big_r, r);
        for _ in 0..1000 {
            let (s, t) = (rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0));
            let got = torus.partials(s, t);
            let want = torus_closed_form(big_r, r, s, t);
            assert_partials(
                &got,
                &want,
                EXACT,
                &format!("R={big_r}, r={r}, (s,t)=({s},{t})"),
            );
        }
    }
}

/// Central differences of `X`: `X_s ≈ (X(s+h,t) − X(s−h,t))/2h`, and for `X_st` the
/// four-point stencil `(X(s+h,t+h) − X(s+h,t−h) − X(s−h,t+h) + X(s−h,t−h))/4h²` applied
/// to the dual-number `X_s` instead (a first difference of an exact first derivative), to
/// keep the rounding error at `ε/h`.
fn central_differences<S: SurfaceDerivatives>(surface: &S, s: f64, t: f64) -> Partials {
    let h = FD_STEP;
    let x = |s, t| surface.point(s, t);
    let xs = |s, t| surface.partials(s, t).ds;
    Partials {
        point: x(s, t),
        ds: (x(s + h, t) - x(s - h, t)) / (2.0 * h),
        dt: (x(s, t + h) - x(s, t - h)) / (2.0 * h),
        dst: (xs(s, t + h) - xs(s, t - h)) / (2.0 * h),
    }
}

#[test]
fn partials_agree_with_central_differences() {
    let mut rng = Rng::new(2);
    for _ in 0..200 {
        let (s, t) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0));
        let at = format!("(s,t)=({s},{t})");
        assert_partials(
            &Torus::default().partials(s, t),
            &central_differences(&Torus::default(), s, t),
            FD,
            &format!("torus {at}"),
        );
        let (s, t) = (s / 3.0, t / 3.0); // keep e^{s+t} moderate
        assert_partials(
            &ExpSurface.partials(s, t),
            &central_differences(&ExpSurface, s, t),
            FD,
            &format!("exp surface {at}"),
        );
    }
}

#[test]
fn sphere_and_exp_surface_match_closed_forms() {
    let mut rng = Rng::new(3);
    let sphere = Sphere::try_new(1.5).expect("valid radius");
    for _ in 0..500 {
        let (s, t) = (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
        let (ss, cs, st, ct) = (s.sin(), s.cos(), t.sin(), t.cos());
        let rho = 1.5;
        let want = Partials {
            point: Vector3::new(ct * cs, ct * ss, st) * rho,
            ds: Vector3::new(-ct * ss, ct * cs, 0.0) * rho,
            dt: Vector3::new(-st * cs, -st * ss, ct) * rho,
            dst: Vector3::new(st * ss, -st * cs, 0.0) * rho,
        };
        assert_partials(
            &sphere.partials(s, t),
            &want,
            EXACT,
            &format!("sphere ({s},{t})"),
        );

        // X = (e^{s+t}, e^{s−t}, sinh s sinh t)
        let (ep, em) = ((s + t).exp(), (s - t).exp());
        let want = Partials {
            point: Vector3::new(ep, em, s.sinh() * t.sinh()),
            ds: Vector3::new(ep, em, s.cosh() * t.sinh()),
            dt: Vector3::new(ep, -em, s.sinh() * t.cosh()),
            dst: Vector3::new(ep, -em, s.cosh() * t.cosh()),
        };
        assert_partials(
            &ExpSurface.partials(s, t),
            &want,
            EXACT,
            &format!("exp ({s},{t})"),
        );
    }
}

#[test]
fn user_closure_gets_exact_partials() {
    // X = (s² t, sin(s t), s + t³): X_s = (2st, t cos st, 1), X_t = (s², s cos st, 3t²),
    // X_st = (2s, cos st − st sin st, 0)
    let user = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
        Vector3::new(s * s * t, (s * t).sin(), s + t.powi(3))
    });
    let mut rng = Rng::new(4);
    for _ in 0..500 {
        let (s, t) = (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
        let st = s * t;
        let want = Partials {
            point: Vector3::new(s * s * t, st.sin(), s + t.powi(3)),
            ds: Vector3::new(2.0 * s * t, t * st.cos(), 1.0),
            dt: Vector3::new(s * s, s * st.cos(), 3.0 * t * t),
            dst: Vector3::new(2.0 * s, st.cos() - st * st.sin(), 0.0),
        };
        assert_partials(
            &user.partials(s, t),
            &want,
            EXACT,
            &format!("closure ({s},{t})"),
        );
        assert_partials(
            &user.partials(s, t),
            &central_differences(&user, s, t),
            FD,
            &format!("closure vs FD ({s},{t})"),
        );
    }
}
