//! symbolic: the symbolic formulas (`bernstein_formulas`, `bspline_basis_formulas`,
//! `curve_formulas`, `surface_formulas`) and `trace`

use super::*;

pub(super) fn cases() -> Vec<Case> {
    use splinelab::symbolic::{
        bernstein_formulas, bspline_basis_formulas, curve_formulas, surface_formulas, trace, Trace,
        MAX_FORMULA_DEPTH, MAX_NODES,
    };
    vec![
        case("symbolic::surface_nan_point", || {
            expect_err!(
                surface_formulas(&Torus::default(), f64::NAN, 0.0),
                Error::NonFinite { .. }
            )
        }),
        case("symbolic::surface_infinite_point", || {
            expect_err!(
                surface_formulas(&Torus::default(), 0.0, f64::NEG_INFINITY),
                Error::NonFinite { .. }
            )
        }),
        case("symbolic::curve_nan_parameter", || {
            let c = NurbsCurve::circle9(v2(0.0, 0.0), 1.0).map_err(|e| e.to_string())?;
            expect_err!(curve_formulas(&c, f64::NAN), Error::NonFinite { .. })
        }),
        case("symbolic::bspline_basis_infinite_parameter", || {
            expect_err!(
                bspline_basis_formulas(&basis(2, 5)?, f64::INFINITY),
                Error::NonFinite { .. }
            )
        }),
        case(
            "symbolic::bspline_basis_outside_domain_is_its_end_span",
            || {
                // outside the domain the end span's polynomial (the curve extrapolates it)
                let b = bspline_basis_formulas(&basis(2, 5)?, -3.0).map_err(|e| e.to_string())?;
                ensure!(b.first == 0, "first function {}", b.first);
                ensure!(
                    b.functions.iter().all(|f| f.eval(&[-3.0]).is_finite()),
                    "finite"
                );
                Ok(())
            },
        ),
        case("symbolic::bernstein_degree_too_large", || {
            expect_err!(bernstein_formulas(10_000), Error::TooLarge { .. })
        }),
        case("symbolic::bernstein_degree_zero_is_one", || {
            let b = bernstein_formulas(0).map_err(|e| e.to_string())?;
            ensure!(b.len() == 1 && b[0].plain() == "1", "{:?}", b[0].plain());
            Ok(())
        }),
        case("symbolic::nesting_too_deep", || {
            let deep = trace([("x", 0.1)], |[x]| {
                let mut e = x;
                for _ in 0..=MAX_FORMULA_DEPTH {
                    e = e.cos();
                }
                vec![e]
            });
            expect_err!(deep, Error::TooLarge { .. })
        }),
        case("symbolic::nan_and_infinite_constants_are_kept", || {
            let out = trace([("x", 0.5)], |[x]| {
                vec![x + f64::NAN, x * f64::INFINITY, x / 0.0]
            })
            .map_err(|e| e.to_string())?;
            ensure!(out.formulas[0].eval(&[1.0]).is_nan(), "NaN");
            ensure!(out.formulas[1].eval(&[1.0]) == f64::INFINITY, "inf");
            ensure!(out.formulas[2].eval(&[1.0]) == f64::INFINITY, "x/0");
            Ok(())
        }),
        case("symbolic::stale_handle", || {
            let mut first = Trace::new();
            let x = first.var("x", 1.0);
            drop(first);
            let second = Trace::new();
            expect_err!(second.formula(&x), Error::Degenerate { .. })
        }),
        case("symbolic::remainder_is_opaque", || {
            let out = trace([("x", 2.5)], |[x]| vec![x % 1.0]).map_err(|e| e.to_string())?;
            ensure!(
                out.formulas[0].plain().starts_with("rem["),
                "{}",
                out.formulas[0]
            );
            ensure!(out.formulas[0].eval(&[9.0]) == 0.5, "the traced value");
            Ok(())
        }),
        case("symbolic::node_limit", || {
            let mut trace = Trace::new();
            let x = trace.var("x", 0.1);
            let mut e = x;
            // three new nodes a step (a constant, a product, a sum): past the limit halfway
            for k in 0..MAX_NODES / 2 + 10 {
                e += x * (k as f64 + 2.0);
            }
            expect_err!(trace.formula(&e), Error::TooLarge { .. })
        }),
        risky("symbolic::huge_power_not_multiplied_out", || {
            let out = trace([("x", 0.1)], |[x]| vec![(x + 1.0).powi(i32::MAX)])
                .map_err(|e| e.to_string())?;
            expect_err!(out.formulas[0].expanded(), Error::TooLarge { .. })
        }),
    ]
}
