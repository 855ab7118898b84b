//! mesh and input: Mesh::try_of_surface, the mesh files, points from CSV and SVG paths
//! (issue 29)

use super::*;
use splinelab::Mesh;

pub(super) fn cases() -> Vec<Case> {
    let mut all = vec![
        case("mesh::one_sample", || {
            expect_err!(
                Mesh::try_of_surface(&Torus::default(), &Rect::unit(), 1, 4),
                Error::TooFewSamples { .. }
            )
        }),
        case("mesh::zero_samples", || {
            expect_err!(
                Mesh::try_of_surface(&Torus::default(), &Rect::unit(), 4, 0),
                Error::TooFewSamples { .. }
            )
        }),
        risky("mesh::usize_max_samples", || {
            expect_err!(
                Mesh::try_of_surface(&Torus::default(), &Rect::unit(), usize::MAX, usize::MAX),
                Error::TooLarge { .. }
            )
        }),
        risky("mesh::max_elements_plus_one", || {
            expect_err!(
                Mesh::try_of_surface(&Torus::default(), &Rect::unit(), MAX_ELEMENTS + 1, 2),
                Error::TooLarge { .. }
            )
        }),
        case("mesh::nan_surface", || {
            let s = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                Vector3::new(s, t, (s - 0.5).sqrt())
            });
            expect_err!(
                Mesh::try_of_surface(&s, &Rect::unit(), 5, 5),
                Error::NonFiniteSurface { .. }
            )
        }),
        case("mesh::a_curve_has_no_normals", || {
            let s =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s + t, s + t, s + t));
            expect_err!(
                Mesh::try_of_surface(&s, &Rect::unit(), 5, 5),
                Error::Degenerate { .. }
            )
        }),
        case("mesh::poles_get_normals", || {
            let rect = Rect::new(0.0, std::f64::consts::TAU, -1.6, 1.6);
            let m = ok(Mesh::try_of_surface(&Sphere::new(1.0), &rect, 9, 9))?;
            ensure!(
                m.normals().iter().all(|n| (n.norm() - 1.0).abs() < 1e-12),
                "a normal is not a unit vector"
            );
            Ok(())
        }),
        case("mesh::tiny_and_huge_scales", || {
            for scale in [1e-300, 1e-150, 1e150, 1e300] {
                let s = FnSurface::new(move |s: HyperDual64, t: HyperDual64| {
                    Vector3::new(s * scale, t * scale, s * t * scale)
                });
                let m = ok(Mesh::try_of_surface(&s, &Rect::unit(), 4, 4))?;
                ensure!(
                    m.normals().iter().all(|n| (n.norm() - 1.0).abs() < 1e-12),
                    "scale {scale:e}: a normal is not a unit vector"
                );
            }
            Ok(())
        }),
        case("mesh::bezier_conversion_bad_tolerances", || {
            use splinelab::bezier::from_curve::cubic_segments;
            let c = ok(CardinalSpline::try_new(some_points(5), 0.5))?;
            for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                expect_err!(cubic_segments(&c, bad), Error::NotPositive { .. })?;
            }
            Ok(())
        }),
        case("mesh::bezier_conversion_below_rounding", || {
            use splinelab::bezier::from_curve::cubic_segments;
            let circle = ok(NurbsCurve::circle9(v2(0.0, 0.0), 1e6))?;
            expect_err!(cubic_segments(&circle, 5e-324), Error::NoConvergence { .. })
        }),
        case("input::csv_points_refusals", || {
            use splinelab::input::{points_from_csv, Columns};
            for text in ["0,1\n2,inf\n", "0,1\n2\n", "a,b\n0,1\nc,d\n", "0,1e999\n"] {
                expect_err!(
                    points_from_csv::<2>(text, &Columns::First),
                    Error::Parse { .. }
                )?;
            }
            for text in ["", "x,y\n", "# nothing\n"] {
                expect_err!(
                    points_from_csv::<2>(text, &Columns::First),
                    Error::TooFewPoints { .. }
                )?;
            }
            expect_err!(
                points_from_csv::<2>("0,1\n", &Columns::Indices(vec![usize::MAX, 0])),
                Error::Parse { .. }
            )
        }),
        case("input::svg_path_refusals", || {
            use splinelab::input::contours_from_svg_path;
            for d in [
                "M 0",
                "L 1 1",
                "M 0 0 A 1 1 0 0 1 2 2",
                "M 0 0 X",
                "M 0 0 L 1e999 0",
                "M\u{0}",
            ] {
                expect_err!(contours_from_svg_path(d, 1e-3), Error::Parse { .. })?;
            }
            for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
                expect_err!(
                    contours_from_svg_path("M 0 0 L 1 1", bad),
                    Error::NotPositive { .. }
                )?;
            }
            Ok(())
        }),
    ];
    all.extend(report_cases());
    all
}

#[cfg(not(feature = "report"))]
fn report_cases() -> Vec<Case> {
    Vec::new()
}

#[cfg(feature = "report")]
fn report_cases() -> Vec<Case> {
    use splinelab::report::export;
    vec![
        case("mesh::stl_refuses_what_a_float_cannot_hold", || {
            let s =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s * 1e300, t, s * t));
            let m = ok(Mesh::try_of_surface(&s, &Rect::unit(), 3, 3))?;
            expect_err!(
                export::stl(&m),
                splinelab::report::Error::Core(Error::Overflow { .. })
            )
        }),
        case("input::glyph_refusals", || {
            use splinelab::report::seed004::letters::glyph;
            let font: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
            for (bytes, ch) in [
                (font, '\u{10FFFF}'),
                (font, ' '),
                (&b"\0\0\0\0garbage"[..], 'a'),
                (&[][..], 'a'),
                (&font[..100], 'a'),
            ] {
                expect_err!(glyph(bytes, ch), splinelab::report::Error::Figure { .. })?;
            }
            Ok(())
        }),
        case("mesh::save_into_a_missing_folder", || {
            let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
            let path = dir.path().join("missing").join("m.obj");
            ensure!(
                export::save(&path, b"v 0 0 0\n").is_err(),
                "saved into nothing"
            );
            ensure!(!path.exists(), "a file was left");
            Ok(())
        }),
    ]
}
