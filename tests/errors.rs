//! Bad input gets a typed error, never a panic: one test per case.

use splinelab::study::hermite_error::{uniform_spline_errors, PatchEvaluation};
use splinelab::{
    de_casteljau, tabulate, Error, HermitePatch, HermiteSurface, Interval, Partition, Rect, Torus,
};

#[test]
fn empty_partition() {
    assert_eq!(
        Partition::try_new(vec![]),
        Err(Error::PartitionTooShort {
            what: "partition",
            got: 0
        })
    );
    assert!(matches!(
        Partition::try_new(vec![0.5]),
        Err(Error::PartitionTooShort { got: 1, .. })
    ));
}

#[test]
fn non_increasing_partition() {
    // one rule for nodes everywhere (domain::check_nodes): a tie is a repeated value, as for
    // interpolation abscissae, a decrease is a decrease
    assert!(matches!(
        Partition::try_new(vec![0.0, 0.5, 0.5, 1.0]),
        Err(Error::RepeatedParameter { index: 2, .. })
    ));
    assert!(matches!(
        splinelab::CubicSpline::function(
            &[0.0, 0.5, 0.5, 1.0],
            &[0.0; 4],
            splinelab::EndCondition::Natural
        ),
        Err(Error::RepeatedParameter { index: 2, .. })
    ));
    assert!(matches!(
        Partition::try_new(vec![0.0, 1.0, 0.9]),
        Err(Error::NotIncreasing { index: 2, .. })
    ));
}

#[test]
fn non_finite_partition_node() {
    assert!(matches!(
        Partition::try_new(vec![0.0, f64::NAN, 1.0]),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        Partition::uniform(0.0, f64::INFINITY, 3),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn zero_width_rectangle() {
    assert!(matches!(
        Rect::try_new(0.3, 0.3, 0.0, 1.0),
        Err(Error::EmptyInterval { start, end, .. }) if start == 0.3 && end == 0.3
    ));
    assert!(matches!(
        Rect::try_new(0.0, 1.0, 2.0, 1.0),
        Err(Error::EmptyInterval { .. })
    ));
}

#[test]
fn nan_rectangle_bound() {
    assert!(matches!(
        Rect::try_new(f64::NAN, 1.0, 0.0, 1.0),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        Interval::try_new(0.0, f64::NEG_INFINITY),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn nan_and_infinite_evaluation_parameters() {
    let spline = HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 2, 2).expect("valid");
    assert!(matches!(
        spline.try_point(f64::NAN, 0.5),
        Err(Error::NonFinite { what: "u", .. })
    ));
    assert!(matches!(
        spline.try_point(0.5, f64::INFINITY),
        Err(Error::NonFinite { what: "v", .. })
    ));
    assert!(matches!(
        spline.tabulate(&[0.0, f64::NAN], &[0.0]),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn parameters_outside_the_domain() {
    let spline = HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 2, 2).expect("valid");
    assert!(matches!(
        spline.try_point(1.0 + 1e-9, 0.5),
        Err(Error::OutOfDomain { what: "u", .. })
    ));
    assert!(
        spline.try_point(1.0, 1.0).is_ok(),
        "right ends belong to the domain"
    );
}

#[test]
fn sample_counts_below_two() {
    let patch = HermitePatch::from_surface(&Torus::default(), &Rect::unit());
    assert!(matches!(
        patch.tabulate(1, 15),
        Err(Error::TooFewSamples { got: 1, .. })
    ));
    assert!(matches!(
        patch.tabulate(15, 0),
        Err(Error::TooFewSamples { got: 0, .. })
    ));
    assert!(matches!(
        tabulate(&Torus::default(), &Rect::unit(), 1, 5),
        Err(Error::TooFewSamples { .. })
    ));
    assert!(matches!(
        uniform_spline_errors(
            &Torus::default(),
            &Rect::unit(),
            1,
            1,
            1,
            PatchEvaluation::HermiteMatrix
        ),
        Err(Error::TooFewSamples { .. })
    ));
}

#[test]
fn zero_patches() {
    assert!(matches!(
        Partition::uniform(0.0, 1.0, 0),
        Err(Error::ZeroPatches { .. })
    ));
    assert!(matches!(
        HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 0, 3),
        Err(Error::ZeroPatches { .. })
    ));
}

#[test]
fn empty_control_polygon() {
    let none: [f64; 0] = [];
    assert!(matches!(
        de_casteljau(&none, 0.5),
        Err(Error::TooFewPoints { got: 0, .. })
    ));
}

#[test]
fn non_positive_radii() {
    assert!(matches!(
        Torus::try_new(0.0, 1.0),
        Err(Error::NotPositive { .. })
    ));
    assert!(matches!(
        Torus::try_new(2.0, f64::NAN),
        Err(Error::NotPositive { .. })
    ));
}

#[test]
fn errors_read_well() {
    let e = Partition::try_new(vec![0.0, 1.0, 0.9]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "partition: nodes must be strictly increasing, but node 2 (0.9) <= node 1 (1)"
    );
}

#[test]
fn debug_shows_the_message_so_notebook_cells_read_well() {
    // `.expect(…)`, `unwrap` and evcxr's top-level `?` print an error with Debug
    let e = Partition::try_new(vec![0.0, 0.5, 0.5, 1.0]).unwrap_err();
    assert_eq!(format!("{e:?}"), format!("{e}"));
    assert!(!format!("{e:?}").contains('{'), "no field dump: {e:?}");
    #[cfg(feature = "report")]
    {
        let r = splinelab::report::figure("no-such-figure").unwrap_err();
        assert_eq!(format!("{r:?}"), format!("{r}"));
        let wrapped = splinelab::report::Error::from(e.clone());
        assert_eq!(
            format!("{wrapped:?}"),
            format!("{e}"),
            "the core message, unwrapped"
        );
    }
}

/// One `Result` story (issue 48): `?` takes either error type into the other, and a round
/// trip gives back the error it started from (no nesting), for every kind of report error.
#[cfg(feature = "report")]
#[test]
fn the_two_error_types_convert_both_ways_without_nesting() {
    use splinelab::report;
    let core = Error::TooFewSamples {
        what: "prec (samples per patch side)",
        got: 1,
    };
    let as_report = report::Error::from(core.clone());
    assert_eq!(as_report, report::Error::Core(core.clone()));
    assert_eq!(Error::from(as_report), core);
    for drawn in [
        report::Error::Figure {
            name: "f".into(),
            message: "m".into(),
        },
        report::Error::UnknownId {
            what: "output",
            id: "x".into(),
        },
        report::Error::Io {
            path: "out/x.png".into(),
            message: "denied".into(),
        },
    ] {
        let as_core = Error::from(drawn.clone());
        assert_eq!(
            as_core.to_string(),
            drawn.to_string(),
            "the message is kept"
        );
        assert!(matches!(&as_core, Error::Layer(_)));
        assert_eq!(report::Error::from(as_core), drawn);
    }
    // a function of either kind takes both with `?`
    fn mathematics_first() -> splinelab::Result<usize> {
        let spline = HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 2, 2)?;
        let figure = report::draw::Plot3d::new("t").spline(&spline)?.figure();
        Ok(figure.to_png()?.len())
    }
    fn report_first() -> report::Result<usize> {
        Ok(mathematics_first()? + Partition::uniform(0.0, 1.0, 2)?.len())
    }
    assert!(report_first().unwrap() > 1000);
}
