//! The data of a table: named columns of equal length, each of one kind of value (numbers,
//! integers, flags or text), any cell possibly missing.
//!
//! The report layer builds every table on this small type rather than on a polars
//! `DataFrame` so that a notebook kernel can load tables and figures without polars (about
//! a hundred crates that the kernel's type analysis, cargo and linker would otherwise pay
//! for in every cell). With the `polars` feature, `Frame::to_polars` and
//! `Frame::try_from(&DataFrame)` convert both ways, so a table is one call from polars'
//! queries and any DataFrame can be written as Markdown, HTML or CSV by
//! [`crate::report::table`](mod@crate::report::table).

use std::fmt;

/// A frame from columns, a [`FrameError`] as [`crate::report::Error::Table`] naming the table.
///
/// # Errors
/// [`crate::report::Error::Table`] if the columns differ in length or repeat a name.
pub fn frame(name: &str, columns: Vec<Column>) -> crate::report::error::Result<Frame> {
    Frame::try_new(columns).map_err(|e| crate::report::error::Error::Table {
        name: name.to_string(),
        message: e.to_string(),
    })
}

/// One column's values: one vector per kind, `None` for a missing cell.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// Floating-point numbers.
    Float(Vec<Option<f64>>),
    /// Signed integers.
    Int(Vec<Option<i64>>),
    /// Unsigned integers.
    UInt(Vec<Option<u64>>),
    /// Yes/no flags.
    Bool(Vec<Option<bool>>),
    /// Text.
    Text(Vec<Option<String>>),
}

/// One cell of a [`Column`], borrowed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell<'a> {
    /// A missing value.
    Null,
    /// A floating-point number.
    Float(f64),
    /// A signed integer.
    Int(i64),
    /// An unsigned integer.
    UInt(u64),
    /// A flag.
    Bool(bool),
    /// Text.
    Text(&'a str),
}

impl Values {
    /// The number of cells.
    pub fn len(&self) -> usize {
        match self {
            Values::Float(v) => v.len(),
            Values::Int(v) => v.len(),
            Values::UInt(v) => v.len(),
            Values::Bool(v) => v.len(),
            Values::Text(v) => v.len(),
        }
    }

    /// No cells.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Cell `i`, `None` past the end.
    pub fn get(&self, i: usize) -> Option<Cell<'_>> {
        fn or_null<T: Copy>(
            v: &[Option<T>],
            i: usize,
            f: fn(T) -> Cell<'static>,
        ) -> Option<Cell<'static>> {
            v.get(i).map(|c| c.map_or(Cell::Null, f))
        }
        match self {
            Values::Float(v) => or_null(v, i, Cell::Float),
            Values::Int(v) => or_null(v, i, Cell::Int),
            Values::UInt(v) => or_null(v, i, Cell::UInt),
            Values::Bool(v) => or_null(v, i, Cell::Bool),
            Values::Text(v) => v
                .get(i)
                .map(|c| c.as_deref().map_or(Cell::Null, Cell::Text)),
        }
    }
}

/// `From<Vec<T>>` and `From<Vec<Option<T>>>` for the column kinds, each element converted
/// without loss (`usize` and `u32` widen to `u64`, `i32` to `i64`).
macro_rules! values_from {
    ($variant:ident: $($t:ty => $conv:expr),* $(,)?) => {$(
        impl From<Vec<$t>> for Values {
            fn from(v: Vec<$t>) -> Self {
                Values::$variant(v.into_iter().map(|x| Some($conv(x))).collect())
            }
        }
        impl From<Vec<Option<$t>>> for Values {
            fn from(v: Vec<Option<$t>>) -> Self {
                Values::$variant(v.into_iter().map(|x| x.map($conv)).collect())
            }
        }
    )*};
}
values_from!(Float: f64 => |x: f64| x);
values_from!(Int: i64 => |x: i64| x, i32 => i64::from);
values_from!(UInt: u64 => |x: u64| x, u32 => u64::from, usize => |x: usize| x as u64);
values_from!(Bool: bool => |x: bool| x);
values_from!(
    Text: String => |x: String| x,
    &str => |x: &str| x.to_string(),
    std::borrow::Cow<'_, str> => std::borrow::Cow::into_owned,
);

/// A named column.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    name: String,
    values: Values,
}

impl Column {
    /// A column named `name` holding `values` (a `Vec` of numbers, integers, flags or text,
    /// with or without `Option`).
    pub fn new(name: String, values: impl Into<Values>) -> Self {
        Self {
            name,
            values: values.into(),
        }
    }

    /// The column's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The values.
    pub fn values(&self) -> &Values {
        &self.values
    }

    /// The number of cells.
    pub fn len(&self) -> usize {
        self.values.len()
    }

    /// No cells.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// Cell `i`, `None` past the end.
    pub fn get(&self, i: usize) -> Option<Cell<'_>> {
        self.values.get(i)
    }

    /// The numbers of a floating-point column (`None` for another kind).
    pub fn f64(&self) -> Option<&[Option<f64>]> {
        match &self.values {
            Values::Float(v) => Some(v),
            _ => None,
        }
    }

    /// The text of a text column (`None` for another kind).
    pub fn text(&self) -> Option<&[Option<String>]> {
        match &self.values {
            Values::Text(v) => Some(v),
            _ => None,
        }
    }
}

/// Why columns do not make a [`Frame`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FrameError {
    /// Two columns differ in length.
    #[error("column `{name}` has {len} rows where `{first}` has {height}")]
    Ragged {
        /// The first column.
        first: String,
        /// Its length.
        height: usize,
        /// The column that differs.
        name: String,
        /// Its length.
        len: usize,
    },
    /// Two columns share a name.
    #[error("column name `{0}` appears twice")]
    DuplicateName(String),
}

/// Named columns of equal length: the data of a [`crate::report::Table`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Frame {
    columns: Vec<Column>,
}

impl Frame {
    /// The columns as a frame.
    ///
    /// # Errors
    /// [`FrameError::Ragged`] if two columns differ in length, [`FrameError::DuplicateName`]
    /// if two share a name.
    pub fn try_new(columns: Vec<Column>) -> Result<Self, FrameError> {
        if let Some(first) = columns.first() {
            if let Some(c) = columns.iter().find(|c| c.len() != first.len()) {
                return Err(FrameError::Ragged {
                    first: first.name.clone(),
                    height: first.len(),
                    name: c.name.clone(),
                    len: c.len(),
                });
            }
        }
        let mut names: Vec<&str> = columns.iter().map(|c| c.name.as_str()).collect();
        names.sort_unstable();
        if let Some(w) = names.windows(2).find(|w| w[0] == w[1]) {
            return Err(FrameError::DuplicateName(w[0].to_string()));
        }
        Ok(Self { columns })
    }

    /// The number of rows.
    pub fn height(&self) -> usize {
        self.columns.first().map_or(0, Column::len)
    }

    /// The number of columns.
    pub fn width(&self) -> usize {
        self.columns.len()
    }

    /// `(height, width)`.
    pub fn shape(&self) -> (usize, usize) {
        (self.height(), self.width())
    }

    /// The columns in order.
    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// The column called `name`.
    pub fn column(&self, name: &str) -> Option<&Column> {
        self.columns.iter().find(|c| c.name == name)
    }

    /// The column names in order.
    pub fn names(&self) -> Vec<&str> {
        self.columns.iter().map(Column::name).collect()
    }
}

impl fmt::Display for Frame {
    /// Tab-separated: the names, then one line per row (cells as `Debug`-free text).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{}", self.names().join("\t"))?;
        for i in 0..self.height() {
            let row: Vec<String> = self
                .columns
                .iter()
                .map(|c| c.get(i).map_or_else(String::new, |v| v.to_string()))
                .collect();
            writeln!(f, "{}", row.join("\t"))?;
        }
        Ok(())
    }
}

impl fmt::Display for Cell<'_> {
    /// Numbers as Rust prints them, a missing cell as nothing.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Cell::Null => Ok(()),
            Cell::Float(x) => write!(f, "{x}"),
            Cell::Int(x) => write!(f, "{x}"),
            Cell::UInt(x) => write!(f, "{x}"),
            Cell::Bool(x) => write!(f, "{x}"),
            Cell::Text(x) => f.write_str(x),
        }
    }
}

#[cfg(feature = "polars")]
mod polars_conversions {
    use super::{Column, Frame, Values};
    use polars::prelude::{AnyValue, Column as PlColumn, DataFrame, DataType, PolarsError};

    impl Frame {
        /// The frame as a polars `DataFrame` (feature `polars`): floats as `Float64`,
        /// integers as `Int64`/`UInt64`, flags as `Boolean`, text as `String`, missing cells
        /// as nulls.
        ///
        /// # Errors
        /// Only if polars refuses the columns (it cannot: a frame's columns have one length
        /// and distinct names).
        pub fn to_polars(&self) -> Result<DataFrame, PolarsError> {
            let columns = self
                .columns
                .iter()
                .map(|c| {
                    let name = c.name.as_str().into();
                    match &c.values {
                        Values::Float(v) => PlColumn::new(name, v),
                        Values::Int(v) => PlColumn::new(name, v),
                        Values::UInt(v) => PlColumn::new(name, v),
                        Values::Bool(v) => PlColumn::new(name, v),
                        Values::Text(v) => PlColumn::new(name, v),
                    }
                })
                .collect();
            DataFrame::new_infer_height(columns)
        }
    }

    impl TryFrom<&DataFrame> for Frame {
        type Error = PolarsError;

        /// Any DataFrame as a frame: float, integer, boolean and string columns keep their
        /// kind (from the column's type, so an all-null column keeps it too); a column of
        /// another type (dates, lists…) becomes text as polars prints it.
        fn try_from(df: &DataFrame) -> Result<Self, PolarsError> {
            let columns = df
                .columns()
                .iter()
                .map(|c| {
                    let cells = (0..df.height())
                        .map(|i| c.get(i))
                        .collect::<Result<Vec<_>, _>>()?;
                    Ok(Column::new(
                        c.name().to_string(),
                        values_of(c.dtype(), &cells),
                    ))
                })
                .collect::<Result<Vec<_>, PolarsError>>()?;
            Ok(Frame { columns })
        }
    }

    /// The cells of one polars column of type `dtype` as the [`Values`] of that kind.
    fn values_of(dtype: &DataType, cells: &[AnyValue]) -> Values {
        fn pick<T>(cells: &[AnyValue], get: impl Fn(&AnyValue) -> Option<T>) -> Vec<Option<T>> {
            cells.iter().map(get).collect()
        }
        if dtype.is_float() {
            Values::Float(pick(cells, |v| v.extract::<f64>()))
        } else if dtype.is_signed_integer() {
            Values::Int(pick(cells, |v| v.extract::<i64>()))
        } else if dtype.is_unsigned_integer() {
            Values::UInt(pick(cells, |v| v.extract::<u64>()))
        } else if dtype.is_bool() {
            Values::Bool(pick(cells, |v| match v {
                AnyValue::Boolean(b) => Some(*b),
                _ => None,
            }))
        } else {
            Values::Text(pick(cells, |v| match v {
                AnyValue::Null => None,
                AnyValue::String(s) => Some(s.to_string()),
                AnyValue::StringOwned(s) => Some(s.to_string()),
                other => Some(other.to_string()),
            }))
        }
    }
}
