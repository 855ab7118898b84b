//! mesh: Mesh::try_of_surface, and (feature `report`) the mesh files

use super::*;
use splinelab::Mesh;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(mesh_cases());
    all.extend(file_cases());
    all
}

/// `Mesh::try_of_surface` and the Bézier conversion of curves.
fn mesh_cases() -> Vec<Case> {
    vec![
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
    ]
}

#[cfg(not(feature = "report"))]
fn file_cases() -> Vec<Case> {
    Vec::new()
}

/// The mesh files: STL, saving (feature `report`).
#[cfg(feature = "report")]
fn file_cases() -> Vec<Case> {
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
