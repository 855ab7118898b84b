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
    crate::report::frame::frame(id, R::columns(rows))
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

#[cfg(test)]
mod tests {
    use super::frame_of;
    use crate::report::frame::Cell;

    crate::record! {
        /// A probe row.
        #[derive(Clone)]
        struct Probe {
            name: &'static str => "name",
            value: Option<f64> => "value",
            count: usize => "count",
        }
    }

    crate::record! {
        /// Two fields naming one column.
        struct Clash {
            a: f64 => "x",
            b: f64 => "x",
        }
    }

    #[test]
    fn fields_become_columns_in_order_with_their_kinds() {
        let rows = [
            Probe {
                name: "a",
                value: Some(0.5),
                count: 3,
            },
            Probe {
                name: "b",
                value: None,
                count: usize::MAX,
            },
        ];
        let f = frame_of("probe", &rows).unwrap();
        assert_eq!(f.names(), ["name", "value", "count"]);
        assert_eq!(f.height(), 2);
        let cell = |name: &str, i: usize| f.column(name).and_then(|c| c.get(i));
        assert_eq!(cell("name", 1), Some(Cell::Text("b")));
        assert_eq!(cell("value", 0), Some(Cell::Float(0.5)));
        assert_eq!(cell("value", 1), Some(Cell::Null));
        assert_eq!(cell("count", 1), Some(Cell::UInt(u64::MAX)));
        // no rows: the columns, empty
        let empty = frame_of::<Probe>("probe", &[]).unwrap();
        assert_eq!((empty.width(), empty.height()), (3, 0));
    }

    #[test]
    fn two_fields_with_one_column_name_are_a_typed_error() {
        let err = frame_of("clash", &[Clash { a: 1.0, b: 2.0 }]).unwrap_err();
        assert!(matches!(err, crate::report::Error::Table { ref name, .. } if name == "clash"));
    }
}
