//! fast_paths: issue 13's fast paths: `CubicSpline::refit` / `refit_function` (the same checks as
//! a fresh build; the twisted solve's pivots that overflow), and the batch evaluation of B-spline,
//! NURBS and cubic spline (`eval_many`, `values_into`): parameters in any order, any degree,
//! control points whose power forms overflow (the span falls back to the basis form)

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(batch_cases());
    all.extend(refit_and_twisted_cases());
    all
}

/// Parameters in no particular order, inside and slightly outside `[a, b]`, ends included.
fn scrambled(a: f64, b: f64) -> Vec<f64> {
    let mut ts: Vec<f64> = (0..97)
        .map(|k| a + (b - a) * ((k * 37) % 97) as f64 / 96.0)
        .collect();
    ts.extend([
        b,
        a,
        b,
        0.5 * (a + b),
        a - 0.01 * (b - a),
        b + 0.01 * (b - a),
        b,
    ]);
    ts
}

/// The batch evaluation: any degree, power forms that overflow, parameters in any order.
fn batch_cases() -> Vec<Case> {
    vec![
        case(
            "fast_paths::batch_degree_3000_declines_the_power_form",
            || {
                // a degree far beyond any power form: one parameter evaluated without building one
                // (it would need p(p+1)/2 weights and p³/2 ≈ 10¹⁰ operations per span)
                let p = 3000;
                let basis = BSplineBasis::try_new(
                    KnotVector::open_uniform(p, p + 1, 0.0, 1.0).expect("knots"),
                    p,
                )
                .expect("basis");
                let c = BSplineCurve::try_new(basis, vec![v2(1.0, 2.0); p + 1]).expect("points");
                let mut out = Vec::new();
                c.eval_many(&[0.5], &mut out);
                ensure!(
                    out.len() == 1 && (out[0] - v2(1.0, 2.0)).amax() < 1e-9,
                    "{out:?}"
                );
                Ok(())
            },
        ),
        case("fast_paths::batch_degree9_overflowing_power_form", || {
            // alternating ±MAX_COORDINATE: the power form's coefficients (up to 3⁹ times the
            // points) overflow, every span falls back to the basis form
            let p = 9;
            let basis =
                BSplineBasis::try_new(KnotVector::open_uniform(p, 14, 0.0, 1.0).expect("knots"), p)
                    .expect("basis");
            let pts: Vec<Vector2<f64>> = (0..14)
                .map(|i| {
                    let s = if i % 2 == 0 { 1.0 } else { -1.0 };
                    v2(s * splinelab::MAX_COORDINATE, 0.0)
                })
                .collect();
            let c = BSplineCurve::try_new(basis, pts).expect("finite points");
            let ts: Vec<f64> = (0..=200).map(|i| i as f64 / 200.0).collect();
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (&t, o) in ts.iter().zip(&out) {
                let r = c.point(t);
                ensure!(o.iter().all(|v| v.is_finite()), "not finite at {t}: {o:?}");
                ensure!(
                    (o - r).amax() <= 1e-12 * splinelab::MAX_COORDINATE,
                    "{o:?} vs {r:?}"
                );
            }
            Ok(())
        }),
        case(
            "fast_paths::bspline_eval_many_any_order_equals_point",
            || {
                let c = ok(BSplineCurve::try_new(basis(3, 9)?, some_points(9)))?;
                let ts = scrambled(0.0, 1.0);
                let mut out = Vec::new();
                c.eval_many(&ts, &mut out);
                for (t, q) in ts.iter().zip(&out) {
                    let p = c.point(*t);
                    ensure!(finite_vecs(&[p, *q]), "t = {t}");
                    ensure!(
                        (p - q).amax() <= 1e-12,
                        "t = {t}: point {p:?} vs batch {q:?}"
                    );
                }
                Ok(())
            },
        ),
        case("fast_paths::nurbs_eval_many_any_order_equals_point", || {
            let c = ok(NurbsCurve::circle7(v2(1.0, -2.0), 3.0))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            c.eval_many(&ts, &mut out);
            for (t, q) in ts.iter().zip(&out) {
                let p = c.point(*t);
                ensure!(finite_vecs(&[p, *q]), "t = {t}");
                ensure!(
                    (p - q).amax() <= 1e-12,
                    "t = {t}: point {p:?} vs batch {q:?}"
                );
            }
            Ok(())
        }),
        case("fast_paths::cubic_eval_many_any_order_equals_point", || {
            let x = [0.0, 0.1, 0.5, 0.55, 1.0];
            let y = [1.0, -1.0, 2.0, 0.0, 1.0];
            let s = ok(CubicSpline::function(&x, &y, EndCondition::Periodic))?;
            let ts = scrambled(0.0, 1.0);
            let mut out = Vec::new();
            s.values_into(&ts, &mut out);
            let mut many = Vec::new();
            s.eval_many(&ts, &mut many);
            for ((t, q), m) in ts.iter().zip(&out).zip(&many) {
                let p = s.value(*t);
                ensure!(p.is_finite() && q.is_finite(), "t = {t}");
                ensure!(
                    (p - q).abs() <= 1e-12 && (p - m.x).abs() <= 1e-12,
                    "t = {t}: {p} vs {q} / {}",
                    m.x
                );
            }
            Ok(())
        }),
    ]
}

/// The natural spline function through 4 points, to be refitted.
fn natural() -> CubicSpline<1> {
    CubicSpline::function(
        &[0.0, 1.0, 2.0, 3.0],
        &[0.0, 1.0, 0.0, 1.0],
        EndCondition::Natural,
    )
    .expect("valid")
}

/// `CubicSpline::refit` / `refit_function` (the same checks as a fresh build) and the
/// twisted solve's pivots and slopes that overflow.
fn refit_and_twisted_cases() -> Vec<Case> {
    vec![
        case("fast_paths::refit_count_mismatch", || {
            expect_err!(
                natural().refit_function(&[0.0, 1.0, 2.0], &[0.0, 1.0]),
                Error::CountMismatch {
                    expected: 3,
                    got: 2,
                    ..
                }
            )
        }),
        case("fast_paths::refit_single_point", || {
            expect_err!(
                natural().refit(&[0.0], &[nalgebra::Vector1::new(1.0)]),
                Error::TooFewPoints {
                    needed: 2,
                    got: 1,
                    ..
                }
            )
        }),
        case("fast_paths::refit_nan_value", || {
            expect_err!(
                natural().refit_function(&[0.0, 1.0, 2.0], &[0.0, f64::NAN, 0.0]),
                Error::NonFinite { .. }
            )
        }),
        case("fast_paths::refit_repeated_abscissa", || {
            expect_err!(
                natural().refit_function(&[0.0, 1.0, 1.0, 2.0, 3.0], &[0.0; 5]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("fast_paths::refit_empty", || {
            expect_err!(
                natural().refit_function(&[], &[]),
                Error::TooFewPoints { .. }
            )
        }),
        case("fast_paths::twisted_pivot_overflow", || {
            // two neighbouring gaps of 8.8e307: the diagonal 2(hᵢ₋₁ + hᵢ) overflows
            let x = [
                -9e307, -8.99e307, -8.98e307, -8.97e307, -8.96e307, -8e306, 8e307, 8.9e307,
                8.91e307,
            ];
            let y = [0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0];
            for end in [EndCondition::Natural, EndCondition::clamped(0.0, 0.0)] {
                match CubicSpline::function(&x, &y, end) {
                    Err(Error::SingularSystem { .. } | Error::Overflow { .. }) => {}
                    Err(e) => ensure!(false, "unexpected error {e}"),
                    Ok(s) => {
                        let v = s.value(0.0);
                        ensure!(v.is_finite(), "accepted spline with value {v}");
                    }
                }
            }
            Ok(())
        }),
        case("fast_paths::twisted_slopes_overflow", || {
            // a slope Δy/h of 1e306/1e-300: the moments overflow, a typed error
            let mut x: Vec<f64> = (0..40).map(|i| i as f64).collect();
            x[1] = 1e-300;
            let y: Vec<f64> = (0..40).map(|i| if i == 1 { 1e306 } else { 0.0 }).collect();
            expect_err!(
                CubicSpline::function(&x, &y, EndCondition::Natural),
                Error::Overflow { .. }
            )
        }),
    ]
}
