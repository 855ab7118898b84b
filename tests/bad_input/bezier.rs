//! bezier: bernstein_all, bernstein_sum, de Casteljau (iterative, recursive, levels, surface),
//! BezierPatch

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(bernstein_cases());
    all.extend(de_casteljau_cases());
    all.extend(patch_cases());
    all.extend(from_curve_cases());
    all
}

/// `bernstein_all` and `bernstein_sum`, sums of points at the limits.
fn bernstein_cases() -> Vec<Case> {
    vec![
        case("bezier::bernstein_all_sums_to_one", || {
            let b = ok(bernstein_all(50, 0.3_f64))?;
            ensure!(b.len() == 51, "{} values", b.len());
            ensure!(
                b.iter().all(|x| x.is_finite() && *x >= 0.0),
                "negative or non-finite value"
            );
            let sum: f64 = b.iter().sum();
            ensure!((sum - 1.0).abs() < 1e-13, "sum {sum}");
            ensure!(
                ok(bernstein_all(0, 0.7_f64))? == vec![1.0],
                "degree 0 is not [1]"
            );
            Ok(())
        }),
        risky("bezier::bernstein_all_usize_max", || {
            expect_err!(bernstein_all(usize::MAX, 0.5_f64), Error::TooLarge { .. })
        }),
        risky("bezier::bernstein_all_above_max_degree", || {
            let n = splinelab::bezier::MAX_BERNSTEIN_DEGREE + 1;
            expect_err!(bernstein_all(n, 0.5_f64), Error::TooLarge { .. })
        }),
        case("bezier::bernstein_sum_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                bernstein_sum(&none, 0.5_f64),
                Error::TooFewPoints {
                    needed: 1,
                    got: 0,
                    ..
                }
            )
        }),
        risky("bezier::bernstein_sum_too_many_points", || {
            let pts = vec![1.0_f64; 1 << 15];
            expect_err!(bernstein_sum(&pts, 0.5_f64), Error::TooLarge { .. })
        }),
        case("bezier::sums_of_points_at_max_coordinate_finite", || {
            let pts = alternating_points(6, MAX_COORDINATE);
            for k in 0..=20 {
                let u = k as f64 / 20.0;
                let a = ok(bernstein_sum(&pts, u))?;
                let b = ok(de_casteljau(&pts, u))?;
                ensure!(finite_vecs(&[a, b]), "u = {u}: {a:?} {b:?}");
            }
            Ok(())
        }),
        case("bezier::points_1e308_apart_finite", || {
            let pts = [v2(-1e308, 1e308), v2(1e308, -1e308)];
            let a = ok(bernstein_sum(&pts, 0.5_f64))?;
            let b = ok(de_casteljau(&pts, 0.5_f64))?;
            ensure!(finite_vecs(&[a, b]), "{a:?} {b:?}");
            Ok(())
        }),
    ]
}

/// `de_casteljau`, `de_casteljau_recursive`, `de_casteljau_levels`, `de_casteljau_surface`.
fn de_casteljau_cases() -> Vec<Case> {
    vec![
        case("bezier::de_casteljau_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                de_casteljau(&none, 0.5_f64),
                Error::TooFewPoints { got: 0, .. }
            )
        }),
        case("bezier::de_casteljau_single_point", || {
            let p = ok(de_casteljau(&[v2(3.0, 4.0)], 0.3_f64))?;
            ensure!(p == v2(3.0, 4.0), "{p:?}");
            Ok(())
        }),
        case("bezier::de_casteljau_recursive_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                de_casteljau_recursive(&none, 0.5_f64),
                Error::TooFewPoints { got: 0, .. }
            )
        }),
        case("bezier::de_casteljau_recursive_single_point", || {
            expect_err!(
                de_casteljau_recursive(&[v2(1.0, 1.0)], 0.5_f64),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        risky("bezier::de_casteljau_recursive_25_points", || {
            let pts = some_points(25);
            expect_err!(
                de_casteljau_recursive(&pts, 0.5_f64),
                Error::TooLarge { got: 25, .. }
            )
        }),
        risky("bezier::de_casteljau_recursive_1e6_points", || {
            let pts = vec![1.0_f64; 1_000_000];
            expect_err!(
                de_casteljau_recursive(&pts, 0.5_f64),
                Error::TooLarge { got: 1_000_000, .. }
            )
        }),
        case(
            "bezier::de_casteljau_recursive_18_points_matches_iterative",
            || {
                let pts = some_points(18);
                let a = ok(de_casteljau_recursive(&pts, 0.3_f64))?;
                let b = ok(de_casteljau(&pts, 0.3_f64))?;
                ensure!((a - b).amax() < 1e-12, "{a:?} vs {b:?}");
                Ok(())
            },
        ),
        case("bezier::de_casteljau_levels_empty", || {
            let none: [Vector2<f64>; 0] = [];
            expect_err!(
                de_casteljau_levels(&none, 0.5_f64),
                Error::TooFewPoints { .. }
            )
        }),
        case("bezier::de_casteljau_levels_single_point", || {
            let l = ok(de_casteljau_levels(&[v2(1.0, 2.0)], 0.5_f64))?;
            ensure!(l == vec![vec![v2(1.0, 2.0)]], "{l:?}");
            Ok(())
        }),
        risky("bezier::de_casteljau_levels_too_many_points", || {
            let pts = vec![1.0_f64; 20_000];
            expect_err!(de_casteljau_levels(&pts, 0.5_f64), Error::TooLarge { .. })
        }),
        case("bezier::de_casteljau_surface_empty_net", || {
            let empty: Grid<Vector3<f64>> = Grid::from_vec(0, 0, vec![]).ok_or("grid")?;
            expect_err!(
                de_casteljau_surface(&empty, 0.5_f64, 0.5_f64),
                Error::TooFewPoints { .. }
            )?;
            let no_cols: Grid<Vector3<f64>> = Grid::from_vec(3, 0, vec![]).ok_or("grid")?;
            expect_err!(
                de_casteljau_surface(&no_cols, 0.5_f64, 0.5_f64),
                Error::TooFewPoints { .. }
            )
        }),
        case("bezier::de_casteljau_surface_single_point", || {
            let one = Grid::from_vec(1, 1, vec![v3(1.0, 2.0, 3.0)]).ok_or("grid")?;
            let p = ok(de_casteljau_surface(&one, 0.2_f64, 0.9_f64))?;
            ensure!(p == v3(1.0, 2.0, 3.0), "{p:?}");
            Ok(())
        }),
    ]
}

/// `BezierPatch`; NaN, ±inf in every entry of a net.
fn patch_cases() -> Vec<Case> {
    vec![
        case("bezier::patch_net_nan", || {
            let mut m = unit_net();
            m[0][3].y = f64::NAN;
            expect_err!(BezierPatch::try_from_net(m), Error::NonFinite { .. })
        }),
        case("bezier::patch_net_inf", || {
            let mut m = unit_net();
            m[2][2].x = f64::NEG_INFINITY;
            expect_err!(BezierPatch::try_from_net(m), Error::NonFinite { .. })
        }),
        case("bezier::patch_net_f64_max", || {
            let mut m = unit_net();
            m[1][1].z = -f64::MAX;
            expect_err!(
                BezierPatch::try_from_net(m),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("bezier::patch_tabulate_too_few", || {
            let p = ok(BezierPatch::try_from_net(unit_net()))?;
            expect_err!(
                p.tabulate_de_casteljau(1, 2),
                Error::TooFewSamples { got: 1, .. }
            )?;
            expect_err!(
                p.tabulate_bernstein(5, 0),
                Error::TooFewSamples { got: 0, .. }
            )
        }),
        risky("bezier::patch_tabulate_100000_squared", || {
            let p = ok(BezierPatch::try_from_net(unit_net()))?;
            expect_err!(
                p.tabulate_de_casteljau(100_000, 100_000),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                p.tabulate_bernstein(100_000, 100_000),
                Error::TooLarge { .. }
            )
        }),
        risky("bezier::patch_tabulate_usize_max", || {
            let p = ok(BezierPatch::try_from_net(unit_net()))?;
            expect_err!(
                p.tabulate_de_casteljau(usize::MAX, 3),
                Error::TooLarge { .. }
            )?;
            expect_err!(p.tabulate_bernstein(3, usize::MAX), Error::TooLarge { .. })
        }),
        case("bezier::patch_at_net_limit_tabulates_finitely", || {
            let p = ok(BezierPatch::try_from_net(alternating_net(NET_LIMIT)))?;
            ensure!(
                finite_grid(&ok(p.tabulate_de_casteljau(17, 17))?),
                "de Casteljau not finite"
            );
            ensure!(
                finite_grid(&ok(p.tabulate_bernstein(17, 17))?),
                "Bernstein not finite"
            );
            Ok(())
        }),
        case("bezier::from_hermite_at_hermite_limit_finite", || {
            let h = ok(HermitePatch::try_from_matrix(alternating_net(
                HERMITE_LIMIT,
            )))?;
            let b = BezierPatch::from_hermite(&h);
            // the printed Codice 7 net of the same matrix is a valid net too
            let _ = splinelab::report_codice7_net(&h);
            ensure!(
                b.net()
                    .iter()
                    .flatten()
                    .all(|v| v.iter().all(|x| x.is_finite())),
                "net not finite"
            );
            ensure!(
                finite_grid(&ok(b.tabulate_bernstein(9, 9))?),
                "tabulation not finite"
            );
            Ok(())
        }),
        case("bezier::sweep_non_finite_net", || {
            sweep(16 * 3, |bad, k| {
                let mut m = unit_net();
                m[k / 12][(k / 3) % 4][k % 3] = bad;
                expect_err!(BezierPatch::try_from_net(m), Error::NonFinite { .. })
            })
        }),
    ]
}

/// A curve's cubic Bézier segments (`bezier::from_curve`).
fn from_curve_cases() -> Vec<Case> {
    vec![
        case("bezier::from_curve_bad_tolerances", || {
            use splinelab::bezier::from_curve::cubic_segments;
            let c = ok(CardinalSpline::try_new(some_points(5), 0.5))?;
            for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                expect_err!(cubic_segments(&c, bad), Error::NotPositive { .. })?;
            }
            Ok(())
        }),
        case("bezier::from_curve_below_rounding", || {
            use splinelab::bezier::from_curve::cubic_segments;
            let circle = ok(NurbsCurve::circle9(v2(0.0, 0.0), 1e6))?;
            expect_err!(cubic_segments(&circle, 5e-324), Error::NoConvergence { .. })
        }),
    ]
}
