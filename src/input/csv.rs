//! Points from CSV text: one point a row, the coordinates in chosen columns.
//!
//! - **Separators**: `;` if the first row has one, else `,` if it has one, else runs of
//!   spaces or tabs; fields are trimmed. Blank lines and lines starting with `#` are skipped;
//!   a byte-order mark is ignored.
//! - **Header**: the first row is a header when one of its fields is not a number; only the
//!   first row may be one.
//! - **Columns** ([`Columns`]): the first `N` by default, or `N` chosen by index (0-based) or
//!   by header name.
//! - **Refused** with [`Error::Parse`] (line and column of the field, 1-based): a field that is
//!   not a number, NaN or infinite, or beyond [`crate::error::MAX_COORDINATE`]; a row with a
//!   different number of fields from the first data row, or too few for the columns chosen; a
//!   column name the header lacks. No rows: [`Error::TooFewPoints`]; more than
//!   [`crate::error::MAX_ELEMENTS`]: [`Error::TooLarge`].

use crate::error::{Error, Result, MAX_COORDINATE, MAX_ELEMENTS};
use nalgebra::SVector;

/// Which columns of a CSV text hold the coordinates.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum Columns {
    /// The first `N` columns.
    #[default]
    First,
    /// These columns (0-based), one per coordinate.
    Indices(Vec<usize>),
    /// The columns with these header names, one per coordinate.
    Names(Vec<String>),
}

/// What the CSV reader names in its errors.
const WHAT: &str = "CSV points";

/// A field and the (1-based, in characters) column where it starts.
type Field<'a> = (usize, &'a str);

/// The points of a CSV text (module docs), `N` coordinates each.
///
/// ```
/// use splinelab::input::{points_from_csv, Columns};
/// let text = "id;x;y\n1; 0.5; 2\n2; 1.5; -1e-3\n";
/// let p = points_from_csv::<2>(text, &Columns::Names(vec!["x".into(), "y".into()]))?;
/// assert_eq!(p[1].y, -1e-3);
/// let err = points_from_csv::<2>("0,1\n2,nan\n", &Columns::First).unwrap_err();
/// assert_eq!(err.to_string(), "CSV points, line 2, column 3: not a finite number: \"nan\"");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// As the module docs say.
pub fn points_from_csv<const N: usize>(
    text: &str,
    columns: &Columns,
) -> Result<Vec<SVector<f64, N>>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l))
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .peekable();
    let Some(&(_, first)) = rows.peek() else {
        return Err(Error::TooFewPoints {
            what: WHAT,
            needed: 1,
            got: 0,
        });
    };
    let separator = if first.contains(';') {
        Some(';')
    } else if first.contains(',') {
        Some(',')
    } else {
        None
    };
    let first_fields = split(first, separator);
    let header = first_fields.iter().any(|(_, f)| f.parse::<f64>().is_err());
    let names: Vec<&str> = if header {
        rows.next();
        first_fields.iter().map(|(_, f)| *f).collect()
    } else {
        Vec::new()
    };
    let first_line = rows.peek().map_or(1, |r| r.0);
    let picked = pick::<N>(columns, &names, first_line)?;
    let mut width = None;
    let mut out = Vec::new();
    for (line, text) in rows {
        let fields = split(text, separator);
        let expected = *width.get_or_insert(fields.len());
        let end = text.chars().count() + 1;
        if fields.len() != expected {
            return Err(parse_error(
                line,
                fields.get(expected).map_or(end, |f| f.0),
                format!("{} fields, the first row has {expected}", fields.len()),
            ));
        }
        let mut p = SVector::<f64, N>::zeros();
        for (k, &c) in picked.iter().enumerate() {
            let Some(&(column, field)) = fields.get(c) else {
                return Err(parse_error(
                    line,
                    end,
                    format!(
                        "{} fields, column {} is asked for",
                        fields.len(),
                        c.saturating_add(1)
                    ),
                ));
            };
            p[k] = number(field, line, column)?;
        }
        if out.len() == MAX_ELEMENTS {
            return Err(Error::TooLarge {
                what: "CSV points",
                got: MAX_ELEMENTS + 1,
                max: MAX_ELEMENTS,
            });
        }
        out.push(p);
    }
    if out.is_empty() {
        return Err(Error::TooFewPoints {
            what: WHAT,
            needed: 1,
            got: 0,
        });
    }
    Ok(out)
}

/// The fields of a row: split at `separator` (trimmed), or at runs of blanks.
fn split<'a>(row: &'a str, separator: Option<char>) -> Vec<Field<'a>> {
    let mut out = Vec::new();
    let mut start: Option<(usize, usize)> = None; // (byte, column) of the field's start
    let mut column = 0;
    let push = |from: usize, col: usize, to: usize, out: &mut Vec<Field<'a>>| {
        let raw = &row[from..to];
        let lead = raw.len() - raw.trim_start().len();
        let skipped = raw[..lead].chars().count();
        out.push((col + skipped, raw.trim()));
    };
    for (byte, ch) in row.char_indices() {
        column += 1;
        match separator {
            Some(sep) => {
                let (from, col) = *start.get_or_insert((byte, column));
                if ch == sep {
                    push(from, col, byte, &mut out);
                    start = None;
                }
            }
            None => {
                if ch.is_whitespace() {
                    if let Some((from, col)) = start.take() {
                        push(from, col, byte, &mut out);
                    }
                } else {
                    start.get_or_insert((byte, column));
                }
            }
        }
    }
    match (separator, start) {
        (_, Some((from, col))) => push(from, col, row.len(), &mut out),
        // a separated row ending in its separator has an empty last field
        (Some(_), None) => push(row.len(), column + 1, row.len(), &mut out),
        (None, None) => {}
    }
    out
}

/// The 0-based columns of the `N` coordinates.
fn pick<const N: usize>(columns: &Columns, names: &[&str], line: usize) -> Result<Vec<usize>> {
    let picked: Vec<usize> = match columns {
        Columns::First => (0..N).collect(),
        Columns::Indices(k) => k.clone(),
        Columns::Names(wanted) => {
            if names.is_empty() {
                return Err(parse_error(
                    line,
                    1,
                    "columns chosen by name, but the first row is not a header".into(),
                ));
            }
            wanted
                .iter()
                .map(|w| {
                    names.iter().position(|n| n == w).ok_or_else(|| {
                        parse_error(
                            line.saturating_sub(1).max(1),
                            1,
                            format!("the header has no column {w:?} (it has {names:?})"),
                        )
                    })
                })
                .collect::<Result<_>>()?
        }
    };
    if picked.len() != N {
        return Err(Error::CountMismatch {
            what: "CSV columns chosen (one per coordinate)",
            expected: N,
            got: picked.len(),
        });
    }
    Ok(picked)
}

/// A field as a finite number within [`MAX_COORDINATE`].
fn number(field: &str, line: usize, column: usize) -> Result<f64> {
    match field.parse::<f64>() {
        Ok(x) if x.is_finite() && x.abs() <= MAX_COORDINATE => Ok(x),
        Ok(x) if x.is_finite() => Err(parse_error(
            line,
            column,
            format!("{field:?} is beyond the largest coordinate, {MAX_COORDINATE:e}"),
        )),
        Ok(_) => Err(parse_error(
            line,
            column,
            format!("not a finite number: {field:?}"),
        )),
        Err(_) => Err(parse_error(
            line,
            column,
            format!("not a number: {field:?}"),
        )),
    }
}

fn parse_error(line: usize, column: usize, message: String) -> Error {
    Error::Parse {
        what: WHAT,
        line,
        column,
        message,
    }
}
