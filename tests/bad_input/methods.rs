//! methods: seed 004's methods and point rules: `Method`, `Interpolant`, `paper_points` and the
//! data helpers (`evenly_spaced`, `decimate`, the coastline, the polygonal "a")

use super::*;
use splinelab::seeds::seed004::{
    coastline, decimate, evenly_spaced, paper_points, polygonal_a, COAST_STEP, SHAPES, TABLE_I,
};

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

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(paper_points_cases());
    all.extend(point_rule_and_data_cases());
    all.extend(method_cases());
    all.extend(method_data_cases());
    all
}

/// `paper_points`: huge counts, invalid, tiny and huge shapes.
fn paper_points_cases() -> Vec<Case> {
    vec![
        risky("methods::paper_points_usize_max", || {
            expect_err!(
                paper_points(&Shape::Circle, &Method::Angular, usize::MAX),
                Error::TooLarge { got, .. } if *got == usize::MAX
            )
        }),
        risky("methods::paper_points_1_shl_40", || {
            expect_err!(
                paper_points(&Shape::Circle, &Method::Linear, 1 << 40),
                Error::TooLarge { got, .. } if *got == 1 << 40
            )
        }),
        risky("methods::paper_points_max_elements_plus_one", || {
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
            "methods::paper_points_huge_counts_every_method_and_shape",
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
        case("methods::paper_points_sweep_non_finite_shape", || {
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
        case("methods::paper_points_zero_and_negative_shape", || {
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
        case("methods::paper_points_shape_beyond_bounds", || {
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
        case("methods::paper_points_subnormal_and_tiny_shapes", || {
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
        case("methods::paper_points_huge_shapes_are_finite", || {
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
    ]
}

/// `paper_points` per method and per cell of Table I; the data helpers.
fn point_rule_and_data_cases() -> Vec<Case> {
    vec![
        case("methods::paper_points_bspline_order_zero_and_one", || {
            for order in [0, 1] {
                expect_err!(
                    paper_points(&Shape::Circle, &Method::BSpline { order }, 6),
                    Error::DegreeTooLow { .. }
                )?;
            }
            Ok(())
        }),
        case("methods::paper_points_bspline_order_usize_max", || {
            expect_err!(
                paper_points(
                    &Shape::Parabola { half_width: 1.0 },
                    &Method::BSpline { order: usize::MAX },
                    6
                ),
                Error::TooFewPoints { .. }
            )
        }),
        case("methods::paper_points_every_printed_cell", || {
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
        case("methods::angular_rectangle_points_draw", || {
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
            "methods::cardinal_points_nan_a_refused_by_the_curve",
            || {
                let m = Method::Cardinal { a: f64::NAN };
                let set = ok(paper_points(&Shape::Circle, &m, 7))?;
                expect_err!(m.curve(&set.points, set.closed), Error::Negative { .. })
            },
        ),
        case("methods::evenly_spaced_empty_and_zero", || {
            ensure!(evenly_spaced(&[], 5).is_empty(), "from no points");
            ensure!(evenly_spaced(&four_points(), 0).is_empty(), "zero points");
            Ok(())
        }),
        risky("methods::evenly_spaced_usize_max", || {
            let p = four_points();
            let e = evenly_spaced(&p, usize::MAX);
            ensure!(e == p, "{e:?}");
            Ok(())
        }),
        case("methods::evenly_spaced_coast", || {
            let coast = coastline();
            let e = evenly_spaced(&coast, 50);
            ensure!(e.len() == 50 && e[0] == coast[0], "{} points", e.len());
            ensure!(
                e.windows(2).all(|w| w[0] != w[1]),
                "repeated consecutive points"
            );
            Ok(())
        }),
        case("methods::decimate_step_zero_and_empty", || {
            let p = four_points();
            ensure!(decimate(&p, 0) == p, "step 0 keeps every point");
            ensure!(decimate(&[], 3).is_empty(), "no points");
            Ok(())
        }),
        risky("methods::decimate_step_usize_max", || {
            let p = four_points();
            let d = decimate(&p, usize::MAX);
            ensure!(d == vec![p[0]], "{d:?}");
            Ok(())
        }),
        case("methods::coastline_is_a_valid_ring", || {
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
            "methods::coastline_decimated_draws_with_every_method",
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
        case("methods::polygonal_a_contours_are_valid_targets", || {
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
    ]
}

/// `Method::curve`: orders, the cardinal `a`, too few points.
fn method_cases() -> Vec<Case> {
    vec![
        case("methods::method_bspline_order_zero_one_and_huge", || {
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
        case("methods::method_cardinal_a_non_finite_negative", || {
            for a in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1.0, -5e-324] {
                for closed in [false, true] {
                    expect_err!(
                        Method::Cardinal { a }.curve(&six_points(1.0), closed),
                        Error::Negative { .. }
                    )
                    .map_err(|e| format!("a = {a}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("methods::method_cardinal_a_zero_is_the_polygon", || {
            // zero tangents: every piece runs along the side between its two points
            for a in [0.0, -0.0] {
                for closed in [false, true] {
                    let m = Method::Cardinal { a };
                    let p = six_points(1.0);
                    let c = ok(m.curve(&p, closed))?;
                    check_curve(&m, &p, closed, &c)?;
                }
            }
            Ok(())
        }),
        case("methods::method_cardinal_a_subnormal", || {
            // a positive a however small: the curve tends to the polygon, still interpolating
            for a in [5e-324, 1e-310, 1e-300] {
                let m = Method::Cardinal { a };
                let p = six_points(1.0);
                let c = ok(m.curve(&p, false))?;
                check_curve(&m, &p, false, &c)?;
            }
            Ok(())
        }),
        case("methods::method_cardinal_a_huge", || {
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
        case("methods::method_empty_and_single_point", || {
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
    ]
}

/// `Method::curve` on non-finite, huge, tiny and repeated points; `Interpolant::breaks`,
/// `Method::counted_points`.
fn method_data_cases() -> Vec<Case> {
    vec![
        case("methods::method_nan_point", || {
            each_method_refuses(f64::NAN, |e| matches!(e, Error::NonFinite { .. }))
        }),
        case("methods::method_pos_inf_point", || {
            each_method_refuses(f64::INFINITY, |e| matches!(e, Error::NonFinite { .. }))
        }),
        case("methods::method_neg_inf_point", || {
            each_method_refuses(f64::NEG_INFINITY, |e| matches!(e, Error::NonFinite { .. }))
        }),
        case("methods::method_point_beyond_coordinate_limit", || {
            each_method_refuses(2.0 * MAX_COORDINATE, |e| {
                matches!(e, Error::CoordinateTooLarge { .. })
            })
        }),
        case("methods::method_point_f64_max", || {
            each_method_refuses(-f64::MAX, |e| matches!(e, Error::CoordinateTooLarge { .. }))
        }),
        case("methods::method_every_family_at_unit_scale", || {
            each_method(1.0, |_| false)
        }),
        case("methods::method_every_family_at_1e-300", || {
            each_method(1e-300, |_| false)
        }),
        case("methods::method_every_family_at_subnormal_scale", || {
            each_method(1e-310, |e| {
                matches!(
                    e,
                    Error::GapTooSmall { .. }
                        | Error::Overflow { .. }
                        | Error::IllConditioned { .. }
                )
            })
        }),
        case("methods::method_every_family_at_1e300", || {
            each_method(1e300, |_| false)
        }),
        case("methods::method_every_family_near_coordinate_limit", || {
            each_method(MAX_COORDINATE / 8.0, |e| {
                matches!(e, Error::Overflow { .. } | Error::CoordinateTooLarge { .. })
            })
        }),
        case("methods::method_periodic_needs_three_points", || {
            let two = &six_points(1.0)[..2];
            for end in [CubicEnd::Cyclic, CubicEnd::Anticyclic] {
                expect_err!(
                    Method::Cubic { end }.curve(two, false),
                    Error::TooFewPoints { .. }
                )?;
            }
            Ok(())
        }),
        case("methods::method_repeated_points", || {
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
        case("methods::interpolant_breaks_cover_the_domain", || {
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
        risky("methods::counted_points_saturates", || {
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
