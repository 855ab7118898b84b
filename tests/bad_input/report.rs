//! report: the file layer's typed errors

use super::*;

#[cfg(not(feature = "report"))]
pub(super) fn cases() -> Vec<Case> {
    Vec::new()
}

#[cfg(feature = "report")]
pub(super) fn cases() -> Vec<Case> {
    use splinelab::report::draw::{self, Plot2d, Plot3d};
    use splinelab::report::{self, Error as RError};
    vec![
        case("report::write_only_unknown_id", || {
            let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
            expect_err!(
                report::write_only(dir.path(), "no-such-output"),
                RError::UnknownId { id, .. } if id == "no-such-output"
            )?;
            expect_err!(report::write_only(dir.path(), ""), RError::UnknownId { .. })
        }),
        case("report::table_write_unwritable_folder", || {
            let (_dir, file) = plain_file()?;
            let table = ok(report::table("torus-partials"))?;
            expect_err!(table.write(&file), RError::Io { path, .. } if path.starts_with(&file))
        }),
        case("report::figure_save_unwritable_folder", || {
            let (_dir, file) = plain_file()?;
            let fig = ok(report::figure("fig2-torus"))?;
            expect_err!(fig.save(&file, "fig2-torus"), RError::Io { .. })
        }),
        case("report::write_only_unwritable_folder", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                report::write_only(&file, "torus-partials"),
                RError::Io { .. }
            )
        }),
        case("report::write_only_folder_below_a_file", || {
            // a folder below a file below a folder: never a panic
            let (_dir, file) = plain_file()?;
            let deeper: &Path = &file.join("a").join("b");
            expect_err!(
                report::write_only(deeper, "torus-partials"),
                RError::Io { .. }
            )
        }),
        case("report::figure_and_table_of_the_wrong_kind", || {
            expect_err!(report::figure("t3-error"), RError::UnknownId { .. })?;
            expect_err!(report::table("fig2-torus"), RError::UnknownId { .. })
        }),
        case("draw::surface_too_few_or_too_many_samples", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            for n in [0, 1] {
                expect_err!(
                    Plot3d::new("x").surface(&f, &Rect::unit(), n),
                    RError::Core(Error::TooFewSamples { .. })
                )?;
            }
            expect_err!(
                Plot3d::new("x").surface(&f, &Rect::unit(), 1 << 20),
                RError::Core(Error::TooLarge { .. })
            )
        }),
        case("draw::surface_nan_anywhere", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, (s - 0.5).ln()));
            expect_err!(
                Plot3d::new("x").surface(&f, &Rect::unit(), 11),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("draw::error_map_bad_samples_and_nan_surface", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            let spline = ok(HermiteSurface::uniform(&f, &Rect::unit(), 2, 2))?;
            expect_err!(
                draw::error_map(&f, &spline, 1),
                RError::Core(Error::TooFewSamples { .. })
            )?;
            let g = FnSurface::new(|s, t| Vector3::new(s, t, (s - 0.3).sqrt()));
            expect_err!(
                draw::error_map(&g, &spline, 11),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("draw::degenerate_data_draws_without_panic", || {
            // empty, NaN, infinite and single-point series; empty studies and scenes
            let nan = Plot2d::new("nan", "x", "y")
                .series("empty", vec![])
                .series(
                    "nan",
                    vec![(f64::NAN, 1.0), (f64::INFINITY, 2.0), (1.0, f64::NAN)],
                )
                .series("one", vec![(1.0, 1.0)])
                .log(true, true)
                .figure();
            ok(nan.to_svg())?;
            ok(draw::convergence(&[], "empty").to_svg())?;
            ok(Plot3d::new("empty scene").figure().to_svg())?;
            ok(Plot3d::new("one point")
                .points(
                    &[Vector3::new(f64::NAN, 0.0, 1.0), Vector3::zeros()],
                    RGB_BLACK,
                    "p",
                )
                .figure()
                .to_svg())
            .map(|_| ())
        }),
        case(
            "figure::huge_size_is_clamped_and_drawn_within_memory",
            || {
                let fig = ok(report::figure("fig-bspline-bases"))?.with_size(u32::MAX, 0);
                if fig.size() != (splinelab::report::figure::MAX_SIDE, 64) {
                    return Err(format!("size {:?}", fig.size()));
                }
                ok(fig.to_rgb()).map(drop)
            },
        ),
        case("table::tabulation_bad_samples", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            expect_err!(
                report::table::tabulation(&f, &Rect::unit(), 1, 5),
                RError::Core(Error::TooFewSamples { .. })
            )?;
            expect_err!(
                report::table::tabulation(&f, &Rect::unit(), 1 << 14, 1 << 14),
                RError::Core(Error::TooLarge { .. })
            )
        }),
    ]
}

/// Black, for markers in the report cases.
#[cfg(feature = "report")]
const RGB_BLACK: plotters::style::RGBColor = plotters::style::RGBColor(0, 0, 0);
