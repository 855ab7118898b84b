//! The bicubic Hermite patch `X(s, t) = H(s)ᵀ C H(t)` of seed 000 §1–2 and §5.

use crate::domain::Rect;
use crate::error::{finite_points, samples, Error, Result};
use crate::grid::Grid;
use crate::hermite::basis::hermite_basis;
use crate::surface::{ParametricSurface, Partials, SurfaceDerivatives};
use crate::tensor::{tabulate_pieces, tensor_eval, BasisSample, Net};
use nalgebra::{Matrix4, Vector3};
use num_dual::DualNum;

/// A bicubic Hermite patch on the local square `(s, t) ∈ [0, 1]²`, held as its Hermite matrix
/// `C` (seed 000 §1, Codice 4), one 3-vector per entry:
///
/// ```text
///     ⎡ X(0,0)   X_t(0,0)   X_t(0,1)   X(0,1)  ⎤
/// C = ⎢ X_s(0,0) X_st(0,0)  X_st(0,1)  X_s(0,1)⎥      rows index s, columns index t
///     ⎢ X_s(1,0) X_st(1,0)  X_st(1,1)  X_s(1,1)⎥
///     ⎣ X(1,0)   X_t(1,0)   X_t(1,1)   X(1,1)  ⎦
/// ```
///
/// [`HermitePatch::planes`] gives the report's three 4×4 planes (x, y, z).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HermitePatch {
    c: Net,
}

/// Row (and column) of the value and of the derivative of corner `k ∈ {0, 1}`:
/// corner 0 uses rows 0 (value) and 1 (derivative), corner 1 rows 3 and 2.
const VALUE: [usize; 2] = [0, 3];
const SLOPE: [usize; 2] = [1, 2];

impl HermitePatch {
    /// A patch from its Hermite matrix `C` (`c[i][j]`: row `i` indexes s, column `j` t).
    ///
    /// # Panics
    /// On an invalid matrix; see [`HermitePatch::try_from_matrix`].
    pub fn from_matrix(c: Net) -> Self {
        Self::try_from_matrix(c).expect("invalid Hermite matrix")
    }

    /// A patch from a matrix already validated (the nets of a [`crate::hermite::spline_surface::HermiteSurface`]).
    pub(crate) fn from_valid_matrix(c: Net) -> Self {
        Self { c }
    }

    /// A patch from its Hermite matrix `C`, checked.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite entry, [`Error::CoordinateTooLarge`] beyond
    /// [`crate::tensor::HERMITE_LIMIT`].
    pub fn try_from_matrix(c: Net) -> Result<Self> {
        crate::tensor::check_net("Hermite matrix entry", &c, crate::tensor::HERMITE_LIMIT)?;
        Ok(Self { c })
    }

    /// The patch interpolating corner data over a rectangle of widths `Δu × Δv`.
    ///
    /// `corners[a][b]` holds `X, X_u, X_v, X_uv` at `(u_a, v_b)`, `a, b ∈ {0, 1}` (0 = start,
    /// 1 = end). In local parameters `s = (u − uₐ)/Δu`, `t = (v − v_a)/Δv` the chain rule
    /// gives `X_s = Δu X_u`, `X_t = Δv X_v`, `X_st = Δu Δv X_uv`, which is the scaling of the
    /// matrix `C⁽ⁱʲ⁾` in seed 000 §5 and Codice 13. (The printed `C⁽ⁱʲ⁾` shows `d⁽⁰¹⁾` in
    /// entries (2,4) and (3,4); Codice 13 uses the s-derivative, as interpolation requires.)
    ///
    /// # Panics
    /// On invalid corner data; see [`HermitePatch::try_from_corners`].
    pub fn from_corners(corners: &[[Partials; 2]; 2], du: f64, dv: f64) -> Self {
        Self::try_from_corners(corners, du, dv).expect("invalid Hermite corner data")
    }

    /// [`HermitePatch::from_corners`], checked: the widths and every entry of the resulting
    /// matrix `C` must be finite, so the patch evaluates finitely on `[0, 1]²`.
    ///
    /// # Errors
    /// [`Error::NotPositive`] unless `du` and `dv` are positive and finite; [`Error::NonFinite`]
    /// for a NaN or infinite corner datum; [`Error::CoordinateTooLarge`] for an entry of `C`
    /// (after the scaling by `Δu`, `Δv`) beyond [`crate::error::MAX_COORDINATE`].
    pub fn try_from_corners(corners: &[[Partials; 2]; 2], du: f64, dv: f64) -> Result<Self> {
        crate::error::positive("patch width Δu", du)?;
        crate::error::positive("patch width Δv", dv)?;
        let mut c = [[Vector3::zeros(); 4]; 4];
        for (a, row) in corners.iter().enumerate() {
            for (b, p) in row.iter().enumerate() {
                finite_points("Hermite corner datum", &[p.point, p.ds, p.dt, p.dst])?;
                c[VALUE[a]][VALUE[b]] = p.point;
                c[VALUE[a]][SLOPE[b]] = p.dt * dv;
                c[SLOPE[a]][VALUE[b]] = p.ds * du;
                // (X_st Δu) Δv: a zero twist stays zero even where Δu Δv overflows
                c[SLOPE[a]][SLOPE[b]] = p.dst * du * dv;
            }
        }
        for x in c.iter().flatten().flat_map(|v| v.iter()) {
            crate::error::derived_coordinate("Hermite matrix entry (scaled corner datum)", *x)?;
        }
        Ok(Self { c })
    }

    /// The patch interpolating `surface` over `rect` (Codice 4 on `[0, 1]²`, Codice 13 on any
    /// rectangle): corner partials are exact (hyper-dual numbers), scaled by `Δu`, `Δv`.
    ///
    /// # Panics
    /// If the surface is not finite at a corner; see [`HermitePatch::try_from_surface`].
    pub fn from_surface<S: SurfaceDerivatives + ?Sized>(surface: &S, rect: &Rect) -> Self {
        Self::try_from_surface(surface, rect).expect("surface not finite at a patch corner")
    }

    /// [`HermitePatch::from_surface`], checked.
    ///
    /// # Errors
    /// [`Error::NonFiniteSurface`] if a point or partial at a corner is NaN or infinite; the
    /// errors of [`HermitePatch::try_from_corners`].
    pub fn try_from_surface<S: SurfaceDerivatives + ?Sized>(
        surface: &S,
        rect: &Rect,
    ) -> Result<Self> {
        let corner = |u, v| -> Result<Partials> {
            let p = surface.partials(u, v);
            if crate::surface::partials_finite(&p) {
                Ok(p)
            } else {
                Err(Error::NonFiniteSurface { s: u, t: v })
            }
        };
        let (ua, ub, va, vb) = (rect.s.start(), rect.s.end(), rect.t.start(), rect.t.end());
        Self::try_from_corners(
            &[
                [corner(ua, va)?, corner(ua, vb)?],
                [corner(ub, va)?, corner(ub, vb)?],
            ],
            rect.s.width(),
            rect.t.width(),
        )
    }

    /// The Hermite matrix `C`, `c[i][j]` with rows indexing s.
    pub fn matrix(&self) -> &Net {
        &self.c
    }

    /// The report's three planes `C(:, :, 1..3)` (x, y, z) as 4×4 matrices.
    pub fn planes(&self) -> [Matrix4<f64>; 3] {
        std::array::from_fn(|k| Matrix4::from_fn(|i, j| self.c[i][j][k]))
    }

    /// `X(s, t) = H(s)ᵀ C H(t)` (seed 000 §2, Codice 5) for any number type.
    pub fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        tensor_eval(&hermite_basis(s), &hermite_basis(t), &self.c)
    }

    /// Tabulates the patch on `linspace(0, 1, ns) × linspace(0, 1, nt)` (local parameters),
    /// row `i` ↔ `sᵢ`, with the basis rows computed once per grid line.
    ///
    /// # Errors
    /// [`crate::error::Error::TooFewSamples`] if `ns < 2` or `nt < 2`; [`Error::TooLarge`] if
    /// `ns · nt` exceeds [`crate::error::MAX_ELEMENTS`].
    pub fn tabulate(&self, ns: usize, nt: usize) -> Result<Grid<Vector3<f64>>> {
        crate::error::size_product("patch samples ns × nt", ns, nt)?;
        let rows = local_basis_samples(samples("ns", ns)?, hermite_basis);
        let cols = local_basis_samples(samples("nt", nt)?, hermite_basis);
        let mut out = Vec::new();
        tabulate_pieces(
            std::slice::from_ref(&self.c),
            1,
            &rows,
            &cols,
            &mut out,
            true,
        );
        Ok(Grid::from_vec(ns, nt, out).expect("tabulate_pieces fills rows × cols"))
    }
}

/// Basis values at `linspace(0, 1, n)` for a single piece.
pub(crate) fn local_basis_samples(n: usize, basis: fn(f64) -> [f64; 4]) -> Vec<BasisSample> {
    crate::domain::linspace(0.0, 1.0, n)
        .into_iter()
        .map(|x| BasisSample {
            piece: 0,
            w: basis(x),
        })
        .collect()
}

impl ParametricSurface for HermitePatch {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        HermitePatch::eval(self, s, t)
    }
}
