//! A user's points and outlines from files, by their extension: CSV points (`.csv`, `.txt`,
//! `.dat`, `.xy`), the paths of an SVG document (`.svg`), SVG path data alone (`.path`), a glyph
//! of a font (`.ttf`, `.otf`).

use crate::input::Contour;
use crate::input::{contours_from_svg_path, points_from_csv, Columns, SvgDocument};
use crate::report::error::{Error, Result};
use crate::study::outline::size;
use nalgebra::Vector2;
use std::path::Path;

/// The largest file read (1 GiB): a larger one is refused before it is read.
pub const MAX_FILE_BYTES: u64 = 1 << 30;

/// Fraction of an SVG outline's size within which its curves are flattened by default.
pub const FLATTEN_FRACTION: f64 = 1e-4;

/// How [`read_outline`] reads a file.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReadOptions {
    /// The CSV columns of `x` and `y`.
    pub columns: Columns,
    /// Whether a CSV outline is closed; `None`: closed when its last point is its first.
    pub closed: Option<bool>,
    /// The character of a font file to read.
    pub glyph: Option<char>,
    /// The distance within which an SVG's outline lies of the curves it describes (an SVG
    /// document's arcs included, which its parser replaces by cubics within
    /// [`crate::input::SvgOutline::arcs`]); `None`: curves flattened within
    /// [`FLATTEN_FRACTION`] of the outline's size, plus that bound.
    pub flatten: Option<f64>,
}

/// What kind of file a path names, by its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// Points as CSV.
    Csv,
    /// An SVG document.
    Svg,
    /// SVG path data (the `d` attribute's text).
    PathData,
    /// A TrueType or OpenType font.
    Font,
}

impl FileKind {
    /// The kind of `path` by its extension (any case).
    ///
    /// # Errors
    /// [`crate::error::Error::Parse`] for an extension none of the readers takes.
    pub fn of(path: &Path) -> Result<FileKind> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        Ok(match ext.as_deref() {
            Some("csv" | "txt" | "dat" | "xy") => FileKind::Csv,
            Some("svg") => FileKind::Svg,
            Some("path") => FileKind::PathData,
            Some("ttf" | "otf") => FileKind::Font,
            _ => {
                return Err(crate::error::Error::Parse {
                    what: "input file name",
                    line: 1,
                    column: 1,
                    message: format!(
                        "{}: the extension says neither CSV points (.csv, .txt, .dat, .xy), an SVG document (.svg), SVG path data (.path) nor a font (.ttf, .otf)",
                        path.display()
                    ),
                }
                .into())
            }
        })
    }
}

/// The bytes of `path`, refused beyond [`MAX_FILE_BYTES`].
///
/// # Errors
/// [`Error::Io`] if it cannot be read or is too large.
pub fn read_bytes(path: &Path) -> Result<Vec<u8>> {
    read_bytes_within(path, MAX_FILE_BYTES)
}

/// The bytes of `path`, refused beyond `max` bytes. The limit holds while reading (at most
/// `max + 1` bytes are read), so a device or a pipe that reads without end (a link to
/// `/dev/zero`, whose length the file system gives as 0) is refused too.
///
/// # Errors
/// [`Error::Io`] if it cannot be read or is larger than `max` bytes.
pub fn read_bytes_within(path: &Path, max: u64) -> Result<Vec<u8>> {
    use std::io::Read;
    let io = |message: String| Error::Io {
        path: path.to_path_buf(),
        message,
    };
    let file = std::fs::File::open(path).map_err(|e| io(e.to_string()))?;
    let len = file.metadata().map_err(|e| io(e.to_string()))?.len();
    if len > max {
        return Err(io(format!("{len} bytes: larger than the {max} bytes read")));
    }
    let mut bytes = Vec::with_capacity(usize::try_from(len).unwrap_or(0));
    file.take(max.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| io(e.to_string()))?;
    if bytes.len() as u64 > max {
        return Err(io(format!(
            "more than the {max} bytes read (a device or a stream without end?)"
        )));
    }
    Ok(bytes)
}

/// The text of `path` (UTF-8).
///
/// # Errors
/// As [`read_bytes`]; [`crate::error::Error::Parse`] at the first byte that is not UTF-8.
pub fn read_text(path: &Path) -> Result<String> {
    let bytes = read_bytes(path)?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let text = String::from_utf8_lossy(valid);
        let (line, column) = crate::input::position(&text, text.len());
        crate::error::Error::Parse {
            what: "input file",
            line,
            column,
            message: "not UTF-8 text".into(),
        }
        .into()
    })
}

/// The points of a CSV file (`x`, `y` by `columns`), for [`super::fit::Fit`].
///
/// # Errors
/// As [`read_text`] and [`points_from_csv`].
pub fn read_points(path: &Path, columns: &Columns) -> Result<Vec<Vector2<f64>>> {
    let text = read_text(path)?;
    Ok(points_from_csv::<2>(&text, columns)?)
}

/// The points of one contour of a CSV file with a `contour` column (as `splinelab fewest`
/// writes its answers, `NAME-METHOD-points.csv`): the rows whose `contour` is `contour`, in
/// order, `x` and `y` from the columns named by `columns` (`x` and `y` for
/// [`Columns::First`]).
///
/// # Errors
/// As [`read_points`]; [`crate::error::Error::Parse`] for column indices (the contour column
/// is found by its name); [`crate::error::Error::TooFewPoints`] if no row is of `contour`.
pub fn read_contour_points(
    path: &Path,
    columns: &Columns,
    contour: u32,
) -> Result<Vec<Vector2<f64>>> {
    let names = match columns {
        Columns::First => vec!["x".to_string(), "y".to_string()],
        Columns::Names(names) => names.clone(),
        Columns::Indices(_) => {
            return Err(crate::error::Error::Parse {
                what: "CSV columns",
                line: 1,
                column: 1,
                message: "a contour is chosen by the `contour` column's name: give the x and y \
                          columns by name too"
                    .into(),
            }
            .into())
        }
    };
    let columns = Columns::Names(
        std::iter::once("contour".to_string())
            .chain(names)
            .collect(),
    );
    let text = read_text(path)?;
    let rows = points_from_csv::<3>(&text, &columns)?;
    let points: Vec<Vector2<f64>> = rows
        .iter()
        .filter(|r| r[0] == f64::from(contour))
        .map(|r| Vector2::new(r[1], r[2]))
        .collect();
    if points.is_empty() {
        return Err(crate::error::Error::TooFewPoints {
            what: "rows of the contour asked for",
            needed: 1,
            got: 0,
        }
        .into());
    }
    Ok(points)
}

/// The size of SVG path data's curves by their extrema (single precision, as an SVG
/// document's parser reads them), 0 if the data cannot be read so: the basis of the
/// flattening tolerance of a path whose segment ends all meet in one point.
fn curves_size(d: &str) -> f64 {
    if d.contains(['"', '<', '&']) {
        return 0.0;
    }
    let document = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"{d}\" fill=\"none\" stroke=\"black\"/></svg>"
    );
    SvgDocument::parse(&document)
        .and_then(|doc| doc.extent())
        .map_or(0.0, |e| e.size())
        .max(0.0)
}

/// The contours of an outline file ([`FileKind`]): a CSV's points as one contour (closed as
/// `options.closed` says), an SVG document's or path data's contours (curves flattened within
/// `options.flatten`; an SVG document's `y` turned up, as the figures draw), a glyph's closed
/// contours in em units.
///
/// # Errors
/// As [`FileKind::of`], [`read_text`], [`points_from_csv`],
/// [`SvgDocument::parse`], [`SvgDocument::outline`], [`contours_from_svg_path`] and
/// [`crate::input::font::glyph`];
/// [`crate::error::Error::Parse`] for a font without `options.glyph`.
pub fn read_outline(path: &Path, options: &ReadOptions) -> Result<Vec<Contour>> {
    let kind = FileKind::of(path)?;
    match kind {
        FileKind::Csv => {
            let points = read_points(path, &options.columns)?;
            let closed = options
                .closed
                .unwrap_or(points.len() > 2 && points.first() == points.last());
            Ok(vec![Contour { points, closed }])
        }
        FileKind::PathData => {
            let text = read_text(path)?;
            let tolerance = match options.flatten {
                Some(t) => t,
                // the size from the path's end points (curves as chords; a loop whose ends
                // meet: from its curves' extrema), then from the curves flattened within
                // that fraction of it: the curves' own size
                None => {
                    let chords = size(&contours_from_svg_path(&text, f64::MAX)?);
                    let basis = if chords > 0.0 {
                        chords
                    } else {
                        curves_size(&text)
                    };
                    match FLATTEN_FRACTION * basis {
                        t if t > 0.0 => FLATTEN_FRACTION * size(&contours_from_svg_path(&text, t)?),
                        t => t,
                    }
                }
            };
            Ok(contours_from_svg_path(&text, tolerance)?)
        }
        FileKind::Svg => {
            let text = read_text(path)?;
            // read once; the size from the drawn curves (their extrema), and the arcs' bound,
            // which no flattening changes
            let document = SvgDocument::parse(&text)?;
            let extent = document.extent()?;
            let tolerance = match options.flatten {
                Some(t) if t.is_finite() && t > extent.arcs => t - extent.arcs,
                Some(t) if t > 0.0 && t.is_finite() => {
                    return Err(crate::error::Error::Parse {
                        what: "SVG flattening tolerance",
                        line: 1,
                        column: 1,
                        message: format!(
                            "{t:e} is below {:e}, the distance within which the SVG parser's cubics follow the document's arcs: give a larger tolerance",
                            extent.arcs
                        ),
                    }
                    .into())
                }
                Some(t) => t,
                None => FLATTEN_FRACTION * extent.size(),
            };
            Ok(document.outline(tolerance)?.into_contours())
        }
        FileKind::Font => {
            let ch = options.glyph.ok_or(crate::error::Error::Parse {
                what: "font outline",
                line: 1,
                column: 1,
                message: "a font needs the character to read (--glyph)".into(),
            })?;
            let font = read_bytes(path)?;
            Ok(crate::input::font::glyph(&font, ch)?
                .into_iter()
                .map(|c| Contour {
                    points: c.outline,
                    closed: true,
                })
                .collect())
        }
    }
}
