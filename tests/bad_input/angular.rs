//! angular: the Angular spline's chord-line limits (`AngularSpline::try_new`, `closed`,
//! `Method::Angular`), `classify`, `circumcircle`, `guide_point`, sampling (`polyline_into`)
//! and evaluation far outside the domain.

use super::*;
use splinelab::interp::classify;
use splinelab::{circumcircle, PieceKind};
use std::f64::consts::PI;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(chord_line_cases());
    all.extend(classify_and_guide_cases());
    all.extend(sampling_cases());
    all
}

/// The chord-line limits: tangents on a chord, collinear points, closed curves.
fn chord_line_cases() -> Vec<Case> {
    vec![
        case("angular::one_end_tangent_on_the_chord", || {
            // the tangent at P₁ lies on the chord P₁P₂, the one at P₂ does not: the limit is
            // the chord with a corner at P₂, so no G¹ piece
            let p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(2.0, 0.0), v2(3.0, 1.0)];
            expect_err!(
                AngularSpline::try_new(p),
                Error::NoSmoothPiece { point: 1, .. }
            )
        }),
        case(
            "angular::one_end_tangent_on_the_chord_at_the_far_end",
            || {
                let p = vec![v2(0.0, 1.0), v2(1.0, 0.0), v2(2.0, 0.0), v2(3.0, 0.0)];
                expect_err!(
                    AngularSpline::try_new(p),
                    Error::NoSmoothPiece { point: 1, .. }
                )
            },
        ),
        case(
            "angular::one_end_tangent_on_the_chord_through_method",
            || {
                let p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(2.0, 0.0), v2(3.0, 1.0)];
                expect_err!(
                    Method::Angular.curve(&p, false),
                    Error::NoSmoothPiece { .. }
                )
            },
        ),
        case("angular::collinear_points_reverse_direction", || {
            // (1,0) → (2,0) with the next point back at (1.5, 0): the tangent at (2,0) points
            // back along the chord
            let p = vec![
                v2(0.0, 0.0),
                v2(1.0, 0.0),
                v2(2.0, 0.0),
                v2(1.5, 0.0),
                v2(0.0, 1.0),
            ];
            expect_err!(
                AngularSpline::try_new(p),
                Error::NoSmoothPiece { point: 1, .. }
            )
        }),
        case("angular::closed_collinear_triangle", || {
            let q = [v2(0.0, 0.0), v2(2.0, 0.0), v2(1.0, 0.0)];
            expect_err!(
                AngularSpline::closed(&q),
                Error::NoSmoothPiece { .. } | Error::ReversedPoints { .. }
            )
        }),
        case("angular::closed_rectangle_with_side_points", || {
            // the corners with a point in the middle of each side: collinear triples at the
            // side points, next to non-collinear ones at the corners
            let q = [
                v2(1.0, -0.5),
                v2(1.0, 0.0),
                v2(1.0, 0.5),
                v2(0.0, 0.5),
                v2(-1.0, 0.5),
                v2(-1.0, 0.0),
                v2(-1.0, -0.5),
                v2(0.0, -0.5),
            ];
            expect_err!(AngularSpline::closed(&q), Error::NoSmoothPiece { .. })
        }),
        case("angular::all_collinear_forward_is_straight", || {
            let p: Vec<Vector2<f64>> = (0..6).map(|i| v2(i as f64, 2.0 * i as f64)).collect();
            let s = ok(AngularSpline::try_new(p.clone()))?;
            ensure!(
                s.kinds().iter().all(|k| *k == PieceKind::Straight),
                "{:?}",
                s.kinds()
            );
            angular_ok(p)
        }),
        case("angular::just_beyond_the_collinear_threshold", || {
            // an angle of about 1e-6 from the chord keeps the paper's curve: G¹, interpolating
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1.0, 0.0),
                v2(2.0, 1e-6),
                v2(3.0, 1.0),
            ])
        }),
    ]
}

/// `classify`, `circumcircle` and `guide_point`.
fn classify_and_guide_cases() -> Vec<Case> {
    vec![
        case("angular::classify_non_finite", || {
            sweep(2, |bad, k| {
                let mut a = [0.5, -0.5];
                a[k] = bad;
                expect_err!(classify(a[0], a[1]), Error::NonFinite { .. })
            })
        }),
        case("angular::classify_chord_limits", || {
            expect_err!(classify(0.0, -0.5), Error::NoSmoothPiece { point: 0, .. })?;
            expect_err!(classify(0.5, 1e-12), Error::NoSmoothPiece { .. })?;
            expect_err!(classify(PI, PI), Error::NoSmoothPiece { .. })?;
            expect_err!(classify(0.0, PI), Error::NoSmoothPiece { .. })?;
            ensure!(
                classify(0.0, -0.0) == Ok(PieceKind::Straight),
                "{:?}",
                classify(0.0, -0.0)
            );
            ensure!(
                classify(5e-324, -5e-324) == Ok(PieceKind::Straight),
                "subnormal"
            );
            Ok(())
        }),
        case("angular::classify_the_three_curved_cases", || {
            ensure!(classify(0.5, -0.5) == Ok(PieceKind::Standard), "standard");
            ensure!(classify(-0.5, 0.5) == Ok(PieceKind::Reflected), "reflected");
            ensure!(
                classify(0.5, 0.5) == Ok(PieceKind::Inflection),
                "inflection"
            );
            ensure!(
                classify(-3.0, -3.0) == Ok(PieceKind::Inflection),
                "inflection below"
            );
            Ok(())
        }),
        case("angular::circumcircle_degenerate_is_none", || {
            let (o, x, y) = (v2(0.0, 0.0), v2(1.0, 0.0), v2(2.0, 0.0));
            ensure!(circumcircle(o, x, y).is_none(), "collinear");
            ensure!(circumcircle(o, o, x).is_none(), "two equal");
            ensure!(
                circumcircle(v2(f64::NAN, 0.0), x, v2(0.0, 1.0)).is_none(),
                "NaN"
            );
            ensure!(
                circumcircle(v2(f64::INFINITY, 0.0), x, v2(0.0, 1.0)).is_none(),
                "infinite"
            );
            Ok(())
        }),
        case("angular::circumcircle_extreme_scales", || {
            for s in [1e-300, 1e-155, 1e150, 1e300, MAX_COORDINATE] {
                let (a, b, c) = (v2(s, 0.0), v2(0.0, s), v2(-s, 0.0));
                match circumcircle(a, b, c) {
                    None => {}
                    Some((centre, r)) => {
                        ensure!(
                            centre.amax() <= 1e-12 * s && (r - s).abs() <= 1e-12 * s,
                            "scale {s:e}: centre {centre:?}, radius {r:e}"
                        );
                    }
                }
            }
            Ok(())
        }),
        case("angular::guide_point_subnormal_tangent", || {
            // only the direction of the tangent matters
            let g = ok(guide_point(v2(0.0, 0.0), v2(1.0, 1.0), v2(5e-324, 0.0)))?;
            ensure!((g - v2(-1.0, 1.0)).amax() <= 1e-15, "{g:?}");
            Ok(())
        }),
        case("angular::guide_point_sweep_non_finite", || {
            sweep(6, |bad, k| {
                let mut c = [0.0, 0.0, 1.0, 1.0, 1.0, 0.0];
                c[k] = bad;
                expect_err!(
                    guide_point(v2(c[0], c[1]), v2(c[2], c[3]), v2(c[4], c[5])),
                    Error::NonFinite { .. }
                )
            })
        }),
        case("angular::guide_point_beyond_coordinate_limit", || {
            expect_err!(
                guide_point(v2(2.0 * MAX_COORDINATE, 0.0), v2(1.0, 1.0), v2(1.0, 0.0)),
                Error::CoordinateTooLarge { .. }
            )?;
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 1.0), v2(f64::MAX, 0.0)),
                Error::CoordinateTooLarge { .. }
            )
        }),
    ]
}

/// Sampling (`polyline_into`), too many points, evaluation far outside, `eval_piece`.
fn sampling_cases() -> Vec<Case> {
    vec![
        case("angular::polyline_into_too_few_samples", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            let mut out = vec![v2(9.0, 9.0)];
            for n in [0, 1] {
                expect_err!(s.polyline_into(n, &mut out), Error::TooFewSamples { .. })?;
            }
            Ok(())
        }),
        risky("angular::polyline_into_usize_max", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            let mut out = Vec::new();
            expect_err!(
                s.polyline_into(usize::MAX, &mut out),
                Error::TooLarge { .. }
            )
        }),
        risky("angular::polyline_into_max_elements_plus_one", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            let mut out = Vec::new();
            expect_err!(
                s.polyline_into(MAX_ELEMENTS + 1, &mut out),
                Error::TooLarge { .. }
            )
        }),
        risky("angular::open_too_many_points", || {
            expect_err!(
                AngularSpline::try_new(vec![v2(0.0, 0.0); MAX_ELEMENTS + 1]),
                Error::TooLarge { .. }
            )
        }),
        case("angular::polyline_into_matches_point", || {
            let s = ok(AngularSpline::try_new(six_points(1.0)))?;
            let mut out = Vec::new();
            ok(s.polyline_into(1001, &mut out))?;
            let (a, b) = s.domain();
            ensure!(out.len() == 1001, "{} samples", out.len());
            for (k, p) in out.iter().enumerate() {
                let t = if k == 1000 {
                    b
                } else {
                    a + (b - a) * k as f64 / 1000.0
                };
                let e = (p - s.point(t)).amax();
                ensure!(e <= 1e-13, "sample {k}: {e:e}");
            }
            Ok(())
        }),
        case("angular::evaluation_far_outside_is_finite", || {
            let s = ok(AngularSpline::try_new(six_points(1.0)))?;
            for t in [-f64::MAX, -1e300, 1e300, f64::MAX, 5e-324, -5e-324] {
                let p = s.point(t);
                ensure!(p.iter().all(|x| x.is_finite()), "at {t:e}: {p:?}");
            }
            expect_err!(s.try_point(f64::INFINITY), Error::NonFinite { .. })?;
            expect_err!(s.try_point(-1e-300), Error::OutOfDomain { .. })
        }),
        risky(
            "angular::eval_piece_out_of_range_panics_as_documented",
            || {
                let s = ok(AngularSpline::try_new(four_points()))?;
                expect_panic("eval_piece(1, ·) of a one-piece spline", move || {
                    s.eval_piece(1, 0.5)
                })
            },
        ),
        case("angular::subnormal_gap", || {
            // found by the 10⁴-case random run (seed 2): consecutive points 5e-324 apart made a
            // piece whose derivative underflowed to zero, a vanishing tangent
            let pts = vec![
                Vector2::new(0.0, 0.0),
                Vector2::new(0.0, -2.8982418757243558),
                Vector2::new(-4.696082535770794, -6.072665850216147),
                Vector2::new(5e-324, 0.0),
                Vector2::new(0.0, 0.0),
                Vector2::new(0.0, -7.644987390097072),
            ];
            expect_err!(
                AngularSpline::try_new(pts),
                Error::NoSmoothPiece { point: 3, .. }
            )?;
            Ok(())
        }),
    ]
}
