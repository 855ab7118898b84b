//! The studies of seed 004: study_cell, cross_methods, pieces_changed; the outline search's
//! size and fewest.

use super::*;
use splinelab::input::Contour;

/// Each point list as a closed contour.
fn closed(contours: Vec<Vec<Vector2<f64>>>) -> Vec<Contour> {
    contours
        .into_iter()
        .map(|points| Contour {
            points,
            closed: true,
        })
        .collect()
}

pub(super) fn cases() -> Vec<Case> {
    use splinelab::study::outline::{fewest, size, Tolerance};
    use splinelab::study::table_i::{cross_methods, pieces_changed, study_cell};
    vec![
        case("table_i::study_cell_column_out_of_range", || {
            // a cell of no column is refused, not studied as another column
            let mut cell = TABLE_I[0];
            cell.column = 99;
            expect_err!(
                study_cell(&cell, &options(12)),
                Error::IndexOutOfRange { index: 99, .. }
            )
        }),
        risky("table_i::study_cell_usize_max_points", || {
            let mut cell = TABLE_I[3];
            cell.points = usize::MAX;
            expect_err!(study_cell(&cell, &options(12)), Error::TooLarge { .. })
        }),
        case("table_i::study_cell_bspline_order_zero", || {
            let mut cell = TABLE_I[30];
            cell.method = Method::BSpline { order: 0 };
            expect_err!(study_cell(&cell, &options(12)), Error::DegreeTooLow { .. })
        }),
        case("table_i::study_cell_cardinal_nan_a", || {
            let mut cell = TABLE_I[12];
            cell.method = Method::Cardinal { a: f64::NAN };
            expect_err!(study_cell(&cell, &options(12)), Error::Negative { .. })
        }),
        case("table_i::cross_methods_of_no_cells", || {
            let c = ok(cross_methods(&[]))?;
            ensure!(c.is_empty(), "{} rows", c.len());
            Ok(())
        }),
        case("outline::size_degenerate", || {
            ensure!(size(&[]) == 0.0, "no contours");
            ensure!(size(&closed(vec![vec![]])) == 0.0, "an empty contour");
            let inf = size(&closed(vec![vec![v2(0.0, 0.0), v2(f64::INFINITY, 1.0)]]));
            ensure!(inf == 0.0, "infinite: {inf}");
            let max = size(&closed(vec![vec![v2(-f64::MAX, 0.0), v2(f64::MAX, 1.0)]]));
            ensure!(max.is_finite() && max >= 0.0, "±f64::MAX: {max}");
            let nan = size(&closed(vec![vec![v2(0.0, 0.0), v2(f64::NAN, 1.0)]]));
            ensure!(nan.is_finite() && nan >= 0.0, "NaN: {nan}");
            Ok(())
        }),
        case("outline::size_of_the_polygonal_a", || {
            let t = Tolerance::default().of(size(&closed(polygonal_a())));
            ensure!((t - 0.01).abs() < 1e-15, "{t}");
            let tiny: Vec<Vec<Vector2<f64>>> = polygonal_a()
                .into_iter()
                .map(|c| c.into_iter().map(|p| p * 1e-310).collect())
                .collect();
            let t = size(&closed(tiny));
            ensure!(t > 0.0 && t.is_finite(), "subnormal: {t:e}");
            Ok(())
        }),
        case("outline::fewest_of_no_contours", || {
            expect_err!(
                fewest(
                    &[],
                    Tolerance::Absolute(0.1),
                    &[Family::Linear],
                    &options(12),
                    &|_| {}
                ),
                Error::TooFewPoints { .. }
            )
        }),
        case("outline::fewest_bad_tolerance", || {
            for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                expect_err!(
                    fewest(
                        &closed(polygonal_a()),
                        Tolerance::Absolute(tol),
                        &[Family::Linear],
                        &options(12),
                        &|_| {}
                    ),
                    Error::NotPositive { .. }
                )?;
            }
            Ok(())
        }),
        case("outline::fewest_bad_contours", || {
            let mut a = polygonal_a();
            a[1][2].x = f64::NAN;
            let linear = [Family::Linear];
            expect_err!(
                fewest(
                    &closed(a),
                    Tolerance::Absolute(0.01),
                    &linear,
                    &options(12),
                    &|_| {}
                ),
                Error::NonFinite { .. }
            )?;
            expect_err!(
                fewest(
                    &closed(vec![four_points()[..2].to_vec()]),
                    Tolerance::Absolute(0.01),
                    &linear,
                    &options(12),
                    &|_| {}
                ),
                Error::TooFewPoints { .. }
            )
        }),
        case("outline::fewest_polygonal_a", || {
            let s = ok(fewest(
                &closed(polygonal_a()),
                Tolerance::Absolute(0.01),
                &[Family::Linear],
                &options(20),
                &|_| {},
            ))?;
            let m = &s.methods[0];
            ensure!(m.within_tolerance() && m.error() <= 0.01, "{s:?}");
            ensure!(m.counted() == 14, "{} points", m.counted());
            Ok(())
        }),
        case("table_i::pieces_changed_index_out_of_range", || {
            let p = six_points(1.0);
            for index in [6, usize::MAX] {
                expect_err!(
                    pieces_changed(&Method::Angular, &p, false, index, v2(0.1, 0.0)),
                    Error::IndexOutOfRange { len: 6, .. }
                )?;
            }
            expect_err!(
                pieces_changed(&Method::Linear, &[], true, 0, v2(0.1, 0.0)),
                Error::IndexOutOfRange { len: 0, .. }
            )
        }),
        case("table_i::pieces_changed_sweep_non_finite_delta", || {
            sweep(2, |bad, k| {
                let mut d = [0.1, 0.1];
                d[k] = bad;
                for m in all_methods() {
                    expect_err!(
                        pieces_changed(&m, &six_points(1.0), false, 2, v2(d[0], d[1])),
                        Error::NonFinite { .. }
                    )
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", m)))?;
                }
                Ok(())
            })
        }),
        case("table_i::pieces_changed_huge_delta", || {
            expect_err!(
                pieces_changed(
                    &Method::Linear,
                    &six_points(1.0),
                    false,
                    2,
                    v2(2.0 * MAX_COORDINATE, 0.0)
                ),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("table_i::pieces_changed_zero_and_subnormal_delta", || {
            for m in all_methods() {
                let n = ok(pieces_changed(&m, &six_points(1.0), false, 2, v2(0.0, 0.0)))?;
                ensure!(
                    n == 0,
                    "{}: {n} pieces change without a move",
                    format_args!("{:?}", m)
                );
                let n = ok(pieces_changed(
                    &m,
                    &six_points(1.0),
                    true,
                    2,
                    v2(5e-324, 0.0),
                ))?;
                ensure!(
                    n == 0,
                    "{}: {n} pieces change by 5e-324",
                    format_args!("{:?}", m)
                );
            }
            Ok(())
        }),
        case("table_i::pieces_changed_angular_is_local", || {
            let p: Vec<Vector2<f64>> = (0..12)
                .map(|i| v2(i as f64, ((i * i) % 5) as f64))
                .collect();
            let n = ok(pieces_changed(&Method::Angular, &p, false, 6, v2(0.0, 0.3)))?;
            ensure!((1..=4).contains(&n), "{n} pieces");
            Ok(())
        }),
        case("table_i::pieces_changed_tiny_points", || {
            let p = six_points(1e-300);
            let n = ok(pieces_changed(
                &Method::Angular,
                &p,
                false,
                2,
                v2(1e-301, 0.0),
            ))?;
            ensure!((1..=3).contains(&n), "{n} pieces");
            Ok(())
        }),
    ]
}
