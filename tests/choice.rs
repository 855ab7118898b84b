//! Automatic point choice (src/interp/choice/) and Table I regenerated
//! (src/study/table_i.rs): the calibration, the guarantee against the paper's rule, an
//! independent check of every accepted error, determinism, bad input.

mod common;

use common::hausdorff;
use nalgebra::Vector2;
use splinelab::interp::choice::{
    fewest_points, search, Family, Minimality, SearchOptions, Target, FINAL_SAMPLES,
};
use splinelab::metrics::curve::sample_pieces;
use splinelab::seeds::seed004::{paper_points, TABLE_I};
use splinelab::study::table_i::{study_cell, table_i, Verdict, REFERENCE_SEGMENTS};
use splinelab::Error;
use splinelab::Shape;
use splinelab::{CubicEnd, Method};

type V = Vector2<f64>;

/// Table I's 36 cells, computed once for the tests that read them (the determinism test
/// computes its own twice).
fn cells() -> &'static [splinelab::study::table_i::CellStudy] {
    static CELLS: std::sync::OnceLock<Vec<splinelab::study::table_i::CellStudy>> =
        std::sync::OnceLock::new();
    CELLS.get_or_init(|| table_i().unwrap())
}

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
    let cells = cells();
    assert_eq!(cells.len(), 36);
    for (index, study) in cells.iter().enumerate() {
        let auto = &study.automatic;
        // every cell has a count within 1 % (issue 25: the Angular rectangle too, its points
        // clustered at the corners, which the local search of issue 23 did not reach)
        assert!(auto.within_tolerance, "cell {index}: {auto:?}");
        assert_ne!(study.outcome(), Verdict::NoneWithin, "cell {index}");
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
    // the Angular spline is G¹: it rounds the corners, so it needs points clustered at each
    // (a collinear triple beside a turn has no G¹ piece, issue 23); whatever it reports is a
    // valid spline whose error is what it claims
    let angular = fewest_points(&target, Family::Angular, &SearchOptions::default()).unwrap();
    assert!(splinelab::AngularSpline::closed(&angular.points).is_ok());
    let again = target.measure(&Method::Angular, &angular.points).unwrap();
    assert_eq!(again, angular.measure);
    assert_eq!(
        angular.within_tolerance,
        again.distances.hausdorff() <= target.tolerance()
    );
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
        ..SearchOptions::default()
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
        every_count_below: false,
        ..SearchOptions::default()
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
    let tolerance =
        splinelab::study::outline::Tolerance::default().of(splinelab::study::outline::size(&[
            splinelab::input::Contour {
                points: outer.clone(),
                closed: true,
            },
        ]));
    let target = Target::polyline(outer, true, tolerance).unwrap();
    // the Angular spline rounds its corners (G¹, issue 23): whatever it reports is a valid
    // spline measured as claimed; the cubic spline draws the same contour within 1 %
    let c = fewest_points(&target, Family::Angular, &SearchOptions::default()).unwrap();
    assert!(splinelab::AngularSpline::closed(&c.points).is_ok());
    assert_eq!(
        c.within_tolerance,
        c.measure.distances.hausdorff() <= target.tolerance()
    );
    let cubic = fewest_points(&target, Family::Cubic, &SearchOptions::default()).unwrap();
    assert!(cubic.within_tolerance, "{:?}", cubic.measure);
}

/// Issue 23, class 7: a `max_points` below the family's fewest is a typed error; the earlier
/// code searched the family's minimum anyway, trying more points than allowed.
#[test]
fn a_point_budget_below_the_family_minimum_is_refused() {
    let target = Target::shape(&Shape::Ellipse { ratio: 0.7 }, 256).unwrap();
    for (family, fewest) in [
        (Family::Angular, 6),
        (Family::Cardinal, 6),
        (Family::Cubic, 4),
        (Family::BSpline, 4),
    ] {
        for max_points in [0, 1, fewest - 1] {
            let options = SearchOptions {
                max_points,
                budget_per_coordinate: 2,
                ..SearchOptions::default()
            };
            let r = fewest_points(&target, family, &options);
            assert!(
                matches!(r, Err(Error::TooFewPoints { needed, got, .. }) if needed == fewest && got == max_points),
                "{family:?} with {max_points}: {:?}",
                r.map(|c| c.measure.counted)
            );
        }
        // at the minimum the search runs and stays within it
        let options = SearchOptions {
            max_points: fewest,
            budget_per_coordinate: 2,
            ..SearchOptions::default()
        };
        let c = fewest_points(&target, family, &options).unwrap();
        assert!(
            c.measure.counted <= fewest,
            "{family:?}: {}",
            c.measure.counted
        );
    }
}

/// Issue 25: the automatic counts of the search before its global stage (commit 5ebd42e),
/// row by row as `TABLE_I`; the Angular rectangle had none within 1 % (41 = beyond the
/// search's 40). The global search may only do better.
const COUNTS_BEFORE_ISSUE_25: [usize; 36] = [
    6, 7, 7, 5, 5, 5, 5, 8, 41, // Angular
    6, 6, 6, 6, 6, 5, 5, 6, 7, // cardinal
    6, 6, 5, 5, 4, 3, 3, 4, 15, // cubic
    5, 5, 5, 3, 3, 4, 3, 4, 5, // B-spline
];

#[test]
fn no_count_is_worse_than_before_the_global_search_and_the_evidence_holds() {
    let cells = cells();
    for (index, (study, &before)) in cells.iter().zip(&COUNTS_BEFORE_ISSUE_25).enumerate() {
        let auto = &study.automatic;
        assert!(auto.within_tolerance, "cell {index}");
        assert!(
            auto.measure.counted <= before,
            "cell {index}: {} > {before}",
            auto.measure.counted
        );
        // every count below the answer was searched with the full budget and failed
        // (B-splines: fitted with every order), unless the answer is the method's minimum
        let below: Vec<usize> = study.attempts.iter().map(|a| a.counted).collect();
        for a in &study.attempts {
            if a.counted < auto.measure.counted {
                assert!(!a.within_tolerance, "cell {index}: {a:?}");
                assert!(a.starts > 0, "cell {index}: {a:?}");
                if let Some(e) = a.best_error {
                    assert!(e > study.tolerance, "cell {index}: {a:?}");
                }
            }
        }
        match study.minimality {
            Minimality::MethodMinimum => assert!(study.below().is_none(), "cell {index}"),
            Minimality::LowerBound { bound, .. } => {
                assert!(bound > study.tolerance, "cell {index}");
                // the search's own best with one fewer never beats the bound
                let e = study.below().and_then(|b| b.best_error).unwrap();
                assert!(e >= bound, "cell {index}: {e} < bound {bound}");
            }
            Minimality::Searched => {
                let lowest = *below.first().unwrap();
                for n in lowest..auto.measure.counted {
                    assert!(below.contains(&n), "cell {index}: {n} not searched");
                }
                assert!(study.below().is_some(), "cell {index}");
            }
            other => panic!("cell {index}: {other:?}"),
        }
    }
}

/// Issue 25: a cardinal spline with `a = ½` and points at equal steps of the parameter
/// reproduces every quadratic, so the parabola needs 4 points as the paper counts them (its
/// ends and two guides one parameter step beyond): the earlier search, with guides on the
/// shape just beyond the ends, found 6.
#[test]
fn the_cardinal_spline_draws_the_parabola_from_four_points() {
    for half_width in [1.0, 2.0] {
        let shape = Shape::Parabola { half_width };
        let target = Target::shape(&shape, REFERENCE_SEGMENTS).unwrap();
        let found = search(&target, Family::Cardinal, &SearchOptions::default()).unwrap();
        let c = &found.choice;
        assert_eq!(c.measure.counted, 4, "half width {half_width}");
        assert!(c.within_tolerance);
        assert_eq!(found.minimality, Minimality::MethodMinimum);
        // exact up to the reference's own chords: far below the tolerance, checked
        // independently on another reference
        let brute = brute_error(&shape, &c.method, &c.points);
        assert!(brute <= 1e-2 * target.tolerance(), "{brute}");
        assert_eq!(c.method, Method::Cardinal { a: 0.5 });
        // the closed form: the guides are the parabola at ∓3 X
        let x = half_width;
        let g = [V::new(-3.0 * x, 9.0 * x * x), V::new(3.0 * x, 9.0 * x * x)];
        assert!((c.points[0] - g[0]).norm() <= 1e-9 * x && (c.points[3] - g[1]).norm() <= 1e-9 * x);
    }
}

/// The bound behind the closed Angular cells: a closed Angular spline through 3 points is
/// their circumcircle, so its error on an ellipse is at least a quarter of the difference of
/// the ellipse's widths.
#[test]
fn a_closed_angular_spline_through_three_points_is_their_circumcircle() {
    let mut state = 12345u64;
    let mut unit = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..200 {
        let p: Vec<V> = (0..3)
            .map(|_| V::new(4.0 * unit() - 2.0, 4.0 * unit() - 2.0))
            .collect();
        let Ok(curve) = Method::Angular.curve(&p, true) else {
            continue;
        };
        // the circumcentre, by its closed form
        let (a, b, c) = (p[0], p[1], p[2]);
        let d = 2.0 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
        if d.abs() < 1e-3 {
            continue;
        }
        let sq = |v: V| v.norm_squared();
        let centre = V::new(
            (sq(a) * (b.y - c.y) + sq(b) * (c.y - a.y) + sq(c) * (a.y - b.y)) / d,
            (sq(a) * (c.x - b.x) + sq(b) * (a.x - c.x) + sq(c) * (b.x - a.x)) / d,
        );
        let r = (a - centre).norm();
        let line = sample_pieces(&curve, &curve.breaks(), 64).unwrap();
        for q in line {
            assert!(
                ((q - centre).norm() - r).abs() <= 1e-9 * r.max(1.0),
                "{p:?}"
            );
        }
    }
    // the bound, against brute-force widths over many directions
    let ellipse = Shape::Ellipse { ratio: 0.7 }.reference(2048).unwrap();
    let (least, diameter) = splinelab::interp::choice::bound::widths(&ellipse);
    let width = |t: f64| {
        let u = V::new(t.cos(), t.sin());
        let (lo, hi) = ellipse
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.dot(&u)), hi.max(p.dot(&u)))
            });
        hi - lo
    };
    let brute: Vec<f64> = (0..3600)
        .map(|k| width(std::f64::consts::PI * k as f64 / 3600.0))
        .collect();
    let brute_min = brute.iter().copied().fold(f64::INFINITY, f64::min);
    let brute_max = brute.iter().copied().fold(0.0, f64::max);
    assert!(
        least <= brute_min + 1e-12 && least >= brute_min - 1e-6,
        "{least} {brute_min}"
    );
    assert!(diameter >= brute_max - 1e-12 && diameter <= brute_max + 1e-6);
    assert!((least - 1.4).abs() < 1e-5 && (diameter - 2.0).abs() < 1e-12);
}

/// Issue 25: a closed shape whose fewest points only a symmetric placement reaches — the
/// superellipse `|x|⁴ + |y/0.6|⁴ = 1`, its reference starting off both axes. The cardinal
/// spline draws it with 4 points + 3 repeats placed symmetrically about an axis (searched in
/// the mirror's own variables); from the plain starts the search finds 8, the earlier search
/// 9.
#[test]
fn a_symmetric_start_reaches_the_superellipse_minimum() {
    let n = 2048;
    let poly: Vec<V> = (0..n)
        .map(|i| {
            let t = 0.3 + std::f64::consts::TAU * i as f64 / n as f64;
            let (c, s) = (t.cos(), t.sin());
            V::new(
                c.signum() * c.abs().sqrt(),
                0.6 * s.signum() * s.abs().sqrt(),
            )
        })
        .collect();
    let target = Target::polyline(&poly, true, 0.02).unwrap();
    let found = search(&target, Family::Cardinal, &SearchOptions::default()).unwrap();
    let c = &found.choice;
    assert!(c.within_tolerance);
    assert_eq!(c.measure.counted, 7, "{:?}", found.attempts);
    assert_eq!(c.start, splinelab::interp::choice::Start::Symmetric);
    // the two axes were found, and the points are symmetric about one of them
    assert_eq!(
        splinelab::interp::choice::symmetry::mirrors(&target).len(),
        2
    );
    let mirrored = splinelab::interp::choice::symmetry::mirrors(&target)
        .iter()
        .any(|m| {
            c.points.iter().all(|p| {
                let q = m.isometry.apply(*p);
                c.points.iter().any(|r| (q - r).norm() <= 1e-6)
            })
        });
    assert!(mirrored, "{:?}", c.points);
    // and it meets the tolerance by an independent measure
    let curve = c.method.curve(&c.points, true).unwrap();
    let line = sample_pieces(&curve, &curve.breaks(), FINAL_SAMPLES).unwrap();
    assert!(hausdorff(&line, &poly) <= 0.02 * 1.001);
}

/// `splinelab fewest` on the paper's shapes (issue 29): each shape given as an outline — its
/// reference polyline, as a user's file would give it, searched through `Target::polyline`
/// rather than the exact shape and without the paper's rule as a known configuration — gets
/// Table I's automatic counts, every cell.
#[cfg(feature = "report")]
#[test]
fn fewest_on_the_paper_shapes_as_outlines_gives_table_i_counts() {
    use splinelab::seeds::seed004::SHAPES;
    use splinelab::study::outline::{fewest, Tolerance};
    use splinelab::study::table_i::{shape_outline, table_i_options};
    let cells = cells();
    let families = [
        Family::Angular,
        Family::Cardinal,
        Family::Cubic,
        Family::BSpline,
    ];
    for (column, shape) in SHAPES {
        let outline = shape_outline(column).unwrap();
        let found = fewest(
            &[outline],
            Tolerance::default(),
            &families,
            &table_i_options(),
            &|_| {},
        )
        .unwrap();
        assert!((found.tolerance - shape.tolerance()).abs() <= 1e-12 * shape.tolerance());
        for m in &found.methods {
            let cell = cells
                .iter()
                .find(|c| c.column == column && Family::of(&c.automatic.method) == Some(m.family))
                .unwrap();
            assert_eq!(
                m.counted(),
                cell.automatic.measure.counted,
                "{column} {:?}",
                m.family
            );
            assert!(m.within_tolerance(), "{column} {:?}", m.family);
        }
    }
}
