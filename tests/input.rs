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

    /// Any text: points or a typed error, never a panic; a parse error's place is inside
    /// the text.
    #[test]
    fn any_text_is_read_or_refused(
        text in "[0-9eE+\\-., ;\\t\\nxyna#]{0,200}",
        first in any::<bool>(),
        cols in prop::collection::vec(prop_oneof![0usize..4, Just(usize::MAX)], 2),
    ) {
        let columns = if first { Columns::First } else { Columns::Indices(cols) };
        match points_from_csv::<2>(&text, &columns) {
            Ok(p) => prop_assert!(p.iter().all(|q| q.iter().all(|x| x.is_finite()))),
            Err(Error::Parse { line, column, .. }) => {
                let l = text.lines().nth(line - 1);
                prop_assert!(l.is_some(), "line {} of {:?}", line, text);
                prop_assert!(column >= 1 && column <= l.unwrap().chars().count() + 1);
            }
            Err(Error::TooFewPoints { .. }) => {}
            Err(e) => prop_assert!(false, "unexpected {e}"),
        }
    }
}
