//! Sweeps: NaN, +inf and −inf in every scalar input position of each constructor

use super::*;

pub(super) fn cases() -> Vec<Case> {
    vec![
        case("domain::sweep_non_finite", || {
            sweep(4, |bad, k| {
                let b = put(vec![0.0, 1.0, 2.0, 3.0], k, bad);
                expect_err!(
                    Rect::try_new(b[0], b[1], b[2], b[3]),
                    Error::NonFinite { .. }
                )?;
                expect_err!(Partition::try_new(b.clone()), Error::NonFinite { .. })?;
                if k < 2 {
                    expect_err!(Interval::try_new(b[0], b[1]), Error::NonFinite { .. })?;
                    expect_err!(Partition::uniform(b[0], b[1], 3), Error::NonFinite { .. })?;
                    expect_err!(Rect::square(b[0], b[1]), Error::NonFinite { .. })?;
                }
                Ok(())
            })
        }),
        case("surface::sweep_non_finite_radii", || {
            sweep(2, |bad, k| {
                let r = put(vec![2.0, 1.0], k, bad);
                expect_err!(Torus::try_new(r[0], r[1]), Error::NotPositive { .. })?;
                expect_err!(Sphere::try_new(bad), Error::NotPositive { .. })
            })
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
        case("bezier::sweep_non_finite_net", || {
            sweep(16 * 3, |bad, k| {
                let mut m = unit_net();
                m[k / 12][(k / 3) % 4][k % 3] = bad;
                expect_err!(BezierPatch::try_from_net(m), Error::NonFinite { .. })
            })
        }),
        case("bspline::sweep_non_finite_inputs", || {
            sweep(5, |bad, k| {
                expect_err!(
                    KnotVector::try_new(put(vec![0.0, 0.0, 0.5, 1.0, 1.0], k, bad)),
                    Error::NonFinite { .. }
                )?;
                let mut pts = some_points(5);
                pts[k][k % 2] = bad;
                expect_err!(
                    BSplineCurve::try_new(basis(2, 5)?, pts),
                    Error::NonFinite { .. }
                )?;
                let c = ok(BSplineCurve::try_new(basis(2, 5)?, some_points(5)))?;
                expect_err!(c.with_point(k, v2(bad, 0.0)), Error::NonFinite { .. })?;
                expect_err!(c.try_point(bad), Error::NonFinite { .. })?;
                if k < 2 {
                    let ab = put(vec![0.0, 1.0], k, bad);
                    expect_err!(
                        KnotVector::open_uniform(2, 5, ab[0], ab[1]),
                        Error::NonFinite { .. }
                    )?;
                    expect_err!(
                        KnotVector::extended_partition(
                            ab[0],
                            ab[1],
                            &[0.5],
                            &[1],
                            3,
                            EndKnots::Clamped
                        ),
                        Error::NonFinite { .. }
                    )?;
                }
                Ok(())
            })
        }),
        case("nurbs::sweep_non_finite_inputs", || {
            sweep(5, |bad, k| {
                expect_err!(
                    nurbs_with(put(vec![1.0; 5], k, bad)),
                    Error::NonPositiveWeight { index, .. } if *index == k
                )?;
                let mut pts = some_points(5);
                pts[k][k % 2] = bad;
                expect_err!(
                    NurbsCurve::try_new(basis(2, 5)?, pts, vec![1.0; 5]),
                    Error::NonFinite { .. }
                )?;
                let c = ok(nurbs_with(vec![1.0; 5]))?;
                expect_err!(c.with_weight(k, bad), Error::NonPositiveWeight { .. })?;
                expect_err!(c.try_point(bad), Error::NonFinite { .. })?;
                if k < 2 {
                    let mut centre = v2(0.0, 0.0);
                    centre[k] = bad;
                    expect_err!(NurbsCurve::circle7(centre, 1.0), Error::NonFinite { .. })?;
                    expect_err!(
                        NurbsCurve::circle9(v2(0.0, 0.0), bad),
                        Error::NotPositive { .. }
                    )?;
                }
                Ok(())
            })
        }),
        case("interp::sweep_non_finite_data", || {
            sweep(4, |bad, k| {
                let x = vec![0.0, 1.0, 2.0, 3.0];
                let y = vec![1.0, -1.0, 2.0, 1.0];
                let (bx, by) = (put(x.clone(), k, bad), put(y.clone(), k, bad));
                expect_err!(
                    PowerPolynomial::interpolate(&bx, &y),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    PowerPolynomial::interpolate(&x, &by),
                    Error::NonFinite { .. }
                )?;
                expect_err!(Lagrange::try_new(&bx, &y), Error::NonFinite { .. })?;
                expect_err!(Lagrange::try_new(&x, &by), Error::NonFinite { .. })?;
                let yv: Vec<Vector1<f64>> = y.iter().map(|v| v1(*v)).collect();
                let byv: Vec<Vector1<f64>> = by.iter().map(|v| v1(*v)).collect();
                expect_err!(PiecewiseLinear::try_new(&bx, &yv), Error::NonFinite { .. })?;
                expect_err!(PiecewiseLinear::try_new(&x, &byv), Error::NonFinite { .. })?;
                for end in [EndCondition::Natural, EndCondition::Anticyclic] {
                    expect_err!(CubicSpline::function(&bx, &y, end), Error::NonFinite { .. })?;
                    expect_err!(CubicSpline::function(&x, &by, end), Error::NonFinite { .. })?;
                    expect_err!(
                        collocation::cubic_spline(&bx, &yv, end),
                        Error::NonFinite { .. }
                    )?;
                    expect_err!(
                        collocation::cubic_spline(&x, &byv, end),
                        Error::NonFinite { .. }
                    )?;
                }
                expect_err!(
                    CubicSpline::function(
                        &x,
                        &y,
                        EndCondition::clamped(
                            if k % 2 == 0 { bad } else { 0.0 },
                            if k % 2 == 1 { bad } else { 0.0 }
                        )
                    ),
                    Error::NonFinite { .. }
                )?;
                expect_err!(vandermonde_condition(&bx), Error::NonFinite { .. })?;
                let sites = put(vec![0.0, 0.3, 0.7, 1.0], k, bad);
                expect_err!(
                    schoenberg_whitney(&basis(2, 4)?, &sites),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    collocation::interpolate(basis(2, 4)?, &sites, &[v1(0.0); 4], &[]),
                    Error::NonFinite { .. }
                )?;
                let mut pts = some_points(4);
                pts[k][k % 2] = bad;
                for p in Parametrization::ALL {
                    expect_err!(p.parameters(&pts), Error::NonFinite { .. })?;
                }
                expect_err!(
                    interpolate_curve(&pts, 2, Parametrization::ChordLength),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    CubicSpline::curve(&pts, Parametrization::Uniform, EndCondition::Natural),
                    Error::NonFinite { .. }
                )?;
                if k < 2 {
                    let ab = put(vec![-1.0, 1.0], k, bad);
                    for family in [NodeFamily::Equispaced, NodeFamily::Chebyshev] {
                        expect_err!(family.nodes(ab[0], ab[1], 4), Error::NonFinite { .. })?;
                    }
                }
                Ok(())
            })
        }),
        case("metrics::sweep_non_finite_entries", || {
            sweep(9, |bad, k| {
                let m = DMatrix::from_fn(3, 3, |i, j| if i * 3 + j == k { bad } else { 1.0 });
                expect_err!(matlab_norm(&m), Error::NonFinite { .. })?;
                let a = grid3(3, 3, |i, j| {
                    if i * 3 + j == k {
                        v3(0.0, bad, 0.0)
                    } else {
                        Vector3::zeros()
                    }
                });
                let z = grid3(3, 3, |_, _| Vector3::zeros());
                expect_err!(compare(&a, &z), Error::NonFinite { .. })?;
                expect_err!(compare(&z, &a), Error::NonFinite { .. })
            })
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
