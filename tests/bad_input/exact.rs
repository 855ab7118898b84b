//! exact: the rational constructors, solve, inverse, determinant and conditions

use super::*;
use splinelab::exact::{self, Rational};
use splinelab::nalgebra::DMatrix;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    vec![
        case("exact::ratio_zero_denominator", || {
            expect_err!(exact::ratio(1, 0), Error::Degenerate { .. })
        }),
        case("exact::ratio_extremes", || {
            // i64::MIN / -1 overflows i64 but not a big rational
            let q = ok(exact::ratio(i64::MIN, -1))?;
            ensure!(
                q == Rational::from(num_bigint::BigInt::from(i64::MIN) * -1),
                "i64::MIN / -1 gave {q}"
            );
            Ok(())
        }),
        case("exact::from_f64_non_finite", || {
            for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                expect_err!(exact::from_f64(x), Error::NonFinite { .. })?;
            }
            Ok(())
        }),
        case("exact::from_f64_extremes_exact", || {
            for x in [f64::MAX, -f64::MAX, f64::MIN_POSITIVE, 5e-324, -0.0] {
                let q = ok(exact::from_f64(x))?;
                ensure!(exact::to_f64(&q) == x, "{x:e} did not read back");
            }
            Ok(())
        }),
        case("exact::matrix_ragged_rows", || {
            expect_err!(
                exact::matrix(&[&[(1, 1), (2, 1)], &[(3, 1)]]),
                Error::CountMismatch { .. }
            )
        }),
        case("exact::matrix_zero_denominator", || {
            expect_err!(exact::matrix(&[&[(1, 0)]]), Error::Degenerate { .. })
        }),
        case("exact::solve_not_square", || {
            let a = DMatrix::from_element(2, 3, exact::int(1));
            let b = DMatrix::from_element(2, 1, exact::int(1));
            expect_err!(exact::solve(&a, &b), Error::ShapeMismatch { .. })
        }),
        case("exact::solve_rows_differ", || {
            let a = exact::identity::<Rational>(3);
            let b = DMatrix::from_element(2, 1, exact::int(1));
            expect_err!(exact::solve(&a, &b), Error::ShapeMismatch { .. })
        }),
        case("exact::solve_singular_exact", || {
            // rank 2: the third row is the sum of the first two
            let a = ok(exact::matrix(&[
                &[(1, 1), (2, 1), (3, 1)],
                &[(1, 2), (1, 3), (1, 4)],
                &[(3, 2), (7, 3), (13, 4)],
            ]))?;
            expect_err!(exact::inverse(&a), Error::SingularSystem { .. })?;
            let d = ok(exact::determinant(&a))?;
            ensure!(d == exact::int(0), "determinant {d}, not 0");
            Ok(())
        }),
        case("exact::solve_singular_f64", || {
            let a = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 2.0, 4.0]);
            expect_err!(exact::inverse(&a), Error::SingularSystem { .. })?;
            let z = DMatrix::<f64>::zeros(3, 3);
            expect_err!(exact::inverse(&z), Error::SingularSystem { .. })
        }),
        case("exact::solve_non_finite_f64", || {
            for x in [f64::NAN, f64::INFINITY] {
                let a = DMatrix::from_row_slice(2, 2, &[1.0, x, 0.0, 1.0]);
                expect_err!(exact::inverse(&a), Error::NonFinite { .. })?;
                let b = DMatrix::from_row_slice(2, 1, &[x, 0.0]);
                expect_err!(
                    exact::solve(&exact::identity(2), &b),
                    Error::NonFinite { .. }
                )?;
                expect_err!(exact::determinant(&a), Error::NonFinite { .. })?;
            }
            Ok(())
        }),
        case("exact::solve_overflow_f64", || {
            // invertible, but the solution 1e308 / 1e-308 is beyond f64
            let a = DMatrix::from_row_slice(1, 1, &[1e-308]);
            let b = DMatrix::from_row_slice(1, 1, &[1e308]);
            expect_err!(exact::solve(&a, &b), Error::Overflow { .. })?;
            let big = DMatrix::from_diagonal_element(3, 3, 1e200);
            expect_err!(exact::determinant(&big), Error::Overflow { .. })
        }),
        case("exact::solve_empty", || {
            // the 0 × 0 system has the empty solution; its determinant is 1
            let a = DMatrix::<Rational>::zeros(0, 0);
            let x = ok(exact::inverse(&a))?;
            ensure!(x.is_empty(), "inverse of 0 × 0 not empty");
            let d = ok(exact::determinant(&a))?;
            ensure!(d == exact::int(1), "determinant of 0 × 0 is {d}");
            Ok(())
        }),
        risky("exact::solve_too_large", || {
            let n = exact::MAX_DIMENSION + 1;
            let a = DMatrix::<f64>::identity(n, n);
            expect_err!(exact::inverse(&a), Error::TooLarge { got, .. } if *got == n)?;
            expect_err!(exact::determinant(&a), Error::TooLarge { .. })?;
            let b = DMatrix::<f64>::zeros(2, n);
            expect_err!(
                exact::solve(&DMatrix::identity(2, 2), &b),
                Error::TooLarge { .. }
            )
        }),
        risky("exact::conditions_too_large", || {
            expect_err!(
                exact::conditions(usize::MAX, &[(0, 0)]),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                exact::conditions(2, &vec![(0, 0); exact::MAX_DIMENSION + 1]),
                Error::TooLarge { .. }
            )
        }),
        case("exact::in_basis_rows_differ", || {
            let b = ok(exact::bernstein(3))?;
            let m = exact::identity::<Rational>(3);
            expect_err!(exact::in_basis(&b, &m), Error::CountMismatch { .. })
        }),
        risky("exact::bernstein_and_unit_too_large", || {
            expect_err!(exact::bernstein(usize::MAX), Error::TooLarge { .. })?;
            expect_err!(
                exact::bernstein(exact::MAX_DIMENSION),
                Error::TooLarge { .. }
            )?;
            expect_err!(exact::unit(usize::MAX, 1, 0, 0), Error::TooLarge { .. })
        }),
        case("exact::unit_outside", || {
            let e = ok(exact::unit(2, 2, 5, 5))?;
            ensure!(exact::is_zero(&e), "a unit outside the matrix gave {e}");
            Ok(())
        }),
        case("exact::codice7_plane_not_4x4", || {
            let c = DMatrix::<f64>::zeros(3, 4);
            expect_err!(splinelab::codice7_plane(&c), Error::ShapeMismatch { .. })?;
            let c = DMatrix::<Rational>::zeros(0, 0);
            expect_err!(splinelab::codice7_plane(&c), Error::ShapeMismatch { .. })
        }),
        case("exact::conditions_high_derivative", || {
            // the 9th derivative of a cubic is 0: a row of zeros, no panic
            let k = ok(exact::conditions(4, &[(9, 1)]))?;
            ensure!(exact::is_zero(&k), "K = {k}");
            Ok(())
        }),
        case("exact::conditions_extreme_points", || {
            // i64::MAX³ is far beyond i64: exact, no overflow
            let k = ok(exact::conditions(4, &[(0, i64::MAX)]))?;
            let big = num_bigint::BigInt::from(i64::MAX);
            ensure!(k[(0, 3)] == Rational::from(big.pow(3)), "K = {k}");
            Ok(())
        }),
    ]
}
