//! Points from CSV text: one point a row, the coordinates in chosen columns. The text is read
//! by the grammar of BurntSushi's CSV reader ([`csv_core`], the engine of the `csv` crate):
//! quoted fields, doubled quotes, fields spanning lines, line ends `\n`, `\r\n` or `\r`,
//! comment lines starting with `#`, blank lines skipped. (The reader ends a comment at `\n`
//! alone: it is handed a lone `\r` as `\n`, every byte in its place.) The reader hands over one field at a
//! time: memory in proportion to the longest field, not to the text or a record.
//!
//! - **Separators**: the first of `;`, `,`, a tab, a space and runs of blanks that splits the
//!   first rows (as the reader reads them) into the same number of fields, two or more; else
//!   `;` or `,` if the first row has one; else runs of blanks. Fields are trimmed of blanks;
//!   a row may end with its separator (trailing empty fields are not fields). With runs of
//!   blanks, the empty fields between blanks are not fields (an empty quoted one is).
//! - **Header**: the first row is a header when none of its fields is a number (`x,y`,
//!   `"lon";"lat"`, ` w x` as pandas writes an index without a name: its first name empty);
//!   a row with a number in it is data, and a field of it that is not a number is refused,
//!   not taken for a name. Names are kept as written, empty and quoted ones included. A header
//!   has as many names as the rows have fields, or one fewer: then its names are those of
//!   the last columns and the first column, unnamed, is an index (pandas' rule); any other
//!   width is refused.
//! - **Columns** ([`Columns`]): the first `N` by default, or `N` chosen by index (0-based) or
//!   by header name.
//! - **Refused** with [`Error::Parse`] (line and column of the field, 1-based, in characters;
//!   a message quotes at most [`QUOTED_CHARS`] characters of a field): a field that is not a
//!   number (a decimal comma included: the message says so), NaN or infinite, or beyond
//!   [`crate::error::MAX_COORDINATE`]; a row with a different number of fields from the first
//!   data row, or too few for the columns chosen; a column name the header lacks; a quote left
//!   open. No rows: [`Error::TooFewPoints`]; more than [`crate::error::MAX_ELEMENTS`]:
//!   [`Error::TooLarge`].

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

/// The most characters of a field a message quotes.
pub const QUOTED_CHARS: usize = 40;

/// The points of a CSV text (module docs), `N` coordinates each.
///
/// ```
/// use splinelab::input::{points_from_csv, Columns};
/// let text = "id;x;y\n1; 0.5; 2\n2; \"1.5\"; -1e-3\n";
/// let p = points_from_csv::<2>(text, &Columns::Names(vec!["x".into(), "y".into()]))?;
/// assert_eq!(p[1].y, -1e-3);
/// // a trailing separator is no field, and a row of numbers no header
/// assert_eq!(points_from_csv::<2>("1,2,\n3,4,\n", &Columns::First)?.len(), 2);
/// // pandas' index column: a header one name short, its first name empty
/// let p = points_from_csv::<2>(" w x\n0 1.5 2.5\n1 3.5 4.5\n", &Columns::Names(vec!["w".into(), "x".into()]))?;
/// assert_eq!((p[0].x, p[0].y), (1.5, 2.5));
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
    let separator = separator_of(text);
    let mut fields = Fields::new(text, separator);
    // the columns picked if the first row is data (by name: refused then)
    let unnamed = pick::<N>(columns, None, 0, &fields, 0);
    let mut names: Option<Vec<String>> = None;
    // the columns picked (0-based, in the rows) and the rows' width, from the first data row
    let mut layout: Option<(Vec<usize>, usize)> = None;
    let mut out = Vec::new();
    loop {
        let keep = match (&layout, &names, &unnamed) {
            // the picked fields, and the first beyond the width (to place a ragged row)
            (Some((picked, width)), _, _) => {
                Keep::Indices(picked.iter().copied().chain([*width]).collect())
            }
            // after a header: the columns by name, at either place its rule allows
            (None, Some(n), _) => {
                Keep::Indices(match pick::<N>(columns, Some(n), n.len(), &fields, 0) {
                    Ok(p) => p.iter().flat_map(|&c| [c, c.saturating_add(1)]).collect(),
                    Err(_) => Vec::new(),
                })
            }
            (None, None, Ok(p)) => Keep::HeaderOr(p.clone()),
            (None, None, Err(_)) => Keep::HeaderOr(Vec::new()),
        };
        let Some(record) = fields.record(&keep) else {
            break;
        };
        if record.width == 0 {
            continue;
        }
        let Some((picked, width)) = &layout else {
            // the first rows: a header (no field a number), then the first data row
            if names.is_none() && record.names {
                names = Some(record.kept.into_iter().map(|f| f.text).collect());
                continue;
            }
            let at = record.kept.first().map_or(record.end, |f| f.start);
            let picked = match &names {
                Some(n) => pick::<N>(columns, Some(n), record.width, &fields, at)?,
                None => unnamed.clone()?,
            };
            out.push(point::<N>(&record, &picked, &fields)?);
            layout = Some((picked, record.width));
            continue;
        };
        if record.width != *width {
            let at = record
                .kept
                .iter()
                .find(|f| f.index == *width)
                .map_or(record.end, |f| f.start);
            return Err(fields.refuse(
                at,
                format!("{} fields, the first row has {width}", record.width),
            ));
        }
        if out.len() == MAX_ELEMENTS {
            return Err(Error::TooLarge {
                what: "CSV points",
                got: MAX_ELEMENTS + 1,
                max: MAX_ELEMENTS,
            });
        }
        out.push(point::<N>(&record, picked, &fields)?);
    }
    if out.is_empty() {
        return Err(no_rows());
    }
    Ok(out)
}

/// Which fields of a record to keep.
enum Keep {
    /// These (0-based).
    Indices(Vec<usize>),
    /// Every field while none is a number (a header's names), then these.
    HeaderOr(Vec<usize>),
}

/// How many rows decide the separator.
const SNIFFED_ROWS: usize = 8;

/// The most bytes read to decide the separator: 64 KiB.
const SNIFFED_BYTES: usize = 1 << 16;

/// How fields are separated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Separator {
    /// One byte.
    Byte(u8),
    /// Runs of spaces or tabs.
    Blanks,
}

/// The separator of `text` (module docs), from its first [`SNIFFED_ROWS`] rows as the reader
/// reads them with each candidate.
fn separator_of(text: &str) -> Separator {
    // the rows that end within the first SNIFFED_BYTES, or the first row's start alone
    let mut cut = text.len().min(SNIFFED_BYTES);
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    let prefix = &text[..cut];
    let widths = |sep: Separator| -> Vec<usize> {
        let mut fields = Fields::new(prefix, sep);
        let mut out = Vec::new();
        while out.len() <= SNIFFED_ROWS {
            let Some(record) = fields.record(&Keep::Indices(Vec::new())) else {
                break;
            };
            if record.width > 0 {
                out.push(record.width);
            }
        }
        if cut < text.len() && out.len() > 1 {
            out.pop();
        }
        out.truncate(SNIFFED_ROWS);
        out
    };
    let candidates = [
        Separator::Byte(b';'),
        Separator::Byte(b','),
        Separator::Byte(b'\t'),
        Separator::Byte(b' '),
        Separator::Blanks,
    ];
    let consistent = candidates.into_iter().find(|&sep| {
        let w = widths(sep);
        w.first()
            .is_some_and(|&first| first >= 2 && w.iter().all(|&k| k == first))
    });
    let first_has = || {
        [Separator::Byte(b';'), Separator::Byte(b',')]
            .into_iter()
            .find(|&sep| widths(sep).first().is_some_and(|&w| w >= 2))
    };
    consistent.or_else(first_has).unwrap_or(Separator::Blanks)
}

/// One field of a record: its index among the record's fields, its text (trimmed, a quote
/// after blanks removed) and the byte where it starts.
#[derive(Debug)]
struct Kept {
    index: usize,
    text: String,
    start: usize,
}

/// A record: its width (fields up to the last that is not empty), the fields kept, and the
/// byte where it ends.
#[derive(Debug)]
struct Record {
    width: usize,
    kept: Vec<Kept>,
    end: usize,
    /// Whether no field is a number (a header, if it is the first row).
    names: bool,
}

/// The reader's fields, one at a time.
struct Fields<'t> {
    text: &'t str,
    separator: Separator,
    reader: csv_core::Reader,
    pos: usize,
    buf: Vec<u8>,
    /// The chunk of text handed to the reader, from byte `chunk_start`.
    chunk: Vec<u8>,
    chunk_start: usize,
}

/// The bytes handed to the reader at a time.
const CHUNK: usize = 1 << 16;

impl<'t> Fields<'t> {
    fn new(text: &'t str, separator: Separator) -> Fields<'t> {
        let delimiter = match separator {
            Separator::Byte(b) => b,
            Separator::Blanks => b' ',
        };
        let reader = csv_core::ReaderBuilder::new()
            .delimiter(delimiter)
            .comment(Some(b'#'))
            .terminator(csv_core::Terminator::CRLF)
            .build();
        Fields {
            text,
            separator,
            reader,
            pos: 0,
            buf: vec![0; 256],
            chunk: Vec::new(),
            chunk_start: 0,
        }
    }

    /// The next field: its input bytes, its length in `self.buf`, whether it ends its record;
    /// `None` at the end of the text.
    fn field(&mut self) -> Option<(std::ops::Range<usize>, usize, bool)> {
        let start = self.pos;
        let mut nout = 0;
        let bytes = self.text.as_bytes();
        loop {
            // a chunk at a time, each byte in its place: a lone `\r` read as `\n` (the
            // reader ends a comment at `\n` alone), and with runs of blanks a tab as a space
            if self.pos >= self.chunk_start + self.chunk.len() && self.pos < bytes.len() {
                let end = bytes.len().min(self.pos + CHUNK);
                let blanks = self.separator == Separator::Blanks;
                let from = self.pos;
                self.chunk.clear();
                self.chunk
                    .extend(bytes[from..end].iter().enumerate().map(|(k, &b)| match b {
                        b'\r' if bytes.get(from + k + 1) != Some(&b'\n') => b'\n',
                        b'\t' if blanks => b' ',
                        b => b,
                    }));
                self.chunk_start = from;
            }
            let input: &[u8] = self
                .chunk
                .get(self.pos.saturating_sub(self.chunk_start)..)
                .unwrap_or(&[]);
            let (result, nin, n) = self.reader.read_field(input, &mut self.buf[nout..]);
            self.pos += nin;
            nout += n;
            match result {
                csv_core::ReadFieldResult::InputEmpty if input.is_empty() => return None,
                csv_core::ReadFieldResult::InputEmpty => {}
                csv_core::ReadFieldResult::OutputFull => {
                    let grown = self.buf.len().saturating_mul(2).max(256);
                    self.buf.resize(grown, 0);
                }
                csv_core::ReadFieldResult::Field { record_end } => {
                    return Some((start..self.pos, nout, record_end))
                }
                csv_core::ReadFieldResult::End => return None,
            }
        }
    }

    /// The next record, keeping the fields `keep` says; `None` at the end of the text. A
    /// record whose first field starts with `#` (a comment after blanks) has width 0.
    fn record(&mut self, keep: &Keep) -> Option<Record> {
        let mut record = Record {
            width: 0,
            kept: Vec::new(),
            end: self.pos,
            names: true,
        };
        let (wanted, mut all) = match keep {
            Keep::Indices(k) => (k, false),
            Keep::HeaderOr(k) => (k, true),
        };
        let mut index = 0;
        let mut comment = false;
        loop {
            let (raw, len, record_end) = self.field()?;
            let value = std::str::from_utf8(&self.buf[..len]).unwrap_or("");
            let trimmed = value.trim();
            let raw_bytes = &self.text.as_bytes()[raw.clone()];
            let quoted = raw_bytes.contains(&b'"');
            // a quote after blanks is text to the reader: the field's quotes are removed here
            let quote_after_blanks = matches!(raw_bytes.first(), Some(b' ' | b'\t'));
            let empty = trimmed.is_empty() && !quoted;
            if index == 0 && trimmed.starts_with('#') && !quoted {
                comment = true;
            }
            let skipped = comment || (empty && self.separator == Separator::Blanks);
            if !skipped {
                if !empty {
                    record.width = index + 1;
                }
                let text = match quote_after_blanks {
                    true => unquote(trimmed),
                    false => std::borrow::Cow::Borrowed(trimmed),
                };
                if record.names && text.parse::<f64>().is_ok() {
                    // a number: no header; only the wanted fields from here on
                    record.names = false;
                    if all {
                        all = false;
                        record.kept.retain(|f| wanted.contains(&f.index));
                    }
                }
                if all || wanted.contains(&index) {
                    record.kept.push(Kept {
                        index,
                        text: text.into_owned(),
                        start: self.visible_start(raw.start, index == 0),
                    });
                }
                index += 1;
            }
            if record_end {
                record.end = self.content_end(self.pos);
                if comment {
                    record.width = 0;
                }
                return Some(record);
            }
        }
    }

    /// The first byte of a field that starts reading at `from`: past blanks, and for a
    /// record's first field past the line ends and comment lines the reader skipped.
    fn visible_start(&self, from: usize, first: bool) -> usize {
        let bytes = self.text.as_bytes();
        let mut k = from;
        loop {
            while k < bytes.len() && matches!(bytes[k], b' ' | b'\t' | b'\r' | b'\n') {
                if !first && matches!(bytes[k], b'\r' | b'\n') {
                    return k;
                }
                k += 1;
            }
            if first
                && bytes.get(k) == Some(&b'#')
                && (k == 0 || matches!(bytes[k - 1], b'\r' | b'\n'))
            {
                while k < bytes.len() && !matches!(bytes[k], b'\r' | b'\n') {
                    k += 1;
                }
                continue;
            }
            return k;
        }
    }

    /// The byte after the last character of the record ending at `end` (its line end left
    /// out).
    fn content_end(&self, end: usize) -> usize {
        let bytes = self.text.as_bytes();
        let mut k = end.min(bytes.len());
        if k > 0 && bytes[k - 1] == b'\n' {
            k -= 1;
        }
        if k > 0 && bytes[k - 1] == b'\r' {
            k -= 1;
        }
        k
    }

    /// A refusal placed at byte `at`.
    fn refuse(&self, at: usize, message: String) -> Error {
        let (line, column) = super::position(self.text, at);
        parse_error(line, column, message)
    }
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

/// At most [`QUOTED_CHARS`] characters of `field`, quoted.
fn shown(field: &str) -> String {
    let mut chars = field.chars();
    let head: String = chars.by_ref().take(QUOTED_CHARS).collect();
    if chars.next().is_some() {
        format!("{head:?}… ({} bytes)", field.len())
    } else {
        format!("{head:?}")
    }
}

/// The 0-based columns of the `N` coordinates in rows `width` fields wide, the header
/// `names` read by the module docs' rule.
fn pick<const N: usize>(
    columns: &Columns,
    names: Option<&[String]>,
    width: usize,
    fields: &Fields,
    at: usize,
) -> Result<Vec<usize>> {
    // a header one name short names the last columns: the first is pandas' unnamed index
    let offset = match names {
        Some(n) if n.len() == width => 0,
        Some(n) if n.len() + 1 == width => 1,
        Some(n) => {
            return Err(fields.refuse(
                at,
                format!(
                    "the header has {} names and the first row {width} fields: not read (a header names every column, or every column but a first index)",
                    n.len()
                ),
            ))
        }
        None => 0,
    };
    let picked: Vec<usize> = match columns {
        Columns::First => (0..N).collect(),
        Columns::Indices(k) => k.clone(),
        Columns::Names(wanted) => {
            let Some(names) = names else {
                return Err(fields.refuse(
                    at,
                    "columns chosen by name, but the first row is not a header".into(),
                ));
            };
            wanted
                .iter()
                .map(|w| {
                    names
                        .iter()
                        .position(|n| n == w)
                        .map(|k| k + offset)
                        .ok_or_else(|| {
                            fields.refuse(
                                0,
                                format!("the header has no column {} (it has {names:?})", shown(w)),
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

/// The point of a data row: its `picked` fields as numbers.
fn point<const N: usize>(
    record: &Record,
    picked: &[usize],
    fields: &Fields,
) -> Result<SVector<f64, N>> {
    let mut p = SVector::<f64, N>::zeros();
    for (k, &c) in picked.iter().enumerate() {
        let Some(field) = record
            .kept
            .iter()
            .find(|f| f.index == c && c < record.width)
        else {
            return Err(fields.refuse(
                record.end,
                format!(
                    "{} fields, column {} is asked for",
                    record.width,
                    c.saturating_add(1)
                ),
            ));
        };
        p[k] = number(&field.text).map_err(|m| fields.refuse(field.start, m))?;
    }
    Ok(p)
}

/// A field as a finite number within [`MAX_COORDINATE`], or what is wrong with it.
fn number(field: &str) -> std::result::Result<f64, String> {
    match field.parse::<f64>() {
        Ok(x) if x.is_finite() && x.abs() <= MAX_COORDINATE => Ok(x),
        Ok(_) if field.parse::<f64>().is_ok_and(f64::is_finite) => Err(format!(
            "{} is beyond the largest coordinate, {MAX_COORDINATE:e}",
            shown(field)
        )),
        Ok(_) => Err(format!("not a finite number: {}", shown(field))),
        Err(_) if field.contains(['\n', '\r']) => Err(format!(
            "a quoted field runs on over lines, {}: a quote left open?",
            shown(field)
        )),
        Err(_) if field.contains(',') && field.replace(',', ".").parse::<f64>().is_ok() => {
            Err(format!(
                "not a number: {} (a decimal comma: write a point, or separate the fields with another character)",
                shown(field)
            ))
        }
        Err(_) => Err(format!("not a number: {}", shown(field))),
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
