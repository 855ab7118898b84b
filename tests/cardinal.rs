//! The cardinal spline of seed 004 (Clark's rule `P′ᵢ = a (Pᵢ₊₁ − Pᵢ₋₁)`): the matrix form
//! equals the Hermite form, it interpolates with shared tangents (C¹), tends to the polygon as
//! `a → 0` at distance O(a), the 4-point circle's best `a` is the paper's 0.83, affine images
//! keep `a`, and each point moves only the four segments around it.

use nalgebra::{Matrix2, Vector2, Vector4};
use splinelab::{cardinal_matrix, CardinalSpline, Error, ParametricCurve};
use std::f64::consts::TAU;

fn v(x: f64, y: f64) -> Vector2<f64> {
    Vector2::new(x, y)
}

fn sample_points() -> Vec<Vector2<f64>> {
    vec![
        v(0.0, 0.0),
        v(1.0, 2.0),
        v(2.5, 2.4),
        v(4.0, 0.3),
        v(5.0, 1.7),
        v(7.0, 2.0),
        v(8.0, -0.5),
    ]
}

#[test]
fn the_matrix_form_equals_the_hermite_form() {
    for a in [0.1, 0.5, 0.83, 1.7] {
        let s = CardinalSpline::try_new(sample_points(), a).expect("valid");
        let m = cardinal_matrix(a);
        for k in 0..s.segments() {
            for j in 0..=10 {
                let t = j as f64 / 10.0;
                let power = Vector4::new(t * t * t, t * t, t, 1.0);
                let w = m.transpose() * power; // weights of P_{k}, …, P_{k+3}
                let p = &s.points()[k..k + 4];
                let by_matrix = p[0] * w[0] + p[1] * w[1] + p[2] * w[2] + p[3] * w[3];
                let u = if k + 1 == s.segments() && j == 10 {
                    s.segments() as f64
                } else {
                    k as f64 + t
                };
                let by_hermite = s.point(u);
                assert!(
                    (by_matrix - by_hermite).amax() < 1e-13,
                    "a = {a}, segment {k}, t = {t}: {by_matrix:?} vs {by_hermite:?}"
                );
                // the rows of M_c(a) sum to [0 0 0 1]: an affine combination
                assert!((w.sum() - 1.0).abs() < 1e-14);
            }
        }
    }
}

#[test]
fn it_interpolates_the_inner_points_with_clarks_tangents() {
    let a = 0.7;
    let pts = sample_points();
    let s = CardinalSpline::try_new(pts.clone(), a).expect("valid");
    assert_eq!(s.domain(), (0.0, (pts.len() - 3) as f64));
    for k in 0..=s.segments() {
        let u = k as f64;
        assert!((s.point(u) - pts[k + 1]).amax() < 1e-14, "node {k}");
        // exact derivative (dual numbers) at the joint, from both sides
        let expected = (pts[k + 2] - pts[k]) * a;
        assert!(
            (s.derivative(u) - expected).amax() < 1e-13,
            "tangent at {k}"
        );
        if k > 0 && k < s.segments() {
            let left = s.derivative(u - 1e-12);
            assert!((left - expected).amax() < 1e-9, "C¹ at joint {k}: {left:?}");
        }
    }
}

/// Distance from `p` to the segment `[a, b]`.
fn to_segment(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
    (p - (a + d * t)).norm()
}

#[test]
fn a_tends_to_the_polygon_at_distance_of_order_a() {
    // the paper's rectangle: the 4 corners of a 2 × 1 rectangle, closed by 3 repeats
    let corners = [v(0.0, 0.0), v(2.0, 0.0), v(2.0, 1.0), v(0.0, 1.0)];
    let mut ratios = Vec::new();
    for a in [0.1, 0.01, 0.001, 0.0001] {
        let s = CardinalSpline::closed(&corners, a).expect("valid");
        let worst = s
            .polyline(4001)
            .expect("samples")
            .iter()
            .map(|&p| {
                (0..4)
                    .map(|i| to_segment(p, corners[i], corners[(i + 1) % 4]))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max);
        ratios.push(worst / a);
    }
    // linear in a (spec: 0.05, 0.005, 5e-4, 5e-5)
    for r in &ratios {
        assert!((0.4..0.6).contains(r), "distance / a = {ratios:?}");
    }
}

/// Largest radial error of the closed cardinal spline through `m` equally spaced points of
/// the unit circle.
fn radial_error(m: usize, a: f64) -> f64 {
    let pts: Vec<Vector2<f64>> = (0..m)
        .map(|k| {
            let t = TAU * k as f64 / m as f64;
            v(t.cos(), t.sin())
        })
        .collect();
    let s = CardinalSpline::closed(&pts, a).expect("valid");
    s.polyline(8001)
        .expect("samples")
        .iter()
        .map(|p| (p.norm() - 1.0).abs())
        .fold(0.0, f64::max)
}

#[test]
fn the_four_point_circle_is_best_at_the_papers_a() {
    // golden-section search of the minimax a on [0.6, 1.1]
    let (mut lo, mut hi) = (0.6, 1.1);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..60 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if radial_error(4, x1) < radial_error(4, x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let best = 0.5 * (lo + hi);
    assert!(
        (0.827..=0.829).contains(&best),
        "best a for 4 points: {best} (the paper's 0.83)"
    );
    assert!(radial_error(4, best) < 3e-4);
    // more points want a smaller a, towards Catmull–Rom's 0.5
    assert!(radial_error(8, 0.5626) < radial_error(8, 0.8279));
}

#[test]
fn an_affine_image_keeps_the_same_a() {
    let pts = sample_points();
    let m = Matrix2::new(1.3, 0.4, -0.2, 0.7);
    let shift = v(3.0, -1.0);
    let mapped: Vec<Vector2<f64>> = pts.iter().map(|p| m * p + shift).collect();
    let a = 0.83;
    let s = CardinalSpline::try_new(pts, a).expect("valid");
    let t = CardinalSpline::try_new(mapped, a).expect("valid");
    for j in 0..=400 {
        let u = s.segments() as f64 * j as f64 / 400.0;
        let image = m * s.point(u) + shift;
        assert!((image - t.point(u)).amax() < 1e-12, "u = {u}");
    }
}

#[test]
fn each_point_moves_only_the_four_segments_around_it() {
    let pts = sample_points();
    let s = CardinalSpline::try_new(pts.clone(), 0.6).expect("valid");
    for j in 0..pts.len() {
        let mut moved = pts.clone();
        moved[j] += v(0.5, -0.8);
        let t = CardinalSpline::try_new(moved, 0.6).expect("valid");
        for k in 0..s.segments() {
            // segment k uses points k … k+3
            let uses = (k..k + 4).contains(&j);
            let changed = (0..=20).any(|i| {
                let u = k as f64 + i as f64 / 20.0;
                (s.point(u) - t.point(u)).amax() > 0.0
            });
            assert_eq!(changed, uses, "point {j}, segment {k}");
        }
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let three = sample_points()[..3].to_vec();
    assert!(matches!(
        CardinalSpline::try_new(three, 0.5),
        Err(Error::TooFewPoints {
            needed: 4,
            got: 3,
            ..
        })
    ));
    assert!(matches!(
        CardinalSpline::closed(&sample_points()[..2], 0.5),
        Err(Error::TooFewPoints {
            needed: 3,
            got: 2,
            ..
        })
    ));
    // a = 0 is the polygon (zero tangents)
    assert!(CardinalSpline::try_new(sample_points(), 0.0).is_ok());
    for a in [-0.5, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(
                CardinalSpline::try_new(sample_points(), a),
                Err(Error::Negative { .. })
            ),
            "a = {a}"
        );
    }
    let mut nan = sample_points();
    nan[2].y = f64::NAN;
    assert!(matches!(
        CardinalSpline::try_new(nan, 0.5),
        Err(Error::NonFinite { .. })
    ));
    // a huge a makes the derived tangents overflow: refused, not evaluated to infinity
    let big = CardinalSpline::try_new(sample_points(), 1e308);
    assert!(
        matches!(
            big,
            Err(Error::CoordinateTooLarge { .. }) | Err(Error::NonFinite { .. })
        ),
        "{big:?}"
    );
    // coincident points are allowed (a zero tangent), and evaluation stays finite
    let same = vec![v(1.0, 1.0); 5];
    let s = CardinalSpline::try_new(same, 0.5).expect("degenerate but valid");
    assert!(s.point(1.3).iter().all(|x| x.is_finite()));
}

#[test]
fn the_hermite_base_reproduces_cubics_on_uneven_knots() {
    // Hermite data of a cubic space curve: the piecewise cubic is the cubic itself
    use nalgebra::Vector3;
    use splinelab::HermiteCurve;
    let c = |u: f64| Vector3::new(u * u * u - 2.0 * u, 0.5 * u * u + 1.0, 3.0 - u);
    let dc = |u: f64| Vector3::new(3.0 * u * u - 2.0, u, -1.0);
    let knots = vec![-1.0, -0.2, 0.05, 1.3, 2.0];
    let curve = HermiteCurve::try_new(
        knots.clone(),
        knots.iter().map(|&u| c(u)).collect(),
        knots.iter().map(|&u| dc(u)).collect(),
    )
    .expect("valid");
    for j in 0..=300 {
        let u = -1.0 + 3.0 * j as f64 / 300.0;
        assert!((curve.point(u) - c(u)).amax() < 1e-13, "value at {u}");
        assert!(
            (curve.derivative(u) - dc(u)).amax() < 1e-12,
            "tangent at {u}"
        );
    }
    // bad input: lengths, knots, non-finite data
    let pts: Vec<Vector3<f64>> = knots.iter().map(|&u| c(u)).collect();
    let tan: Vec<Vector3<f64>> = knots.iter().map(|&u| dc(u)).collect();
    assert!(matches!(
        HermiteCurve::try_new(knots[..4].to_vec(), pts.clone(), tan.clone()),
        Err(Error::CountMismatch { .. })
    ));
    assert!(matches!(
        HermiteCurve::try_new(vec![0.0, 1.0, 1.0, 2.0, 3.0], pts.clone(), tan.clone()),
        Err(Error::RepeatedParameter { index: 2, .. })
    ));
    let mut bad = tan.clone();
    bad[1].x = f64::INFINITY;
    assert!(HermiteCurve::try_new(knots.clone(), pts.clone(), bad).is_err());
    assert!(matches!(
        HermiteCurve::try_new(vec![0.0], pts[..1].to_vec(), tan[..1].to_vec()),
        Err(Error::TooFewPoints { .. })
    ));
}
