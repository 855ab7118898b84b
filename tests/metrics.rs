//! Curve error measures (src/metrics/curve.rs): the segment tree against brute force, the
//! Hausdorff distances against closed forms, the curvature profile and smoothness against
//! shapes whose curvature is known.

mod common;

use common::{
    distance_close, distance_to_polyline, exact_distance_to_polyline, exact_segment_distance, Rng,
    EXACT,
};
use nalgebra::Vector2;
use proptest::prelude::*;
use splinelab::metrics::curve::{
    curvature_profile, polyline_distances, sample_pieces, segment_distance, smoothness,
    SegmentTree, FLAT,
};
use splinelab::Shape;
use splinelab::{Error, ParametricCurve};
use std::f64::consts::{PI, TAU};

type V = Vector2<f64>;

fn circle(r: f64, n: usize, phase: f64) -> Vec<V> {
    (0..=n)
        .map(|i| {
            let t = phase + TAU * i as f64 / n as f64;
            V::new(r * t.cos(), r * t.sin())
        })
        .collect()
}

#[test]
fn segment_distance_closed_forms() {
    let (a, b) = (V::new(0.0, 0.0), V::new(2.0, 0.0));
    // above the segment: the ordinate; beyond an end: the distance to that end
    assert_eq!(segment_distance(V::new(1.3, 0.7), a, b), 0.7);
    assert_eq!(segment_distance(V::new(-3.0, 4.0), a, b), 5.0);
    assert_eq!(segment_distance(V::new(5.0, -4.0), a, b), 5.0);
    // a degenerate segment is a point
    assert_eq!(segment_distance(V::new(3.0, 4.0), a, a), 5.0);
}

#[test]
fn concentric_circles_are_their_radii_apart() {
    // vertices of the outer circle are 0.5 from the inner polygon plus at most its sagitta
    // r (1 − cos(π/n)); the inner vertices are within the outer polygon's sagitta of 0.5
    for (n, m) in [(64, 64), (100, 37), (1000, 999)] {
        let inner = circle(1.0, n, 0.0);
        let outer = circle(1.5, m, 0.3);
        let d = polyline_distances(&outer, &inner).unwrap();
        let sag_in = 1.0 - (PI / n as f64).cos();
        let sag_out = 1.5 * (1.0 - (PI / m as f64).cos());
        assert!(
            d.curve_to_reference >= 0.5 - EXACT && d.curve_to_reference <= 0.5 + sag_in + EXACT
        );
        assert!(
            d.reference_to_curve >= 0.5 - sag_out - EXACT && d.reference_to_curve <= 0.5 + EXACT
        );
        assert_eq!(
            d.hausdorff(),
            d.curve_to_reference.max(d.reference_to_curve)
        );
    }
}

#[test]
fn one_sided_distances_differ_for_a_part_of_a_shape() {
    // [0, 1] on the x axis against [0, 2]: the short one lies on the long one (0), the long
    // one's far end is 1 from the short one
    let short: Vec<V> = (0..=10).map(|i| V::new(i as f64 / 10.0, 0.0)).collect();
    let long = vec![V::new(0.0, 0.0), V::new(2.0, 0.0)];
    let d = polyline_distances(&short, &long).unwrap();
    assert_eq!(d.curve_to_reference, 0.0);
    assert_eq!(d.reference_to_curve, 1.0);
    // a parallel copy shifted by 0.25 is 0.25 away both ways (equal x samples)
    let shifted: Vec<V> = short.iter().map(|p| p + V::new(0.0, 0.25)).collect();
    let d = polyline_distances(&shifted, &short).unwrap();
    assert_eq!((d.curve_to_reference, d.reference_to_curve), (0.25, 0.25));
}

#[test]
fn the_tree_equals_brute_force_on_awkward_polylines() {
    let mut rng = Rng::new(12);
    // long crossing segments, a zig-zag of near-duplicates, a single point, a huge scale
    let cases: Vec<Vec<V>> = vec![
        vec![
            V::new(-10.0, -10.0),
            V::new(10.0, 10.0),
            V::new(-10.0, 10.0),
            V::new(10.0, -10.0),
        ],
        (0..500)
            .map(|i| V::new(i as f64 * 1e-9, if i % 2 == 0 { 0.0 } else { 1.0 }))
            .collect(),
        vec![V::new(0.5, 0.5)],
        (0..300)
            .map(|_| V::new(rng.uniform(-1e90, 1e90), rng.uniform(-1e90, 1e90)))
            .collect(),
    ];
    for line in cases {
        let tree = SegmentTree::new(&line).unwrap();
        let scale = line.iter().map(|p| p.amax()).fold(1.0, f64::max);
        for _ in 0..200 {
            let q = V::new(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)) * scale;
            let brute = if line.len() == 1 {
                (q - line[0]).norm()
            } else {
                exact_distance_to_polyline(&line, q)
            };
            let d = tree.distance(q);
            assert!(distance_close(d, brute, 4.0 * scale), "{d} vs {brute}");
            assert_eq!(d, kernel_brute(&line, q));
        }
    }
}

#[test]
fn long_segments_near_the_query_are_not_pruned() {
    // A segment 3·10⁵ long passing 0.74 from the query: its computed distance carries the
    // rounding of the foot of the perpendicular (ulps of 10⁵, 10⁻¹⁰ of the distance), below
    // its box's distance; the tree's pruning must still visit it, so that its minimum is the
    // brute-force one exactly (found by the random-input tests in CI).
    let line = [
        V::new(0.0, 0.0),
        V::new(0.0, 0.0),
        V::new(469344.0804474658, 0.0),
        V::new(-4.4939975281473465, 0.0),
        V::new(-4.4939975281473465, 0.0),
        V::new(-5.77973837694964, -329246.1530427028),
    ];
    let tree = SegmentTree::new(&line).unwrap();
    let mut rng = Rng::new(11);
    let queries = [V::new(-5.2366494299894955, 0.0)]
        .into_iter()
        .chain((0..2000).map(|_| V::new(rng.uniform(-6.0, -4.0), rng.uniform(-3e5, 1.0))));
    for q in queries {
        let brute = line
            .windows(2)
            .map(|w| segment_distance(q, w[0], w[1]))
            .fold(f64::INFINITY, f64::min);
        assert_eq!(tree.distance(q), brute, "at {q:?}");
    }
}

#[test]
fn coordinates_near_the_limit_do_not_overflow() {
    // squares of 1e300 overflow; the tree scales by a power of two and agrees with brute
    // force on the same data scaled down
    let big = 1e300;
    let line = [V::new(-big, -big), V::new(big, 0.0), V::new(0.0, big)];
    let tree = SegmentTree::new(&line).unwrap();
    let small: Vec<V> = line.iter().map(|p| p / big).collect();
    for q in [
        V::new(0.0, 0.0),
        V::new(big, big),
        V::new(-2.0 * big, 3.0 * big),
    ] {
        let d = tree.distance(q);
        let expected = distance_to_polyline(&small, q / big) * big;
        assert!(
            d.is_finite() && (d - expected).abs() <= EXACT * expected,
            "{d} vs {expected}"
        );
        assert_eq!(
            d,
            segment_distance(q, line[0], line[1]).min(segment_distance(q, line[1], line[2]))
        );
    }
    let d = polyline_distances(&line, &[V::new(0.0, 0.0)]).unwrap();
    assert!(d.hausdorff().is_finite() && d.hausdorff() > big);
}

#[test]
fn bad_polylines_are_typed_errors() {
    assert!(matches!(
        SegmentTree::new(&[]),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        SegmentTree::new(&[V::new(0.0, f64::NAN)]),
        Err(Error::NonFinite { .. })
    ));
    assert!(SegmentTree::new(&[V::new(0.0, f64::INFINITY)]).is_err());
    let c = Shape::Circle;
    assert!(matches!(
        sample_pieces(&c, &[0.0], 8),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        sample_pieces(&c, &[0.0, 1.0], 1),
        Err(Error::TooFewSamples { .. })
    ));
    assert!(matches!(
        sample_pieces(&c, &[0.0, 1.0], usize::MAX),
        Err(Error::TooLarge { .. })
    ));
    assert!(matches!(
        curvature_profile(&c, &[0.0, 1.0], 0),
        Err(Error::TooFewSamples { .. })
    ));
}

#[test]
fn sampled_pieces_hit_every_break() {
    let c = Shape::Circle;
    let breaks = [0.0, 1.0, 2.5, TAU];
    let line = sample_pieces(&c, &breaks, 5).unwrap();
    assert_eq!(line.len(), 3 * 4 + 1);
    for (k, &b) in breaks.iter().enumerate() {
        assert_eq!(line[4 * k], c.point(b));
    }
}

#[test]
fn a_circle_is_smooth_and_a_sine_has_its_inflections() {
    // κ = 1/r on the circle: κL = 2 with L = 2 (its diameter), no inflection, no jump
    let c = Shape::Circle;
    let profile = curvature_profile(&c, &[0.0, 2.0, TAU], 33).unwrap();
    for &(_, k) in profile.iter().flatten() {
        assert!((k - 1.0).abs() <= EXACT);
    }
    let s = smoothness(&profile, 2.0);
    assert_eq!((s.inflections, s.singular), (0, 0));
    assert!(s.max_jump <= 10.0 * EXACT && (s.max_curvature - 2.0).abs() <= 10.0 * EXACT);
    // y = sin x over three periods changes sign at kπ, k = 1 … 5
    let sine = Shape::Sinusoid { periods: 3.0 };
    let (a, b) = sine.domain();
    let breaks: Vec<f64> = (0..=12).map(|i| a + (b - a) * i as f64 / 12.0).collect();
    let s = smoothness(&curvature_profile(&sine, &breaks, 40).unwrap(), 1.0);
    assert_eq!(s.inflections, 5);
    // a straight line has no sign at all
    let flat = splinelab::PiecewiseLinear::curve(
        &[V::new(0.0, 0.0), V::new(1.0, 1.0)],
        splinelab::Parametrization::Uniform,
    )
    .unwrap();
    let s = smoothness(&curvature_profile(&flat, &[0.0, 1.0], 9).unwrap(), 1.0);
    assert_eq!((s.inflections, s.max_curvature), (0, 0.0));
    // wiggles below FLAT do not count, above it they do
    let wiggle = |k: f64| vec![vec![(0.0, k), (1.0, -k), (2.0, k)]];
    assert_eq!(smoothness(&wiggle(0.5 * FLAT), 1.0).inflections, 0);
    assert_eq!(smoothness(&wiggle(2.0 * FLAT), 1.0).inflections, 2);
    // a cusp is counted, not hidden
    let cusp = smoothness(&[vec![(0.0, 1.0), (1.0, f64::NAN)]], 1.0);
    assert_eq!(cusp.singular, 1);
}

#[test]
fn curvature_jumps_show_at_the_breaks_of_a_g1_curve_and_not_of_a_c2_one() {
    use splinelab::{CubicEnd, Method};
    // eight points of an ellipse: the Angular spline is made of circular arcs (κ constant on
    // each, different from piece to piece), the periodic cubic spline is C²
    let pts: Vec<V> = (0..8)
        .map(|i| {
            let t = TAU * i as f64 / 8.0;
            V::new(t.cos(), 0.5 * t.sin())
        })
        .collect();
    let jump = |m: Method| {
        let c = m.curve(&pts, true).unwrap();
        smoothness(&curvature_profile(&c, &c.breaks(), 17).unwrap(), 2.0).max_jump
    };
    assert!(jump(Method::Angular) > 0.1);
    let cyclic = jump(Method::Cubic {
        end: CubicEnd::Cyclic,
    });
    assert!(cyclic <= 1e-6, "{cyclic}");
    // on one circle the Angular pieces are arcs of it: no jump
    let circle: Vec<V> = pts.iter().map(|p| V::new(p.x, 2.0 * p.y)).collect();
    let c = Method::Angular.curve(&circle, true).unwrap();
    let s = smoothness(&curvature_profile(&c, &c.breaks(), 17).unwrap(), 2.0);
    assert!(s.max_jump <= 1e-6 && s.inflections == 0, "{s:?}");
}

/// The minimum of the library's segment distance over the polyline's segments, by brute
/// force (the tree must equal it exactly: the same kernel, the minimum in another order).
fn kernel_brute(line: &[V], q: V) -> f64 {
    if line.len() == 1 {
        return segment_distance(q, line[0], line[0]);
    }
    line.windows(2)
        .map(|w| segment_distance(q, w[0], w[1]))
        .fold(f64::INFINITY, f64::min)
}

fn brute_hausdorff(a: &[V], b: &[V]) -> f64 {
    let one = |p: &[V], q: &[V]| p.iter().map(|&x| kernel_brute(q, x)).fold(0.0, f64::max);
    one(a, b).max(one(b, a))
}

#[test]
fn distances_of_tiny_shapes_do_not_underflow() {
    // issue 23, class 3: below ~1e-154 the squares underflowed and every distance was 0, so
    // the point search "met" any tolerance on a tiny shape (fails on the earlier code)
    for scale in [1e-160, 1e-200, 1e-300, 1e-310] {
        let a = V::new(0.0, 0.0) * scale;
        let b = V::new(1.0, 0.0) * scale;
        let p = V::new(0.5, 0.75) * scale;
        let d = segment_distance(p, a, b);
        let exact = exact_segment_distance(p, a, b);
        assert!(
            exact > 0.0 && distance_close(d, exact, scale),
            "{scale}: {d} vs {exact}"
        );
        let curve = [p, V::new(0.25, 0.5) * scale];
        let h = polyline_distances(&curve, &[a, b]).unwrap().hausdorff();
        let exact = curve
            .iter()
            .map(|&x| exact_distance_to_polyline(&[a, b], x))
            .chain(
                [a, b]
                    .iter()
                    .map(|&x| exact_distance_to_polyline(&curve, x)),
            )
            .fold(0.0, f64::max);
        assert!(
            exact > 0.0 && distance_close(h, exact, scale),
            "{scale}: {h} vs {exact}"
        );
    }
}

#[test]
fn distances_far_from_the_origin_keep_their_digits() {
    // issue 23, class 3: near 1e7 the foot p − (a + ab·t) lost digits of the coordinates'
    // size (1e-9 relative at 1e7); measured from a, the distance is exact to rounding
    let o = V::new(1.234_567_8e7, -7.654_321e6);
    let a = o + V::new(0.0, 0.0);
    let b = o + V::new(3.0, 1.0);
    let mut rng = Rng::new(5);
    for _ in 0..2000 {
        let p = o + V::new(rng.uniform(-1.0, 4.0), rng.uniform(-1.0, 2.0));
        let d = segment_distance(p, a, b);
        let exact = exact_segment_distance(p, a, b);
        assert!(distance_close(d, exact, 4.0), "{p:?}: {d} vs {exact}");
    }
    // a point almost on a long segment: the cross product keeps the distance's digits
    let (a, b) = (V::new(0.1, 0.3), V::new(1e6 + 0.7, 3e5 + 0.9));
    let p = a + (b - a) * 0.37 + V::new(-3e-10, 1e-9);
    let exact = exact_segment_distance(p, a, b);
    let d = segment_distance(p, a, b);
    assert!(distance_close(d, exact, 1e6), "{d} vs {exact}");
}

/// A point at magnitude `10^e` (random mantissas and signs), for the distance targets.
fn at_magnitude() -> impl Strategy<Value = (f64, [f64; 6], f64)> {
    (
        -300i32..=300,
        prop::array::uniform6(-1.0f64..1.0),
        0.0f64..1.0,
    )
        .prop_map(|(e, v, near)| (10f64.powi(e), v, near))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// The segment distance equals the exact rational one to rounding of the distance, at
    /// magnitudes 1e-300 … 1e300, for points anywhere and points close to the segment.
    #[test]
    fn segment_distance_is_exact_to_rounding_at_every_magnitude((m, v, near) in at_magnitude()) {
        let a = V::new(v[0], v[1]) * m;
        let b = V::new(v[2], v[3]) * m;
        // half the points lie within 1e-6 of the segment's size from it
        let p = if near < 0.5 {
            a + (b - a) * (2.0 * near) + V::new(v[4], v[5]) * (m * 1e-6)
        } else {
            V::new(v[4], v[5]) * m
        };
        let d = segment_distance(p, a, b);
        let exact = exact_segment_distance(p, a, b);
        prop_assert!(distance_close(d, exact, 4.0 * m), "{:?} {:?} {:?}: {} vs {}", p, a, b, d, exact);
        // scale invariance: a power of two changes nothing but the exponent
        // (towards 1, so nothing becomes subnormal)
        let k = if m < 1.0 { 2f64.powi(40) } else { 2f64.powi(-40) };
        prop_assert_eq!(segment_distance(p * k, a * k, b * k), d * k);
    }

    /// The tree's distances and one-sided maxima equal brute force over the same kernel
    /// exactly, and the exact rational distances to rounding.
    #[test]
    fn tree_matches_brute_force(
        line in prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0), 2..120),
        other in prop::collection::vec((-12.0f64..12.0, -12.0f64..12.0), 1..80),
    ) {
        let line: Vec<V> = line.into_iter().map(|(x, y)| V::new(x, y)).collect();
        let other: Vec<V> = other.into_iter().map(|(x, y)| V::new(x, y)).collect();
        let tree = SegmentTree::new(&line).unwrap();
        for (i, &q) in other.iter().enumerate() {
            let d = tree.distance(q);
            prop_assert_eq!(d, kernel_brute(&line, q));
            // the exact rational reference for a few (it is slow)
            if i < 4 {
                let exact = exact_distance_to_polyline(&line, q);
                prop_assert!(distance_close(d, exact, 40.0), "{} vs {}", d, exact);
            }
        }
        let (far, at) = tree.farthest(&other);
        let brute = other.iter().map(|&q| kernel_brute(&line, q)).fold(0.0, f64::max);
        prop_assert_eq!(far, brute);
        prop_assert_eq!(kernel_brute(&line, other[at.unwrap()]), brute);
        if other.len() > 1 {
            let d = polyline_distances(&other, &line).unwrap();
            prop_assert_eq!(d.hausdorff(), brute_hausdorff(&other, &line));
        }
    }
}
