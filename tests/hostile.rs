//! Documents and CSV texts written to turn the readers against the user: each read ends
//! within [`SECONDS`] and [`MAX_BYTES`] of memory allocated at its peak (measured by this
//! binary's allocator), opens no file a document names, and either reads what a viewer draws
//! or refuses by name. Random documents and CSV texts are held to the same bounds.
#![cfg(feature = "svg")]

use splinelab::input::{points_from_csv, read_svg_document, Columns, SvgDocument};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The time a hostile read may take (the issue's bound; the test profile is optimised).
const SECONDS: f64 = 2.0;
/// The memory a hostile read may hold at its peak, beyond what it was given.
const MAX_BYTES: usize = 200 << 20;

struct Counting;
static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);
/// One measured read at a time (the counts are the process's).
static MEASURED: Mutex<()> = Mutex::new(());

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let live = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(live, Ordering::Relaxed);
        }
        p
    }
    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        unsafe { System.dealloc(p, layout) };
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
    }
    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new: usize) -> *mut u8 {
        let q = unsafe { System.realloc(p, layout, new) };
        if !q.is_null() {
            if new >= layout.size() {
                let live =
                    LIVE.fetch_add(new - layout.size(), Ordering::Relaxed) + new - layout.size();
                PEAK.fetch_max(live, Ordering::Relaxed);
            } else {
                LIVE.fetch_sub(layout.size() - new, Ordering::Relaxed);
            }
        }
        q
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Runs `read` on a thread of its own and returns its result, failing the test if it takes
/// more than [`SECONDS`] (a read blocked on a named pipe it opened included) or holds more
/// than [`MAX_BYTES`] at its peak.
fn bounded<T: Send + 'static>(what: &str, read: impl FnOnce() -> T + Send + 'static) -> T {
    let _one = MEASURED.lock().unwrap_or_else(|e| e.into_inner());
    let base = LIVE.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    let start = Instant::now();
    let (send, receive) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(read());
    });
    let out = receive
        .recv_timeout(Duration::from_secs_f64(SECONDS))
        .unwrap_or_else(|_| panic!("{what}: no answer within {SECONDS} s"));
    let peak = PEAK.load(Ordering::Relaxed).saturating_sub(base);
    assert!(peak <= MAX_BYTES, "{what}: {} MB at the peak", peak >> 20);
    eprintln!(
        "{what}: {:.3} s, {:.1} MB at the peak",
        start.elapsed().as_secs_f64(),
        peak as f64 / 1048576.0
    );
    out
}

fn doc(body: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 100 100">{body}</svg>"#
    )
}

/// The message of a refusal, or a panic naming what was read instead.
fn refused(what: &str, text: String) -> String {
    match bounded(what, move || read_svg_document(&text, 1e-3)) {
        Ok(o) => panic!("{what}: read, {} paths", o.paths.len()),
        Err(e) => e.to_string(),
    }
}

/// A named pipe: opening it to read blocks until a writer comes, so a reader that opens it
/// never answers and [`bounded`] fails the test.
fn trap() -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("trap.png");
    let made = std::process::Command::new("mkfifo").arg(&path).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    let name = path.to_str().unwrap().to_string();
    (dir, name)
}

#[test]
fn no_document_opens_a_file_it_names() {
    let (_dir, pipe) = trap();
    let square = r#"<rect x="10" y="10" width="20" height="20"/>"#;
    for (what, body) in [
        (
            "feImage of a file",
            format!(
                r#"<filter id="f"><feImage href="{pipe}"/></filter><g filter="url(#f)">{square}</g>"#
            ),
        ),
        (
            "feImage by xlink:href",
            format!(
                r#"<filter id="f"><feImage xlink:href="file://{pipe}"/></filter><rect filter="url(#f)" width="5" height="5"/>"#
            ),
        ),
        (
            "feImage of an SVG data URL that names the file",
            format!(
                r#"<filter id="f"><feImage href="data:image/svg+xml;utf8,&lt;svg xmlns='http://www.w3.org/2000/svg'&gt;&lt;image href='{pipe}'/&gt;&lt;/svg&gt;"/></filter><rect filter="url(#f)" width="5" height="5"/>"#
            ),
        ),
    ] {
        let text = doc(&body);
        let out = bounded(what, move || read_svg_document(&text, 1e-3));
        assert!(out.is_ok(), "{what}: {out:?}");
    }
    // an <image> is refused by name, before any parser could open it
    let m = refused(
        "image",
        doc(&format!(r#"<image href="{pipe}" width="5" height="5"/>"#)),
    );
    assert!(m.contains("<image> has no outline"), "{m}");
    // an external entity is not loaded
    let text = format!(
        r#"<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY e SYSTEM "{pipe}">]>{}"#,
        doc("<rect width='1' height='1'/><desc>&e;</desc>")
    );
    let m = refused("external entity", text);
    assert!(m.contains("entity"), "{m}");
}

#[test]
fn entity_expansion_is_bounded_and_drawing_programs_entities_read() {
    // one 100 kB entity referenced 10⁴ times: 1 GB of text from a 1.1 MB document
    let big = "x".repeat(100_000);
    let refs = "&e;".repeat(10_000);
    let text = format!(
        r#"<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY e "{big}">]>{}"#,
        doc(&format!("<rect width='1' height='1'/><desc>{refs}</desc>"))
    );
    let m = refused("entity expansion", text);
    assert!(m.contains("expand to more than"), "{m}");
    // nested: ten of ten of ten ... (the parser's own check stops deep loops; the budget the rest)
    let mut decls = String::from(r#"<!ENTITY a0 "0123456789">"#);
    for k in 1..6 {
        decls += &format!(r#"<!ENTITY a{k} "{}">"#, format!("&a{};", k - 1).repeat(10));
    }
    let text = format!(
        r#"<!DOCTYPE svg [{decls}]>{}"#,
        doc(&format!(
            "<rect width='1' height='1'/><desc>{}</desc>",
            "&a5;".repeat(100)
        ))
    );
    let m = refused("nested entities", text);
    assert!(
        m.contains("expand to more than") || m.contains("loop"),
        "{m}"
    );
    let m = refused(
        "parameter entity",
        format!(
            r#"<!DOCTYPE svg [<!ENTITY % p "x">]>{}"#,
            doc("<rect width='1' height='1'/>")
        ),
    );
    assert!(m.contains("parameter entity"), "{m}");
    // Illustrator's namespace entities, used in attributes
    let text = r#"<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [
	<!ENTITY ns_extend "http://ns.adobe.com/Extensibility/1.0/">
	<!ENTITY ns_ai "http://ns.adobe.com/AdobeIllustrator/10.0/">
	<!ENTITY ns_svg "http://www.w3.org/2000/svg">
	<!ENTITY ns_xlink "http://www.w3.org/1999/xlink">
]>
<svg version="1.1" xmlns:x="&ns_extend;" xmlns:i="&ns_ai;" xmlns="&ns_svg;" xmlns:xlink="&ns_xlink;" viewBox="0 0 10 10">
<rect x="1" y="1" width="5" height="5"/>
</svg>"#;
    let out = bounded("Illustrator's entities", move || {
        read_svg_document(text, 1e-3)
    });
    assert_eq!(out.unwrap().paths.len(), 1);
}

#[test]
fn huge_numbers_are_refused_before_the_parser() {
    for (what, body) in [
        (
            "arc radius 1e38 in a hidden path",
            r#"<rect width="1" height="1"/><path visibility="hidden" d="M 0 0 A 1e38 1e38 0 0 1 1 0"/>"#,
        ),
        (
            "arc chord 1e30",
            r#"<path d="M 0 0 A 1 1 0 0 1 1e30 0 A 1 1 0 0 1 0 0"/>"#,
        ),
        (
            "coordinates 3e38",
            r#"<path d="M 0 0 L 3e38 0 L 3e38 3e38 Z"/>"#,
        ),
        ("a rect 1e30 wide", r#"<rect width="1e30" height="1"/>"#),
        (
            "a transform 1e20",
            r#"<g transform="scale(1e20)"><rect width="1" height="1"/></g>"#,
        ),
        (
            "a CSS transform 1e20",
            r#"<rect style="transform: scale(1e20)" width="1" height="1"/>"#,
        ),
    ] {
        let m = refused(what, doc(body));
        assert!(m.contains("beyond the largest"), "{what}: {m}");
    }
    // nested transforms, each within bounds, that carry a path beyond single precision
    let body = r#"<g transform="scale(1e9)"><g transform="scale(1e9)"><g transform="scale(1e9)"><g transform="scale(1e9)"><path id="far" d="M 0 0 L 1e9 0 L 1e9 1e9 Z"/></g></g></g></g>"#;
    let m = refused("nested transforms", doc(body));
    assert!(
        m.contains("<path id=\"far\">") && m.contains("transforms above it"),
        "{m}"
    );
    // the same through <use>
    let body = r##"<defs><path id="p" d="M 0 0 L 1e9 0 L 1e9 1e9 Z"/><g id="a" transform="scale(1e9)"><use href="#p"/></g><g id="b" transform="scale(1e9)"><use href="#a"/></g><g id="c" transform="scale(1e9)"><use href="#b"/></g></defs><use href="#c" transform="scale(1e9)"/>"##;
    let m = refused("nested uses", doc(body));
    assert!(m.contains("transforms above it"), "{m}");
}

#[test]
fn style_sheets_are_bounded() {
    // `rules` class rules and `rects` rectangles of those classes
    let sheet = |rules: usize, rects: usize| {
        let rules: String = (0..rules).map(|k| format!(".c{k}{{fill:red}}")).collect();
        let rects: String = (0..rects)
            .map(|k| format!("<rect class='c{k}' width='1' height='1'/>"))
            .collect();
        doc(&format!("<style>{rules}</style>{rects}"))
    };
    let m = refused("10^5 CSS rules", sheet(100_000, 300));
    assert!(m.contains("style-sheet rules"), "{m}");
    let m = refused("3 000 rules on 10^4 elements", sheet(3_000, 10_000));
    assert!(m.contains("matches read"), "{m}");
    // a sheet of a few rules reads
    let text = doc("<style>.a{fill:red}</style><rect class='a' width='1' height='1'/>");
    assert!(bounded("a small sheet", move || read_svg_document(&text, 1e-3)).is_ok());
}

#[test]
fn use_bombs_end_in_time() {
    // each level shows the previous ten times: 10⁸ paths if expanded
    let mut defs = String::from(r#"<path id="l0" d="M0 0 L1 0 L1 1 Z"/>"#);
    for k in 1..9 {
        let uses: String = (0..10)
            .map(|_| format!("<use href='#l{}'/>", k - 1))
            .collect();
        defs += &format!("<g id='l{k}'>{uses}</g>");
    }
    let text = doc(&format!("<defs>{defs}</defs><use href='#l8'/>"));
    let out = bounded("use bomb", move || read_svg_document(&text, 1e-3));
    assert!(out.is_err(), "{out:?}");
}

#[test]
fn a_curved_shape_whose_ends_lie_on_a_line_is_read() {
    // a lens of two cubics: its size is that of its curves, not of its chords
    let text = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 16"><path d="M2 8C6 2 10 2 14 8C10 14 6 14 2 8Z"/></svg>"#;
    let document = SvgDocument::parse(text).unwrap();
    let extent = document.extent().unwrap();
    assert!((extent.width - 12.0).abs() < 1e-5, "{extent:?}");
    assert!((extent.height - 9.0).abs() < 1e-5, "{extent:?}");
    let outline = document.outline(1e-4 * extent.size()).unwrap();
    let points = &outline.paths[0].contours[0].points;
    let top = points.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
    assert!((top - (-3.5)).abs() < 2e-3, "{top}");
    // an oval of two cubics and a path of curves through one point
    for d in ["M0 0C0 5 10 5 10 0C10 -5 0 -5 0 0Z", "M5 5C0 0 10 0 5 5Z"] {
        let text = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="-20 -20 40 40"><path d="{d}"/></svg>"#
        );
        let document = SvgDocument::parse(&text).unwrap();
        assert!(document.extent().unwrap().size() > 3.0, "{d}");
    }
    // a document that draws nothing says what it dropped and why
    let m = refused(
        "nothing drawn",
        doc(
            r#"<path id="a" d="M0 0 L 5 5 L 10 10 Z"/><rect id="b" width="5" height="5" fill="none"/>"#,
        ),
    );
    assert!(
        m.contains("<path id=\"a\">") && m.contains("one line"),
        "{m}"
    );
    assert!(
        m.contains("<rect id=\"b\">") && m.contains("neither"),
        "{m}"
    );
}

#[test]
fn an_arc_flag_followed_by_blanks_and_a_comma_is_read() {
    let with = doc(r#"<path d="M 0 0 A 1 1 0 1 , 0 2 0 Z"/>"#);
    let without = doc(r#"<path d="M 0 0 A 1 1 0 1,0 2 0 Z"/>"#);
    let a = read_svg_document(&with, 1e-4).unwrap();
    let b = read_svg_document(&without, 1e-4).unwrap();
    assert_eq!(a, b);
    let path = splinelab::input::contours_from_svg_path("M 0 0 A 1 1 0 1 , 0 2 0", 1e-4).unwrap();
    let same = splinelab::input::contours_from_svg_path("M 0 0 A 1 1 0 1,0 2 0", 1e-4).unwrap();
    assert_eq!(path, same);
}

#[test]
fn csv_reads_are_bounded_and_quote_short_prefixes() {
    // a 10 MB field: refused with a message that quotes a short prefix of it
    let text = format!("x,y\n1,{}\n", "9a".repeat(5_000_000));
    let m = bounded("10 MB field", move || {
        points_from_csv::<2>(&text, &Columns::First)
            .unwrap_err()
            .to_string()
    });
    assert!(m.len() < 300, "{} bytes of message", m.len());
    // a 100 MB line of fields: memory in proportion to one field
    let mut line = String::with_capacity(100 << 20);
    while line.len() < 100 << 20 {
        line.push_str("1,");
    }
    let text = format!("{line}\n");
    let out = bounded("100 MB line", move || {
        points_from_csv::<2>(&text, &Columns::First).map(|p| p.len())
    });
    assert_eq!(out.unwrap(), 1);
}

mod random {
    use super::{bounded, doc};
    use proptest::prelude::*;
    use splinelab::input::{points_from_csv, read_svg_document, Columns};

    /// A number as a document may write one: small, huge, tiny, negative, odd forms.
    fn number() -> impl Strategy<Value = String> {
        prop_oneof![
            (-100.0..100.0f64).prop_map(|x| format!("{x:.3}")),
            (-40i32..40, any::<bool>())
                .prop_map(|(e, neg)| format!("{}1e{e}", if neg { "-" } else { "" })),
            Just(".5".to_string()),
            Just("1e38".to_string()),
            Just("-3.4e38".to_string()),
            Just("NaN".to_string()),
        ]
    }

    /// Path data: commands with numbers, commas and blanks, not always well formed.
    fn path_data() -> impl Strategy<Value = String> {
        let command = prop_oneof![
            Just("M"),
            Just("L"),
            Just("H"),
            Just("V"),
            Just("C"),
            Just("S"),
            Just("Q"),
            Just("T"),
            Just("A"),
            Just("Z"),
            Just("m"),
            Just("a"),
            Just("c"),
            Just(",")
        ];
        prop::collection::vec((command, prop::collection::vec(number(), 0..8)), 1..12).prop_map(
            |parts| {
                parts
                    .into_iter()
                    .map(|(c, n)| format!("{c}{}", n.join(" ")))
                    .collect::<Vec<_>>()
                    .join(" ")
            },
        )
    }

    /// One element of a document: paths, shapes, uses, clips, groups with transforms, style
    /// sheets, entities' references, images that name files.
    fn element() -> impl Strategy<Value = String> {
        prop_oneof![
            path_data().prop_map(|d| format!("<path id=\"p\" d=\"{d}\"/>")),
            (number(), number(), number()).prop_map(|(x, y, r)| format!(
                "<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\" stroke=\"black\"/>"
            )),
            (number(), number()).prop_map(|(w, h)| format!("<rect width=\"{w}\" height=\"{h}\"/>")),
            (number(), number()).prop_map(|(a, b)| format!(
                "<g transform=\"matrix({a} 0 0 {b} 1 1)\"><use href=\"#p\"/><use href=\"#p\"/></g>"
            )),
            (number(), number()).prop_map(|(w, h)| format!(
                "<clipPath id=\"c\"><rect width=\"{w}\" height=\"{h}\"/></clipPath><g clip-path=\"url(#c)\"><circle r=\"40\"/><path d=\"M0 50H100\" stroke=\"red\"/></g>"
            )),
            (1usize..200).prop_map(|n| format!(
                "<style>{}</style>",
                (0..n).map(|i| format!(".c{i} {{ fill: red }} ")).collect::<String>()
            )),
            Just("<image href=\"/dev/zero\" width=\"1\" height=\"1\"/>".to_string()),
            Just("<filter id=\"f\"><feImage href=\"/dev/zero\"/></filter><rect width=\"1\" height=\"1\" filter=\"url(#f)\"/>".to_string()),
            Just("<mask id=\"m\"><rect width=\"9\" height=\"9\" fill=\"white\"/></mask><rect width=\"2\" height=\"2\" mask=\"url(#m)\"/>".to_string()),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Random documents of hostile pieces: each read ends within the bounds, read or
        /// refused.
        #[test]
        fn random_documents_are_bounded(body in prop::collection::vec(element(), 1..8)) {
            let text = doc(&body.concat());
            let shown = text.chars().take(200).collect::<String>();
            let _ = bounded(&shown, move || read_svg_document(&text, 1e-2).map(|o| o.paths.len()));
        }

        /// Random CSV texts over the characters that matter to the grammar: each read ends
        /// within the bounds, and a refusal quotes a short part of the text.
        #[test]
        fn random_csv_texts_are_bounded(text in "[0-9eE.,;\" \t\r\n#+x-]{0,2000}") {
            let shown = text.chars().take(60).collect::<String>();
            let result = bounded(&shown, move || points_from_csv::<2>(&text, &Columns::First));
            if let Err(e) = result {
                prop_assert!(e.to_string().len() < 400, "{e}");
            }
        }
    }
}
