//! Points from SVG path data (the `d` attribute): an outline drawn in a drawing program, as
//! dense polylines.
//!
//! - **Commands**: every command of SVG 1.1 paths — `M L H V C S Q T A Z`, absolute (upper
//!   case) and relative (lower case); after a move, further coordinate pairs are lines (the
//!   SVG rule); a command letter may be left out when it repeats; `S` and `T` reflect the
//!   previous curve's last control point (or start at the current point after another
//!   command). Numbers follow SVG's grammar (`-1.5e-3`, `.5.5` is two numbers), separated by
//!   blanks or commas; an arc's flags are `0` or `1` written apart.
//! - **Flattening**: a line is its end point; a cubic (`C`, `S`) or quadratic (`Q`, `T`)
//!   Bézier is halved (de Casteljau) until its control points lie within `tolerance` of the
//!   chord, so the polyline is within `tolerance` of the curve; an arc (`A`, SVG's endpoint
//!   form with its corrections: zero radii draw a line, radii too small are scaled up) is cut
//!   at equal steps of the ellipse's angle small enough that every chord is within
//!   `tolerance` of it; each flattened piece has at most [`MAX_PIECES_PER_CURVE`] segments.
//! - **Contours**: each `M` starts one; `Z` closes it (its first point repeated at its end).
//! - **Refused** with [`Error::Parse`] (line and column of the command or number at fault): an
//!   unknown command, a command without its numbers, a number that is not finite, an arc flag
//!   that is not `0` or `1` (flags packed as `01` are refused, not misread), data before the
//!   first `M`.

use crate::bezier::de_casteljau::de_casteljau_levels;
use crate::error::{Error, Result, MAX_COORDINATE, MAX_ELEMENTS};
use crate::metrics::curve::segment_distance;
use nalgebra::Vector2;

/// The most segments one Bézier command flattens into (2¹⁶).
pub const MAX_PIECES_PER_CURVE: usize = 1 << 16;

/// A contour of a path: its points, and whether `Z` closed it (the first point is then
/// repeated at the end).
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The flattened points.
    pub points: Vec<Vector2<f64>>,
    /// Whether the contour was closed by `Z`.
    pub closed: bool,
}

const WHAT: &str = "SVG path";

/// The contours of SVG path data `d` flattened within `tolerance` (module docs).
///
/// ```
/// use splinelab::input::svg_path::contours_from_svg_path;
/// let c = contours_from_svg_path("M 0 0 L 10 0 q 5 5 0 10 Z", 0.01)?;
/// assert_eq!(c.len(), 1);
/// assert!(c[0].closed);
/// // a half circle of radius 1 about (1, 0)
/// let arc = contours_from_svg_path("M 0 0 A 1 1 0 0 1 2 0", 1e-6)?;
/// assert!(arc[0].points.iter().all(|p| ((p.x - 1.0).hypot(p.y) - 1.0).abs() < 1e-12));
/// let err = contours_from_svg_path("M 0 0 X 1 1", 0.01).unwrap_err();
/// assert_eq!(err.to_string(), "SVG path, line 1, column 7: unknown command 'X'");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// As the module docs say; [`Error::NotPositive`] for a tolerance that is not positive and
/// finite; [`Error::TooLarge`] beyond [`MAX_ELEMENTS`] points.
pub fn contours_from_svg_path(d: &str, tolerance: f64) -> Result<Vec<Contour>> {
    crate::error::positive("SVG path flattening tolerance", tolerance)?;
    let tokens = tokenize(d)?;
    let mut out: Vec<Contour> = Vec::new();
    let mut pos = Vector2::zeros();
    let mut start = Vector2::zeros();
    let mut total = 0usize;
    let mut k = 0;
    let mut command: Option<(char, usize)> = None;
    // the previous command's last control point, for S (after C or S) and T (after Q or T)
    let mut cubic_control: Option<Vector2<f64>> = None;
    let mut quadratic_control: Option<Vector2<f64>> = None;
    while k < tokens.len() {
        let (c, at) = match tokens[k] {
            Token::Command(c, at) => {
                k += 1;
                (c, at)
            }
            Token::Number(_, at) => match command {
                // an implicit repeat; after a move, pairs are lines
                Some(('M', _)) => ('L', at),
                Some(('m', _)) => ('l', at),
                Some((c, _)) if !matches!(c, 'Z' | 'z') => (c, at),
                _ => {
                    return Err(parse_error(
                        d,
                        at,
                        "a number where a command was expected".into(),
                    ))
                }
            },
        };
        command = Some((c, at));
        let relative = c.is_ascii_lowercase();
        let base = if relative { pos } else { Vector2::zeros() };
        let mut take = |n: usize| -> Result<Vec<f64>> {
            let mut v = Vec::with_capacity(n);
            for _ in 0..n {
                match tokens.get(k) {
                    Some(&Token::Number(x, _)) => {
                        v.push(x);
                        k += 1;
                    }
                    _ => {
                        return Err(parse_error(
                            d,
                            at,
                            format!("{c} needs {n} numbers, found {}", v.len()),
                        ))
                    }
                }
            }
            Ok(v)
        };
        if !c.eq_ignore_ascii_case(&'M') && out.is_empty() {
            return Err(parse_error(d, at, format!("{c} before the first M")));
        }
        let mut new_points: Vec<Vector2<f64>> = Vec::new();
        let (mut next_cubic, mut next_quadratic) = (None, None);
        match c.to_ascii_uppercase() {
            'M' => {
                let v = take(2)?;
                pos = base + Vector2::new(v[0], v[1]);
                start = pos;
                out.push(Contour {
                    points: vec![pos],
                    closed: false,
                });
            }
            'L' => {
                let v = take(2)?;
                pos = base + Vector2::new(v[0], v[1]);
                new_points.push(pos);
            }
            'H' => {
                let v = take(1)?;
                pos.x = if relative { pos.x + v[0] } else { v[0] };
                new_points.push(pos);
            }
            'V' => {
                let v = take(1)?;
                pos.y = if relative { pos.y + v[0] } else { v[0] };
                new_points.push(pos);
            }
            'C' | 'S' => {
                let (first, v) = if c.eq_ignore_ascii_case(&'C') {
                    let v = take(6)?;
                    (base + Vector2::new(v[0], v[1]), v[2..].to_vec())
                } else {
                    // the reflection of the previous cubic's second control point, or the
                    // current point
                    (cubic_control.map_or(pos, |q| pos * 2.0 - q), take(4)?)
                };
                let p = [
                    pos,
                    first,
                    base + Vector2::new(v[0], v[1]),
                    base + Vector2::new(v[2], v[3]),
                ];
                flatten(&p, tolerance, &mut new_points);
                pos = p[3];
                next_cubic = Some(p[2]);
            }
            'Q' | 'T' => {
                let (q, v) = if c.eq_ignore_ascii_case(&'Q') {
                    let v = take(4)?;
                    (base + Vector2::new(v[0], v[1]), v[2..].to_vec())
                } else {
                    (quadratic_control.map_or(pos, |q| pos * 2.0 - q), take(2)?)
                };
                let e = base + Vector2::new(v[0], v[1]);
                // the quadratic as a cubic (degree elevation, exact)
                let p = [
                    pos,
                    pos + (q - pos) * (2.0 / 3.0),
                    e + (q - e) * (2.0 / 3.0),
                    e,
                ];
                flatten(&p, tolerance, &mut new_points);
                pos = e;
                next_quadratic = Some(q);
            }
            'A' => {
                let v = take(7)?;
                // the seven numbers are the tokens just taken
                let first = k - 7;
                // a flag is one digit, 0 or 1 (flags packed as `01` are refused, not misread)
                let flag = |index: usize| -> Result<bool> {
                    let Some(&Token::Number(_, a)) = tokens.get(index) else {
                        return Err(parse_error(d, at, "an arc without its flags".into()));
                    };
                    let text: String = d[a..]
                        .chars()
                        .take_while(|ch| {
                            ch.is_ascii_digit() || matches!(ch, '.' | 'e' | 'E' | '+' | '-')
                        })
                        .collect();
                    match text.as_str() {
                        "0" => Ok(false),
                        "1" => Ok(true),
                        _ => Err(parse_error(
                            d,
                            a,
                            format!("an arc flag is 0 or 1, found {text:?} (packed flags such as 01 are not read: separate them)"),
                        )),
                    }
                };
                let (large, sweep) = (flag(first + 3)?, flag(first + 4)?);
                let end = base + Vector2::new(v[5], v[6]);
                let arc = Arc {
                    radii: Vector2::new(v[0], v[1]),
                    rotation: v[2].to_radians(),
                    large,
                    sweep,
                };
                arc.flatten(pos, end, tolerance, &mut new_points);
                pos = end;
            }
            'Z' => {
                if let Some(last) = out.last_mut() {
                    if !last.closed {
                        last.closed = true;
                        if last.points.last() != Some(&start) {
                            new_points.push(start);
                        }
                    }
                }
                pos = start;
            }
            _ => return Err(parse_error(d, at, format!("unknown command {c:?}"))),
        }
        (cubic_control, quadratic_control) = (next_cubic, next_quadratic);
        if let Some(bad) = new_points
            .iter()
            .chain(std::iter::once(&pos))
            .find(|p| !p.iter().all(|x| x.abs() <= MAX_COORDINATE))
        {
            return Err(parse_error(
                d,
                at,
                format!(
                    "the point ({}, {}) is not finite or beyond the largest coordinate",
                    bad.x, bad.y
                ),
            ));
        }
        total = total.saturating_add(new_points.len() + 1);
        if total > MAX_ELEMENTS {
            return Err(Error::TooLarge {
                what: "SVG path points",
                got: total,
                max: MAX_ELEMENTS,
            });
        }
        if let Some(last) = out.last_mut() {
            if last.closed && !new_points.is_empty() && !c.eq_ignore_ascii_case(&'Z') {
                // drawing on after Z starts a new contour at the start point (SVG)
                out.push(Contour {
                    points: vec![start],
                    closed: false,
                });
            }
        }
        if let Some(last) = out.last_mut() {
            last.points.extend(new_points);
        }
    }
    Ok(out)
}

/// Appends the points of the cubic `p` (its start excluded) within `tolerance`: halved at
/// `u = ½` by de Casteljau's triangle ([`de_casteljau_levels`]: the left half is the first
/// point of each level, the right half the last, from the bottom up) until both inner
/// control points lie within `tolerance` of the chord — then the curve, inside their convex
/// hull, does too.
/// An elliptical arc's shape: the SVG `A` command's radii, `x`-axis rotation and flags.
struct Arc {
    radii: Vector2<f64>,
    rotation: f64,
    large: bool,
    sweep: bool,
}

impl Arc {
    /// The arc from `from` to `to` (SVG's endpoint parametrisation, with its corrections:
    /// zero radii draw a line, radii too small for the endpoints are scaled up, equal
    /// endpoints draw nothing) as points after `from` at equal steps of the ellipse's angle,
    /// the step small enough that every chord lies within `tolerance` of the arc (the sagitta
    /// of the circle of the larger radius bounds the ellipse's, an affine image of it shrunk in
    /// one direction), at most [`MAX_PIECES_PER_CURVE`] chords.
    fn flatten(
        &self,
        from: Vector2<f64>,
        to: Vector2<f64>,
        tolerance: f64,
        out: &mut Vec<Vector2<f64>>,
    ) {
        let (mut rx, mut ry) = (self.radii.x.abs(), self.radii.y.abs());
        if from == to {
            return;
        }
        if !(rx > 0.0 && ry > 0.0 && rx.is_finite() && ry.is_finite()) {
            out.push(to);
            return;
        }
        let (sin, cos) = self.rotation.sin_cos();
        // the endpoints in the ellipse's axes, about their midpoint
        let h = (from - to) * 0.5;
        let p = Vector2::new(cos * h.x + sin * h.y, -sin * h.x + cos * h.y);
        let lambda = (p.x / rx).powi(2) + (p.y / ry).powi(2);
        if lambda > 1.0 {
            let grow = lambda.sqrt();
            rx *= grow;
            ry *= grow;
        }
        let (rx2, ry2, px2, py2) = (rx * rx, ry * ry, p.x * p.x, p.y * p.y);
        let num = rx2 * ry2 - rx2 * py2 - ry2 * px2;
        let den = rx2 * py2 + ry2 * px2;
        let mut root = if den > 0.0 {
            (num / den).max(0.0).sqrt()
        } else {
            0.0
        };
        if self.large == self.sweep {
            root = -root;
        }
        let c = Vector2::new(root * rx * p.y / ry, -root * ry * p.x / rx);
        let centre = Vector2::new(cos * c.x - sin * c.y, sin * c.x + cos * c.y) + (from + to) * 0.5;
        let angle = |v: Vector2<f64>| v.y.atan2(v.x);
        let start = angle(Vector2::new((p.x - c.x) / rx, (p.y - c.y) / ry));
        let mut delta = angle(Vector2::new((-p.x - c.x) / rx, (-p.y - c.y) / ry)) - start;
        let tau = std::f64::consts::TAU;
        if self.sweep && delta < 0.0 {
            delta += tau;
        } else if !self.sweep && delta > 0.0 {
            delta -= tau;
        }
        let r = rx.max(ry);
        let step = 2.0 * (1.0 - tolerance / r).max(-1.0).acos();
        let pieces = if step.is_finite() && step > 0.0 {
            (delta.abs() / step)
                .ceil()
                .clamp(1.0, MAX_PIECES_PER_CURVE as f64) as usize
        } else {
            MAX_PIECES_PER_CURVE
        };
        for i in 1..pieces {
            let t = start + delta * (i as f64 / pieces as f64);
            let e = Vector2::new(rx * t.cos(), ry * t.sin());
            out.push(Vector2::new(cos * e.x - sin * e.y, sin * e.x + cos * e.y) + centre);
        }
        // the end exactly
        out.push(to);
    }
}

fn flatten(p: &[Vector2<f64>; 4], tolerance: f64, out: &mut Vec<Vector2<f64>>) {
    let mut stack = vec![(*p, 0usize)];
    // depth 16 gives at most MAX_PIECES_PER_CURVE pieces
    while let Some((q, depth)) = stack.pop() {
        let flat = [q[1], q[2]]
            .iter()
            .all(|&c| segment_distance(c, q[0], q[3]) <= tolerance);
        // four points make a triangle of four levels (the call cannot fail on them)
        let levels = match de_casteljau_levels(&q, 0.5) {
            Ok(levels) if depth < 16 && !flat => levels,
            _ => {
                out.push(q[3]);
                continue;
            }
        };
        let left = [0, 1, 2, 3].map(|k| levels[k][0]);
        let right = [3, 2, 1, 0].map(|k| levels[k][levels[k].len() - 1]);
        // the second half first on the stack, so the first half is emitted first
        stack.push((right, depth + 1));
        stack.push((left, depth + 1));
    }
}

#[derive(Debug, Clone, Copy)]
enum Token {
    /// A command letter and its byte offset.
    Command(char, usize),
    /// A number and its byte offset.
    Number(f64, usize),
}

/// Splits path data into command letters and numbers (SVG's number grammar).
fn tokenize(d: &str) -> Result<Vec<Token>> {
    let bytes = d.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let b = bytes[i];
        if b.is_ascii_whitespace() || b == b',' {
            i += 1;
        } else if b.is_ascii_alphabetic() && b != b'e' && b != b'E' {
            out.push(Token::Command(b as char, i));
            i += 1;
        } else if b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.') {
            let start = i;
            if matches!(b, b'+' | b'-') {
                i += 1;
            }
            let mut dot = false;
            while i < bytes.len() && (bytes[i].is_ascii_digit() || (bytes[i] == b'.' && !dot)) {
                dot |= bytes[i] == b'.';
                i += 1;
            }
            if i < bytes.len() && matches!(bytes[i], b'e' | b'E') {
                let mut j = i + 1;
                if j < bytes.len() && matches!(bytes[j], b'+' | b'-') {
                    j += 1;
                }
                if j < bytes.len() && bytes[j].is_ascii_digit() {
                    while j < bytes.len() && bytes[j].is_ascii_digit() {
                        j += 1;
                    }
                    i = j;
                }
            }
            let text = &d[start..i];
            match text.parse::<f64>() {
                Ok(x) if x.is_finite() => out.push(Token::Number(x, start)),
                _ => {
                    return Err(parse_error(
                        d,
                        start,
                        format!("not a finite number: {text:?}"),
                    ))
                }
            }
        } else {
            let ch = d[i..].chars().next().unwrap_or('?');
            return Err(parse_error(d, i, format!("unexpected character {ch:?}")));
        }
    }
    Ok(out)
}

/// A parse error at byte offset `at` of `d`, as line and column (1-based, in characters).
/// The contours of every `<path>` element's `d` attribute in an SVG document, in document
/// order, each flattened within `tolerance` ([`contours_from_svg_path`]). The coordinates are
/// the document's own (SVG's `y` points down; no `transform` is applied). Comments are
/// skipped; other elements (`<rect>`, `<circle>`, text) are not read.
///
/// ```
/// use splinelab::input::svg_path::contours_from_svg_document;
/// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg">
///   <path fill="none" d="M 0 0 L 4 0 L 4 3 Z"/>
/// </svg>"#;
/// let c = contours_from_svg_document(svg, 0.01)?;
/// assert_eq!(c[0].points.len(), 4);
/// let err = contours_from_svg_document("<svg>\n<path d='M 0 0 L 1'/></svg>", 0.01).unwrap_err();
/// assert_eq!(err.to_string(), "SVG path, line 2, column 16: L needs 2 numbers, found 1");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// [`Error::Parse`] with the document's line and column: a `<path>` without a `d`, an
/// unterminated tag or attribute, a document with no path; the errors of
/// [`contours_from_svg_path`] placed in the document.
pub fn contours_from_svg_document(text: &str, tolerance: f64) -> Result<Vec<Contour>> {
    let mut out = Vec::new();
    let mut at = 0;
    let mut paths = 0usize;
    while let Some(found) = next_tag(text, at) {
        let (start, name) = found;
        let end = match text[start..].find('>') {
            Some(e) => start + e,
            None => {
                return Err(parse_error(
                    text,
                    start,
                    format!("the tag <{name} is not closed"),
                ))
            }
        };
        at = end + 1;
        if name != "path" {
            continue;
        }
        paths += 1;
        let (value_at, value) = d_attribute(text, start, end)?;
        let contours = contours_from_svg_path(value, tolerance).map_err(|e| match e {
            Error::Parse {
                line,
                column,
                message,
                ..
            } => {
                let (l0, c0) = position(text, value_at);
                let column = if line == 1 { c0 + column - 1 } else { column };
                Error::Parse {
                    what: WHAT,
                    line: l0 + line - 1,
                    column,
                    message,
                }
            }
            other => other,
        })?;
        if out.len().saturating_add(contours.len()) > MAX_ELEMENTS {
            return Err(Error::TooLarge {
                what: "SVG contours",
                got: usize::MAX,
                max: MAX_ELEMENTS,
            });
        }
        out.extend(contours);
    }
    if paths == 0 {
        return Err(parse_error(
            text,
            text.len(),
            "the document has no <path> element".into(),
        ));
    }
    Ok(out)
}

/// The next tag from byte `at`: its start and name; comments, `<?…?>` and `<!…>` skipped.
fn next_tag(text: &str, mut at: usize) -> Option<(usize, &str)> {
    loop {
        let start = at + text.get(at..)?.find('<')?;
        let rest = &text[start + 1..];
        if let Some(comment) = rest.strip_prefix("!--") {
            // past the comment's end, or the text's if it has none
            at = start + 4 + comment.find("-->").map_or(comment.len(), |e| e + 3);
            continue;
        }
        let name_len = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == ':' || c == '-' || c == '_'))
            .unwrap_or(rest.len());
        if name_len == 0 {
            // a closing tag, a declaration or a processing instruction
            at = start + 1;
            continue;
        }
        let name = &rest[..name_len];
        return Some((start, name.rsplit(':').next().unwrap_or(name)));
    }
}

/// The `d` attribute's value within the tag `text[start..end]`, with its byte offset.
fn d_attribute(text: &str, start: usize, end: usize) -> Result<(usize, &str)> {
    let tag = &text[start..end];
    let mut from = 0;
    while let Some(i) = tag[from..].find('d') {
        let i = from + i;
        from = i + 1;
        let before_ok = tag[..i].ends_with(|c: char| c.is_ascii_whitespace());
        let after = tag[i + 1..].trim_start();
        if !before_ok || !after.starts_with('=') {
            continue;
        }
        let value = after[1..].trim_start();
        let quote = match value.chars().next() {
            Some(q @ ('"' | '\'')) => q,
            _ => {
                return Err(parse_error(
                    text,
                    start + i,
                    "the d attribute's value is not quoted".into(),
                ))
            }
        };
        // the value starts after its quote, `value` being a suffix of the tag
        let value_at = start + (tag.len() - value.len()) + 1;
        return match text[value_at..].find(quote) {
            Some(close) => Ok((value_at, &text[value_at..value_at + close])),
            None => Err(parse_error(
                text,
                value_at - 1,
                "the d attribute is not closed".into(),
            )),
        };
    }
    Err(parse_error(
        text,
        start,
        "a <path> without a d attribute".into(),
    ))
}

/// The 1-based line and column of byte `at` of `text`.
fn position(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

fn parse_error(d: &str, at: usize, message: String) -> Error {
    let (line, column) = position(d, at);
    Error::Parse {
        what: WHAT,
        line,
        column,
        message,
    }
}
