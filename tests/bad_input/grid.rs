//! grid: Grid::try_from_fn, Grid::from_vec and the Grid::from_fn shorthand

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    vec![
        risky("grid::try_from_fn_usize_max", || {
            expect_err!(
                Grid::try_from_fn(usize::MAX, 2, |_, _| -> u8 {
                    panic!("f must not be called")
                }),
                Error::TooLarge { .. }
            )
        }),
        risky("grid::try_from_fn_max_elements_plus_one", || {
            expect_err!(
                Grid::try_from_fn(MAX_ELEMENTS + 1, 1, |_, _| -> u8 { panic!("f must not be called") }),
                Error::TooLarge { got, .. } if *got == MAX_ELEMENTS + 1
            )
        }),
        risky("grid::try_from_fn_2_pow_40", || {
            expect_err!(
                Grid::try_from_fn(1 << 20, 1 << 20, |_, _| -> u8 {
                    panic!("f must not be called")
                }),
                Error::TooLarge { .. }
            )
        }),
        case("grid::from_vec_wrapping_shape", || {
            // 2³² · 2³² wraps to 0 = the length of an empty vector
            let g = Grid::<u8>::from_vec(1 << 32, 1 << 32, Vec::new());
            ensure!(g.is_none(), "a wrapping shape was accepted");
            let g = Grid::<u8>::from_vec(usize::MAX, 2, vec![0; 6]);
            ensure!(g.is_none(), "an overflowing shape was accepted");
            Ok(())
        }),
        case("grid::from_vec_length_mismatch", || {
            ensure!(
                Grid::from_vec(2, 2, vec![1u8; 3]).is_none(),
                "3 values for 2×2 accepted"
            );
            ensure!(
                Grid::from_vec(2, 2, vec![1u8; 4]).is_some(),
                "4 values for 2×2 refused"
            );
            Ok(())
        }),
        case("grid::try_from_fn_zero_rows", || {
            let g = ok(Grid::try_from_fn(0, 5, |_, _| -> u8 {
                panic!("f must not be called")
            }))?;
            ensure!(g.rows() == 0 && g.as_slice().is_empty(), "not empty");
            Ok(())
        }),
        risky("grid::from_fn_shorthand_panics_without_allocating", || {
            let r = catch_unwind(|| Grid::from_fn(usize::MAX, 2, |_, _| 0u8).rows());
            ensure!(r.is_err(), "Grid::from_fn(usize::MAX, 2) did not panic");
            Ok(())
        }),
    ]
}
