//! interp: polynomial, nodes, parametrization, piecewise linear, cubic (with `CubicSpline::refit`
//! and `refit_function`), collocation (with the B-spline route of the cubic spline on nearly
//! coincident knots)

use super::*;

/// The anticyclic data of the brief: an interval of 1e-8 at the end, `y = sin 2x`.
fn anticyclic_data() -> (Vec<f64>, Vec<f64>) {
    let x = vec![0.0, 0.25, 0.5, 0.5 + 1e-8];
    let y = x.iter().map(|v: &f64| (2.0 * v).sin()).collect();
    (x, y)
}

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(power_cases());
    all.extend(vandermonde_and_lagrange_cases());
    all.extend(nodes_and_max_error_cases());
    all.extend(parametrization_cases());
    all.extend(linear_cases());
    all.extend(cubic_cases());
    all.extend(cubic_extreme_cases());
    all.extend(refit_cases());
    all.extend(refit_end_and_size_cases());
    all.extend(collocation_cases());
    all.extend(schoenberg_whitney_and_cubic_collocation_cases());
    all.extend(near_knots_cases());
    all.extend(curve_cases());
    all
}

/// `PowerPolynomial::interpolate`.
fn power_cases() -> Vec<Case> {
    vec![
        case("interp::power_empty", || {
            expect_err!(
                PowerPolynomial::interpolate(&[], &[]),
                Error::TooFewPoints { got: 0, .. }
            )
        }),
        case("interp::power_count_mismatch", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0], &[1.0]),
                Error::CountMismatch {
                    expected: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::power_nan_node", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, f64::NAN], &[1.0, 2.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::power_inf_value", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0], &[1.0, f64::INFINITY]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::power_repeated_node", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0, 1.0], &[1.0, 2.0, 3.0]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::power_decreasing_nodes", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 2.0, 1.0], &[1.0, 2.0, 3.0]),
                Error::NotIncreasing { index: 2, .. }
            )
        }),
        case("interp::power_nodes_1e-310_apart", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1e-310], &[1.0, 2.0]),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::power_vandermonde_entry_overflows", || {
            expect_err!(
                PowerPolynomial::interpolate(&[0.0, 1.0, 1e200], &[1.0, 2.0, 3.0]),
                Error::Overflow { .. }
            )
        }),
        case("interp::power_single_point", || {
            let p = ok(PowerPolynomial::interpolate(&[0.5], &[3.0]))?;
            ensure!(
                p.eval(7.0_f64) == 3.0,
                "constant interpolant {}",
                p.eval(7.0_f64)
            );
            Ok(())
        }),
        case(
            "interp::power_30_equispaced_refused_or_interpolates",
            || {
                let x = linspace(0.0, 1.0, 30);
                let y: Vec<f64> = x.iter().map(|v| (3.0 * v).sin()).collect();
                match PowerPolynomial::interpolate(&x, &y) {
                    Err(Error::IllConditioned { .. } | Error::SingularSystem { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(p) => {
                        ensure!(
                            p.coefficients().iter().all(|c| c.is_finite()),
                            "non-finite coefficient"
                        );
                        check_interpolates(&x, &y, |t| p.eval(t))
                    }
                }
            },
        ),
        case("interp::power_values_f64_max", || {
            let x = [0.0, 1.0, 2.0, 3.0];
            let y = [f64::MAX, -f64::MAX, f64::MAX, -f64::MAX];
            match PowerPolynomial::interpolate(&x, &y) {
                Err(_) => Ok(()),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        risky("interp::power_too_many_nodes", || {
            let x = linspace(0.0, 1.0, 11_586);
            let y = vec![0.0; x.len()];
            expect_err!(PowerPolynomial::interpolate(&x, &y), Error::TooLarge { .. })
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
    ]
}

/// `vandermonde_condition` and `Lagrange`.
fn vandermonde_and_lagrange_cases() -> Vec<Case> {
    vec![
        risky("interp::vandermonde_condition_nan", || {
            expect_err!(
                vandermonde_condition(&[f64::NAN, 1.0, 2.0]),
                Error::NonFinite { .. }
            )
        }),
        risky("interp::vandermonde_condition_inf", || {
            expect_err!(
                vandermonde_condition(&[0.0, f64::INFINITY, 2.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::vandermonde_condition_empty", || {
            let r = vandermonde_condition(&[]);
            ensure!(r == Ok(None), "empty nodes: {}", show(&r));
            Ok(())
        }),
        case("interp::vandermonde_condition_well_posed", || {
            let k = ok(vandermonde_condition(&[0.0, 1.0, 2.0]))?;
            ensure!(
                matches!(k, Some(k) if k.is_finite() && k >= 1.0),
                "κ = {k:?}"
            );
            Ok(())
        }),
        case(
            "interp::vandermonde_condition_repeated_nodes_singular",
            || {
                let r = vandermonde_condition(&[1.0, 1.0, 1.0]);
                ensure!(r == Ok(None), "repeated nodes: {}", show(&r));
                Ok(())
            },
        ),
        case("interp::vandermonde_condition_power_overflows", || {
            expect_err!(
                vandermonde_condition(&[0.0, 1e200, 2e200]),
                Error::Overflow { .. }
            )
        }),
        risky("interp::vandermonde_condition_30_equispaced", || {
            let r = vandermonde_condition(&linspace(0.0, 1.0, 30));
            match r {
                Ok(None) => Ok(()),
                Ok(Some(k)) if k.is_finite() && k > 1e10 => Ok(()),
                other => Err(format!("30 equispaced nodes: {}", show(&other))),
            }
        }),
        risky("interp::vandermonde_condition_too_many_nodes", || {
            expect_err!(
                vandermonde_condition(&vec![0.5; 11_586]),
                Error::TooLarge { .. }
            )
        }),
        case("interp::lagrange_empty", || {
            expect_err!(Lagrange::try_new(&[], &[]), Error::TooFewPoints { .. })
        }),
        case("interp::lagrange_nan_value", || {
            expect_err!(
                Lagrange::try_new(&[0.0, 1.0], &[f64::NAN, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::lagrange_repeated_node", || {
            expect_err!(
                Lagrange::try_new(&[0.0, 0.0], &[1.0, 1.0]),
                Error::RepeatedParameter { index: 1, .. }
            )
        }),
        case("interp::lagrange_count_mismatch", || {
            expect_err!(
                Lagrange::try_new(&[0.0, 1.0, 2.0], &[1.0]),
                Error::CountMismatch { .. }
            )
        }),
        case("interp::lagrange_nodes_1e-310_apart", || {
            expect_err!(
                Lagrange::try_new(&[1.0, 2.0, 2.0 + 1e-310], &[1.0, 2.0, 3.0]),
                Error::RepeatedParameter { .. } | Error::GapTooSmall { .. }
            )?;
            expect_err!(
                Lagrange::try_new(&[0.0, 1e-310], &[1.0, 2.0]),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::lagrange_150_equispaced_on_0_1000", || {
            let x = linspace(0.0, 1000.0, 150);
            let y: Vec<f64> = x.iter().map(|v| (v / 100.0).sin()).collect();
            let p = ok(Lagrange::try_new(&x, &y))?;
            check_interpolates(&x, &y, |t| p.eval(t))?;
            for t in linspace(0.0, 1000.0, 2001) {
                ensure!(p.eval(t).is_finite(), "p({t}) = {}", p.eval(t));
            }
            Ok(())
        }),
        case(
            "interp::lagrange_1500_equispaced_overflow_or_interpolates",
            || {
                let x = linspace(0.0, 1.0, 1500);
                let y: Vec<f64> = x.iter().map(|v| (3.0 * v).cos()).collect();
                match Lagrange::try_new(&x, &y) {
                    Err(Error::Overflow { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
                }
            },
        ),
        case("interp::lagrange_values_1e300_tiny_gaps_finite", || {
            let x = [0.0, 1e-300, 2e-300, 3e-300];
            let y = [1e300, -1e300, 1e300, -1e300];
            match Lagrange::try_new(&x, &y) {
                Err(_) => Ok(()),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        case("interp::lagrange_values_f64_max_evaluate_finitely", || {
            // the cubic through alternating ±MAX overshoots to 1.19·MAX near x = 0.74
            let x = [0.0, 1.0, 2.0, 3.0];
            let y = [f64::MAX, -f64::MAX, f64::MAX, -f64::MAX];
            match Lagrange::try_new(&x, &y) {
                Err(Error::CoordinateTooLarge { .. } | Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected error {e:?}")),
                Ok(p) => check_interpolates(&x, &y, |t| p.eval(t)),
            }
        }),
        risky("interp::lagrange_too_many_nodes", || {
            let x = linspace(0.0, 1.0, 11_586);
            let y = vec![0.0; x.len()];
            expect_err!(Lagrange::try_new(&x, &y), Error::TooLarge { .. })
        }),
        case("interp::lagrange_nodes_width_overflows", || {
            expect_err!(
                Lagrange::try_new(&[-1e308, 0.0, 1e308], &[1.0, 2.0, 3.0]),
                Error::Overflow { .. }
            )
        }),
    ]
}

/// `NodeFamily::nodes` and `max_interpolation_error`.
fn nodes_and_max_error_cases() -> Vec<Case> {
    vec![
        case("interp::nodes_nan_bound", || {
            expect_err!(
                NodeFamily::Chebyshev.nodes(f64::NAN, 1.0, 3),
                Error::NonFinite { .. }
            )
        }),
        case("interp::nodes_empty_interval", || {
            expect_err!(
                NodeFamily::Equispaced.nodes(1.0, 0.0, 3),
                Error::EmptyInterval { .. }
            )
        }),
        case("interp::nodes_width_overflows", || {
            expect_err!(
                NodeFamily::Equispaced.nodes(-1e308, 1e308, 3),
                Error::Overflow { .. }
            )
        }),
        risky("interp::nodes_usize_max_degree", || {
            expect_err!(
                NodeFamily::Chebyshev.nodes(0.0, 1.0, usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                NodeFamily::Equispaced.nodes(0.0, 1.0, MAX_ELEMENTS),
                Error::TooLarge { .. }
            )
        }),
        case("interp::nodes_degree_zero", || {
            let e = ok(NodeFamily::Equispaced.nodes(1.0, 3.0, 0))?;
            let c = ok(NodeFamily::Chebyshev.nodes(1.0, 3.0, 0))?;
            ensure!(e == vec![2.0], "equispaced {e:?}");
            ensure!(
                c.len() == 1 && (c[0] - 2.0).abs() < 1e-15,
                "Chebyshev {c:?}"
            );
            Ok(())
        }),
        case(
            "interp::nodes_unresolvable_width_distinct_or_refused",
            || {
                for family in [NodeFamily::Equispaced, NodeFamily::Chebyshev] {
                    match family.nodes(1.0, 1.0 + 4.0 * f64::EPSILON, 10) {
                        Err(_) => {}
                        Ok(x) => ensure!(
                            x.windows(2).all(|w| w[0] < w[1]),
                            "{} nodes repeat: {x:?}",
                            format_args!("{:?}", family)
                        ),
                    }
                }
                Ok(())
            },
        ),
        case("interp::max_error_function_nan", || {
            expect_err!(
                max_interpolation_error(|_| f64::NAN, (0.0, 1.0), 4, NodeFamily::Equispaced, 11),
                Error::NonFinite { .. } | Error::Overflow { .. }
            )
        }),
        case("interp::max_error_function_nan_between_nodes", || {
            let f = |x: f64| {
                if x > 0.55 && x < 0.56 {
                    f64::NAN
                } else {
                    x * x
                }
            };
            expect_err!(
                max_interpolation_error(f, (0.0, 1.0), 2, NodeFamily::Equispaced, 1001),
                Error::Overflow { value, .. } if value.is_nan()
            )
        }),
        case("interp::max_error_too_few_samples", || {
            expect_err!(
                max_interpolation_error(runge, (-5.0, 5.0), 4, NodeFamily::Chebyshev, 1),
                Error::TooFewSamples { got: 1, .. }
            )
        }),
        risky("interp::max_error_huge_sizes", || {
            expect_err!(
                max_interpolation_error(runge, (-5.0, 5.0), 4, NodeFamily::Chebyshev, usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                max_interpolation_error(runge, (-5.0, 5.0), 1 << 40, NodeFamily::Chebyshev, 11),
                Error::TooLarge { .. }
            )
        }),
        case("interp::max_error_runge_documented", || {
            let e = ok(max_interpolation_error(
                runge,
                (-5.0, 5.0),
                10,
                NodeFamily::Equispaced,
                2001,
            ))?;
            ensure!(
                e.is_finite() && e > 1.0,
                "Runge's phenomenon at degree 10: {e}"
            );
            let c = ok(max_interpolation_error(
                runge,
                (-5.0, 5.0),
                10,
                NodeFamily::Chebyshev,
                2001,
            ))?;
            ensure!(c.is_finite() && c < e, "Chebyshev {c} vs equispaced {e}");
            Ok(())
        }),
    ]
}

/// `Parametrization::parameters`.
fn parametrization_cases() -> Vec<Case> {
    vec![
        case("interp::param_one_point", || {
            expect_err!(
                Parametrization::ChordLength.parameters(&[v2(0.0, 0.0)]),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::param_nan_coordinate", || {
            expect_err!(
                Parametrization::Centripetal.parameters(&[v2(0.0, 0.0), v2(f64::NAN, 1.0)]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::param_coordinate_1e308", || {
            expect_err!(
                Parametrization::Uniform.parameters(&[v2(0.0, 0.0), v2(1e308, 1.0)]),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("interp::param_repeated_point", || {
            expect_err!(
                Parametrization::ChordLength.parameters(&[
                    v2(0.0, 0.0),
                    v2(1.0, 1.0),
                    v2(1.0, 1.0)
                ]),
                Error::RepeatedPoint { index: 2 }
            )
        }),
        case("interp::param_steps_1_and_1e-20", || {
            for p in Parametrization::ALL {
                match p.parameters(&unequal_step_points()) {
                    Err(Error::RepeatedParameter { .. }) => {}
                    Err(e) => return Err(format!("{}: unexpected {e:?}", format_args!("{:?}", p))),
                    Ok(t) => check_parameters(&t)
                        .map_err(|e| format!("{}: {e}", format_args!("{:?}", p)))?,
                }
            }
            Ok(())
        }),
        case("interp::param_points_1e306_apart", || {
            let pts = [v2(-1e306, 0.0), v2(1e306, 0.0), v2(1e306, 2e306)];
            for p in Parametrization::ALL {
                let t = ok(p.parameters(&pts))?;
                check_parameters(&t).map_err(|e| format!("{}: {e}", format_args!("{:?}", p)))?;
            }
            Ok(())
        }),
        case("interp::param_subnormal_coordinates", || {
            let pts = [v2(0.0, 0.0), v2(5e-324, 0.0), v2(1e-323, 0.0)];
            for p in Parametrization::ALL {
                let t = ok(p.parameters(&pts))?;
                check_parameters(&t).map_err(|e| format!("{}: {e}", format_args!("{:?}", p)))?;
            }
            Ok(())
        }),
    ]
}

/// `PiecewiseLinear`.
fn linear_cases() -> Vec<Case> {
    vec![
        case("interp::linear_count_mismatch", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1.0], &[v1(0.0)]),
                Error::CountMismatch { .. }
            )
        }),
        case("interp::linear_single_point", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0], &[v1(0.0)]),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::linear_nan_abscissa", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, f64::NAN], &[v1(0.0), v1(1.0)]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::linear_repeated_abscissa", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1.0, 1.0], &[v1(0.0), v1(1.0), v1(2.0)]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::linear_abscissae_1e-310_apart", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1e-310], &[v1(0.0), v1(1.0)]),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::linear_slope_overflows_values_stay_exact", || {
            // the slope 1e600 is not representable, but the polygon is: its convex form
            // reproduces both ends and stays finite in between; only the derivative overflows
            let p = ok(PiecewiseLinear::try_new(
                &[0.0, 1e-300],
                &[v1(0.0), v1(1e300)],
            ))?;
            ensure!(
                p.point(1e-300).x == 1e300,
                "right end {:?}",
                p.point(1e-300)
            );
            ensure!(p.point(0.0).x == 0.0, "left end {:?}", p.point(0.0));
            let mid = p.point(0.5e-300).x;
            ensure!(
                mid.is_finite() && (mid / 0.5e300 - 1.0).abs() < 1e-15,
                "middle {mid:e}"
            );
            Ok(())
        }),
        case("interp::linear_value_beyond_max_coordinate", || {
            expect_err!(
                PiecewiseLinear::try_new(&[0.0, 1.0], &[v1(0.0), v1(f64::MAX)]),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("interp::linear_right_end_exact", || {
            let p = ok(PiecewiseLinear::try_new(
                &[0.0, 0.3, 1.0],
                &[v1(1.0), v1(-MAX_COORDINATE), v1(MAX_COORDINATE)],
            ))?;
            let end = ok(p.try_point(1.0))?;
            ensure!(
                (end.x - MAX_COORDINATE).abs() <= 4.0 * f64::EPSILON * MAX_COORDINATE,
                "p(1) = {}",
                end.x
            );
            for t in linspace(0.0, 1.0, 101) {
                ensure!(p.point(t).x.is_finite(), "p({t}) not finite");
            }
            Ok(())
        }),
        case("interp::linear_curve_repeated_point", || {
            expect_err!(
                PiecewiseLinear::curve(&[v2(0.0, 0.0), v2(0.0, 0.0)], Parametrization::ChordLength),
                Error::RepeatedPoint { index: 1 }
            )
        }),
        case(
            "interp::linear_curve_steps_1_and_1e-20",
            || match PiecewiseLinear::curve(&unequal_step_points(), Parametrization::ChordLength) {
                Err(_) => Ok(()),
                Ok(c) => {
                    let (a, b) = c.domain();
                    ensure!(a == 0.0 && b == 1.0, "domain {a} {b}");
                    Ok(())
                }
            },
        ),
        case("interp::linear_abscissae_width_overflows", || {
            expect_err!(
                PiecewiseLinear::try_new(&[-1e308, 1e308], &[v1(0.0), v1(1.0)]),
                Error::Overflow { .. }
            )
        }),
    ]
}

/// `CubicSpline`: refused data and end conditions.
fn cubic_cases() -> Vec<Case> {
    vec![
        case("interp::cubic_count_mismatch", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0], EndCondition::Natural),
                Error::CountMismatch {
                    expected: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("interp::cubic_single_point", || {
            expect_err!(
                CubicSpline::function(&[0.0], &[1.0], EndCondition::Natural),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("interp::cubic_periodic_two_points", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0], &[1.0, 1.0], EndCondition::Periodic),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("interp::cubic_nan_abscissa", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, f64::NAN, 2.0],
                    &[0.0, 1.0, 0.0],
                    EndCondition::Natural
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::cubic_inf_value", || {
            expect_err!(
                CubicSpline::try_new(
                    &[0.0, 1.0, 2.0],
                    &[v2(0.0, 0.0), v2(f64::INFINITY, 0.0), v2(0.0, 1.0)],
                    EndCondition::Natural
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::cubic_repeated_abscissa", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0, 1.0], &[0.0, 1.0, 0.0], EndCondition::Natural),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::cubic_decreasing_abscissae", || {
            expect_err!(
                CubicSpline::function(&[0.0, 2.0, 1.0], &[0.0, 1.0, 0.0], EndCondition::Natural),
                Error::NotIncreasing { index: 2, .. }
            )
        }),
        case("interp::cubic_knots_at_1e-310", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1e-310, 1.0], &[0.0, 1.0, 0.0], EndCondition::Natural),
                Error::GapTooSmall { index: 1, .. }
            )
        }),
        case("interp::cubic_slopes_overflow", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1e-10, 1.0],
                    &[1e300, -1e300, 1e300],
                    EndCondition::Natural
                ),
                Error::Overflow { .. } | Error::IllConditioned { .. }
            )
        }),
        case("interp::cubic_moments_overflow", || {
            // slopes of 1e300 fit, moments of 1e600 do not
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1e-300, 2e-300],
                    &[0.0, 1.0, 0.0],
                    EndCondition::Natural
                ),
                Error::Overflow { .. } | Error::IllConditioned { .. }
            )
        }),
        case("interp::cubic_periodic_ends_mismatch", || {
            expect_err!(
                CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.5], EndCondition::Periodic),
                Error::PeriodicEndsMismatch { distance } if (*distance - 0.5).abs() < 1e-15
            )
        }),
        case("interp::cubic_clamped_nan_derivative", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[0.0, 1.0, 0.0],
                    EndCondition::clamped(f64::NAN, 0.0)
                ),
                Error::NonFinite { .. }
            )
        }),
    ]
}

/// `CubicSpline`: extreme data, the right end, curves.
fn cubic_extreme_cases() -> Vec<Case> {
    vec![
        case("interp::cubic_clamped_huge_derivative", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[0.0, 1.0, 0.0],
                    EndCondition::clamped(0.0, f64::MAX)
                ),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("interp::cubic_value_beyond_max_coordinate", || {
            expect_err!(
                CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[0.0, f64::MAX, 0.0],
                    EndCondition::Natural
                ),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case(
            "interp::cubic_anticyclic_tiny_interval_refused_or_interpolates",
            || {
                let (x, y) = anticyclic_data();
                match CubicSpline::function(&x, &y, EndCondition::Anticyclic) {
                    Err(Error::IllConditioned { .. } | Error::Overflow { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(s) => check_interpolates(&x, &y, |t| s.value(t)),
                }
            },
        ),
        case(
            "interp::cubic_near_max_coordinate_evaluates_finitely",
            || {
                let x = [0.0, 1.0, 2.0, 3.0, 4.0];
                let y = [
                    MAX_COORDINATE,
                    -MAX_COORDINATE,
                    MAX_COORDINATE,
                    -MAX_COORDINATE,
                    MAX_COORDINATE,
                ];
                for end in [
                    EndCondition::Natural,
                    EndCondition::Periodic,
                    EndCondition::Anticyclic,
                    EndCondition::clamped(0.0, 0.0),
                ] {
                    let s = ok(CubicSpline::function(&x, &y, end))?;
                    let xs = linspace(0.0, 4.0, 401);
                    let mut out = Vec::new();
                    s.values_into(&xs, &mut out);
                    ensure!(
                        out.iter().all(|v| v.is_finite()),
                        "{}: values_into not finite",
                        format_args!("{:?}", end)
                    );
                    check_interpolates(&x, &y, |t| s.value(t))
                        .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
                }
                Ok(())
            },
        ),
        case("interp::cubic_right_end_is_left_limit", || {
            let x = [0.0, 0.5, 0.9, 1.0];
            let y = [0.0, 1.0, -1.0, 2.0];
            let s = ok(CubicSpline::function(&x, &y, EndCondition::Natural))?;
            let end = ok(s.try_point(1.0))?;
            ensure!((end.x - 2.0).abs() <= 1e-14, "s(1) = {}", end.x);
            let m = s.second_derivative(1.0);
            ensure!(m.abs() <= 1e-10, "natural end: s''(1) = {m}");
            let mut out = Vec::new();
            s.eval_many(&[0.0, 1.0], &mut out);
            ensure!(
                (out[1].x - end.x).abs() <= 1e-14,
                "eval_many(1) = {}",
                out[1].x
            );
            Ok(())
        }),
        case("interp::cubic_curve_repeated_point", || {
            expect_err!(
                CubicSpline::curve(
                    &[v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 0.0)],
                    Parametrization::Centripetal,
                    EndCondition::Natural
                ),
                Error::RepeatedPoint { index: 2 }
            )
        }),
        case(
            "interp::cubic_curve_steps_1_and_1e-20",
            || match CubicSpline::curve(
                &unequal_step_points(),
                Parametrization::ChordLength,
                EndCondition::Natural,
            ) {
                Err(_) => Ok(()),
                Ok(s) => {
                    let pts = unequal_step_points();
                    let t = s.nodes().to_vec();
                    check_parameters(&t)?;
                    for (ti, p) in t.iter().zip(&pts) {
                        ensure!(
                            (s.point(*ti) - p).amax() <= RESIDUAL_TOLERANCE,
                            "misses {p:?}"
                        );
                    }
                    Ok(())
                }
            },
        ),
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
    ]
}

/// The natural spline function through 4 points, to be refitted.
fn natural4() -> Result<CubicSpline<1>, String> {
    ok(CubicSpline::function(
        &[0.0, 1.0, 2.0, 3.0],
        &[0.0, 1.0, 0.0, 1.0],
        EndCondition::Natural,
    ))
}

/// A spline function reproduces its data exactly and is finite on its domain.
fn check_function(s: &CubicSpline<1>, x: &[f64], y: &[f64]) -> CaseResult {
    for (xi, yi) in x.iter().zip(y) {
        ensure!(
            s.value(*xi) == *yi,
            "s({xi:e}) = {:e}, not {yi:e}",
            s.value(*xi)
        );
    }
    let (a, b) = (x[0], x[x.len() - 1]);
    for k in 0..=64 {
        let t = a + (b - a) * (k as f64 / 64.0);
        let t = if t.is_finite() { t } else { 0.5 * a + 0.5 * b };
        ensure!(s.value(t).is_finite(), "s({t:e}) = {}", s.value(t));
    }
    Ok(())
}

/// `CubicSpline::refit` and `refit_function`: the data.
fn refit_cases() -> Vec<Case> {
    vec![
        case("interp::sweep_non_finite_abscissa", || {
            sweep(4, |bad, k| {
                let x = put(vec![0.0, 1.0, 2.0, 3.0], k, bad);
                expect_err!(
                    natural4()?.refit_function(&x, &[0.0, 1.0, 0.0, 1.0]),
                    Error::NonFinite { .. }
                )
            })
        }),
        case("interp::sweep_non_finite_value_2d", || {
            sweep(8, |bad, k| {
                let s = ok(CubicSpline::try_new(
                    &[0.0, 1.0, 2.0, 3.0],
                    &four_points(),
                    EndCondition::Natural,
                ))?;
                let mut p = four_points();
                p[k / 2][k % 2] = bad;
                expect_err!(s.refit(&[0.0, 1.0, 2.0, 3.0], &p), Error::NonFinite { .. })
            })
        }),
        case("interp::gap_below_min_positive", || {
            for gap in [5e-324, 1e-310] {
                expect_err!(
                    natural4()?.refit_function(&[0.0, gap, 1.0], &[0.0, 1.0, 0.0]),
                    Error::GapTooSmall { .. }
                )?;
            }
            Ok(())
        }),
        case("interp::decreasing_and_repeated", || {
            expect_err!(
                natural4()?.refit_function(&[0.0, 2.0, 1.0], &[0.0; 3]),
                Error::NotIncreasing { index: 2, .. }
            )?;
            expect_err!(
                natural4()?.refit_function(&[0.0, -0.0, 1.0], &[0.0; 3]),
                Error::RepeatedParameter { index: 1, .. }
            )
        }),
        case("interp::abscissae_width_overflows", || {
            expect_err!(
                natural4()?.refit_function(&[-f64::MAX, 0.0, f64::MAX], &[0.0, 1.0, 0.0]),
                Error::Overflow { .. }
            )
        }),
        case("interp::huge_abscissae", || {
            let x = [-1e307, -1e306, 1e306, 8e307];
            let y = [0.0, 1.0, -1.0, 2.0];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("interp::values_beyond_coordinate_limit", || {
            for v in [2.0 * MAX_COORDINATE, -f64::MAX] {
                expect_err!(
                    natural4()?.refit_function(&[0.0, 1.0, 2.0], &[0.0, v, 0.0]),
                    Error::CoordinateTooLarge { .. }
                )?;
            }
            Ok(())
        }),
        case("interp::values_near_coordinate_limit", || {
            let m = MAX_COORDINATE;
            let x = [0.0, 1e-3, 2e-3, 1.0];
            let y = [m, -m, m, -m];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("interp::tiny_and_subnormal_values", || {
            for v in [1e-300, 5e-324] {
                let x = [0.0, 1.0, 2.0, 3.0];
                let y = [v, -v, 2.0 * v, 0.0];
                let s = ok(natural4()?.refit_function(&x, &y))?;
                check_function(&s, &x, &y)?;
            }
            Ok(())
        }),
        case("interp::tiny_abscissae", || {
            let x = [1e-300, 2e-300, 3e-300, 5e-300];
            let y = [0.0, 1.0, 0.0, 1.0];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("interp::periodic_mismatch_and_too_few", || {
            let p = ok(CubicSpline::function(
                &[0.0, 1.0, 2.0],
                &[0.0, 1.0, 0.0],
                EndCondition::Periodic,
            ))?;
            expect_err!(
                p.clone().refit_function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.5]),
                Error::PeriodicEndsMismatch { .. }
            )?;
            expect_err!(
                p.refit_function(&[0.0, 1.0], &[0.0, 0.0]),
                Error::TooFewPoints { needed: 3, .. }
            )
        }),
    ]
}

/// `CubicSpline::refit` and `refit_function`: end conditions and sizes.
fn refit_end_and_size_cases() -> Vec<Case> {
    vec![
        case("interp::clamped_ends_non_finite", || {
            for bad in NON_FINITE {
                for end in [
                    EndCondition::clamped(bad, 0.0),
                    EndCondition::clamped(0.0, bad),
                ] {
                    expect_err!(
                        CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.0], end),
                        Error::NonFinite { .. }
                    )?;
                }
            }
            Ok(())
        }),
        case("interp::clamped_ends_huge", || {
            let x = [0.0, 1.0, 2.0];
            let y = [0.0, 1.0, 0.0];
            for d in [1e300, MAX_COORDINATE] {
                match CubicSpline::function(&x, &y, EndCondition::clamped(d, -d)) {
                    Ok(s) => check_function(&s, &x, &y)?,
                    Err(Error::Overflow { .. }) => {}
                    Err(e) => return Err(format!("{d:e}: unexpected {e}")),
                }
            }
            expect_err!(
                CubicSpline::function(&x, &y, EndCondition::clamped(f64::MAX, 0.0)),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("interp::larger_then_smaller_data", || {
            let x: Vec<f64> = (0..2000).map(|i| i as f64 * 0.01).collect();
            let y: Vec<f64> = x.iter().map(|t| t.sin()).collect();
            let s = ok(natural4()?.refit_function(&x, &y))?;
            check_function(&s, &x, &y)?;
            let s = ok(s.refit_function(&[0.0, 1.0], &[3.0, 4.0]))?;
            ensure!(s.nodes() == [0.0, 1.0], "{:?}", s.nodes());
            check_function(&s, &[0.0, 1.0], &[3.0, 4.0])
        }),
        case("interp::every_end_condition", || {
            let x = [0.0, 0.5, 1.5, 3.0, 3.25];
            let y = [1.0, -1.0, 2.0, 0.5, 1.0];
            for end in [
                EndCondition::Natural,
                EndCondition::Periodic,
                EndCondition::Cyclic,
                EndCondition::Anticyclic,
                EndCondition::clamped(1.0, -1.0),
            ] {
                let s = ok(CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[1.0, 0.0, 1.0],
                    end,
                ))?;
                let s = ok(s.refit_function(&x, &y))
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
                check_function(&s, &x, &y)
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
            }
            Ok(())
        }),
        case("interp::curve_2d_count_mismatch", || {
            let s = ok(CubicSpline::try_new(
                &[0.0, 1.0, 2.0, 3.0],
                &four_points(),
                EndCondition::Natural,
            ))?;
            expect_err!(
                s.refit(&[0.0, 1.0, 2.0], &four_points()),
                Error::CountMismatch {
                    expected: 3,
                    got: 4,
                    ..
                }
            )
        }),
        risky("interp::too_many_points", || {
            let x: Vec<f64> = (0..=MAX_ELEMENTS).map(|i| i as f64).collect();
            let y = vec![0.0; MAX_ELEMENTS + 1];
            expect_err!(natural4()?.refit_function(&x, &y), Error::TooLarge { .. })
        }),
    ]
}

/// `collocation::interpolate`.
fn collocation_cases() -> Vec<Case> {
    vec![
        case("interp::collocation_values_mismatch", || {
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.3, 0.6, 1.0], &[v1(0.0); 3], &[]),
                Error::CountMismatch {
                    expected: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("interp::collocation_sites_count_mismatch", || {
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[]),
                Error::CountMismatch {
                    expected: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("interp::collocation_nan_site", || {
            expect_err!(
                collocation::interpolate(
                    basis(2, 4)?,
                    &[0.0, f64::NAN, 0.6, 1.0],
                    &[v1(0.0); 4],
                    &[]
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_site_outside_domain", || {
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.3, 0.6, 1.5], &[v1(0.0); 4], &[]),
                Error::OutOfDomain { value, .. } if *value == 1.5
            )
        }),
        case("interp::collocation_schoenberg_whitney_fails", || {
            expect_err!(
                collocation::interpolate(
                    basis(2, 4)?,
                    &[0.0, 0.01, 0.02, 0.03],
                    &[v1(1.0); 4],
                    &[]
                ),
                Error::SchoenbergWhitney { .. }
            )
        }),
        case("interp::collocation_nan_value", || {
            expect_err!(
                collocation::interpolate(
                    basis(2, 4)?,
                    &[0.0, 0.3, 0.6, 1.0],
                    &[v1(0.0), v1(f64::NAN), v1(0.0), v1(0.0)],
                    &[]
                ),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_condition_nan_site", || {
            let c = Condition {
                order: DerivativeOrder::First,
                terms: vec![(f64::NAN, 1.0)],
                value: v1(0.0),
            };
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[c]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_condition_inf_coefficient", || {
            let c = Condition {
                order: DerivativeOrder::Second,
                terms: vec![(0.0, f64::INFINITY)],
                value: v1(0.0),
            };
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[c]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::collocation_condition_site_outside", || {
            let c = Condition {
                order: DerivativeOrder::First,
                terms: vec![(2.0, 1.0)],
                value: v1(0.0),
            };
            expect_err!(
                collocation::interpolate(basis(2, 4)?, &[0.0, 0.5, 1.0], &[v1(0.0); 3], &[c]),
                Error::OutOfDomain { .. }
            )
        }),
        risky("interp::collocation_too_large_system", || {
            let n = 11_600;
            let sites = linspace(0.0, 1.0, n);
            let values = vec![v1(0.0); n];
            expect_err!(
                collocation::interpolate(basis(1, n)?, &sites, &values, &[]),
                Error::TooLarge { .. }
            )
        }),
    ]
}

/// `schoenberg_whitney` and the B-spline route of the cubic spline (`collocation::cubic_spline`).
fn schoenberg_whitney_and_cubic_collocation_cases() -> Vec<Case> {
    vec![
        case(
            "interp::schoenberg_whitney_more_sites_than_functions",
            || {
                expect_err!(
                    schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.2, 0.4, 0.6, 1.0]),
                    Error::CountMismatch {
                        expected: 4,
                        got: 5,
                        ..
                    }
                )
            },
        ),
        case("interp::schoenberg_whitney_nan_site", || {
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.2, f64::NAN, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("interp::schoenberg_whitney_site_outside", || {
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[-0.5, 0.2, 0.4, 1.0]),
                Error::OutOfDomain { .. }
            )
        }),
        case("interp::schoenberg_whitney_repeated_site", || {
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.2, 0.2, 1.0]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("interp::schoenberg_whitney_fails_index", || {
            // N₃ is supported on [0.5, 1]: the site 0.4 lies outside it
            expect_err!(
                schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.1, 0.2, 0.4]),
                Error::SchoenbergWhitney { index: 3, .. }
            )
        }),
        case("interp::schoenberg_whitney_valid", || {
            ok(schoenberg_whitney(&basis(2, 4)?, &[0.0, 0.3, 0.7, 1.0]))
        }),
        case(
            "interp::collocation_anticyclic_tiny_interval_refused_or_interpolates",
            || {
                let (x, y) = anticyclic_data();
                let yv: Vec<Vector1<f64>> = y.iter().map(|v| v1(*v)).collect();
                match collocation::cubic_spline(&x, &yv, EndCondition::Anticyclic) {
                    Err(Error::IllConditioned { .. } | Error::SingularSystem { .. }) => Ok(()),
                    Err(e) => Err(format!("unexpected error {e:?}")),
                    Ok(c) => check_interpolates(&x, &y, |t| c.point(t).x),
                }
            },
        ),
        case("interp::collocation_cubic_knots_at_1e-310", || {
            expect_err!(
                collocation::cubic_spline(
                    &[0.0, 1e-310, 1.0],
                    &[v1(0.0), v1(1.0), v1(0.0)],
                    EndCondition::Natural
                ),
                Error::GapTooSmall { .. }
            )
        }),
        case("interp::collocation_cubic_periodic_mismatch", || {
            expect_err!(
                collocation::cubic_spline(
                    &[0.0, 0.5, 1.0],
                    &[v1(0.0), v1(1.0), v1(0.3)],
                    EndCondition::Periodic
                ),
                Error::PeriodicEndsMismatch { .. }
            )
        }),
        case("interp::collocation_cubic_too_few", || {
            expect_err!(
                collocation::cubic_spline(
                    &[0.0, 1.0],
                    &[v1(0.0), v1(0.0)],
                    EndCondition::Anticyclic
                ),
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            )
        }),
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
    ]
}

/// The B-spline route through `(x, y)` with `end`: solved, interpolating within
/// [`RESIDUAL_TOLERANCE`] of the data scale (refusing as ill-conditioned fails the case).
fn collocation_solves(x: &[f64], y: &[f64], end: EndCondition<1>) -> CaseResult {
    let ys: Vec<Vector1<f64>> = y.iter().map(|&v| v1(v)).collect();
    let c = ok(collocation::cubic_spline(x, &ys, end))?;
    let scale = y.iter().map(|v| v.abs()).fold(f64::MIN_POSITIVE, f64::max);
    for (xi, yi) in x.iter().zip(y) {
        let e = (c.point(*xi)[0] - yi).abs();
        ensure!(
            e <= RESIDUAL_TOLERANCE * scale,
            "{}: misses {yi} at {xi} by {e:e}",
            format_args!("{:?}", end)
        );
    }
    let line = ok(c.polyline(200))?;
    ensure!(finite_vecs(&line), "not finite");
    Ok(())
}

/// The B-spline route of the cubic spline on nearly coincident knots.
fn near_knots_cases() -> Vec<Case> {
    vec![
        case("interp::natural_knots_1e-8_apart", || {
            collocation_solves(
                &[0.0, 1.0, 1.0 + 1e-8, 2.0, 3.0],
                &[0.0, 1.0, 1.0, 0.0, 1.0],
                EndCondition::Natural,
            )
        }),
        case("interp::clamped_knots_1e-8_apart", || {
            collocation_solves(
                &[0.0, 1.0, 1.0 + 1e-8, 2.0, 3.0],
                &[0.0, 1.0, 1.0, 0.0, 1.0],
                EndCondition::clamped(0.0, 0.0),
            )
        }),
        case("interp::natural_two_close_pairs", || {
            collocation_solves(
                &[0.0, 1e-8, 1.0, 2.0, 2.0 + 1e-8, 3.0],
                &[0.0, 0.0, 1.0, -1.0, -1.0, 0.5],
                EndCondition::Natural,
            )
        }),
        case("interp::uniform_spacing_1e-8", || {
            let x: Vec<f64> = (0..8).map(|i| i as f64 * 1e-8).collect();
            let y: Vec<f64> = (0..8).map(|i| (i as f64).sin()).collect();
            collocation_solves(&x, &y, EndCondition::Natural)?;
            collocation_solves(&x, &y, EndCondition::clamped(0.0, 0.0))
        }),
        case("interp::non_finite_and_subnormal_sites", || {
            let y = [v1(0.0), v1(1.0), v1(0.0)];
            for bad in NON_FINITE {
                expect_err!(
                    collocation::cubic_spline(&[0.0, bad, 2.0], &y, EndCondition::Natural),
                    Error::NonFinite { .. }
                )?;
            }
            expect_err!(
                collocation::cubic_spline(&[0.0, 5e-324, 2.0], &y, EndCondition::Natural),
                Error::GapTooSmall { .. }
            )
        }),
    ]
}

/// `interpolate_curve`; NaN, ±inf in every input of the area.
fn curve_cases() -> Vec<Case> {
    vec![
        case("interp::curve_degree_zero", || {
            expect_err!(
                interpolate_curve(&some_points(5), 0, Parametrization::Uniform),
                Error::DegreeTooLow { min: 1, got: 0 }
            )
        }),
        case("interp::curve_degree_usize_max", || {
            expect_err!(
                interpolate_curve(&some_points(5), usize::MAX, Parametrization::Uniform),
                Error::TooFewPoints { .. } | Error::TooLarge { .. }
            )
        }),
        case("interp::curve_too_few_points", || {
            expect_err!(
                interpolate_curve(&some_points(3), 3, Parametrization::ChordLength),
                Error::TooFewPoints {
                    needed: 4,
                    got: 3,
                    ..
                }
            )
        }),
        case("interp::curve_repeated_points", || {
            let mut pts = some_points(5);
            pts[3] = pts[2];
            expect_err!(
                interpolate_curve(&pts, 3, Parametrization::ChordLength),
                Error::RepeatedPoint { index: 3 }
            )
        }),
        case("interp::curve_steps_1_and_1e-20", || {
            let pts = unequal_step_points();
            match interpolate_curve(&pts, 2, Parametrization::ChordLength) {
                Err(_) => Ok(()),
                Ok(c) => {
                    let t = ok(Parametrization::ChordLength.parameters(&pts))?;
                    check_parameters(&t)?;
                    for (ti, p) in t.iter().zip(&pts) {
                        ensure!(
                            (c.point(*ti) - p).amax() <= RESIDUAL_TOLERANCE,
                            "misses {p:?}"
                        );
                    }
                    Ok(())
                }
            }
        }),
        case("interp::curve_interpolates", || {
            let pts = some_points(7);
            let c = ok(interpolate_curve(&pts, 3, Parametrization::Centripetal))?;
            let t = ok(Parametrization::Centripetal.parameters(&pts))?;
            for (ti, p) in t.iter().zip(&pts) {
                let q = c.point(*ti);
                ensure!(
                    (q - p).amax() <= RESIDUAL_TOLERANCE * 3.0,
                    "C({ti}) = {q:?} vs {p:?}"
                );
            }
            Ok(())
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
        case("interp::moment_system_bad_data", || {
            use splinelab::exact::{self, Rational};
            let natural = EndCondition::Natural;
            expect_err!(
                splinelab::moment_system(&[0.0, 1.0, 2.0], &[0.0, 1.0], &natural),
                Error::CountMismatch { .. }
            )?;
            expect_err!(
                splinelab::moment_system(&[0.0], &[0.0], &natural),
                Error::TooFewPoints { needed: 2, .. }
            )?;
            expect_err!(
                splinelab::moment_system(&[0.0, 1.0], &[0.0, 1.0], &EndCondition::Cyclic),
                Error::TooFewPoints { needed: 3, .. }
            )?;
            expect_err!(
                splinelab::moment_system(&[0.0, 1.0, 1.0], &[0.0, 1.0, 2.0], &natural),
                Error::NotIncreasing { index: 2, .. }
            )?;
            expect_err!(
                splinelab::moment_system(&[0.0, 2.0, 1.0], &[0.0, 1.0, 2.0], &natural),
                Error::NotIncreasing { index: 2, .. }
            )?;
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                expect_err!(
                    splinelab::moment_system(&[0.0, 1.0, 2.0], &[0.0, bad, 2.0], &natural),
                    Error::NonFinite { .. }
                )?;
                expect_err!(
                    splinelab::moment_system(
                        &[0.0, 1.0, 2.0],
                        &[0.0, 1.0, 2.0],
                        &EndCondition::clamped(bad, 0.0)
                    ),
                    Error::NonFinite { .. }
                )?;
            }
            let many: Vec<Rational> = (0..300).map(exact::int).collect();
            expect_err!(
                splinelab::moment_system(&many, &many, &natural),
                Error::TooLarge { .. }
            )?;
            // finite nodes whose derived coefficients overflow: 2(h₀ + h₁) = 4·f64::MAX
            expect_err!(
                splinelab::moment_system(&[-f64::MAX, 0.0, f64::MAX], &[0.0, 1.0, 0.0], &natural),
                Error::Overflow { .. }
            )?;
            expect_err!(
                splinelab::moment_system(
                    &[-f64::MAX, f64::MAX],
                    &[0.0, 1.0],
                    &EndCondition::clamped(0.0, 0.0)
                ),
                Error::Overflow { .. }
            )?;
            Ok(())
        }),
    ]
}
