//! input: points from CSV and contours from SVG paths (issue 29), and (feature `report`) SVG
//! documents and glyph outlines from a font

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(text_cases());
    all.extend(font_cases());
    all.extend(svg_document_cases());
    all
}

/// Points from CSV, contours from SVG paths.
fn text_cases() -> Vec<Case> {
    vec![
        case("input::csv_points_refusals", || {
            use splinelab::input::{points_from_csv, Columns};
            for text in ["0,1\n2,inf\n", "0,1\n2\n", "a,b\n0,1\nc,d\n", "0,1e999\n"] {
                expect_err!(
                    points_from_csv::<2>(text, &Columns::First),
                    Error::Parse { .. }
                )?;
            }
            for text in ["", "x,y\n", "# nothing\n"] {
                expect_err!(
                    points_from_csv::<2>(text, &Columns::First),
                    Error::TooFewPoints { .. }
                )?;
            }
            expect_err!(
                points_from_csv::<2>("0,1\n", &Columns::Indices(vec![usize::MAX, 0])),
                Error::Parse { .. }
            )
        }),
        case("input::csv_real_forms_refused_in_place", || {
            use splinelab::input::{points_from_csv, Columns};
            // (text, line, column) of the refusal
            for (text, line, column) in [
                ("1,2\n3,\"4\n5,6\n", 2, 3),
                ("x;y\n1,5;2\n", 2, 1),
                ("1,abc\n2,3\n", 1, 3),
                ("\"x\",\"y\"\n\"1\",\"nan\"\n", 2, 5),
                ("1,2\n\"3\n\",x\n", 3, 3),
                ("1;2;\n3;4;5\n", 2, 5),
                ("\u{feff}x,y\r\n1,2\r\n3,\r\n", 3, 3),
            ] {
                match points_from_csv::<2>(text, &Columns::First) {
                    Err(Error::Parse {
                        line: l, column: c, ..
                    }) if (l, c) == (line, column) => {}
                    other => {
                        return Err(format!(
                            "{text:?}: {other:?}, expected line {line}, column {column}"
                        ))
                    }
                }
            }
            Ok(())
        }),
        case("input::svg_arcs_at_extremes", || {
            use splinelab::input::contours_from_svg_path;
            // radii from tiny to huge, NaN-free: a finite polyline or a typed error, bounded
            for r in ["1e-300", "1e300", "0", "-3", "1e-320"] {
                for tol in [1e-12, 1e-3, 1e3] {
                    let d = format!("M 0 0 A {r} {r} 30 1 0 5 5 Z");
                    if let Ok(c) = contours_from_svg_path(&d, tol) {
                        ensure!(
                            c.iter()
                                .flat_map(|c| c.points.iter())
                                .all(|p| p.iter().all(|v| v.is_finite())),
                            "{d}: a non-finite point"
                        );
                        ensure!(
                            c[0].points.len()
                                <= 2 * splinelab::input::flatten::MAX_PIECES_PER_CURVE + 4,
                            "{d}: {} points",
                            c[0].points.len()
                        );
                    }
                }
            }
            Ok(())
        }),
        case("input::svg_path_refusals", || {
            use splinelab::input::contours_from_svg_path;
            for d in [
                "M 0",
                "L 1 1",
                "M 0 0 A 1 1 0 01 2",
                "M 0 0 A 1 1 0 2 1 2 2",
                "M 0 0 A 1 1 0 0.5 1 2 2",
                "M 0 0 A 1 1 0 0 1 2",
                "M 0 0 S 1 1",
                "M 0 0 T",
                "M 0 0 X",
                "M 0 0 L 1e999 0",
                "M\u{0}",
            ] {
                expect_err!(contours_from_svg_path(d, 1e-3), Error::Parse { .. })?;
            }
            for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                expect_err!(
                    contours_from_svg_path("M 0 0 L 1 1", bad),
                    Error::NotPositive { .. }
                )?;
            }
            Ok(())
        }),
    ]
}

#[cfg(not(feature = "report"))]
fn font_cases() -> Vec<Case> {
    Vec::new()
}

/// Glyph outlines from a font (feature `report`).
#[cfg(feature = "report")]
fn font_cases() -> Vec<Case> {
    vec![case("input::glyph_refusals", || {
        use splinelab::input::font::glyph;
        let font: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
        for (bytes, ch) in [
            (font, '\u{10FFFF}'),
            (font, ' '),
            (&b"\0\0\0\0garbage"[..], 'a'),
            (&[][..], 'a'),
            (&font[..100], 'a'),
        ] {
            expect_err!(glyph(bytes, ch), Error::Glyph { .. })?;
        }
        Ok(())
    })]
}

#[cfg(not(feature = "report"))]
fn svg_document_cases() -> Vec<Case> {
    Vec::new()
}

/// SVG documents refused with words that say why (feature `svg`, which `report` implies).
#[cfg(feature = "report")]
fn svg_document_cases() -> Vec<Case> {
    vec![case("input::svg_documents", || {
        use splinelab::input::contours_from_svg_document;
        const NS: &str = "xmlns='http://www.w3.org/2000/svg'";
        // (document, words its refusal says)
        let docs: Vec<(String, &str)> = vec![
                ("".into(), "not well-formed XML"),
                ("<".into(), "not well-formed XML"),
                ("<path d='".into(), "not well-formed XML"),
                ("<!-- <path d='M 0 0 L 1 1'/>".into(), "not well-formed XML"),
                ("<svg><path d='M 0 0 L 1 1'/></svg>".into(), "not SVG's <svg>"),
                (format!("<svg {NS}/>"), "draws nothing"),
                (format!("<svg {NS}><path/></svg>"), "draws nothing"),
                (format!("<svg {NS}><path d=M0,0/></svg>"), "not well-formed XML"),
                (format!("<svg {NS}><path d='M 0 0 S 1 1 2'/></svg>"), "S is short"),
                (format!("<svg {NS}><path d='M 0 0 A 1 1 0 1e0 1 2 2'/></svg>"), "cannot read 'e'"),
                (format!("<svg {NS}><path d='Z'/></svg>"), "starts with a move"),
                (format!("<svg {NS}><path d=\"M 0 0 L 1e400 0\"/></svg>"), "not a finite"),
                (format!("<svg {NS}><text>a</text><rect width='1' height='1'/></svg>"), "<text>"),
                (format!("<svg {NS}><image width='1' height='1'/></svg>"), "<image>"),
                (format!("<svg {NS}><foreignObject/></svg>"), "<foreignObject>"),
                (format!("<svg {NS}><use href='icons.svg#home'/><rect width='1' height='1'/></svg>"), "another file"),
                (format!("<svg {NS}><rect width='1' height='1' transform='rotate(30'/></svg>"), "transform"),
                (format!("<svg {NS}><polygon points='0 0 1 1 2'/></svg>"), "odd count"),
                (format!("<svg {NS}><polygon points='0 0 1 x'/></svg>"), "cannot be read"),
                (format!("<svg {NS}><rect width='1q' height='1'/></svg>"), "width"),
                (
                    format!("<svg {NS}><mask id='m'><rect width='1' height='1' fill='white'/></mask><rect width='2' height='2' mask='url(#m)'/></svg>"),
                    "a mask",
                ),
                (
                    format!("<svg {NS}><clipPath id='d'><rect width='1' height='1'/></clipPath><clipPath id='c' clip-path='url(#d)'><circle r='1'/></clipPath><rect width='2' height='2' clip-path='url(#c)'/></svg>"),
                    "is clipped again",
                ),
                (
                    format!("<svg {NS}><clipPath id='c'><circle cx='9' r='1'/></clipPath><rect width='2' height='2' clip-path='url(#c)'/></svg>"),
                    "lies outside the clip path",
                ),
                (format!("<svg {NS} width='0' height='1'><rect width='1' height='1'/></svg>"), ""),
                (format!("<svg {NS} viewBox='-inf -inf inf inf'><rect width='1' height='1'/></svg>"), ""),
                (format!("<svg {NS}><rect width='1e39' height='1'/></svg>"), ""),
                (format!("<svg {NS}><path d='M 0 0 L 1e300 1'/></svg>"), ""),
            ];
        for (doc, words) in &docs {
            match contours_from_svg_document(doc, 1e-3) {
                Ok(c) => {
                    // read: finite points only
                    ensure!(
                        words.is_empty()
                            && c.iter()
                                .flat_map(|c| c.points.iter())
                                .all(|p| p.iter().all(|v| v.is_finite())),
                        "{doc:?} was read"
                    );
                }
                Err(e) => ensure!(e.to_string().contains(words), "{doc:?}: {e}"),
            }
        }
        Ok(())
    })]
}
