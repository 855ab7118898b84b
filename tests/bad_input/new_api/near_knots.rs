//! collocation2: the B-spline route of the cubic spline on nearly coincident knots

use super::*;

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

pub(super) fn cases() -> Vec<Case> {
    vec![
        case("collocation2::natural_knots_1e-8_apart", || {
            collocation_solves(
                &[0.0, 1.0, 1.0 + 1e-8, 2.0, 3.0],
                &[0.0, 1.0, 1.0, 0.0, 1.0],
                EndCondition::Natural,
            )
        }),
        case("collocation2::clamped_knots_1e-8_apart", || {
            collocation_solves(
                &[0.0, 1.0, 1.0 + 1e-8, 2.0, 3.0],
                &[0.0, 1.0, 1.0, 0.0, 1.0],
                EndCondition::clamped(0.0, 0.0),
            )
        }),
        case("collocation2::natural_two_close_pairs", || {
            collocation_solves(
                &[0.0, 1e-8, 1.0, 2.0, 2.0 + 1e-8, 3.0],
                &[0.0, 0.0, 1.0, -1.0, -1.0, 0.5],
                EndCondition::Natural,
            )
        }),
        case("collocation2::uniform_spacing_1e-8", || {
            let x: Vec<f64> = (0..8).map(|i| i as f64 * 1e-8).collect();
            let y: Vec<f64> = (0..8).map(|i| (i as f64).sin()).collect();
            collocation_solves(&x, &y, EndCondition::Natural)?;
            collocation_solves(&x, &y, EndCondition::clamped(0.0, 0.0))
        }),
        case("collocation2::non_finite_and_subnormal_sites", || {
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
