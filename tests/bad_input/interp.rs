//! interp: polynomial, nodes, parametrization, piecewise linear, cubic, collocation

use super::*;

/// The anticyclic data of the brief: an interval of 1e-8 at the end, `y = sin 2x`.
fn anticyclic_data() -> (Vec<f64>, Vec<f64>) {
    let x = vec![0.0, 0.25, 0.5, 0.5 + 1e-8];
    let y = x.iter().map(|v: &f64| (2.0 * v).sin()).collect();
    (x, y)
}

pub(super) fn cases() -> Vec<Case> {
    let mut cases = vec![
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
    ];
    cases.extend(collocation_cases());
    cases
}

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
    ]
}
