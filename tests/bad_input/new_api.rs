//! Bad-input cases for the public API added with seed 004 and issue 13: the methods and their
//! point rules (`seed004api::*`), the Angular spline's chord-line limits (`angular2::*`), the
//! exact test shapes (`shapes::*`), the curve metrics (`metrics2::*`), the automatic point
//! choice (`choice::*`), the comparison (`comparison::*`), the cubic spline's refit
//! (`refit::*`), collocation on nearly coincident knots (`collocation2::*`), the B-spline batch
//! evaluation outside a short domain (`bspline2::*`), and — with the `report` feature — the
//! figure value (`figure::*`), the plane and 3-D builders (`plot::*`, `plot3::*`), tables
//! (`table::*`) and the glyphs of the letter "a" (`letters::*`).
//!
//! Included from `tests/bad_input.rs` as a child module, so it uses that file's machinery
//! (`case`, `risky`, `expect_err!`, `ensure!`, `ok`, `show`, the helpers) through `super::*`.
//! Every huge count is a `risky` case (a child process under a memory limit); every figure
//! over extreme data that could loop is `risky` too (a child killed after 20 s).

use super::*;
use splinelab::interp::angular::{circumcircle, classify, PieceKind};
use splinelab::interp::choice::bound::{
    circle_bound, convex_hull, sampled_circle_bound, segment_bound, widths,
};
use splinelab::interp::choice::symmetry::mirrors;
use splinelab::interp::choice::{
    fewest_points, max_distinct_for, search, Choice, Family, Measure, Minimality, SearchOptions,
    Target, MAX_RANDOM_STARTS,
};
use splinelab::metrics::curve::{
    curvature_profile, distances_to, polyline_distances, sample_pieces, sample_pieces_into,
    segment_distance, smoothness, Distances, SegmentTree, Smoothness,
};
use splinelab::seeds::seed004::{
    coastline, decimate, evenly_spaced, paper_points, polygonal_a, COAST_STEP, SHAPES, TABLE_I,
};
use splinelab::shapes::Shape;
use splinelab::{CubicEnd, Interpolant, Method};
use std::f64::consts::{PI, TAU};

/// Every case of this file.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(seed004api_cases());
    all.extend(angular2_cases());
    all.extend(shapes_cases());
    all.extend(metrics2_cases());
    all.extend(choice_cases());
    all.extend(comparison_cases());
    all.extend(refit_cases());
    all.extend(collocation2_cases());
    all.extend(bspline2_cases());
    all.extend(report::cases());
    all
}

// ---------------------------------------------------------------------------------------------
// helpers
// ---------------------------------------------------------------------------------------------

/// One method of every family, the cubic spline with each of its ends.
fn all_methods() -> Vec<Method> {
    vec![
        Method::Angular,
        Method::Cardinal { a: 0.5 },
        Method::Cubic {
            end: CubicEnd::Relaxed,
        },
        Method::Cubic {
            end: CubicEnd::Cyclic,
        },
        Method::Cubic {
            end: CubicEnd::Anticyclic,
        },
        Method::BSpline { order: 3 },
        Method::Linear,
    ]
}

/// Six points without collinear triples (open or closed), times `scale`.
fn six_points(scale: f64) -> Vec<Vector2<f64>> {
    [
        (0.0, 0.0),
        (1.0, 1.0),
        (2.0, 0.0),
        (3.0, 1.0),
        (4.0, 0.5),
        (5.0, 2.0),
    ]
    .iter()
    .map(|&(x, y)| v2(x * scale, y * scale))
    .collect()
}

/// The defining property of a method's curve through `points`: finite samples, and the
/// points interpolated (the B-spline: its end control points) to `1e-13` of their scale.
fn check_curve(m: &Method, points: &[Vector2<f64>], closed: bool, c: &Interpolant) -> CaseResult {
    let line = ok(c.polyline(257))?;
    ensure!(
        finite_vecs(&line),
        "{}: a sample is not finite",
        format_args!("{:?}", m)
    );
    let all = m.prepared(points, closed);
    let scale = all
        .iter()
        .map(|p| p.amax())
        .fold(f64::MIN_POSITIVE, f64::max);
    let tol = 1e-13 * scale;
    let miss = |t: f64, p: &Vector2<f64>| (c.point(t) - p).amax();
    match m {
        Method::BSpline { .. } => {
            let (a, b) = c.domain();
            let e = miss(a, &all[0]).max(miss(b, &all[all.len() - 1]));
            ensure!(
                e <= tol,
                "{}: misses its end points by {e:e}",
                format_args!("{:?}", m)
            );
        }
        Method::Angular | Method::Cardinal { .. } => {
            for (j, p) in all[1..all.len() - 1].iter().enumerate() {
                let e = miss(j as f64, p);
                ensure!(
                    e <= tol,
                    "{}: misses point {} by {e:e}",
                    format_args!("{:?}", m),
                    j + 1
                );
            }
        }
        Method::Cubic { .. } | Method::Linear => {
            let breaks = c.breaks();
            ensure!(
                breaks.len() == all.len(),
                "{}: {} breaks for {} points",
                format_args!("{:?}", m),
                breaks.len(),
                all.len()
            );
            for (j, (t, p)) in breaks.iter().zip(&all).enumerate() {
                let e = miss(*t, p);
                ensure!(
                    e <= tol,
                    "{}: misses point {j} by {e:e}",
                    format_args!("{:?}", m)
                );
            }
        }
    }
    Ok(())
}

/// Every method, open and closed, through [`six_points`]`(scale)`: an `Ok` curve is checked
/// ([`check_curve`]); an error is accepted only if `allowed` admits it.
fn each_method(scale: f64, allowed: fn(&Error) -> bool) -> CaseResult {
    let points = six_points(scale);
    for closed in [false, true] {
        for m in all_methods() {
            match m.curve(&points, closed) {
                Ok(c) => check_curve(&m, &points, closed, &c)
                    .map_err(|e| format!("closed = {closed}: {e}"))?,
                Err(e) if allowed(&e) => {}
                Err(e) => {
                    return Err(format!(
                        "{} (closed = {closed}) at scale {scale:e}: unexpected Err({e})",
                        format_args!("{:?}", m)
                    ))
                }
            }
        }
    }
    Ok(())
}

/// Every method, open and closed, on [`six_points`] with one coordinate replaced by `bad`:
/// the error `expected` admits.
fn each_method_refuses(bad: f64, expected: fn(&Error) -> bool) -> CaseResult {
    for closed in [false, true] {
        for m in all_methods() {
            for k in 0..12 {
                let mut points = six_points(1.0);
                points[k / 2][k % 2] = bad;
                match m.curve(&points, closed) {
                    Err(e) if expected(&e) => {}
                    other => {
                        return Err(format!(
                            "{} (closed = {closed}) with {bad:e} at coordinate {k}: {}",
                            format_args!("{:?}", m),
                            show(&other)
                        ))
                    }
                }
            }
        }
    }
    Ok(())
}

/// The shapes with parameters, each parameter position replaced by `bad` (the rectangle in
/// either side).
fn shapes_with(bad: f64) -> Vec<Shape> {
    vec![
        Shape::Ellipse { ratio: bad },
        Shape::Parabola { half_width: bad },
        Shape::Hyperbola { b: bad },
        Shape::Sinusoid { periods: bad },
        Shape::Rectangle {
            width: bad,
            height: 1.0,
        },
        Shape::Rectangle {
            width: 2.0,
            height: bad,
        },
    ]
}

/// The distance from `p` to the segment `ab` computed independently of the library: the
/// origin moved to `a` (the differences of nearby or tiny coordinates are exact), then scaled
/// by powers of two so the larger difference is about 1, where no square under- or overflows.
fn reference_distance(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let (w, u) = (p - a, b - a);
    let m = w.amax().max(u.amax());
    if m == 0.0 {
        return 0.0;
    }
    let e = -(m.log2().floor() as i32);
    let (k1, k2) = (2f64.powi(e / 2), 2f64.powi(e - e / 2));
    let (w, u) = (w * k1 * k2, u * k1 * k2);
    let len2 = u.norm_squared();
    let t = if len2 > 0.0 {
        (w.dot(&u) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (w - u * t).norm() / k1 / k2
}

/// The one-sided distance `max_{a ∈ from} min_{segments of to}` by brute force with
/// [`reference_distance`] (`to` of one point: its distance).
fn reference_one_sided(from: &[Vector2<f64>], to: &[Vector2<f64>]) -> f64 {
    from.iter()
        .map(|&p| {
            if to.len() == 1 {
                return reference_distance(p, to[0], to[0]);
            }
            to.windows(2)
                .map(|w| reference_distance(p, w[0], w[1]))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}

/// `|got − want| ≤ rel · |want|`, and `want > 0` so that a zero is never mistaken for it.
fn close(what: &str, got: f64, want: f64, rel: f64) -> CaseResult {
    ensure!(
        want > 0.0 && want.is_finite(),
        "{what}: the reference is {want:e}"
    );
    ensure!(
        (got - want).abs() <= rel * want,
        "{what}: got {got:e}, the rescaled computation gives {want:e} (relative error {:e})",
        (got - want).abs() / want
    );
    Ok(())
}

/// Two parallel segments `dist` apart, at `offset` and of length `len`: the curve and its
/// reference for the distance cases.
fn parallel_pair(
    offset: Vector2<f64>,
    len: f64,
    dist: f64,
) -> (Vec<Vector2<f64>>, Vec<Vector2<f64>>) {
    let u = v2(0.6, 0.8) * len;
    let n = v2(-0.8, 0.6) * dist;
    let curve = vec![offset, offset + u * 0.5, offset + u];
    let reference = vec![offset + n, offset + u + n];
    (curve, reference)
}

/// The rectangle 2 × 1 as a closed polyline of `samples` segments, tolerance 1 % of 2.
fn rectangle_target(samples: usize) -> Result<Target, String> {
    let r = Shape::Rectangle {
        width: 2.0,
        height: 1.0,
    };
    ok(Target::polyline(&ok(r.reference(samples))?, true, 0.02))
}

fn options(max_points: usize) -> SearchOptions {
    SearchOptions {
        max_points,
        budget_per_coordinate: 10,
        ..SearchOptions::default()
    }
}

/// A search result that claims to meet the tolerance with `points`, counted as `counted`.
fn bogus_choice(method: Method, points: Vec<Vector2<f64>>, counted: usize) -> Choice {
    Choice {
        method,
        points,
        measure: Measure {
            distances: Distances {
                curve_to_reference: 0.0,
                reference_to_curve: 0.0,
            },
            smoothness: Smoothness {
                inflections: 0,
                max_jump: 0.0,
                max_curvature: 0.0,
                singular: 0,
            },
            counted,
        },
        within_tolerance: true,
        evaluations: 0,
        start: splinelab::interp::choice::Start::Known,
    }
}

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

// ---------------------------------------------------------------------------------------------
// seed004api: Method, Interpolant, paper_points and the data helpers
// ---------------------------------------------------------------------------------------------

fn seed004api_cases() -> Vec<Case> {
    vec![
        risky("seed004api::paper_points_usize_max", || {
            expect_err!(
                paper_points(&Shape::Circle, &Method::Angular, usize::MAX),
                Error::TooLarge { got, .. } if *got == usize::MAX
            )
        }),
        risky("seed004api::paper_points_1_shl_40", || {
            expect_err!(
                paper_points(&Shape::Circle, &Method::Linear, 1 << 40),
                Error::TooLarge { got, .. } if *got == 1 << 40
            )
        }),
        risky("seed004api::paper_points_max_elements_plus_one", || {
            expect_err!(
                paper_points(
                    &Shape::Sinusoid { periods: 1.0 },
                    &Method::Cardinal { a: 0.5 },
                    MAX_ELEMENTS + 1
                ),
                Error::TooLarge { .. }
            )
        }),
        risky(
            "seed004api::paper_points_huge_counts_every_method_and_shape",
            || {
                for (name, shape) in SHAPES {
                    for m in all_methods() {
                        for count in [usize::MAX, usize::MAX - 2, 1 << 40, MAX_ELEMENTS + 1] {
                            expect_err!(paper_points(&shape, &m, count), Error::TooLarge { .. })
                                .map_err(|e| {
                                    format!("{name}, {}, {count}: {e}", format_args!("{:?}", m))
                                })?;
                        }
                    }
                }
                Ok(())
            },
        ),
        case("seed004api::paper_points_sweep_non_finite_shape", || {
            for bad in NON_FINITE {
                for shape in shapes_with(bad) {
                    for m in all_methods() {
                        expect_err!(paper_points(&shape, &m, 7), Error::NotPositive { .. })
                            .map_err(|e| format!("{shape:?}, {}: {e}", format_args!("{:?}", m)))?;
                    }
                }
            }
            Ok(())
        }),
        case("seed004api::paper_points_zero_and_negative_shape", || {
            for bad in [0.0, -0.0, -1.0, -5e-324, f64::MIN] {
                for shape in shapes_with(bad) {
                    expect_err!(
                        paper_points(&shape, &Method::Angular, 7),
                        Error::NotPositive { .. }
                    )
                    .map_err(|e| format!("{shape:?}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("seed004api::paper_points_shape_beyond_bounds", || {
            for shape in [
                Shape::Ellipse { ratio: 1.5 },
                Shape::Parabola { half_width: 1e300 },
                Shape::Hyperbola { b: f64::MAX },
                Shape::Sinusoid { periods: 2e6 },
                Shape::Rectangle {
                    width: 2.0 * MAX_COORDINATE,
                    height: 1.0,
                },
            ] {
                expect_err!(
                    paper_points(&shape, &Method::Linear, 7),
                    Error::OutOfDomain { .. }
                )
                .map_err(|e| format!("{shape:?}: {e}"))?;
            }
            Ok(())
        }),
        case("seed004api::paper_points_subnormal_and_tiny_shapes", || {
            // valid (positive, within bounds) however small: finite points, or a typed
            // refusal of a derived quantity; every failure is listed
            let mut bad = Vec::new();
            for p in [5e-324, 1e-310, 1e-300] {
                for shape in [
                    Shape::Ellipse { ratio: p },
                    Shape::Parabola { half_width: p },
                    Shape::Hyperbola { b: p },
                    Shape::Sinusoid { periods: p },
                    Shape::Rectangle {
                        width: p,
                        height: p,
                    },
                    Shape::Rectangle {
                        width: 2.0,
                        height: p,
                    },
                ] {
                    for m in [Method::Angular, Method::Cardinal { a: 0.5 }, Method::Linear] {
                        match paper_points(&shape, &m, 7) {
                            Ok(set) if set.points.len() >= 2 && finite_vecs(&set.points) => {}
                            Err(
                                Error::Overflow { .. }
                                | Error::GapTooSmall { .. }
                                | Error::Degenerate { .. },
                            ) => {}
                            Ok(set) => bad.push(format!(
                                "{shape:?}, {}: Ok({:?})",
                                format_args!("{:?}", m),
                                &set.points[..set.points.len().min(3)]
                            )),
                            Err(e) => bad
                                .push(format!("{shape:?}, {}: Err({e})", format_args!("{:?}", m))),
                        }
                    }
                }
            }
            ensure!(bad.is_empty(), "{}", bad.join("; "));
            Ok(())
        }),
        case("seed004api::paper_points_huge_shapes_are_finite", || {
            for shape in [
                Shape::Parabola { half_width: 1e100 },
                Shape::Hyperbola { b: 1e100 },
                Shape::Sinusoid { periods: 1e6 },
                Shape::Rectangle {
                    width: 1e100,
                    height: 1e-100,
                },
            ] {
                for m in [
                    Method::Angular,
                    Method::Cardinal { a: 0.5 },
                    Method::Cubic {
                        end: CubicEnd::Relaxed,
                    },
                    Method::Linear,
                ] {
                    let set = ok(paper_points(&shape, &m, 9))?;
                    ensure!(
                        finite_vecs(&set.points),
                        "{shape:?}, {}",
                        format_args!("{:?}", m)
                    );
                }
            }
            Ok(())
        }),
        case(
            "seed004api::paper_points_bspline_order_zero_and_one",
            || {
                for order in [0, 1] {
                    expect_err!(
                        paper_points(&Shape::Circle, &Method::BSpline { order }, 6),
                        Error::DegreeTooLow { .. }
                    )?;
                }
                Ok(())
            },
        ),
        case("seed004api::paper_points_bspline_order_usize_max", || {
            expect_err!(
                paper_points(
                    &Shape::Parabola { half_width: 1.0 },
                    &Method::BSpline { order: usize::MAX },
                    6
                ),
                Error::TooFewPoints { .. }
            )
        }),
        case("seed004api::paper_points_every_printed_cell", || {
            // the configuration of every cell of Table I: finite points its method draws
            for c in TABLE_I {
                let (name, shape) = SHAPES[c.column];
                let set = ok(paper_points(&shape, &c.method, c.points))
                    .map_err(|e| format!("{name}, {}: {e}", format_args!("{:?}", c.method)))?;
                ensure!(
                    finite_vecs(&set.points),
                    "{name}, {}",
                    format_args!("{:?}", c.method)
                );
                let curve = ok(c.method.curve(&set.points, set.closed))
                    .map_err(|e| format!("{name}, {}: {e}", format_args!("{:?}", c.method)))?;
                if !matches!(c.method, Method::BSpline { .. }) {
                    check_curve(&c.method, &set.points, set.closed, &curve)
                        .map_err(|e| format!("{name}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("seed004api::angular_rectangle_points_draw", || {
            // the Angular rectangle's rule must give points the Angular spline accepts
            let r = Shape::Rectangle {
                width: 2.0,
                height: 1.0,
            };
            for count in [6, 15, 27] {
                let set = ok(paper_points(&r, &Method::Angular, count))?;
                let c = ok(Method::Angular.curve(&set.points, set.closed))?;
                check_curve(&Method::Angular, &set.points, set.closed, &c)?;
            }
            Ok(())
        }),
        case(
            "seed004api::cardinal_points_nan_a_refused_by_the_curve",
            || {
                let m = Method::Cardinal { a: f64::NAN };
                let set = ok(paper_points(&Shape::Circle, &m, 7))?;
                expect_err!(m.curve(&set.points, set.closed), Error::NotPositive { .. })
            },
        ),
        case("seed004api::evenly_spaced_empty_and_zero", || {
            ensure!(evenly_spaced(&[], 5).is_empty(), "from no points");
            ensure!(evenly_spaced(&four_points(), 0).is_empty(), "zero points");
            Ok(())
        }),
        risky("seed004api::evenly_spaced_usize_max", || {
            let p = four_points();
            let e = evenly_spaced(&p, usize::MAX);
            ensure!(e == p, "{e:?}");
            Ok(())
        }),
        case("seed004api::evenly_spaced_coast", || {
            let coast = coastline();
            let e = evenly_spaced(&coast, 50);
            ensure!(e.len() == 50 && e[0] == coast[0], "{} points", e.len());
            ensure!(
                e.windows(2).all(|w| w[0] != w[1]),
                "repeated consecutive points"
            );
            Ok(())
        }),
        case("seed004api::decimate_step_zero_and_empty", || {
            let p = four_points();
            ensure!(decimate(&p, 0) == p, "step 0 keeps every point");
            ensure!(decimate(&[], 3).is_empty(), "no points");
            Ok(())
        }),
        risky("seed004api::decimate_step_usize_max", || {
            let p = four_points();
            let d = decimate(&p, usize::MAX);
            ensure!(d == vec![p[0]], "{d:?}");
            Ok(())
        }),
        case("seed004api::coastline_is_a_valid_ring", || {
            let c = coastline();
            ensure!(c.len() >= 300, "{} points", c.len());
            ensure!(finite_vecs(&c), "not finite");
            ensure!(c[0] != c[c.len() - 1], "the closing point is repeated");
            let (x0, y0) = c.iter().fold((f64::INFINITY, f64::INFINITY), |(x, y), p| {
                (x.min(p.x), y.min(p.y))
            });
            ensure!(x0 == 0.0 && y0 == 0.0, "corner ({x0}, {y0})");
            ok(Target::polyline(&c, true, 1.0)).map(drop)
        }),
        case(
            "seed004api::coastline_decimated_draws_with_every_method",
            || {
                let d = decimate(&coastline(), COAST_STEP);
                for m in all_methods() {
                    match m.curve(&d, true) {
                        Ok(c) => check_curve(&m, &d, true, &c)?,
                        // the Angular spline refuses a collinear triple of the ring
                        Err(Error::NoSmoothPiece { .. }) if m == Method::Angular => {}
                        Err(e) => return Err(format!("{}: {e}", format_args!("{:?}", m))),
                    }
                }
                Ok(())
            },
        ),
        case("seed004api::polygonal_a_contours_are_valid_targets", || {
            let a = polygonal_a();
            ensure!(a.len() == 2, "{} contours", a.len());
            for c in &a {
                ensure!(c.len() >= 4 && finite_vecs(c), "{c:?}");
                ok(Target::polyline(c, true, 0.01))?;
                let l = ok(Method::Linear.curve(c, true))?;
                check_curve(&Method::Linear, c, true, &l)?;
            }
            Ok(())
        }),
        case("seed004api::method_bspline_order_zero_one_and_huge", || {
            let p = six_points(1.0);
            for order in [0, 1] {
                expect_err!(
                    Method::BSpline { order }.curve(&p, false),
                    Error::DegreeTooLow { .. }
                )?;
            }
            expect_err!(
                Method::BSpline { order: usize::MAX }.curve(&p, true),
                Error::TooFewPoints { .. }
            )
        }),
        case(
            "seed004api::method_cardinal_a_non_finite_zero_negative",
            || {
                for a in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -0.0, -1.0] {
                    for closed in [false, true] {
                        expect_err!(
                            Method::Cardinal { a }.curve(&six_points(1.0), closed),
                            Error::NotPositive { .. }
                        )
                        .map_err(|e| format!("a = {a}: {e}"))?;
                    }
                }
                Ok(())
            },
        ),
        case("seed004api::method_cardinal_a_subnormal", || {
            // a positive a however small: the curve tends to the polygon, still interpolating
            for a in [5e-324, 1e-310, 1e-300] {
                let m = Method::Cardinal { a };
                let p = six_points(1.0);
                let c = ok(m.curve(&p, false))?;
                check_curve(&m, &p, false, &c)?;
            }
            Ok(())
        }),
        case("seed004api::method_cardinal_a_huge", || {
            for a in [1e300, f64::MAX] {
                let m = Method::Cardinal { a };
                let p = six_points(1.0);
                match m.curve(&p, false) {
                    Ok(c) => check_curve(&m, &p, false, &c)?,
                    // a derived tangent beyond the limit (the catalog's seed004 cases accept
                    // NonFinite for it too)
                    Err(
                        Error::CoordinateTooLarge { .. }
                        | Error::Overflow { .. }
                        | Error::NonFinite { .. },
                    ) => {}
                    Err(e) => return Err(format!("a = {a:e}: unexpected {e}")),
                }
            }
            Ok(())
        }),
        case("seed004api::method_empty_and_single_point", || {
            for m in all_methods() {
                for n in [0, 1] {
                    for closed in [false, true] {
                        // one point closed is that point twice: a chord-length
                        // parametrization sees two coincident points
                        let r = m.curve(&six_points(1.0)[..n], closed);
                        match &r {
                            Err(Error::TooFewPoints { .. }) => Ok(()),
                            Err(Error::RepeatedPoint { .. }) if n == 1 && closed => Ok(()),
                            _ => Err(format!("expected TooFewPoints, got {}", show(&r))),
                        }
                        .map_err(|e| {
                            format!(
                                "{}, {n} points, closed = {closed}: {e}",
                                format_args!("{:?}", m)
                            )
                        })?;
                    }
                }
            }
            Ok(())
        }),
        case("seed004api::method_nan_point", || {
            each_method_refuses(f64::NAN, |e| matches!(e, Error::NonFinite { .. }))
        }),
        case("seed004api::method_pos_inf_point", || {
            each_method_refuses(f64::INFINITY, |e| matches!(e, Error::NonFinite { .. }))
        }),
        case("seed004api::method_neg_inf_point", || {
            each_method_refuses(f64::NEG_INFINITY, |e| matches!(e, Error::NonFinite { .. }))
        }),
        case("seed004api::method_point_beyond_coordinate_limit", || {
            each_method_refuses(2.0 * MAX_COORDINATE, |e| {
                matches!(e, Error::CoordinateTooLarge { .. })
            })
        }),
        case("seed004api::method_point_f64_max", || {
            each_method_refuses(-f64::MAX, |e| matches!(e, Error::CoordinateTooLarge { .. }))
        }),
        case("seed004api::method_every_family_at_unit_scale", || {
            each_method(1.0, |_| false)
        }),
        case("seed004api::method_every_family_at_1e-300", || {
            each_method(1e-300, |_| false)
        }),
        case("seed004api::method_every_family_at_subnormal_scale", || {
            each_method(1e-310, |e| {
                matches!(
                    e,
                    Error::GapTooSmall { .. }
                        | Error::Overflow { .. }
                        | Error::IllConditioned { .. }
                )
            })
        }),
        case("seed004api::method_every_family_at_1e300", || {
            each_method(1e300, |_| false)
        }),
        case(
            "seed004api::method_every_family_near_coordinate_limit",
            || {
                each_method(MAX_COORDINATE / 8.0, |e| {
                    matches!(e, Error::Overflow { .. } | Error::CoordinateTooLarge { .. })
                })
            },
        ),
        case("seed004api::method_periodic_needs_three_points", || {
            let two = &six_points(1.0)[..2];
            for end in [CubicEnd::Cyclic, CubicEnd::Anticyclic] {
                expect_err!(
                    Method::Cubic { end }.curve(two, false),
                    Error::TooFewPoints { .. }
                )?;
            }
            Ok(())
        }),
        case("seed004api::method_repeated_points", || {
            // a chord-length parametrization cannot separate equal points; the Angular
            // spline has no chord
            let mut p = six_points(1.0);
            p[3] = p[2];
            for m in [
                Method::Angular,
                Method::Cubic {
                    end: CubicEnd::Relaxed,
                },
                Method::Linear,
            ] {
                expect_err!(m.curve(&p, false), Error::RepeatedPoint { .. })
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", m)))?;
            }
            Ok(())
        }),
        case("seed004api::interpolant_breaks_cover_the_domain", || {
            let p = six_points(1.0);
            for closed in [false, true] {
                for m in all_methods() {
                    let c = ok(m.curve(&p, closed))?;
                    let b = c.breaks();
                    let (lo, hi) = c.domain();
                    ensure!(
                        b.len() >= 2 && b[0] == lo && b[b.len() - 1] == hi,
                        "{}: breaks {b:?}, domain [{lo}, {hi}]",
                        format_args!("{:?}", m)
                    );
                    ensure!(
                        b.windows(2).all(|w| w[0] < w[1]),
                        "{}: breaks not increasing {b:?}",
                        format_args!("{:?}", m)
                    );
                }
            }
            Ok(())
        }),
        risky("seed004api::counted_points_saturates", || {
            for m in all_methods() {
                ensure!(
                    m.counted_points(usize::MAX, true) == usize::MAX,
                    "{}",
                    format_args!("{:?}", m)
                );
                ensure!(m.counted_points(usize::MAX, false) == usize::MAX, "open");
            }
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// angular2: the Angular spline's chord-line limits, classify, circumcircle, guides, sampling
// ---------------------------------------------------------------------------------------------

fn angular2_cases() -> Vec<Case> {
    vec![
        case("angular2::one_end_tangent_on_the_chord", || {
            // the tangent at P₁ lies on the chord P₁P₂, the one at P₂ does not: the limit is
            // the chord with a corner at P₂, so no G¹ piece
            let p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(2.0, 0.0), v2(3.0, 1.0)];
            expect_err!(
                AngularSpline::try_new(p),
                Error::NoSmoothPiece { point: 1, .. }
            )
        }),
        case(
            "angular2::one_end_tangent_on_the_chord_at_the_far_end",
            || {
                let p = vec![v2(0.0, 1.0), v2(1.0, 0.0), v2(2.0, 0.0), v2(3.0, 0.0)];
                expect_err!(
                    AngularSpline::try_new(p),
                    Error::NoSmoothPiece { point: 1, .. }
                )
            },
        ),
        case(
            "angular2::one_end_tangent_on_the_chord_through_method",
            || {
                let p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(2.0, 0.0), v2(3.0, 1.0)];
                expect_err!(
                    Method::Angular.curve(&p, false),
                    Error::NoSmoothPiece { .. }
                )
            },
        ),
        case("angular2::collinear_points_reverse_direction", || {
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
        case("angular2::closed_collinear_triangle", || {
            let q = [v2(0.0, 0.0), v2(2.0, 0.0), v2(1.0, 0.0)];
            expect_err!(
                AngularSpline::closed(&q),
                Error::NoSmoothPiece { .. } | Error::ReversedPoints { .. }
            )
        }),
        case("angular2::closed_rectangle_with_side_points", || {
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
        case("angular2::all_collinear_forward_is_straight", || {
            let p: Vec<Vector2<f64>> = (0..6).map(|i| v2(i as f64, 2.0 * i as f64)).collect();
            let s = ok(AngularSpline::try_new(p.clone()))?;
            ensure!(
                s.kinds().iter().all(|k| *k == PieceKind::Straight),
                "{:?}",
                s.kinds()
            );
            angular_ok(p)
        }),
        case("angular2::just_beyond_the_collinear_threshold", || {
            // an angle of about 1e-6 from the chord keeps the paper's curve: G¹, interpolating
            angular_ok(vec![
                v2(0.0, 0.0),
                v2(1.0, 0.0),
                v2(2.0, 1e-6),
                v2(3.0, 1.0),
            ])
        }),
        case("angular2::classify_non_finite", || {
            sweep(2, |bad, k| {
                let mut a = [0.5, -0.5];
                a[k] = bad;
                expect_err!(classify(a[0], a[1]), Error::NonFinite { .. })
            })
        }),
        case("angular2::classify_chord_limits", || {
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
        case("angular2::classify_the_three_curved_cases", || {
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
        case("angular2::circumcircle_degenerate_is_none", || {
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
        case("angular2::circumcircle_extreme_scales", || {
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
        case("angular2::guide_point_subnormal_tangent", || {
            // only the direction of the tangent matters
            let g = ok(guide_point(v2(0.0, 0.0), v2(1.0, 1.0), v2(5e-324, 0.0)))?;
            ensure!((g - v2(-1.0, 1.0)).amax() <= 1e-15, "{g:?}");
            Ok(())
        }),
        case("angular2::guide_point_sweep_non_finite", || {
            sweep(6, |bad, k| {
                let mut c = [0.0, 0.0, 1.0, 1.0, 1.0, 0.0];
                c[k] = bad;
                expect_err!(
                    guide_point(v2(c[0], c[1]), v2(c[2], c[3]), v2(c[4], c[5])),
                    Error::NonFinite { .. }
                )
            })
        }),
        case("angular2::guide_point_beyond_coordinate_limit", || {
            expect_err!(
                guide_point(v2(2.0 * MAX_COORDINATE, 0.0), v2(1.0, 1.0), v2(1.0, 0.0)),
                Error::CoordinateTooLarge { .. }
            )?;
            expect_err!(
                guide_point(v2(0.0, 0.0), v2(1.0, 1.0), v2(f64::MAX, 0.0)),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("angular2::polyline_into_too_few_samples", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            let mut out = vec![v2(9.0, 9.0)];
            for n in [0, 1] {
                expect_err!(s.polyline_into(n, &mut out), Error::TooFewSamples { .. })?;
            }
            Ok(())
        }),
        risky("angular2::polyline_into_usize_max", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            let mut out = Vec::new();
            expect_err!(
                s.polyline_into(usize::MAX, &mut out),
                Error::TooLarge { .. }
            )
        }),
        risky("angular2::polyline_into_max_elements_plus_one", || {
            let s = ok(AngularSpline::try_new(four_points()))?;
            let mut out = Vec::new();
            expect_err!(
                s.polyline_into(MAX_ELEMENTS + 1, &mut out),
                Error::TooLarge { .. }
            )
        }),
        risky("angular2::open_too_many_points", || {
            expect_err!(
                AngularSpline::try_new(vec![v2(0.0, 0.0); MAX_ELEMENTS + 1]),
                Error::TooLarge { .. }
            )
        }),
        case("angular2::polyline_into_matches_point", || {
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
        case("angular2::evaluation_far_outside_is_finite", || {
            let s = ok(AngularSpline::try_new(six_points(1.0)))?;
            for t in [-f64::MAX, -1e300, 1e300, f64::MAX, 5e-324, -5e-324] {
                let p = s.point(t);
                ensure!(p.iter().all(|x| x.is_finite()), "at {t:e}: {p:?}");
            }
            expect_err!(s.try_point(f64::INFINITY), Error::NonFinite { .. })?;
            expect_err!(s.try_point(-1e-300), Error::OutOfDomain { .. })
        }),
        risky(
            "angular2::eval_piece_out_of_range_panics_as_documented",
            || {
                let s = ok(AngularSpline::try_new(four_points()))?;
                expect_panic("eval_piece(1, ·) of a one-piece spline", move || {
                    s.eval_piece(1, 0.5)
                })
            },
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// shapes: Shape::validated, reference, point, corners
// ---------------------------------------------------------------------------------------------

fn shapes_cases() -> Vec<Case> {
    vec![
        case("shapes::validated_sweep_non_finite", || {
            for bad in NON_FINITE {
                for shape in shapes_with(bad) {
                    expect_err!(shape.validated(), Error::NotPositive { .. })
                        .map_err(|e| format!("{shape:?}: {e}"))?;
                    expect_err!(shape.reference(100), Error::NotPositive { .. })
                        .map_err(|e| format!("{shape:?}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("shapes::validated_zero_and_negative", || {
            for bad in [0.0, -0.0, -5e-324, -1.0, f64::MIN] {
                for shape in shapes_with(bad) {
                    expect_err!(shape.validated(), Error::NotPositive { .. })
                        .map_err(|e| format!("{shape:?}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("shapes::validated_bounds", || {
            for shape in [
                Shape::Ellipse { ratio: 1.0 },
                Shape::Parabola { half_width: 1e100 },
                Shape::Hyperbola { b: 1e100 },
                Shape::Sinusoid { periods: 1e6 },
                Shape::Rectangle {
                    width: 1e100,
                    height: 1e100,
                },
            ] {
                ok(shape.validated()).map_err(|e| format!("{shape:?}: {e}"))?;
            }
            for shape in [
                Shape::Ellipse {
                    ratio: 1.0 + f64::EPSILON,
                },
                Shape::Parabola {
                    half_width: 1.1e100,
                },
                Shape::Hyperbola { b: f64::MAX },
                Shape::Sinusoid { periods: 1e6 + 1.0 },
                Shape::Rectangle {
                    width: 1.0,
                    height: 1e101,
                },
            ] {
                expect_err!(shape.validated(), Error::OutOfDomain { .. })
                    .map_err(|e| format!("{shape:?}: {e}"))?;
            }
            Ok(())
        }),
        case("shapes::validated_subnormal_is_valid", || {
            for p in [5e-324, 1e-310] {
                for shape in [
                    Shape::Ellipse { ratio: p },
                    Shape::Parabola { half_width: p },
                    Shape::Hyperbola { b: p },
                    Shape::Sinusoid { periods: p },
                    Shape::Rectangle {
                        width: p,
                        height: 1.0,
                    },
                ] {
                    ok(shape.validated()).map_err(|e| format!("{shape:?}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("shapes::reference_too_few_samples", || {
            for (_, shape) in SHAPES {
                for n in [0, 1, 2, 3] {
                    expect_err!(shape.reference(n), Error::TooFewSamples { got, .. } if *got == n)
                        .map_err(|e| format!("{shape:?}, {n}: {e}"))?;
                }
            }
            Ok(())
        }),
        risky("shapes::reference_usize_max", || {
            for (_, shape) in SHAPES {
                expect_err!(shape.reference(usize::MAX), Error::TooLarge { .. })?;
            }
            Ok(())
        }),
        risky("shapes::reference_1_shl_40", || {
            expect_err!(Shape::Circle.reference(1 << 40), Error::TooLarge { .. })
        }),
        risky("shapes::reference_max_elements_plus_one", || {
            let r = Shape::Rectangle {
                width: 2.0,
                height: 1.0,
            };
            expect_err!(r.reference(MAX_ELEMENTS + 1), Error::TooLarge { .. })
        }),
        case(
            "shapes::reference_of_every_shape_is_finite_and_closed",
            || {
                for (name, shape) in SHAPES {
                    for n in [4, 5, 97, 720] {
                        let r = ok(shape.reference(n))?;
                        ensure!(finite_vecs(&r), "{name}: not finite");
                        ensure!(r.len() >= n / 2, "{name}: {} points for {n}", r.len());
                        if shape.is_closed() {
                            ensure!(r[0] == r[r.len() - 1], "{name}: not closed");
                        }
                        let (x0, x1, y0, y1) = shape.bounding_box();
                        let slack = 1e-12 * (x1 - x0).max(y1 - y0);
                        ensure!(
                            r.iter().all(|p| p.x >= x0 - slack
                                && p.x <= x1 + slack
                                && p.y >= y0 - slack
                                && p.y <= y1 + slack),
                            "{name}: a point outside the bounding box"
                        );
                    }
                }
                Ok(())
            },
        ),
        case("shapes::reference_subnormal_and_tiny_parameters", || {
            for p in [5e-324, 1e-310, 1e-300] {
                for shape in [
                    Shape::Ellipse { ratio: p },
                    Shape::Parabola { half_width: p },
                    Shape::Hyperbola { b: p },
                    Shape::Sinusoid { periods: p },
                    Shape::Rectangle {
                        width: p,
                        height: p,
                    },
                ] {
                    let r = ok(shape.reference(64)).map_err(|e| format!("{shape:?}: {e}"))?;
                    ensure!(finite_vecs(&r) && r.len() >= 5, "{shape:?}: {r:?}");
                }
            }
            Ok(())
        }),
        case("shapes::reference_huge_parameters", || {
            for shape in [
                Shape::Parabola { half_width: 1e100 },
                Shape::Hyperbola { b: 1e100 },
                Shape::Sinusoid { periods: 1e6 },
                Shape::Rectangle {
                    width: 1e100,
                    height: 1e-100,
                },
                Shape::Rectangle {
                    width: 1e100,
                    height: 1e100,
                },
            ] {
                let r = ok(shape.reference(16)).map_err(|e| format!("{shape:?}: {e}"))?;
                ensure!(finite_vecs(&r), "{shape:?}");
                for c in shape.corners() {
                    ensure!(r.contains(&c), "{shape:?}: corner {c:?} is not a sample");
                }
            }
            Ok(())
        }),
        case("shapes::try_point_non_finite_and_outside", || {
            for (name, shape) in SHAPES {
                for bad in NON_FINITE {
                    expect_err!(shape.try_point(bad), Error::NonFinite { .. })
                        .map_err(|e| format!("{name}: {e}"))?;
                }
                let (a, b) = shape.domain();
                expect_err!(shape.try_point(b + 1.0), Error::OutOfDomain { .. })?;
                expect_err!(shape.try_point(a - 1.0), Error::OutOfDomain { .. })?;
                ensure!(
                    ok(shape.try_point(a))?.iter().all(|x| x.is_finite()),
                    "{name}"
                );
            }
            Ok(())
        }),
        case("shapes::rectangle_point_at_its_corners", || {
            let r = Shape::Rectangle {
                width: 2.0,
                height: 1.0,
            };
            let c = r.corners();
            let (_, b) = r.domain();
            for (t, k) in [(0.0, 0), (1.0, 1), (3.0, 2), (4.0, 3), (b, 0)] {
                ensure!(r.point(t) == c[k], "at {t}: {:?} vs {:?}", r.point(t), c[k]);
            }
            // span_at never panics, NaN included
            for t in [f64::NAN, -1.0, 1e300, f64::INFINITY] {
                ensure!(r.span_at(t).is_some(), "span at {t}");
            }
            Ok(())
        }),
        case("shapes::corners_only_for_the_rectangle", || {
            for (name, shape) in SHAPES {
                let c = shape.corners();
                match shape {
                    Shape::Rectangle { .. } => ensure!(c.len() == 4, "{name}"),
                    _ => ensure!(c.is_empty(), "{name}: {c:?}"),
                }
            }
            Ok(())
        }),
        case("shapes::tolerance_and_bounding_box_finite", || {
            for (name, shape) in SHAPES {
                let t = shape.tolerance();
                ensure!(t.is_finite() && t > 0.0, "{name}: {t}");
            }
            let s = Shape::Sinusoid { periods: 1e-300 };
            let (x0, x1, y0, y1) = s.bounding_box();
            ensure!(
                [x0, x1, y0, y1].iter().all(|v| v.is_finite()) && s.tolerance() > 0.0,
                "tiny sinusoid box ({x0}, {x1}, {y0}, {y1})"
            );
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// metrics2: segment_distance, SegmentTree, distances, sampling, curvature, smoothness
// ---------------------------------------------------------------------------------------------

fn metrics2_cases() -> Vec<Case> {
    vec![
        case("metrics2::segment_distance_below_1e-154", || {
            for s in [1e-155, 1e-170, 1e-200, 1e-300] {
                let (p, a, b) = (v2(2.0 * s, 3.0 * s), v2(0.0, 0.0), v2(4.0 * s, 0.0));
                close(
                    &format!("scale {s:e}"),
                    segment_distance(p, a, b),
                    reference_distance(p, a, b),
                    1e-14,
                )?;
            }
            Ok(())
        }),
        case("metrics2::segment_distance_subnormal", || {
            let (p, a, b) = (v2(5e-311, 3e-311), v2(0.0, 0.0), v2(1e-310, 0.0));
            close(
                "subnormal",
                segment_distance(p, a, b),
                reference_distance(p, a, b),
                1e-9,
            )
        }),
        case("metrics2::segment_distance_to_a_point_below_1e-154", || {
            let (p, a) = (v2(3e-170, 4e-170), v2(0.0, 0.0));
            close("point", segment_distance(p, a, a), 5e-170, 1e-14)
        }),
        case("metrics2::segment_distance_near_1e7", || {
            // a distance of 1e-6 from a segment of length 5 at 1.2e7: the foot of the
            // perpendicular must not be rounded at the coordinates' ulp (2e-9)
            let a = v2(12_345_678.0, 23_456_789.0);
            let u = v2(3.0, 4.0);
            let n = v2(-0.8, 0.6);
            let b = a + u;
            for (f, d) in [(0.37, 1e-6), (0.5, 1e-7), (0.91, 3e-6)] {
                let p = a + u * f + n * d;
                close(
                    &format!("t = {f}, distance {d:e}"),
                    segment_distance(p, a, b),
                    reference_distance(p, a, b),
                    1e-9,
                )?;
            }
            Ok(())
        }),
        case("metrics2::segment_distance_at_coordinate_limits", || {
            for m in [MAX_COORDINATE, f64::MAX / 2.0, f64::MAX] {
                let d = segment_distance(v2(0.0, m), v2(-m, 0.0), v2(m, 0.0));
                ensure!(
                    d.is_finite() && (d - m).abs() <= 1e-15 * m,
                    "{m:e}: distance {d:e}"
                );
            }
            Ok(())
        }),
        case("metrics2::segment_tree_empty", || {
            expect_err!(SegmentTree::new(&[]), Error::TooFewPoints { got: 0, .. })
        }),
        case("metrics2::segment_tree_sweep_non_finite", || {
            sweep(6, |bad, k| {
                let mut p = vec![v2(0.0, 0.0), v2(1.0, 0.0), v2(1.0, 1.0)];
                p[k / 2][k % 2] = bad;
                expect_err!(SegmentTree::new(&p), Error::NonFinite { .. })
            })
        }),
        case("metrics2::segment_tree_beyond_coordinate_limit", || {
            for bad in [2.0 * MAX_COORDINATE, f64::MAX, -f64::MAX] {
                expect_err!(
                    SegmentTree::new(&[v2(0.0, 0.0), v2(bad, 1.0)]),
                    Error::CoordinateTooLarge { .. }
                )?;
            }
            Ok(())
        }),
        risky("metrics2::segment_tree_too_many_points", || {
            expect_err!(
                SegmentTree::new(&vec![v2(0.0, 0.0); MAX_ELEMENTS + 1]),
                Error::TooLarge { .. }
            )
        }),
        case("metrics2::segment_tree_single_point", || {
            let t = ok(SegmentTree::new(&[v2(1.0, 1.0)]))?;
            let d = t.distance(v2(4.0, 5.0));
            ensure!(d == 5.0, "{d}");
            let (m, at) = t.farthest(&[v2(1.0, 1.0), v2(1.0, 3.0)]);
            ensure!(m == 2.0 && at == Some(1), "{m} at {at:?}");
            Ok(())
        }),
        case("metrics2::segment_tree_distance_below_1e-154", || {
            for s in [1e-160, 1e-200, 1e-300] {
                let pts: Vec<Vector2<f64>> = (0..40)
                    .map(|i| v2(i as f64 * s, (i as f64 * 0.3).sin() * s))
                    .collect();
                let t = ok(SegmentTree::new(&pts))?;
                let q = v2(7.3 * s, 2.0 * s);
                close(
                    &format!("scale {s:e}"),
                    t.distance(q),
                    reference_one_sided(&[q], &pts),
                    1e-12,
                )?;
            }
            Ok(())
        }),
        case("metrics2::segment_tree_distance_near_1e7", || {
            let (curve, reference) = parallel_pair(v2(1.1e7, -2.3e7), 10.0, 1e-6);
            let t = ok(SegmentTree::new(&reference))?;
            for p in &curve {
                close(
                    "vertex",
                    t.distance(*p),
                    reference_one_sided(&[*p], &reference),
                    1e-9,
                )?;
            }
            Ok(())
        }),
        case("metrics2::segment_tree_at_coordinate_limit", || {
            let m = MAX_COORDINATE;
            let pts = vec![v2(-m, -m), v2(m, -m), v2(m, m), v2(-m, m), v2(-m, -m)];
            let t = ok(SegmentTree::new(&pts))?;
            let d = t.distance(v2(0.0, 0.0));
            ensure!((d - m).abs() <= 1e-15 * m, "{d:e}");
            let (f, at) = t.farthest(&[v2(0.0, 0.0), v2(m, m)]);
            ensure!(
                (f - m).abs() <= 1e-15 * m && at == Some(0),
                "{f:e} at {at:?}"
            );
            Ok(())
        }),
        case("metrics2::farthest_of_no_points", || {
            let t = ok(SegmentTree::new(&four_points()))?;
            let (m, at) = t.farthest(&[]);
            ensure!(m == 0.0 && at.is_none(), "{m} at {at:?}");
            Ok(())
        }),
        case("metrics2::farthest_matches_brute_force", || {
            let pts: Vec<Vector2<f64>> = (0..500)
                .map(|i| {
                    let t = i as f64 * 0.0125;
                    v2(t.cos() * (1.0 + 0.3 * (7.0 * t).sin()), t.sin())
                })
                .collect();
            let from: Vec<Vector2<f64>> = (0..300)
                .map(|i| v2((i as f64 * 0.37).sin() * 1.5, (i as f64 * 0.71).cos() * 1.5))
                .collect();
            let t = ok(SegmentTree::new(&pts))?;
            let (m, at) = t.farthest(&from);
            let brute = reference_one_sided(&from, &pts);
            ensure!(
                (m - brute).abs() <= 1e-14 * brute && at.is_some(),
                "{m} vs {brute}"
            );
            Ok(())
        }),
        case("metrics2::polyline_distances_empty", || {
            let p = four_points();
            expect_err!(polyline_distances(&[], &p), Error::TooFewPoints { .. })?;
            expect_err!(polyline_distances(&p, &[]), Error::TooFewPoints { .. })
        }),
        case("metrics2::polyline_distances_sweep_non_finite", || {
            sweep(8, |bad, k| {
                let mut a = four_points();
                let b = six_points(1.0);
                a[k / 2][k % 2] = bad;
                expect_err!(polyline_distances(&a, &b), Error::NonFinite { .. })?;
                expect_err!(polyline_distances(&b, &a), Error::NonFinite { .. })
            })
        }),
        case(
            "metrics2::polyline_distances_beyond_coordinate_limit",
            || {
                let mut a = four_points();
                a[2].y = -2.0 * MAX_COORDINATE;
                expect_err!(
                    polyline_distances(&a, &four_points()),
                    Error::CoordinateTooLarge { .. }
                )
            },
        ),
        case(
            "metrics2::polyline_distances_identical_and_symmetric",
            || {
                let (a, b) = (six_points(1.0), four_points());
                let d = ok(polyline_distances(&a, &a))?;
                ensure!(d.hausdorff() == 0.0, "{d:?}");
                let (ab, ba) = (
                    ok(polyline_distances(&a, &b))?,
                    ok(polyline_distances(&b, &a))?,
                );
                ensure!(
                    ab.curve_to_reference == ba.reference_to_curve
                        && ab.reference_to_curve == ba.curve_to_reference,
                    "{ab:?} vs {ba:?}"
                );
                Ok(())
            },
        ),
        case("metrics2::polyline_distances_below_1e-154", || {
            for s in [1e-160, 1e-200, 1e-300, 1e-310] {
                let (c, r) = parallel_pair(v2(0.0, 0.0), s, 0.01 * s);
                let d = ok(polyline_distances(&c, &r))?;
                let want = reference_one_sided(&c, &r).max(reference_one_sided(&r, &c));
                close(&format!("scale {s:e}"), d.hausdorff(), want, 1e-9)?;
            }
            Ok(())
        }),
        case("metrics2::polyline_distances_near_1e7", || {
            for offset in [v2(1e7, 1e7), v2(-3.3e7, 9.9e6), v2(2.0e8, 0.0)] {
                let (c, r) = parallel_pair(offset, 5.0, 1e-6);
                let d = ok(polyline_distances(&c, &r))?;
                let want = reference_one_sided(&c, &r).max(reference_one_sided(&r, &c));
                close(&format!("offset {offset:?}"), d.hausdorff(), want, 1e-9)?;
            }
            Ok(())
        }),
        case("metrics2::polyline_distances_huge_offsets", || {
            // far apart near the coordinate limit: finite
            let m = MAX_COORDINATE;
            let d = ok(polyline_distances(&[v2(-m, -m)], &[v2(m, m)]))?;
            ensure!(d.hausdorff().is_finite(), "{d:?}");
            Ok(())
        }),
        case("metrics2::distances_to_non_finite_curve", || {
            let t = ok(SegmentTree::new(&four_points()))?;
            expect_err!(
                distances_to(&[v2(0.0, f64::NAN)], &t),
                Error::NonFinite { .. }
            )?;
            expect_err!(distances_to(&[], &t), Error::TooFewPoints { .. })
        }),
        case("metrics2::sample_pieces_too_few_breaks", || {
            for breaks in [&[][..], &[0.0][..]] {
                expect_err!(
                    sample_pieces(&Shape::Circle, breaks, 8),
                    Error::TooFewPoints { .. }
                )?;
                expect_err!(
                    curvature_profile(&Shape::Circle, breaks, 8),
                    Error::TooFewPoints { .. }
                )?;
            }
            Ok(())
        }),
        case("metrics2::sample_pieces_too_few_per_piece", || {
            for n in [0, 1] {
                expect_err!(
                    sample_pieces(&Shape::Circle, &[0.0, TAU], n),
                    Error::TooFewSamples { .. }
                )?;
                expect_err!(
                    curvature_profile(&Shape::Circle, &[0.0, TAU], n),
                    Error::TooFewSamples { .. }
                )?;
            }
            Ok(())
        }),
        risky("metrics2::sample_pieces_usize_max", || {
            expect_err!(
                sample_pieces(&Shape::Circle, &[0.0, TAU], usize::MAX),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics2::sample_pieces_product_overflows", || {
            let breaks = linspace(0.0, TAU, 1000);
            expect_err!(
                sample_pieces(&Shape::Circle, &breaks, usize::MAX / 500),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                sample_pieces(&Shape::Circle, &breaks, 1 << 40),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics2::sample_pieces_max_elements_plus_one", || {
            expect_err!(
                sample_pieces(&Shape::Circle, &[0.0, TAU], MAX_ELEMENTS + 1),
                Error::TooLarge { .. }
            )
        }),
        risky("metrics2::curvature_profile_huge_counts", || {
            expect_err!(
                curvature_profile(&Shape::Circle, &[0.0, TAU], usize::MAX),
                Error::TooLarge { .. }
            )?;
            expect_err!(
                curvature_profile(&Shape::Circle, &linspace(0.0, TAU, 5), 1 << 40),
                Error::TooLarge { .. }
            )
        }),
        case("metrics2::sample_pieces_non_finite_breaks", || {
            for bad in NON_FINITE {
                expect_err!(
                    sample_pieces(&Shape::Parabola { half_width: 1.0 }, &[0.0, bad, 1.0], 4),
                    Error::NonFinite { .. } | Error::Overflow { .. }
                )?;
            }
            Ok(())
        }),
        case("metrics2::sample_pieces_overflowing_curve", || {
            // y = x² at x = 1e200 overflows
            expect_err!(
                sample_pieces(&Shape::Parabola { half_width: 1.0 }, &[0.0, 1e200], 4),
                Error::Overflow { .. }
            )
        }),
        case("metrics2::sample_pieces_into_clears_its_buffer", || {
            let mut out = vec![v2(9.0, 9.0); 3];
            expect_err!(
                sample_pieces_into(&Shape::Circle, &[0.0], 4, &mut out),
                Error::TooFewPoints { .. }
            )?;
            ensure!(out.is_empty(), "{out:?}");
            ok(sample_pieces_into(
                &Shape::Circle,
                &[0.0, PI, TAU],
                3,
                &mut out,
            ))?;
            ensure!(out.len() == 5 && finite_vecs(&out), "{out:?}");
            Ok(())
        }),
        case("metrics2::sample_pieces_subnormal_breaks", || {
            let s = ok(sample_pieces(&Shape::Circle, &[0.0, 5e-324, 1e-310], 4))?;
            ensure!(s.len() == 7 && finite_vecs(&s), "{s:?}");
            Ok(())
        }),
        case("metrics2::curvature_profile_of_the_circle", || {
            let p = ok(curvature_profile(&Shape::Circle, &[0.0, PI, TAU], 9))?;
            ensure!(p.len() == 2 && p.iter().all(|v| v.len() == 9), "shape");
            for &(t, k) in p.iter().flatten() {
                ensure!((k - 1.0).abs() <= 1e-12, "κ({t}) = {k}");
            }
            Ok(())
        }),
        case("metrics2::smoothness_of_nothing", || {
            let s = smoothness(&[], 1.0);
            ensure!(
                s.inflections == 0
                    && s.max_jump == 0.0
                    && s.max_curvature == 0.0
                    && s.singular == 0,
                "{s:?}"
            );
            let s = smoothness(&[vec![], vec![]], 1.0);
            ensure!(s.singular == 0 && s.max_jump == 0.0, "{s:?}");
            Ok(())
        }),
        case("metrics2::smoothness_counts_non_finite_as_singular", || {
            let profile = vec![
                vec![(0.0, 1.0), (0.5, f64::NAN), (1.0, 2.0)],
                vec![(1.0, f64::INFINITY), (1.5, -1.0), (2.0, f64::NEG_INFINITY)],
            ];
            let s = smoothness(&profile, 1.0);
            ensure!(s.singular == 3, "{s:?}");
            ensure!(
                s.max_curvature == 2.0 && s.max_jump.is_finite() && s.inflections == 1,
                "{s:?}"
            );
            Ok(())
        }),
        case("metrics2::smoothness_extreme_lengths", || {
            let profile = ok(curvature_profile(&Shape::Circle, &[0.0, PI, TAU], 9))?;
            let s = smoothness(&profile, f64::NAN);
            ensure!(
                s.singular == 18 && s.max_curvature == 0.0,
                "NaN length {s:?}"
            );
            let s = smoothness(&profile, f64::MAX);
            ensure!(
                s.max_curvature.is_finite() && s.max_jump.is_finite(),
                "f64::MAX length {s:?}"
            );
            let s = smoothness(&profile, 5e-324);
            ensure!(
                s.inflections == 0 && s.singular == 0 && s.max_curvature <= 1e-300,
                "subnormal length {s:?}"
            );
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// choice: Target, fewest_points and the rest of src/interp/choice.rs
// ---------------------------------------------------------------------------------------------

fn choice_cases() -> Vec<Case> {
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
                Error::NotPositive { .. }
            )
        }),
        case("choice::measure_far_points_finite", || {
            // a curve far from a small target: a finite (huge) error
            let t = ok(rectangle_target(40))?;
            let m = ok(t.measure(&Method::Linear, &six_points(1e300)))?;
            ensure!(m.distances.hausdorff().is_finite(), "{m:?}");
            Ok(())
        }),
        case("choice::fewest_points_max_points_zero", || {
            let t = ok(rectangle_target(40))?;
            for family in [
                Family::Angular,
                Family::Cardinal,
                Family::Cubic,
                Family::BSpline,
                Family::Linear,
            ] {
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
                    Err(Error::NotPositive { .. } | Error::NonFinite { .. }) => {}
                    Err(e) => return Err(format!("a = {a}: unexpected {e}")),
                }
            }
            Ok(())
        }),
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

// ---------------------------------------------------------------------------------------------
// comparison: study_cell, cross_methods, contour_tolerance, fewest_for_contours, pieces_changed
// ---------------------------------------------------------------------------------------------

fn comparison_cases() -> Vec<Case> {
    use splinelab::study::table_i::{
        contour_tolerance, cross_methods, fewest_for_contours, pieces_changed, study_cell,
    };
    vec![
        case("comparison::study_cell_column_out_of_range", || {
            // a cell of no column is refused, not studied as another column
            let mut cell = TABLE_I[0];
            cell.column = 99;
            expect_err!(
                study_cell(&cell, &options(12)),
                Error::IndexOutOfRange { index: 99, .. }
            )
        }),
        risky("comparison::study_cell_usize_max_points", || {
            let mut cell = TABLE_I[3];
            cell.points = usize::MAX;
            expect_err!(study_cell(&cell, &options(12)), Error::TooLarge { .. })
        }),
        case("comparison::study_cell_bspline_order_zero", || {
            let mut cell = TABLE_I[30];
            cell.method = Method::BSpline { order: 0 };
            expect_err!(study_cell(&cell, &options(12)), Error::DegreeTooLow { .. })
        }),
        case("comparison::study_cell_cardinal_nan_a", || {
            let mut cell = TABLE_I[12];
            cell.method = Method::Cardinal { a: f64::NAN };
            expect_err!(study_cell(&cell, &options(12)), Error::NotPositive { .. })
        }),
        case("comparison::cross_methods_of_no_cells", || {
            let c = ok(cross_methods(&[]))?;
            ensure!(c.is_empty(), "{} rows", c.len());
            Ok(())
        }),
        case("comparison::contour_tolerance_degenerate", || {
            ensure!(contour_tolerance(&[]) == 0.0, "no contours");
            ensure!(contour_tolerance(&[vec![]]) == 0.0, "an empty contour");
            let inf = contour_tolerance(&[vec![v2(0.0, 0.0), v2(f64::INFINITY, 1.0)]]);
            ensure!(inf == 0.0, "infinite: {inf}");
            let max = contour_tolerance(&[vec![v2(-f64::MAX, 0.0), v2(f64::MAX, 1.0)]]);
            ensure!(max.is_finite() && max >= 0.0, "±f64::MAX: {max}");
            let nan = contour_tolerance(&[vec![v2(0.0, 0.0), v2(f64::NAN, 1.0)]]);
            ensure!(nan.is_finite() && nan >= 0.0, "NaN: {nan}");
            Ok(())
        }),
        case("comparison::contour_tolerance_of_the_polygonal_a", || {
            let t = contour_tolerance(&polygonal_a());
            ensure!((t - 0.01).abs() < 1e-15, "{t}");
            let tiny: Vec<Vec<Vector2<f64>>> = polygonal_a()
                .into_iter()
                .map(|c| c.into_iter().map(|p| p * 1e-310).collect())
                .collect();
            let t = contour_tolerance(&tiny);
            ensure!(t > 0.0 && t.is_finite(), "subnormal: {t:e}");
            Ok(())
        }),
        case("comparison::fewest_for_contours_empty", || {
            let s = ok(fewest_for_contours(&[], 0.1, Family::Linear, &options(12)))?;
            ensure!(
                s.contours.is_empty()
                    && s.counted() == 0
                    && s.error() == 0.0
                    && s.within_tolerance(),
                "{s:?}"
            );
            Ok(())
        }),
        case("comparison::fewest_for_contours_bad_tolerance", || {
            for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                expect_err!(
                    fewest_for_contours(&polygonal_a(), tol, Family::Linear, &options(12)),
                    Error::NotPositive { .. }
                )?;
            }
            Ok(())
        }),
        case("comparison::fewest_for_contours_bad_contours", || {
            let mut a = polygonal_a();
            a[1][2].x = f64::NAN;
            expect_err!(
                fewest_for_contours(&a, 0.01, Family::Linear, &options(12)),
                Error::NonFinite { .. }
            )?;
            expect_err!(
                fewest_for_contours(
                    &[four_points()[..2].to_vec()],
                    0.01,
                    Family::Linear,
                    &options(12)
                ),
                Error::TooFewPoints { .. }
            )
        }),
        case("comparison::fewest_for_contours_polygonal_a", || {
            let s = ok(fewest_for_contours(
                &polygonal_a(),
                0.01,
                Family::Linear,
                &options(20),
            ))?;
            ensure!(s.within_tolerance() && s.error() <= 0.01, "{s:?}");
            ensure!(s.counted() == 14, "{} points", s.counted());
            Ok(())
        }),
        case("comparison::pieces_changed_index_out_of_range", || {
            let p = six_points(1.0);
            for index in [6, usize::MAX] {
                expect_err!(
                    pieces_changed(&Method::Angular, &p, false, index, v2(0.1, 0.0)),
                    Error::IndexOutOfRange { len: 6, .. }
                )?;
            }
            expect_err!(
                pieces_changed(&Method::Linear, &[], true, 0, v2(0.1, 0.0)),
                Error::IndexOutOfRange { len: 0, .. }
            )
        }),
        case("comparison::pieces_changed_sweep_non_finite_delta", || {
            sweep(2, |bad, k| {
                let mut d = [0.1, 0.1];
                d[k] = bad;
                for m in all_methods() {
                    expect_err!(
                        pieces_changed(&m, &six_points(1.0), false, 2, v2(d[0], d[1])),
                        Error::NonFinite { .. }
                    )
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", m)))?;
                }
                Ok(())
            })
        }),
        case("comparison::pieces_changed_huge_delta", || {
            expect_err!(
                pieces_changed(
                    &Method::Linear,
                    &six_points(1.0),
                    false,
                    2,
                    v2(2.0 * MAX_COORDINATE, 0.0)
                ),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case(
            "comparison::pieces_changed_zero_and_subnormal_delta",
            || {
                for m in all_methods() {
                    let n = ok(pieces_changed(&m, &six_points(1.0), false, 2, v2(0.0, 0.0)))?;
                    ensure!(
                        n == 0,
                        "{}: {n} pieces change without a move",
                        format_args!("{:?}", m)
                    );
                    let n = ok(pieces_changed(
                        &m,
                        &six_points(1.0),
                        true,
                        2,
                        v2(5e-324, 0.0),
                    ))?;
                    ensure!(
                        n == 0,
                        "{}: {n} pieces change by 5e-324",
                        format_args!("{:?}", m)
                    );
                }
                Ok(())
            },
        ),
        case("comparison::pieces_changed_angular_is_local", || {
            let p: Vec<Vector2<f64>> = (0..12)
                .map(|i| v2(i as f64, ((i * i) % 5) as f64))
                .collect();
            let n = ok(pieces_changed(&Method::Angular, &p, false, 6, v2(0.0, 0.3)))?;
            ensure!((1..=4).contains(&n), "{n} pieces");
            Ok(())
        }),
        case("comparison::pieces_changed_tiny_points", || {
            let p = six_points(1e-300);
            let n = ok(pieces_changed(
                &Method::Angular,
                &p,
                false,
                2,
                v2(1e-301, 0.0),
            ))?;
            ensure!((1..=3).contains(&n), "{n} pieces");
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// refit: CubicSpline::refit, refit_function
// ---------------------------------------------------------------------------------------------

/// The natural spline function through 4 points, to be refitted.
fn natural4() -> Result<CubicSpline<1>, String> {
    ok(CubicSpline::function(
        &[0.0, 1.0, 2.0, 3.0],
        &[0.0, 1.0, 0.0, 1.0],
        EndCondition::Natural,
    ))
}

/// A spline function reproduces its data exactly and is finite on its domain.
fn check_function(s: &CubicSpline<1>, x: &[f64], y: &[f64]) -> CaseResult {
    for (xi, yi) in x.iter().zip(y) {
        ensure!(
            s.value(*xi) == *yi,
            "s({xi:e}) = {:e}, not {yi:e}",
            s.value(*xi)
        );
    }
    let (a, b) = (x[0], x[x.len() - 1]);
    for k in 0..=64 {
        let t = a + (b - a) * (k as f64 / 64.0);
        let t = if t.is_finite() { t } else { 0.5 * a + 0.5 * b };
        ensure!(s.value(t).is_finite(), "s({t:e}) = {}", s.value(t));
    }
    Ok(())
}

fn refit_cases() -> Vec<Case> {
    vec![
        case("refit::sweep_non_finite_abscissa", || {
            sweep(4, |bad, k| {
                let x = put(vec![0.0, 1.0, 2.0, 3.0], k, bad);
                expect_err!(
                    natural4()?.refit_function(&x, &[0.0, 1.0, 0.0, 1.0]),
                    Error::NonFinite { .. }
                )
            })
        }),
        case("refit::sweep_non_finite_value_2d", || {
            sweep(8, |bad, k| {
                let s = ok(CubicSpline::try_new(
                    &[0.0, 1.0, 2.0, 3.0],
                    &four_points(),
                    EndCondition::Natural,
                ))?;
                let mut p = four_points();
                p[k / 2][k % 2] = bad;
                expect_err!(s.refit(&[0.0, 1.0, 2.0, 3.0], &p), Error::NonFinite { .. })
            })
        }),
        case("refit::gap_below_min_positive", || {
            for gap in [5e-324, 1e-310] {
                expect_err!(
                    natural4()?.refit_function(&[0.0, gap, 1.0], &[0.0, 1.0, 0.0]),
                    Error::GapTooSmall { .. }
                )?;
            }
            Ok(())
        }),
        case("refit::decreasing_and_repeated", || {
            expect_err!(
                natural4()?.refit_function(&[0.0, 2.0, 1.0], &[0.0; 3]),
                Error::NotIncreasing { index: 2, .. }
            )?;
            expect_err!(
                natural4()?.refit_function(&[0.0, -0.0, 1.0], &[0.0; 3]),
                Error::RepeatedParameter { index: 1, .. }
            )
        }),
        case("refit::abscissae_width_overflows", || {
            expect_err!(
                natural4()?.refit_function(&[-f64::MAX, 0.0, f64::MAX], &[0.0, 1.0, 0.0]),
                Error::Overflow { .. }
            )
        }),
        case("refit::huge_abscissae", || {
            let x = [-1e307, -1e306, 1e306, 8e307];
            let y = [0.0, 1.0, -1.0, 2.0];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("refit::values_beyond_coordinate_limit", || {
            for v in [2.0 * MAX_COORDINATE, -f64::MAX] {
                expect_err!(
                    natural4()?.refit_function(&[0.0, 1.0, 2.0], &[0.0, v, 0.0]),
                    Error::CoordinateTooLarge { .. }
                )?;
            }
            Ok(())
        }),
        case("refit::values_near_coordinate_limit", || {
            let m = MAX_COORDINATE;
            let x = [0.0, 1e-3, 2e-3, 1.0];
            let y = [m, -m, m, -m];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("refit::tiny_and_subnormal_values", || {
            for v in [1e-300, 5e-324] {
                let x = [0.0, 1.0, 2.0, 3.0];
                let y = [v, -v, 2.0 * v, 0.0];
                let s = ok(natural4()?.refit_function(&x, &y))?;
                check_function(&s, &x, &y)?;
            }
            Ok(())
        }),
        case("refit::tiny_abscissae", || {
            let x = [1e-300, 2e-300, 3e-300, 5e-300];
            let y = [0.0, 1.0, 0.0, 1.0];
            match natural4()?.refit_function(&x, &y) {
                Ok(s) => check_function(&s, &x, &y),
                Err(Error::Overflow { .. }) => Ok(()),
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
        case("refit::periodic_mismatch_and_too_few", || {
            let p = ok(CubicSpline::function(
                &[0.0, 1.0, 2.0],
                &[0.0, 1.0, 0.0],
                EndCondition::Periodic,
            ))?;
            expect_err!(
                p.clone().refit_function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.5]),
                Error::PeriodicEndsMismatch { .. }
            )?;
            expect_err!(
                p.refit_function(&[0.0, 1.0], &[0.0, 0.0]),
                Error::TooFewPoints { needed: 3, .. }
            )
        }),
        case("refit::clamped_ends_non_finite", || {
            for bad in NON_FINITE {
                for end in [
                    EndCondition::clamped(bad, 0.0),
                    EndCondition::clamped(0.0, bad),
                ] {
                    expect_err!(
                        CubicSpline::function(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.0], end),
                        Error::NonFinite { .. }
                    )?;
                }
            }
            Ok(())
        }),
        case("refit::clamped_ends_huge", || {
            let x = [0.0, 1.0, 2.0];
            let y = [0.0, 1.0, 0.0];
            for d in [1e300, MAX_COORDINATE] {
                match CubicSpline::function(&x, &y, EndCondition::clamped(d, -d)) {
                    Ok(s) => check_function(&s, &x, &y)?,
                    Err(Error::Overflow { .. }) => {}
                    Err(e) => return Err(format!("{d:e}: unexpected {e}")),
                }
            }
            expect_err!(
                CubicSpline::function(&x, &y, EndCondition::clamped(f64::MAX, 0.0)),
                Error::CoordinateTooLarge { .. }
            )
        }),
        case("refit::larger_then_smaller_data", || {
            let x: Vec<f64> = (0..2000).map(|i| i as f64 * 0.01).collect();
            let y: Vec<f64> = x.iter().map(|t| t.sin()).collect();
            let s = ok(natural4()?.refit_function(&x, &y))?;
            check_function(&s, &x, &y)?;
            let s = ok(s.refit_function(&[0.0, 1.0], &[3.0, 4.0]))?;
            ensure!(s.nodes() == [0.0, 1.0], "{:?}", s.nodes());
            check_function(&s, &[0.0, 1.0], &[3.0, 4.0])
        }),
        case("refit::every_end_condition", || {
            let x = [0.0, 0.5, 1.5, 3.0, 3.25];
            let y = [1.0, -1.0, 2.0, 0.5, 1.0];
            for end in [
                EndCondition::Natural,
                EndCondition::Periodic,
                EndCondition::Cyclic,
                EndCondition::Anticyclic,
                EndCondition::clamped(1.0, -1.0),
            ] {
                let s = ok(CubicSpline::function(
                    &[0.0, 1.0, 2.0],
                    &[1.0, 0.0, 1.0],
                    end,
                ))?;
                let s = ok(s.refit_function(&x, &y))
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
                check_function(&s, &x, &y)
                    .map_err(|e| format!("{}: {e}", format_args!("{:?}", end)))?;
            }
            Ok(())
        }),
        case("refit::curve_2d_count_mismatch", || {
            let s = ok(CubicSpline::try_new(
                &[0.0, 1.0, 2.0, 3.0],
                &four_points(),
                EndCondition::Natural,
            ))?;
            expect_err!(
                s.refit(&[0.0, 1.0, 2.0], &four_points()),
                Error::CountMismatch {
                    expected: 3,
                    got: 4,
                    ..
                }
            )
        }),
        risky("refit::too_many_points", || {
            let x: Vec<f64> = (0..=MAX_ELEMENTS).map(|i| i as f64).collect();
            let y = vec![0.0; MAX_ELEMENTS + 1];
            expect_err!(natural4()?.refit_function(&x, &y), Error::TooLarge { .. })
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// collocation2: the B-spline route of the cubic spline on nearly coincident knots
// ---------------------------------------------------------------------------------------------

/// The B-spline route through `(x, y)` with `end`: solved, interpolating within
/// [`RESIDUAL_TOLERANCE`] of the data scale (refusing as ill-conditioned fails the case).
fn collocation_solves(x: &[f64], y: &[f64], end: EndCondition<1>) -> CaseResult {
    let ys: Vec<Vector1<f64>> = y.iter().map(|&v| v1(v)).collect();
    let c = ok(collocation::cubic_spline(x, &ys, end))?;
    let scale = y.iter().map(|v| v.abs()).fold(f64::MIN_POSITIVE, f64::max);
    for (xi, yi) in x.iter().zip(y) {
        let e = (c.point(*xi)[0] - yi).abs();
        ensure!(
            e <= RESIDUAL_TOLERANCE * scale,
            "{}: misses {yi} at {xi} by {e:e}",
            format_args!("{:?}", end)
        );
    }
    let line = ok(c.polyline(200))?;
    ensure!(finite_vecs(&line), "not finite");
    Ok(())
}

fn collocation2_cases() -> Vec<Case> {
    vec![
        case("collocation2::natural_knots_1e-8_apart", || {
            collocation_solves(
                &[0.0, 1.0, 1.0 + 1e-8, 2.0, 3.0],
                &[0.0, 1.0, 1.0, 0.0, 1.0],
                EndCondition::Natural,
            )
        }),
        case("collocation2::clamped_knots_1e-8_apart", || {
            collocation_solves(
                &[0.0, 1.0, 1.0 + 1e-8, 2.0, 3.0],
                &[0.0, 1.0, 1.0, 0.0, 1.0],
                EndCondition::clamped(0.0, 0.0),
            )
        }),
        case("collocation2::natural_two_close_pairs", || {
            collocation_solves(
                &[0.0, 1e-8, 1.0, 2.0, 2.0 + 1e-8, 3.0],
                &[0.0, 0.0, 1.0, -1.0, -1.0, 0.5],
                EndCondition::Natural,
            )
        }),
        case("collocation2::uniform_spacing_1e-8", || {
            let x: Vec<f64> = (0..8).map(|i| i as f64 * 1e-8).collect();
            let y: Vec<f64> = (0..8).map(|i| (i as f64).sin()).collect();
            collocation_solves(&x, &y, EndCondition::Natural)?;
            collocation_solves(&x, &y, EndCondition::clamped(0.0, 0.0))
        }),
        case("collocation2::non_finite_and_subnormal_sites", || {
            let y = [v1(0.0), v1(1.0), v1(0.0)];
            for bad in NON_FINITE {
                expect_err!(
                    collocation::cubic_spline(&[0.0, bad, 2.0], &y, EndCondition::Natural),
                    Error::NonFinite { .. }
                )?;
            }
            expect_err!(
                collocation::cubic_spline(&[0.0, 5e-324, 2.0], &y, EndCondition::Natural),
                Error::GapTooSmall { .. }
            )
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// bspline2: batch evaluation against point() outside a very short domain
// ---------------------------------------------------------------------------------------------

fn short_domain_curve() -> Result<BSplineCurve<2>, String> {
    let knots = ok(KnotVector::try_new(vec![
        0.0,
        1.0,
        2.0,
        3.0,
        3.0 + 1e-9,
        4.0,
        5.0,
        6.0,
    ]))?;
    let basis = ok(BSplineBasis::try_new(knots, 3))?;
    ok(BSplineCurve::try_new(
        basis,
        vec![v2(0.0, 0.0), v2(1.0, 2.0), v2(2.0, -1.0), v2(3.0, 1.0)],
    ))
}

/// `eval_many` and `point` agree at `ts` to `rel` of the larger value (at least 1).
fn batch_agrees(c: &BSplineCurve<2>, ts: &[f64], rel: f64) -> CaseResult {
    let mut out = vec![v2(7.0, 7.0)];
    c.eval_many(ts, &mut out);
    ensure!(
        out.len() == ts.len(),
        "{} values for {}",
        out.len(),
        ts.len()
    );
    for (t, o) in ts.iter().zip(&out) {
        let p = c.point(*t);
        let scale = o.amax().max(p.amax()).max(1.0);
        ensure!(
            (o - p).amax() <= rel * scale,
            "at {t}: eval_many {o:?}, point {p:?}"
        );
    }
    Ok(())
}

fn bspline2_cases() -> Vec<Case> {
    vec![
        case("bspline2::eval_many_outside_a_short_domain", || {
            let c = short_domain_curve()?;
            batch_agrees(&c, &[2.999], 1e-6)?;
            batch_agrees(
                &c,
                &[2.9, 2.99, 2.999, 2.999_999, 3.000_001, 3.001, 3.1],
                1e-6,
            )
        }),
        case("bspline2::eval_many_inside_a_short_domain", || {
            let c = short_domain_curve()?;
            let ts: Vec<f64> = (0..=16).map(|k| 3.0 + 1e-9 * k as f64 / 16.0).collect();
            batch_agrees(&c, &ts, 1e-12)
        }),
        case("bspline2::eval_many_empty_and_non_finite", || {
            let c = short_domain_curve()?;
            let mut out = vec![v2(1.0, 1.0)];
            c.eval_many(&[], &mut out);
            ensure!(out.is_empty(), "{out:?}");
            c.eval_many(&[f64::NAN, f64::INFINITY, 3.0], &mut out);
            ensure!(out.len() == 3, "{out:?}");
            ensure!(
                (out[2] - c.point(3.0)).amax() <= 1e-12,
                "{:?} vs {:?}",
                out[2],
                c.point(3.0)
            );
            Ok(())
        }),
    ]
}

// ---------------------------------------------------------------------------------------------
// The report layer: figures, plane and 3-D builders, tables, glyphs
// ---------------------------------------------------------------------------------------------

#[cfg(not(feature = "report"))]
mod report {
    pub(super) fn cases() -> Vec<super::Case> {
        Vec::new()
    }
}

#[cfg(feature = "report")]
mod report {
    use super::*;
    use plotters::style::RGBColor;
    use splinelab::report::draw::{self, Plot2d, Plot3d};
    use splinelab::report::figure::{Figure, MAX_SIDE};
    use splinelab::report::heatmap::{ColorScale, HeatMap};
    use splinelab::report::plot2d::{self, Figure2d, Panel, Series, Style, MAX_PANELS};
    use splinelab::report::render3d::{Marker, Segment, View, SCENE_LIMIT};
    use splinelab::report::seed004::{figures, letters::letter_a};
    use splinelab::report::table::{self, Table};
    use splinelab::report::Error as RError;
    use splinelab::CoordErrors;

    pub(super) fn cases() -> Vec<Case> {
        let mut all = Vec::new();
        all.extend(figure_cases());
        all.extend(plot_cases());
        all.extend(plot3_cases());
        all.extend(table_cases());
        all.extend(letters_cases());
        all
    }

    const BLUE: RGBColor = RGBColor(0, 0, 255);

    /// A figure drawn as SVG: `Ok` (an SVG document) or a typed [`RError::Figure`] —
    /// never a panic or a hang.
    fn svg_or_refused(fig: &Figure) -> CaseResult {
        match fig.to_svg() {
            Ok(svg) => {
                ensure!(svg.contains("<svg"), "not an SVG document");
                Ok(())
            }
            Err(RError::Figure { .. }) => Ok(()),
            Err(e) => Err(format!("unexpected Err({e})")),
        }
    }

    /// A figure drawn both as SVG and as pixels (at a small size): `Ok` or a typed
    /// [`RError::Figure`], the pixel buffer of the figure's size.
    fn drawable(fig: Figure) -> CaseResult {
        let fig = fig.with_size(320, 240);
        svg_or_refused(&fig)?;
        match fig.to_rgb() {
            Ok(px) => {
                ensure!(px.len() == 320 * 240 * 3, "{} bytes", px.len());
                Ok(())
            }
            Err(RError::Figure { .. }) => Ok(()),
            Err(e) => Err(format!("unexpected Err({e})")),
        }
    }

    /// A figure that must draw (finite, ordinary data): SVG and pixels.
    fn draws(fig: Figure) -> CaseResult {
        let fig = fig.with_size(320, 240);
        let svg = ok(fig.to_svg())?;
        ensure!(svg.contains("<svg"), "not an SVG document");
        let px = ok(fig.to_rgb())?;
        ensure!(px.len() == 320 * 240 * 3, "{} bytes", px.len());
        Ok(())
    }

    /// One panel of one series `points`, as a figure.
    fn series_figure(points: Vec<(f64, f64)>) -> Figure {
        Plot2d::new("extreme data", "x", "y")
            .series("data", points)
            .figure()
    }

    fn simple_figure() -> Figure {
        series_figure(vec![(0.0, 0.0), (1.0, 2.0), (2.0, 1.0)])
    }

    fn surface() -> FnSurface<impl Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64> + Sync> {
        FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * t))
    }

    fn heat(x: Vec<f64>, y: Vec<f64>, values: Grid<f64>, scale: ColorScale) -> Figure {
        HeatMap {
            title: "map".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            bar_label: "v".into(),
            x,
            y,
            values,
            x_lines: vec![f64::NAN, 0.5, f64::INFINITY, 1e300],
            y_lines: vec![-f64::MAX, 0.25],
            scale,
            footnote: Some("note".into()),
        }
        .into()
    }

    fn tempdir() -> Result<tempfile::TempDir, String> {
        tempfile::tempdir().map_err(|e| format!("tempdir: {e}"))
    }

    // -----------------------------------------------------------------------------------------
    // figure: the Figure value and its outputs
    // -----------------------------------------------------------------------------------------

    fn figure_cases() -> Vec<Case> {
        vec![
            case("figure::with_size_zero_is_clamped_to_64", || {
                let fig = simple_figure().with_size(0, 0);
                ensure!(fig.size() == (64, 64), "{:?}", fig.size());
                let px = ok(fig.to_rgb())?;
                ensure!(px.len() == 64 * 64 * 3, "{} bytes", px.len());
                Ok(())
            }),
            risky("figure::with_size_u32_max_both_sides", || {
                let fig = simple_figure().with_size(u32::MAX, u32::MAX);
                ensure!(fig.size() == (MAX_SIDE, MAX_SIDE), "{:?}", fig.size());
                let px = ok(fig.to_rgb())?;
                let side = MAX_SIDE as usize;
                ensure!(px.len() == side * side * 3, "{} bytes", px.len());
                Ok(())
            }),
            risky("figure::to_rgb_huge_size_of_a_scene_and_a_map", || {
                let scene = Plot3d::new("scene")
                    .points(&[v3(0.0, 0.0, 0.0), v3(1.0, 1.0, 1.0)], BLUE, "p")
                    .figure()
                    .with_size(u32::MAX, 1);
                ensure!(scene.size() == (MAX_SIDE, 64), "{:?}", scene.size());
                ok(scene.to_rgb())?;
                let map = heat(
                    vec![0.0, 1.0],
                    vec![0.0, 1.0],
                    Grid::from_fn(2, 2, |i, j| (i + j) as f64),
                    ColorScale::Linear,
                )
                .with_size(1, u32::MAX);
                ok(map.to_rgb()).map(drop)
            }),
            case("figure::write_png_below_a_file", || {
                let (_dir, file) = plain_file()?;
                expect_err!(
                    simple_figure().write_png(&file.join("f.png")),
                    RError::Io { .. }
                )
            }),
            case("figure::write_svg_below_a_file", || {
                let (_dir, file) = plain_file()?;
                expect_err!(
                    simple_figure().write_svg(&file.join("f.svg")),
                    RError::Io { .. }
                )
            }),
            case("figure::save_below_a_file", || {
                let (_dir, file) = plain_file()?;
                expect_err!(
                    simple_figure().save(&file.join("a").join("b"), "f"),
                    RError::Io { .. }
                )
            }),
            case("figure::save_stem_in_a_missing_folder", || {
                let dir = tempdir()?;
                expect_err!(
                    simple_figure().save(dir.path(), "no-such-folder/f"),
                    RError::Io { .. }
                )
            }),
            case("figure::write_to_an_existing_directory", || {
                let dir = tempdir()?;
                expect_err!(simple_figure().write_png(dir.path()), RError::Io { .. })?;
                expect_err!(simple_figure().write_svg(dir.path()), RError::Io { .. })
            }),
            case("figure::save_writes_a_png_of_its_size_and_an_svg", || {
                let dir = tempdir()?;
                let paths = ok(simple_figure().with_size(200, 100).save(dir.path(), "f"))?;
                ensure!(paths.len() == 2, "{paths:?}");
                let png = image::open(&paths[0]).map_err(|e| format!("png: {e}"))?;
                ensure!(
                    (png.width(), png.height()) == (200, 100),
                    "{}×{}",
                    png.width(),
                    png.height()
                );
                let svg = std::fs::read_to_string(&paths[1]).map_err(|e| e.to_string())?;
                ensure!(svg.contains("<svg"), "svg");
                Ok(())
            }),
            case("figure::layout_without_cells", || {
                for layout in [(0, 0), (0, 3), (3, 0)] {
                    let fig = draw::panels("t", vec![Plot2d::new("p", "x", "y").panel()], layout);
                    expect_err!(fig.to_svg(), RError::Figure { .. })?;
                    expect_err!(fig.to_rgb(), RError::Figure { .. })?;
                }
                Ok(())
            }),
            risky("figure::layout_usize_max", || {
                for layout in [
                    (usize::MAX, usize::MAX),
                    (usize::MAX, 1),
                    (1 << 40, 1 << 40),
                ] {
                    let fig = draw::panels("t", vec![Plot2d::new("p", "x", "y").panel()], layout);
                    expect_err!(fig.to_svg(), RError::Figure { .. })?;
                }
                Ok(())
            }),
            case("figure::layout_max_panels", || {
                let one = || {
                    vec![Plot2d::new("p", "x", "y")
                        .series("s", vec![(0.0, 1.0)])
                        .panel()]
                };
                expect_err!(
                    draw::panels("t", one(), (1, MAX_PANELS + 1)).to_svg(),
                    RError::Figure { .. }
                )?;
                ok(draw::panels("t", one(), (32, 32)).to_svg()).map(drop)
            }),
            case("figure::more_cells_or_more_panels_than_the_layout", || {
                let panel = || {
                    Plot2d::new("p", "x", "y")
                        .series("s", vec![(0.0, 1.0), (1.0, 0.0)])
                        .panel()
                };
                draws(draw::panels("few", vec![panel()], (3, 3)))?;
                draws(draw::panels(
                    "many",
                    (0..7).map(|_| panel()).collect(),
                    (1, 2),
                ))?;
                draws(draw::panels("none", vec![], (2, 2)))
            }),
            case("figure::very_long_and_empty_titles", || {
                draws(draw::panels("", vec![], (1, 1)))?;
                let long = "a very long title ".repeat(600);
                draws(Plot2d::new(long, "x", "y").figure())
            }),
            case("figure::heatmap_non_finite_values", || {
                let v = [
                    f64::NAN,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    0.0,
                    5e-324,
                    f64::MAX,
                ];
                for scale in [ColorScale::Linear, ColorScale::Log { decades: 4.0 }] {
                    drawable(heat(
                        vec![0.0, 1.0, 2.0],
                        vec![0.0, 1.0],
                        Grid::from_fn(3, 2, |i, j| v[2 * i + j]),
                        scale,
                    ))?;
                }
                Ok(())
            }),
            case("figure::heatmap_mismatched_and_empty", || {
                drawable(heat(
                    vec![0.0, 1.0, 2.0, 3.0],
                    vec![0.0],
                    Grid::from_fn(2, 5, |i, j| (i * j) as f64),
                    ColorScale::Linear,
                ))?;
                drawable(heat(
                    vec![],
                    vec![],
                    Grid::from_fn(0, 0, |_, _| 0.0),
                    ColorScale::Log { decades: 3.0 },
                ))
            }),
            case("figure::heatmap_log_scale_degenerate_decades", || {
                for decades in [f64::NAN, -1.0, 0.0, 1e300, f64::INFINITY] {
                    drawable(heat(
                        vec![0.0, 1.0],
                        vec![0.0, 1.0],
                        Grid::from_fn(2, 2, |_, _| 0.0),
                        ColorScale::Log { decades },
                    ))
                    .map_err(|e| format!("{decades} decades: {e}"))?;
                }
                Ok(())
            }),
            risky("figure::heatmap_extreme_axes", || {
                for (x, y) in [
                    (vec![-f64::MAX, f64::MAX], vec![0.0, 1e-300]),
                    (vec![0.0, 5e-324], vec![f64::NAN, 1.0]),
                    (vec![1e300, 1e300], vec![-1e300, 1e300]),
                ] {
                    drawable(heat(
                        x,
                        y,
                        Grid::from_fn(2, 2, |i, j| (i + 2 * j) as f64 * 1e300),
                        ColorScale::Linear,
                    ))?;
                }
                Ok(())
            }),
        ]
    }

    // -----------------------------------------------------------------------------------------
    // plot: Plot2d, Figure2d, Panel, Series and the plane figures of draw
    // -----------------------------------------------------------------------------------------

    fn plot_cases() -> Vec<Case> {
        vec![
            risky("plot::series_spanning_f64_max", || {
                drawable(series_figure(vec![
                    (-f64::MAX, -f64::MAX),
                    (f64::MAX, f64::MAX),
                ]))
            }),
            risky("plot::series_spanning_f64_max_in_x_only", || {
                drawable(series_figure(vec![(-f64::MAX, 0.0), (f64::MAX, 1.0)]))
            }),
            risky("plot::series_near_f64_max_of_one_sign", || {
                drawable(series_figure(vec![
                    (f64::MAX / 2.0, 1.0),
                    (f64::MAX, 2.0),
                    (0.75 * f64::MAX, f64::MAX),
                ]))
            }),
            risky("plot::series_spanning_twice_the_coordinate_limit", || {
                let m = 2.0 * MAX_COORDINATE;
                drawable(series_figure(vec![(-m, m), (m, -m), (0.0, 0.0)]))
            }),
            case("plot::series_of_non_finite_points_only", || {
                drawable(series_figure(vec![
                    (f64::NAN, f64::NAN),
                    (f64::INFINITY, 1.0),
                    (1.0, f64::NEG_INFINITY),
                ]))?;
                drawable(series_figure(vec![]))
            }),
            risky("plot::series_of_a_tiny_span", || {
                drawable(series_figure(vec![
                    (0.0, 0.0),
                    (1e-300, 1e-300),
                    (2e-300, 0.0),
                ]))
            }),
            risky("plot::series_of_a_subnormal_span", || {
                drawable(series_figure(vec![
                    (0.0, 0.0),
                    (5e-324, 5e-324),
                    (1e-310, 0.0),
                ]))
            }),
            risky("plot::series_far_from_zero_and_narrow", || {
                drawable(series_figure(vec![
                    (1e300, -1e300),
                    (1e300 * (1.0 + 2.0 * f64::EPSILON), -1e300),
                ]))?;
                drawable(series_figure(vec![(1e7, 1e7), (1e7 + 1e-9, 1e7 + 2e-9)]))
            }),
            risky("plot::series_of_every_extreme_value", || {
                let v = [
                    f64::NAN,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::MAX,
                    -f64::MAX,
                    1e-300,
                    -5e-324,
                    0.0,
                ];
                let pts = v
                    .iter()
                    .flat_map(|&x| v.iter().map(move |&y| (x, y)))
                    .collect();
                drawable(series_figure(pts))
            }),
            risky(
                "plot::log_axes_with_non_positive_and_extreme_values",
                || {
                    let fig = Plot2d::new("log", "x", "y")
                        .log(true, true)
                        .series(
                            "s",
                            vec![
                                (0.0, 0.0),
                                (-1.0, -1.0),
                                (f64::MAX, f64::MAX),
                                (5e-324, 5e-324),
                                (f64::NAN, 1.0),
                            ],
                        )
                        .figure();
                    drawable(fig)?;
                    let only_bad = Plot2d::new("log", "x", "y")
                        .log(true, true)
                        .series("s", vec![(0.0, -1.0), (-5.0, 0.0)])
                        .figure();
                    drawable(only_bad)
                },
            ),
            risky("plot::log_axes_from_subnormal_to_f64_max", || {
                drawable(
                    Plot2d::new("log", "x", "y")
                        .log(true, false)
                        .series("s", vec![(5e-324, 0.0), (f64::MAX, 1.0)])
                        .figure(),
                )
            }),
            risky("plot::equal_axes_of_an_extreme_aspect", || {
                for pts in [
                    vec![(0.0, 0.0), (1e300, 1e-300)],
                    vec![(0.0, 0.0), (5e-324, f64::MAX)],
                    vec![(-f64::MAX, 0.0), (f64::MAX, 0.0)],
                ] {
                    drawable(
                        Plot2d::new("equal", "x", "y")
                            .equal()
                            .series("s", pts)
                            .figure(),
                    )?;
                }
                Ok(())
            }),
            risky("plot::fixed_ranges_non_finite_reversed_or_empty", || {
                for (x, y) in [
                    ((f64::NAN, f64::NAN), (f64::NEG_INFINITY, f64::INFINITY)),
                    ((1.0, 0.0), (2.0, 2.0)),
                    ((-f64::MAX, f64::MAX), (-f64::MAX, f64::MAX)),
                    ((0.0, 5e-324), (1e300, f64::INFINITY)),
                ] {
                    let panel = Panel::new("p", "x", "y")
                        .x_range(x.0, x.1)
                        .y_range(y.0, y.1)
                        .with(Series::line("s", vec![(0.0, 0.0), (1.0, 1.0)], BLUE));
                    drawable(draw::panels("ranges", vec![panel], (1, 1)))
                        .map_err(|e| format!("x {x:?}, y {y:?}: {e}"))?;
                }
                Ok(())
            }),
            case("plot::notes_at_extreme_positions", || {
                let mut panel = Panel::new("p", "x", "y").with(Series::line(
                    "s",
                    vec![(0.0, 0.0), (1.0, 1.0)],
                    BLUE,
                ));
                for (x, y) in [
                    (f64::NAN, 0.5),
                    (f64::MAX, -f64::MAX),
                    (f64::NEG_INFINITY, 0.0),
                    (1e-300, 0.5),
                ] {
                    panel = panel.note(x, y, "note");
                }
                drawable(draw::panels("notes", vec![panel], (1, 1)))
            }),
            case("plot::stroke_widths_and_marks_u32_max", || {
                let pts = vec![(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)];
                let panel = Panel::new("p", "x", "y")
                    .with(Series::line("w", pts.clone(), BLUE).width(u32::MAX))
                    .with(Series::line("p", pts.clone(), BLUE).styled(Style::Points(u32::MAX)))
                    .with(Series::line("c", pts.clone(), BLUE).styled(Style::Crosses(u32::MAX)))
                    .with(Series::line("l", pts.clone(), BLUE).styled(Style::LinePoints(u32::MAX)))
                    .with(
                        Series::line("z", pts, BLUE)
                            .width(0)
                            .styled(Style::Points(0)),
                    );
                draws(
                    Figure2d::new("marks", vec![panel], (1, 1))
                        .shared_legend()
                        .into(),
                )
            }),
            risky("plot::dashed_line_across_f64_max", || {
                let panel = Panel::new("p", "x", "y").with(
                    Series::line("d", vec![(-f64::MAX, 0.0), (f64::MAX, 1.0)], BLUE)
                        .styled(Style::Dashed),
                );
                drawable(draw::panels("dashes", vec![panel], (1, 1)))
            }),
            case("plot::dashed_line_with_gaps", || {
                let panel = Panel::new("p", "x", "y").with(
                    Series::line(
                        "d",
                        vec![
                            (0.0, 0.0),
                            (f64::NAN, 1.0),
                            (1.0, 1.0),
                            (2.0, 0.0),
                            (2.0, 0.0),
                        ],
                        BLUE,
                    )
                    .styled(Style::Dashed),
                );
                drawable(draw::panels("dashes", vec![panel], (1, 1)))
            }),
            risky("plot::shared_legend_of_thousands_of_entries", || {
                let panels = (0..4)
                    .map(|p| {
                        (0..500).fold(Plot2d::new("p", "x", "y"), |plot, k| {
                            plot.series(&format!("series {p}-{k}"), vec![(k as f64, p as f64)])
                        })
                    })
                    .map(Plot2d::panel)
                    .collect();
                drawable(
                    Figure2d::new("legend", panels, (2, 2))
                        .shared_legend()
                        .into(),
                )
            }),
            case("plot::tangents_at_bad_parameters_and_lengths", || {
                let c = ok(AngularSpline::try_new(six_points(1.0)))?;
                for length in [1.0, f64::MAX, f64::NAN, -1e300, 5e-324] {
                    let fig = Plot2d::new("tangents", "x", "y")
                        .tangents(&c, &[f64::NAN, f64::INFINITY, 1e300, -1e300, 0.5], length)
                        .figure();
                    drawable(fig).map_err(|e| format!("length {length:e}: {e}"))?;
                }
                Ok(())
            }),
            case("plot::function_over_a_non_finite_interval", || {
                for (a, b) in [
                    (f64::NAN, 1.0),
                    (0.0, f64::INFINITY),
                    (f64::NEG_INFINITY, f64::INFINITY),
                    (1.0, 0.0),
                ] {
                    let fig = Plot2d::new("f", "x", "y")
                        .function("f", a, b, |x| x * x)
                        .figure();
                    drawable(fig).map_err(|e| format!("[{a}, {b}]: {e}"))?;
                }
                Ok(())
            }),
            risky("plot::function_over_an_f64_max_interval", || {
                let fig = Plot2d::new("f", "x", "y")
                    .function("f", -f64::MAX, f64::MAX, |x| x)
                    .function("g", -f64::MAX, f64::MAX, |x| x * x)
                    .figure();
                drawable(fig)
            }),
            case("plot::curve_trace_and_sampling", || {
                let t = ok(plot2d::trace(&Shape::Circle))?;
                ensure!(t.len() == plot2d::SAMPLES, "{} samples", t.len());
                let s = plot2d::sampled(f64::NAN, 1.0, |x| (x, x));
                ensure!(s.len() == plot2d::SAMPLES, "{} samples", s.len());
                ensure!(plot2d::xy(&[]).is_empty(), "xy of nothing");
                let c = ok(AngularSpline::try_new(six_points(1.0)))?;
                draws(
                    ok(Plot2d::new("c", "x", "y").curve("angular", &c))?
                        .control_polygon("polygon", &six_points(1.0))
                        .points("points", &six_points(1.0))
                        .figure(),
                )
            }),
            case("plot::interpolation_panel_of_empty_or_nan_data", || {
                let c = ok(AngularSpline::try_new(six_points(1.0)))?;
                let empty = ok(draw::interpolation("empty", &[], &[], true, &c))?;
                let nan = [v2(f64::NAN, 0.0), v2(1.0, f64::INFINITY)];
                let bad = ok(draw::interpolation("nan", &nan, &nan, false, &c))?;
                drawable(draw::panels("interpolation", vec![empty, bad], (1, 2)))
            }),
            case("plot::methods_figure_refuses_a_bad_method", || {
                let cases = vec![
                    (Method::Angular, six_points(1.0), false),
                    (Method::BSpline { order: 0 }, six_points(1.0), false),
                ];
                expect_err!(
                    draw::methods("m", &six_points(1.0), &cases, (1, 2)),
                    RError::Core(Error::DegreeTooLow { .. })
                )?;
                let nan = vec![(Method::Linear, vec![v2(f64::NAN, 0.0), v2(1.0, 1.0)], false)];
                expect_err!(
                    draw::methods("m", &[], &nan, (1, 1)),
                    RError::Core(Error::NonFinite { .. })
                )
            }),
            case("plot::methods_figure_of_no_cases_or_no_layout", || {
                draws(ok(draw::methods("none", &[], &[], (1, 1)))?)?;
                let cases: Vec<_> = all_methods()
                    .into_iter()
                    .map(|m| (m, six_points(1.0), true))
                    .collect();
                draws(ok(draw::methods("all", &six_points(1.0), &cases, (3, 3)))?)?;
                let fig = ok(draw::methods("zero", &[], &cases, (0, 0)))?;
                expect_err!(fig.to_svg(), RError::Figure { .. })
            }),
            case("plot::choice_figure_of_a_search", || {
                let t = ok(rectangle_target(40))?;
                let c = ok(fewest_points(&t, Family::Linear, &options(12)))?;
                draws(ok(draw::choice(&t, &c))?)?;
                let bad = bogus_choice(Method::Angular, vec![v2(f64::NAN, 0.0); 4], 7);
                expect_err!(
                    draw::choice_panel("bad", &t, &bad),
                    RError::Core(Error::NonFinite { .. })
                )
            }),
            case("plot::series_figure_on_log_axes_with_zeros", || {
                let fig = draw::series(
                    "s",
                    "x",
                    "y",
                    &[
                        ("zeros", vec![(0.0, 0.0), (1.0, 0.0)]),
                        ("negative", vec![(-1.0, -1.0), (2.0, -3.0)]),
                        ("fine", vec![(1e-3, 1e3), (1e3, 1e-3)]),
                        ("empty", vec![]),
                    ],
                    (true, true),
                );
                drawable(fig)
            }),
            case("plot::bases_of_degree_zero_and_high_degree", || {
                draws(draw::bases(&basis(0, 3)?, "degree 0"))?;
                draws(draw::bases(&basis(12, 40)?, "degree 12"))
            }),
            case("plot::convergence_of_degenerate_rows", || {
                draws(draw::convergence(&[], "no rows"))?;
                let e = |v: f64| CoordErrors {
                    report_norm: v3(v, v, v),
                    max_abs: v3(v, -v, 0.0),
                    rms: v3(v, v, v),
                };
                let rows = vec![
                    splinelab::ConvergenceRow {
                        n: 0,
                        h: f64::NAN,
                        errors: e(f64::INFINITY),
                        order: None,
                    },
                    splinelab::ConvergenceRow {
                        n: usize::MAX,
                        h: 0.0,
                        errors: e(5e-324),
                        order: None,
                    },
                    splinelab::ConvergenceRow {
                        n: 1,
                        h: f64::MAX,
                        errors: e(f64::MAX),
                        order: None,
                    },
                ];
                drawable(draw::convergence(&rows, "bad rows"))
            }),
            case("plot::de_casteljau_bad_input", || {
                expect_err!(
                    draw::de_casteljau(&[], &[0.5], "none"),
                    RError::Core(Error::TooFewPoints { .. })
                )?;
                for u in [f64::NAN, f64::INFINITY, 1e300] {
                    match draw::de_casteljau(&six_points(1.0), &[u], "bad u") {
                        Ok(fig) => drawable(fig)?,
                        Err(RError::Core(Error::NonFinite { .. } | Error::OutOfDomain { .. })) => {}
                        Err(e) => return Err(format!("u = {u}: unexpected {e}")),
                    }
                }
                Ok(())
            }),
            case("plot::de_casteljau_no_or_many_parameters", || {
                draws(ok(draw::de_casteljau(&six_points(1.0), &[], "no u"))?)?;
                let us: Vec<f64> = (0..1000).map(|k| k as f64 / 999.0).collect();
                draws(ok(draw::de_casteljau(&six_points(1.0), &us, "many u"))?)
            }),
            risky("plot::de_casteljau_at_the_coordinate_limit", || {
                let m = MAX_COORDINATE / 2.0;
                let p = vec![v2(-m, -m), v2(m, -m), v2(m, m), v2(-m, m)];
                match draw::de_casteljau(&p, &[0.5, 0.25], "huge") {
                    Ok(fig) => drawable(fig),
                    Err(RError::Core(
                        Error::CoordinateTooLarge { .. } | Error::Overflow { .. },
                    )) => Ok(()),
                    Err(e) => Err(format!("unexpected {e}")),
                }
            }),
        ]
    }

    // -----------------------------------------------------------------------------------------
    // plot3: Plot3d, Figure3d, Scene, View
    // -----------------------------------------------------------------------------------------

    fn scene_of(points: &[Vector3<f64>]) -> Figure {
        Plot3d::new("scene")
            .points(points, BLUE, "points")
            .polyline(points, BLUE, "line")
            .figure()
    }

    fn plot3_cases() -> Vec<Case> {
        vec![
            case("plot3::points_beyond_the_scene_limit", || {
                for far in [1e301, f64::MAX, -f64::MAX, 2.0 * SCENE_LIMIT] {
                    let fig = scene_of(&[v3(0.0, 0.0, 0.0), v3(far, 1.0, 0.0)]);
                    expect_err!(fig.to_svg(), RError::Figure { .. })?;
                    expect_err!(fig.to_rgb(), RError::Figure { .. })?;
                }
                Ok(())
            }),
            risky("plot3::points_at_the_scene_limit", || {
                let m = SCENE_LIMIT;
                drawable(scene_of(&[v3(-m, -m, -m), v3(m, m, m), v3(m, -m, 0.0)]))
            }),
            risky("plot3::points_of_tiny_and_subnormal_extent", || {
                for s in [1e-300, 5e-324, 1e-310] {
                    drawable(scene_of(&[
                        v3(0.0, 0.0, 0.0),
                        v3(s, s, s),
                        v3(s, 0.0, 2.0 * s),
                    ]))
                    .map_err(|e| format!("{s:e}: {e}"))?;
                }
                drawable(scene_of(&[v3(1e300, 1e300, 1e300); 3]))
            }),
            case("plot3::non_finite_primitives_are_dropped", || {
                let nan = [
                    v3(f64::NAN, 0.0, 0.0),
                    v3(0.0, f64::INFINITY, 0.0),
                    v3(0.0, 0.0, f64::NEG_INFINITY),
                    v3(1.0, 1.0, 1.0),
                ];
                drawable(scene_of(&nan))?;
                drawable(scene_of(&nan[..3]))
            }),
            case("plot3::views_non_finite_and_extreme", || {
                for (yaw, pitch, scale) in [
                    (f64::NAN, f64::INFINITY, f64::NEG_INFINITY),
                    (1e300, -1e300, 1e300),
                    (0.0, 0.0, 0.0),
                    (-5e-324, 5e-324, 5e-324),
                    (PI / 2.0, PI / 2.0, -1.0),
                ] {
                    let fig = Plot3d::new("view")
                        .view(View { yaw, pitch, scale })
                        .points(&[v3(0.0, 0.0, 0.0), v3(1.0, 2.0, 3.0)], BLUE, "p")
                        .figure();
                    drawable(fig).map_err(|e| format!("view ({yaw}, {pitch}, {scale}): {e}"))?;
                }
                Ok(())
            }),
            case("plot3::view_drawable_clamps", || {
                let d = View::default();
                let v = View {
                    yaw: f64::NAN,
                    pitch: f64::NEG_INFINITY,
                    scale: f64::NAN,
                }
                .drawable();
                ensure!(
                    v.yaw == d.yaw && v.pitch == d.pitch && v.scale == 1.0,
                    "{v:?}"
                );
                for (scale, want) in [(0.0, 1.0), (-3.0, 1.0), (1e10, 16.0), (5e-324, 1.0 / 16.0)] {
                    let v = View { scale, ..d }.drawable();
                    ensure!(v.scale == want, "scale {scale:e} → {}", v.scale);
                }
                Ok(())
            }),
            case("plot3::grids_empty_single_row_and_non_finite", || {
                let g0: Grid<Vector3<f64>> = Grid::from_fn(0, 0, |_, _| Vector3::zeros());
                let g1 = Grid::from_fn(1, 5, |_, j| v3(j as f64, 0.0, 1.0));
                let bad = Grid::from_fn(4, 4, |i, j| {
                    let z = match (i + j) % 4 {
                        0 => f64::NAN,
                        1 => f64::INFINITY,
                        2 => -1e300,
                        _ => (i * j) as f64,
                    };
                    v3(i as f64, j as f64, z)
                });
                for g in [&g0, &g1, &bad] {
                    drawable(Plot3d::new("grid").grid(g, None, 1.0).figure())?;
                    drawable(Plot3d::new("grid").grid(g, Some(BLUE), 0.5).figure())?;
                }
                Ok(())
            }),
            risky("plot3::surface_huge_samples", || {
                for n in [usize::MAX, 1 << 40, MAX_ELEMENTS + 1] {
                    expect_err!(
                        Plot3d::new("s").surface(&surface(), &Rect::unit(), n),
                        RError::Core(Error::TooLarge { .. })
                    )?;
                }
                Ok(())
            }),
            case("plot3::surface_colored_alpha_extremes", || {
                for alpha in [f64::NAN, -1.0, 1e300, f64::INFINITY, 0.0] {
                    let fig = ok(Plot3d::new("s").surface_colored(
                        &surface(),
                        &Rect::unit(),
                        6,
                        BLUE,
                        alpha,
                    ))?
                    .figure();
                    drawable(fig).map_err(|e| format!("alpha {alpha}: {e}"))?;
                }
                Ok(())
            }),
            case("plot3::segments_and_markers_of_extreme_sizes", || {
                let mut plot = Plot3d::new("s").points(&[v3(1.0, 1.0, 1.0)], BLUE, "");
                let o = v3(0.0, 0.0, 0.0);
                let scene = plot.scene_mut();
                scene.segments.push(Segment::arrow(o, o, BLUE, 3));
                scene
                    .segments
                    .push(Segment::line(o, v3(1.0, 0.0, 0.0), BLUE, u32::MAX));
                scene
                    .segments
                    .push(Segment::arrow(o, v3(0.0, 1.0, 0.0), BLUE, 0));
                scene.markers.push(Marker {
                    at: o,
                    color: BLUE,
                    radius: u32::MAX,
                });
                draws(plot.mesh(false).figure())
            }),
            case("plot3::space_curve_and_its_tangents", || {
                let k = ok(KnotVector::open_uniform(3, 5, 0.0, 1.0))?;
                let pts = vec![
                    v3(0.0, 0.0, 0.0),
                    v3(1.0, 2.0, 0.0),
                    v3(2.0, -1.0, 1.0),
                    v3(3.0, 1.0, 2.0),
                    v3(4.0, 0.0, 0.0),
                ];
                let c = ok(BSplineCurve::try_new(ok(BSplineBasis::try_new(k, 3))?, pts))?;
                let fig = ok(Plot3d::new("curve").curve(&c, BLUE, "c"))?
                    .tangents(&c, &[f64::NAN, 0.5, 1e300, f64::NEG_INFINITY], 0.3)
                    .tangents(&c, &[0.25], f64::MAX)
                    .figure();
                drawable(fig)
            }),
            case("plot3::many_legend_entries", || {
                let plot = (0..400).fold(Plot3d::new("legend"), |p, k| {
                    p.legend(format!("entry {k}"), BLUE)
                });
                drawable(plot.points(&[v3(0.0, 0.0, 0.0)], BLUE, "p").figure())
            }),
            case("plot3::patches_too_few_samples", || {
                let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
                for n in [0, 1] {
                    expect_err!(
                        Plot3d::new("p").patches(&s, n, 1.0, true, |_, _| BLUE),
                        RError::Core(Error::TooFewSamples { .. })
                    )?;
                }
                draws(ok(Plot3d::new("p").spline(&s))?.figure())
            }),
            risky("plot3::patches_huge_samples", || {
                let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
                for n in [usize::MAX, 1 << 40] {
                    expect_err!(
                        Plot3d::new("p").patches(&s, n, 1.0, false, |_, _| BLUE),
                        RError::Core(Error::TooLarge { .. })
                    )?;
                }
                Ok(())
            }),
            case("plot3::outline_of_a_nan_surface", || {
                let f = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                    Vector3::new(s, t, (s - 0.5).sqrt())
                });
                expect_err!(
                    Plot3d::new("o").outline(&f, &Rect::unit(), BLUE),
                    RError::Core(Error::NonFiniteSurface { .. })
                )
            }),
            case(
                "plot3::corners_and_derivatives_of_an_overflowing_surface",
                || {
                    let f = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                        Vector3::new(s, t, (s * 700.0).exp() * (t * 10.0).exp())
                    });
                    let fig = Plot3d::new("d")
                        .corners(&f, &Rect::unit())
                        .derivatives(&f, &Rect::unit())
                        .figure();
                    drawable(fig)?;
                    let g = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                        Vector3::new(s.ln(), t, s * t)
                    });
                    drawable(
                        Plot3d::new("ln")
                            .corners(&g, &Rect::unit())
                            .derivatives(&g, &Rect::unit())
                            .figure(),
                    )
                },
            ),
            case("plot3::nets_degenerate", || {
                let g0: Grid<Vector3<f64>> = Grid::from_fn(0, 3, |_, _| Vector3::zeros());
                let g1 = Grid::from_fn(1, 1, |_, _| v3(1.0, 1.0, 1.0));
                let gn = Grid::from_fn(2, 2, |i, _| v3(f64::NAN, i as f64, 0.0));
                drawable(
                    Plot3d::new("nets")
                        .net(&g0, BLUE, "empty")
                        .net(&g1, BLUE, "")
                        .net(&gn, BLUE, "nan")
                        .figure(),
                )
            }),
        ]
    }

    // -----------------------------------------------------------------------------------------
    // table: frames, Markdown, HTML, CSV, files and the tables built from studies
    // -----------------------------------------------------------------------------------------

    fn extreme_frame() -> Result<table::Frame, String> {
        use table::Column;
        ok(table::frame(
            "extreme",
            vec![
                Column::new(
                    "v".into(),
                    vec![
                        f64::NAN,
                        f64::INFINITY,
                        f64::NEG_INFINITY,
                        f64::MAX,
                        5e-324,
                        -0.0,
                        0.1 + 0.2,
                    ],
                ),
                Column::new(
                    "name".into(),
                    vec!["a", "<b>", "c|d", "e,f", "\"g\"", "", "ü"],
                ),
            ],
        ))
    }

    fn table_cases() -> Vec<Case> {
        use table::Column;
        vec![
            case("table::frame_mismatched_lengths", || {
                expect_err!(
                    table::frame(
                        "t",
                        vec![
                            Column::new("a".into(), vec![1.0, 2.0]),
                            Column::new("b".into(), vec![1.0]),
                        ]
                    ),
                    RError::Table { .. }
                )
            }),
            case("table::frame_duplicate_names", || {
                expect_err!(
                    table::frame(
                        "t",
                        vec![
                            Column::new("a".into(), vec![1.0]),
                            Column::new("a".into(), vec![2.0]),
                        ]
                    ),
                    RError::Table { .. }
                )
            }),
            case("frame::try_new_ragged_third_column", || {
                let got = table::Frame::try_new(vec![
                    Column::new("a".into(), vec![1.0, 2.0]),
                    Column::new("b".into(), vec!["x", "y"]),
                    Column::new("c".into(), vec![Some(true)]),
                ]);
                match got {
                    Err(table::FrameError::Ragged {
                        name,
                        len: 1,
                        height: 2,
                        ..
                    }) if name == "c" => Ok(()),
                    other => Err(format!("{other:?}")),
                }
            }),
            case("frame::try_new_names_repeated_apart", || {
                let got = table::Frame::try_new(vec![
                    Column::new("a".into(), vec![1u32]),
                    Column::new("b".into(), vec![2i64]),
                    Column::new("a".into(), vec![3usize]),
                ]);
                match got {
                    Err(table::FrameError::DuplicateName(n)) if n == "a" => Ok(()),
                    other => Err(format!("{other:?}")),
                }
            }),
            case("frame::try_new_zero_rows", || {
                let f = ok(table::Frame::try_new(vec![
                    Column::new("a".into(), Vec::<f64>::new()),
                    Column::new("b".into(), Vec::<Option<String>>::new()),
                ]))?;
                ensure!(f.shape() == (0, 2), "{:?}", f.shape());
                ensure!(f.columns()[0].get(0).is_none(), "a cell past the end");
                let csv = ok(table::csv(&f))?;
                ensure!(csv == b"a,b\n", "{:?}", String::from_utf8_lossy(&csv));
                Ok(())
            }),
            case("table::frame_of_nothing", || {
                let df = ok(table::frame("empty", vec![]))?;
                let t = Table::new("empty", "", df.clone());
                ok(t.to_markdown())?;
                ok(t.to_html())?;
                ok(table::csv(&df))?;
                let (names, rows) = ok(table::display_rows(&df))?;
                ensure!(names.is_empty() && rows.is_empty(), "{names:?} {rows:?}");
                Ok(())
            }),
            case("table::non_finite_cells_in_every_format", || {
                let df = extreme_frame()?;
                let md = ok(table::markdown(&df))?;
                ensure!(md.contains("NaN") && md.contains("inf"), "{md}");
                let html = ok(table::html_table(&df))?;
                ensure!(!html.contains("<b>"), "unescaped cell: {html}");
                let csv = String::from_utf8(ok(table::csv(&df))?).map_err(|e| e.to_string())?;
                ensure!(csv.lines().count() == 8, "{csv}");
                Ok(())
            }),
            case("table::csv_keeps_full_precision", || {
                let df = extreme_frame()?;
                let csv = String::from_utf8(ok(table::csv(&df))?).map_err(|e| e.to_string())?;
                let values: Vec<f64> = csv
                    .lines()
                    .skip(1)
                    .filter_map(|l| l.split(',').next()?.parse().ok())
                    .collect();
                for want in [f64::MAX, 5e-324, 0.1 + 0.2] {
                    ensure!(values.contains(&want), "{want:e} not read back from {csv}");
                }
                Ok(())
            }),
            case("table::html_escapes_title_and_notes", || {
                let t = Table::new("t", "<script>x</script>", ok(table::frame("t", vec![]))?)
                    .note("a & b < c");
                let html = ok(t.to_html())?;
                ensure!(
                    !html.contains("<script>") && !html.contains("a & b"),
                    "{html}"
                );
                Ok(())
            }),
            case("table::write_below_a_file", || {
                let (_dir, file) = plain_file()?;
                let t = Table::new("t", "t", extreme_frame()?);
                expect_err!(t.write(&file.join("sub")), RError::Io { .. })?;
                expect_err!(
                    table::write_csv(&t.df, &file.join("t.csv")),
                    RError::Io { .. }
                )
            }),
            case("table::write_an_id_in_a_missing_folder", || {
                let dir = tempdir()?;
                let t = Table::new("missing/t", "t", extreme_frame()?);
                expect_err!(t.write(dir.path()), RError::Io { .. })
            }),
            case("table::write_csv_to_a_directory", || {
                let dir = tempdir()?;
                expect_err!(
                    table::write_csv(&extreme_frame()?, dir.path()),
                    RError::Io { .. }
                )
            }),
            case("table::write_and_read_back", || {
                let dir = tempdir()?;
                let paths = ok(Table::new("t", "title", extreme_frame()?).write(dir.path()))?;
                ensure!(
                    paths.len() == 2 && paths.iter().all(|p| p.exists()),
                    "{paths:?}"
                );
                Ok(())
            }),
            case("table::tabulation_too_few_samples", || {
                for (ns, nt) in [(0, 5), (5, 1), (0, 0)] {
                    expect_err!(
                        table::tabulation(&surface(), &Rect::unit(), ns, nt),
                        RError::Core(Error::TooFewSamples { .. })
                    )?;
                }
                Ok(())
            }),
            risky("table::tabulation_huge_counts", || {
                for (ns, nt) in [
                    (usize::MAX, 2),
                    (2, 1 << 40),
                    (1 << 32, 1 << 32),
                    (MAX_ELEMENTS + 1, 2),
                ] {
                    expect_err!(
                        table::tabulation(&surface(), &Rect::unit(), ns, nt),
                        RError::Core(Error::TooLarge { .. })
                    )
                    .map_err(|e| format!("{ns} × {nt}: {e}"))?;
                }
                Ok(())
            }),
            case("table::tabulation_of_a_nan_surface", || {
                let f = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                    Vector3::new(s, t, (s - 0.5).ln())
                });
                expect_err!(
                    table::tabulation(&f, &Rect::unit(), 5, 5),
                    RError::Core(Error::NonFiniteSurface { .. })
                )
            }),
            case("table::study_tables_of_nothing", || {
                let t = ok(table::coord_errors("e", "t", &[]))?;
                ensure!(t.df.height() == 0, "{} rows", t.df.height());
                ok(t.to_markdown())?;
                let t = ok(table::convergence("c", "t", &[]))?;
                ensure!(t.df.height() == 0, "{} rows", t.df.height());
                let t = ok(table::error_study(&surface(), &Rect::unit(), &[], 5))?;
                ensure!(t.df.height() == 0, "{} rows", t.df.height());
                Ok(())
            }),
            case("table::coord_errors_non_finite", || {
                let e = CoordErrors {
                    report_norm: v3(f64::NAN, f64::INFINITY, f64::NEG_INFINITY),
                    max_abs: v3(f64::MAX, 5e-324, -0.0),
                    rms: v3(1e-300, 0.0, 1.0),
                };
                let t = ok(table::coord_errors("e", "t", &[("bad".into(), e)]))?;
                ensure!(t.df.height() == 3, "{} rows", t.df.height());
                let md = ok(t.to_markdown())?;
                ensure!(md.contains("NaN"), "{md}");
                Ok(())
            }),
            case("table::seam_continuity_too_few_samples", || {
                let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 3))?;
                for n in [0, 1] {
                    expect_err!(
                        table::seam_continuity(&s, n),
                        RError::Core(Error::TooFewSamples { .. })
                    )?;
                }
                let t = ok(table::seam_continuity(&s, 5))?;
                ensure!(t.df.height() == 3, "{} seams", t.df.height());
                Ok(())
            }),
            risky("table::seam_continuity_huge_samples", || {
                let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
                for n in [usize::MAX, MAX_ELEMENTS + 1] {
                    expect_err!(
                        table::seam_continuity(&s, n),
                        RError::Core(Error::TooLarge { .. })
                    )?;
                }
                Ok(())
            }),
            case("table::error_study_bad_cases", || {
                expect_err!(
                    table::error_study(&surface(), &Rect::unit(), &[(0, 1)], 5),
                    RError::Core(Error::ZeroPatches { .. })
                )?;
                expect_err!(
                    table::error_study(&surface(), &Rect::unit(), &[(2, 2)], 1),
                    RError::Core(Error::TooFewSamples { .. })
                )
            }),
            risky("table::error_study_huge_cases", || {
                for case in [(usize::MAX, 1), (1 << 20, 1 << 20), (1, 1 << 40)] {
                    expect_err!(
                        table::error_study(&surface(), &Rect::unit(), &[case], 5),
                        RError::Core(Error::TooLarge { .. })
                    )
                    .map_err(|e| format!("{case:?}: {e}"))?;
                }
                expect_err!(
                    table::error_study(&surface(), &Rect::unit(), &[(2, 2)], usize::MAX),
                    RError::Core(Error::TooLarge { .. })
                )
            }),
        ]
    }

    // -----------------------------------------------------------------------------------------
    // letters: the glyph outlines of the letter "a" and the seed-004 figures built on them
    // -----------------------------------------------------------------------------------------

    fn letters_cases() -> Vec<Case> {
        vec![
            case("letters::unknown_versions", || {
                for v in [0, 5, usize::MAX] {
                    expect_err!(letter_a(v), RError::UnknownId { .. })?;
                    expect_err!(figures::letter(v), RError::UnknownId { .. })?;
                }
                Ok(())
            }),
            case("letters::every_version_is_a_valid_target", || {
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
            case("letters::every_version_with_the_letter_methods", || {
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
            case("letters::shape_column_out_of_range", || {
                for column in [9, usize::MAX] {
                    expect_err!(figures::shape_column(column), RError::UnknownId { .. })?;
                }
                Ok(())
            }),
        ]
    }
}
