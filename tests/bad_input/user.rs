//! user (feature `report`): the report layer's user functions (`splinelab::report::user`):
//! reading outline files within a size limit, fits and their printed formulas, the outline
//! search's requests, surface meshes

use super::*;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(outline_file_cases());
    all.extend(fit_cases());
    all.extend(request_cases());
    all
}

/// Reading outline files: the size limit, CSV, SVG documents, paths, fonts.
fn outline_file_cases() -> Vec<Case> {
    vec![
        case("user::file_size_limit_while_reading", || {
            use splinelab::report::user::outline::read_bytes_within;
            let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
            let zero = dir.path().join("zero.svg");
            std::os::unix::fs::symlink("/dev/zero", &zero).map_err(|e| e.to_string())?;
            expect_err!(
                read_bytes_within(&zero, 4096),
                splinelab::report::Error::Io { .. }
            )
        }),
        case("user::outline_files", || {
            use splinelab::report::user::outline::{read_outline, ReadOptions};
            let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
            let font = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/DejaVuSans.ttf");
            let million: String = (0..1_000_000).map(|i| format!("{i},{}\n", i % 7)).collect();
            let files: [(&str, Vec<u8>); 12] = [
                ("empty.csv", Vec::new()),
                ("nan.csv", b"0,0\n1,NaN\n2,2\n".to_vec()),
                ("inf.csv", b"0,0\n1,inf\n".to_vec()),
                ("ragged.csv", b"0,0\n1\n2,2\n".to_vec()),
                ("garbage.csv", vec![0xde, 0xad, 0xbe, 0xef, 0, 0xff]),
                ("empty.svg", Vec::new()),
                (
                    "unterminated.svg",
                    b"<svg xmlns='http://www.w3.org/2000/svg'><path d='M 0 0 L 1 1".to_vec(),
                ),
                (
                    "unterminated-tag.svg",
                    b"<svg xmlns='http://www.w3.org/2000/svg'><path d='M 0 0 L 1 1'".to_vec(),
                ),
                (
                    "no-d.svg",
                    b"<svg xmlns='http://www.w3.org/2000/svg'><path fill='none'/></svg>".to_vec(),
                ),
                ("unknown.path", b"M 0 0 L 1 1 W 2 2".to_vec()),
                ("short.path", b"M 0 0 C 1 1 2".to_vec()),
                ("garbage.svg", vec![0xff; 64]),
            ];
            for (name, bytes) in files {
                let path = dir.path().join(name);
                std::fs::write(&path, bytes).map_err(|e| e.to_string())?;
                ensure!(
                    read_outline(&path, &ReadOptions::default()).is_err(),
                    "{name} was read"
                );
            }
            // a million rows are read (one contour, no half-read)
            let big = dir.path().join("million.csv");
            std::fs::write(&big, million).map_err(|e| e.to_string())?;
            let c = ok(read_outline(&big, &ReadOptions::default()))?;
            ensure!(
                c[0].points.len() == 1_000_000,
                "{} points",
                c[0].points.len()
            );
            // a glyph the font lacks, a font without --glyph, an unknown kind, a missing file
            let lacks = ReadOptions {
                glyph: Some('\u{10FFFF}'),
                ..ReadOptions::default()
            };
            ensure!(
                read_outline(font.as_ref(), &lacks).is_err(),
                "a missing glyph was read"
            );
            ensure!(
                read_outline(font.as_ref(), &ReadOptions::default()).is_err(),
                "no glyph"
            );
            ensure!(
                read_outline("a.docx".as_ref(), &ReadOptions::default()).is_err(),
                "docx"
            );
            ensure!(
                read_outline(&dir.path().join("none.csv"), &ReadOptions::default()).is_err(),
                "missing"
            );
            for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                let p = dir.path().join("ok.path");
                std::fs::write(&p, b"M 0 0 Q 1 1 2 0").map_err(|e| e.to_string())?;
                let o = ReadOptions {
                    flatten: Some(bad),
                    ..ReadOptions::default()
                };
                ensure!(read_outline(&p, &o).is_err(), "flatten {bad}");
            }
            Ok(())
        }),
    ]
}

/// `Fit`: refused requests, samples, formulas.
fn fit_cases() -> Vec<Case> {
    vec![
        case("user::formulas_checked_over_their_range", || {
            use splinelab::report::user::fit::{Fit, FormulaStyle};
            // an inflection piece prints two arcs, each checked on its own range
            let pts: Vec<Vector2<f64>> = [(0.0, 0.0), (1.0, 0.0), (2.0, 1.0), (3.0, 1.0)]
                .iter()
                .map(|&(x, y)| v2(x, y))
                .collect();
            let fit =
                Fit::try_new(&pts, splinelab::Method::Angular, false).map_err(|e| e.to_string())?;
            let text = fit
                .formulas(FormulaStyle::Plain)
                .map_err(|e| e.to_string())?;
            ensure!(text.contains("arc 2 of 2"), "{text}");
            Ok(())
        }),
        case("user::fit", || {
            use splinelab::report::user::fit::Fit;
            let pts: Vec<Vector2<f64>> = [(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (3.0, 1.0)]
                .map(|(x, y)| Vector2::new(x, y))
                .to_vec();
            let mut dup = pts.clone();
            dup[1] = dup[0];
            let mut nan = pts.clone();
            nan[2].x = f64::NAN;
            let huge: Vec<Vector2<f64>> = pts.iter().map(|p| p * 1e300).collect();
            for (points, method, closed) in [
                (&pts[..0], splinelab::Method::Linear, false),
                (&pts[..1], splinelab::Method::Angular, true),
                (
                    &nan[..],
                    splinelab::Method::Cubic {
                        end: splinelab::CubicEnd::Relaxed,
                    },
                    false,
                ),
                (&dup[..], splinelab::Method::Angular, false),
                (&pts[..], splinelab::Method::Cardinal { a: -1.0 }, false),
                (
                    &pts[..],
                    splinelab::Method::Cardinal { a: f64::INFINITY },
                    true,
                ),
                (&pts[..], splinelab::Method::BSpline { order: 1 }, false),
                (
                    &pts[..],
                    splinelab::Method::BSpline { order: usize::MAX },
                    false,
                ),
            ] {
                ensure!(
                    Fit::try_new(points, method, closed).is_err(),
                    "{method:?} {closed} accepted"
                );
            }
            // huge coordinates: a curve or a typed error, never a NaN curve
            if let Ok(fit) = Fit::try_new(
                &huge,
                splinelab::Method::Cubic {
                    end: splinelab::CubicEnd::Relaxed,
                },
                false,
            ) {
                if let Ok(s) = fit.samples(4) {
                    ensure!(
                        s.iter().all(|(_, p)| p.iter().all(|v| v.is_finite())),
                        "a NaN sample"
                    );
                }
            }
            let fit = ok(Fit::try_new(&pts, splinelab::Method::Linear, false))?;
            ensure!(
                fit.samples(0).is_err() && fit.samples(usize::MAX).is_err(),
                "samples"
            );
            ensure!(
                fit.bezier(f64::NAN).is_err() && fit.bezier(-1.0).is_err(),
                "tolerance"
            );
            Ok(())
        }),
    ]
}

/// Requests refused: the outline search's (`fewest`, `fewest_in_stages`, tolerances) and
/// the surface meshes' (partitions, built-in surfaces, formats).
fn request_cases() -> Vec<Case> {
    vec![case("user::surface_requests", || {
        use splinelab::report::user::surface::{BuiltIn, MeshFormat, PartitionSpec, SurfaceMesh};
        for p in [
            "",
            "x",
            "3x",
            "x3",
            "0x2",
            "2x0",
            "axb",
            "3x3x3",
            "99999999999999999999x2",
        ] {
            let parsed = p.parse::<PartitionSpec>();
            ensure!(
                parsed.is_err()
                    || parsed
                        .ok()
                        .and_then(|s| s.partitions(&BuiltIn::Exp).ok())
                        .is_none(),
                "{p:?}"
            );
        }
        for (s, t) in [
            (vec![], vec![0.0, 1.0]),
            (vec![1.0, 0.0], vec![0.0, 1.0]),
            (vec![0.0, f64::NAN], vec![0.0, 1.0]),
        ] {
            ensure!(
                PartitionSpec::Nodes(s, t)
                    .partitions(&BuiltIn::Exp)
                    .is_err(),
                "nodes"
            );
        }
        let (s, t) = ok("2x2"
            .parse::<PartitionSpec>()
            .map_err(|e| e.to_string())
            .and_then(|p| p.partitions(&BuiltIn::Exp).map_err(|e| e.to_string())))?;
        for (surface, steps) in [
            (BuiltIn::Exp, 0),
            (BuiltIn::Exp, usize::MAX),
            (
                BuiltIn::Torus {
                    major: f64::NAN,
                    minor: 1.0,
                },
                2,
            ),
            (
                BuiltIn::Torus {
                    major: 1.0,
                    minor: 0.0,
                },
                2,
            ),
            (
                BuiltIn::Sphere {
                    radius: f64::INFINITY,
                },
                2,
            ),
            (BuiltIn::Sphere { radius: 1e308 }, 2),
        ] {
            ensure!(
                SurfaceMesh::try_new(&surface, s.clone(), t.clone(), steps).is_err(),
                "{surface:?} {steps}"
            );
        }
        // the exp surface on huge nodes overflows: a typed error
        let far = PartitionSpec::Nodes(vec![0.0, 800.0], vec![0.0, 1.0]);
        let (s, t) = ok(far.partitions(&BuiltIn::Exp))?;
        ensure!(
            SurfaceMesh::try_new(&BuiltIn::Exp, s, t, 2).is_err(),
            "exp(800)"
        );
        for name in ["a", "a.", "a.gltf", "a.obj.gz", ""] {
            ensure!(
                MeshFormat::of_path(name.as_ref(), false).is_err(),
                "{name:?}"
            );
        }
        Ok(())
    })]
}
