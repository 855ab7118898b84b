//! Seed 003: de Casteljau (recursive as printed, iterative, Bernstein), the blending
//! functions, the printed `bspline` and OpenGL procedures, the sliding bicubic surface.

mod common;

use common::{Rng, EXACT};
use nalgebra::{Vector2, Vector3};
use proptest::prelude::*;
use splinelab::blending::opengl::{opengl_groups, opengl_polyline, LastGroup};
use splinelab::blending::surface::SlidingBicubic;
use splinelab::blending::window::{printed_bspline_polyline, WindowCurve};
use splinelab::seeds::seed003 as data;
use splinelab::{
    bernstein_sum, de_casteljau, de_casteljau_levels, de_casteljau_recursive, lagrange4,
    printed_setbval, uniform_bspline4, BSplineBasis, BSplineCurve, Blending, Grid, KnotVector,
    ParametricCurve,
};

#[test]
fn de_casteljau_recursive_iterative_and_bernstein_agree_at_the_printed_parameters() {
    let pts = data::CASTELJAU_POINTS.map(|(x, y)| Vector2::new(x, y));
    for &u in &data::CASTELJAU_U {
        let rec = de_casteljau_recursive(&pts, u).expect("points");
        let it = de_casteljau(&pts, u).expect("points");
        let bern = bernstein_sum(&pts, u).expect("points");
        assert!(
            (rec - it).amax() <= EXACT && (rec - bern).amax() <= EXACT,
            "u = {u}"
        );
        // the levels end in the curve point; level k has n − k points
        let levels = de_casteljau_levels(&pts, u).expect("points");
        assert_eq!(
            levels.iter().map(Vec::len).collect::<Vec<_>>(),
            vec![4, 3, 2, 1]
        );
        assert!((levels[3][0] - rec).amax() <= EXACT);
    }
}

#[test]
fn lagrange_blending_is_cardinal_and_sums_to_one() {
    for (node, u) in [-1.0_f64, 0.0, 1.0, 2.0].into_iter().enumerate() {
        let b = lagrange4(u);
        for (i, &v) in b.iter().enumerate() {
            let want = if i == node { 1.0 } else { 0.0 };
            assert!((v - want).abs() <= EXACT, "B{}({u}) = {v}", i + 1);
        }
    }
    for k in 0..=60 {
        let u = -1.0 + 0.05 * k as f64;
        assert!(
            (lagrange4(u).iter().sum::<f64>() - 1.0).abs() <= EXACT,
            "Σ B(u) at {u}"
        );
    }
}

#[test]
fn printed_setbval_is_the_uniform_cubic_bspline_and_cox_de_boor_agrees() {
    for nb in [3, 4, 6, 10] {
        for (j, b) in printed_setbval(nb).expect("small nb").iter().enumerate() {
            let f = uniform_bspline4(j as f64 / nb as f64);
            for i in 0..4 {
                assert!((b[i] - f[i]).abs() <= EXACT, "nb = {nb}, j = {j}, b{i}");
            }
        }
    }
    let integer = BSplineBasis::new(KnotVector::new((0..8).map(f64::from).collect()), 3);
    for k in 0..=50 {
        let u = k as f64 / 50.0;
        let b = uniform_bspline4(u);
        for (i, bi) in b.iter().enumerate() {
            let n = integer.cox_de_boor(i, 3, 3.0 + u);
            // N_{i,3} on [3, 4) is piece 3 − i of its support [i, i + 4): b_i
            assert!((n - bi).abs() <= EXACT, "u = {u}: b{i} vs N{i},3");
        }
    }
}

#[test]
fn printed_bspline_is_a_uniform_bspline_on_the_padded_points() {
    let pts = data::four_way_points(7);
    let w = WindowCurve::printed_bspline(&pts).expect("points");
    let q = w.window_points().to_vec();
    assert_eq!(q.len(), pts.len() + 5, "first point ×3, last ×4");
    let knots: Vec<f64> = (0..q.len() + 4).map(|k| k as f64).collect();
    let b = BSplineCurve::new(BSplineBasis::new(KnotVector::new(knots), 3), q);
    let (_, end) = w.domain();
    for k in 0..=400 {
        let s = end * k as f64 / 400.0;
        assert!((w.eval(s) - b.point(3.0 + s)).amax() <= 1e-12, "s = {s}");
    }
    // the padding makes it start at P₀ and end at the last point
    assert!((w.eval(0.0) - pts[0]).amax() <= EXACT);
    assert!((w.eval(end) - pts[6]).amax() <= EXACT);
}

#[test]
fn printed_polyline_starts_at_p0_and_stops_just_short_of_the_end() {
    let pts = data::four_way_points(6);
    let nb = 6;
    let line = printed_bspline_polyline(&pts, nb).expect("points");
    assert_eq!(line.len(), 1 + (pts.len() + 1) * nb);
    assert_eq!(line[0], pts[0]);
    // the last vertex is u = 5/6 of the last segment (P₄, P₅, P₅, P₅): b₀(5/6)(P₄ − P₅) away
    let gap = (line[line.len() - 1] - pts[5]).norm();
    let predicted = (pts[4] - pts[5]).norm() / (6.0 * (nb as f64).powi(3));
    assert!(
        (gap - predicted).abs() <= EXACT,
        "gap {gap:e} vs {predicted:e}"
    );
}

#[test]
fn lagrange_window_passes_through_every_point() {
    let pts = data::four_way_points(7);
    let w = WindowCurve::lagrange(&pts).expect("points");
    assert_eq!(w.segments(), 6);
    for (k, p) in pts.iter().enumerate() {
        assert!((w.eval(k as f64) - p).amax() <= 1e-12, "P{k}");
    }
}

#[test]
fn opengl_groups_as_intended_and_as_printed() {
    let pts = data::four_way_points(9);
    let idx = |g: &Vec<Vector2<f64>>| -> Vec<usize> {
        g.iter()
            .map(|p| pts.iter().position(|q| q == p).expect("a data point"))
            .collect()
    };
    let seven = &pts[..7];
    let t = opengl_groups(seven, 5, LastGroup::Truncated).expect("points");
    assert_eq!(
        t.iter().map(&idx).collect::<Vec<_>>(),
        vec![vec![0, 1, 2, 3, 4], vec![4, 5, 6]]
    );
    let p = opengl_groups(seven, 5, LastGroup::AsPrinted).expect("points");
    assert_eq!(p[1].len(), 5);
    assert_eq!(
        idx(&p[1]),
        vec![4, 5, 6, 3, 4],
        "stale entries 3, 4 of the previous group"
    );
    // 9 points fit two groups exactly, but the loop runs once more with one fresh point
    let nine = opengl_groups(&pts, 5, LastGroup::AsPrinted).expect("points");
    assert_eq!(
        nine.iter().map(&idx).collect::<Vec<_>>(),
        vec![
            vec![0, 1, 2, 3, 4],
            vec![4, 5, 6, 7, 8],
            vec![8, 5, 6, 7, 8],
        ]
    );
    // each group's Bézier curve starts and ends at its end control points
    let line = opengl_polyline(seven, 5, 10, LastGroup::Truncated).expect("points");
    assert_eq!(line.len(), 22);
    assert!((line[0] - pts[0]).amax() <= EXACT && (line[10] - pts[4]).amax() <= EXACT);
    assert!((line[11] - pts[4]).amax() <= EXACT && (line[21] - pts[6]).amax() <= EXACT);
}

fn wave_grid(rows: usize, cols: usize) -> Grid<Vector3<f64>> {
    Grid::from_fn(rows, cols, |i, j| {
        let (x, y) = (i as f64, 0.8 * j as f64);
        Vector3::new(x, y, (0.7 * x).sin() * (0.5 * y).cos())
    })
}

#[test]
fn sliding_lagrange_surface_interpolates_the_grid_at_cell_corners() {
    let grid = wave_grid(6, 7);
    let s = SlidingBicubic::try_new(&grid, Blending::Lagrange).expect("grid");
    assert_eq!(s.cells(), (3, 4));
    for i in 0..3 {
        for j in 0..4 {
            for (a, b) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                let p = s.eval((i, j), a as f64, b as f64);
                let want = grid.get(i + 1 + a, j + 1 + b);
                assert!(
                    (p - want).amax() <= 1e-12,
                    "cell ({i},{j}) corner ({a},{b})"
                );
            }
        }
    }
}

#[test]
fn sliding_bspline_surface_is_c1_across_cells() {
    let grid = wave_grid(6, 6);
    let s = SlidingBicubic::try_new(&grid, Blending::UniformBSpline).expect("grid");
    let du = |cell, u: f64, v: f64| {
        s.eval(
            cell,
            num_dual::Dual64::from_re(u).derivative(),
            num_dual::Dual64::from_re(v),
        )
        .map(|d| d.eps)
    };
    for k in 0..=10 {
        let v = k as f64 / 10.0;
        // the edge u = 1 of cell (0, 0) is the edge u = 0 of cell (1, 0)
        assert!(
            (s.eval((0, 0), 1.0, v) - s.eval((1, 0), 0.0, v)).amax() <= EXACT,
            "C⁰ at v = {v}"
        );
        assert!(
            (du((0, 0), 1.0, v) - du((1, 0), 0.0, v)).amax() <= 1e-12,
            "C¹ at v = {v}"
        );
    }
    let tab = s.tabulate_cell((1, 1), 5).expect("cell");
    assert!((tab.get(2, 3) - s.eval((1, 1), 0.5, 0.75)).amax() <= EXACT);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn recursive_de_casteljau_equals_the_bernstein_sum(seed in 0u64..10_000, n in 2usize..10, u in 0.0f64..=1.0) {
        let mut rng = Rng::new(seed);
        let pts: Vec<Vector3<f64>> = (0..n).map(|_| Vector3::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))).collect();
        let a = de_casteljau_recursive(&pts, u).expect("points");
        let b = bernstein_sum(&pts, u).expect("points");
        prop_assert!((a - b).amax() <= EXACT, "{:?} vs {:?}", a, b);
    }
}
