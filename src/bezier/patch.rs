//! The bicubic Bézier patch `X(s, t) = B(s)ᵀ M B(t)` and its construction from Hermite form
//! (seed 000 §4, Codice 7–12).

use crate::bezier::bernstein::bernstein3;
use crate::bezier::de_casteljau::reduce;
use crate::error::{samples, Result};
use crate::grid::Grid;
use crate::hermite::patch::{local_basis_samples, HermitePatch};
use crate::surface::ParametricSurface;
use crate::tensor::{tabulate_pieces, tensor_eval, Net};
use nalgebra::{Matrix4, Vector3};
use num_dual::DualNum;

/// A bicubic Bézier patch on `(s, t) ∈ [0, 1]²` with control net `M` (`m[i][j]`, rows ↔ s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BezierPatch {
    m: Net,
}

/// Hermite data of a cubic, `(P(0), P′(0), P′(1), P(1))`, to its Bézier control points:
/// `b₀ = P(0)`, `b₁ = P(0) + P′(0)/3`, `b₂ = P(1) − P′(1)/3`, `b₃ = P(1)`,
/// since a cubic Bézier curve has `P′(0) = 3(b₁ − b₀)` and `P′(1) = 3(b₃ − b₂)`.
fn hermite_to_bezier_1d(h: [Vector3<f64>; 4]) -> [Vector3<f64>; 4] {
    [h[0], h[0] + h[1] / 3.0, h[3] - h[2] / 3.0, h[3]]
}

impl BezierPatch {
    /// A patch from its control net (`m[i][j]`: row `i` ↔ s).
    ///
    /// # Panics
    /// On an invalid net; see [`BezierPatch::try_from_net`].
    pub fn from_net(m: Net) -> Self {
        Self::try_from_net(m).expect("invalid Bézier net")
    }

    /// A patch from its control net, checked.
    ///
    /// # Errors
    /// [`crate::error::Error::NonFinite`] for a NaN or infinite coordinate,
    /// [`crate::error::Error::CoordinateTooLarge`] beyond [`crate::tensor::NET_LIMIT`].
    pub fn try_from_net(m: Net) -> Result<Self> {
        crate::tensor::check_net("Bézier control point", &m, crate::tensor::NET_LIMIT)?;
        Ok(Self { m })
    }

    /// The Bézier form of a Hermite patch (seed 000 §4, Codice 7–8, corrected).
    ///
    /// With `A` the 1-D map of `hermite_to_bezier_1d` (`b = A h`), the net is `M = A C Aᵀ`:
    /// `A` is applied to every column of `C` (the s direction) and then to every row (t).
    /// Written out, with `C` 1-based as in the report:
    ///
    /// | entry | value |
    /// |---|---|
    /// | M(1,1), M(1,4), M(4,1), M(4,4) | C(1,1), C(1,4), C(4,1), C(4,4) |
    /// | M(1,2) | C(1,1) + C(1,2)/3 |
    /// | M(2,1) | C(1,1) + C(2,1)/3 |
    /// | M(2,2) | C(1,1) + C(1,2)/3 + C(2,1)/3 + C(2,2)/9 |
    /// | M(3,1) | C(4,1) − C(3,1)/3 |
    /// | M(4,2) | C(4,1) + C(4,2)/3 |
    /// | M(3,2) | C(4,1) + C(4,2)/3 − C(3,1)/3 **− C(3,2)/9** |
    /// | M(1,3) | C(1,4) − C(1,3)/3 |
    /// | M(2,4) | C(1,4) + C(2,4)/3 |
    /// | M(2,3) | C(1,4) + C(2,4)/3 − C(1,3)/3 − C(2,3)/9 |
    /// | M(3,4) | C(4,4) − C(3,4)/3 |
    /// | M(4,3) | C(4,4) − C(4,3)/3 |
    /// | M(3,3) | C(4,4) − C(4,3)/3 − C(3,4)/3 + C(3,3)/9 |
    ///
    /// The report's Codice 7 prints `+ C(3,2)/9` in M(3,2); see [`crate::report_codice7_net`].
    pub fn from_hermite(h: &HermitePatch) -> Self {
        let c = h.matrix();
        // columns: convert along s for each t index j
        let mut m = [[Vector3::zeros(); 4]; 4];
        for j in 0..4 {
            let col = hermite_to_bezier_1d([c[0][j], c[1][j], c[2][j], c[3][j]]);
            for i in 0..4 {
                m[i][j] = col[i];
            }
        }
        // rows: convert along t
        for row in m.iter_mut() {
            *row = hermite_to_bezier_1d(*row);
        }
        Self { m }
    }

    /// The control net `M`.
    pub fn net(&self) -> &Net {
        &self.m
    }

    /// The report's three planes `M(:, :, 1..3)` as 4×4 matrices.
    pub fn planes(&self) -> [Matrix4<f64>; 3] {
        std::array::from_fn(|k| Matrix4::from_fn(|i, j| self.m[i][j][k]))
    }

    /// `X(s, t) = B(s)ᵀ M B(t)`, the Bernstein (matrix) form of Codice 9.
    pub fn eval_bernstein<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        tensor_eval(&bernstein3(s), &bernstein3(t), &self.m)
    }

    /// `X(s, t)` by bivariate de Casteljau exactly as Codice 11: every row of the net is
    /// reduced in `t`, then the four resulting points in `s`.
    pub fn eval_de_casteljau<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        let mut q: [Vector3<D>; 4] = std::array::from_fn(|i| {
            let mut row: [Vector3<D>; 4] = std::array::from_fn(|j| self.m[i][j].map(D::from));
            reduce(&mut row, t)
        });
        reduce(&mut q, s)
    }

    /// Tabulates on `linspace(0,1,ns) × linspace(0,1,nt)` by de Casteljau (the report's
    /// `plotDeCasteljau`, whose listing is not printed): for each `sᵢ` the four columns of
    /// the net are reduced in `s` once, then that cubic in `t` is reduced at every `tⱼ`.
    /// By the tensor-product structure this equals Codice 11 at every sample.
    ///
    /// # Errors
    /// [`crate::error::Error::TooFewSamples`] if `ns < 2` or `nt < 2`; [`crate::error::Error::TooLarge`] if
    /// `ns · nt` exceeds [`crate::error::MAX_ELEMENTS`].
    pub fn tabulate_de_casteljau(&self, ns: usize, nt: usize) -> Result<Grid<Vector3<f64>>> {
        crate::error::size_product("patch samples ns × nt", ns, nt)?;
        let s = crate::domain::linspace(0.0, 1.0, samples("ns", ns)?);
        let t = crate::domain::linspace(0.0, 1.0, samples("nt", nt)?);
        let mut out = Vec::with_capacity(ns * nt);
        for &si in &s {
            let curve: [Vector3<f64>; 4] = std::array::from_fn(|j| {
                let mut col = [self.m[0][j], self.m[1][j], self.m[2][j], self.m[3][j]];
                reduce(&mut col, si)
            });
            out.extend(t.iter().map(|&tj| reduce(&mut curve.clone(), tj)));
        }
        Ok(Grid::from_vec(ns, nt, out).expect("filled ns × nt"))
    }

    /// Tabulates by the Bernstein matrix form, basis rows computed once per grid line.
    ///
    /// # Errors
    /// [`crate::error::Error::TooFewSamples`] if `ns < 2` or `nt < 2`; [`crate::error::Error::TooLarge`] if
    /// `ns · nt` exceeds [`crate::error::MAX_ELEMENTS`].
    pub fn tabulate_bernstein(&self, ns: usize, nt: usize) -> Result<Grid<Vector3<f64>>> {
        crate::error::size_product("patch samples ns × nt", ns, nt)?;
        let rows = local_basis_samples(samples("ns", ns)?, bernstein3);
        let cols = local_basis_samples(samples("nt", nt)?, bernstein3);
        let mut out = Vec::new();
        tabulate_pieces(
            std::slice::from_ref(&self.m),
            1,
            &rows,
            &cols,
            &mut out,
            true,
        );
        Ok(Grid::from_vec(ns, nt, out).expect("filled ns × nt"))
    }
}

impl ParametricSurface for BezierPatch {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        self.eval_bernstein(s, t)
    }
}

impl From<&HermitePatch> for BezierPatch {
    fn from(h: &HermitePatch) -> Self {
        Self::from_hermite(h)
    }
}
