//! Glyph outlines from TrueType and OpenType fonts (feature `fonts`, read with `ttf-parser`):
//! the closed contours of one character in em units ([`glyph`]), for seed 004's letters
//! ([`crate::seeds::letters`]) and for a user's own letter (`splinelab fewest font.ttf
//! --glyph g`).
//!
//! A TrueType outline is a closed sequence of line and quadratic Bézier segments (an OpenType
//! one of cubic segments). The interpolation points of a contour are the segments' end points
//! (the on-curve points, including the midpoints TrueType leaves implicit between two
//! off-curve points) — the points a draughtsman would mark on the letter; the reference
//! outline samples every curved segment densely.

use crate::error::{Error, Result};
use nalgebra::Vector2;

/// Samples per curved segment of the reference outline.
const QUAD_SAMPLES: usize = 24;

/// One closed contour of a glyph, in em units (the em square is `[0, 1]²`).
#[derive(Debug, Clone, PartialEq)]
pub struct GlyphContour {
    /// The on-curve points in order, without repeating the first: the interpolation points.
    pub points: Vec<Vector2<f64>>,
    /// The outline's points as the font gives them, in order, each marked on-curve (`true`)
    /// or off-curve (`false`, a quadratic's control point); TrueType's implied on-curve
    /// midpoints are included as on-curve.
    pub marked: Vec<(Vector2<f64>, bool)>,
    /// The outline sampled densely, closed (last point = first).
    pub outline: Vec<Vector2<f64>>,
}

/// The closed contours of the glyph of `ch` in a TrueType or OpenType font (the bytes of a
/// `.ttf` or `.otf` file), in em units (module docs).
///
/// ```
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// let font = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/DejaVuSans.ttf"))?;
/// let g = splinelab::input::font::glyph(&font, 'g')?;
/// assert!(!g.is_empty() && g.iter().all(|c| c.outline.first() == c.outline.last()));
/// assert!(splinelab::input::font::glyph(&font, '\u{10FFFF}').is_err());
/// # Ok(()) }
/// ```
///
/// # Errors
/// [`Error::Glyph`] naming the character if the bytes are not a font the parser reads, the
/// font has no glyph for `ch`, or the glyph has no outline (a space).
pub fn glyph(font: &[u8], ch: char) -> Result<Vec<GlyphContour>> {
    let fail = |message: &str| Error::Glyph {
        ch,
        message: message.into(),
    };
    let face = ttf_parser::Face::parse(font, 0)
        .map_err(|e| fail(&format!("not a font the parser reads ({e})")))?;
    let index = face
        .glyph_index(ch)
        .filter(|g| g.0 != 0)
        .ok_or_else(|| fail("the font has no glyph for it"))?;
    let mut builder = Outline {
        em: f64::from(face.units_per_em()),
        contours: Vec::new(),
    };
    face.outline_glyph(index, &mut builder)
        .ok_or_else(|| fail("the glyph has no outline"))?;
    Ok(builder.contours)
}

/// Collects contours from `ttf-parser`'s outline callbacks.
struct Outline {
    em: f64,
    contours: Vec<GlyphContour>,
}

impl Outline {
    fn point(&self, x: f32, y: f32) -> Vector2<f64> {
        Vector2::new(f64::from(x) / self.em, f64::from(y) / self.em)
    }

    fn current(&mut self) -> &mut GlyphContour {
        if self.contours.is_empty() {
            self.contours.push(GlyphContour {
                points: Vec::new(),
                marked: Vec::new(),
                outline: Vec::new(),
            });
        }
        let last = self.contours.len() - 1;
        &mut self.contours[last]
    }

    fn push_on_curve(&mut self, p: Vector2<f64>) {
        let c = self.current();
        if c.points.last() != Some(&p) {
            c.points.push(p);
            c.marked.push((p, true));
        }
    }
}

impl ttf_parser::OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        let p = self.point(x, y);
        self.contours.push(GlyphContour {
            points: vec![p],
            marked: vec![(p, true)],
            outline: vec![p],
        });
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.point(x, y);
        self.current().outline.push(p);
        self.push_on_curve(p);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (c, p) = (self.point(x1, y1), self.point(x, y));
        self.current().marked.push((c, false));
        let start = *self.current().outline.last().unwrap_or(&p);
        for k in 1..=QUAD_SAMPLES {
            let t = k as f64 / QUAD_SAMPLES as f64;
            let s = 1.0 - t;
            let q = start * (s * s) + c * (2.0 * s * t) + p * (t * t);
            self.current().outline.push(q);
        }
        self.push_on_curve(p);
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (c1, c2, p) = (self.point(x1, y1), self.point(x2, y2), self.point(x, y));
        self.current().marked.extend([(c1, false), (c2, false)]);
        let start = *self.current().outline.last().unwrap_or(&p);
        for k in 1..=QUAD_SAMPLES {
            let t = k as f64 / QUAD_SAMPLES as f64;
            let s = 1.0 - t;
            let q = start * (s * s * s)
                + c1 * (3.0 * s * s * t)
                + c2 * (3.0 * s * t * t)
                + p * (t * t * t);
            self.current().outline.push(q);
        }
        self.push_on_curve(p);
    }

    fn close(&mut self) {
        let c = self.current();
        if let Some(&first) = c.outline.first() {
            if c.outline.last() != Some(&first) {
                c.outline.push(first);
            }
        }
        if c.points.len() > 1 && c.points.last() == c.points.first() {
            c.points.pop();
            c.marked.pop();
        }
    }
}
