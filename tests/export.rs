//! Meshes of surfaces and their files (issue 29): the mesh against closed forms (points on the
//! surface, normals the torus's and the sphere's own, the poles' normals from their triangles,
//! faces wound like the normals), and each file read back by a reader written here from the
//! formats' specifications, independent of the writers: OBJ, PLY (ASCII and binary), binary
//! STL — vertices, texture coordinates, normals and faces compared with the mesh.
#![cfg(feature = "report")]

use nalgebra::Vector3;
use num_dual::DualNum;
use splinelab::report::export::{self, PlyEncoding};
use splinelab::{Error, FnSurface, Mesh, Rect, Sphere, SurfaceDerivatives, Torus};
use std::f64::consts::{FRAC_PI_2, TAU};

fn torus_mesh() -> Mesh {
    Mesh::try_of_surface(
        &Torus::new(2.0, 1.0),
        &Rect::new(0.0, TAU, 0.0, TAU),
        25,
        13,
    )
    .unwrap()
}

fn sphere_mesh() -> Mesh {
    let rect = Rect::new(0.0, TAU, -FRAC_PI_2, FRAC_PI_2);
    Mesh::try_of_surface(&Sphere::new(1.5), &rect, 17, 9).unwrap()
}

#[test]
fn torus_vertices_normals_and_faces_are_the_surfaces() {
    let torus = Torus::new(2.0, 1.0);
    let m = torus_mesh();
    assert_eq!(m.positions().len(), 25 * 13);
    assert_eq!(m.triangles().len(), 2 * 24 * 12);
    for (k, p) in m.positions().iter().enumerate() {
        let (i, j) = (k / 13, k % 13);
        let (s, t) = (TAU * i as f64 / 24.0, TAU * j as f64 / 12.0);
        assert!((p - torus.partials(s, t).point).norm() < 1e-14);
        assert!((m.uvs()[k][0] - i as f64 / 24.0).abs() < 1e-15);
        assert!((m.uvs()[k][1] - j as f64 / 12.0).abs() < 1e-15);
        // the torus's outward normal (cos t cos s, cos t sin s, sin t): X_s × X_t points out
        let outward = Vector3::new(t.cos() * s.cos(), t.cos() * s.sin(), t.sin());
        assert!((m.normals()[k] - outward).norm() < 1e-14, "vertex {k}");
    }
    faces_wound_like_normals(&m);
}

#[test]
fn sphere_poles_take_the_normal_of_their_triangles() {
    let m = sphere_mesh();
    for (k, p) in m.positions().iter().enumerate() {
        let outward = p / 1.5;
        let n = m.normals()[k];
        assert!((n.norm() - 1.0).abs() < 1e-15);
        assert!(
            (n - outward).norm() < 1e-12,
            "vertex {k}: {n:?} vs {outward:?}"
        );
    }
    faces_wound_like_normals(&m);
}

/// Every triangle of positive area has its face normal on the side of its vertex normals.
fn faces_wound_like_normals(m: &Mesh) {
    let (p, n) = (m.positions(), m.normals());
    for t in m.triangles() {
        let [a, b, c] = t.map(|k| k as usize);
        let face = (p[b] - p[a]).cross(&(p[c] - p[a]));
        if face.norm() > 1e-12 {
            assert!(face.dot(&(n[a] + n[b] + n[c])) > 0.0, "triangle {t:?}");
        }
    }
}

#[test]
fn bad_meshes_are_typed_errors() {
    let rect = Rect::unit();
    let torus = Torus::default();
    assert!(matches!(
        Mesh::try_of_surface(&torus, &rect, 1, 5),
        Err(Error::TooFewSamples { .. })
    ));
    assert!(matches!(
        Mesh::try_of_surface(&torus, &rect, 5, 0),
        Err(Error::TooFewSamples { .. })
    ));
    // too many vertices: refused before anything is allocated
    for (a, b) in [
        (1 << 20, 1 << 20),
        (usize::MAX, 2),
        (2, usize::MAX),
        (usize::MAX, usize::MAX),
    ] {
        assert!(matches!(
            Mesh::try_of_surface(&torus, &rect, a, b),
            Err(Error::TooLarge { .. })
        ));
    }
    let nan = FnSurface::new(|s: num_dual::HyperDual64, t| Vector3::new(s, t, (s - 0.5).ln()));
    assert!(matches!(
        Mesh::try_of_surface(&nan, &rect, 5, 5),
        Err(Error::NonFiniteSurface { .. })
    ));
    // a curve, not a surface: no normal anywhere
    let line = FnSurface::new(|s: num_dual::HyperDual64, t| Vector3::new(s + t, s + t, s + t));
    assert!(matches!(
        Mesh::try_of_surface(&line, &rect, 5, 5),
        Err(Error::Degenerate { .. })
    ));
    // coordinates a float cannot hold: OBJ and PLY keep them, STL refuses them
    let huge = FnSurface::new(|s: num_dual::HyperDual64, t| {
        Vector3::new(s * 1e300, t * 1e300, s * t * 1e300)
    });
    let m = Mesh::try_of_surface(&huge, &rect, 3, 3).unwrap();
    assert!(matches!(
        export::stl(&m),
        Err(splinelab::report::Error::Core(Error::Overflow { .. }))
    ));
    assert_eq!(read_obj(&export::obj(&m)).positions, m.positions());
}

// ---------------------------------------------------------------------------------------------
// readers written from the formats' specifications
// ---------------------------------------------------------------------------------------------

#[derive(Debug, Default, PartialEq)]
struct Read {
    positions: Vec<Vector3<f64>>,
    normals: Vec<Vector3<f64>>,
    uvs: Vec<[f64; 2]>,
    triangles: Vec<[u32; 3]>,
}

fn floats(parts: &[&str]) -> Vec<f64> {
    parts
        .iter()
        .map(|x| x.parse::<f64>().expect("a number"))
        .collect()
}

/// Wavefront OBJ: `v`, `vt`, `vn`, and `f` with `v/vt/vn` triples (1-based, the same index in
/// each place here).
fn read_obj(text: &str) -> Read {
    let mut r = Read::default();
    for line in text.lines() {
        let parts: Vec<&str> = line.split_whitespace().collect();
        match parts.first() {
            Some(&"v") => {
                let x = floats(&parts[1..]);
                r.positions.push(Vector3::new(x[0], x[1], x[2]));
            }
            Some(&"vn") => {
                let x = floats(&parts[1..]);
                r.normals.push(Vector3::new(x[0], x[1], x[2]));
            }
            Some(&"vt") => {
                let x = floats(&parts[1..]);
                r.uvs.push([x[0], x[1]]);
            }
            Some(&"f") => {
                let idx: Vec<u32> = parts[1..]
                    .iter()
                    .map(|c| {
                        let ks: Vec<u32> = c.split('/').map(|k| k.parse().unwrap()).collect();
                        assert!(ks.iter().all(|&k| k == ks[0]), "v/vt/vn agree");
                        ks[0] - 1
                    })
                    .collect();
                assert_eq!(idx.len(), 3);
                r.triangles.push([idx[0], idx[1], idx[2]]);
            }
            Some(&"#") | None => {}
            Some(other) => panic!("unexpected OBJ statement {other}"),
        }
    }
    r
}

/// PLY with a vertex element of doubles (`x y z nx ny nz s t`) and a face element of
/// `uchar`-counted `uint` lists, ASCII or binary little-endian.
fn read_ply(bytes: &[u8]) -> Read {
    let end = b"end_header\n";
    let at = bytes
        .windows(end.len())
        .position(|w| w == end)
        .expect("end_header")
        + end.len();
    let header = std::str::from_utf8(&bytes[..at]).unwrap();
    let mut lines = header.lines();
    assert_eq!(lines.next(), Some("ply"));
    let (mut format, mut vertices, mut faces, mut props) = ("", 0usize, 0usize, Vec::new());
    let mut in_vertex = false;
    for line in lines {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.as_slice() {
            ["format", f, "1.0"] => format = f,
            ["element", "vertex", n] => {
                vertices = n.parse().unwrap();
                in_vertex = true;
            }
            ["element", "face", n] => {
                faces = n.parse().unwrap();
                in_vertex = false;
            }
            ["property", "double", name] if in_vertex => props.push(*name),
            ["property", "list", "uchar", "uint", "vertex_indices"] => {}
            ["comment", ..] | ["end_header"] => {}
            other => panic!("unexpected PLY header line {other:?}"),
        }
    }
    assert_eq!(props, ["x", "y", "z", "nx", "ny", "nz", "s", "t"]);
    let mut r = Read::default();
    let mut push_vertex = |v: &[f64]| {
        r.positions.push(Vector3::new(v[0], v[1], v[2]));
        r.normals.push(Vector3::new(v[3], v[4], v[5]));
        r.uvs.push([v[6], v[7]]);
    };
    let body = &bytes[at..];
    let mut triangles = Vec::new();
    match format {
        "ascii" => {
            let text = std::str::from_utf8(body).unwrap();
            let mut lines = text.lines();
            for _ in 0..vertices {
                push_vertex(&floats(
                    &lines.next().unwrap().split(' ').collect::<Vec<_>>(),
                ));
            }
            for _ in 0..faces {
                let k: Vec<u32> = lines
                    .next()
                    .unwrap()
                    .split(' ')
                    .map(|x| x.parse().unwrap())
                    .collect();
                assert_eq!(k[0], 3);
                triangles.push([k[1], k[2], k[3]]);
            }
            assert_eq!(lines.next(), None);
        }
        "binary_little_endian" => {
            let f64_at = |o: usize| f64::from_le_bytes(body[o..o + 8].try_into().unwrap());
            for v in 0..vertices {
                let xs: Vec<f64> = (0..8).map(|q| f64_at(64 * v + 8 * q)).collect();
                push_vertex(&xs);
            }
            let mut o = 64 * vertices;
            for _ in 0..faces {
                assert_eq!(body[o], 3);
                let u = |q: usize| u32::from_le_bytes(body[q..q + 4].try_into().unwrap());
                triangles.push([u(o + 1), u(o + 5), u(o + 9)]);
                o += 13;
            }
            assert_eq!(o, body.len());
        }
        other => panic!("format {other}"),
    }
    r.triangles = triangles;
    r
}

/// Binary STL: 80 bytes of header, a `u32` count, then per triangle 12 `f32`s (normal, three
/// vertices) and a `u16`.
fn read_stl(bytes: &[u8]) -> Vec<[Vector3<f32>; 4]> {
    assert!(
        !bytes.starts_with(b"solid"),
        "a binary STL must not look like ASCII"
    );
    let n = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(bytes.len(), 84 + 50 * n);
    (0..n)
        .map(|t| {
            let f = |q: usize| {
                let o = 84 + 50 * t + 4 * q;
                f32::from_le_bytes(bytes[o..o + 4].try_into().unwrap())
            };
            let v = |q: usize| Vector3::new(f(3 * q), f(3 * q + 1), f(3 * q + 2));
            [v(0), v(1), v(2), v(3)]
        })
        .collect()
}

#[test]
fn obj_reads_back_exactly() {
    for m in [torus_mesh(), sphere_mesh()] {
        let r = read_obj(&export::obj(&m));
        assert_eq!(r.positions, m.positions());
        assert_eq!(r.normals, m.normals());
        assert_eq!(r.uvs, m.uvs());
        assert_eq!(r.triangles, m.triangles());
    }
}

#[test]
fn ply_reads_back_exactly_in_both_encodings() {
    for m in [torus_mesh(), sphere_mesh()] {
        for encoding in [PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian] {
            let r = read_ply(&export::ply(&m, encoding));
            assert_eq!(r.positions, m.positions(), "{encoding:?}");
            assert_eq!(r.normals, m.normals(), "{encoding:?}");
            assert_eq!(r.uvs, m.uvs(), "{encoding:?}");
            assert_eq!(r.triangles, m.triangles(), "{encoding:?}");
        }
    }
}

#[test]
fn stl_holds_the_triangles_as_floats_with_unit_normals() {
    for m in [torus_mesh(), sphere_mesh()] {
        let facets = read_stl(&export::stl(&m).unwrap());
        assert_eq!(facets.len(), m.triangles().len());
        for (f, t) in facets.iter().zip(m.triangles()) {
            for q in 0..3 {
                let want = m.positions()[t[q] as usize].map(|x| x as f32);
                assert_eq!(f[q + 1], want);
            }
            let n = f[0].map(f64::from);
            assert!((n.norm() - 1.0).abs() < 1e-6);
            let (a, b, c) = (
                f[1].map(f64::from),
                f[2].map(f64::from),
                f[3].map(f64::from),
            );
            let face = (b - a).cross(&(c - a));
            if face.norm() > 1e-6 {
                assert!(face.dot(&n) > 0.0);
            }
        }
    }
}

#[test]
fn files_are_written_atomically_and_completely() {
    let dir = tempfile::tempdir().unwrap();
    let m = torus_mesh();
    let path = dir.path().join("torus.obj");
    export::save(&path, export::obj(&m).as_bytes()).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    assert_eq!(read_obj(&text).positions, m.positions());
    // nothing else left beside it
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    // a folder that does not exist: a typed error, no file
    let bad = dir.path().join("missing").join("x.stl");
    assert!(export::save(&bad, b"x").is_err());
    assert!(!bad.exists());
}

// ---------------------------------------------------------------------------------------------
// curves as cubic Béziers and SVG paths
// ---------------------------------------------------------------------------------------------

mod curves {
    use nalgebra::Vector2;
    use splinelab::bezier::from_curve::{bezier_point, cubic_segments, CubicSegment};
    use splinelab::report::export;
    use splinelab::{
        AngularSpline, BSplineCurve, CardinalSpline, CubicSpline, EndCondition, Error, NurbsCurve,
        ParametricCurve, Parametrization, PiecewiseLinear,
    };

    fn points() -> Vec<Vector2<f64>> {
        [
            (0.0, 0.0),
            (1.0, 2.0),
            (3.0, 2.5),
            (4.0, 0.5),
            (6.0, 1.0),
            (7.0, 3.0),
        ]
        .iter()
        .map(|&(x, y)| Vector2::new(x, y))
        .collect()
    }

    /// The largest distance between the segments and the curve over 64 parameters of each
    /// segment, the segments' parameters found from the curve's pieces in order.
    fn deviation<C: ParametricCurve<2>>(c: &C, segments: &[CubicSegment<2>]) -> f64 {
        let (a, b) = c.domain();
        let dense: Vec<Vector2<f64>> = (0..=20_000)
            .map(|k| c.point(a + (b - a) * k as f64 / 20_000.0))
            .collect();
        // distances to the dense polyline's segments (its chords stray ≲ 1e-7 from the curve)
        let tree = splinelab::metrics::curve::SegmentTree::new(&dense).unwrap();
        let mut worst: f64 = 0.0;
        for s in segments {
            for k in 0..=64 {
                worst = worst.max(tree.distance(bezier_point(s, k as f64 / 64.0)));
            }
        }
        worst
    }

    #[test]
    fn cubic_pieces_convert_exactly_one_segment_each() {
        let p = points();
        let cubic =
            CubicSpline::curve(&p, Parametrization::ChordLength, EndCondition::Natural).unwrap();
        let cardinal = CardinalSpline::try_new(p.clone(), 0.5).unwrap();
        let bspline = BSplineCurve::with_order(p.clone(), 4).unwrap();
        let linear = PiecewiseLinear::curve(&p, Parametrization::Uniform).unwrap();
        let tol = 1e-9;
        let check = |name: &str,
                     c: &dyn Fn(f64) -> Vector2<f64>,
                     pieces: Vec<(f64, f64)>,
                     s: Vec<CubicSegment<2>>| {
            assert_eq!(s.len(), pieces.len(), "{name}: one segment per piece");
            for ((a, b), seg) in pieces.iter().zip(&s) {
                for k in 0..=32 {
                    let u = k as f64 / 32.0;
                    let e = (bezier_point(seg, u) - c(a + u * (b - a))).norm();
                    assert!(e < 1e-12, "{name}: {e:e} at u = {u}");
                }
            }
        };
        fn pieces<C: ParametricCurve<2>>(c: &C) -> Vec<(f64, f64)> {
            let (mut a, end) = c.domain();
            let mut out = Vec::new();
            while a < end {
                let b = c.span_at(a).map_or(end, |s| s.hi.min(end));
                out.push((a, b));
                a = b;
            }
            out
        }
        check(
            "cubic",
            &|t| cubic.point(t),
            pieces(&cubic),
            cubic_segments(&cubic, tol).unwrap(),
        );
        check(
            "cardinal",
            &|t| cardinal.point(t),
            pieces(&cardinal),
            cubic_segments(&cardinal, tol).unwrap(),
        );
        check(
            "B-spline",
            &|t| bspline.point(t),
            pieces(&bspline),
            cubic_segments(&bspline, tol).unwrap(),
        );
        check(
            "linear",
            &|t| linear.point(t),
            pieces(&linear),
            cubic_segments(&linear, tol).unwrap(),
        );
    }

    #[test]
    fn other_pieces_are_halved_to_the_tolerance() {
        let circle = NurbsCurve::circle9(Vector2::new(1.0, -2.0), 3.0).unwrap();
        let angular = AngularSpline::try_new(points()).unwrap();
        for tol in [1e-3, 1e-6, 1e-9] {
            let s = cubic_segments(&circle, tol).unwrap();
            let e = deviation(&circle, &s);
            assert!(e <= 2.0 * tol + 1e-7, "circle, tol {tol:e}: {e:e}");
            for seg in &s {
                for k in 0..=16 {
                    let r = (bezier_point(seg, k as f64 / 16.0) - Vector2::new(1.0, -2.0)).norm();
                    assert!(
                        (r - 3.0).abs() <= 2.0 * tol,
                        "circle radius off by {:e}",
                        r - 3.0
                    );
                }
            }
            let s = cubic_segments(&angular, tol).unwrap();
            let e = deviation(&angular, &s);
            assert!(e <= 2.0 * tol + 1e-7, "Angular, tol {tol:e}: {e:e}");
        }
    }

    #[test]
    fn bad_tolerances_are_typed_errors() {
        let c = CardinalSpline::try_new(points(), 0.5).unwrap();
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                cubic_segments(&c, bad),
                Err(Error::NotPositive { .. })
            ));
        }
        // below the rounding of a circle's own points: refused after the halvings, no hang
        let circle = NurbsCurve::circle9(Vector2::new(0.0, 0.0), 1e6).unwrap();
        assert!(matches!(
            cubic_segments(&circle, 1e-300),
            Err(Error::NoConvergence { .. })
        ));
    }

    /// SVG path data read back: `M`, `C` and `Z` as the SVG specification defines them
    /// (absolute commands), the segments recovered exactly.
    fn read_path(d: &str) -> Vec<CubicSegment<2>> {
        let tokens: Vec<&str> = d.split_whitespace().collect();
        let (mut k, mut at, mut out) = (0, Vector2::zeros(), Vec::new());
        let num = |s: &str| s.parse::<f64>().unwrap();
        while k < tokens.len() {
            match tokens[k] {
                "M" => {
                    at = Vector2::new(num(tokens[k + 1]), num(tokens[k + 2]));
                    k += 3;
                }
                "C" => {
                    let p = |q: usize| {
                        Vector2::new(num(tokens[k + 1 + 2 * q]), num(tokens[k + 2 + 2 * q]))
                    };
                    let seg = [at, p(0), p(1), p(2)];
                    at = seg[3];
                    out.push(seg);
                    k += 7;
                }
                "Z" => k += 1,
                other => panic!("unexpected path token {other}"),
            }
        }
        out
    }

    #[test]
    fn svg_path_reads_back_exactly_and_closes_closed_curves() {
        let closed = CardinalSpline::closed(&points(), 0.5).unwrap();
        let s = cubic_segments(&closed, 1e-9).unwrap();
        let d = export::svg_path(&s);
        assert!(d.starts_with("M ") && d.ends_with(" Z"), "{d}");
        assert_eq!(read_path(&d), s);
        let open = CubicSpline::curve(
            &points(),
            Parametrization::Centripetal,
            EndCondition::Natural,
        )
        .unwrap();
        let s = cubic_segments(&open, 1e-9).unwrap();
        let d = export::svg_path(&s);
        assert!(!d.ends_with('Z'));
        assert_eq!(read_path(&d), s);
        let doc = export::svg_document(&s, 0.05).unwrap();
        assert!(doc.starts_with("<svg ") && doc.contains(&format!("d=\"{d}\"")));
    }
}

/// A user's glyph (issue 29): any character of any font file, the shipped letter "a" the same
/// as the seed-004 study's; a glyph the font lacks, a glyph without outline and bytes that are
/// no font are typed errors naming the character.
#[test]
fn glyphs_of_a_font_file() {
    use splinelab::input::font::glyph;
    use splinelab::seeds::letters::letter_a;
    let font = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/fonts/DejaVuSans.ttf"
    ))
    .unwrap();
    assert_eq!(glyph(&font, 'a').unwrap(), letter_a(1).unwrap().contours);
    let b = glyph(&font, 'B').unwrap();
    assert_eq!(b.len(), 3, "B: the outer contour and two counters");
    for c in &b {
        assert_eq!(c.outline.first(), c.outline.last());
        assert!(c.points.iter().all(|p| p.x.is_finite() && p.y.is_finite()));
    }
    for (bytes, ch) in [
        (&font[..], '\u{10FFFF}'),
        (&font[..], ' '),
        (&b"not a font"[..], 'a'),
        (&[][..], 'a'),
    ] {
        let e = glyph(bytes, ch).unwrap_err().to_string();
        assert!(e.contains(&format!("{ch:?}")), "{e}");
    }
}
