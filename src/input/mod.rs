//! Users' data in: points from CSV ([`csv`]), outlines from SVG path data ([`svg_path`]), SVG
//! documents (`svg_document`, feature `svg`) and fonts' glyphs (`font`, feature `fonts`), drawn
//! as polylines within a stated distance
//! ([`flatten`]). Every reader takes the text (reading the file is the caller's), refuses what
//! it cannot read with [`crate::error::Error::Parse`] naming the line and column at fault, and returns
//! nothing half-read.

#[cfg(feature = "svg")]
mod clip;
pub mod csv;
pub mod flatten;
#[cfg(feature = "fonts")]
pub mod font;
#[cfg(feature = "svg")]
pub mod svg_document;
#[cfg(feature = "svg")]
pub mod svg_limits;
pub mod svg_path;

#[cfg(feature = "svg")]
pub use clip::FillRule;
pub use csv::{points_from_csv, Columns};
pub use flatten::{Contour, SvgArc};
#[cfg(feature = "svg")]
pub use svg_document::{
    contours_from_svg_document, read_svg_document, DrawnPath, Stroke, SvgDocument, SvgExtent,
    SvgOutline,
};
pub use svg_path::contours_from_svg_path;

/// The 1-based line and column (in characters) of byte `at` of `text` (clamped to the text, and
/// back to a character boundary): where a reader places what it cannot read. Lines end with
/// `\n`, `\r\n` or `\r`.
pub(crate) fn position(text: &str, at: usize) -> (usize, usize) {
    let mut at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    let before = &text[..at];
    let bytes = before.as_bytes();
    let ends = bytes
        .iter()
        .enumerate()
        .filter(|&(k, &b)| b == b'\n' || (b == b'\r' && bytes.get(k + 1) != Some(&b'\n')))
        .count();
    let column = before
        .rsplit(['\n', '\r'])
        .next()
        .map_or(0, |l| l.chars().count())
        + 1;
    (ends + 1, column)
}
