//! domain: Interval, Rect, Partition

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(interval_and_rect_cases());
    all.extend(partition_cases());
    all
}

/// `Interval` and `Rect`.
fn interval_and_rect_cases() -> Vec<Case> {
    vec![
        case(
            "domain::interval_nan_start",
            || expect_err!(Interval::try_new(f64::NAN, 1.0), Error::NonFinite { value, .. } if value.is_nan()),
        ),
        case(
            "domain::interval_pos_inf_end",
            || expect_err!(Interval::try_new(0.0, f64::INFINITY), Error::NonFinite { value, .. } if *value == f64::INFINITY),
        ),
        case(
            "domain::interval_neg_inf_start",
            || expect_err!(Interval::try_new(f64::NEG_INFINITY, 0.0), Error::NonFinite { value, .. } if *value == f64::NEG_INFINITY),
        ),
        case(
            "domain::interval_empty",
            || expect_err!(Interval::try_new(1.0, 1.0), Error::EmptyInterval { start, end, .. } if *start == 1.0 && *end == 1.0),
        ),
        case("domain::interval_decreasing", || {
            expect_err!(Interval::try_new(2.0, 1.0), Error::EmptyInterval { .. })
        }),
        case(
            "domain::interval_width_overflows",
            || expect_err!(Interval::try_new(-1e308, 1e308), Error::Overflow { value, .. } if value.is_infinite()),
        ),
        case("domain::interval_subnormal_width", || {
            expect_err!(Interval::try_new(0.0, 1e-310), Error::GapTooSmall { .. })
        }),
        case("domain::interval_linspace_too_few", || {
            let i = ok(Interval::try_new(0.0, 1.0))?;
            expect_err!(i.linspace(1), Error::TooFewSamples { got: 1, .. })?;
            expect_err!(i.linspace(0), Error::TooFewSamples { got: 0, .. })
        }),
        risky("domain::interval_linspace_usize_max", || {
            let i = ok(Interval::try_new(0.0, 1.0))?;
            expect_err!(i.linspace(usize::MAX), Error::TooLarge { .. })
        }),
        risky("domain::interval_linspace_max_elements_plus_one", || {
            let i = ok(Interval::try_new(0.0, 1.0))?;
            expect_err!(i.linspace(MAX_ELEMENTS + 1), Error::TooLarge { got, .. } if *got == MAX_ELEMENTS + 1)
        }),
        case("domain::interval_linspace_ends_exact", || {
            let i = ok(Interval::try_new(0.1, 0.7))?;
            let v = ok(i.linspace(8))?;
            ensure!(v[0] == 0.1 && v[7] == 0.7, "ends not exact: {v:?}");
            Ok(())
        }),
        case("domain::rect_nan_bound", || {
            expect_err!(
                Rect::try_new(0.0, 1.0, f64::NAN, 1.0),
                Error::NonFinite { .. }
            )
        }),
        case(
            "domain::rect_empty_t_side",
            || expect_err!(Rect::try_new(0.0, 1.0, 2.0, 1.0), Error::EmptyInterval { what, .. } if what.contains('t')),
        ),
        case("domain::rect_width_overflows", || {
            expect_err!(
                Rect::try_new(-1e308, 1e308, 0.0, 1.0),
                Error::Overflow { .. }
            )
        }),
        case("domain::rect_square_infinite", || {
            expect_err!(Rect::square(0.0, f64::INFINITY), Error::NonFinite { .. })
        }),
        case("domain::rect_subnormal_side", || {
            expect_err!(
                Rect::try_new(0.0, 1.0, 0.0, 1e-310),
                Error::GapTooSmall { .. }
            )
        }),
    ]
}

/// `Partition`; NaN, ±inf in every input of the area.
fn partition_cases() -> Vec<Case> {
    vec![
        case("domain::partition_empty", || {
            expect_err!(
                Partition::try_new(vec![]),
                Error::PartitionTooShort { got: 0, .. }
            )
        }),
        case("domain::partition_single_node", || {
            expect_err!(
                Partition::try_new(vec![0.5]),
                Error::PartitionTooShort { got: 1, .. }
            )
        }),
        case("domain::partition_nan_node", || {
            expect_err!(
                Partition::try_new(vec![0.0, f64::NAN, 1.0]),
                Error::NonFinite { .. }
            )
        }),
        case("domain::partition_inf_node", || {
            expect_err!(
                Partition::try_new(vec![0.0, 1.0, f64::INFINITY]),
                Error::NonFinite { .. }
            )
        }),
        case("domain::partition_repeated_node", || {
            expect_err!(
                Partition::try_new(vec![0.0, 0.5, 0.5, 1.0]),
                Error::RepeatedParameter { index: 2, .. }
            )
        }),
        case("domain::partition_decreasing", || {
            expect_err!(
                Partition::try_new(vec![0.0, 1.0, 0.9]),
                Error::NotIncreasing { index: 2, .. }
            )
        }),
        case("domain::partition_subnormal_gap", || {
            expect_err!(
                Partition::try_new(vec![0.0, 1e-310, 1.0]),
                Error::GapTooSmall { index: 1, .. }
            )
        }),
        case("domain::partition_total_width_overflows", || {
            expect_err!(
                Partition::try_new(vec![-1e308, 0.0, 1e308]),
                Error::Overflow { .. }
            )
        }),
        case("domain::partition_uniform_zero", || {
            expect_err!(Partition::uniform(0.0, 1.0, 0), Error::ZeroPatches { .. })
        }),
        risky("domain::partition_uniform_usize_max", || {
            expect_err!(
                Partition::uniform(0.0, 1.0, usize::MAX),
                Error::TooLarge { .. }
            )
        }),
        risky("domain::partition_uniform_max_elements", || {
            expect_err!(
                Partition::uniform(0.0, 1.0, MAX_ELEMENTS),
                Error::TooLarge { .. }
            )
        }),
        case("domain::partition_uniform_unresolvable_width", || {
            expect_err!(
                Partition::uniform(1.0, 1.0 + f64::EPSILON, 4),
                Error::RepeatedParameter { .. }
                    | Error::NotIncreasing { .. }
                    | Error::GapTooSmall { .. }
            )
        }),
        case("domain::partition_uniform_subnormal_steps", || {
            expect_err!(
                Partition::uniform(0.0, 1e-307, 1000),
                Error::RepeatedParameter { .. }
                    | Error::NotIncreasing { .. }
                    | Error::GapTooSmall { .. }
            )
        }),
        case("domain::partition_uniform_width_overflows", || {
            expect_err!(Partition::uniform(-1e308, 1e308, 2), Error::Overflow { .. })
        }),
        case("domain::partition_uniform_nan", || {
            expect_err!(
                Partition::uniform(f64::NAN, 1.0, 3),
                Error::NonFinite { .. }
            )
        }),
        case("domain::partition_right_end_in_last_piece", || {
            let p = ok(Partition::try_new(vec![0.0, 0.5, 1.0]))?;
            ensure!(p.locate(1.0) == 1, "right end in piece {}", p.locate(1.0));
            ensure!(
                p.locate(0.5) == 1,
                "interior node in piece {}",
                p.locate(0.5)
            );
            Ok(())
        }),
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
    ]
}
