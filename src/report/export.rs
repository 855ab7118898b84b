//! Standard files out: a [`Mesh`] as Wavefront OBJ, PLY (ASCII or binary) and binary STL,
//! for Blender, ParaView, MeshLab and slicers; a curve as an SVG path of cubic Béziers
//! ([`svg_path`], [`svg_document`]; exact for cubic pieces, [`crate::bezier::from_curve`]) for
//! drawing programs; written atomically like every other output ([`save`]).
//!
//! ```
//! use splinelab::report::export::{self, PlyEncoding};
//! use splinelab::{Mesh, Rect, Torus};
//! let torus = Torus::new(2.0, 1.0);
//! let rect = Rect::new(0.0, std::f64::consts::TAU, 0.0, std::f64::consts::TAU);
//! let mesh = Mesh::try_of_surface(&torus, &rect, 49, 25)?;
//! let obj = export::obj(&mesh);            // v, vt, vn, f v/vt/vn
//! let ply = export::ply(&mesh, PlyEncoding::BinaryLittleEndian);
//! let stl = export::stl(&mesh)?;           // 80-byte header, count, 50 bytes a triangle
//! assert_eq!(stl.len(), 84 + 50 * mesh.triangles().len());
//! # let _ = (obj, ply);
//! # Ok::<(), splinelab::report::Error>(())
//! ```
//!
//! **Precision.** OBJ and ASCII PLY print each number as the shortest decimal that reads back
//! to the same `f64`; binary PLY stores `double`s; STL stores `float`s (the format's only
//! type), so a coordinate beyond `f32::MAX` is refused there. **Normals** are the mesh's exact
//! vertex normals (OBJ `vn`, PLY `nx ny nz`); an STL facet's normal is the normalised sum of
//! its three vertex normals (the triangle's own normal where they cancel).

use crate::bezier::from_curve::CubicSegment;
use crate::mesh::Mesh;
use crate::printed::decimal;
use crate::report::error::Result;
use nalgebra::Vector3;
use std::fmt::Write as _;
use std::path::Path;

/// How a PLY file stores its numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlyEncoding {
    /// Text, one vertex or face a line.
    Ascii,
    /// Little-endian binary (`double` coordinates, `uint` indices).
    BinaryLittleEndian,
}

/// The mesh as Wavefront OBJ: `v x y z`, `vt u v`, `vn nx ny nz` per vertex and
/// `f a/a/a b/b/b c/c/c` per triangle (1-based indices).
pub fn obj(mesh: &Mesh) -> String {
    let mut out = format!(
        "# splinelab mesh: {} vertices, {} triangles; normals exact (X_s x X_t), texture coordinates the parameters scaled to [0, 1]\n",
        mesh.positions().len(),
        mesh.triangles().len()
    );
    for p in mesh.positions() {
        let _ = writeln!(out, "v {}", numbers(p.as_slice()));
    }
    for uv in mesh.uvs() {
        let _ = writeln!(out, "vt {}", numbers(uv));
    }
    for n in mesh.normals() {
        let _ = writeln!(out, "vn {}", numbers(n.as_slice()));
    }
    for t in mesh.triangles() {
        let [a, b, c] = t.map(|k| k + 1);
        let _ = writeln!(out, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}");
    }
    out
}

/// The mesh as PLY: vertices with `x y z nx ny nz s t` (texture coordinates), faces as lists
/// of three `uint` indices.
pub fn ply(mesh: &Mesh, encoding: PlyEncoding) -> Vec<u8> {
    let format = match encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
    };
    let mut out = format!("ply\nformat {format} 1.0\ncomment splinelab mesh: normals exact (X_s x X_t), s t the parameters scaled to [0, 1]\nelement vertex {}\n", mesh.positions().len());
    for name in ["x", "y", "z", "nx", "ny", "nz", "s", "t"] {
        let _ = writeln!(out, "property double {name}");
    }
    let _ = write!(
        out,
        "element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        mesh.triangles().len()
    );
    let vertex = |k: usize| {
        let (p, n, uv) = (mesh.positions()[k], mesh.normals()[k], mesh.uvs()[k]);
        [p.x, p.y, p.z, n.x, n.y, n.z, uv[0], uv[1]]
    };
    let count = mesh.positions().len();
    match encoding {
        PlyEncoding::Ascii => {
            for k in 0..count {
                let _ = writeln!(out, "{}", numbers(&vertex(k)));
            }
            for [a, b, c] in mesh.triangles() {
                let _ = writeln!(out, "3 {a} {b} {c}");
            }
            out.into_bytes()
        }
        PlyEncoding::BinaryLittleEndian => {
            let mut bytes = out.into_bytes();
            bytes.reserve(count * 64 + mesh.triangles().len() * 13);
            for k in 0..count {
                for x in vertex(k) {
                    bytes.extend_from_slice(&x.to_le_bytes());
                }
            }
            for t in mesh.triangles() {
                bytes.push(3);
                for k in t {
                    bytes.extend_from_slice(&k.to_le_bytes());
                }
            }
            bytes
        }
    }
}

/// The mesh as binary STL: an 80-byte header, the triangle count, and per triangle its normal
/// and three vertices as `float`s and a zero attribute.
///
/// # Errors
/// [`crate::error::Error::Overflow`] (as [`crate::report::Error::Core`]) for a coordinate beyond
/// `f32::MAX`, which a `float` cannot hold.
pub fn stl(mesh: &Mesh) -> Result<Vec<u8>> {
    let mut header = [b' '; 80];
    let text = b"splinelab mesh (binary STL; normals from the exact partials)";
    header[..text.len()].copy_from_slice(text);
    let mut out = Vec::with_capacity(84 + 50 * mesh.triangles().len());
    out.extend_from_slice(&header);
    // the triangle count fits: Mesh refuses more than u32::MAX triangles
    out.extend_from_slice(&(mesh.triangles().len() as u32).to_le_bytes());
    let single = |v: &Vector3<f64>| -> Result<[f32; 3]> {
        let w = v.map(|x| x as f32);
        if w.iter().all(|x| x.is_finite()) {
            Ok([w.x, w.y, w.z])
        } else {
            Err(crate::error::Error::Overflow {
                what: "STL coordinate (a 32-bit float)",
                value: v.amax(),
            }
            .into())
        }
    };
    for t in mesh.triangles() {
        let [a, b, c] = t.map(|k| k as usize);
        let (p, n) = (mesh.positions(), mesh.normals());
        let normal = (n[a] + n[b] + n[c])
            .try_normalize(0.0)
            .or_else(|| (p[b] - p[a]).cross(&(p[c] - p[a])).try_normalize(0.0))
            .unwrap_or_else(Vector3::zeros);
        for v in [normal, p[a], p[b], p[c]] {
            for x in single(&v)? {
                out.extend_from_slice(&x.to_le_bytes());
            }
        }
        out.extend_from_slice(&0u16.to_le_bytes());
    }
    Ok(out)
}

/// Writes `bytes` to `path` atomically: a temporary file beside it, renamed into place only
/// when complete, so a failed write never leaves a truncated file under the name.
///
/// # Errors
/// [`crate::report::Error::Io`] if the file cannot be written.
pub fn save(path: &Path, bytes: &[u8]) -> Result<()> {
    crate::report::files::write_atomic(path, bytes)
}

/// The SVG path data of cubic Bézier segments: `M x y C x₁ y₁ x₂ y₂ x₃ y₃ …`, a new `M`
/// where a segment does not start at the previous one's end, `Z` where a subpath of more than
/// one segment returns to its start. Coordinates are the curve's own (SVG's `y` points down:
/// [`svg_document`] flips it).
pub fn svg_path(segments: &[CubicSegment<2>]) -> String {
    let mut d = String::new();
    let mut at: Option<nalgebra::Vector2<f64>> = None;
    let mut start = None;
    let mut pieces = 0usize;
    for s in segments {
        if at != Some(s[0]) {
            if at.is_some() && at == start && pieces > 1 {
                d.push_str(" Z");
            }
            let _ = write!(
                d,
                "{}M {}",
                if d.is_empty() { "" } else { " " },
                numbers(s[0].as_slice())
            );
            start = Some(s[0]);
            pieces = 0;
        }
        pieces += 1;
        let _ = write!(
            d,
            " C {} {} {}",
            numbers(s[1].as_slice()),
            numbers(s[2].as_slice()),
            numbers(s[3].as_slice())
        );
        at = Some(s[3]);
    }
    if at.is_some() && at == start && pieces > 1 {
        d.push_str(" Z");
    }
    d
}

/// A standalone SVG document drawing the path `d` ([`svg_path`]) with a stroke of
/// `stroke_width` (in the curve's units), its `viewBox` the bounding box of `segments`' control
/// points with a margin, and `y` pointing up as in the curve's coordinates.
///
/// # Errors
/// [`crate::error::Error::Overflow`] if the `viewBox` (the extent with its margin) is not finite:
/// control points so far apart that their distance overflows.
pub fn svg_document(segments: &[CubicSegment<2>], stroke_width: f64) -> Result<String> {
    let points = segments.iter().flatten();
    let (mut lo, mut hi) = (
        nalgebra::Vector2::repeat(f64::INFINITY),
        nalgebra::Vector2::repeat(f64::NEG_INFINITY),
    );
    for p in points {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    if segments.is_empty() {
        (lo, hi) = (nalgebra::Vector2::zeros(), nalgebra::Vector2::repeat(1.0));
    }
    let margin = 0.05 * (hi - lo).amax().max(f64::MIN_POSITIVE) + stroke_width;
    let (x, y) = (lo.x - margin, lo.y - margin);
    let (w, h) = (hi.x - lo.x + 2.0 * margin, hi.y - lo.y + 2.0 * margin);
    if let Some(&bad) = [x, y, w, h, 2.0 * y + h, stroke_width]
        .iter()
        .find(|v| !v.is_finite())
    {
        return Err(crate::error::Error::Overflow {
            what: "the SVG document's viewBox (the curve's extent with its margin)",
            value: bad,
        }
        .into());
    }
    Ok(format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\">\n<g transform=\"matrix(1 0 0 -1 0 {})\">\n<path d=\"{}\" fill=\"none\" stroke=\"black\" stroke-width=\"{}\"/>\n</g>\n</svg>\n",
        decimal(x),
        decimal(y),
        decimal(w),
        decimal(h),
        decimal(2.0 * y + h),
        svg_path(segments),
        decimal(stroke_width)
    ))
}

/// Numbers separated by spaces, each the shortest decimal that reads back to it.
fn numbers(xs: &[f64]) -> String {
    xs.iter().map(|&x| decimal(x)).collect::<Vec<_>>().join(" ")
}
