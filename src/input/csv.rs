//! Points from CSV text: one point a row, the coordinates in chosen columns. The text is read
//! by BurntSushi's [`csv`] reader (quoted fields, escaped quotes, fields spanning lines);
//! this module decides the separator, the header and the columns, and places every refusal.
//!
//! - **Separators**: `;`, `,`, a tab or runs of blanks, the first that splits the first rows
//!   (outside quotes) into the same number of fields; else `;` or `,` if the first row has
//!   one; else runs of spaces or tabs. Fields are trimmed; a row may end with its separator (trailing empty
//!   fields are not fields). Blank lines and lines starting with `#` are skipped; a
//!   byte-order mark is ignored; line ends may be `\n` or `\r\n`.
//! - **Header**: the first row is a header when none of its fields is a number (`x,y`,
//!   `"lon";"lat"`); a row with a number in it is data, and a field of it that is not a number
//!   is refused, not taken for a name. Only the first row may be a header.
//! - **Columns** ([`Columns`]): the first `N` by default, or `N` chosen by index (0-based) or
//!   by header name.
//! - **Refused** with [`Error::Parse`] (line and column of the field, 1-based, in characters):
//!   a field that is not a number (a decimal comma included: the message says so), NaN or
//!   infinite, or beyond [`crate::error::MAX_COORDINATE`]; a row with a different number of
//!   fields from the first data row, or too few for the columns chosen; a column name the
//!   header lacks; a quote left open. No rows: [`Error::TooFewPoints`]; more than
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

/// A field's text and its (1-based) line and column.
type Field<'a> = (&'a str, (usize, usize));

/// The points of a CSV text (module docs), `N` coordinates each.
///
/// ```
/// use splinelab::input::{points_from_csv, Columns};
/// let text = "id;x;y\n1; 0.5; 2\n2; \"1.5\"; -1e-3\n";
/// let p = points_from_csv::<2>(text, &Columns::Names(vec!["x".into(), "y".into()]))?;
/// assert_eq!(p[1].y, -1e-3);
/// // a trailing separator is no field, and a row of numbers no header
/// assert_eq!(points_from_csv::<2>("1,2,\n3,4,\n", &Columns::First)?.len(), 2);
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
    let rows: Vec<&str> = text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .take(SNIFFED_ROWS)
        .collect();
    if rows.is_empty() {
        return Err(no_rows());
    }
    let separator = separator_of(&rows);
    // blanks: runs of spaces or tabs, read as spaces (one character each, so columns hold)
    let spaced;
    let source = if separator.is_none() && text.contains('\t') {
        spaced = text.replace('\t', " ");
        spaced.as_str()
    } else {
        text
    };
    let delimiter = separator.unwrap_or(b' ');
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .delimiter(delimiter)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(source.as_bytes());
    let mut record = csv::StringRecord::new();
    let mut picked: Option<Vec<usize>> = None;
    let mut names: Vec<String> = Vec::new();
    let mut width = None;
    let mut first_row = true;
    let mut out = Vec::new();
    // the line of byte `counted` (lines are counted here: the reader's count skips blank ones)
    let (mut counted, mut counted_line) = (0usize, 1usize);
    loop {
        match reader.read_record(&mut record) {
            Ok(true) => {}
            Ok(false) => break,
            Err(e) => return Err(csv_error(source, counted, counted_line, &e)),
        }
        let Some(position) = record.position() else {
            continue;
        };
        // the record's first byte, past line ends the reader puts before it
        let mut byte = (position.byte() as usize).min(source.len());
        byte += source[byte..].len() - source[byte..].trim_start_matches(['\r', '\n']).len();
        counted_line += source.as_bytes()[counted.min(byte)..byte]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        counted = counted.max(byte);
        let line = counted_line;
        let places = field_places(source, byte, line, delimiter);
        let unquoted: Vec<std::borrow::Cow<str>> = record.iter().map(unquote).collect();
        let mut fields: Vec<Field> = unquoted
            .iter()
            .enumerate()
            .map(|(k, f)| (f.as_ref(), places.get(k).copied().unwrap_or((line, 1))))
            .collect();
        if separator.is_none() {
            // runs of blanks make empty fields between them
            fields.retain(|(f, _)| !f.is_empty());
        }
        while fields.last().is_some_and(|(f, _)| f.is_empty()) {
            fields.pop();
        }
        if fields.is_empty() || fields[0].0.starts_with('#') {
            continue;
        }
        let end = (line, last_column(source, byte));
        if std::mem::take(&mut first_row) && fields.iter().all(|(f, _)| f.parse::<f64>().is_err()) {
            names = fields.iter().map(|(f, _)| f.to_string()).collect();
            continue;
        }
        let picked = match &picked {
            Some(p) => p,
            None => picked.insert(pick::<N>(columns, &names, line)?),
        };
        let expected = *width.get_or_insert(fields.len());
        if fields.len() != expected {
            let (l, c) = fields.get(expected).map_or(end, |f| f.1);
            return Err(parse_error(
                l,
                c,
                format!("{} fields, the first row has {expected}", fields.len()),
            ));
        }
        let mut p = SVector::<f64, N>::zeros();
        for (k, &c) in picked.iter().enumerate() {
            let Some(&(field, (l, column))) = fields.get(c) else {
                return Err(parse_error(
                    end.0,
                    end.1,
                    format!(
                        "{} fields, column {} is asked for",
                        fields.len(),
                        c.saturating_add(1)
                    ),
                ));
            };
            p[k] = number(field, l, column)?;
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
        return Err(no_rows());
    }
    Ok(out)
}

/// How many rows decide the separator.
const SNIFFED_ROWS: usize = 8;

/// The separator of a text whose first rows are `rows`: the first of `;`, `,`, a tab and runs
/// of blanks (`None`) that splits every row outside quotes into the same number (two or more)
/// of fields; failing that, the first of `;`, `,` the first row has outside quotes; else
/// blanks.
fn separator_of(rows: &[&str]) -> Option<u8> {
    let counts = |sep: Option<char>| -> Vec<usize> {
        rows.iter().map(|r| fields_outside_quotes(r, sep)).collect()
    };
    let consistent = [Some(';'), Some(','), Some('\t'), None]
        .into_iter()
        .find(|&sep| {
            let c = counts(sep);
            c[0] >= 2 && c.iter().all(|&k| k == c[0])
        });
    let first_has = || {
        [Some(';'), Some(',')]
            .into_iter()
            .find(|&sep| fields_outside_quotes(rows[0], sep) >= 2)
    };
    consistent.or_else(first_has).flatten().map(|c| c as u8)
}

/// The fields of `row` split at `sep` (or at runs of blanks) outside quotes, a trailing
/// separator not counted.
fn fields_outside_quotes(row: &str, sep: Option<char>) -> usize {
    let mut quoted = false;
    let mut count = 0;
    let mut in_field = false;
    for c in row.trim_end_matches([' ', '\t', '\r']).chars() {
        if c == '"' {
            quoted = !quoted;
        }
        if quoted {
            in_field = true;
            continue;
        }
        let splits = match sep {
            Some(s) => c == s,
            None => c == ' ' || c == '\t',
        };
        if splits {
            if in_field || sep.is_some() {
                count += 1;
            }
            in_field = false;
        } else if !c.is_whitespace() || sep.is_some() {
            in_field = true;
        }
    }
    count + usize::from(in_field)
}

/// A field quoted after blanks (`x, "y"`: the reader takes a quote for a quote only at a
/// field's first character) without its quotes, doubled quotes made single.
fn unquote(field: &str) -> std::borrow::Cow<'_, str> {
    match field.strip_prefix('"').and_then(|f| f.strip_suffix('"')) {
        Some(inner) => std::borrow::Cow::Owned(inner.replace("\"\"", "\"")),
        None => std::borrow::Cow::Borrowed(field),
    }
}

fn no_rows() -> Error {
    Error::TooFewPoints {
        what: WHAT,
        needed: 1,
        got: 0,
    }
}

/// The line and column where each field of the record starting at byte `start` (on `line`)
/// begins: its first character after blanks (a quoted field's opening quote). Only places
/// are found here; the fields' values are the reader's.
fn field_places(source: &str, start: usize, line: usize, delimiter: u8) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let (mut line, mut column) = (line, 0usize);
    let mut field: Option<(usize, usize)> = None;
    let mut quoted = false;
    let mut chars = source[start.min(source.len())..].chars().peekable();
    while let Some(ch) = chars.next() {
        column += 1;
        if quoted {
            match ch {
                '"' if chars.peek() == Some(&'"') => {
                    chars.next();
                    column += 1;
                }
                '"' => quoted = false,
                '\n' => {
                    line += 1;
                    column = 0;
                }
                _ => {}
            }
            continue;
        }
        match ch {
            '\n' => break,
            c if c == char::from(delimiter) => {
                out.push(field.take().unwrap_or((line, column)));
            }
            ' ' | '\t' | '\r' => {}
            c => {
                if field.is_none() {
                    field = Some((line, column));
                    quoted = c == '"';
                }
            }
        }
    }
    out.push(field.unwrap_or((line, column + 1)));
    out
}

/// The column just after the last character of the line starting at byte `start`.
fn last_column(source: &str, start: usize) -> usize {
    let rest = &source[start.min(source.len())..];
    let line = rest.split('\n').next().unwrap_or("");
    line.trim_end_matches('\r').chars().count() + 1
}

/// A reader error (a quote left open, bytes that are not UTF-8) placed at its line: that of
/// byte `counted` (`counted_line`) advanced to the error's byte.
fn csv_error(source: &str, counted: usize, counted_line: usize, e: &csv::Error) -> Error {
    let byte = e
        .position()
        .map_or(source.len(), |p| p.byte() as usize)
        .clamp(counted.min(source.len()), source.len());
    let line = counted_line
        + source.as_bytes()[counted.min(byte)..byte]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
    parse_error(line, 1, format!("the CSV reader stops here: {e}"))
}

/// The 0-based columns of the `N` coordinates.
fn pick<const N: usize>(columns: &Columns, names: &[String], line: usize) -> Result<Vec<usize>> {
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
        Err(_) if field.contains('\n') => Err(parse_error(
            line,
            column,
            format!("a quoted field runs on over lines, {field:?}: a quote left open?"),
        )),
        Err(_) if field.contains(',') && field.replace(',', ".").parse::<f64>().is_ok() => {
            Err(parse_error(
                line,
                column,
                format!("not a number: {field:?} (a decimal comma: write a point, or separate the fields with another character)"),
            ))
        }
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
