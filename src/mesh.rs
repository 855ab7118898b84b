//! A triangle mesh of a surface on a rectangle of its parameters, with the surface's exact
//! normals — what other tools (Blender, ParaView, MeshLab) open once it is written as OBJ, PLY
//! or STL (the report layer's `export`).
//!
//! **Vertices** are the surface's points on a grid of `samples_s × samples_t` parameters,
//! equally spaced over the rectangle, both ends included (a closed surface such as the torus
//! repeats its seam vertices, as its parametrization does). **Normals** are
//! `n = X_s × X_t / |X_s × X_t|` from the exact partials (hyper-dual numbers), computed from
//! the unit tangents so that no scale overflows or underflows. Where the tangents are
//! (nearly) parallel or one vanishes — a sphere's poles, a cone's apex — `X_s × X_t` gives no
//! direction (`|ŝ × t̂| < 10⁻⁸`); the vertex then takes the normalised sum of the unit normals
//! of the grid triangles around it, oriented like the parametrization, and the mesh is refused
//! (`Error::Degenerate`) only if that sum vanishes too. **Texture coordinates** are the
//! parameters scaled to `[0, 1]`: `u = (s − s_a)/(s_b − s_a)`, `v = (t − t_a)/(t_b − t_a)`.
//! **Triangles**: each grid cell `(i, j)` gives `(i, j), (i+1, j), (i+1, j+1)` and
//! `(i, j), (i+1, j+1), (i, j+1)`, counter-clockwise seen from the side `X_s × X_t` points to,
//! so their face normals agree with the vertex normals wherever the grid is fine enough.

use crate::domain::Rect;
use crate::error::{Error, Result};
use crate::surface::{partials_on_grid, SurfaceDerivatives};
use nalgebra::Vector3;

/// Below this `|ŝ × t̂|` (unit tangents) a vertex's normal comes from its triangles.
pub const PARALLEL_TANGENTS: f64 = 1e-8;

/// A triangle mesh with a unit normal and texture coordinates per vertex (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    positions: Vec<Vector3<f64>>,
    normals: Vec<Vector3<f64>>,
    uvs: Vec<[f64; 2]>,
    triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// The mesh of `surface` on `rect` with `samples_s × samples_t` vertices (module docs).
    ///
    /// # Errors
    /// [`Error::TooFewSamples`] if a sample count is below 2; [`Error::TooLarge`] if the
    /// vertices exceed [`crate::error::MAX_ELEMENTS`] or the triangles `u32::MAX` (the STL
    /// count); [`Error::NonFiniteSurface`] where the surface or a partial is NaN or infinite;
    /// [`Error::Degenerate`] at a vertex with no normal (module docs).
    pub fn try_of_surface<S: SurfaceDerivatives + Sync + ?Sized>(
        surface: &S,
        rect: &Rect,
        samples_s: usize,
        samples_t: usize,
    ) -> Result<Mesh> {
        crate::error::samples("mesh samples along s", samples_s)?;
        crate::error::samples("mesh samples along t", samples_t)?;
        // sizes first: nothing is allocated for a grid that is refused
        crate::error::size_product("mesh vertices", samples_s, samples_t)?;
        let s_nodes = rect.s.linspace(samples_s)?;
        let t_nodes = rect.t.linspace(samples_t)?;
        let cells = (samples_s - 1).saturating_mul(samples_t - 1);
        let triangles = cells.saturating_mul(2);
        if triangles > u32::MAX as usize {
            return Err(Error::TooLarge {
                what: "mesh triangles",
                got: triangles,
                max: u32::MAX as usize,
            });
        }
        let grid = partials_on_grid(surface, &s_nodes, &t_nodes)?;
        let at = |i: usize, j: usize| i * samples_t + j;
        let positions: Vec<Vector3<f64>> = grid.as_slice().iter().map(|p| p.point).collect();
        let mut triangles = Vec::with_capacity(triangles);
        for i in 0..samples_s - 1 {
            for j in 0..samples_t - 1 {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                triangles.push([a as u32, b as u32, c as u32]);
                triangles.push([a as u32, c as u32, d as u32]);
            }
        }
        let mut normals: Vec<Option<Vector3<f64>>> = grid
            .as_slice()
            .iter()
            .map(|p| unit_cross(p.ds, p.dt))
            .collect();
        if normals.iter().any(Option::is_none) {
            // the vertices without a normal of their own take their triangles'
            let mut sums = vec![Vector3::zeros(); positions.len()];
            for t in &triangles {
                let [a, b, c] = t.map(|k| positions[k as usize]);
                if let Some(n) = unit_cross(b - a, c - a) {
                    for &k in t {
                        sums[k as usize] += n;
                    }
                }
            }
            for (k, n) in normals.iter_mut().enumerate() {
                if n.is_none() {
                    *n = Some(sums[k].try_normalize(0.0).ok_or(Error::Degenerate {
                        what: "mesh normal",
                        reason: "X_s × X_t vanishes and so do the normals of the triangles around the vertex",
                    })?);
                }
            }
        }
        let (su, tv) = (rect.s, rect.t);
        let uvs = s_nodes
            .iter()
            .flat_map(|&s| {
                t_nodes
                    .iter()
                    .map(move |&t| [su.to_local(s), tv.to_local(t)])
            })
            .collect();
        Ok(Mesh {
            positions,
            normals: normals.into_iter().flatten().collect(),
            uvs,
            triangles,
        })
    }

    /// The vertices.
    pub fn positions(&self) -> &[Vector3<f64>] {
        &self.positions
    }

    /// The unit normal of each vertex.
    pub fn normals(&self) -> &[Vector3<f64>] {
        &self.normals
    }

    /// The texture coordinates `(u, v) ∈ [0, 1]²` of each vertex.
    pub fn uvs(&self) -> &[[f64; 2]] {
        &self.uvs
    }

    /// The triangles, as indices of vertices, counter-clockwise seen from the normals' side.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }
}

/// `a × b / |a × b|` from the unit vectors along `a` and `b`, or `None` where one vanishes or
/// they are (nearly) parallel (`|â × b̂| <` [`PARALLEL_TANGENTS`]).
fn unit_cross(a: Vector3<f64>, b: Vector3<f64>) -> Option<Vector3<f64>> {
    let a = unit(a)?;
    let b = unit(b)?;
    let c = a.cross(&b);
    let n = c.norm();
    (n >= PARALLEL_TANGENTS).then(|| c / n)
}

/// `v / |v|`, scaled first by its largest component so that no square overflows or
/// underflows; `None` for a zero (or non-finite) vector.
fn unit(v: Vector3<f64>) -> Option<Vector3<f64>> {
    let m = v.amax();
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let w = v / m;
    Some(w / w.norm())
}
