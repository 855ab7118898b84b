//! Users' points from CSV text (issue 29): the separators, header, column choices and
//! comments a file may have, read back exactly; every refusal a typed error naming the line
//! and column at fault; random texts never panic, and random points written out read back
//! bit for bit.

use nalgebra::{Vector2, Vector3};
use proptest::prelude::*;
use splinelab::input::{points_from_csv, Columns};
use splinelab::Error;

fn v2(x: f64, y: f64) -> Vector2<f64> {
    Vector2::new(x, y)
}

#[test]
fn the_forms_a_file_takes_read_alike() {
    let want = vec![v2(0.0, 1.0), v2(2.5, -3.0), v2(1e-300, 4e300)];
    for text in [
        "0,1\n2.5,-3\n1e-300,4e300\n",
        "x,y\n0, 1\n 2.5 , -3\n1e-300,4e300",
        "x;y\r\n0;1\r\n2.5;-3\r\n1e-300;4e300\r\n",
        "\u{feff}# exported by hand\n\n0 1\n2.5\t-3\n   1e-300   4e300\n",
    ] {
        assert_eq!(
            points_from_csv::<2>(text, &Columns::First).unwrap(),
            want,
            "{text:?}"
        );
    }
    let three = points_from_csv::<3>("1 2 3\n4 5 6\n", &Columns::First).unwrap();
    assert_eq!(
        three,
        [Vector3::new(1.0, 2.0, 3.0), Vector3::new(4.0, 5.0, 6.0)]
    );
}

#[test]
fn columns_are_chosen_by_index_or_by_name() {
    let text = "id,lat,lon,y,x\n7,0,0,10,20\n8,0,0,11,21\n";
    let by_name =
        points_from_csv::<2>(text, &Columns::Names(vec!["x".into(), "y".into()])).unwrap();
    assert_eq!(by_name, [v2(20.0, 10.0), v2(21.0, 11.0)]);
    let by_index = points_from_csv::<2>(text, &Columns::Indices(vec![4, 3])).unwrap();
    assert_eq!(by_index, by_name);
}

/// The error's line and column, or a panic naming what came instead.
fn at(r: Result<Vec<Vector2<f64>>, Error>) -> (usize, usize, String) {
    match r {
        Err(Error::Parse {
            line,
            column,
            message,
            ..
        }) => (line, column, message),
        other => panic!("expected a parse error, got {other:?}"),
    }
}

#[test]
fn bad_fields_and_rows_name_their_line_and_column() {
    let first = &Columns::First;
    assert_eq!(at(points_from_csv("0,1\n2,nan\n", first)).0, 2);
    assert_eq!(at(points_from_csv("0,1\n2,nan\n", first)).1, 3);
    for bad in [
        "inf", "-inf", "NaN", "1e400", "1e307", "abc", "", "0x10", "1,5",
    ] {
        let text = format!("0;1\n2;{bad}\n");
        let (line, column, message) = at(points_from_csv(&text, first));
        assert_eq!((line, column), (2, 3), "{bad:?}: {message}");
    }
    // ragged: a row with more or fewer fields than the first
    let (line, column, message) = at(points_from_csv("0,1\n2,3\n4,5,6\n", first));
    assert_eq!((line, column), (3, 5), "{message}");
    let (line, _, message) = at(points_from_csv("0 1 2\n3 4\n", first));
    assert_eq!(line, 2, "{message}");
    // a header only on the first row
    let (line, column, _) = at(points_from_csv("x,y\n0,1\nx,y\n", first));
    assert_eq!((line, column), (3, 1));
    // columns the rows do not have, names the header does not have
    assert_eq!(
        at(points_from_csv("0,1\n", &Columns::Indices(vec![0, 2]))).0,
        1
    );
    assert_eq!(
        at(points_from_csv(
            "a,b\n0,1\n",
            &Columns::Names(vec!["a".into(), "c".into()])
        ))
        .0,
        1
    );
    assert_eq!(
        at(points_from_csv(
            "0,1\n",
            &Columns::Names(vec!["a".into(), "b".into()])
        ))
        .0,
        1
    );
    assert!(matches!(
        points_from_csv::<2>("0,1\n", &Columns::Indices(vec![0])),
        Err(Error::CountMismatch { .. })
    ));
    // binary garbage read as text: refused at its first field
    let garbage: String = (0u8..=255).map(char::from).collect();
    let (line, column, _) = at(points_from_csv(&garbage, first));
    assert!(line >= 1 && column >= 1);
}

#[test]
fn csv_as_people_write_it_trailing_separators_quotes_numeric_first_rows() {
    let first = &Columns::First;
    let want = vec![v2(1.0, 2.0), v2(3.0, 4.0), v2(5.0, 6.0)];
    for text in [
        // a row ending in its separator, no header: the first row is data
        "1,2,\n3,4,\n5,6,\n",
        "1;2;\r\n3;4;\r\n5;6;\r\n",
        "1 2 \n3 4\t\n5 6\n",
        // quoted fields, quoted header names (with a quote and a separator inside)
        "\"x\",\"y\"\n\"1\",\"2\"\n\"3\",4\n5,\"6\"\n",
        "\"the \"\"x\"\"\";\"y; km\"\n1;2\n3;4\n5;6\n",
        "  # a comment after blanks\n1,2\n\n3,4\n# another\n5,6\n",
    ] {
        assert_eq!(points_from_csv::<2>(text, first).unwrap(), want, "{text:?}");
    }
    // a header name with the separator inside it, chosen by name
    let named = points_from_csv::<2>(
        "\"y; km\";\"the \"\"x\"\"\"\n2;1\n4;3\n6;5\n",
        &Columns::Names(vec!["the \"x\"".into(), "y; km".into()]),
    )
    .unwrap();
    assert_eq!(named, want);
    // a first row with a number in it is data: its other field is refused, not a header
    let (line, column, message) = at(points_from_csv("1,abc\n2,3\n", first));
    assert_eq!((line, column), (1, 3), "{message}");
    // a decimal comma is named
    let (line, column, message) = at(points_from_csv("x;y\n1,5;2\n", first));
    assert_eq!((line, column), (2, 1), "{message}");
    assert!(message.contains("decimal comma"), "{message}");
    // a quote left open: the field runs on to the end, refused where it starts
    let (line, column, message) = at(points_from_csv("1,2\n3,\"4\n5,6\n", first));
    assert_eq!((line, column), (2, 3), "{message}");
    assert!(message.contains("a quote left open?"), "{message}");
    // a quoted field spanning lines: the next field's line is the second
    let (line, column, message) = at(points_from_csv("1,2\n\"3\n\",x\n", first));
    assert_eq!((line, column), (3, 3), "{message}");
}

#[test]
fn empty_texts_have_no_points() {
    for text in ["", "\n\n", "# only a comment\n", "x,y\n", "\u{feff}"] {
        assert!(
            matches!(
                points_from_csv::<2>(text, &Columns::First),
                Err(Error::TooFewPoints { .. })
            ),
            "{text:?}"
        );
    }
}

#[test]
fn a_million_rows_read() {
    let text: String = (0..1_000_000)
        .map(|i| format!("{i},{}\n", i as f64 * 0.5))
        .collect();
    let p = points_from_csv::<2>(&text, &Columns::First).unwrap();
    assert_eq!(p.len(), 1_000_000);
    assert_eq!(p[999_999], v2(999_999.0, 499_999.5));
}

proptest! {
    /// Points written with any separator read back bit for bit.
    #[test]
    fn written_points_read_back_exactly(
        pts in prop::collection::vec((-1e300f64..1e300, -1e-300f64..1e-300), 1..50),
        sep in prop::sample::select(vec![",", ";", " ", "\t", " , "]),
        header in any::<bool>(),
    ) {
        let mut text = if header { format!("x{sep}y\n") } else { String::new() };
        for (x, y) in &pts {
            text.push_str(&format!("{x:e}{sep}{y}\n"));
        }
        let back = points_from_csv::<2>(&text, &Columns::First).unwrap();
        let want: Vec<Vector2<f64>> = pts.iter().map(|&(x, y)| v2(x, y)).collect();
        prop_assert_eq!(back, want);
    }

    /// Random files written by the `csv` crate (any delimiter, quoting style and line end,
    /// with or without a header) read back bit for bit.
    #[test]
    fn files_written_by_the_csv_crate_read_back_exactly(
        pts in prop::collection::vec((-1e300f64..1e300, -1e-300f64..1e-300), 1..40),
        delimiter in prop::sample::select(vec![b',', b';', b'\t', b' ']),
        quote in prop::sample::select(vec![
            csv::QuoteStyle::Always,
            csv::QuoteStyle::Necessary,
            csv::QuoteStyle::NonNumeric,
        ]),
        crlf in any::<bool>(),
        header in prop::option::of(prop::sample::select(vec![
            ("x", "y"),
            ("lon, deg", "lat; deg"),
            ("the \"x\"", "y"),
        ])),
    ) {
        let mut w = csv::WriterBuilder::new()
            .delimiter(delimiter)
            .quote_style(quote)
            .terminator(if crlf { csv::Terminator::CRLF } else { csv::Terminator::Any(b'\n') })
            .from_writer(Vec::new());
        if let Some((a, b)) = header {
            w.write_record([a, b]).unwrap();
        }
        for (x, y) in &pts {
            w.write_record([x.to_string(), y.to_string()]).unwrap();
        }
        let text = String::from_utf8(w.into_inner().unwrap()).unwrap();
        let back = points_from_csv::<2>(&text, &Columns::First);
        let want: Vec<Vector2<f64>> = pts.iter().map(|&(x, y)| v2(x, y)).collect();
        prop_assert_eq!(back.ok(), Some(want), "{}", text);
    }

    /// Any text: points or a typed error, never a panic; a parse error's place is inside
    /// the text.
    #[test]
    fn any_text_is_read_or_refused(
        text in "[0-9eE+\\-., ;\\t\\nxyna#\"\\r]{0,200}",
        first in any::<bool>(),
        cols in prop::collection::vec(prop_oneof![0usize..4, Just(usize::MAX)], 2),
    ) {
        let columns = if first { Columns::First } else { Columns::Indices(cols) };
        match points_from_csv::<2>(&text, &columns) {
            Ok(p) => prop_assert!(p.iter().all(|q| q.iter().all(|x| x.is_finite()))),
            Err(Error::Parse { line, column, .. }) => {
                // lines end with \n, \r\n or \r, as the reader reads them
                let l = text.replace("\r\n", "\n").split(['\n', '\r']).nth(line - 1).map(str::to_string);
                prop_assert!(l.is_some(), "line {} of {:?}", line, text);
                prop_assert!(column >= 1 && column <= l.unwrap_or_default().chars().count() + 1);
            }
            Err(Error::TooFewPoints { .. }) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// SVG path data
// ---------------------------------------------------------------------------------------------

mod svg {
    use nalgebra::Vector2;
    use proptest::prelude::*;
    use splinelab::input::{contours_from_svg_path, Contour};
    use splinelab::Error;

    fn pts(c: &Contour) -> Vec<(f64, f64)> {
        c.points.iter().map(|p| (p.x, p.y)).collect()
    }

    #[test]
    fn lines_absolute_relative_and_implicit_agree() {
        let want = vec![(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 1.0)];
        for d in [
            "M 1 1 L 3 1 L 3 3 Z",
            "m1,1 l2,0 l0,2 z",
            "M1 1 3 1 3 3z",
            "M 1 1 H 3 V 3 Z",
            "M1,1h2v2Z",
        ] {
            let c = contours_from_svg_path(d, 1e-3).unwrap();
            assert_eq!(c.len(), 1, "{d}");
            assert!(c[0].closed, "{d}");
            assert_eq!(pts(&c[0]), want, "{d}");
        }
        let two = contours_from_svg_path("M0 0 L1 0 M 5 5 l 1 1", 1e-3).unwrap();
        assert_eq!(two.len(), 2);
        assert!(!two[0].closed && !two[1].closed);
        assert_eq!(pts(&two[1]), [(5.0, 5.0), (6.0, 6.0)]);
    }

    #[test]
    fn curves_flatten_onto_the_curve_within_the_tolerance() {
        // the quadratic (0,0) (1,2) (2,0) is y = 2x − x²
        for tol in [1e-2, 1e-5, 1e-8] {
            let c = contours_from_svg_path("M 0 0 Q 1 2 2 0", tol).unwrap();
            let p = &c[0].points;
            assert!(p.len() >= 3);
            for q in p {
                assert!((q.y - (2.0 * q.x - q.x * q.x)).abs() < 1e-12, "{q:?}");
            }
            // the curve within tol of the polyline: its points between two vertices (B(t) =
            // (2t, 4t − 4t²), t = x/2) near the chord joining them
            for w in p.windows(2) {
                let (t0, t1) = (w[0].x / 2.0, w[1].x / 2.0);
                let chord = w[1] - w[0];
                for k in 0..=8 {
                    let t = t0 + (t1 - t0) * k as f64 / 8.0;
                    let b = Vector2::new(2.0 * t, 4.0 * t - 4.0 * t * t);
                    let u = ((b - w[0]).dot(&chord) / chord.norm_squared()).clamp(0.0, 1.0);
                    let e = (b - (w[0] + chord * u)).norm();
                    assert!(e <= tol * (1.0 + 1e-9) + 1e-12, "tol {tol:e}: {e:e}");
                }
            }
        }
        // a cubic and its relative form flatten alike
        let a = contours_from_svg_path("M 1 1 C 1 2 2 2 2 1", 1e-4).unwrap();
        let b = contours_from_svg_path("M 1 1 c 0 1 1 1 1 0", 1e-4).unwrap();
        assert_eq!(a, b);
        let last = a[0].points.last().unwrap();
        assert_eq!(*last, Vector2::new(2.0, 1.0));
    }

    fn where_(d: &str) -> (usize, usize, String) {
        match contours_from_svg_path(d, 1e-3) {
            Err(Error::Parse {
                line,
                column,
                message,
                ..
            }) => (line, column, message),
            other => panic!("{d:?}: expected a parse error, got {other:?}"),
        }
    }

    #[test]
    fn bad_paths_name_the_place_the_grammar_stops() {
        // (data, column, words of the message)
        for (d, column, words) in [
            ("L 1 1", 1, "starts with a move"),
            ("  5 5", 3, "starts with a move"),
            ("M 0 0 L 1", 10, "L is short of numbers"),
            ("M 0 0 A 1 1 0 0 1 2", 20, "A is short of numbers"),
            ("M 0 0 S 1 1 2", 14, "S is short of numbers"),
            ("M 0 0 T 1 L 2 2", 11, "T is short of numbers before 'L'"),
            ("M 0 0 X 1 1", 7, "cannot read 'X'"),
            ("M 0 0 L 1e999 0", 9, "not a finite number: \"1e999\""),
            ("M 0 0 L 1 # 2", 11, "cannot read \"#\""),
            ("M 0", 4, "M is short of numbers"),
            ("M 0 0 Z 1 2", 9, "a number after Z"),
            // a point beyond the largest coordinate: at the command that draws it
            ("M 0 0 L 1.7e308 0", 7, "beyond the largest coordinate"),
            (
                "M 0 0 L 2e306 0 l 2e306 0",
                17,
                "beyond the largest coordinate",
            ),
        ] {
            let (line, c, message) = where_(d);
            assert_eq!((line, c), (1, column), "{d}: {message}");
            assert!(message.contains(words), "{d}: {message}");
        }
        assert_eq!(where_("M 0 0\nL 1"), (2, 4, "L is short of numbers".into()));
        assert!(matches!(
            contours_from_svg_path("M 0 0 L 1 1", 0.0),
            Err(Error::NotPositive { .. })
        ));
        assert_eq!(contours_from_svg_path("", 1e-3).unwrap(), []);
        // a lone move draws nothing
        assert_eq!(contours_from_svg_path("M 1 1 M 2 2", 1e-3).unwrap(), []);
    }

    proptest! {
        /// Any path text: contours of finite points or a typed error placed inside the text.
        #[test]
        fn any_path_text_is_read_or_refused(d in "[MmLlHhVvCcQqZzAaSsXx0-9 ,.eE+\\-\\n]{0,120}") {
            match contours_from_svg_path(&d, 1e-2) {
                Ok(cs) => prop_assert!(cs.iter().all(|c| c.points.iter().all(|p| p.x.is_finite() && p.y.is_finite()))),
                Err(Error::Parse { line, column, .. }) => {
                    let lines: Vec<&str> = d.split('\n').collect();
                    prop_assert!(line >= 1 && line <= lines.len());
                    prop_assert!(column >= 1 && column <= lines[line - 1].chars().count() + 1);
                }
                Err(Error::TooLarge { .. }) => {}
                Err(e) => prop_assert!(false, "unexpected {e}"),
            }
        }
    }
}

mod smooth_curves_and_arcs {
    use nalgebra::Vector2;
    use splinelab::input::contours_from_svg_path;
    use splinelab::metrics::curve::segment_distance;

    fn points(d: &str, tol: f64) -> Vec<Vector2<f64>> {
        let c = contours_from_svg_path(d, tol).unwrap();
        c.into_iter().flat_map(|c| c.points).collect()
    }

    #[test]
    fn smooth_curves_reflect_the_previous_control_point() {
        // S after C: its first control point is the reflection of C's second about C's end
        assert_eq!(
            points("M 0 0 C 1 2 3 2 4 0 S 7 -2 8 0", 1e-4),
            points("M 0 0 C 1 2 3 2 4 0 C 5 -2 7 -2 8 0", 1e-4)
        );
        assert_eq!(
            points("m 0 0 c 1 2 3 2 4 0 s 3 -2 4 0", 1e-4),
            points("M 0 0 C 1 2 3 2 4 0 C 5 -2 7 -2 8 0", 1e-4)
        );
        // S after a line: its first control point is the current point
        assert_eq!(
            points("M 0 0 L 1 0 S 2 2 3 0", 1e-4),
            points("M 0 0 L 1 0 C 1 0 2 2 3 0", 1e-4)
        );
        // T after Q (and after T), and T after a line
        assert_eq!(
            points("M 0 0 Q 1 2 2 0 T 4 0 T 6 0", 1e-4),
            points("M 0 0 Q 1 2 2 0 Q 3 -2 4 0 Q 5 2 6 0", 1e-4)
        );
        assert_eq!(
            points("M 0 0 L 1 1 T 3 1", 1e-4),
            points("M 0 0 L 1 1 Q 1 1 3 1", 1e-4)
        );
        // S after Q does not reflect Q's control point
        assert_eq!(
            points("M 0 0 Q 1 2 2 0 S 3 1 4 0", 1e-4),
            points("M 0 0 Q 1 2 2 0 C 2 0 3 1 4 0", 1e-4)
        );
    }

    #[test]
    fn arcs_lie_on_their_ellipse_within_the_tolerance() {
        for tol in [1e-2, 1e-4, 1e-7] {
            // a half circle about (1, 0), on the side of the sweep
            for (sweep, side) in [(1, -1.0), (0, 1.0)] {
                let p = points(&format!("M 0 0 A 1 1 0 0 {sweep} 2 0"), tol);
                assert_eq!(p[0], Vector2::new(0.0, 0.0));
                assert_eq!(*p.last().unwrap(), Vector2::new(2.0, 0.0));
                for q in &p {
                    assert!(((q.x - 1.0).hypot(q.y) - 1.0).abs() < 1e-12);
                    assert!(q.y * side >= -1e-15, "sweep {sweep}: {q:?}");
                }
                // every chord within the tolerance of the circle: its midpoint's depth
                for w in p.windows(2) {
                    let m = (w[0] + w[1]) * 0.5;
                    assert!(1.0 - (m.x - 1.0).hypot(m.y) <= tol * (1.0 + 1e-9));
                }
            }
        }
        // a rotated ellipse (radii 3 and 1, 30°): every vertex on it, in its own axes
        let (a, b, phi) = (3.0, 1.0, 30f64.to_radians());
        let p = points("M 0 0 A 3 1 30 1 1 2 1", 1e-6);
        // the centre by the SVG specification's formulas (F.6.5), written out here
        let centre = {
            let (s, c) = phi.sin_cos();
            let h = (Vector2::new(0.0, 0.0) - Vector2::new(2.0, 1.0)) * 0.5;
            let q = Vector2::new(c * h.x + s * h.y, -s * h.x + c * h.y);
            let num = a * a * b * b - a * a * q.y * q.y - b * b * q.x * q.x;
            let den = a * a * q.y * q.y + b * b * q.x * q.x;
            let root = -(num / den).sqrt(); // large = sweep: the root's sign is −
            let cc = Vector2::new(root * a * q.y / b, -root * b * q.x / a);
            Vector2::new(c * cc.x - s * cc.y, s * cc.x + c * cc.y) + Vector2::new(1.0, 0.5)
        };
        let (s, c) = phi.sin_cos();
        for q in &p {
            let d = q - centre;
            let u = Vector2::new(c * d.x + s * d.y, -s * d.x + c * d.y);
            assert!(
                ((u.x / a).powi(2) + (u.y / b).powi(2) - 1.0).abs() < 1e-12,
                "{q:?}"
            );
        }
        // the large arc is the longer way round
        let small = points("M 0 0 A 3 1 30 0 1 2 1", 1e-6);
        let length = |p: &[Vector2<f64>]| p.windows(2).map(|w| (w[1] - w[0]).norm()).sum::<f64>();
        assert!(length(&p) > length(&small));
    }

    #[test]
    fn arcs_take_the_corrections_of_the_svg_specification() {
        // radii too small for the endpoints are scaled up: a half circle of radius 1
        let p = points("M 0 0 A 0.1 0.1 0 0 1 2 0", 1e-6);
        assert!(p
            .iter()
            .all(|q| ((q.x - 1.0).hypot(q.y) - 1.0).abs() < 1e-12));
        assert!(p.len() > 10);
        // a zero radius draws a line; equal endpoints draw nothing
        assert_eq!(
            points("M 0 0 A 0 1 0 0 1 2 0", 1e-6),
            vec![Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0)]
        );
        assert!(points("M 0 0 A 1 1 0 0 1 0 0", 1e-6).is_empty());
        // negative radii are their absolute values; relative arcs are the absolute ones
        assert_eq!(
            points("M 0 0 A -1 -1 0 0 1 2 0", 1e-6),
            points("M 0 0 A 1 1 0 0 1 2 0", 1e-6)
        );
        assert_eq!(
            points("M 1 1 a 1 1 0 0 1 2 0", 1e-6),
            points("M 1 1 A 1 1 0 0 1 3 1", 1e-6)
        );
        // a flattened arc is within the tolerance of a dense one, chord by chord
        let coarse = points("M 0 0 A 2 1 10 1 0 3 2", 1e-3);
        let dense = points("M 0 0 A 2 1 10 1 0 3 2", 1e-9);
        for q in &dense {
            let d = coarse
                .windows(2)
                .map(|w| segment_distance(*q, w[0], w[1]))
                .fold(f64::INFINITY, f64::min);
            assert!(d <= 1e-3 * (1.0 + 1e-6), "{d}");
        }
    }

    #[test]
    fn arc_flags_follow_the_svg_grammar() {
        // flags are single digits: packed with each other or with the next number, as
        // minifiers write them, they read as the separated forms
        for (packed, separate) in [
            ("M 0 0 A 1 1 0 01 2 2", "M 0 0 A 1 1 0 0 1 2 2"),
            ("M0 0a1 1 0 00-.5.5", "M 0 0 a 1 1 0 0 0 -0.5 0.5"),
            ("M0 0a.5.5 0 0 0-1 0", "M 0 0 a 0.5 0.5 0 0 0 -1 0"),
            ("M0 0a6 6 0 10-6 6", "M 0 0 a 6 6 0 1 0 -6 6"),
            (
                "M0 0a.18.18 0 00.29.15",
                "M 0 0 a 0.18 0.18 0 0 0 0.29 0.15",
            ),
        ] {
            assert_eq!(points(packed, 1e-6), points(separate, 1e-6), "{packed}");
        }
        // a flag that is not 0 or 1 is refused at the flag
        for (d, column) in [
            ("M 0 0 A 1 1 0 2 1 2 2", 15),
            ("M 0 0 A 1 1 0 0 2 2 2", 17),
            ("M 0 0 a 1 1 0 .5 0 2 2", 15),
        ] {
            match contours_from_svg_path(d, 1e-3) {
                Err(splinelab::Error::Parse {
                    line: 1,
                    column: c,
                    message,
                    ..
                }) => {
                    assert_eq!(c, column, "{d}: {message}");
                    assert!(message.contains("arc flag 0 or 1"), "{message}");
                }
                other => panic!("{d}: {other:?}"),
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Limits that hold at the limit
// ---------------------------------------------------------------------------------------------

mod limits {
    use nalgebra::Vector2;
    use proptest::prelude::*;
    use splinelab::input::{contours_from_svg_path, SvgArc};
    use splinelab::Error;

    #[test]
    fn a_curve_past_the_piece_cap_is_refused_not_drawn_coarse() {
        // a half circle of radius 5e9 within 1e-6 needs ~8e7 chords
        match contours_from_svg_path("M 0 0 A 1 1 0 0 1 1e10 0", 1e-6) {
            Err(Error::Parse {
                column, message, ..
            }) => {
                assert_eq!(column, 7, "{message}");
                assert!(message.contains("more than 65536 pieces"), "{message}");
            }
            other => panic!("{other:?}"),
        }
        // a cubic as long
        assert!(matches!(
            contours_from_svg_path("M 0 0 C 0 1e10 1e10 1e10 1e10 0", 1e-6),
            Err(Error::Parse { .. })
        ));
        // at a coarser tolerance both are read, every chord within it
        let c = contours_from_svg_path("M 0 0 A 1 1 0 0 1 1e10 0", 1e3).unwrap();
        let centre = Vector2::new(5e9, 0.0);
        for w in c[0].points.windows(2) {
            let mid = (w[0] + w[1]) * 0.5;
            assert!(5e9 - (mid - centre).norm() <= 1e3 * (1.0 + 1e-9));
        }
    }

    #[test]
    fn arcs_with_extreme_radii_are_read_or_refused_by_name() {
        // radii negligible beside the chord: scaled up to the half circle on it
        let c = contours_from_svg_path("M 0 0 A 1e-300 1e-300 0 1 1 1e6 0", 1e-3).unwrap();
        let centre = Vector2::new(5e5, 0.0);
        for p in &c[0].points {
            assert!(((p - centre).norm() - 5e5).abs() <= 1e-9 * 5e5, "{p:?}");
        }
        assert!(c[0].points.len() > 100);
        // subnormal radii, and radii so unequal that their ratio underflows: a line
        for d in [
            "M 0 0 A 1e-320 1e-320 0 1 1 1e6 0",
            "M 0 0 A 1e300 1e-300 0 1 1 1e6 0",
        ] {
            let c = contours_from_svg_path(d, 1e-3).unwrap();
            assert!(
                c[0].points.iter().all(|p| p.iter().all(|v| v.is_finite())),
                "{d}"
            );
        }
        // an arc that reaches beyond the largest coordinate is refused naming the arc
        match contours_from_svg_path("M 0 0 A 1e307 1e307 0 1 1 1 0", 1e300) {
            Err(Error::Parse { message, .. }) => {
                assert!(message.contains("the arc (radii"), "{message}")
            }
            other => panic!("{other:?}"),
        }
    }

    proptest! {
        /// Radii too small for the end points are scaled up and the centre is the chord's
        /// midpoint, exactly (SVG's radicand is zero there); every point drawn lies on the
        /// scaled ellipse.
        #[test]
        fn scaled_up_arcs_are_centred_exactly_on_the_chord(
            from in (-1e3f64..1e3, -1e3f64..1e3),
            to in (-1e3f64..1e3, -1e3f64..1e3),
            shape in (0.05f64..1.0, 0.05f64..1.0),
            shrink in 1e-6f64..0.999,
            rotation in 0.0f64..360.0,
            flags in any::<(bool, bool)>(),
        ) {
            let (from, to) = (Vector2::new(from.0, from.1), Vector2::new(to.0, to.1));
            prop_assume!((from - to).norm() > 1e-3);
            // radii of this shape just large enough, then shrunk
            let probe = SvgArc {
                radii: Vector2::new(shape.0, shape.1) * 1e-9,
                rotation: rotation.to_radians(),
                large: flags.0,
                sweep: flags.1,
            };
            let needed = probe.centre_form(from, to).unwrap().radii;
            let arc = SvgArc { radii: needed * shrink, ..probe };
            let c = arc.centre_form(from, to).unwrap();
            prop_assert_eq!(c.centre, (from + to) * 0.5);
            prop_assert!((c.sweep.abs() - std::f64::consts::PI).abs() < 1e-9);
            let d = format!(
                "M {} {} A {} {} {rotation} {} {} {} {}",
                from.x, from.y, arc.radii.x, arc.radii.y,
                u8::from(flags.0), u8::from(flags.1), to.x, to.y
            );
            let points = &contours_from_svg_path(&d, 1e-9 * c.radii.amax()).unwrap()[0].points;
            let (sin, cos) = rotation.to_radians().sin_cos();
            for p in points {
                let q = p - c.centre;
                let local = Vector2::new(cos * q.x + sin * q.y, -sin * q.x + cos * q.y);
                let unit = Vector2::new(local.x / c.radii.x, local.y / c.radii.y).norm();
                prop_assert!((unit - 1.0).abs() < 1e-12, "{}: {}", d, unit);
            }
        }
    }
}

/// The forms the CSV grammar allows that a hand-written layer got wrong: pandas' unnamed
/// index column, CR-only line ends with comments, headers narrower than their rows, empty
/// and quoted names.
#[test]
fn csv_by_the_grammar_line_ends_comments_and_headers() {
    let names = |n: &[&str]| Columns::Names(n.iter().map(|s| s.to_string()).collect());
    // pandas' to_csv(sep=' ') with its index: the header's first name is empty
    let text = " w x\n0 1.5 2.5\n1 3.5 4.5\n";
    let p = points_from_csv::<2>(text, &names(&["w", "x"])).unwrap();
    assert_eq!(p, [v2(1.5, 2.5), v2(3.5, 4.5)]);
    // the same without the empty name: a header one short names the last columns
    let text = "w,x\n0,1.5,2.5\n1,3.5,4.5\n";
    let p = points_from_csv::<2>(text, &names(&["w", "x"])).unwrap();
    assert_eq!(p, [v2(1.5, 2.5), v2(3.5, 4.5)]);
    // two short: refused, never shifted
    let (line, _, message) = at(points_from_csv("w,x\n0,1,1.5,2.5\n", &names(&["w", "x"])));
    assert_eq!(line, 2, "{message}");
    assert!(message.contains("the header has 2 names"), "{message}");
    // CR-only line ends: a comment ends at its line end
    for end in ["\r", "\n", "\r\n"] {
        let text = ["# points", "0,1", "1,2", "# more", "2,3", "3,4", "4,5"].join(end);
        let p = points_from_csv::<2>(&text, &Columns::First).unwrap();
        assert_eq!(p.len(), 5, "{end:?}");
        let (line, column, _) = at(points_from_csv(&format!("0,1{end}1,x"), &Columns::First));
        assert_eq!((line, column), (2, 3), "{end:?}");
    }
    // empty and quoted names are names
    let text = "\"\",\"a b\",\"\"\"c\"\"\"\n1,2,3\n";
    let p = points_from_csv::<2>(text, &names(&["\"c\"", ""])).unwrap();
    assert_eq!(p, [v2(3.0, 1.0)]);
}
