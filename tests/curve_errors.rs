//! Bad input to the curve and interpolation code gets a typed error, never a panic: one test
//! per case.

use nalgebra::{Vector1, Vector2};
use splinelab::blending::opengl::{opengl_groups, LastGroup};
use splinelab::blending::window::{printed_bspline_polyline, WindowCurve};
use splinelab::interp::collocation::{interpolate, interpolate_curve};
use splinelab::{
    de_casteljau_recursive, BSplineBasis, BSplineCurve, CubicSpline, EndCondition, EndKnots, Error,
    KnotVector, Lagrange, NurbsCurve, ParametricCurve, Parametrization, PiecewiseLinear,
    PowerPolynomial,
};

fn v2(x: f64, y: f64) -> Vector2<f64> {
    Vector2::new(x, y)
}

fn cubic_basis() -> BSplineBasis {
    BSplineBasis::new(KnotVector::open_uniform(3, 5, 0.0, 1.0).expect("knots"), 3)
}

#[test]
fn unsorted_knots() {
    let e = KnotVector::try_new(vec![0.0, 0.5, 0.4, 1.0]).unwrap_err();
    assert!(matches!(e, Error::KnotsNotSorted { index: 2, .. }), "{e:?}");
}

#[test]
fn too_short_knot_vectors() {
    let e = KnotVector::try_new(vec![0.0]).unwrap_err();
    assert!(
        matches!(e, Error::TooFewKnots { needed: 2, got: 1 }),
        "{e:?}"
    );
    // degree 2 needs 2(p + 1) = 6 knots
    let e = BSplineBasis::try_new(KnotVector::new(vec![0.0, 0.0, 1.0, 1.0]), 2).unwrap_err();
    assert!(
        matches!(e, Error::TooFewKnots { needed: 6, got: 4 }),
        "{e:?}"
    );
}

#[test]
fn knots_all_equal_or_empty_domain() {
    let e = KnotVector::try_new(vec![1.0, 1.0]).unwrap_err();
    assert!(matches!(e, Error::EmptyInterval { .. }), "{e:?}");
    // domain [t_p, t_{n+1}] = [0, 0] for these knots and degree 2
    let e =
        BSplineBasis::try_new(KnotVector::new(vec![0.0, 0.0, 0.0, 0.0, 0.0, 1.0]), 2).unwrap_err();
    assert!(
        matches!(
            e,
            Error::MultiplicityTooHigh { .. } | Error::EmptyInterval { .. }
        ),
        "{e:?}"
    );
}

#[test]
fn knot_multiplicity_above_the_order() {
    let e = BSplineBasis::try_new(KnotVector::new(vec![0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0]), 1)
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::MultiplicityTooHigh {
                multiplicity: 3,
                max: 2,
                ..
            }
        ),
        "{e:?}"
    );
    let e =
        KnotVector::extended_partition(0.0, 1.0, &[0.5], &[5], 4, EndKnots::Clamped).unwrap_err();
    assert!(
        matches!(
            e,
            Error::MultiplicityTooHigh {
                multiplicity: 5,
                max: 4,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn extended_partition_with_breakpoints_outside_or_unsorted() {
    let e = KnotVector::extended_partition(0.0, 1.0, &[0.5, 1.5], &[1, 1], 3, EndKnots::Clamped)
        .unwrap_err();
    assert!(matches!(e, Error::NotIncreasing { .. }), "{e:?}");
    let e = KnotVector::extended_partition(1.0, 0.0, &[], &[], 3, EndKnots::Clamped).unwrap_err();
    assert!(matches!(e, Error::EmptyInterval { .. }), "{e:?}");
    let e = KnotVector::extended_partition(0.0, 1.0, &[0.5], &[1, 1], 3, EndKnots::Clamped)
        .unwrap_err();
    assert!(matches!(e, Error::CountMismatch { .. }), "{e:?}");
    let e = KnotVector::extended_partition(0.0, 1.0, &[0.5], &[1], 3, EndKnots::Spaced(-1.0))
        .unwrap_err();
    assert!(matches!(e, Error::NotPositive { .. }), "{e:?}");
}

#[test]
fn wrong_number_of_control_points() {
    let e = BSplineCurve::try_new(cubic_basis(), vec![v2(0.0, 0.0); 4]).unwrap_err();
    assert!(
        matches!(
            e,
            Error::CountMismatch {
                expected: 5,
                got: 4,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn wrong_number_of_weights() {
    let e = NurbsCurve::try_new(cubic_basis(), vec![v2(0.0, 0.0); 5], vec![1.0; 6]).unwrap_err();
    assert!(
        matches!(
            e,
            Error::CountMismatch {
                expected: 5,
                got: 6,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn non_positive_weights() {
    for w in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = NurbsCurve::try_new(
            cubic_basis(),
            vec![v2(0.0, 0.0); 5],
            vec![1.0, 1.0, w, 1.0, 1.0],
        )
        .unwrap_err();
        assert!(
            matches!(e, Error::NonPositiveWeight { index: 2, .. }),
            "w = {w}: {e:?}"
        );
    }
    let circle = NurbsCurve::circle9(v2(0.0, 0.0), 1.0).expect("circle");
    assert!(matches!(
        circle.with_weight(1, 0.0),
        Err(Error::NonPositiveWeight { .. })
    ));
    assert!(matches!(
        circle.with_weight(99, 1.0),
        Err(Error::IndexOutOfRange { .. })
    ));
    assert!(matches!(
        NurbsCurve::circle7(v2(0.0, 0.0), -2.0),
        Err(Error::NotPositive { .. })
    ));
}

#[test]
fn repeated_parameter_values() {
    let x = [0.0, 1.0, 1.0, 2.0];
    let y = [0.0, 1.0, 2.0, 3.0];
    for e in [
        CubicSpline::function(&x, &y, EndCondition::Natural).unwrap_err(),
        PowerPolynomial::interpolate(&x, &y).unwrap_err(),
        Lagrange::try_new(&x, &y).unwrap_err(),
        PiecewiseLinear::try_new(&x, &y.map(Vector1::new)).unwrap_err(),
    ] {
        assert!(
            matches!(e, Error::RepeatedParameter { index: 2, .. }),
            "{e:?}"
        );
    }
    let e = CubicSpline::function(&[0.0, 2.0, 1.0], &[0.0; 3], EndCondition::Natural).unwrap_err();
    assert!(matches!(e, Error::NotIncreasing { index: 2, .. }), "{e:?}");
}

#[test]
fn repeated_points_under_chord_parametrizations() {
    let pts = [v2(0.0, 0.0), v2(1.0, 1.0), v2(1.0, 1.0), v2(2.0, 0.0)];
    for param in [Parametrization::ChordLength, Parametrization::Centripetal] {
        let e = CubicSpline::curve(&pts, param, EndCondition::Natural).unwrap_err();
        assert!(matches!(e, Error::RepeatedPoint { index: 2 }), "{e:?}");
    }
    // uniform parameters do not look at distances
    assert!(Parametrization::Uniform.parameters(&pts).is_ok());
}

#[test]
fn fewer_points_than_the_method_needs() {
    let e = CubicSpline::function(&[0.0], &[1.0], EndCondition::Natural).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooFewPoints {
                needed: 2,
                got: 1,
                ..
            }
        ),
        "{e:?}"
    );
    let e = CubicSpline::function(&[0.0, 1.0], &[1.0, 1.0], EndCondition::Periodic).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooFewPoints {
                needed: 3,
                got: 2,
                ..
            }
        ),
        "{e:?}"
    );
    let e = WindowCurve::lagrange(&[v2(0.0, 0.0); 3]).unwrap_err();
    assert!(matches!(e, Error::TooFewPoints { needed: 4, .. }), "{e:?}");
    let e = de_casteljau_recursive::<Vector2<f64>, f64>(&[v2(0.0, 0.0)], 0.5).unwrap_err();
    assert!(matches!(e, Error::TooFewPoints { needed: 2, .. }), "{e:?}");
    let e = PowerPolynomial::interpolate(&[], &[]).unwrap_err();
    assert!(matches!(e, Error::TooFewPoints { .. }), "{e:?}");
    let e = opengl_groups(&[v2(0.0, 0.0); 4], 5, LastGroup::AsPrinted).unwrap_err();
    assert!(matches!(e, Error::TooFewPoints { needed: 5, .. }), "{e:?}");
    let e =
        interpolate_curve(&[v2(0.0, 0.0), v2(1.0, 0.0)], 3, Parametrization::Uniform).unwrap_err();
    assert!(matches!(e, Error::TooFewPoints { needed: 4, .. }), "{e:?}");
}

#[test]
fn periodic_data_whose_ends_do_not_match() {
    let e = CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.5], EndCondition::Periodic)
        .unwrap_err();
    assert!(matches!(e, Error::PeriodicEndsMismatch { .. }), "{e:?}");
    let open = [v2(0.0, 0.0), v2(1.0, 1.0), v2(2.0, 0.0)];
    let e = CubicSpline::curve(&open, Parametrization::ChordLength, EndCondition::Periodic)
        .unwrap_err();
    assert!(matches!(e, Error::PeriodicEndsMismatch { .. }), "{e:?}");
}

#[test]
fn nan_and_infinite_input() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(
            KnotVector::try_new(vec![0.0, bad, 1.0]),
            Err(Error::NonFinite { .. })
        ));
        assert!(matches!(
            BSplineCurve::try_new(
                cubic_basis(),
                vec![
                    v2(0.0, 0.0),
                    v2(bad, 0.0),
                    v2(0.0, 0.0),
                    v2(0.0, 0.0),
                    v2(0.0, 0.0)
                ]
            ),
            Err(Error::NonFinite { .. })
        ));
        assert!(matches!(
            CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, bad, 1.0], EndCondition::Natural),
            Err(Error::NonFinite { .. })
        ));
        assert!(matches!(
            CubicSpline::function(
                &[0.0, 1.0, 2.0],
                &[0.0, 1.0, 1.0],
                EndCondition::clamped(bad, 0.0)
            ),
            Err(Error::NonFinite { .. })
        ));
        assert!(matches!(
            Lagrange::try_new(&[0.0, bad], &[1.0, 2.0]),
            Err(Error::NonFinite { .. })
        ));
        assert!(matches!(
            Parametrization::ChordLength.parameters(&[v2(0.0, 0.0), v2(bad, 1.0)]),
            Err(Error::NonFinite { .. })
        ));
        let curve = BSplineCurve::new(cubic_basis(), vec![v2(0.0, 0.0); 5]);
        assert!(matches!(curve.try_point(bad), Err(Error::NonFinite { .. })));
    }
}

#[test]
fn evaluation_outside_the_domain() {
    let curve = BSplineCurve::new(cubic_basis(), vec![v2(0.0, 0.0); 5]);
    assert!(curve.try_point(1.0).is_ok(), "right end is inside");
    assert!(matches!(
        curve.try_point(1.5),
        Err(Error::OutOfDomain { .. })
    ));
}

#[test]
fn schoenberg_whitney_violation() {
    // cubic, 5 basis functions on [0, ¼, ½, ¾, 1]-style knots; all sites crowded at the left
    // leave N₄ without a site in its support [t₄, t₈)
    let basis = cubic_basis();
    let sites = [0.0, 0.05, 0.1, 0.15, 0.2];
    let values = vec![Vector1::new(1.0); 5];
    let e = interpolate(basis, &sites, &values, &[]).unwrap_err();
    assert!(matches!(e, Error::SchoenbergWhitney { .. }), "{e:?}");
}

#[test]
fn bad_procedure_parameters() {
    assert!(matches!(
        opengl_groups(&[v2(0.0, 0.0); 6], 1, LastGroup::Truncated),
        Err(Error::DegreeTooLow { .. })
    ));
    assert!(matches!(
        printed_bspline_polyline(&[v2(0.0, 0.0); 6], 0),
        Err(Error::TooFewSamples { .. })
    ));
    assert!(matches!(
        interpolate_curve(&[v2(0.0, 0.0); 3], 0, Parametrization::Uniform),
        Err(Error::DegreeTooLow { .. })
    ));
}

#[test]
fn curve_errors_read_well() {
    let e = NurbsCurve::try_new(
        cubic_basis(),
        vec![v2(0.0, 0.0); 5],
        vec![1.0, 1.0, 0.0, 1.0, 1.0],
    )
    .unwrap_err();
    assert_eq!(e.to_string(), "weight 2 must be positive and finite, got 0");
}
