//! The letter "a" in four versions for seed 004's Figs 9–20 (feature `fonts`; the paper's
//! typefaces are not named, spec decision A17): the outlines of DejaVu Sans, DejaVu Serif and
//! DejaVu Serif Italic (single-storey), read from the fonts the crate embeds
//! ([`crate::input::font::glyph`]), and the hand-made polygonal "a" of
//! [`crate::seeds::seed004::polygonal_a`] for the version made of straight segments.

use crate::error::{Error, Result};
use crate::input::font::{glyph, GlyphContour};

const DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
const DEJAVU_SERIF: &[u8] = include_bytes!("../../assets/fonts/DejaVuSerif.ttf");
const DEJAVU_SERIF_ITALIC: &[u8] = include_bytes!("../../assets/fonts/DejaVuSerif-Italic.ttf");

/// A letter: its name and contours (the outer one first).
#[derive(Debug, Clone, PartialEq)]
pub struct Letter {
    /// Which version, in words.
    pub name: &'static str,
    /// The closed contours.
    pub contours: Vec<GlyphContour>,
}

/// The four versions of the letter "a": 1 DejaVu Sans, 2 DejaVu Serif, 3 the polygonal one,
/// 4 DejaVu Serif Italic.
///
/// # Errors
/// [`Error::IndexOutOfRange`] for another version; [`Error::Glyph`] if a font cannot
/// be read.
pub fn letter_a(version: usize) -> Result<Letter> {
    let (name, font) = match version {
        1 => ("DejaVu Sans", DEJAVU_SANS),
        2 => ("DejaVu Serif", DEJAVU_SERIF),
        3 => {
            let contours = crate::seeds::seed004::polygonal_a()
                .into_iter()
                .map(|points| {
                    let mut outline = points.clone();
                    outline.push(points[0]);
                    let marked = points.iter().map(|&p| (p, true)).collect();
                    GlyphContour {
                        points,
                        marked,
                        outline,
                    }
                })
                .collect();
            return Ok(Letter {
                name: "polygonal",
                contours,
            });
        }
        4 => ("DejaVu Serif Italic", DEJAVU_SERIF_ITALIC),
        _ => {
            return Err(Error::IndexOutOfRange {
                what: "letter version (1–4)",
                index: version,
                len: 5,
            })
        }
    };
    Ok(Letter {
        name,
        contours: glyph(font, 'a')?,
    })
}
