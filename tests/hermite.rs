//! Hermite patches and spline surfaces: interpolation conditions, Hermite ≡ Bézier,
//! de Casteljau ≡ Bernstein, C¹ seams, exact reproduction of bicubics.

mod common;
use common::{assert_close, Rng, EXACT};
use nalgebra::{Vector2, Vector3};
use num_dual::{Dual64, DualNum, HyperDual64};
use proptest::prelude::*;
use splinelab::{
    bernstein_sum, de_casteljau, de_casteljau_surface, report_codice7_net, BezierPatch, ExpSurface,
    FnSurface, Grid, HermitePatch, HermiteSurface, ParametricSurface, Partials, Partition, Rect,
    SurfaceDerivatives, Torus,
};

/// Rectangles on which every corner's mixed partial is non-zero: for the torus
/// `X_st = (sin t sin s, −sin t cos s, 0)`, so `t` avoids multiples of π and, for the x and y
/// entries separately, `s` avoids multiples of π/2.
const TWISTED: [(f64, f64, f64, f64); 3] = [
    (0.3, 1.4, 0.5, 1.7),
    (2.0, 2.9, -1.2, -0.4),
    (-0.7, -0.2, 2.2, 2.6),
];

fn every_corner_twisted<S: SurfaceDerivatives>(surface: &S, r: &Rect) -> bool {
    [r.s.start(), r.s.end()].iter().all(|&s| {
        [r.t.start(), r.t.end()].iter().all(|&t| {
            // x and y: the torus's z twist is identically 0, so only these can tell
            let d = surface.partials(s, t).dst;
            d.x.abs() > 1e-3 && d.y.abs() > 1e-3
        })
    })
}

/// The patch's own `X, X_s, X_t, X_st` at local `(s, t)`, from hyper-dual numbers.
fn patch_partials<P: ParametricSurface>(patch: &P, s: f64, t: f64) -> Partials {
    patch.partials(s, t)
}

#[test]
fn patch_meets_all_16_interpolation_conditions_with_delta_scaling() {
    for &(sa, sb, ta, tb) in &TWISTED {
        let rect = Rect::new(sa, sb, ta, tb);
        for (name, patch, surface_partials) in [
            (
                "torus",
                HermitePatch::from_surface(&Torus::default(), &rect),
                Box::new(|s, t| Torus::default().partials(s, t))
                    as Box<dyn Fn(f64, f64) -> Partials>,
            ),
            (
                "exp",
                HermitePatch::from_surface(&ExpSurface, &rect),
                Box::new(|s, t| ExpSurface.partials(s, t)),
            ),
        ] {
            let (du, dv) = (rect.s.width(), rect.t.width());
            for (a, u) in [(0.0, sa), (1.0, sb)] {
                for (b, v) in [(0.0, ta), (1.0, tb)] {
                    let got = patch_partials(&patch, a, b);
                    let want = surface_partials(u, v);
                    let at = format!("{name} corner ({u},{v}) of {rect:?}");
                    assert_close(&got.point, &want.point, EXACT, &format!("value {at}"));
                    assert_close(&got.ds, &(want.ds * du), EXACT, &format!("∂s {at}"));
                    assert_close(&got.dt, &(want.dt * dv), EXACT, &format!("∂t {at}"));
                    assert_close(&got.dst, &(want.dst * du * dv), EXACT, &format!("∂st {at}"));
                }
            }
        }
        assert!(every_corner_twisted(&Torus::default(), &rect), "{rect:?}");
        assert!(every_corner_twisted(&ExpSurface, &rect), "{rect:?}");
    }
}

#[test]
fn hermite_matrix_layout_is_codice_4() {
    // On [0,1]² (Δ = 1) the entries are the surface's partials in the report's positions.
    let torus = Torus::default();
    let c = *HermitePatch::from_surface(&torus, &Rect::new(0.0, 1.0, 0.5, 1.0)).matrix();
    let p = |s, t| torus.partials(s, t);
    let (a, b) = (p(0.0, 0.5), p(1.0, 1.0));
    assert_eq!(c[0][0], a.point, "C(1,1) = X(sa,ta)");
    assert_eq!(c[0][1], a.dt * 0.5, "C(1,2) = dv X_t(sa,ta)");
    assert_eq!(c[1][0], a.ds, "C(2,1) = du X_s(sa,ta)");
    assert_eq!(c[1][1], a.dst * 0.5, "C(2,2) = du dv X_st(sa,ta)");
    assert_eq!(c[3][3], b.point, "C(4,4) = X(sb,tb)");
    assert_eq!(c[3][2], b.dt * 0.5, "C(4,3) = dv X_t(sb,tb)");
    assert_eq!(c[2][3], b.ds, "C(3,4) = du X_s(sb,tb)");
    assert_eq!(c[2][2], b.dst * 0.5, "C(3,3) = du dv X_st(sb,tb)");
}

fn max_dev(h: &HermitePatch, b: &BezierPatch, n: usize) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 0..n {
        for j in 0..n {
            let (s, t) = (i as f64 / (n - 1) as f64, j as f64 / (n - 1) as f64);
            let x = h.eval(s, t);
            worst = worst
                .max((x - b.eval_bernstein(s, t)).amax())
                .max((x - b.eval_de_casteljau(s, t)).amax());
        }
    }
    worst
}

#[test]
fn report_codice7_fails_exactly_where_the_twist_is_nonzero() {
    let torus = Torus::default();
    // On [0,1]², X_st(1, 0) = 0: the printed Codice 7 is indistinguishable from the correct net.
    let h = HermitePatch::from_surface(&torus, &Rect::unit());
    let dev = max_dev(&h, &report_codice7_net(&h), 31);
    assert!(dev < 1e-13, "Codice 7 on [0,1]²: {dev:e}");
    // With every corner twisted, its sign error shows.
    for &(sa, sb, ta, tb) in &TWISTED {
        let h = HermitePatch::from_surface(&torus, &Rect::new(sa, sb, ta, tb));
        let dev = max_dev(&h, &report_codice7_net(&h), 31);
        assert!(
            dev > 1e-4,
            "Codice 7 should differ on twisted rectangle: {dev:e}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn hermite_equals_bezier_on_random_twisted_rectangles(
        sa in -3.0..3.0f64, ds in 0.05..1.5f64, ta in 0.2..2.5f64, dt in 0.05..0.6f64,
    ) {
        // t in (0.2, 3.1) keeps sin t ≠ 0 at both t corners, so X_st ≠ 0 at every corner.
        let rect = Rect::new(sa, sa + ds, ta, ta + dt);
        for h in [
            HermitePatch::from_surface(&Torus::default(), &rect),
            HermitePatch::from_surface(&ExpSurface, &Rect::new(sa / 3.0, (sa + ds) / 3.0, ta / 3.0, (ta + dt) / 3.0)),
        ] {
            let b = BezierPatch::from_hermite(&h);
            let dev = max_dev(&h, &b, 11);
            // absolute, as the report's Codice 10 (`abs(X_st − XB_st) < 1.0e-13`)
            prop_assert!(dev < 1e-13, "max |Hermite − Bézier| = {dev:e} on {rect:?}");
        }
    }

    #[test]
    fn de_casteljau_equals_bernstein_sum(
        pts in prop::collection::vec((-10.0..10.0f64, -10.0..10.0f64), 1..12),
        u in 0.0..=1.0f64,
    ) {
        let p: Vec<Vector2<f64>> = pts.iter().map(|&(x, y)| Vector2::new(x, y)).collect();
        let a = de_casteljau(&p, u).expect("non-empty");
        let b = bernstein_sum(&p, u).expect("non-empty");
        prop_assert!((a - b).amax() <= EXACT * 10.0, "{a:?} vs {b:?} at u = {u}");
        // derivatives too: dual numbers through both algorithms
        let pd: Vec<Vector2<Dual64>> = p.iter().map(|v| v.map(Dual64::from)).collect();
        let ud = Dual64::from_re(u).derivative();
        let (a, b) = (de_casteljau(&pd, ud).expect("non-empty"), bernstein_sum(&pd, ud).expect("non-empty"));
        prop_assert!((a.map(|d| d.eps) - b.map(|d| d.eps)).amax() <= 1e-11 * p.len() as f64);
    }

    #[test]
    fn general_de_casteljau_surface_equals_bicubic_patch(s in 0.0..=1.0f64, t in 0.0..=1.0f64) {
        let h = HermitePatch::from_surface(&Torus::default(), &Rect::new(0.3, 1.4, 0.5, 1.7));
        let b = BezierPatch::from_hermite(&h);
        let net = Grid::from_fn(4, 4, |i, j| b.net()[i][j]);
        let x = de_casteljau_surface(&net, s, t).expect("non-empty");
        prop_assert!((x - b.eval_bernstein(s, t)).amax() <= EXACT * 4.0);
    }
}

#[test]
fn spline_surface_is_c1_across_seams() {
    let u = Partition::new(vec![0.0, 0.5, 0.9, 1.0]);
    let v = Partition::new(vec![0.2, 0.7, 1.3]);
    let spline = HermiteSurface::from_surface(&Torus::default(), u.clone(), v.clone());
    let du = |i: usize| u.interval(i).width();
    let dv = |j: usize| v.interval(j).width();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        // seams u = 0.5, 0.9 inside each v piece j
        for i in 1..3 {
            for j in 0..2 {
                let left = spline.patch(i - 1, j).partials(1.0, t);
                let right = spline.patch(i, j).partials(0.0, t);
                let at = format!("u seam {i}, v piece {j}, t = {t}");
                assert_close(&left.point, &right.point, EXACT, &at);
                assert_close(
                    &(left.ds / du(i - 1)),
                    &(right.ds / du(i)),
                    EXACT,
                    &format!("X_u {at}"),
                );
                assert_close(
                    &(left.dt / dv(j)),
                    &(right.dt / dv(j)),
                    EXACT,
                    &format!("X_v {at}"),
                );
            }
        }
        // seam v = 0.7 inside each u piece i
        for i in 0..3 {
            let low = spline.patch(i, 0).partials(t, 1.0);
            let high = spline.patch(i, 1).partials(t, 0.0);
            let at = format!("v seam, u piece {i}, s = {t}");
            assert_close(&low.point, &high.point, EXACT, &at);
            assert_close(
                &(low.dt / dv(0)),
                &(high.dt / dv(1)),
                EXACT,
                &format!("X_v {at}"),
            );
            assert_close(
                &(low.ds / du(i)),
                &(high.ds / du(i)),
                EXACT,
                &format!("X_u {at}"),
            );
        }
    }
}

#[test]
fn spline_global_derivatives_interpolate_the_surface_at_every_node() {
    // Dual numbers through the global evaluation include the 1/Δ chain rule, so the spline's
    // X_u, X_v, X_uv at the nodes equal the surface's, unscaled.
    let u = Partition::new(vec![0.3, 0.8, 1.0, 1.9]);
    let v = Partition::new(vec![-0.5, 0.1, 0.6]);
    let spline = HermiteSurface::from_surface(&ExpSurface, u.clone(), v.clone());
    for &x in u.nodes() {
        for &y in v.nodes() {
            let got = spline.partials(x, y);
            let want = ExpSurface.partials(x, y);
            let at = format!("node ({x}, {y})");
            assert_close(&got.point, &want.point, EXACT, &at);
            assert_close(&got.ds, &want.ds, EXACT, &format!("X_u {at}"));
            assert_close(&got.dt, &want.dt, EXACT, &format!("X_v {at}"));
            assert_close(&got.dst, &want.dst, EXACT, &format!("X_uv {at}"));
        }
    }
}

#[test]
fn bicubic_polynomials_are_reproduced_exactly() {
    // Hermite interpolation is exact on polynomials of degree ≤ 3 in each variable.
    let poly = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
        Vector3::new(
            s.powi(3) * t * t - s * t + 2.0,
            s * s * t.powi(3) + t,
            (s - t * 2.0) * s * t,
        )
    });
    let spline = HermiteSurface::from_surface(
        &poly,
        Partition::new(vec![-1.0, 0.2, 1.5]),
        Partition::new(vec![0.0, 0.4, 2.0]),
    );
    let mut rng = Rng::new(9);
    for _ in 0..200 {
        let (u, v) = (rng.uniform(-1.0, 1.5), rng.uniform(0.0, 2.0));
        let got = spline.try_point(u, v).expect("inside the domain");
        assert_close(
            &got,
            &poly.point(u, v),
            EXACT * 10.0,
            &format!("({u}, {v})"),
        );
    }
}

#[test]
fn spline_tabulation_matches_pointwise_evaluation_including_right_ends() {
    let spline = HermiteSurface::uniform(&Torus::default(), &Rect::new(0.0, 6.0, 0.0, 6.0), 4, 3)
        .expect("valid");
    let us = [0.0, 0.7, 1.5, 3.0, 5.99, 6.0];
    let vs = [0.0, 2.0, 4.0, 6.0];
    let grid = spline.tabulate(&us, &vs).expect("inside");
    for (i, &u) in us.iter().enumerate() {
        for (j, &v) in vs.iter().enumerate() {
            let p = spline.try_point(u, v).expect("inside");
            assert_close(grid.get(i, j), &p, EXACT, &format!("({u}, {v})"));
            assert_close(
                &p,
                &Torus::default().point(u, v),
                0.1,
                &format!("near torus ({u}, {v})"),
            );
        }
    }
}
