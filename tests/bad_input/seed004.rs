//! seed 004: Hermite curve, cardinal and Angular splines, guide points, and (feature `report`)
//! the glyph outlines of the letter "a" (`splinelab::seeds::letters::letter_a`) and the seed-004
//! figures built on them

use super::*;
#[cfg(feature = "report")]
use splinelab::report::seed004::figures;
#[cfg(feature = "report")]
use splinelab::seeds::letters::letter_a;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(hermite_and_cardinal_cases());
    all.extend(angular_cases());
    all.extend(bspline_order_and_fit_cases());
    all.extend(shape_method_and_guide_cases());
    all.extend(letters_cases());
    all
}

/// `HermiteCurve` and `CardinalSpline`.
fn hermite_and_cardinal_cases() -> Vec<Case> {
    vec![
        case("seed004::hermite_curve_one_point", || {
            expect_err!(
                HermiteCurve::try_new(vec![0.0], vec![v2(0.0, 0.0)], vec![v2(1.0, 0.0)]),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::hermite_curve_count_mismatch", || {
            expect_err!(
                HermiteCurve::try_new(
                    vec![0.0, 1.0],
                    vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                    vec![v2(1.0, 0.0)]
                ),
                Error::CountMismatch { .. }
            )
        }),
        case("seed004::hermite_curve_repeated_knot", || {
            expect_err!(
                HermiteCurve::try_new(
                    vec![0.0, 0.0],
                    vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                    vec![v2(1.0, 0.0); 2]
                ),
                Error::RepeatedParameter { .. }
            )
        }),
        case("seed004::hermite_curve_nan_tangent", || {
            expect_err!(
                HermiteCurve::try_new(
                    vec![0.0, 1.0],
                    vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                    vec![v2(f64::NAN, 0.0); 2]
                ),
                Error::NonFinite { .. }
            )
        }),
        case(
            "seed004::hermite_curve_tangent_times_width_too_large",
            || {
                expect_err!(
                    HermiteCurve::try_new(
                        vec![0.0, 1e300],
                        vec![v2(0.0, 0.0), v2(1.0, 0.0)],
                        vec![v2(1e300, 0.0); 2]
                    ),
                    Error::CoordinateTooLarge { .. } | Error::NonFinite { .. }
                )
            },
        ),
        case("seed004::cardinal_three_points", || {
            expect_err!(
                CardinalSpline::try_new(four_points()[..3].to_vec(), 0.5),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::cardinal_a_zero_is_the_polygon", || {
            let p = four_points();
            let c = CardinalSpline::try_new(p.clone(), 0.0).map_err(|e| e.to_string())?;
            // every point of the curve on the side between the interpolated points
            for k in 0..=64 {
                let q = c.point(k as f64 / 64.0);
                let d = splinelab::metrics::curve::segment_distance(q, p[1], p[2]);
                ensure!(d <= 1e-15, "{q:?} is {d} off the side");
            }
            Ok(())
        }),
        case("seed004::cardinal_a_negative", || {
            expect_err!(
                CardinalSpline::try_new(four_points(), -0.5),
                Error::Negative { .. }
            )
        }),
        case("seed004::cardinal_a_nan", || {
            expect_err!(
                CardinalSpline::try_new(four_points(), f64::NAN),
                Error::Negative { .. }
            )
        }),
        case("seed004::cardinal_a_huge_overflows_tangent", || {
            let p = vec![v2(0.0, 0.0), v2(1.0, 1.0), v2(1e300, 0.0), v2(3.0, 1.0)];
            expect_err!(
                CardinalSpline::try_new(p, 1e10),
                Error::CoordinateTooLarge { .. } | Error::NonFinite { .. }
            )
        }),
        case("seed004::cardinal_nan_point", || {
            let mut p = four_points();
            p[2].x = f64::NAN;
            expect_err!(CardinalSpline::try_new(p, 0.5), Error::NonFinite { .. })
        }),
        case("seed004::cardinal_closed_two_points", || {
            expect_err!(
                CardinalSpline::closed(&four_points()[..2], 0.5),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::cardinal_repeated_points_are_fine", || {
            // the cardinal spline has no chord: equal consecutive points are a valid stop
            let p = vec![v2(0.0, 0.0), v2(1.0, 1.0), v2(1.0, 1.0), v2(3.0, 1.0)];
            let s = ok(CardinalSpline::try_new(p, 0.5))?;
            ensure!(finite_vecs(&ok(s.polyline(33))?), "not finite");
            Ok(())
        }),
    ]
}

/// `AngularSpline`.
fn angular_cases() -> Vec<Case> {
    vec![
        case("seed004::angular_three_points", || {
            expect_err!(
                AngularSpline::try_new(four_points()[..3].to_vec()),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::angular_empty", || {
            expect_err!(AngularSpline::try_new(vec![]), Error::TooFewPoints { .. })
        }),
        case("seed004::angular_repeated_point", || {
            let mut p = four_points();
            p[2] = p[1];
            expect_err!(AngularSpline::try_new(p), Error::RepeatedPoint { index: 2 })
        }),
        case("seed004::angular_repeated_guide", || {
            let mut p = four_points();
            p[1] = p[0];
            expect_err!(AngularSpline::try_new(p), Error::RepeatedPoint { index: 1 })
        }),
        case("seed004::angular_repeated_signed_zero", || {
            let p = vec![v2(0.0, 0.0), v2(-0.0, -0.0), v2(2.0, 0.0), v2(3.0, 1.0)];
            expect_err!(AngularSpline::try_new(p), Error::RepeatedPoint { index: 1 })
        }),
        case("seed004::angular_reversal", || {
            let mut p = four_points();
            p[2] = p[0];
            expect_err!(
                AngularSpline::try_new(p),
                Error::ReversedPoints { index: 1 }
            )
        }),
        case("seed004::angular_nan", || {
            let mut p = four_points();
            p[3].y = f64::NAN;
            expect_err!(AngularSpline::try_new(p), Error::NonFinite { .. })
        }),
        case("seed004::angular_infinite", || {
            let mut p = four_points();
            p[0].x = f64::NEG_INFINITY;
            expect_err!(AngularSpline::try_new(p), Error::NonFinite { .. })
        }),
        case("seed004::angular_beyond_coordinate_limit", || {
            let mut p = four_points();
            p[0].x = 2.0 * MAX_COORDINATE;
            expect_err!(AngularSpline::try_new(p), Error::CoordinateTooLarge { .. })
        }),
        case("seed004::angular_at_coordinate_limit", || {
            let m = MAX_COORDINATE / 4.0;
            let p = vec![v2(-m, -m), v2(-m, m), v2(m, m), v2(m, -m)];
            angular_ok(p)
        }),
        case("seed004::angular_subnormal_spacing", || {
            let e = 1e-310;
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(e, e),
                v2(2.0 * e, 0.0),
                v2(3.0 * e, e),
            ])
        }),
        case("seed004::angular_mixed_scales", || {
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1e-300, 0.0),
                v2(1e300, 1e300),
                v2(-1e300, 1e300),
                v2(0.0, 1.0),
            ])
        }),
        case("seed004::angular_near_reversal", || {
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1.0, 0.0),
                v2(1e-12, 1e-15),
                v2(-1.0, 1.0),
            ])
        }),
        case("seed004::angular_collinear", || {
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1.0, 0.0),
                v2(2.0, 0.0),
                v2(3.0, 0.0),
                v2(4.0, 0.0),
            ])
        }),
        case("seed004::angular_backtrack_on_line", || {
            // P₀ lies on the chord between P₁ and P₂: the tangent at P₁ points back along the
            // chord (φ = π), a spike in the limit, no G¹ piece (issue 23: it was a straight
            // piece meeting its neighbour at a cusp)
            expect_err!(
                AngularSpline::try_new(vec![
                    v2(0.5, 0.0),
                    v2(0.0, 0.0),
                    v2(1.0, 0.0),
                    v2(2.0, 1.0)
                ]),
                Error::NoSmoothPiece { point: 1, .. }
            )
        }),
        case("seed004::angular_closed_two_points", || {
            expect_err!(
                AngularSpline::closed(&four_points()[..2]),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::angular_closed_seam_repeats", || {
            let q = [v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 1.0), v2(0.0, 0.0)];
            expect_err!(AngularSpline::closed(&q), Error::RepeatedPoint { .. })
        }),
        case("seed004::angular_eval_nan_and_outside", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            expect_err!(s.try_point(f64::NAN), Error::NonFinite { .. })?;
            expect_err!(s.try_point(1.5), Error::OutOfDomain { .. })?;
            let outside = s.point(7.0);
            ensure!(
                outside == s.point(1.0),
                "outside the domain the end point, got {outside:?}"
            );
            Ok(())
        }),
        risky("seed004::angular_too_many_points", || {
            expect_err!(
                AngularSpline::closed(&vec![v2(0.0, 0.0); MAX_ELEMENTS]),
                Error::TooLarge { .. }
            )
        }),
    ]
}

/// `BSplineCurve::with_order` and `fit_bspline`.
fn bspline_order_and_fit_cases() -> Vec<Case> {
    vec![
        case("seed004::bspline_order_one", || {
            expect_err!(
                BSplineCurve::with_order(four_points(), 1),
                Error::DegreeTooLow { .. }
            )
        }),
        case("seed004::bspline_order_above_count", || {
            expect_err!(
                BSplineCurve::with_order(four_points(), 5),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::bspline_order_empty", || {
            expect_err!(
                BSplineCurve::<2>::with_order(vec![], 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::bspline_order_nan", || {
            let mut p = four_points();
            p[1].x = f64::NAN;
            expect_err!(BSplineCurve::with_order(p, 3), Error::NonFinite { .. })
        }),
        case("seed004::bspline_order_huge", || {
            let mut p = four_points();
            p[1].x = 2.0 * MAX_COORDINATE;
            expect_err!(
                BSplineCurve::with_order(p, 3),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("seed004::fit_fewer_samples_than_vertices", || {
            expect_err!(
                fit_bspline(&four_points(), 5, 3, 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::fit_one_sample", || {
            expect_err!(
                fit_bspline(&four_points()[..1], 1, 2, 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::fit_bad_order", || {
            expect_err!(
                fit_bspline(&four_points(), 3, 4, 2),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::fit_repeated_samples", || {
            let p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 0.0), v2(2.0, 1.0)];
            expect_err!(fit_bspline(&p, 3, 2, 2), Error::RepeatedPoint { .. })
        }),
        case("seed004::fit_undetermined_vertex", || {
            let mut p: Vec<Vector2<f64>> = (0..30).map(|i| v2(i as f64 * 1e-3, 0.0)).collect();
            p.push(v2(50.0, 1.0));
            expect_err!(fit_bspline(&p, 10, 4, 2), Error::IllConditioned { .. })
        }),
        case("seed004::fit_huge_coordinates", || {
            let m = MAX_COORDINATE / 2.0;
            let p = vec![
                v2(-m, 0.0),
                v2(0.0, m),
                v2(m, 0.0),
                v2(0.0, -m),
                v2(-m * 0.9, 0.1),
            ];
            match fit_bspline(&p, 4, 3, 5) {
                Ok(f) => {
                    ensure!(
                        finite_vecs(f.curve.points()) && f.max_distance.is_finite(),
                        "{:?}",
                        f.curve.points()
                    );
                    Ok(())
                }
                Err(
                    Error::Overflow { .. }
                    | Error::CoordinateTooLarge { .. }
                    | Error::IllConditioned { .. },
                ) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        risky("seed004::fit_too_large", || {
            let p = vec![v2(0.0, 0.0), v2(1.0, 1.0)];
            expect_err!(
                fit_bspline(&p, usize::MAX, 2, 1),
                Error::TooFewPoints { .. } | Error::TooLarge { .. }
            )
        }),
    ]
}

/// Shapes, `paper_points`, error messages, `Method::curve`, `guide_point`.
fn shape_method_and_guide_cases() -> Vec<Case> {
    vec![
        case("seed004::shape_nan_ratio_reference", || {
            expect_err!(
                splinelab::Shape::Ellipse { ratio: f64::NAN }.reference(100),
                Error::NotPositive { .. }
            )
        }),
        case("seed004::shape_zero_rectangle_reference", || {
            let r = splinelab::Shape::Rectangle {
                width: 0.0,
                height: 1.0,
            };
            expect_err!(r.reference(100), Error::NotPositive { .. })
        }),
        case("seed004::paper_points_invalid_shape", || {
            let bad = splinelab::Shape::Parabola { half_width: -2.0 };
            expect_err!(
                splinelab::seeds::seed004::paper_points(&bad, &splinelab::Method::Angular, 5),
                Error::NotPositive { .. }
            )
        }),
        case("seed004::paper_points_tiny_counts", || {
            for (_, shape) in splinelab::seeds::seed004::SHAPES {
                for m in [
                    splinelab::Method::Angular,
                    splinelab::Method::Cardinal { a: 0.5 },
                    splinelab::Method::Linear,
                ] {
                    for count in [0, 1, 2, 3] {
                        let set = ok(splinelab::seeds::seed004::paper_points(&shape, &m, count))?;
                        let c = m.curve(&set.points, set.closed);
                        ensure!(
                            c.is_ok(),
                            "{} on {} with {count}: {}",
                            format_args!("{:?}", m),
                            shape.name(),
                            show(&c)
                        );
                    }
                }
            }
            Ok(())
        }),
        case("seed004::error_messages_at_index_zero", || {
            let text = format!(
                "{} {}",
                Error::RepeatedPoint { index: 0 },
                Error::ReversedPoints { index: 0 }
            );
            ensure!(text.contains("point 0"), "{text}");
            Ok(())
        }),
        case("seed004::method_closed_two_points", || {
            let two = [v2(0.0, 0.0), v2(1.0, 0.0)];
            expect_err!(
                splinelab::Method::Angular.curve(&two, true),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004::guide_repeated", || {
            expect_err!(
                guide_point(v2(1.0, 1.0), v2(1.0, 1.0), v2(1.0, 0.0)),
                Error::RepeatedPoint { .. }
            )
        }),
        case("seed004::guide_zero_tangent", || {
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 1.0), v2(0.0, 0.0)),
                Error::Degenerate { .. }
            )
        }),
        case("seed004::guide_tangent_away", || {
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 0.0), v2(-2.0, 0.0)),
                Error::Degenerate { .. }
            )
        }),
        case("seed004::guide_nan", || {
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 0.0), v2(f64::NAN, 0.0)),
                Error::NonFinite { .. }
            )
        }),
        case("seed004::guide_nearly_away_is_far", || {
            // almost straight away: a huge circle; the guide is far but finite, or refused
            let r = guide_point(v2(0.0, 0.0), v2(1.0, 0.0), v2(-1.0, 1e-8));
            match r {
                Ok(g) => ensure!(g.iter().all(|x| x.is_finite()), "{g:?}"),
                Err(Error::Degenerate { .. } | Error::CoordinateTooLarge { .. }) => {}
                Err(e) => return Err(format!("unexpected {e}")),
            }
            Ok(())
        }),
        case("seed004::guide_at_coordinate_limit", || {
            let m = MAX_COORDINATE;
            let r = guide_point(v2(-m, 0.0), v2(m, 0.0), v2(-1.0, 0.5));
            match r {
                Ok(g) => ensure!(g.iter().all(|x| x.abs() <= MAX_COORDINATE), "{g:?}"),
                Err(Error::CoordinateTooLarge { .. }) => {}
                Err(e) => return Err(format!("unexpected {e}")),
            }
            Ok(())
        }),
    ]
}

#[cfg(not(feature = "report"))]
fn letters_cases() -> Vec<Case> {
    Vec::new()
}

/// The glyph outlines of the letter "a" and the seed-004 figures built on them (feature
/// `report`).
#[cfg(feature = "report")]
fn letters_cases() -> Vec<Case> {
    vec![
        case("seed004::unknown_versions", || {
            for v in [0, 5, usize::MAX] {
                expect_err!(letter_a(v), Error::IndexOutOfRange { .. })?;
                expect_err!(
                    figures::letter(v),
                    RError::Core(Error::IndexOutOfRange { .. })
                )?;
            }
            Ok(())
        }),
        case("seed004::every_version_is_a_valid_target", || {
            for v in 1..=4 {
                let l = ok(letter_a(v))?;
                ensure!(!l.contours.is_empty(), "version {v}: no contour");
                for c in &l.contours {
                    ensure!(
                        c.points.len() >= 3 && finite_vecs(&c.points),
                        "version {v}: {} points",
                        c.points.len()
                    );
                    ensure!(
                        c.outline.len() > c.points.len()
                            && c.outline[0] == c.outline[c.outline.len() - 1],
                        "version {v}: outline not closed"
                    );
                    ensure!(
                        c.points.iter().all(|p| p.amax() <= 2.0),
                        "version {v}: beyond the em square"
                    );
                    ok(Target::polyline(&c.outline, true, 0.01))
                        .map_err(|e| format!("version {v}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("seed004::every_version_with_the_letter_methods", || {
            for v in 1..=4 {
                for c in ok(letter_a(v))?.contours {
                    for m in [
                        Method::Angular,
                        Method::Cardinal { a: 0.8 },
                        Method::Cubic {
                            end: CubicEnd::Relaxed,
                        },
                    ] {
                        match m.curve(&c.points, true) {
                            Ok(curve) => check_curve(&m, &c.points, true, &curve)
                                .map_err(|e| format!("version {v}: {e}"))?,
                            // the polygonal letter's collinear triples
                            Err(Error::NoSmoothPiece { .. }) if m == Method::Angular => {}
                            Err(e) => {
                                return Err(format!(
                                    "version {v}, {}: {e}",
                                    format_args!("{:?}", m)
                                ))
                            }
                        }
                    }
                }
            }
            Ok(())
        }),
        case("seed004::shape_column_out_of_range", || {
            for column in [9, usize::MAX] {
                expect_err!(figures::shape_column(column), RError::UnknownId { .. })?;
            }
            Ok(())
        }),
    ]
}
