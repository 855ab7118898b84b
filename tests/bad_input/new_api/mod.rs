//! Bad-input cases for the public API added with seed 004 and issue 13: the methods and their
//! point rules (`seed004api::*`), the Angular spline's chord-line limits (`angular2::*`), the
//! exact test shapes (`shapes::*`), the curve metrics (`metrics2::*`), the automatic point
//! choice (`choice::*`), the comparison (`comparison::*`), the cubic spline's refit
//! (`refit::*`), collocation on nearly coincident knots (`collocation2::*`), the B-spline batch
//! evaluation outside a short domain (`bspline2::*`), and — with the `report` feature — the
//! figure value (`figure::*`), the plane and 3-D builders (`plot::*`, `plot3::*`), tables
//! (`table::*`) and the glyphs of the letter "a" (`letters::*`).
//!
//! A child module of the catalog's harness (`tests/bad_input/main.rs`), so it uses that file's machinery
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
    all.extend(methods::cases());
    all.extend(angular::cases());
    all.extend(shapes::cases());
    all.extend(curve_metrics::cases());
    all.extend(choice::cases());
    all.extend(table_i::cases());
    all.extend(refit::cases());
    all.extend(near_knots::cases());
    all.extend(bspline::cases());
    all.extend(report::cases());
    all
}

mod angular;
mod bspline;
mod choice;
mod curve_metrics;
mod methods;
mod near_knots;
mod refit;
#[cfg(feature = "report")]
mod report;
mod shapes;
mod table_i;

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
// The report layer: figures, plane and 3-D builders, tables, glyphs
// ---------------------------------------------------------------------------------------------

#[cfg(not(feature = "report"))]
mod report {
    pub(super) fn cases() -> Vec<super::Case> {
        Vec::new()
    }
}
