//! Automatic point choice (src/interp/choice.rs) and Table I regenerated
//! (src/comparison.rs): the calibration, the guarantee against the paper's rule, an
//! independent check of every accepted error, determinism, bad input.

mod common;

use common::hausdorff;
use nalgebra::Vector2;
use splinelab::comparison::{study_cell, table_i, REFERENCE_SEGMENTS};
use splinelab::curve_metrics::sample_pieces;
use splinelab::interp::choice::{fewest_points, Family, SearchOptions, Target, FINAL_SAMPLES};
use splinelab::interp::methods::{CubicEnd, Method};
use splinelab::seeds::seed004::{paper_points, TABLE_I};
use splinelab::shapes::Shape;
use splinelab::Error;

type V = Vector2<f64>;

/// The error of a choice measured again by brute force against a reference of its own
/// (another sampling of the exact shape).
fn brute_error(shape: &Shape, method: &Method, points: &[V]) -> f64 {
    let curve = method.curve(points, shape.is_closed()).unwrap();
    let line = sample_pieces(&curve, &curve.breaks(), FINAL_SAMPLES).unwrap();
    hausdorff(&line, &shape.reference(3001).unwrap())
}

#[test]
fn the_relaxed_cubic_circle_is_first_under_the_tolerance_at_11_points() {
    // spec §4 calibration, through the comparison's own measure: 11 is the first count
    // (odd or even) whose Hausdorff error is within 1 % of the diameter
    let target = Target::shape(&Shape::Circle, REFERENCE_SEGMENTS).unwrap();
    let relaxed = Method::Cubic {
        end: CubicEnd::Relaxed,
    };
    let first = (4..=20)
        .find(|&n| {
            let set = paper_points(&Shape::Circle, &relaxed, n).unwrap();
            target
                .measure(&relaxed, &set.points)
                .unwrap()
                .distances
                .hausdorff()
                <= target.tolerance()
        })
        .unwrap();
    assert_eq!(first, 11);
    assert_eq!(target.tolerance(), 0.02);
}

/// Every cell of Table I (the search takes ~5 s in release, ~15 s in the test profile, which
/// is optimised for this: Cargo.toml's `[profile.dev]`).
#[test]
fn automatic_counts_never_exceed_the_paper_rule_and_their_errors_hold() {
    let cells = table_i().unwrap();
    assert_eq!(cells.len(), 36);
    for (index, study) in cells.iter().enumerate() {
        let auto = &study.automatic;
        assert!(auto.within_tolerance, "cell {index}: {auto:?}");
        if let Some(rule) = &study.paper_rule {
            assert!(
                auto.measure.counted <= rule.measure.counted,
                "cell {index}: automatic {} > rule {}",
                auto.measure.counted,
                rule.measure.counted
            );
        }
        // the accepted error, measured independently, is within the tolerance (up to the
        // references' own sampling: 2048 vs 3001 segments)
        let brute = brute_error(&study.shape, &auto.method, &auto.points);
        assert!(
            (brute - auto.measure.distances.hausdorff()).abs() <= 1e-3 * study.tolerance,
            "cell {index}: {brute} vs {}",
            auto.measure.distances.hausdorff()
        );
        assert!(brute <= study.tolerance * 1.001, "cell {index}: {brute}");
        // the count is the one the paper would print for these points
        assert_eq!(
            auto.measure.counted,
            auto.method
                .counted_points(auto.points.len(), study.shape.is_closed())
        );
    }
}

#[test]
fn the_table_is_the_same_on_every_run() {
    assert_eq!(table_i().unwrap(), table_i().unwrap());
}

#[test]
fn one_cell_is_the_same_on_every_run() {
    let cell = &TABLE_I[4]; // Parabola 2, Angular
    let a = study_cell(cell, &SearchOptions::default()).unwrap();
    let b = study_cell(cell, &SearchOptions::default()).unwrap();
    assert_eq!(a, b);
    assert!(a.automatic.measure.counted <= a.paper_rule.unwrap().measure.counted);
}

#[test]
fn a_polygon_gets_its_corners() {
    // the 2 : 1 rectangle as a plain polyline: the polygon through its 4 corners is exact,
    // and the Angular spline needs the corners and one point per side (collinear triples)
    let rect = Shape::Rectangle {
        width: 2.0,
        height: 1.0,
    };
    let target = Target::polyline(&rect.reference(400).unwrap(), true, 0.02).unwrap();
    let linear = fewest_points(&target, Family::Linear, &SearchOptions::default()).unwrap();
    assert_eq!(linear.measure.counted, 5);
    assert!(linear.measure.distances.hausdorff() <= 1e-12);
    let angular = fewest_points(&target, Family::Angular, &SearchOptions::default()).unwrap();
    assert!(angular.within_tolerance);
    assert!(angular.measure.counted <= 11, "{}", angular.measure.counted);
}

#[test]
fn an_impossible_tolerance_is_reported_not_hidden() {
    let target = Target::shape(&Shape::Sinusoid { periods: 1.0 }, 512)
        .unwrap()
        .with_tolerance(1e-9)
        .unwrap();
    let options = SearchOptions {
        max_points: 6,
        budget_per_coordinate: 2,
        known: None,
    };
    for family in [Family::Angular, Family::Cubic, Family::BSpline] {
        let c = fewest_points(&target, family, &options).unwrap();
        assert!(!c.within_tolerance);
        assert!(c.measure.distances.hausdorff() > 1e-9);
    }
}

#[test]
fn huge_search_options_stay_bounded() {
    // a tolerance nothing meets with a limit of a million points: the count stops at four
    // points per reference vertex (at least 64) and the compass search at its evaluation cap
    let shape = Shape::Parabola { half_width: 1.0 };
    let target = Target::polyline(&shape.reference(24).unwrap(), false, 1e-12).unwrap();
    let options = SearchOptions {
        max_points: 1_000_000,
        budget_per_coordinate: 1,
        known: None,
    };
    let c = fewest_points(&target, Family::Linear, &options).unwrap();
    assert!(!c.within_tolerance || c.measure.distances.hausdorff() <= 1e-12);
    assert!(c.points.len() <= splinelab::interp::choice::max_distinct_for(&target));
}

#[test]
fn bad_targets_are_typed_errors() {
    let p = |x: f64, y: f64| V::new(x, y);
    let line = [p(0.0, 0.0), p(1.0, 0.0)];
    assert!(matches!(
        Target::polyline(&line, false, 0.0),
        Err(Error::NotPositive { .. })
    ));
    assert!(matches!(
        Target::polyline(&line, false, f64::NAN),
        Err(Error::NotPositive { .. })
    ));
    assert!(matches!(
        Target::polyline(&line[..1], false, 0.1),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        Target::polyline(&line, true, 0.1),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        Target::polyline(&[p(1.0, 1.0); 5], false, 0.1),
        Err(Error::Degenerate { .. })
    ));
    assert!(matches!(
        Target::polyline(&[p(0.0, 0.0), p(f64::NAN, 1.0)], false, 0.1),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        Target::polyline(&[p(0.0, 0.0), p(f64::MAX, 1.0)], false, 0.1),
        Err(Error::CoordinateTooLarge { .. })
    ));
    // near the limit a target is valid and measures finitely
    let far =
        Target::polyline(&[p(0.0, 0.0), p(1e300, 1.0), p(1e300, 1e300)], false, 1e297).unwrap();
    let m = far
        .measure(&Method::Linear, &[p(0.0, 0.0), p(1e300, 1e300)])
        .unwrap();
    assert!(m.distances.hausdorff().is_finite() && m.distances.hausdorff() > 1e299);
    assert!(Target::shape(&Shape::Ellipse { ratio: f64::NAN }, 64).is_err());
    assert!(matches!(
        Target::shape(&Shape::Circle, 2),
        Err(Error::TooFewSamples { .. })
    ));
    let t = Target::shape(&Shape::Circle, 64).unwrap();
    assert!(t.clone().with_tolerance(-1.0).is_err());
    let huge = SearchOptions {
        max_points: usize::MAX,
        ..SearchOptions::default()
    };
    assert!(matches!(
        fewest_points(&t, Family::Angular, &huge),
        Err(Error::TooLarge { .. })
    ));
    // a method refusing the points is an error from measure, never a panic
    assert!(t
        .measure(&Method::Angular, &[p(1.0, 0.0), p(1.0, 0.0)])
        .is_err());
}

#[cfg(feature = "report")]
#[test]
fn the_table_i_outputs_build() {
    use splinelab::report;
    let fig = report::figure("fig-table-i").unwrap();
    let rgb = fig.to_rgb().unwrap();
    assert_eq!(rgb.len(), (fig.size().0 * fig.size().1 * 3) as usize);
    let inked = rgb.chunks(3).filter(|p| p.iter().any(|&c| c < 200)).count();
    assert!(inked * 50 > rgb.len() / 3, "fig-table-i is nearly blank");
    let table = report::table("table-i").unwrap();
    assert_eq!(table.df.height(), 36);
    assert_eq!(report::table("table-i-cross").unwrap().df.height(), 9 * 12);
}

#[test]
fn a_polygon_with_few_vertices_gets_points_on_its_sides() {
    // the polygonal letter a's outer contour has 8 vertices; the Angular spline needs the 8
    // corners and a point inside every side (16 + 3 counted), more points than vertices
    let outer = &splinelab::seeds::seed004::polygonal_a()[0];
    let tolerance = splinelab::comparison::contour_tolerance(std::slice::from_ref(outer));
    let target = Target::polyline(outer, true, tolerance).unwrap();
    let c = fewest_points(&target, Family::Angular, &SearchOptions::default()).unwrap();
    assert!(c.within_tolerance, "{:?}", c.measure);
    assert!(c.measure.counted <= 19, "{}", c.measure.counted);
    assert!(c.points.len() > outer.len());
}
