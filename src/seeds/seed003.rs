//! The worked examples of seed 003, the lecture notes on curves (control points, parameters,
//! the grid of the bicubic surface). The notes' figures are lost, so the points are ours.

use nalgebra::Vector2;

/// The four control points of the de Casteljau figure.
pub const CASTELJAU_POINTS: [(f64, f64); 4] = [(0.0, 0.0), (1.0, 3.0), (4.0, 3.0), (5.0, 0.0)];
/// The parameters of seed 003's de Casteljau figures.
pub const CASTELJAU_U: [f64; 3] = [0.3, 0.5, 0.7];

/// Control points for the four-way comparison of seed 003 (6 or 7 points; any other count
/// repeats the pattern).
pub fn four_way_points(count: usize) -> Vec<Vector2<f64>> {
    const PATTERN: [(f64, f64); 7] = [
        (0.0, 0.0),
        (1.0, 2.5),
        (3.0, 3.2),
        (4.0, 0.6),
        (6.0, 0.2),
        (7.0, 2.8),
        (9.0, 2.2),
    ];
    (0..count)
        .map(|i| {
            let (x, y) = PATTERN[i % PATTERN.len()];
            Vector2::new(x + 9.0 * (i / PATTERN.len()) as f64, y)
        })
        .collect()
}

/// The 7×7 grid of seed 003's bicubic surface: `x = i`, `y = j`, `z = f(x, y)` with
/// `f = 1.2 sin(0.9 x) cos(0.7 y)` (the notes' grid `x[i] = x0 + i dx`, `y[j] = y0 + j dy`,
/// `z = f(x, y)`, with an `f` of ours).
pub fn sliding_grid() -> crate::grid::Grid<nalgebra::Vector3<f64>> {
    crate::grid::Grid::from_fn(7, 7, |i, j| {
        let (x, y) = (i as f64, j as f64);
        nalgebra::Vector3::new(x, y, 1.2 * (0.9 * x).sin() * (0.7 * y).cos())
    })
}
