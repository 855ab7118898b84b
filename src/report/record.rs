//! Tables from records: a row is a struct, one field per column, and the one place that turns
//! fields into columns is the [`Record`] implementation that [`record!`](crate::record) writes
//! beside the struct (as polars' `df!` names each column once).
//!
//! ```
//! splinelab::record! {
//!     /// One knot vector of a table.
//!     #[derive(Debug, Clone)]
//!     pub struct Row {
//!         /// What it is.
//!         pub example: String => "example",
//!         /// Its degree.
//!         pub degree: u32 => "degree",
//!         /// Whether it is open.
//!         pub open: bool => "open",
//!     }
//! }
//! let rows = [
//!     Row { example: "cubic".into(), degree: 3, open: true },
//!     Row { example: "quadratic".into(), degree: 2, open: false },
//! ];
//! let frame = splinelab::report::record::frame_of("knots", &rows)?;
//! assert_eq!(frame.height(), 2);
//! assert_eq!(frame.names(), ["example", "degree", "open"]);
//! # Ok::<(), splinelab::report::Error>(())
//! ```

use crate::report::error::Result;
use crate::report::frame::{Column, Frame};

/// A table row: its fields as the columns of a slice of rows, in field order.
pub trait Record: Sized {
    /// One column per field, one value per row.
    fn columns(rows: &[Self]) -> Vec<Column>;
}

/// The frame of `rows` (one row each), named `id` in its errors.
///
/// # Errors
/// [`crate::report::Error::Table`] if two fields share a column name.
pub fn frame_of<R: Record>(id: &str, rows: &[R]) -> Result<Frame> {
    crate::report::table::frame(id, R::columns(rows))
}

/// Declares a row struct and its [`Record`] implementation: each field with the name of its
/// column (`field: Type => "column"`). A field's type is any whose vector makes a column
/// (numbers, integers, flags, text, and their `Option`s for missing cells) and that is `Clone`.
#[macro_export]
macro_rules! record {
    (
        $(#[$meta:meta])*
        $vis:vis struct $name:ident {
            $($(#[$field_meta:meta])* $field_vis:vis $field:ident : $ty:ty => $column:expr),* $(,)?
        }
    ) => {
        $(#[$meta])*
        $vis struct $name {
            $($(#[$field_meta])* $field_vis $field: $ty),*
        }

        impl $crate::report::record::Record for $name {
            fn columns(rows: &[Self]) -> Vec<$crate::report::frame::Column> {
                vec![$(
                    $crate::report::frame::Column::new(
                        ::std::string::String::from($column),
                        rows.iter().map(|r| r.$field.clone()).collect::<Vec<$ty>>(),
                    )
                ),*]
            }
        }
    };
}
