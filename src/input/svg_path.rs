//! Points from SVG path data (the `d` attribute, or a `.path` file): an outline drawn in a
//! drawing program, as dense polylines.
//!
//! - **Grammar**: SVG's path grammar as the resvg project's parser reads it
//!   ([`svgtypes::PathParser`]): every command — `M L H V C S Q T A Z`, absolute (upper case)
//!   and relative (lower case); after a move, further coordinate pairs are lines; a repeated
//!   command letter may be left out; numbers as SVG writes them (`-1.5e-3`, `.5.5` is two
//!   numbers, `1-2` too); an arc's flags are single digits that may touch what follows
//!   (`a.5.5 0 0 0-1 0`, `a1 1 0 00-.5.5`). `S` and `T` reflect the previous curve's last
//!   control point (or start at the current point after another command).
//! - **Flattening** within `tolerance` ([`super::flatten`]): Béziers by de Casteljau halving,
//!   arcs (SVG's endpoint form with its corrections) at equal angle steps, exactly.
//! - **Contours**: each `M` starts one; `Z` closes it (its first point repeated at its end);
//!   drawing on after `Z` starts a new one at the closed contour's start. A contour that draws
//!   nothing (a lone `M`) is not returned.
//! - **Refused** with [`Error::Parse`] at the line and column where the data cannot be read
//!   (SVG's renderers draw a path up to its first error; a reader of outlines refuses it
//!   instead, naming the place): an unknown command, a command short of numbers, a number that
//!   is not finite, an arc flag that is not `0` or `1`, data before the first `M`; a curve
//!   that needs more than [`super::flatten::MAX_PIECES_PER_CURVE`] pieces within the
//!   tolerance, a point beyond [`crate::error::MAX_COORDINATE`].

use super::flatten::{Contour, Flattener, SvgArc};
use super::position;
use crate::error::{Error, Result};
use nalgebra::Vector2;
use svgtypes::PathSegment;

const WHAT: &str = "SVG path";

/// The contours of SVG path data `d` flattened within `tolerance` (module docs).
///
/// ```
/// use splinelab::input::svg_path::contours_from_svg_path;
/// let c = contours_from_svg_path("M 0 0 L 10 0 q 5 5 0 10 Z", 0.01)?;
/// assert_eq!(c.len(), 1);
/// assert!(c[0].closed);
/// // a half circle of radius 1 about (1, 0); flags written as minifiers do
/// let arc = contours_from_svg_path("M0 0a1 1 0 01 2 0", 1e-6)?;
/// assert!(arc[0].points.iter().all(|p| ((p.x - 1.0).hypot(p.y) - 1.0).abs() < 1e-12));
/// let err = contours_from_svg_path("M 0 0 X 1 1", 0.01).unwrap_err();
/// assert_eq!(err.to_string(), "SVG path, line 1, column 7: cannot read 'X' here (a command letter or a number is expected)");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// As the module docs say; [`Error::NotPositive`] for a tolerance that is not positive and
/// finite; [`Error::TooLarge`] beyond [`crate::error::MAX_ELEMENTS`] points.
pub fn contours_from_svg_path(d: &str, tolerance: f64) -> Result<Vec<Contour>> {
    let mut pen = Flattener::new(tolerance)?;
    let d = &normalized_path_data(d);
    draw_path_data(d, &mut pen).map_err(|(e, at)| place(e, d, at))?;
    Ok(pen.finish())
}

/// Draws path data `d` into `pen`. An error comes with the byte offset of the command at
/// fault (or of the text the grammar cannot read).
fn draw_path_data(d: &str, pen: &mut Flattener) -> std::result::Result<(), (Error, usize)> {
    let mut state = PenState::default();
    // path data is runs of a command letter and its numbers (no other letter than e and E,
    // an exponent's, occurs in SVG's numbers): each run is read by the grammar on its own, so
    // every error is placed in its run, a pen's refusal at the run's command letter
    let letters: Vec<usize> = d
        .bytes()
        .enumerate()
        .filter(|&(_, b)| is_command(b))
        .map(|(i, _)| i)
        .collect();
    let first = letters.first().copied().unwrap_or(d.len());
    let lead = skip_blanks(d, 0);
    if lead < first {
        return Err((parse_message(grammar_message(d, lead)), lead));
    }
    if let Some(&f) = letters.first() {
        if !matches!(d.as_bytes()[f], b'M' | b'm') {
            return Err((parse_message(grammar_message(d, f)), f));
        }
    }
    for (k, &start) in letters.iter().enumerate() {
        let end = letters.get(k + 1).copied().unwrap_or(d.len());
        let run = &d[start..end];
        // the grammar wants a move first: a dummy one (5 characters), skipped
        let text = format!("M0 0 {run}");
        let mut parser = svgtypes::PathParser::from(text.as_str()).skip(1);
        for segment in parser.by_ref() {
            let segment = segment.map_err(|e| {
                let at = match e {
                    svgtypes::Error::UnexpectedData(pos) | svgtypes::Error::InvalidNumber(pos) => {
                        start + byte_of_char(run, pos.saturating_sub(5))
                    }
                    _ => end,
                };
                (parse_message(grammar_message(d, at)), at)
            })?;
            state.draw(segment, pen).map_err(|e| (e, start))?;
        }
    }
    Ok(())
}

/// Path data with every comma moved before the blanks that precede it (`A 1 1 0 1 , 0 2 0` →
/// `A 1 1 0 1,  0 2 0`), so that every byte keeps its place: SVG's grammar gives those blanks
/// no meaning, and the path grammar crate accepts a comma after an arc's flag only directly
/// after the flag.
pub fn normalized_path_data(d: &str) -> std::borrow::Cow<'_, str> {
    let bytes = d.as_bytes();
    if !bytes
        .windows(2)
        .any(|w| w[0].is_ascii_whitespace() && w[1] == b',')
    {
        return std::borrow::Cow::Borrowed(d);
    }
    let mut out = bytes.to_vec();
    let mut k = 0;
    while k < out.len() {
        if out[k] == b',' {
            let mut j = k;
            while j > 0 && out[j - 1].is_ascii_whitespace() {
                out.swap(j - 1, j);
                j -= 1;
            }
        }
        k += 1;
    }
    // only ASCII bytes moved: still UTF-8
    std::borrow::Cow::Owned(String::from_utf8(out).unwrap_or_else(|_| d.to_string()))
}

/// The current point, the contour's start and the last control points for `S` and `T`,
/// all untransformed.
#[derive(Debug, Default)]
struct PenState {
    pos: Vector2<f64>,
    start: Vector2<f64>,
    cubic: Option<Vector2<f64>>,
    quadratic: Option<Vector2<f64>>,
}

impl PenState {
    fn draw(&mut self, segment: PathSegment, pen: &mut Flattener) -> Result<()> {
        let pos = self.pos;
        let relative = !segment.is_abs();
        let base = if relative { pos } else { Vector2::zeros() };
        let v = |x: f64, y: f64| base + Vector2::new(x, y);
        let (mut cubic, mut quadratic) = (None, None);
        let end = match segment {
            PathSegment::MoveTo { x, y, .. } => {
                let e = v(x, y);
                self.start = e;
                pen.move_to(e)?;
                e
            }
            PathSegment::LineTo { x, y, .. } => {
                let e = v(x, y);
                pen.line_to(e)?;
                e
            }
            PathSegment::HorizontalLineTo { x, .. } => {
                let e = Vector2::new(if relative { pos.x + x } else { x }, pos.y);
                pen.line_to(e)?;
                e
            }
            PathSegment::VerticalLineTo { y, .. } => {
                let e = Vector2::new(pos.x, if relative { pos.y + y } else { y });
                pen.line_to(e)?;
                e
            }
            PathSegment::CurveTo {
                x1,
                y1,
                x2,
                y2,
                x,
                y,
                ..
            } => {
                let (c1, c2, e) = (v(x1, y1), v(x2, y2), v(x, y));
                cubic = Some(c2);
                pen.cubic_to(c1, c2, e)?;
                e
            }
            PathSegment::SmoothCurveTo { x2, y2, x, y, .. } => {
                // the reflection of the previous cubic's second control point, or the
                // current point
                let c1 = self.cubic.map_or(pos, |q| pos * 2.0 - q);
                let (c2, e) = (v(x2, y2), v(x, y));
                cubic = Some(c2);
                pen.cubic_to(c1, c2, e)?;
                e
            }
            PathSegment::Quadratic { x1, y1, x, y, .. } => {
                let (c, e) = (v(x1, y1), v(x, y));
                quadratic = Some(c);
                pen.quad_to(c, e)?;
                e
            }
            PathSegment::SmoothQuadratic { x, y, .. } => {
                let c = self.quadratic.map_or(pos, |q| pos * 2.0 - q);
                let e = v(x, y);
                quadratic = Some(c);
                pen.quad_to(c, e)?;
                e
            }
            PathSegment::EllipticalArc {
                rx,
                ry,
                x_axis_rotation,
                large_arc,
                sweep,
                x,
                y,
                ..
            } => {
                let e = v(x, y);
                let arc = SvgArc {
                    radii: Vector2::new(rx, ry),
                    rotation: x_axis_rotation.to_radians(),
                    large: large_arc,
                    sweep,
                };
                pen.arc_to(&arc, e)?;
                e
            }
            PathSegment::ClosePath { .. } => {
                pen.close();
                self.start
            }
        };
        self.pos = end;
        (self.cubic, self.quadratic) = (cubic, quadratic);
        Ok(())
    }
}

/// The byte offset of the first non-blank at or after `at`.
fn skip_blanks(d: &str, at: usize) -> usize {
    let rest = d.get(at..).unwrap_or("");
    at + (rest.len()
        - rest
            .trim_start_matches(|c: char| c.is_ascii_whitespace() || c == ',')
            .len())
}

fn is_command(b: u8) -> bool {
    matches!(
        b.to_ascii_uppercase(),
        b'M' | b'Z' | b'L' | b'H' | b'V' | b'C' | b'S' | b'Q' | b'T' | b'A'
    )
}

/// The byte offset of 1-based character position `pos` of `d`.
fn byte_of_char(d: &str, pos: usize) -> usize {
    d.char_indices()
        .nth(pos.saturating_sub(1))
        .map_or(d.len(), |(b, _)| b)
}

/// What cannot be read at byte `at` of `d`, in words.
fn grammar_message(d: &str, at: usize) -> String {
    let at = at.min(d.len());
    let found: String = d[at..]
        .chars()
        .take_while(|c| !c.is_ascii_whitespace() && *c != ',')
        .take(12)
        .collect();
    let before = d[..at].trim_end_matches(|c: char| c.is_ascii_whitespace() || c == ',');
    // the run's command letter, for "X is short of numbers"
    let command = d[..at]
        .bytes()
        .rev()
        .find(|&b| is_command(b))
        .map(char::from);
    if before.is_empty() {
        return format!("path data starts with a move (M or m), not {found:?}");
    }
    if found.parse::<f64>().is_ok_and(|x| !x.is_finite()) {
        return format!("not a finite number: {found:?}");
    }
    let first = found.chars().next();
    match (first, command) {
        (None, Some(c)) => format!("{c} is short of numbers"),
        (Some(f), _) if f.is_ascii_alphabetic() && is_command(f as u8) => {
            format!("{} is short of numbers before {f:?}", command.unwrap_or(f))
        }
        (Some(f), _) if f.is_ascii_alphabetic() => {
            format!("cannot read {f:?} here (a command letter or a number is expected)")
        }
        (Some(_), Some('A' | 'a')) if found.chars().all(|c| c.is_ascii_digit() || c == '.') => {
            format!("cannot read {found:?} here (a number, or an arc flag 0 or 1, is expected)")
        }
        (Some(_), Some('Z' | 'z')) => format!("a number after Z: {found:?}"),
        _ => format!("cannot read {found:?} here (a number is expected)"),
    }
}

fn parse_message(message: String) -> Error {
    Error::Parse {
        what: WHAT,
        line: 0,
        column: 0,
        message,
    }
}

/// An error of the pen or the grammar placed at byte `at` of `d` (line and column 1-based,
/// in characters); other errors unchanged.
pub(crate) fn place(e: Error, d: &str, at: usize) -> Error {
    match e {
        Error::Parse { message, .. } => {
            let (line, column) = position(d, at);
            Error::Parse {
                what: WHAT,
                line,
                column,
                message,
            }
        }
        other => other,
    }
}
