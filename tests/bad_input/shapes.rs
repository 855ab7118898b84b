//! shapes: the exact test shapes: `Shape::validated`, `reference`, `try_point`, `corners`,
//! `tolerance`, `bounding_box`

use super::*;
use splinelab::seeds::seed004::SHAPES;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(validated_cases());
    all.extend(reference_and_point_cases());
    all
}

/// `Shape::validated`.
fn validated_cases() -> Vec<Case> {
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
    ]
}

/// `Shape::reference`, `try_point`, `corners`, `tolerance`, `bounding_box`.
fn reference_and_point_cases() -> Vec<Case> {
    vec![
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
