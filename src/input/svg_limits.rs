//! The bounds an SVG document is held to before its parser runs, so that no document makes a
//! read take more than time and memory in proportion to its size (feature `svg`).
//!
//! - **Entities**: a document type's internal subset may declare general entities (drawing
//!   programs declare a few short ones, e.g. Illustrator's namespace entities); the text their
//!   references expand to, every reference counted with every reference inside its value, is
//!   at most [`MAX_ENTITY_EXPANSION`] bytes. Parameter entities (`<!ENTITY % …>`) and entity
//!   values holding a character reference to `&` or `%` (whose expansion would be read
//!   again as references) are refused. External entities are not loaded (their references
//!   are refused by the XML parser).
//! - **Numbers**: every number of path data (radii included), of `points`, of a `transform`
//!   (attribute or `style` declaration), of a `viewBox` and of a geometric length is at most
//!   [`MAX_SVG_NUMBER`] in magnitude: the parser holds geometry in single precision and
//!   replaces an arc by a number of cubics that grows with its radius.
//! - **Transforms**: the coordinates an element reaches through the transforms, `<use>`
//!   offsets and nested viewports above it are bounded before the parser runs
//!   ([`MAX_PLACED_COORDINATE`]); beyond, the element is refused by name (the parser would
//!   drop its overflowing geometry without a word). Once every `<use>` shows what it names,
//!   a document has at most [`MAX_SHOWN_ELEMENTS`] elements.
//! - **Style sheets**: the `<style>` elements hold at most [`MAX_CSS_RULES`] rules, and the
//!   rules times the elements they are matched against is at most [`MAX_CSS_WORK`].

use super::position;
use super::svg_path::normalized_path_data;
use crate::error::{Error, Result};
use std::collections::HashMap;
use std::str::FromStr;
use usvg::roxmltree;

/// The most bytes a document's entity references may expand to, in all: 1 MiB.
pub const MAX_ENTITY_EXPANSION: u64 = 1 << 20;

/// The largest magnitude of a number in an SVG document's geometry: `10⁹`.
pub const MAX_SVG_NUMBER: f64 = 1e9;

/// The largest magnitude a coordinate may reach through the transforms above it: `10³⁰`
/// (single precision ends at `3.4·10³⁸`; the margin keeps the parser's products finite).
pub const MAX_PLACED_COORDINATE: f64 = 1e30;

/// The most elements a document may show once every `<use>` shows what it names: 200 000.
pub const MAX_SHOWN_ELEMENTS: u64 = 200_000;

/// The most rules a document's style sheets may hold: 4 000 (the CSS parser's time grows
/// with the square of their number: 0.36 s for 5 000 rules, 1.5 s for 10 000, 123 s for
/// 100 000, measured here).
pub const MAX_CSS_RULES: u64 = 4_000;

/// The most style-sheet rules times elements a document may ask to match: `2·10⁷`.
pub const MAX_CSS_WORK: u64 = 20_000_000;

const WHAT: &str = "SVG document";

/// How a refusal names an element: `<path id="a">`, or `<path>` without an id.
pub(crate) fn element_name(node: roxmltree::Node) -> String {
    match node.attribute("id") {
        Some(id) => format!("<{} id={id:?}>", node.tag_name().name()),
        None => format!("<{}>", node.tag_name().name()),
    }
}

/// A refusal of the document placed at byte `at` of its text.
pub(crate) fn refuse_at(text: &str, at: usize, message: String) -> Error {
    let (line, column) = position(text, at);
    Error::Parse {
        what: WHAT,
        line,
        column,
        message,
    }
}

/// An entity declared in the internal subset: its name, its value (`None` for an external
/// one) and the byte where its declaration starts.
struct Entity<'a> {
    name: &'a str,
    value: Option<&'a str>,
    at: usize,
}

/// Refuses, before any parsing, a document whose entity references expand beyond
/// [`MAX_ENTITY_EXPANSION`] bytes, or whose entities cannot be bounded (module docs).
pub(crate) fn check_entities(text: &str) -> Result<()> {
    let Some(doctype) = text.find("<!DOCTYPE") else {
        return Ok(());
    };
    let Some((subset, end)) = internal_subset(text, doctype) else {
        return Ok(());
    };
    let entities = declarations(text, subset, end)?;
    if entities.is_empty() {
        return Ok(());
    }
    let by_name: HashMap<&str, &Entity> = entities.iter().map(|e| (e.name, e)).collect();
    let mut memo: HashMap<&str, u64> = HashMap::new();
    let mut total = 0u64;
    let mut worst: Option<(&Entity, u64)> = None;
    // every reference in the text (those inside the subset's values too: an over-count)
    for (at, name) in references(&text[end..]) {
        let Some(e) = by_name.get(name) else { continue };
        let size = expanded(e, &by_name, &mut memo, 0);
        total = total.saturating_add(size);
        if worst.is_none_or(|(_, s)| size > s) {
            worst = Some((e, size));
        }
        if total > MAX_ENTITY_EXPANSION {
            let (e, _) = worst.unwrap_or((e, size));
            return Err(refuse_at(
                text,
                e.at,
                format!(
                    "the entity references expand to more than {MAX_ENTITY_EXPANSION} bytes (&{}; alone expands to {size} bytes, referenced up to byte {}): not read",
                    e.name,
                    end + at
                ),
            ));
        }
    }
    Ok(())
}

/// The byte range of the internal subset of the `<!DOCTYPE` at `doctype` (between `[` and
/// `]`), if it has one.
fn internal_subset(text: &str, doctype: usize) -> Option<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut k = doctype + "<!DOCTYPE".len();
    let mut quote = None;
    while k < bytes.len() {
        let b = bytes[k];
        match quote {
            Some(q) if b == q => quote = None,
            Some(_) => {}
            None if b == b'"' || b == b'\'' => quote = Some(b),
            None if b == b'>' => return None,
            None if b == b'[' => break,
            None => {}
        }
        k += 1;
    }
    let start = k + 1;
    k = start;
    quote = None;
    while k < bytes.len() {
        let b = bytes[k];
        match quote {
            Some(q) if b == q => quote = None,
            Some(_) => {}
            None if text[k..].starts_with("<!--") => {
                k = text[k..].find("-->").map_or(bytes.len(), |e| k + e + 2);
            }
            None if b == b'"' || b == b'\'' => quote = Some(b),
            None if b == b']' => return Some((start, k)),
            None => {}
        }
        k += 1;
    }
    Some((start.min(bytes.len()), bytes.len()))
}

/// The general entities declared in `text[start..end]`.
fn declarations(text: &str, start: usize, end: usize) -> Result<Vec<Entity<'_>>> {
    let mut out = Vec::new();
    let mut k = start;
    while let Some(found) = text[k..end].find("<!ENTITY") {
        let at = k + found;
        let rest = text[at + "<!ENTITY".len()..end].trim_start();
        if rest.starts_with('%') {
            return Err(refuse_at(
                text,
                at,
                "a parameter entity (<!ENTITY % …>) is not read".into(),
            ));
        }
        let name_len = rest
            .find(|c: char| c.is_whitespace() || c == '"' || c == '\'' || c == '>')
            .unwrap_or(rest.len());
        let name = &rest[..name_len];
        let after = rest[name_len..].trim_start();
        let value = match after.chars().next() {
            Some(q @ ('"' | '\'')) => {
                let inner = &after[1..];
                let close = inner.find(q).unwrap_or(inner.len());
                Some(&inner[..close])
            }
            _ => None,
        };
        if let Some(v) = value {
            let v = v.to_ascii_lowercase();
            if ["&#38;", "&#x26;", "&#37;", "&#x25;"]
                .iter()
                .any(|r| v.replace("&#0", "&#").contains(r))
            {
                return Err(refuse_at(
                    text,
                    at,
                    format!("the entity {name:?} holds a character reference to '&' or '%', whose expansion would be read again: not read"),
                ));
            }
        }
        out.push(Entity { name, value, at });
        // past the value, which may hold '>' or "<!ENTITY" (`after` ends where the subset does)
        k = (end - after.len() + value.map_or(0, |v| v.len() + 2)).min(end);
    }
    Ok(out)
}

/// Every `&name;` reference of `text` (not `&#…;`), with its byte offset.
fn references(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.match_indices('&').filter_map(move |(at, _)| {
        let rest = &text[at + 1..];
        let semi = rest.find(';')?;
        let name = &rest[..semi];
        (!name.is_empty()
            && !name.starts_with('#')
            && name
                .chars()
                .all(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | '.' | ':')))
        .then_some((at, name))
    })
}

/// The bytes entity `e` expands to, its references expanded (saturating; beyond the XML
/// parser's depth of ten a loop, which that parser refuses: counted as the limit).
fn expanded<'a>(
    e: &Entity<'a>,
    by_name: &HashMap<&'a str, &Entity<'a>>,
    memo: &mut HashMap<&'a str, u64>,
    depth: usize,
) -> u64 {
    if let Some(&n) = memo.get(e.name) {
        return n;
    }
    if depth > 10 {
        return MAX_ENTITY_EXPANSION + 1;
    }
    let Some(value) = e.value else { return 0 };
    let mut size = value.len() as u64;
    for (_, name) in references(value) {
        if let Some(inner) = by_name.get(name) {
            let n = expanded(inner, by_name, memo, depth + 1);
            size = size.saturating_add(n);
        }
    }
    memo.insert(e.name, size);
    size
}

/// Refuses a number of attribute `name` beyond [`MAX_SVG_NUMBER`] if it holds geometry, a
/// transform or a `style` with a `transform` declaration (module docs).
pub(crate) fn check_attribute(
    name: &str,
    value: &str,
    placed: &dyn Fn(usize, String) -> Error,
) -> Result<()> {
    match name {
        "d" | "points" | "viewBox" | "transform" | "x" | "y" | "width" | "height" | "rx" | "ry"
        | "cx" | "cy" | "r" | "x1" | "y1" | "x2" | "y2" => check_numbers(name, value, placed),
        "style" => {
            for d in simplecss::DeclarationTokenizer::from(value) {
                if d.name == "transform" {
                    check_numbers("transform", d.value, placed)?;
                }
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// Refuses a number of the document's geometry beyond [`MAX_SVG_NUMBER`] (module docs):
/// `value` is attribute `name`'s (or a `style` declaration's) value, placed by `placed`.
fn check_numbers(name: &str, value: &str, placed: &dyn Fn(usize, String) -> Error) -> Result<()> {
    let too_large = |x: f64| x.is_nan() || x.abs() > MAX_SVG_NUMBER;
    let beyond = |x: f64| {
        placed(
            0,
            format!(
                "{name}: the number {x:e} is beyond the largest an SVG document's geometry may hold here, {MAX_SVG_NUMBER:e}"
            ),
        )
    };
    match name {
        "d" => {
            let data = normalized_path_data(value);
            for segment in svgtypes::PathParser::from(data.as_ref()).flatten() {
                if let Some(x) = segment_numbers(&segment)
                    .into_iter()
                    .find(|&x| too_large(x))
                {
                    return Err(beyond(x));
                }
            }
        }
        "points" | "viewBox" => {
            for x in svgtypes::NumberListParser::from(value).flatten() {
                if too_large(x) {
                    return Err(beyond(x));
                }
            }
        }
        "transform" => {
            if let Ok(t) = svgtypes::Transform::from_str(value) {
                if let Some(x) = [t.a, t.b, t.c, t.d, t.e, t.f]
                    .into_iter()
                    .find(|&x| too_large(x))
                {
                    return Err(beyond(x));
                }
            }
        }
        _ => {
            if let Ok(l) = svgtypes::Length::from_str(value) {
                if too_large(l.number) {
                    return Err(beyond(l.number));
                }
            }
        }
    }
    Ok(())
}

fn segment_numbers(s: &svgtypes::PathSegment) -> Vec<f64> {
    use svgtypes::PathSegment as P;
    match *s {
        P::MoveTo { x, y, .. } | P::LineTo { x, y, .. } | P::SmoothQuadratic { x, y, .. } => {
            vec![x, y]
        }
        P::HorizontalLineTo { x, .. } => vec![x],
        P::VerticalLineTo { y, .. } => vec![y],
        P::CurveTo {
            x1,
            y1,
            x2,
            y2,
            x,
            y,
            ..
        } => vec![x1, y1, x2, y2, x, y],
        P::SmoothCurveTo { x2, y2, x, y, .. } => vec![x2, y2, x, y],
        P::Quadratic { x1, y1, x, y, .. } => vec![x1, y1, x, y],
        P::EllipticalArc { rx, ry, x, y, .. } => vec![rx, ry, x, y],
        P::ClosePath { .. } => Vec::new(),
    }
}

/// Refuses a document whose style sheets hold more than [`MAX_CSS_RULES`] rules or ask for
/// more than [`MAX_CSS_WORK`] matches of a rule against an element; bounds the numbers of the
/// sheets' `transform` declarations.
pub(crate) fn check_css(doc: &roxmltree::Document) -> Result<()> {
    let mut rules = 0u64;
    let mut elements = 0u64;
    let mut sheets = Vec::new();
    for node in doc.descendants().filter(|n| n.is_element()) {
        elements += 1;
        if node.tag_name().name() == "style" {
            for css in node.children().filter_map(|c| c.text()) {
                // every rule has a block: the braces bound the rules before any CSS parsing
                // (the CSS parser's time grows with the square of the rules)
                rules += css.bytes().filter(|&b| b == b'{').count() as u64;
                sheets.push((node.range().start, css));
            }
        }
    }
    let at = sheets.first().map_or(0, |s| s.0);
    if rules > MAX_CSS_RULES {
        return Err(refuse_at(
            doc.input_text(),
            at,
            format!("{rules} style-sheet rules: more than the {MAX_CSS_RULES} read"),
        ));
    }
    let work = rules.saturating_mul(elements);
    if work > MAX_CSS_WORK {
        return Err(refuse_at(
            doc.input_text(),
            at,
            format!("{rules} style-sheet rules matched against {elements} elements: more than the {MAX_CSS_WORK} matches read"),
        ));
    }
    for (at, css) in sheets {
        let placed = |_: usize, m: String| refuse_at(doc.input_text(), at, m);
        let sheet = simplecss::StyleSheet::parse(css);
        for d in sheet.rules.iter().flat_map(|r| &r.declarations) {
            if d.name == "transform" {
                check_numbers("transform", d.value, &placed)?;
            }
        }
    }
    Ok(())
}

/// Refuses an element whose coordinates the transforms, `<use>` offsets and nested
/// viewports above it carry beyond [`MAX_PLACED_COORDINATE`] (module docs), and a document
/// of more than [`MAX_SHOWN_ELEMENTS`] elements once every `<use>` shows what it names.
/// Bounds are computed as `|x'| ≤ ‖M‖∞·|x| + ‖t‖∞` from every element's own numbers down the
/// tree, `<use>` followed to what it shows.
pub(crate) fn check_placement(doc: &roxmltree::Document) -> Result<()> {
    let ids: HashMap<&str, roxmltree::NodeId> = doc
        .descendants()
        .filter_map(|n| Some((n.attribute("id")?, n.id())))
        .collect();
    let mut memo: HashMap<roxmltree::NodeId, Placed> = HashMap::new();
    let root = doc.root_element();
    let placed = reach(doc, root, &ids, &mut memo, 0);
    if placed.elements > MAX_SHOWN_ELEMENTS {
        return Err(refuse_at(
            doc.input_text(),
            root.range().start,
            format!(
                "the document shows {} elements once every <use> shows what it names: more than the {MAX_SHOWN_ELEMENTS} read",
                placed.elements
            ),
        ));
    }
    if placed.reach.is_nan() || placed.reach > MAX_PLACED_COORDINATE {
        let node = doc.get_node(placed.at).unwrap_or(root);
        let named = element_name(node);
        return Err(refuse_at(
            doc.input_text(),
            node.range().start,
            format!(
                "{named}: the transforms above it carry its coordinates to {:e}, beyond the {MAX_PLACED_COORDINATE:e} single precision holds with a margin: not read",
                placed.reach
            ),
        ));
    }
    Ok(())
}

/// What [`reach`] finds of an element.
#[derive(Debug, Clone, Copy)]
struct Placed {
    /// A bound on the magnitude of its coordinates in its parent's units.
    reach: f64,
    /// The element deepest down that reaches it.
    at: roxmltree::NodeId,
    /// The elements it shows, itself included, every `<use>` expanded (saturating).
    elements: u64,
}

fn reach(
    doc: &roxmltree::Document,
    node: roxmltree::Node,
    ids: &HashMap<&str, roxmltree::NodeId>,
    memo: &mut HashMap<roxmltree::NodeId, Placed>,
    depth: usize,
) -> Placed {
    if let Some(&r) = memo.get(&node.id()) {
        return r;
    }
    let mut best = Placed {
        reach: own_extent(node),
        at: node.id(),
        elements: 1,
    };
    if depth > 64 {
        // deeper than any drawing; `<use>` cycles are the parser's to refuse
        return best;
    }
    memo.insert(node.id(), best);
    let own = best.reach;
    let consider = |best: &mut Placed, r: Placed| {
        if r.reach.is_nan() || r.reach > best.reach {
            (best.reach, best.at) = (r.reach, r.at);
        }
        best.elements = best.elements.saturating_add(r.elements);
    };
    for child in node.children().filter(|c| c.is_element()) {
        let r = reach(doc, child, ids, memo, depth + 1);
        consider(&mut best, r);
    }
    if node.tag_name().name() == "use" {
        let href = node
            .attribute(("http://www.w3.org/1999/xlink", "href"))
            .or_else(|| node.attribute("href"))
            .unwrap_or("");
        if let Some(target) = href
            .trim()
            .strip_prefix('#')
            .and_then(|id| ids.get(id))
            .and_then(|&id| doc.get_node(id))
        {
            let r = reach(doc, target, ids, memo, depth + 1);
            // the use's x and y translate what it shows
            let at = if r.reach > 0.0 { r.at } else { node.id() };
            consider(
                &mut best,
                Placed {
                    reach: r.reach + own,
                    at,
                    elements: r.elements,
                },
            );
        }
    }
    let (scale, shift) = placement(node);
    best.reach = scale * best.reach + shift;
    memo.insert(node.id(), best);
    best
}

/// The largest magnitude of `node`'s own geometric numbers.
fn own_extent(node: roxmltree::Node) -> f64 {
    let mut m = 0.0f64;
    for attr in node.attributes().filter(|a| a.namespace().is_none()) {
        let value = attr.value();
        match attr.name() {
            "d" => {
                let data = normalized_path_data(value);
                for s in svgtypes::PathParser::from(data.as_ref()).flatten() {
                    for x in segment_numbers(&s) {
                        m = m.max(x.abs());
                    }
                }
            }
            "points" => {
                for x in svgtypes::NumberListParser::from(value).flatten() {
                    m = m.max(x.abs());
                }
            }
            "x" | "y" | "width" | "height" | "rx" | "ry" | "cx" | "cy" | "r" | "x1" | "y1"
            | "x2" | "y2" => {
                if let Ok(l) = svgtypes::Length::from_str(value) {
                    m = m.max(l.number.abs());
                }
            }
            _ => {}
        }
    }
    // a circle's or a rounded rectangle's extent is its centre plus its radius, at most twice
    2.0 * m
}

/// `(‖M‖∞, ‖t‖∞)` of the map from `node`'s coordinates to its parent's: its `transform`
/// (attribute or `style` declaration), times a nested viewport's `viewBox` scale.
fn placement(node: roxmltree::Node) -> (f64, f64) {
    let mut transforms: Vec<svgtypes::Transform> = Vec::new();
    if let Some(t) = node
        .attribute("transform")
        .and_then(|v| svgtypes::Transform::from_str(v).ok())
    {
        transforms.push(t);
    }
    if let Some(style) = node.attribute("style") {
        for d in simplecss::DeclarationTokenizer::from(style) {
            if d.name == "transform" {
                if let Ok(t) = svgtypes::Transform::from_str(d.value) {
                    transforms.push(t);
                }
            }
        }
    }
    let (mut scale, mut shift) = (1.0f64, 0.0f64);
    for t in transforms {
        let norm = (t.a.abs() + t.c.abs()).max(t.b.abs() + t.d.abs());
        scale *= norm;
        shift = norm * shift + t.e.abs().max(t.f.abs());
    }
    if matches!(node.tag_name().name(), "svg" | "symbol") {
        if let Some(vb) = node
            .attribute("viewBox")
            .and_then(|v| svgtypes::ViewBox::from_str(v).ok())
        {
            let length = |n: &str| {
                node.attribute(n)
                    .and_then(|v| svgtypes::Length::from_str(v).ok())
                    .map_or(0.0, |l| l.number.abs())
            };
            let size = length("width").max(length("height")).max(1.0);
            let unit = vb.w.abs().min(vb.h.abs());
            let s = if unit > 0.0 {
                size / unit
            } else {
                f64::INFINITY
            };
            scale *= s.max(1.0);
            shift += s * vb.x.abs().max(vb.y.abs());
        }
    }
    (scale, shift)
}
