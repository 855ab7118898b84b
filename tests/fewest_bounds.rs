//! The fewest points on random outlines: no family worse than a family it contains (the
//! B-spline family contains the polygon, the cardinal family the polygon with two points
//! more), and a thorough search never worse than the default one it starts from.

use nalgebra::Vector2;
use proptest::prelude::*;
use splinelab::interp::choice::{search, Family, Minimality, SearchOptions, Target};

/// A wobbly ring (closed) or arc (open) of `radii.len()` vertices.
fn outline(radii: &[f64], closed: bool) -> Vec<Vector2<f64>> {
    let n = radii.len();
    radii
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let t = k as f64 / n as f64 * if closed { std::f64::consts::TAU } else { 3.0 };
            Vector2::new(r * t.cos(), r * t.sin())
        })
        .collect()
}

/// `splinelab fewest`'s options by default, up to 40 points.
fn options() -> SearchOptions {
    SearchOptions {
        max_points: 40,
        budget_per_coordinate: 10,
        every_count_below: false,
        ..SearchOptions::default()
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// The B-spline count is never above the polygon's, the cardinal count never above the
    /// polygon's + 2, and neither is "none within" where the polygon meets the tolerance.
    #[test]
    fn families_containing_the_polygon_are_never_worse(
        radii in prop::collection::vec(0.7..1.3f64, 12..40),
        closed in any::<bool>(),
        tolerance in 0.02..0.1f64,
    ) {
        let target = Target::polyline(&outline(&radii, closed), closed, tolerance).unwrap();
        let polygon = search(&target, Family::Linear, &options()).unwrap();
        prop_assert!(polygon.choice.within_tolerance);
        let optimum = matches!(polygon.minimality, Minimality::Optimum { .. });
        prop_assert!(optimum, "{:?}", polygon.minimality);
        let linear = polygon.choice.measure.counted;
        let bspline = search(&target, Family::BSpline, &options()).unwrap();
        prop_assert!(bspline.choice.within_tolerance);
        prop_assert!(bspline.choice.measure.counted <= linear,
            "bspline {} against the polygon's {}", bspline.choice.measure.counted, linear);
        let cardinal = search(&target, Family::Cardinal, &options()).unwrap();
        prop_assert!(cardinal.choice.within_tolerance);
        prop_assert!(cardinal.choice.measure.counted <= linear + 2,
            "cardinal {} against the polygon's {} + 2", cardinal.choice.measure.counted, linear);
    }
}

mod thorough {
    use super::*;
    use splinelab::input::Contour;
    use splinelab::study::outline::{
        default_options, fewest, fewest_in_stages, MethodStudy, Tolerance,
    };
    use splinelab::study::table_i::thorough_options;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4))]

        /// `--thorough` (the default search, then Table I's from its answer) is never worse than
        /// the default search, method by method.
        #[test]
        fn thorough_is_never_worse_than_the_default(
            radii in prop::collection::vec(0.8..1.2f64, 12..24),
            closed in any::<bool>(),
        ) {
            let contour = Contour { points: outline(&radii, closed), closed };
            let outline = [contour];
            let families = [Family::Cardinal, Family::Cubic, Family::BSpline, Family::Linear];
            let first = SearchOptions { max_points: 24, ..default_options() };
            let then = SearchOptions { max_points: 24, ..thorough_options(&first) };
            let tolerance = Tolerance::Fraction(0.03);
            let quick = fewest(&outline, tolerance, &families, &first, &|_| {}).unwrap();
            let thorough =
                fewest_in_stages(&outline, tolerance, &families, &[first, then], &|_| {}).unwrap();
            for (q, t) in quick.methods.iter().zip(&thorough.methods) {
                let rank = |m: &MethodStudy| {
                    (!m.within_tolerance(), m.counted())
                };
                prop_assert!(rank(t) <= rank(q), "{:?}: {:?} against {:?}", q.family, rank(t), rank(q));
            }
        }
    }
}
