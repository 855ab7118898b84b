//! Piecewise bicubic Hermite (spline) surfaces over rectangular partitions (seed 000 §5).

use crate::domain::{Interval, Partition, Rect};
use crate::error::{Error, Result};
use crate::grid::Grid;
use crate::hermite::basis::hermite_basis;
use crate::hermite::patch::HermitePatch;
use crate::surface::{partials_on_grid, ParametricSurface, Partials, SurfaceDerivatives};
use crate::tensor::{tabulate_pieces, BasisSample, Net};
use nalgebra::Vector3;
use num_dual::DualNum;

/// A surface `X : [u₀, uₙ] × [v₀, vₘ] → ℝ³` made of `n × m` bicubic Hermite patches
/// (seed 000 §5): `X = X⁽ⁱʲ⁾` on `[uᵢ, uᵢ₊₁] × [vⱼ, vⱼ₊₁]`, with local parameters
/// `s = (u − uᵢ)/Δuᵢ`, `t = (v − vⱼ)/Δvⱼ` and the matrices `C⁽ⁱʲ⁾` of Codice 13.
///
/// Built from a surface, it interpolates `X`, `X_u`, `X_v`, `X_uv` at every node `(uᵢ, vⱼ)`;
/// neighbouring patches share their edge data, so the surface is C¹ across the seams.
///
/// **Outside its domain it extrapolates**: `point`, `partials` and `eval` at a parameter
/// beyond `[u₀, uₙ] × [v₀, vₘ]` continue the nearest end patch's polynomial (no error, no
/// clamping); [`HermiteSurface::try_point`] refuses such a parameter instead.
///
/// # Examples
/// ```
/// use splinelab::prelude::*;
/// let u = Partition::new(vec![0.0, 0.5, 0.9, 1.0]); // Fig 6 of the report
/// let v = Partition::uniform(0.0, 1.0, 1)?;
/// let torus = Torus::default();
/// let spline = HermiteSurface::try_from_surface(&torus, u, v)?;
/// assert_eq!(spline.patch_counts(), (3, 1));
/// // it interpolates the torus and its partials at the nodes, exactly up to rounding
/// let (d, e) = (spline.partials(0.5, 1.0), torus.partials(0.5, 1.0));
/// assert!((d.dst - e.dst).norm() < 1e-14);
/// // beyond the domain it extrapolates; `try_point` refuses
/// assert!(spline.point(1.5, 0.5).norm().is_finite());
/// assert!(spline.try_point(1.5, 0.5).is_err());
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteSurface {
    u: Partition,
    v: Partition,
    /// Row-major: patch `(i, j)` at `i * m + j`.
    nets: Vec<Net>,
}

impl HermiteSurface {
    /// Interpolates `surface` on the partitions `u` (s direction) and `v` (t direction).
    /// The partials are computed once per node and shared by the patches that meet there.
    ///
    /// # Panics
    /// On a surface that is not finite at a node, or a grid too large; see
    /// [`HermiteSurface::try_from_surface`].
    pub fn from_surface<S: SurfaceDerivatives + Sync + ?Sized>(
        surface: &S,
        u: Partition,
        v: Partition,
    ) -> Self {
        Self::try_from_surface(surface, u, v).expect("invalid Hermite spline surface")
    }

    /// [`HermiteSurface::from_surface`], checked: every node's point and partials must be
    /// finite and every patch matrix valid, so the spline evaluates finitely on its domain.
    ///
    /// # Errors
    /// [`Error::TooLarge`] if the `(n + 1)(m + 1)` nodes exceed
    /// [`crate::error::MAX_ELEMENTS`]; [`Error::NonFiniteSurface`] at the first node where the
    /// surface is NaN or infinite; the errors of [`HermitePatch::try_from_corners`].
    pub fn try_from_surface<S: SurfaceDerivatives + Sync + ?Sized>(
        surface: &S,
        u: Partition,
        v: Partition,
    ) -> Result<Self> {
        let nodes = partials_on_grid(surface, u.nodes(), v.nodes())?;
        Self::try_from_node_partials(&nodes, u, v)
    }

    /// Builds the patches from partials given at every node (`nodes[(i, j)]` at `(uᵢ, vⱼ)`).
    ///
    /// # Panics
    /// If the grid is not `(n + 1) × (m + 1)` or its data are invalid; see
    /// [`HermiteSurface::try_from_node_partials`].
    pub fn from_node_partials(nodes: &Grid<Partials>, u: Partition, v: Partition) -> Self {
        Self::try_from_node_partials(nodes, u, v).expect("invalid node partials")
    }

    /// [`HermiteSurface::from_node_partials`], checked.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless the grid is `(n + 1) × (m + 1)`; the errors of
    /// [`HermitePatch::try_from_corners`] for any patch.
    pub fn try_from_node_partials(
        nodes: &Grid<Partials>,
        u: Partition,
        v: Partition,
    ) -> Result<Self> {
        let (n, m) = (u.len(), v.len());
        if (nodes.rows(), nodes.cols()) != (n + 1, m + 1) {
            return Err(Error::ShapeMismatch {
                left_rows: nodes.rows(),
                left_cols: nodes.cols(),
                right_rows: n + 1,
                right_cols: m + 1,
            });
        }
        let mut nets = Vec::with_capacity(n * m);
        for i in 0..n {
            for j in 0..m {
                let corner = |a: usize, b: usize| *nodes.get(i + a, j + b);
                let patch = HermitePatch::try_from_corners(
                    &[[corner(0, 0), corner(0, 1)], [corner(1, 0), corner(1, 1)]],
                    u.interval(i).width(),
                    v.interval(j).width(),
                )?;
                nets.push(*patch.matrix());
            }
        }
        Ok(Self { u, v, nets })
    }

    /// `n × m` uniform patches of `rect` (the report's §6 experiments: `linspace(0, 1, n+1)`).
    ///
    /// # Errors
    /// [`Error::ZeroPatches`] if `n` or `m` is 0; the errors of [`Partition::uniform`] and
    /// [`HermiteSurface::try_from_surface`].
    pub fn uniform<S: SurfaceDerivatives + Sync + ?Sized>(
        surface: &S,
        rect: &Rect,
        n: usize,
        m: usize,
    ) -> Result<Self> {
        let u = Partition::uniform(rect.s.start(), rect.s.end(), n)?;
        let v = Partition::uniform(rect.t.start(), rect.t.end(), m)?;
        Self::try_from_surface(surface, u, v)
    }

    /// The u partition.
    pub fn u(&self) -> &Partition {
        &self.u
    }

    /// The v partition.
    pub fn v(&self) -> &Partition {
        &self.v
    }

    /// `(n, m)`: patches along u and along v.
    pub fn patch_counts(&self) -> (usize, usize) {
        (self.u.len(), self.v.len())
    }

    /// Patch `(i, j)` on `[uᵢ, uᵢ₊₁] × [vⱼ, vⱼ₊₁]`, in its local parameters.
    ///
    /// # Panics
    /// If `i >= n` or `j >= m`.
    pub fn patch(&self, i: usize, j: usize) -> HermitePatch {
        let (n, m) = self.patch_counts();
        assert!(
            i < n && j < m,
            "patch index ({i}, {j}) out of range {n}x{m}"
        );
        HermitePatch::from_valid_matrix(self.nets[i * m + j])
    }

    /// The rectangle of patch `(i, j)`.
    pub fn patch_rect(&self, i: usize, j: usize) -> Rect {
        Rect {
            s: self.u.interval(i),
            t: self.v.interval(j),
        }
    }

    /// The whole parameter domain.
    pub fn domain(&self) -> Rect {
        Rect {
            s: self.u.span(),
            t: self.v.span(),
        }
    }

    /// `X(u, v)` at global parameters, checked.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for NaN or infinite parameters, [`Error::OutOfDomain`] outside
    /// the domain (its right ends included).
    pub fn try_point(&self, u: f64, v: f64) -> Result<Vector3<f64>> {
        check_in("u", u, &self.u.span())?;
        check_in("v", v, &self.v.span())?;
        Ok(self.eval(u, v))
    }

    /// Tabulates on `u_samples × v_samples` (row `i` ↔ `u_samples[i]`), with basis rows
    /// computed once per grid line and the patch found once per sample.
    ///
    /// # Errors
    /// As [`HermiteSurface::try_point`] for any sample; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`] samples.
    pub fn tabulate(&self, u_samples: &[f64], v_samples: &[f64]) -> Result<Grid<Vector3<f64>>> {
        let mut out = Vec::new();
        self.tabulate_into(u_samples, v_samples, &mut out)?;
        Ok(Grid::from_vec(u_samples.len(), v_samples.len(), out).expect("filled rows × cols"))
    }

    /// As [`HermiteSurface::tabulate`], writing into `out` (resized to the grid, row-major;
    /// its former contents overwritten) so a caller that tabulates repeatedly reuses one
    /// buffer. From 65 536 points the rows are shared between two threads (the same result
    /// as on one).
    ///
    /// # Errors
    /// As [`HermiteSurface::try_point`] for any sample.
    pub fn tabulate_into(
        &self,
        u_samples: &[f64],
        v_samples: &[f64],
        out: &mut Vec<Vector3<f64>>,
    ) -> Result<()> {
        self.tabulate_into_on(u_samples, v_samples, out, true)
    }

    /// [`HermiteSurface::tabulate_into`], on one thread unless `parallel` is set (the
    /// benchmark's single-core figure).
    pub(crate) fn tabulate_into_on(
        &self,
        u_samples: &[f64],
        v_samples: &[f64],
        out: &mut Vec<Vector3<f64>>,
        parallel: bool,
    ) -> Result<()> {
        crate::error::size_product("spline samples", u_samples.len(), v_samples.len())?;
        let rows = basis_samples("u", &self.u, u_samples)?;
        let cols = basis_samples("v", &self.v, v_samples)?;
        tabulate_pieces(&self.nets, self.v.len(), &rows, &cols, out, parallel);
        Ok(())
    }
}

fn check_in(what: &'static str, x: f64, span: &Interval) -> Result<f64> {
    crate::domain::check_domain(what, x, (span.start(), span.end()))
}

/// Locates each sample's piece and evaluates the Hermite basis at its local parameter.
fn basis_samples(
    what: &'static str,
    partition: &Partition,
    samples: &[f64],
) -> Result<Vec<BasisSample>> {
    let span = partition.span();
    samples
        .iter()
        .map(|&x| {
            check_in(what, x, &span)?;
            let piece = partition.locate(x);
            Ok(BasisSample {
                piece,
                w: hermite_basis(partition.interval(piece).to_local(x)),
            })
        })
        .collect()
}

impl ParametricSurface for HermiteSurface {
    /// `X(u, v)` at global parameters. The patch is chosen by the real parts (the right end
    /// belongs to the last patch); parameters outside the domain extrapolate the nearest
    /// end patch's polynomial — use [`HermiteSurface::try_point`] for checked evaluation.
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, u: D, v: D) -> Vector3<D> {
        let i = crate::branch::piece(self.u.nodes(), &u);
        let j = crate::branch::piece(self.v.nodes(), &v);
        let (iu, iv) = (self.u.interval(i), self.v.interval(j));
        let s = (u - iu.start()) / iu.width();
        let t = (v - iv.start()) / iv.width();
        self.patch(i, j).eval(s, t)
    }

    /// The patch's intervals `[uᵢ, uᵢ₊₁) × [vⱼ, vⱼ₊₁)` (the last ones closed).
    fn span_at(&self, u: f64, v: f64) -> Option<[crate::domain::Span; 2]> {
        let (nu, nv) = (self.u.nodes(), self.v.nodes());
        Some([
            crate::domain::Span::of(nu, self.u.locate(u)),
            crate::domain::Span::of(nv, self.v.locate(v)),
        ])
    }
}
