//! Outlines from SVG documents, as a viewer shows them (feature `svg`).
//!
//! The document is read by the resvg project's parser, [`usvg`] (XML by [`roxmltree`], CSS
//! `style` attributes and `<style>` sheets, `transform`s, units `mm` `cm` `in` `pt` `pc` `%`
//! at 96 px to the inch, `<use>` and `<symbol>`, nested `<svg>`, `<switch>`, markers, the
//! basic shapes as paths, `display` and `visibility`). What it resolves to is read here:
//!
//! - **The outline** is the geometry of every path a viewer fills or strokes: a filled path's
//!   contours are the boundary of its fill (an open subpath of a filled path is closed, as the
//!   fill closes it); a path only stroked gives its **centre line** (the stroke's width is not
//!   an outline), and so does a filled subpath along one line, which has no inside (a `<line>`:
//!   its stroke's centre line if it is stroked, nothing otherwise). Paths with neither fill nor stroke, hidden ones (`visibility`, `display`),
//!   those under a group of opacity 0 and whatever is not drawn where it stands (`<defs>`,
//!   `<symbol>` until used, `<clipPath>`, `<mask>`, `<marker>` until placed, `<pattern>`
//!   contents) are not outline.
//! - **Coordinates**: the root `viewBox`'s user units (the document's own units when it has no
//!   `viewBox`), `y` pointing **up** (SVG's `y` points down; the reader turns it so figures
//!   are not upside down).
//! - **Precision**: the parser holds the geometry in single precision (`f32`), about 6·10⁻⁸ of
//!   the coordinates' size; it replaces arcs (`A`, `<circle>`, `<ellipse>`, rounded corners of
//!   `<rect>`) by cubic Béziers, at least four to a full turn, which lie within
//!   [`ARC_APPROXIMATION`] of the arc's larger radius of the exact ellipse (measured in the
//!   tests), and at most 0.1 of the local units from it. The Béziers are flattened within the
//!   tolerance given, after every transform, so each polyline lies within that tolerance of
//!   the parser's curves.
//! - **Refused** with [`Error::Parse`] at the line and column of the element: a `<text>`
//!   (text is not read as an outline: convert it to paths in the drawing program, e.g.
//!   Inkscape's *Path ▸ Object to Path*), an `<image>` or `<foreignObject>` (no outline), a
//!   `<use>` of another file (not loaded), path
//!   data, `points`, a `transform` or a shape's length that cannot be read (a viewer draws a
//!   path up to its first error and skips a bad transform; a reader of outlines refuses
//!   them), a `mask` on drawn content, a clip path clipped again, a document with nothing
//!   drawn. Filters (blur, shadows) are not read: they change colours, not outlines.
//! - **Clips** (`clip-path`, and the viewport of a nested `<svg>`, a `<symbol>` or a marker)
//!   are applied: a clip that leaves every drawn point inside it changes nothing; otherwise a
//!   filled path's outline is the boundary of its fill's intersection with the clip region
//!   (the union of the clip's paths, each by its `clip-rule`), and a stroked path's is its
//!   centre line cut at the region's edge, by the polygon boolean operations of i_overlay (on
//!   an `i64` grid over the shapes' extent). The size of clipped content is its extent cut to
//!   the clip's box.

use super::clip::FillRule;
use super::flatten::{Contour, Flattener};
use super::svg_limits::{
    check_attribute, check_css, check_entities, check_placement, element_name, refuse_at,
};
use super::svg_path::{contours_from_svg_path, normalized_path_data};
use crate::error::{Error, Result};
use nalgebra::{Matrix2, Vector2};
use std::str::FromStr;
use usvg::roxmltree;

/// The largest distance between the parser's cubic Béziers and the exact arc they replace,
/// as a fraction of the arc's larger radius: `2.73·10⁻⁴`, the error of the classical
/// four-cubics circle (kurbo's arc approximation, which the parser uses, takes at least four
/// pieces to a full turn; the per-curve bound the reader states is
/// [`arc_approximation_bound`]). Measured against the exact ellipse in
/// `tests/svg_documents.rs`.
pub const ARC_APPROXIMATION: f64 = 2.73e-4;

const WHAT: &str = "SVG document";
const SVG_NS: &str = "http://www.w3.org/2000/svg";

/// How a stroke's ends are drawn (SVG's `stroke-linecap`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineCap {
    /// `butt`.
    Butt,
    /// `round`.
    Round,
    /// `square`.
    Square,
}

/// How a stroke's corners are drawn (SVG's `stroke-linejoin`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineJoin {
    /// `miter`.
    Miter,
    /// `miter-clip`.
    MiterClip,
    /// `round`.
    Round,
    /// `bevel`.
    Bevel,
}

/// A path's stroke, lengths in viewBox units (the transform's mean stretch `√|det|` applied).
#[derive(Debug, Clone, PartialEq)]
pub struct Stroke {
    /// The width.
    pub width: f64,
    /// The ends.
    pub cap: LineCap,
    /// The corners.
    pub join: LineJoin,
    /// The miter limit (a ratio).
    pub miter_limit: f64,
    /// The dash pattern, if dashed.
    pub dashes: Option<Vec<f64>>,
}

/// One path as a viewer draws it: its contours (viewBox units, `y` up), its fill rule if it
/// is filled and its stroke if it is stroked.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawnPath {
    /// The element's `id` (empty if it has none).
    pub id: String,
    /// The flattened contours.
    pub contours: Vec<Contour>,
    /// The fill rule, if the path is filled.
    pub fill: Option<FillRule>,
    /// The stroke, if the path is stroked.
    pub stroke: Option<Stroke>,
}

/// The outline of an SVG document: every drawn path's contours, in document order (module
/// docs), flattened within `tolerance`.
///
/// ```
/// use splinelab::input::svg_document::contours_from_svg_document;
/// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">
///   <g transform="translate(2 3)"><rect width="4" height="3"/></g>
///   <rect width="10" height="10" fill="none"/>
/// </svg>"#;
/// let c = contours_from_svg_document(svg, 0.01)?;
/// assert_eq!(c.len(), 1); // the invisible square is no outline
/// assert!(c[0].closed);
/// assert!(c[0].points.iter().any(|p| (p.x - 6.0).abs() < 1e-6 && (p.y + 6.0).abs() < 1e-6));
/// let err = contours_from_svg_document("<svg xmlns='http://www.w3.org/2000/svg'>\n<path d='M 0 0 L 1'/></svg>", 0.01).unwrap_err();
/// assert_eq!(err.to_string(), "SVG document, line 2, column 19: L is short of numbers");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// As [`read_svg_document`].
pub fn contours_from_svg_document(text: &str, tolerance: f64) -> Result<Vec<Contour>> {
    Ok(read_svg_document(text, tolerance)?.into_contours())
}

/// An SVG document's drawn paths and the distance within which they hold.
#[derive(Debug, Clone, PartialEq)]
pub struct SvgOutline {
    /// The drawn paths, in document order.
    pub paths: Vec<DrawnPath>,
    /// The distance within which every polyline lies of the curves the document describes:
    /// the flattening tolerance, plus, if the document has arcs (path `A` commands,
    /// `<circle>`, `<ellipse>`, rounded `<rect>`), the bound of the parser's cubic
    /// approximation of them ([`arc_approximation_bound`] over every cubic drawn); single
    /// precision rounding aside (module docs).
    pub within: f64,
    /// The bound of the parser's approximation of arcs alone (0 without arcs): the part of
    /// `within` that no flattening tolerance reduces.
    pub arcs: f64,
}

impl SvgOutline {
    /// Every drawn path's contours, in document order.
    pub fn into_contours(self) -> Vec<Contour> {
        self.paths.into_iter().flat_map(|p| p.contours).collect()
    }
}

/// Every path of an SVG document a viewer draws, with its fill and stroke (module docs),
/// flattened within `tolerance`: [`SvgDocument::parse`], then [`SvgDocument::outline`].
///
/// # Errors
/// As [`SvgDocument::parse`] and [`SvgDocument::outline`].
pub fn read_svg_document(text: &str, tolerance: f64) -> Result<SvgOutline> {
    crate::error::positive("SVG flattening tolerance", tolerance)?;
    SvgDocument::parse(text)?.outline(tolerance)
}

/// An SVG document read once (module docs), whose outline can then be measured
/// ([`SvgDocument::extent`]) and flattened ([`SvgDocument::outline`]) without reading it again.
///
/// ```
/// use splinelab::input::svg_document::SvgDocument;
/// // a lens of two cubics whose ends lie on one line: its size is that of its curves
/// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 16">
///   <path d="M2 8C6 2 10 2 14 8C10 14 6 14 2 8Z"/></svg>"#;
/// let doc = SvgDocument::parse(svg)?;
/// let extent = doc.extent()?;
/// assert!((extent.height - 9.0).abs() < 1e-6 && (extent.width - 12.0).abs() < 1e-6);
/// let outline = doc.outline(1e-3 * extent.size())?;
/// assert_eq!(outline.paths.len(), 1);
/// # Ok::<(), splinelab::Error>(())
/// ```
pub struct SvgDocument<'a> {
    text: &'a str,
    doc: roxmltree::Document<'a>,
    tree: usvg::Tree,
    to_user: Affine,
    has_arcs: bool,
}

impl std::fmt::Debug for SvgDocument<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SvgDocument")
            .field("bytes", &self.text.len())
            .field("has_arcs", &self.has_arcs)
            .finish_non_exhaustive()
    }
}

/// The extent of a document's drawn curves (not of their chords) in user units, and the
/// bound of the parser's approximation of its arcs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SvgExtent {
    /// The width of the bounding box of the drawn curves.
    pub width: f64,
    /// Its height.
    pub height: f64,
    /// The bound of the parser's cubics for the document's arcs
    /// ([`arc_approximation_bound`] over every drawn cubic; 0 without arcs).
    pub arcs: f64,
}

impl SvgExtent {
    /// The larger side of the bounding box.
    pub fn size(&self) -> f64 {
        self.width.max(self.height)
    }
}

impl<'a> SvgDocument<'a> {
    /// Reads `text`: the bounds of [`super::svg_limits`] first (entities, numbers,
    /// transforms, style sheets), then the XML and the SVG parser, which opens no file and
    /// loads no image a document names.
    ///
    /// # Errors
    /// [`Error::Parse`] at the document's line and column for XML that cannot be read, for
    /// what the module docs list and beyond the bounds of [`super::svg_limits`];
    /// [`Error::TooLarge`] beyond the parser's element limit.
    pub fn parse(text: &'a str) -> Result<SvgDocument<'a>> {
        check_entities(text)?;
        let doc = roxmltree::Document::parse_with_options(text, xml_options()).map_err(|e| {
            let pos = e.pos();
            Error::Parse {
                what: WHAT,
                line: pos.row as usize,
                column: pos.col as usize,
                message: format!("not well-formed XML: {e}"),
            }
        })?;
        let has_arcs = check_elements(&doc)?;
        check_css(&doc)?;
        check_placement(&doc)?;
        // what the parser reads: path data whose commas the path grammar takes, each byte in
        // its place (svg_path::normalized_path_data)
        let tree = match normalized_document(&doc) {
            Some(t) => {
                let reparsed =
                    roxmltree::Document::parse_with_options(&t, xml_options()).map_err(|e| {
                        refuse_at(text, 0, format!("not well-formed XML once normalised: {e}"))
                    })?;
                svg_tree(&reparsed, text)?
            }
            None => svg_tree(&doc, text)?,
        };
        let to_user = viewport_to_user(&doc, &tree).ok_or_else(|| {
            refuse_at(
                text,
                doc.root_element().range().start,
                "the viewBox or the document's size cannot be inverted".into(),
            )
        })?;
        Ok(SvgDocument {
            text,
            doc,
            tree,
            to_user,
            has_arcs,
        })
    }

    /// The bounding box of the drawn curves (their extrema, not their end points) and the
    /// bound of the parser's arcs.
    ///
    /// # Errors
    /// As [`SvgDocument::outline`], but for the tolerance.
    pub fn extent(&self) -> Result<SvgExtent> {
        let mut reader = self.reader(None);
        reader.group(self.tree.root(), &self.to_user)?;
        reader.nothing_drawn()?;
        let (lo, hi) = reader.bounds;
        Ok(SvgExtent {
            width: hi.x - lo.x,
            height: hi.y - lo.y,
            arcs: reader.arc_bound,
        })
    }

    /// Every drawn path (module docs), flattened within `tolerance`.
    ///
    /// # Errors
    /// [`Error::NotPositive`] for a tolerance that is not positive and finite;
    /// [`Error::Parse`] at the element for what the module docs list, and, naming what was
    /// dropped and why, for a document that draws nothing; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`] points.
    pub fn outline(&self, tolerance: f64) -> Result<SvgOutline> {
        crate::error::positive("SVG flattening tolerance", tolerance)?;
        let mut reader = self.reader(Some(tolerance));
        reader.group(self.tree.root(), &self.to_user)?;
        reader.nothing_drawn()?;
        Ok(SvgOutline {
            within: tolerance + reader.arc_bound,
            arcs: reader.arc_bound,
            paths: reader.out,
        })
    }

    fn reader(&self, tolerance: Option<f64>) -> Reader<'_, 'a> {
        Reader {
            text: self.text,
            doc: &self.doc,
            tolerance,
            has_arcs: self.has_arcs,
            arc_bound: 0.0,
            bounds: EMPTY_BOX,
            dropped: Vec::new(),
            out: Vec::new(),
        }
    }
}

/// The XML parser's options: a document type's entities read (bounded before:
/// [`check_entities`]), at most [`crate::error::MAX_ELEMENTS`] nodes.
fn xml_options<'input>() -> roxmltree::ParsingOptions<'input> {
    roxmltree::ParsingOptions {
        allow_dtd: true,
        nodes_limit: u32::try_from(crate::error::MAX_ELEMENTS).unwrap_or(u32::MAX),
        ..roxmltree::ParsingOptions::default()
    }
}

/// The SVG parser's tree of `doc` (whose text is `text`, or a normalised copy of it with
/// every byte in its place).
fn svg_tree(doc: &roxmltree::Document, text: &str) -> Result<usvg::Tree> {
    usvg::Tree::from_xmltree(doc, &parser_options()).map_err(|e| match e {
        usvg::Error::ElementsLimitReached => Error::TooLarge {
            what: "SVG elements (with every <use> expanded)",
            got: 1_000_001,
            max: 1_000_000,
        },
        other => refuse_at(text, doc.root_element().range().start, other.to_string()),
    })
}

/// The parser's options: no file, URL or image a document names is resolved (`<image>` is
/// refused by name before the parser runs; a filter's `feImage` is not read, as filters are
/// not), no font is loaded.
fn parser_options() -> usvg::Options<'static> {
    usvg::Options {
        resources_dir: None,
        image_href_resolver: usvg::ImageHrefResolver {
            resolve_data: Box::new(|_, _, _| None),
            resolve_string: Box::new(|_, _| None),
        },
        ..usvg::Options::default()
    }
}

/// The document's text with every `d` attribute written as the reader reads it
/// ([`super::svg_path::normalized_path_data`], which keeps every byte in its place), if any
/// differs.
fn normalized_document(doc: &roxmltree::Document) -> Option<String> {
    let text = doc.input_text();
    let mut out: Option<String> = None;
    for node in doc.descendants().filter(|n| n.is_element()) {
        let Some(attr) = node
            .attributes()
            .find(|a| a.name() == "d" && a.namespace().is_none())
        else {
            continue;
        };
        let range = attr.range_value();
        if text.get(range.clone()) != Some(attr.value()) {
            continue;
        }
        if let std::borrow::Cow::Owned(fixed) = normalized_path_data(attr.value()) {
            out.get_or_insert_with(|| text.to_string())
                .replace_range(range, &fixed);
        }
    }
    out
}

/// A bound on the distance between a cubic Bézier `p` and the elliptical arc it replaces, if
/// it is the parser's approximation of one (kurbo's: pieces of at most a quarter turn, the
/// classical handles `4/3·tan(Δθ/4)`, in the ellipse's unit circle, mapped by the ellipse's
/// and the document's affine maps): `1.93·10⁻⁴·|p₃ − p₀| + 9.31·10⁻⁴·|B(½) − (p₀ + p₃)/2|`.
///
/// Why: on the unit circle a piece of sweep `Δθ ≤ π/2` misses the arc by at most `E(Δθ)`,
/// `E(π/2) = 2.7253·10⁻⁴`, increasing as `Δθ⁶`; its chord is `2·sin(Δθ/2)` along the
/// unit tangent `t` of its middle and its midpoint `B(½)` lies on the circle, `1 − cos(Δθ/2)`
/// from the chord along the normal `n`. An affine map `L` takes the radial error `E·r`, `r`
/// within a quarter turn of `n`, to at most `E·(|Lt| + |Ln|)`, and `|Lt|`, `|Ln|` are the
/// mapped chord and midpoint offset divided by those lengths; the two ratios
/// `E/(2 sin(Δθ/2))` and `E/(1 − cos(Δθ/2))` grow with `Δθ`, to `1.927·10⁻⁴` and `9.305·10⁻⁴`
/// at a quarter turn. Measured against the exact ellipse in `tests/svg_documents.rs`.
pub fn arc_approximation_bound(p: &[Vector2<f64>; 4]) -> f64 {
    let mid = (p[0] + p[3]) * 0.5;
    let half = (p[0] + (p[1] * 3.0) + (p[2] * 3.0) + p[3]) / 8.0;
    1.93e-4 * (p[3] - p[0]).norm() + 9.31e-4 * (half - mid).norm()
}

/// An affine map `x ↦ m·x + t` in double precision.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Affine {
    m: Matrix2<f64>,
    t: Vector2<f64>,
}

impl Affine {
    fn of(ts: usvg::Transform) -> Affine {
        Affine {
            m: Matrix2::new(
                f64::from(ts.sx),
                f64::from(ts.kx),
                f64::from(ts.ky),
                f64::from(ts.sy),
            ),
            t: Vector2::new(f64::from(ts.tx), f64::from(ts.ty)),
        }
    }

    /// `self ∘ other`.
    fn then_inner(&self, other: &Affine) -> Affine {
        Affine {
            m: self.m * other.m,
            t: self.m * other.t + self.t,
        }
    }

    fn apply(&self, p: usvg::tiny_skia_path::Point) -> Vector2<f64> {
        self.m * Vector2::new(f64::from(p.x), f64::from(p.y)) + self.t
    }

    /// The mean stretch `√|det m|`.
    fn mean_stretch(&self) -> f64 {
        self.m.determinant().abs().sqrt()
    }
}

/// The map from the parser's coordinates (the viewport's, with the root `viewBox` applied)
/// back to the root `viewBox`'s user units, `y` turned up.
fn viewport_to_user(doc: &roxmltree::Document, tree: &usvg::Tree) -> Option<Affine> {
    let root = doc.root_element();
    let size = tree.size();
    let (w, h) = (f64::from(size.width()), f64::from(size.height()));
    let view_box = root
        .attribute("viewBox")
        .and_then(|v| svgtypes::ViewBox::from_str(v).ok())
        .filter(|v| v.w > 0.0 && v.h > 0.0 && v.w.is_finite() && v.h.is_finite());
    let aspect = root
        .attribute("preserveAspectRatio")
        .and_then(|v| svgtypes::AspectRatio::from_str(v).ok())
        .unwrap_or_default();
    let (x, y, vw, vh) = match view_box {
        Some(v) => (v.x, v.y, v.w, v.h),
        None => (0.0, 0.0, w, h),
    };
    // the viewBox → viewport map, as SVG 1.1 §7.8 and the parser compute it (in f32 there)
    let (mut sx, mut sy) = (w / vw, h / vh);
    let (mut tx, mut ty) = (0.0, 0.0);
    if aspect.align != svgtypes::Align::None {
        let s = if aspect.slice { sx.max(sy) } else { sx.min(sy) };
        (sx, sy) = (s, s);
        let (free_x, free_y) = (w - vw * s, h - vh * s);
        use svgtypes::Align::*;
        tx = match aspect.align {
            XMidYMin | XMidYMid | XMidYMax => free_x / 2.0,
            XMaxYMin | XMaxYMid | XMaxYMax => free_x,
            _ => 0.0,
        };
        ty = match aspect.align {
            XMinYMid | XMidYMid | XMaxYMid => free_y / 2.0,
            XMinYMax | XMidYMax | XMaxYMax => free_y,
            _ => 0.0,
        };
    }
    // viewport = s·(user − origin) + t  ⇒  user = (viewport − t)/s + origin; then y ↦ −y
    if !(sx > 0.0 && sy > 0.0 && sx.is_finite() && sy.is_finite()) {
        return None;
    }
    Some(Affine {
        m: Matrix2::new(1.0 / sx, 0.0, 0.0, -1.0 / sy),
        t: Vector2::new(x - tx / sx, -(y - ty / sy)),
    })
}

/// A box that holds nothing (its low corner above its high one).
const EMPTY_BOX: (Vector2<f64>, Vector2<f64>) = (
    Vector2::new(f64::INFINITY, f64::INFINITY),
    Vector2::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
);

struct Reader<'a, 'input> {
    text: &'a str,
    doc: &'a roxmltree::Document<'input>,
    /// The flattening tolerance; `None` measures only (bounds and arcs, no contours).
    tolerance: Option<f64>,
    /// Whether the document has arcs, which the parser replaces by cubics.
    has_arcs: bool,
    /// The largest [`arc_approximation_bound`] of a drawn cubic (if `has_arcs`).
    arc_bound: f64,
    /// The bounding box of the drawn curves.
    bounds: (Vector2<f64>, Vector2<f64>),
    /// What was not drawn, and why (for a document that draws nothing).
    dropped: Vec<String>,
    out: Vec<DrawnPath>,
}

impl Reader<'_, '_> {
    /// Refuses a document that draws nothing, naming what was dropped and why.
    fn nothing_drawn(&self) -> Result<()> {
        // flattened, something must be left once the clips are applied
        let left = self.tolerance.is_none() || !self.out.is_empty();
        if self.bounds.0.x <= self.bounds.1.x && left {
            return Ok(());
        }
        let why = match self.dropped.len() {
            0 => "no visible path, shape or use of one".to_string(),
            n => {
                let shown: Vec<&str> = self.dropped.iter().take(3).map(String::as_str).collect();
                let more = if n > 3 {
                    format!("; {} more", n - 3)
                } else {
                    String::new()
                };
                format!("{}{more}", shown.join("; "))
            }
        };
        Err(refuse_at(
            self.text,
            self.doc.root_element().range().start,
            format!("the document draws nothing: {why}"),
        ))
    }

    /// `<path id="a">` (or the tag alone) for the element with this id.
    fn named(&self, id: &str) -> String {
        match self.element(id) {
            Some(node) => element_name(node),
            None if !id.is_empty() => format!("the path {id:?}"),
            None => "a path".to_string(),
        }
    }

    /// Reads the drawn paths of `group`, whose coordinates `ts` maps to user units.
    fn group(&mut self, group: &usvg::Group, ts: &Affine) -> Result<()> {
        let ts = ts.then_inner(&Affine::of(group.transform()));
        if group.opacity().get() <= 0.0 {
            let named = self.named(group.id());
            self.dropped.push(format!("{named} has opacity 0"));
            return Ok(());
        }
        if let Some(mask) = group.mask() {
            // the masked element, else the mask
            let at = self
                .element(group.id())
                .or_else(|| self.referencing("mask", mask.id()))
                .or_else(|| self.element(mask.id()));
            return Err(self.refuse_node(
                at,
                "a mask changes what is drawn: the outline of masked content is not read (apply the mask in the drawing program, or remove it)",
            ));
        }
        let first = self.out.len();
        // the bounds of clipped content are cut to the clip's box below
        let outer = self.bounds;
        if group.clip_path().is_some() {
            self.bounds = EMPTY_BOX;
        }
        for child in group.children() {
            match child {
                usvg::Node::Group(g) => self.group(g, &ts)?,
                usvg::Node::Path(p) => self.path(p, &ts)?,
                usvg::Node::Image(i) => {
                    return Err(self.refuse_id(i.id(), "an image has no outline"));
                }
                // the parser is built without text (module docs); text elements are refused
                // before it runs
                _ => {}
            }
        }
        if let Some(clip) = group.clip_path() {
            self.apply_clip(clip, &ts, first)?;
            let clip_ts = ts.then_inner(&Affine::of(clip.transform()));
            let (lo, hi) = self.region_box(clip.root(), &clip_ts);
            let inner = self.bounds;
            self.bounds = outer;
            let (lo, hi) = (inner.0.sup(&lo), inner.1.inf(&hi));
            if lo.x <= hi.x && lo.y <= hi.y {
                self.include((lo, hi));
            }
        }
        Ok(())
    }

    /// The bounding box of the curves of a clip path's visible paths (their extrema).
    fn region_box(&self, group: &usvg::Group, ts: &Affine) -> (Vector2<f64>, Vector2<f64>) {
        let mut b = EMPTY_BOX;
        for child in group.children() {
            let (lo, hi) = match child {
                usvg::Node::Group(g) => {
                    self.region_box(g, &ts.then_inner(&Affine::of(g.transform())))
                }
                usvg::Node::Path(p) if p.is_visible() => subpaths(p.data(), ts)
                    .iter()
                    .fold(EMPTY_BOX, |(lo, hi), s| (lo.inf(&s.lo), hi.sup(&s.hi))),
                _ => continue,
            };
            b = (b.0.inf(&lo), b.1.sup(&hi));
        }
        b
    }

    /// Reads one path if it is drawn.
    fn path(&mut self, path: &usvg::Path, ts: &Affine) -> Result<()> {
        let fill = path
            .fill()
            .filter(|f| f.opacity().get() > 0.0)
            .map(|f| match f.rule() {
                usvg::FillRule::NonZero => FillRule::NonZero,
                usvg::FillRule::EvenOdd => FillRule::EvenOdd,
            });
        let stretch = ts.mean_stretch();
        let stroke = path
            .stroke()
            .filter(|s| s.opacity().get() > 0.0)
            .map(|s| Stroke {
                width: f64::from(s.width().get()) * stretch,
                cap: match s.linecap() {
                    usvg::LineCap::Butt => LineCap::Butt,
                    usvg::LineCap::Round => LineCap::Round,
                    usvg::LineCap::Square => LineCap::Square,
                },
                join: match s.linejoin() {
                    usvg::LineJoin::Miter => LineJoin::Miter,
                    usvg::LineJoin::MiterClip => LineJoin::MiterClip,
                    usvg::LineJoin::Round => LineJoin::Round,
                    usvg::LineJoin::Bevel => LineJoin::Bevel,
                },
                miter_limit: f64::from(s.miterlimit().get()),
                dashes: s
                    .dasharray()
                    .map(|d| d.iter().map(|&x| f64::from(x) * stretch).collect()),
            });
        if fill.is_none() && stroke.is_none() {
            let named = self.named(path.id());
            self.dropped.push(format!(
                "{named} has neither a visible fill nor a visible stroke"
            ));
            return Ok(());
        }
        if !path.is_visible() {
            let named = self.named(path.id());
            self.dropped.push(format!("{named} is hidden"));
            return Ok(());
        }
        let subpaths = subpaths(path.data(), ts);
        if subpaths
            .iter()
            .any(|s| !s.points.iter().all(|p| p.iter().all(|x| x.is_finite())))
        {
            return Err(self.refuse_id(
                path.id(),
                "its coordinates overflow once transformed: not read",
            ));
        }
        // a filled subpath on one line has no inside (an SVG <line> is filled so): a viewer
        // draws only its stroke, whose outline is its centre line, or nothing; decided on the
        // curves' control points, whatever the tolerance
        let flat: Vec<bool> = subpaths
            .iter()
            .map(|s| fill.is_some() && encloses_nothing(&s.points))
            .collect();
        if stroke.is_none() && flat.iter().all(|&f| f) {
            let named = self.named(path.id());
            self.dropped.push(format!(
                "{named} is filled, not stroked, and lies along one line: it has no inside"
            ));
            return Ok(());
        }
        let mut drawn = false;
        for (sub, &f) in subpaths.iter().zip(&flat) {
            if !f || stroke.is_some() {
                drawn = true;
                self.include((sub.lo, sub.hi));
            }
        }
        if !drawn {
            return Ok(());
        }
        if self.has_arcs {
            self.arc_bound = self.arc_bound.max(arcs_bound(path.data(), ts));
        }
        let Some(tolerance) = self.tolerance else {
            return Ok(());
        };
        let contours = self
            .flatten(path.data(), ts, fill.is_some(), tolerance)
            .map_err(|e| self.place_id(path.id(), e))?;
        let contours = if flat.iter().any(|&f| f) {
            let lines = self
                .flatten(path.data(), ts, false, tolerance)
                .map_err(|e| self.place_id(path.id(), e))?;
            pick_subpaths(contours, lines, &flat, stroke.is_some())
        } else {
            contours
        };
        self.out.push(DrawnPath {
            id: path.id().to_string(),
            contours,
            fill,
            stroke,
        });
        Ok(())
    }

    /// Widens the bounds to the box `(lo, hi)`.
    fn include(&mut self, (lo, hi): (Vector2<f64>, Vector2<f64>)) {
        self.bounds = (self.bounds.0.inf(&lo), self.bounds.1.sup(&hi));
    }

    /// The contours of `data` mapped by `ts`, flattened within the tolerance, one a subpath; each subpath
    /// closed if `close_all` (a fill closes it).
    fn flatten(
        &self,
        data: &usvg::tiny_skia_path::Path,
        ts: &Affine,
        close_all: bool,
        tolerance: f64,
    ) -> Result<Vec<Contour>> {
        use usvg::tiny_skia_path::PathSegment as S;
        let mut pen = Flattener::new(tolerance)?;
        let mut open = false;
        for segment in data.segments() {
            match segment {
                S::MoveTo(p) => {
                    if close_all && open {
                        pen.close();
                    }
                    pen.move_to(ts.apply(p))?;
                    open = true;
                }
                S::LineTo(p) => pen.line_to(ts.apply(p))?,
                S::QuadTo(c, p) => pen.quad_to(ts.apply(c), ts.apply(p))?,
                S::CubicTo(c1, c2, p) => pen.cubic_to(ts.apply(c1), ts.apply(c2), ts.apply(p))?,
                S::Close => {
                    pen.close();
                    open = false;
                }
            }
        }
        if close_all && open {
            pen.close();
        }
        Ok(pen.finish())
    }

    /// Applies a clip path to every path drawn since `first` (module docs): nothing changes
    /// where it leaves their contours whole; otherwise a filled path becomes the boundary of
    /// its fill's intersection with the clip region, and a stroked one its centre line's
    /// parts inside the region ([`super::clip`], i_overlay's boolean operations), a path
    /// left with nothing dropped, saying so. A clip path clipped again is refused, naming the
    /// clipped element and the clip.
    fn apply_clip(&mut self, clip: &usvg::ClipPath, ts: &Affine, first: usize) -> Result<()> {
        // a clip the document names, or the viewport the parser clips a nested <svg>, a
        // <symbol> or a marker to
        let what = if self.element(clip.id()).is_some() {
            format!("the clip path {:?}", clip.id())
        } else {
            "the viewport of a nested <svg>, <symbol> or marker".to_string()
        };
        if clip.clip_path().is_some() {
            // the element that names the clip, else the first clipped path with an id, else
            // the clip
            let at = self
                .referencing("clip-path", clip.id())
                .or_else(|| self.out[first..].iter().find_map(|p| self.element(&p.id)))
                .or_else(|| self.element(clip.id()));
            return Err(self.refuse_node(
                at,
                &format!("{what} is clipped again: not read (simplify the clipping in the drawing program)"),
            ));
        }
        let Some(tolerance) = self.tolerance else {
            return Ok(());
        };
        let mut region: Vec<(Vec<Contour>, FillRule)> = Vec::new();
        let ts = ts.then_inner(&Affine::of(clip.transform()));
        self.clip_region(clip.root(), &ts, tolerance, &mut region)?;
        let drawn: Vec<&Contour> = self.out[first..]
            .iter()
            .flat_map(|p| p.contours.iter())
            .collect();
        if super::clip::contains(&region, &drawn).is_ok() {
            return Ok(());
        }
        let shapes = super::clip::region_shapes(&region);
        for path in self.out.split_off(first) {
            let mut kept = Vec::new();
            if let Some(rule) = path.fill {
                let contours = super::clip::clipped_fill(&path.contours, rule, &shapes);
                if !contours.is_empty() {
                    kept.push(DrawnPath {
                        id: path.id.clone(),
                        contours,
                        fill: Some(rule),
                        stroke: None,
                    });
                }
            }
            if let Some(stroke) = &path.stroke {
                let contours = super::clip::clipped_lines(&path.contours, &shapes);
                if !contours.is_empty() {
                    kept.push(DrawnPath {
                        id: path.id.clone(),
                        contours,
                        fill: None,
                        stroke: Some(stroke.clone()),
                    });
                }
            }
            if kept.is_empty() {
                let named = self.named(&path.id);
                self.dropped.push(format!("{named} lies outside {what}"));
            }
            self.out.extend(kept);
        }
        Ok(())
    }

    /// The filled region of a clip path's children, as contours with their fill rules.
    fn clip_region(
        &self,
        group: &usvg::Group,
        ts: &Affine,
        tolerance: f64,
        out: &mut Vec<(Vec<Contour>, FillRule)>,
    ) -> Result<()> {
        for child in group.children() {
            match child {
                usvg::Node::Group(g) => {
                    if g.clip_path().is_some() {
                        return Err(self.refuse_id(
                            g.id(),
                            "a clip path whose content is clipped again is not read",
                        ));
                    }
                    self.clip_region(
                        g,
                        &ts.then_inner(&Affine::of(g.transform())),
                        tolerance,
                        out,
                    )?
                }
                usvg::Node::Path(p) if p.is_visible() => {
                    let rule = match p.fill().map(|f| f.rule()) {
                        Some(usvg::FillRule::EvenOdd) => FillRule::EvenOdd,
                        _ => FillRule::NonZero,
                    };
                    let contours = self
                        .flatten(p.data(), ts, true, tolerance)
                        .map_err(|e| self.place_id(p.id(), e))?;
                    out.push((contours, rule));
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// The source element with this `id`, if the document has exactly one.
    fn element(&self, id: &str) -> Option<roxmltree::Node<'_, '_>> {
        if id.is_empty() {
            return None;
        }
        let mut found = self
            .doc
            .descendants()
            .filter(|n| n.is_element() && n.attribute("id") == Some(id));
        let first = found.next()?;
        found.next().is_none().then_some(first)
    }

    /// The one element whose `property` (`clip-path`, `mask`; attribute or style) names `#id`.
    fn referencing(&self, property: &str, id: &str) -> Option<roxmltree::Node<'_, '_>> {
        if id.is_empty() {
            return None;
        }
        let url = format!("#{id})");
        let names_it = |v: &str| v.replace(['"', '\'', ' '], "").contains(&url);
        let mut found = self.doc.descendants().filter(|n| {
            n.attribute(property).is_some_and(names_it)
                || n.attribute("style")
                    .is_some_and(|v| v.contains(property) && names_it(v))
        });
        let first = found.next()?;
        found.next().is_none().then_some(first)
    }

    fn refuse_id(&self, id: &str, message: &str) -> Error {
        self.refuse_node(self.element(id), message)
    }

    /// A refusal placed at `node` and naming it (`<rect id="a">: …`), or at the root.
    fn refuse_node(&self, node: Option<roxmltree::Node<'_, '_>>, message: &str) -> Error {
        let Some(node) = node else {
            return refuse_at(
                self.text,
                self.doc.root_element().range().start,
                message.to_string(),
            );
        };
        let named = element_name(node);
        refuse_at(self.text, node.range().start, format!("{named}: {message}"))
    }

    /// A flattening refusal placed at the element `id` (or the root).
    fn place_id(&self, id: &str, e: Error) -> Error {
        match e {
            Error::Parse { message, .. } => self.refuse_id(id, &message),
            other => other,
        }
    }
}

/// The largest [`arc_approximation_bound`] of the cubics of `data` mapped by `ts`.
fn arcs_bound(data: &usvg::tiny_skia_path::Path, ts: &Affine) -> f64 {
    use usvg::tiny_skia_path::PathSegment as S;
    let mut last = Vector2::zeros();
    let mut start = Vector2::zeros();
    let mut bound = 0.0f64;
    for segment in data.segments() {
        last = match segment {
            S::MoveTo(p) => {
                start = ts.apply(p);
                start
            }
            S::LineTo(p) | S::QuadTo(_, p) => ts.apply(p),
            S::CubicTo(c1, c2, p) => {
                let q = [last, ts.apply(c1), ts.apply(c2), ts.apply(p)];
                bound = bound.max(arc_approximation_bound(&q));
                q[3]
            }
            S::Close => start,
        };
    }
    bound
}

/// Refuses, before the parser runs, what it would skip or draw only in part (module docs);
/// says whether the document has arcs (path `A`, circles, ellipses, rounded rectangles).
fn check_elements(doc: &roxmltree::Document) -> Result<bool> {
    let mut arcs = false;
    let text = doc.input_text();
    let root = doc.root_element();
    if root.tag_name().name() != "svg" || root.tag_name().namespace() != Some(SVG_NS) {
        return Err(refuse_at(
            text,
            root.range().start,
            format!(
                "the root element is <{}> in the namespace {:?}, not SVG's <svg> (xmlns=\"{SVG_NS}\")",
                root.tag_name().name(),
                root.tag_name().namespace().unwrap_or("")
            ),
        ));
    }
    for node in doc.descendants().filter(|n| n.is_element()) {
        if node.tag_name().namespace() != Some(SVG_NS) {
            continue;
        }
        let at = node.range().start;
        let refuse = |message: String| refuse_at(text, at, message);
        match node.tag_name().name() {
            "text" => {
                return Err(refuse(
                    "a <text> element: text is not read as an outline (convert it to paths in the drawing program, e.g. Inkscape's Path ▸ Object to Path, or remove it)".into(),
                ))
            }
            "image" => return Err(refuse("an <image> has no outline".into())),
            "circle" | "ellipse" => arcs = true,
            "rect" => arcs |= node.has_attribute("rx") || node.has_attribute("ry"),
            "path" => {
                arcs |= node
                    .attribute("d")
                    .is_some_and(|d| d.contains(['A', 'a']))
            }
            "foreignObject" => {
                return Err(refuse("a <foreignObject> has no outline".into()))
            }
            "use" => {
                let href = node
                    .attribute(("http://www.w3.org/1999/xlink", "href"))
                    .or_else(|| node.attribute("href"))
                    .unwrap_or("");
                if !href.trim_start().starts_with('#') && !href.trim().is_empty() {
                    return Err(refuse(format!(
                        "a <use> of another file ({href:?}) is not read: copy what it shows into this document"
                    )));
                }
            }
            _ => {}
        }
        for attr in node.attributes() {
            if attr.namespace().is_some() {
                continue;
            }
            let value = attr.value();
            // the value's text as written: equal to the value unless it holds references
            let value_at = attr.range_value().start;
            let verbatim = text.get(attr.range_value()) == Some(value);
            let placed = |offset: usize, message: String| {
                let at = if verbatim {
                    value_at + offset
                } else {
                    value_at
                };
                refuse_at(text, at, message)
            };
            check_attribute(attr.name(), value, &placed)?;
            match (node.tag_name().name(), attr.name()) {
                ("path", "d") => {
                    if let Err(e) = contours_from_svg_path(value, f64::MAX) {
                        let Error::Parse {
                            line,
                            column,
                            message,
                            ..
                        } = e
                        else {
                            return Err(e);
                        };
                        let offset = byte_at(value, line, column);
                        return Err(placed(offset, message));
                    }
                }
                ("polygon" | "polyline", "points") => {
                    if let Some(message) = points_error(value) {
                        return Err(placed(0, message));
                    }
                }
                (_, "transform") if svgtypes::Transform::from_str(value).is_err() => {
                    return Err(placed(0, format!("the transform {value:?} cannot be read")));
                }
                (
                    "rect" | "circle" | "ellipse" | "line" | "use" | "svg" | "symbol",
                    "x" | "y" | "width" | "height" | "rx" | "ry" | "cx" | "cy" | "r" | "x1" | "y1"
                    | "x2" | "y2",
                ) => {
                    let auto = value.trim() == "auto";
                    if !auto && svgtypes::Length::from_str(value).is_err() {
                        return Err(placed(
                            0,
                            format!("the length {}={value:?} cannot be read", attr.name()),
                        ));
                    }
                }
                _ => {}
            }
        }
    }
    Ok(arcs)
}

/// What is wrong with a `points` list, if anything: a number that cannot be read, or an odd
/// count of numbers.
fn points_error(value: &str) -> Option<String> {
    let mut count = 0usize;
    for n in svgtypes::NumberListParser::from(value) {
        if n.is_err() {
            return Some(format!("the points {value:?} cannot be read"));
        }
        count += 1;
    }
    (count % 2 == 1).then(|| format!("the points list has an odd count of numbers ({count})"))
}

/// The byte offset of 1-based `line` and `column` (characters) in `text`.
fn byte_at(text: &str, line: usize, column: usize) -> usize {
    let mut offset = 0;
    for (k, l) in text.split_inclusive('\n').enumerate() {
        if k + 1 == line {
            return offset
                + l.char_indices()
                    .nth(column.saturating_sub(1))
                    .map_or(l.len(), |(b, _)| b);
        }
        offset += l.len();
    }
    text.len()
}

/// One subpath of a drawn path, mapped to user units: its control points (end points
/// included, in order) and the bounding box of its curves.
struct Subpath {
    points: Vec<Vector2<f64>>,
    lo: Vector2<f64>,
    hi: Vector2<f64>,
}

impl Subpath {
    fn start(p: Vector2<f64>) -> Subpath {
        Subpath {
            points: vec![p],
            lo: p,
            hi: p,
        }
    }

    fn line_to(&mut self, p: Vector2<f64>) {
        self.points.push(p);
        (self.lo, self.hi) = (self.lo.inf(&p), self.hi.sup(&p));
    }

    /// A cubic from the last point: its box is its end points' and its extrema's, the roots
    /// in `(0, 1)` of each coordinate's derivative `3[(1−t)²(c₁−a) + 2t(1−t)(c₂−c₁) + t²(p−c₂)]`.
    fn cubic_to(&mut self, c1: Vector2<f64>, c2: Vector2<f64>, p: Vector2<f64>) {
        let a = self.points.last().copied().unwrap_or(c1);
        self.points.extend([c1, c2]);
        self.line_to(p);
        for k in 0..2 {
            let (d0, d1, d2) = (c1[k] - a[k], c2[k] - c1[k], p[k] - c2[k]);
            // d0(1−t)² + 2 d1 t(1−t) + d2 t² = (d0 − 2d1 + d2) t² + 2(d1 − d0) t + d0
            let (qa, qb, qc) = (d0 - 2.0 * d1 + d2, 2.0 * (d1 - d0), d0);
            let mut roots = [f64::NAN; 2];
            if qa.abs() > 1e-12 * (qb.abs() + qc.abs()) {
                let disc = qb * qb - 4.0 * qa * qc;
                if disc >= 0.0 {
                    let r = disc.sqrt();
                    roots = [(-qb - r) / (2.0 * qa), (-qb + r) / (2.0 * qa)];
                }
            } else if qb != 0.0 {
                roots[0] = -qc / qb;
            }
            for t in roots.into_iter().filter(|t| *t > 0.0 && *t < 1.0) {
                let u = 1.0 - t;
                let x = u * u * u * a[k]
                    + 3.0 * u * u * t * c1[k]
                    + 3.0 * u * t * t * c2[k]
                    + t * t * t * p[k];
                self.lo[k] = self.lo[k].min(x);
                self.hi[k] = self.hi[k].max(x);
            }
        }
    }
}

/// The subpaths of `data` mapped by `ts`; a subpath that draws nothing (a lone move) is left
/// out. Quadratics are written as the cubics they are.
fn subpaths(data: &usvg::tiny_skia_path::Path, ts: &Affine) -> Vec<Subpath> {
    use usvg::tiny_skia_path::PathSegment as S;
    let mut out: Vec<Subpath> = Vec::new();
    let mut current: Option<Subpath> = None;
    let mut flush = |current: &mut Option<Subpath>| {
        if let Some(c) = current.take().filter(|c| c.points.len() > 1) {
            out.push(c);
        }
    };
    for segment in data.segments() {
        if let S::MoveTo(p) = segment {
            flush(&mut current);
            current = Some(Subpath::start(ts.apply(p)));
            continue;
        }
        let Some(c) = current.as_mut() else { continue };
        match segment {
            S::LineTo(p) => c.line_to(ts.apply(p)),
            S::QuadTo(q, p) => {
                let a = c.points.last().copied().unwrap_or_else(|| ts.apply(q));
                let (q, p) = (ts.apply(q), ts.apply(p));
                c.cubic_to(a + (q - a) * (2.0 / 3.0), p + (q - p) * (2.0 / 3.0), p);
            }
            S::CubicTo(c1, c2, p) => c.cubic_to(ts.apply(c1), ts.apply(c2), ts.apply(p)),
            S::MoveTo(_) | S::Close => {}
        }
    }
    flush(&mut current);
    out
}

/// The contours of a filled path's subpaths (`filled`, each closed) or, for the subpaths
/// along one line (`flat`), their centre lines (`lines`) if the path is stroked, or nothing.
fn pick_subpaths(
    filled: Vec<Contour>,
    lines: Vec<Contour>,
    flat: &[bool],
    stroked: bool,
) -> Vec<Contour> {
    if filled.len() == flat.len() && lines.len() == flat.len() {
        return filled
            .into_iter()
            .zip(lines)
            .zip(flat)
            .filter_map(|((c, l), &f)| match f {
                false => Some(c),
                true => stroked.then_some(l),
            })
            .collect();
    }
    // the flattener left out a subpath the control points kept (one of zero length)
    filled
        .into_iter()
        .filter(|c| !encloses_nothing(&c.points))
        .collect()
}

/// Whether the points of a filled subpath all lie on one line (to a few units of rounding of
/// their extent), so that its fill covers nothing.
fn encloses_nothing(points: &[Vector2<f64>]) -> bool {
    let Some(&a) = points.first() else {
        return true;
    };
    // the point farthest from the first, and every point's distance off the line through both
    let Some(&b) = points
        .iter()
        .max_by(|p, q| (*p - a).norm().total_cmp(&(*q - a).norm()))
    else {
        return true;
    };
    let d = b - a;
    let length = d.norm();
    if length.is_nan() || length <= 0.0 {
        return true;
    }
    let slack = 64.0 * f64::EPSILON * points.iter().map(|p| p.amax()).fold(0.0, f64::max);
    points
        .iter()
        .all(|p| ((p - a).x * d.y - (p - a).y * d.x).abs() / length <= slack)
}
