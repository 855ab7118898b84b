//! bspline2: batch evaluation against point() outside a very short domain

use super::*;

fn short_domain_curve() -> Result<BSplineCurve<2>, String> {
    let knots = ok(KnotVector::try_new(vec![
        0.0,
        1.0,
        2.0,
        3.0,
        3.0 + 1e-9,
        4.0,
        5.0,
        6.0,
    ]))?;
    let basis = ok(BSplineBasis::try_new(knots, 3))?;
    ok(BSplineCurve::try_new(
        basis,
        vec![v2(0.0, 0.0), v2(1.0, 2.0), v2(2.0, -1.0), v2(3.0, 1.0)],
    ))
}

/// `eval_many` and `point` agree at `ts` to `rel` of the larger value (at least 1).
fn batch_agrees(c: &BSplineCurve<2>, ts: &[f64], rel: f64) -> CaseResult {
    let mut out = vec![v2(7.0, 7.0)];
    c.eval_many(ts, &mut out);
    ensure!(
        out.len() == ts.len(),
        "{} values for {}",
        out.len(),
        ts.len()
    );
    for (t, o) in ts.iter().zip(&out) {
        let p = c.point(*t);
        let scale = o.amax().max(p.amax()).max(1.0);
        ensure!(
            (o - p).amax() <= rel * scale,
            "at {t}: eval_many {o:?}, point {p:?}"
        );
    }
    Ok(())
}

pub(super) fn cases() -> Vec<Case> {
    vec![
        case("bspline2::eval_many_outside_a_short_domain", || {
            let c = short_domain_curve()?;
            batch_agrees(&c, &[2.999], 1e-6)?;
            batch_agrees(
                &c,
                &[2.9, 2.99, 2.999, 2.999_999, 3.000_001, 3.001, 3.1],
                1e-6,
            )
        }),
        case("bspline2::eval_many_inside_a_short_domain", || {
            let c = short_domain_curve()?;
            let ts: Vec<f64> = (0..=16).map(|k| 3.0 + 1e-9 * k as f64 / 16.0).collect();
            batch_agrees(&c, &ts, 1e-12)
        }),
        case("bspline2::eval_many_empty_and_non_finite", || {
            let c = short_domain_curve()?;
            let mut out = vec![v2(1.0, 1.0)];
            c.eval_many(&[], &mut out);
            ensure!(out.is_empty(), "{out:?}");
            c.eval_many(&[f64::NAN, f64::INFINITY, 3.0], &mut out);
            ensure!(out.len() == 3, "{out:?}");
            ensure!(
                (out[2] - c.point(3.0)).amax() <= 1e-12,
                "{:?} vs {:?}",
                out[2],
                c.point(3.0)
            );
            Ok(())
        }),
    ]
}
