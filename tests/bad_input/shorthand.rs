//! shorthand: the `new`-style shorthands (`Interval::new`, `Rect::new`, `Torus::new`, …) panic
//! on invalid input as they document (each in a child process)

use super::*;

pub(super) fn cases() -> Vec<Case> {
    vec![
        risky("shorthand::interval_new_panics", || {
            expect_panic("Interval::new(1, 0)", || Interval::new(1.0, 0.0))
        }),
        risky("shorthand::rect_new_panics", || {
            expect_panic("Rect::new(NaN…)", || Rect::new(f64::NAN, 1.0, 0.0, 1.0))
        }),
        risky("shorthand::partition_new_panics", || {
            expect_panic("Partition::new([1])", || Partition::new(vec![1.0]))
        }),
        risky("shorthand::torus_new_panics", || {
            expect_panic("Torus::new(0, 1)", || Torus::new(0.0, 1.0))
        }),
        risky("shorthand::sphere_new_panics", || {
            expect_panic("Sphere::new(−1)", || Sphere::new(-1.0))
        }),
        risky("shorthand::knot_vector_new_panics", || {
            expect_panic("KnotVector::new([])", || KnotVector::new(vec![]))
        }),
        risky("shorthand::basis_new_panics", || {
            let k = ok(KnotVector::try_new(vec![0.0, 0.0, 1.0, 1.0]))?;
            expect_panic("BSplineBasis::new(k, 5)", move || BSplineBasis::new(k, 5))
        }),
        risky("shorthand::curve_new_panics", || {
            let b = basis(2, 5)?;
            expect_panic("BSplineCurve::new mismatch", move || {
                BSplineCurve::new(b, some_points(4))
            })
        }),
        risky("shorthand::nurbs_new_panics", || {
            let b = basis(2, 5)?;
            expect_panic("NurbsCurve::new zero weight", move || {
                NurbsCurve::new(b, some_points(5), vec![0.0; 5])
            })
        }),
        risky("shorthand::hermite_from_matrix_panics", || {
            let mut c = unit_net();
            c[0][0].x = f64::NAN;
            expect_panic("HermitePatch::from_matrix(NaN)", move || {
                HermitePatch::from_matrix(c)
            })
        }),
        risky("shorthand::bezier_from_net_panics", || {
            let mut m = unit_net();
            m[3][0].y = f64::INFINITY;
            expect_panic("BezierPatch::from_net(inf)", move || {
                BezierPatch::from_net(m)
            })
        }),
        risky("shorthand::hermite_from_corners_panics", || {
            let c = [[partials(1.0, 1.0, 1.0, 1.0); 2]; 2];
            expect_panic("HermitePatch::from_corners(Δu = 0)", move || {
                HermitePatch::from_corners(&c, 0.0, 1.0)
            })
        }),
        risky("shorthand::spline_from_surface_panics", || {
            let nan =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * f64::NAN));
            let u = ok(Partition::try_new(vec![0.0, 1.0]))?;
            expect_panic("HermiteSurface::from_surface(NaN)", move || {
                HermiteSurface::from_surface(&nan, u.clone(), u)
            })
        }),
    ]
}
