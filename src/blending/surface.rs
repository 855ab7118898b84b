//! The bicubic surface of seed 003: a 4×4 window of grid points sliding over a larger grid,
//! each position drawing the central cell with tensor-product blending functions.

use crate::blending::functions::Blending;
use crate::error::{samples, Error, Result};
use crate::grid::Grid;
use crate::tensor::{tabulate_pieces, tensor_eval, BasisSample, Net};
use nalgebra::Vector3;
use num_dual::DualNum;

/// A surface over a `rows × cols` grid of points `P_{i,j}` (seed 003: "il reticolo 4×4 si
/// sposta lungo il reticolo dato … interessa ad ogni passo solo la parte centrale"): for every
/// interior cell `(i, j)`, `1 ≤ i ≤ rows − 3`, `1 ≤ j ≤ cols − 3`, the patch
///
/// `P(u, v) = Σ_{a,b} P_{i−1+a, j−1+b} B_a(u) B_b(v)`, `u, v ∈ [0, 1]`,
///
/// with the cubic [`Blending`] functions in both directions. With [`Blending::Lagrange`] it
/// interpolates the grid points at the cell corners; with [`Blending::UniformBSpline`] it
/// approximates them and is C² across cells.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingBicubic {
    nets: Vec<Net>,
    cells: (usize, usize),
    blending: Blending,
}

impl SlidingBicubic {
    /// The surface of `points` (row `i`, column `j`).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] unless the grid is at least 4 × 4; [`Error::NonFinite`].
    pub fn try_new(points: &Grid<Vector3<f64>>, blending: Blending) -> Result<Self> {
        let (rows, cols) = (points.rows(), points.cols());
        if rows < 4 || cols < 4 {
            return Err(Error::TooFewPoints {
                what: "grid rows and columns of the sliding bicubic surface",
                needed: 4,
                got: rows.min(cols),
            });
        }
        crate::error::finite_points("grid point coordinate", points.as_slice())?;
        let cells = (rows - 3, cols - 3);
        let mut nets = Vec::with_capacity(cells.0 * cells.1);
        for i in 0..cells.0 {
            for j in 0..cells.1 {
                nets.push(std::array::from_fn(|a| {
                    std::array::from_fn(|b| *points.get(i + a, j + b))
                }));
            }
        }
        Ok(Self {
            nets,
            cells,
            blending,
        })
    }

    /// Number of cells (patches) `(rows − 3, cols − 3)`.
    pub fn cells(&self) -> (usize, usize) {
        self.cells
    }

    /// `P(u, v)` on cell `(i, j)` for any number type.
    ///
    /// # Panics
    /// If the cell index is out of range.
    pub fn eval<D: DualNum<Primitive = f64> + Copy>(
        &self,
        cell: (usize, usize),
        u: D,
        v: D,
    ) -> Vector3<D> {
        assert!(
            cell.0 < self.cells.0 && cell.1 < self.cells.1,
            "cell out of range"
        );
        let net = &self.nets[cell.0 * self.cells.1 + cell.1];
        tensor_eval(&self.blending.weights(u), &self.blending.weights(v), net)
    }

    /// Cell `(i, j)` tabulated on `n × n` samples of `[0, 1]²` (basis rows computed once).
    ///
    /// # Errors
    /// [`Error::TooFewSamples`] below 2; [`Error::TooLarge`] if `n²` exceeds
    /// [`crate::error::MAX_ELEMENTS`]; [`Error::IndexOutOfRange`] for a bad cell.
    pub fn tabulate_cell(&self, cell: (usize, usize), n: usize) -> Result<Grid<Vector3<f64>>> {
        if cell.0 >= self.cells.0 || cell.1 >= self.cells.1 {
            return Err(Error::IndexOutOfRange {
                what: "sliding bicubic cell",
                index: cell.0.saturating_mul(self.cells.1).saturating_add(cell.1),
                len: self.nets.len(),
            });
        }
        crate::error::size_product("cell samples n × n", n, n)?;
        let rows: Vec<BasisSample> = crate::domain::linspace(0.0, 1.0, samples("cell samples", n)?)
            .into_iter()
            .map(|u| BasisSample {
                piece: 0,
                w: self.blending.weights(u),
            })
            .collect();
        let mut out = Vec::new();
        let net = self.nets[cell.0 * self.cells.1 + cell.1];
        tabulate_pieces(&[net], 1, &rows, &rows, &mut out, true);
        Ok(Grid::from_vec(n, n, out).expect("tabulate_pieces fills n × n"))
    }
}
