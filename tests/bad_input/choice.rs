//! choice: the automatic point choice (`src/interp/choice/`): `Target`, its placements and
//! measure, `fewest_points`, `search`, the bounds and the mirror symmetries

use super::*;
use splinelab::interp::choice::bound::{
    circle_bound, convex_hull, sampled_circle_bound, segment_bound, widths,
};
use splinelab::interp::choice::symmetry::mirrors;
use splinelab::interp::choice::{
    fewest_points, max_distinct_for, search, Family, Minimality, MAX_RANDOM_STARTS,
};
use splinelab::metrics::curve::SegmentTree;
use splinelab::seeds::seed004::SHAPES;
use std::f64::consts::TAU;

/// A choice the search returned: finite points, a finite error, the within-tolerance flag
/// true to its error, and the error measured again on the target.
fn check_choice(target: &Target, c: &Choice) -> CaseResult {
    ensure!(
        !c.points.is_empty() && finite_vecs(&c.points),
        "points {:?}",
        c.points
    );
    let h = c.measure.distances.hausdorff();
    ensure!(h.is_finite(), "error {h}");
    ensure!(
        c.within_tolerance == (h <= target.tolerance()),
        "within_tolerance {} with error {h:e} and tolerance {:e}",
        c.within_tolerance,
        target.tolerance()
    );
    let again = ok(target.measure(&c.method, &c.points))?;
    ensure!(
        (again.distances.hausdorff() - h).abs() <= 1e-12 * target.size(),
        "measured again: {:e} vs {h:e}",
        again.distances.hausdorff()
    );
    Ok(())
}

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(target_cases());
    all.extend(placement_and_measure_cases());
    all.extend(fewest_points_cases());
    all.extend(fewest_points_known_cases());
    all.extend(search_cases());
    all.extend(parameter_bound_and_symmetry_cases());
    all
}

/// `Target`: polylines, shapes, tolerances, points on a closed target.
fn target_cases() -> Vec<Case> {
    vec![
        case("choice::target_tolerance_not_positive", || {
            let p = six_points(1.0);
            for tol in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -0.0, -1.0] {
                expect_err!(Target::polyline(&p, false, tol), Error::NotPositive { .. })
                    .map_err(|e| format!("{tol}: {e}"))?;
            }
            Ok(())
        }),
        case("choice::target_too_few_points", || {
            let p = six_points(1.0);
            expect_err!(
                Target::polyline(&[], false, 0.1),
                Error::TooFewPoints { .. }
            )?;
            expect_err!(
                Target::polyline(&p[..1], false, 0.1),
                Error::TooFewPoints { .. }
            )?;
            expect_err!(
                Target::polyline(&p[..2], true, 0.1),
                Error::TooFewPoints { .. }
            )
        }),
        case("choice::target_sweep_non_finite_point", || {
            sweep(12, |bad, k| {
                let mut p = six_points(1.0);
                p[k / 2][k % 2] = bad;
                expect_err!(Target::polyline(&p, false, 0.1), Error::NonFinite { .. })?;
                expect_err!(Target::polyline(&p, true, 0.1), Error::NonFinite { .. })
            })
        }),
        case("choice::target_beyond_coordinate_limit", || {
            let mut p = six_points(1.0);
            p[4].x = f64::MAX;
            expect_err!(
                Target::polyline(&p, false, 0.1),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("choice::target_zero_length", || {
            expect_err!(
                Target::polyline(&[v2(1.0, 1.0); 5], false, 0.1),
                Error::Degenerate { .. }
            )
        }),
        case("choice::target_length_overflows", || {
            let m = MAX_COORDINATE;
            let p: Vec<Vector2<f64>> = (0..200)
                .map(|i| if i % 2 == 0 { v2(-m, -m) } else { v2(m, m) })
                .collect();
            expect_err!(Target::polyline(&p, false, 1.0), Error::Overflow { .. })
        }),
        case("choice::target_subnormal_and_tiny_scales", || {
            for s in [1e-310, 1e-300] {
                let p = six_points(s);
                let t = ok(Target::polyline(&p, false, s))?;
                ensure!(
                    t.length() > 0.0 && t.length().is_finite() && t.size() > 0.0,
                    "scale {s:e}: length {:e}, size {:e}",
                    t.length(),
                    t.size()
                );
            }
            Ok(())
        }),
        risky("choice::target_too_many_points", || {
            expect_err!(
                Target::polyline(&vec![v2(0.0, 0.0); MAX_ELEMENTS + 1], false, 1.0),
                Error::TooLarge { .. }
            )
        }),
        case("choice::target_shape_invalid", || {
            for shape in shapes_with(f64::NAN) {
                expect_err!(Target::shape(&shape, 64), Error::NotPositive { .. })?;
            }
            expect_err!(
                Target::shape(&Shape::Circle, 3),
                Error::TooFewSamples { .. }
            )
        }),
        risky("choice::target_shape_huge_samples", || {
            expect_err!(
                Target::shape(&Shape::Circle, usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                Target::shape(&Shape::Circle, MAX_ELEMENTS + 1),
                Error::TooLarge { .. }
            )
        }),
        case("choice::with_tolerance_sweep", || {
            let t = ok(Target::shape(&Shape::Circle, 64))?;
            for tol in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -1e-300] {
                expect_err!(t.clone().with_tolerance(tol), Error::NotPositive { .. })?;
            }
            let tiny = ok(t.with_tolerance(5e-324))?;
            ensure!(tiny.tolerance() == 5e-324, "{}", tiny.tolerance());
            Ok(())
        }),
        case("choice::point_wraps_huge_arc_on_a_closed_target", || {
            let t = ok(Target::shape(&Shape::Circle, 64))?;
            for s in [1e300, -1e300, f64::MAX, -f64::MAX, 5e-324] {
                let p = t.point(s);
                ensure!(
                    p.iter().all(|x| x.is_finite()) && (p.norm() - 1.0).abs() < 1e-9,
                    "at {s:e}: {p:?}"
                );
            }
            Ok(())
        }),
    ]
}

/// `Target::placement`, `feature_placement` and `measure`.
fn placement_and_measure_cases() -> Vec<Case> {
    vec![
        case("choice::placement_degenerate_arguments", || {
            let t = ok(rectangle_target(40))?;
            ensure!(t.placement(0, 0.5, 0.0).is_empty(), "closed, no points");
            for (beta, phase) in [(f64::NAN, 0.0), (f64::INFINITY, f64::NAN), (-1e300, 1e300)] {
                let p = t.placement(7, beta, phase);
                ensure!(p.len() == 7, "{p:?}");
                ensure!(
                    p.iter().all(|s| s.is_finite()),
                    "beta {beta}, phase {phase}: {p:?}"
                );
            }
            let open = ok(Target::polyline(&six_points(1.0), false, 0.1))?;
            let p = open.placement(0, 0.5, 0.0);
            ensure!(p == vec![0.0, open.length()], "open, no points: {p:?}");
            Ok(())
        }),
        case("choice::feature_placement_without_corners_or_room", || {
            let circle = ok(Target::shape(&Shape::Circle, 64))?;
            ensure!(
                circle.feature_placement(10).is_none(),
                "a circle has no corners"
            );
            let rect = ok(rectangle_target(40))?;
            ensure!(
                rect.feature_placement(3).is_none(),
                "fewer than its corners"
            );
            let p = rect.feature_placement(8).ok_or("no placement")?;
            ensure!(p.len() == 8 && p.iter().all(|s| s.is_finite()), "{p:?}");
            Ok(())
        }),
        case("choice::measure_bad_points", || {
            let t = ok(rectangle_target(40))?;
            let mut p = six_points(0.1);
            expect_err!(t.measure(&Method::Linear, &[]), Error::TooFewPoints { .. })?;
            p[2].y = f64::NAN;
            expect_err!(t.measure(&Method::Angular, &p), Error::NonFinite { .. })?;
            p[2].y = 2.0 * MAX_COORDINATE;
            expect_err!(
                t.measure(&Method::Linear, &p),
                Error::CoordinateTooLarge { .. }
            )?;
            expect_err!(
                t.measure(&Method::Cardinal { a: f64::NAN }, &six_points(0.1)),
                Error::Negative { .. }
            )
        }),
        case("choice::measure_far_points_finite", || {
            // a curve far from a small target: a finite (huge) error
            let t = ok(rectangle_target(40))?;
            let m = ok(t.measure(&Method::Linear, &six_points(1e300)))?;
            ensure!(m.distances.hausdorff().is_finite(), "{m:?}");
            Ok(())
        }),
    ]
}

/// `fewest_points`: point limits, budgets, a polygon beyond its candidates.
fn fewest_points_cases() -> Vec<Case> {
    vec![
        case("choice::fewest_points_max_points_zero", || {
            let t = ok(rectangle_target(40))?;
            for family in Family::ALL {
                expect_err!(
                    fewest_points(&t, family, &options(0)),
                    Error::TooFewPoints { .. } | Error::OutOfDomain { .. }
                )
                .map_err(|e| format!("{family:?}: {e}"))?;
            }
            Ok(())
        }),
        case(
            "choice::fewest_points_max_points_below_the_closed_minimum",
            || {
                // a closed Angular or cardinal curve needs 3 points + 3 repeats
                let t = ok(rectangle_target(40))?;
                for family in [Family::Angular, Family::Cardinal] {
                    expect_err!(
                        fewest_points(&t, family, &options(5)),
                        Error::TooFewPoints { .. } | Error::OutOfDomain { .. }
                    )
                    .map_err(|e| format!("{family:?}: {e}"))?;
                }
                expect_err!(
                    fewest_points(&t, Family::Cubic, &options(3)),
                    Error::TooFewPoints { .. } | Error::OutOfDomain { .. }
                )
            },
        ),
        case(
            "choice::fewest_points_max_points_below_the_open_minimum",
            || {
                // an open Angular curve needs 2 points and 2 guides
                let t = ok(Target::shape(&Shape::Parabola { half_width: 1.0 }, 64))?;
                expect_err!(
                    fewest_points(&t, Family::Angular, &options(3)),
                    Error::TooFewPoints { .. } | Error::OutOfDomain { .. }
                )?;
                expect_err!(
                    fewest_points(&t, Family::BSpline, &options(1)),
                    Error::TooFewPoints { .. } | Error::OutOfDomain { .. }
                )
            },
        ),
        risky("choice::fewest_points_max_points_usize_max", || {
            let t = ok(rectangle_target(40))?;
            expect_err!(
                fewest_points(&t, Family::Linear, &options(usize::MAX)),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                fewest_points(&t, Family::BSpline, &options(MAX_ELEMENTS + 1)),
                Error::TooLarge { .. }
            )
        }),
        risky("choice::polygon_beyond_its_candidates", || {
            // more vertices than the polygon's optimum takes: a typed refusal for the polygon,
            // and the families it bounds still answer (without the bound)
            let n = (1 << 20) + 100;
            let ring: Vec<Vector2<f64>> = (0..n)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / n as f64;
                    Vector2::new(t.cos(), t.sin())
                })
                .collect();
            let t = ok(Target::polyline(&ring, true, 0.02))?;
            expect_err!(
                fewest_points(&t, Family::Linear, &SearchOptions::default()),
                Error::TooLarge { .. }
            )?;
            let c = ok(fewest_points(&t, Family::BSpline, &options(12)))?;
            ensure!(c.within_tolerance, "{:?}", c.measure);
            Ok(())
        }),
        case("choice::fewest_points_budget_zero", || {
            let t = ok(rectangle_target(40))?;
            let c = ok(fewest_points(
                &t,
                Family::Linear,
                &SearchOptions {
                    budget_per_coordinate: 0,
                    ..SearchOptions::default()
                },
            ))?;
            check_choice(&t, &c)?;
            ensure!(c.within_tolerance, "the polygon of the corners is exact");
            Ok(())
        }),
        risky("choice::fewest_points_budget_usize_max", || {
            let t = ok(rectangle_target(40))?;
            let c = ok(fewest_points(
                &t,
                Family::Linear,
                &SearchOptions {
                    budget_per_coordinate: usize::MAX,
                    max_points: 8,
                    ..SearchOptions::default()
                },
            ))?;
            check_choice(&t, &c)
        }),
    ]
}

/// `fewest_points` with a known configuration; a tiny target.
fn fewest_points_known_cases() -> Vec<Case> {
    vec![
        case("choice::fewest_points_known_with_zero_count", || {
            // a known configuration that claims 0 points: refused, or ignored
            let t = ok(rectangle_target(40))?;
            let o = SearchOptions {
                known: Some(bogus_choice(Method::Linear, vec![], 0)),
                ..SearchOptions::default()
            };
            match fewest_points(&t, Family::Linear, &o) {
                Ok(c) => check_choice(&t, &c),
                Err(
                    Error::TooFewPoints { .. }
                    | Error::Degenerate { .. }
                    | Error::CountMismatch { .. },
                ) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("choice::fewest_points_known_with_nan_points", || {
            // a known configuration with NaN points must not come back as the answer
            let t = ok(rectangle_target(40))?;
            let o = SearchOptions {
                known: Some(bogus_choice(Method::Linear, vec![v2(f64::NAN, 0.0); 4], 5)),
                ..SearchOptions::default()
            };
            match fewest_points(&t, Family::Linear, &o) {
                Ok(c) => check_choice(&t, &c),
                Err(Error::NonFinite { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("choice::fewest_points_known_of_another_family", || {
            let t = ok(rectangle_target(40))?;
            let o = SearchOptions {
                known: Some(bogus_choice(Method::Angular, four_points(), 7)),
                ..SearchOptions::default()
            };
            match fewest_points(&t, Family::Linear, &o) {
                Ok(c) => {
                    ensure!(c.method == Method::Linear, "answer of {:?}", c.method);
                    check_choice(&t, &c)
                }
                Err(Error::CountMismatch { .. } | Error::Degenerate { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case(
            "choice::fewest_points_tiny_target_measured_rescaled",
            || {
                // a 64-gon of radius 1e-300: the search's error must be the error of the same
                // configuration on the target scaled by 2^996, scaled back
                let k = 2f64.powi(996);
                let ring: Vec<Vector2<f64>> = (0..=64)
                    .map(|i| {
                        let t = TAU * i as f64 / 64.0;
                        v2(t.cos(), t.sin()) * 1e-300
                    })
                    .collect();
                let tiny = ok(Target::polyline(&ring, true, 2e-302))?;
                let c = ok(fewest_points(&tiny, Family::Linear, &options(40)))?;
                let scaled: Vec<Vector2<f64>> = ring.iter().map(|p| p * k).collect();
                let big = ok(Target::polyline(&scaled, true, 2e-302 * k))?;
                let points: Vec<Vector2<f64>> = c.points.iter().map(|p| p * k).collect();
                let m = ok(big.measure(&c.method, &points))?;
                close(
                    "the search's error",
                    c.measure.distances.hausdorff(),
                    m.distances.hausdorff() / k,
                    1e-9,
                )?;
                ensure!(
                    c.within_tolerance == (m.distances.hausdorff() <= big.tolerance()),
                    "within_tolerance {} but the rescaled error is {:e} of {:e}",
                    c.within_tolerance,
                    m.distances.hausdorff(),
                    big.tolerance()
                );
                Ok(())
            },
        ),
    ]
}

/// `search`: random starts, seeds, its evidence, known configurations.
fn search_cases() -> Vec<Case> {
    vec![
        risky("choice::search_random_starts_beyond_the_limit", || {
            let t = ok(rectangle_target(40))?;
            for random_starts in [MAX_RANDOM_STARTS + 1, usize::MAX] {
                let o = SearchOptions {
                    random_starts,
                    ..options(12)
                };
                for family in [Family::Cardinal, Family::BSpline] {
                    expect_err!(search(&t, family, &o), Error::TooLarge { .. })?;
                }
            }
            Ok(())
        }),
        case(
            "choice::search_random_starts_zero_and_extreme_seeds",
            || {
                let t = ok(rectangle_target(40))?;
                for seed in [0, u64::MAX] {
                    let o = SearchOptions {
                        random_starts: 0,
                        seed,
                        ..options(12)
                    };
                    let a = ok(search(&t, Family::Linear, &o))?;
                    let b = ok(search(&t, Family::Linear, &o))?;
                    ensure!(a == b, "two runs differ with seed {seed}");
                    check_choice(&t, &a.choice)?;
                }
                let o = SearchOptions {
                    random_starts: MAX_RANDOM_STARTS,
                    seed: u64::MAX,
                    ..options(8)
                };
                let c = ok(search(&t, Family::Linear, &o))?;
                check_choice(&t, &c.choice)
            },
        ),
        case("choice::search_evidence_is_consistent", || {
            // both count strategies: attempts in increasing order, every count below the
            // answer failed, the minimality true to the attempts
            let t = ok(rectangle_target(40))?;
            for every_count_below in [true, false] {
                let o = SearchOptions {
                    every_count_below,
                    ..options(12)
                };
                for family in [Family::Linear, Family::Cubic] {
                    let s = ok(search(&t, family, &o))?;
                    check_choice(&t, &s.choice)?;
                    let n = s.choice.measure.counted;
                    ensure!(
                        s.attempts.windows(2).all(|w| w[0].counted < w[1].counted),
                        "attempts out of order: {:?}",
                        s.attempts
                    );
                    // (an answer out of the tolerance is the lowest error found, at any count)
                    let below = s.attempts.iter().filter(|a| a.counted < n);
                    for a in below.filter(|_| s.choice.within_tolerance) {
                        ensure!(
                            !a.within_tolerance,
                            "{family:?}: {a:?} below the answer {n}"
                        );
                    }
                    match s.minimality {
                        Minimality::Searched => ensure!(
                            s.below().is_some_and(|b| !b.within_tolerance),
                            "{family:?}: searched without the count below"
                        ),
                        Minimality::NotMet => ensure!(!s.choice.within_tolerance, "{family:?}"),
                        _ => {}
                    }
                }
            }
            Ok(())
        }),
        case("choice::search_known_reversed_or_off_the_shape", || {
            // a known polygon of the rectangle's corners in the opposite direction, and one
            // whose points are far from the shape: no panic, the answer measured again
            let t = ok(rectangle_target(40))?;
            let corners = vec![v2(1.0, 0.5), v2(-1.0, 0.5), v2(-1.0, -0.5), v2(1.0, -0.5)];
            let mut reversed = corners.clone();
            reversed.reverse();
            let far: Vec<Vector2<f64>> = corners.iter().map(|p| p * 1e12).collect();
            for points in [corners, reversed, far] {
                let o = SearchOptions {
                    known: Some(bogus_choice(Method::Linear, points, 5)),
                    ..options(12)
                };
                let s = ok(search(&t, Family::Linear, &o))?;
                check_choice(&t, &s.choice)?;
                ensure!(s.choice.within_tolerance, "the corners' polygon is exact");
            }
            Ok(())
        }),
        case("choice::search_known_cardinal_with_nan_a", || {
            let t = ok(Target::shape(&Shape::Circle, 256))?;
            let ring: Vec<Vector2<f64>> = (0..8)
                .map(|i| {
                    let a = TAU * i as f64 / 8.0;
                    v2(a.cos(), a.sin())
                })
                .collect();
            for a in [f64::NAN, f64::INFINITY, -1.0, 0.0] {
                let o = SearchOptions {
                    known: Some(bogus_choice(Method::Cardinal { a }, ring.clone(), 11)),
                    ..options(12)
                };
                match search(&t, Family::Cardinal, &o) {
                    Ok(s) => check_choice(&t, &s.choice)?,
                    Err(Error::Negative { .. } | Error::NonFinite { .. }) => {}
                    Err(e) => return Err(format!("a = {a}: unexpected {e}")),
                }
            }
            Ok(())
        }),
    ]
}

/// `Target::parameter_at` and `point_at_parameter`, the bounds, the mirrors, `max_distinct_for`,
/// `Family::of`.
fn parameter_bound_and_symmetry_cases() -> Vec<Case> {
    vec![
        case(
            "choice::parameter_at_and_point_at_parameter_non_finite",
            || {
                let t = ok(Target::shape(&Shape::Circle, 64))?;
                for s in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    ensure!(t.parameter_at(s).is_none(), "parameter at {s}");
                }
                for s in [0.0, -1e300, 1e300, f64::MAX, 5e-324] {
                    let u = t.parameter_at(s).ok_or(format!("no parameter at {s:e}"))?;
                    ensure!(u.is_finite(), "parameter {u} at {s:e}");
                }
                for u in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    ensure!(t.point_at_parameter(u).is_none(), "point at {u}");
                }
                for u in [0.0, -1e300, 1e300, f64::MAX] {
                    let p = t
                        .point_at_parameter(u)
                        .ok_or(format!("no point at {u:e}"))?;
                    ensure!((p.norm() - 1.0).abs() < 1e-9, "{p:?} at {u:e}");
                }
                // an open exact shape continued far beyond its domain: finite or None
                let parabola = ok(Target::shape(&SHAPES[3].1, 64))?;
                for u in [1e300, -f64::MAX] {
                    if let Some(p) = parabola.point_at_parameter(u) {
                        ensure!(finite_vecs(&[p]), "{p:?}");
                    }
                }
                let polyline = ok(rectangle_target(40))?;
                ensure!(
                    polyline.parameter_at(0.5).is_none()
                        && polyline.point_at_parameter(0.5).is_none(),
                    "a polyline has no parameter of its own"
                );
                Ok(())
            },
        ),
        case("choice::bounds_degenerate_inputs", || {
            ensure!(convex_hull(&[]).is_empty(), "hull of nothing");
            let one = [v2(1.0, 2.0)];
            ensure!(convex_hull(&one) == one.to_vec(), "hull of one point");
            ensure!(widths(&one) == (0.0, 0.0), "widths of one point");
            let nan = [v2(f64::NAN, 0.0), v2(0.0, f64::INFINITY), v2(1.0, 1.0)];
            ensure!(
                convex_hull(&nan) == vec![v2(1.0, 1.0)],
                "non-finite points dropped"
            );
            // collinear points: the hull is the segment, the least width 0
            let line: Vec<Vector2<f64>> = (0..10).map(|i| v2(i as f64, 2.0 * i as f64)).collect();
            ensure!(convex_hull(&line).len() == 2, "{:?}", convex_hull(&line));
            let (least, diameter) = widths(&line);
            close("collinear diameter", diameter, 9.0 * 5f64.sqrt(), 1e-15)?;
            ensure!(least == 0.0 && segment_bound(&line) == 0.0, "least {least}");
            for b in [
                segment_bound(&[]),
                circle_bound(&[]),
                sampled_circle_bound(&[]),
            ] {
                ensure!(b == 0.0, "bound of nothing {b}");
            }
            Ok(())
        }),
        case("choice::bounds_at_every_magnitude", || {
            // a square of side 2m: least width 2m, diameter 2√2 m, circle bound (√2 − 1) m / 2,
            // from subnormal m to the coordinate limit
            for m in [5e-320, 1e-300, 1.0, 1e300, MAX_COORDINATE] {
                let square = [v2(m, m), v2(-m, m), v2(-m, -m), v2(m, -m)];
                let (least, diameter) = widths(&square);
                let rel = if m < 1e-307 { 1e-3 } else { 1e-14 };
                close("least width", least, 2.0 * m, rel)?;
                close("diameter", diameter, 2.0 * 2f64.sqrt() * m, rel)?;
                close("segment bound", segment_bound(&square), m, rel)?;
                close(
                    "circle bound",
                    circle_bound(&square),
                    0.5 * (2f64.sqrt() - 1.0) * m,
                    rel.max(1e-13),
                )?;
                ensure!(
                    sampled_circle_bound(&square) < circle_bound(&square),
                    "the sampled bound is below the exact one"
                );
            }
            // beyond the coordinate limit: no NaN width, no panic
            let huge = [
                v2(f64::MAX, f64::MAX),
                v2(-f64::MAX, 0.0),
                v2(0.0, -f64::MAX),
            ];
            let (least, diameter) = widths(&huge);
            ensure!(!least.is_nan() && !diameter.is_nan(), "{least} {diameter}");
            Ok(())
        }),
        case("choice::mirrors_are_symmetries_at_every_scale", || {
            // every mirror found maps the reference onto itself (within a sliver of its
            // size); a circle has some at every scale, a scalene triangle none
            for scale in [1e-300, 1.0, 1e300] {
                let ring: Vec<Vector2<f64>> = (0..=256)
                    .map(|i| {
                        let a = TAU * i as f64 / 256.0;
                        v2(a.cos(), 0.5 * a.sin()) * scale
                    })
                    .collect();
                let t = ok(Target::polyline(&ring, true, 0.01 * scale))?;
                let found = mirrors(&t);
                ensure!(
                    !found.is_empty(),
                    "no mirror of an ellipse at scale {scale:e}"
                );
                let tree = ok(SegmentTree::new(t.reference()))?;
                for m in &found {
                    for p in t.reference() {
                        let q = m.isometry.apply(*p);
                        ensure!(finite_vecs(&[q]), "{q:?}");
                        let d = tree.distance(q);
                        ensure!(
                            d <= 1e-3 * t.size(),
                            "scale {scale:e}: {m:?} moves {p:?} by {d:e}"
                        );
                    }
                }
            }
            let triangle = [v2(0.0, 0.0), v2(3.0, 0.0), v2(0.7, 1.9), v2(0.0, 0.0)];
            let t = ok(Target::polyline(&triangle, true, 0.01))?;
            ensure!(
                mirrors(&t).is_empty(),
                "a scalene triangle: {:?}",
                mirrors(&t)
            );
            Ok(())
        }),
        case("choice::max_distinct_for_small_targets", || {
            let t = ok(Target::polyline(&six_points(1.0), false, 0.1))?;
            ensure!(max_distinct_for(&t) == 64, "{}", max_distinct_for(&t));
            let big = ok(Target::shape(&Shape::Circle, 100))?;
            ensure!(
                max_distinct_for(&big) == 4 * big.reference().len(),
                "{}",
                max_distinct_for(&big)
            );
            Ok(())
        }),
        case("choice::family_of_every_method", || {
            for m in all_methods() {
                ensure!(Family::of(&m).is_some(), "{}", format_args!("{:?}", m));
            }
            ensure!(
                Family::of(&Method::Cardinal { a: f64::NAN }) == Some(Family::Cardinal),
                "cardinal"
            );
            Ok(())
        }),
    ]
}
