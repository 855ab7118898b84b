//! The report's numbers reproduced, the cause of the disagreement shown, and the order of
//! convergence observed.

// Index loops over k ∈ {x, y, z} read printed, listing and our values side by side.
#![allow(clippy::needless_range_loop)]
#[cfg(feature = "report")]
use splinelab::report::seed000::tables;
use splinelab::seeds::seed000::{agrees_to_printed, T3, T6};
use splinelab::study::hermite_error::REPORT_PREC;
use splinelab::study::hermite_error::{convergence, uniform_spline_errors, PatchEvaluation};
use splinelab::{Rect, Torus};

fn errors(side: f64, n: usize, m: usize, eval: PatchEvaluation) -> [f64; 3] {
    let rect = Rect::square(0.0, side).expect("valid");
    let e =
        uniform_spline_errors(&Torus::default(), &rect, n, m, REPORT_PREC, eval).expect("valid");
    [e.report_norm.x, e.report_norm.y, e.report_norm.z]
}

#[test]
fn t3_is_reproduced_to_every_printed_digit() {
    for row in &T3 {
        for eval in PatchEvaluation::ALL {
            let ours = errors(row.side, 1, 1, eval);
            for k in 0..3 {
                assert!(
                    agrees_to_printed(row.values[k], ours[k]),
                    "T3 [0,{}]² coord {k} by {eval:?}: printed {}, ours {}",
                    row.side,
                    row.values[k],
                    ours[k]
                );
            }
        }
    }
}

#[test]
fn the_reports_listing_reproduces_every_t6_value() {
    for row in &T6 {
        let lit = errors(row.side, row.n, row.m, PatchEvaluation::ReportListing);
        for k in 0..3 {
            assert!(
                agrees_to_printed(row.values[k], lit[k]),
                "T6 {}×{} coord {k}: printed {}, report's listing {}",
                row.n,
                row.m,
                row.values[k],
                lit[k]
            );
        }
    }
}

#[test]
fn the_correct_method_differs_exactly_where_codice7_is_wrong() {
    // Rows with m = 1 have tₐ = 0 on every patch, where X_st = 0: correct = printed.
    // z has X_st = 0 everywhere: correct = printed. x, y with m > 1: the sign error shows.
    for row in &T6 {
        let ours = errors(row.side, row.n, row.m, PatchEvaluation::HermiteMatrix);
        let dc = errors(row.side, row.n, row.m, PatchEvaluation::DeCasteljau);
        for k in 0..3 {
            let expect_agree = row.m == 1 || k == 2;
            assert_eq!(
                agrees_to_printed(row.values[k], ours[k]),
                expect_agree,
                "T6 {}×{} coord {k}: printed {}, ours {}",
                row.n,
                row.m,
                row.values[k],
                ours[k]
            );
            assert!(
                (ours[k] - dc[k]).abs() <= 1e-13,
                "matrix form {} vs de Casteljau {}",
                ours[k],
                dc[k]
            );
            if !expect_agree {
                let printed: f64 = row.values[k].parse().expect("number");
                assert!(
                    ours[k] < printed / 2.0,
                    "correct error {} should be well below {printed}",
                    ours[k]
                );
            }
        }
    }
}

#[test]
fn max_abs_error_converges_with_order_four() {
    let ns = [1, 2, 4, 8, 16, 32, 64];
    let rows = convergence(&Torus::default(), &Rect::unit(), &ns, REPORT_PREC).expect("valid");
    // From n = 4 on the observed order is asymptotic (n = 1 → 2 is still pre-asymptotic,
    // about 3.4–3.8 per coordinate).
    for row in rows.iter().filter(|r| r.n >= 4) {
        let o = row.order.expect("not the first row");
        for k in 0..3 {
            let (max_abs, rms) = (
                o.max_abs[k].expect("non-zero errors"),
                o.rms[k].expect("non-zero errors"),
            );
            assert!(
                (3.8..=4.2).contains(&max_abs),
                "order of max-abs at n = {}, coord {k}: {max_abs}",
                row.n,
            );
            assert!(
                (3.8..=4.2).contains(&rms),
                "rms order at n = {}: {rms}",
                row.n,
            );
        }
    }
    // the error really goes down by ~16 per halving
    assert!(
        rows[6].errors.max_abs.x < 1e-9,
        "{:?}",
        rows[6].errors.max_abs
    );
}

#[cfg(feature = "report")]
#[test]
fn tables_build_with_expected_shapes() {
    let t3 = tables::t3().expect("t3");
    assert_eq!(t3.df.shape(), (6, 13));
    let t6 = tables::t6().expect("t6");
    assert_eq!(t6.df.height(), 12);
    let eq = tables::equivalence().expect("equivalence");
    assert_eq!(eq.df.height(), 6);
    let conv = tables::convergence_table().expect("convergence");
    assert_eq!(conv.df.height(), 21);
}

#[cfg(feature = "report")]
#[test]
fn torus_partials_table_shows_dual_equal_to_closed_form() {
    let t = tables::torus_partials().expect("partials table");
    assert_eq!(
        t.df.height(),
        5 * 4 * 3,
        "5 points × (X and 3 partials) × 3 coordinates"
    );
    let worst = |name: &str| {
        let col = t.df.column(name).expect("column");
        (0..t.df.height())
            .map(|i| col.f64().expect("f64")[i].expect("value"))
            .fold(0.0, f64::max)
    };
    let dual = worst("abs_difference");
    assert!(dual <= 1e-15, "largest |dual − closed form| = {dual:e}");
    // every one of the 12 formulas, evaluated, equals its hyper-dual value
    let formula = worst("formula_abs_difference");
    assert!(formula <= 1e-15, "largest |formula − dual| = {formula:e}");
    let text = t.df.column("formula").expect("formula column");
    let first: Vec<String> = (0..12)
        .map(|i| text.text().expect("text")[i].clone().expect("value"))
        .collect();
    assert_eq!(
        first,
        [
            "cos(s)*(2 + cos(t))",
            "sin(s)*(2 + cos(t))",
            "sin(t)",
            "-sin(s)*(2 + cos(t))",
            "cos(s)*(2 + cos(t))",
            "0",
            "-cos(s)*sin(t)",
            "-sin(s)*sin(t)",
            "cos(t)",
            "sin(s)*sin(t)",
            "-cos(s)*sin(t)",
            "0",
        ]
    );
}

#[test]
fn printed_precision_is_respected() {
    assert!(agrees_to_printed("0.0717", 0.07174443));
    assert!(!agrees_to_printed("0.0717", 0.07176));
    assert!(agrees_to_printed("6.9577e-04", 6.95774e-4));
    assert!(!agrees_to_printed("6.9577e-04", 6.9580e-4));
    assert!(!agrees_to_printed("not a number", 1.0));
    assert!(!agrees_to_printed("0.0717", f64::NAN));
}

#[cfg(feature = "report")]
#[test]
fn notebook_html_shows_every_row_and_escapes() {
    let t6 = tables::t6().expect("t6");
    let html = t6.to_html().expect("html");
    assert_eq!(html.matches("<tr>").count(), 1 + 12, "header + 12 rows");
    assert!(!html.contains('…'), "no elided rows");
    let eq = tables::equivalence().expect("equivalence");
    let html = eq.to_html().expect("html");
    assert!(
        html.contains("&lt;") || !eq.notes.iter().any(|n| n.contains('<')),
        "escaped"
    );
}

#[cfg(feature = "report")]
#[test]
fn csv_is_full_precision_and_quoted() {
    use splinelab::report::frame::{Column, Frame};
    let x = [0.1 + 0.2, std::f64::consts::PI, -1.0e-300, 6.02214076e23];
    let df = Frame::try_new(vec![
        Column::new("x".into(), x.to_vec()),
        Column::new(
            "label".into(),
            vec!["plain", "a, b", "say \"hi\"", "two\nlines"],
        ),
        Column::new("maybe".into(), vec![Some(1.5), None, Some(2.0), None]),
    ])
    .expect("frame");
    let text = String::from_utf8(splinelab::report::table::csv(&df).expect("csv")).expect("utf8");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "x,label,maybe");
    for (k, v) in x.iter().enumerate().take(3) {
        let first = lines[k + 1].split(',').next().expect("field");
        assert_eq!(
            first.parse::<f64>().expect("float"),
            *v,
            "round trip of {v}"
        );
    }
    assert!(lines[2].contains("\"a, b\""), "{}", lines[2]);
    assert!(lines[3].contains("\"say \"\"hi\"\"\""), "{}", lines[3]);
    assert!(text.contains("\"two\nlines\""), "{text}");
    assert!(
        lines[2].ends_with(','),
        "a missing value is empty: {}",
        lines[2]
    );
}

/// A frame of every kind of column, with missing cells, goes to polars and back unchanged,
/// and a library table does too (its CSV byte for byte); a DataFrame of narrower polars types
/// comes in with the kinds widened.
#[cfg(feature = "polars")]
#[test]
fn frames_go_to_polars_and_back() {
    use polars::prelude::{Column as PlColumn, DataFrame};
    use splinelab::report::frame::{Column, Frame, Values};
    use splinelab::report::table;
    let frame = Frame::try_new(vec![
        Column::new(
            "f".into(),
            vec![Some(0.1 + 0.2), None, Some(f64::NAN), Some(-0.0)],
        ),
        Column::new("i".into(), vec![Some(-3i64), Some(i64::MIN), None, Some(7)]),
        Column::new("u".into(), vec![Some(u64::MAX), None, Some(0u64), Some(1)]),
        Column::new("b".into(), vec![Some(true), Some(false), None, Some(true)]),
        Column::new(
            "t".into(),
            vec![
                Some("a, b".to_string()),
                None,
                Some(String::new()),
                Some("ü".into()),
            ],
        ),
    ])
    .expect("frame");
    let back = Frame::try_from(&frame.to_polars().expect("to polars")).expect("from polars");
    // NaN ≠ NaN: compare the CSV text, which spells every cell
    assert_eq!(
        table::csv(&back).expect("csv"),
        table::csv(&frame).expect("csv")
    );
    assert_eq!(back.names(), frame.names());
    for (a, b) in back.columns().iter().zip(frame.columns()) {
        assert_eq!(
            std::mem::discriminant(a.values()),
            std::mem::discriminant(b.values()),
            "kind of {}",
            a.name()
        );
    }
    let t = tables::torus_partials().expect("table");
    let df = t.to_polars().expect("to polars");
    assert_eq!(df.shape(), t.df.shape());
    assert_eq!(
        table::csv(&Frame::try_from(&df).expect("back")).expect("csv"),
        table::csv(&t.df).expect("csv")
    );
    let narrow = DataFrame::new_infer_height(vec![
        PlColumn::new("a".into(), vec![1i32, -2]),
        PlColumn::new("b".into(), vec![1u32, 2]),
        PlColumn::new("c".into(), vec![0.5f32, 1.5]),
        PlColumn::new("d".into(), vec![None::<f64>, None]),
    ])
    .expect("df");
    let f = Frame::try_from(&narrow).expect("frame");
    assert_eq!(
        f.column("a").expect("a").values(),
        &Values::Int(vec![Some(1), Some(-2)])
    );
    assert_eq!(
        f.column("b").expect("b").values(),
        &Values::UInt(vec![Some(1), Some(2)])
    );
    assert_eq!(
        f.column("c").expect("c").f64(),
        Some(&[Some(0.5), Some(1.5)][..])
    );
    // an all-null column keeps its type's kind
    assert_eq!(f.column("d").expect("d").f64(), Some(&[None, None][..]));
}
