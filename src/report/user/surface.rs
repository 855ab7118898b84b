//! A Hermite spline surface of a built-in surface on a user's partition ([`SurfaceMesh`]), as a
//! mesh in a standard format ([`MeshFormat`]): the `surface` command's work.
//!
//! ```
//! use splinelab::report::user::surface::{BuiltIn, MeshFormat, PartitionSpec, SurfaceMesh};
//! let torus = BuiltIn::Torus { major: 2.0, minor: 1.0 };
//! let spec: PartitionSpec = "8x6".parse()?;
//! let (s, t) = spec.partitions(&torus)?;
//! let made = SurfaceMesh::try_new(&torus, s, t, 8)?;
//! assert_eq!(made.mesh.positions().len(), (8 * 8 + 1) * (6 * 8 + 1));
//! let obj = MeshFormat::Obj.encode(&made.mesh)?;
//! assert!(obj.starts_with(b"# "));
//! # Ok::<(), splinelab::report::Error>(())
//! ```

use crate::domain::{Partition, Rect};
use crate::hermite::spline_surface::HermiteSurface;
use crate::mesh::Mesh;
use crate::report::error::Result;
use crate::report::export::{self, PlyEncoding};
use crate::surface::{ExpSurface, Sphere, Torus};
use std::f64::consts::{FRAC_PI_2, TAU};
use std::path::Path;
use std::str::FromStr;

/// A surface the library defines, with its natural domain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BuiltIn {
    /// The torus of seed 000 ([`Torus`]) on `[0, 2π]²`.
    Torus {
        /// `R`.
        major: f64,
        /// `r`.
        minor: f64,
    },
    /// The sphere ([`Sphere`]) in longitude `s ∈ [0, 2π]` and latitude `t ∈ [−π/2, π/2]`.
    Sphere {
        /// `ρ`.
        radius: f64,
    },
    /// The test surface `(e^{s+t}, e^{s−t}, sinh s sinh t)` ([`ExpSurface`]) on `[0, 1]²`.
    Exp,
}

impl BuiltIn {
    /// The surface's natural domain (module docs).
    pub fn domain(&self) -> Rect {
        match self {
            BuiltIn::Torus { .. } => Rect::new(0.0, TAU, 0.0, TAU),
            BuiltIn::Sphere { .. } => Rect::new(0.0, TAU, -FRAC_PI_2, FRAC_PI_2),
            BuiltIn::Exp => Rect::new(0.0, 1.0, 0.0, 1.0),
        }
    }
}

/// How the domain is cut into patches.
#[derive(Debug, Clone, PartialEq)]
pub enum PartitionSpec {
    /// `n × m` equal patches of the natural domain (`"8x6"`).
    Uniform(usize, usize),
    /// The nodes along `s` and along `t`, increasing.
    Nodes(Vec<f64>, Vec<f64>),
}

impl PartitionSpec {
    /// The partition used when none is given: 8 × 8 equal patches.
    pub const DEFAULT: PartitionSpec = PartitionSpec::Uniform(8, 8);
}

impl FromStr for PartitionSpec {
    type Err = crate::error::Error;

    /// `NxM` (equal patches; `N` along `s`, `M` along `t`).
    fn from_str(s: &str) -> crate::error::Result<Self> {
        let bad = |message: String| crate::error::Error::Parse {
            what: "partition",
            line: 1,
            column: 1,
            message,
        };
        let (n, m) = s.trim().split_once(['x', 'X', '×']).ok_or_else(|| {
            bad(format!(
                "{s:?} is not NxM (8x6: 8 patches along s, 6 along t)"
            ))
        })?;
        let count = |v: &str| {
            v.trim()
                .parse::<usize>()
                .map_err(|_| bad(format!("{v:?} in {s:?} is not a patch count")))
        };
        Ok(PartitionSpec::Uniform(count(n)?, count(m)?))
    }
}

impl PartitionSpec {
    /// The partitions along `s` and `t` on `surface`'s domain (explicit nodes as given).
    ///
    /// # Errors
    /// The errors of [`Partition::uniform`] (0 patches, too many for the width) and
    /// [`Partition::try_new`] (fewer than 2 nodes, not increasing, not finite).
    pub fn partitions(&self, surface: &BuiltIn) -> Result<(Partition, Partition)> {
        let rect = surface.domain();
        Ok(match self {
            PartitionSpec::Uniform(n, m) => (
                Partition::uniform(rect.s.start(), rect.s.end(), *n)?,
                Partition::uniform(rect.t.start(), rect.t.end(), *m)?,
            ),
            PartitionSpec::Nodes(s, t) => (
                Partition::try_new(s.clone())?,
                Partition::try_new(t.clone())?,
            ),
        })
    }
}

/// The Hermite spline surface of a built-in surface and its mesh.
#[derive(Debug, Clone)]
pub struct SurfaceMesh {
    /// The spline surface (bicubic Hermite patches on the partition).
    pub spline: HermiteSurface,
    /// Its mesh: `samples_per_patch` steps a patch in each direction, normals from the
    /// spline's exact partials ([`Mesh::try_of_surface`]).
    pub mesh: Mesh,
}

impl SurfaceMesh {
    /// Interpolates `surface` on the partitions `s` and `t`
    /// ([`HermiteSurface::try_from_surface`]) and meshes the spline with `samples_per_patch`
    /// steps a patch (on a uniform partition the patch edges are mesh lines).
    ///
    /// # Errors
    /// [`crate::error::Error::NotPositive`] for a radius that is not positive and finite;
    /// [`crate::error::Error::TooFewSamples`] for fewer than 1 step a patch; [`crate::error::Error::TooLarge`]
    /// if the vertices exceed [`crate::error::MAX_ELEMENTS`]; the errors of
    /// [`HermiteSurface::try_from_surface`] and [`Mesh::try_of_surface`].
    pub fn try_new(
        surface: &BuiltIn,
        s: Partition,
        t: Partition,
        samples_per_patch: usize,
    ) -> Result<SurfaceMesh> {
        if samples_per_patch == 0 {
            return Err(crate::error::Error::TooFewSamples {
                what: "mesh steps per patch",
                got: 0,
            }
            .into());
        }
        let steps = |n: usize| {
            n.checked_mul(samples_per_patch)
                .and_then(|k| k.checked_add(1))
                .ok_or(crate::error::Error::TooLarge {
                    what: "mesh samples",
                    got: usize::MAX,
                    max: crate::error::MAX_ELEMENTS,
                })
        };
        let (ns, nt) = (steps(s.len())?, steps(t.len())?);
        crate::error::size_product("mesh vertices", ns, nt)?;
        let nodes = |p: &Partition| (p.nodes()[0], p.nodes()[p.len()]);
        let ((s0, s1), (t0, t1)) = (nodes(&s), nodes(&t));
        let rect = Rect::try_new(s0, s1, t0, t1)?;
        let spline = match *surface {
            BuiltIn::Torus { major, minor } => {
                HermiteSurface::try_from_surface(&Torus::try_new(major, minor)?, s, t)?
            }
            BuiltIn::Sphere { radius } => {
                HermiteSurface::try_from_surface(&Sphere::try_new(radius)?, s, t)?
            }
            BuiltIn::Exp => HermiteSurface::try_from_surface(&ExpSurface, s, t)?,
        };
        let mesh = Mesh::try_of_surface(&spline, &rect, ns, nt)?;
        Ok(SurfaceMesh { spline, mesh })
    }
}

/// A mesh file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    /// Wavefront OBJ ([`export::obj`]).
    Obj,
    /// PLY, ASCII or binary ([`export::ply`]).
    Ply(PlyEncoding),
    /// Binary STL ([`export::stl`]).
    Stl,
}

impl MeshFormat {
    /// The format of a file name's extension (`.obj`, `.ply`, `.stl`, any case); a PLY is
    /// binary unless `ascii`.
    ///
    /// # Errors
    /// [`crate::error::Error::Parse`] for another extension.
    pub fn of_path(path: &Path, ascii: bool) -> Result<MeshFormat> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("obj") => Ok(MeshFormat::Obj),
            Some("ply") if ascii => Ok(MeshFormat::Ply(PlyEncoding::Ascii)),
            Some("ply") => Ok(MeshFormat::Ply(PlyEncoding::BinaryLittleEndian)),
            Some("stl") => Ok(MeshFormat::Stl),
            _ => Err(crate::error::Error::Parse {
                what: "mesh file name",
                line: 1,
                column: 1,
                message: format!("{} does not end in .obj, .ply or .stl", path.display()),
            }
            .into()),
        }
    }

    /// The file's bytes.
    ///
    /// # Errors
    /// As [`export::stl`] (a coordinate beyond `f32`).
    pub fn encode(self, mesh: &Mesh) -> Result<Vec<u8>> {
        Ok(match self {
            MeshFormat::Obj => export::obj(mesh).into_bytes(),
            MeshFormat::Ply(encoding) => export::ply(mesh, encoding),
            MeshFormat::Stl => export::stl(mesh)?,
        })
    }
}
