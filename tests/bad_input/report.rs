//! report (feature `report`): the file layer's typed errors (`report::write_only`, `figure`,
//! `table`), the `Figure` value and its outputs (sizes, files, layouts, heat maps), frames and
//! tables (Markdown, HTML, CSV, files, the tables built from studies)

use super::*;
use splinelab::report::draw::{self, Plot3d};
use splinelab::report::figure::MAX_SIDE;
use splinelab::report::heatmap::{ColorScale, HeatMap};
use splinelab::report::plot2d::MAX_PANELS;
use splinelab::report::table::{self, Table};
use splinelab::report::{self, frame};
use splinelab::CoordErrors;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(output_cases());
    all.extend(figure_cases());
    all.extend(layout_and_heatmap_cases());
    all.extend(frame_and_table_cases());
    all.extend(study_table_cases());
    all
}

/// `report::write_only`, `report::figure` and `report::table`: unknown ids, unwritable
/// folders.
fn output_cases() -> Vec<Case> {
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
    ]
}

fn simple_figure() -> Figure {
    series_figure(vec![(0.0, 0.0), (1.0, 2.0), (2.0, 1.0)])
}

fn tempdir() -> Result<tempfile::TempDir, String> {
    tempfile::tempdir().map_err(|e| format!("tempdir: {e}"))
}

/// The `Figure` value and its outputs: sizes, PNG and SVG files.
fn figure_cases() -> Vec<Case> {
    vec![
        case("report::with_size_zero_is_clamped_to_64", || {
            let fig = simple_figure().with_size(0, 0);
            ensure!(fig.size() == (64, 64), "{:?}", fig.size());
            let px = ok(fig.to_rgb())?;
            ensure!(px.len() == 64 * 64 * 3, "{} bytes", px.len());
            Ok(())
        }),
        risky("report::with_size_u32_max_both_sides", || {
            let fig = simple_figure().with_size(u32::MAX, u32::MAX);
            ensure!(fig.size() == (MAX_SIDE, MAX_SIDE), "{:?}", fig.size());
            let px = ok(fig.to_rgb())?;
            let side = MAX_SIDE as usize;
            ensure!(px.len() == side * side * 3, "{} bytes", px.len());
            Ok(())
        }),
        risky("report::to_rgb_huge_size_of_a_scene_and_a_map", || {
            let scene = Plot3d::new("scene")
                .points(&[v3(0.0, 0.0, 0.0), v3(1.0, 1.0, 1.0)], BLUE, "p")
                .figure()
                .with_size(u32::MAX, 1);
            ensure!(scene.size() == (MAX_SIDE, 64), "{:?}", scene.size());
            ok(scene.to_rgb())?;
            let map = heat(
                vec![0.0, 1.0],
                vec![0.0, 1.0],
                Grid::from_fn(2, 2, |i, j| (i + j) as f64),
                ColorScale::Linear,
            )
            .with_size(1, u32::MAX);
            ok(map.to_rgb()).map(drop)
        }),
        case("report::write_png_below_a_file", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                simple_figure().write_png(&file.join("f.png")),
                RError::Io { .. }
            )
        }),
        case("report::write_svg_below_a_file", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                simple_figure().write_svg(&file.join("f.svg")),
                RError::Io { .. }
            )
        }),
        case("report::save_below_a_file", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                simple_figure().save(&file.join("a").join("b"), "f"),
                RError::Io { .. }
            )
        }),
        case("report::save_stem_in_a_missing_folder", || {
            let dir = tempdir()?;
            expect_err!(
                simple_figure().save(dir.path(), "no-such-folder/f"),
                RError::Io { .. }
            )
        }),
        case("report::write_to_an_existing_directory", || {
            let dir = tempdir()?;
            expect_err!(simple_figure().write_png(dir.path()), RError::Io { .. })?;
            expect_err!(simple_figure().write_svg(dir.path()), RError::Io { .. })
        }),
        case("report::save_writes_a_png_of_its_size_and_an_svg", || {
            let dir = tempdir()?;
            let paths = ok(simple_figure().with_size(200, 100).save(dir.path(), "f"))?;
            ensure!(paths.len() == 2, "{paths:?}");
            let png = image::open(&paths[0]).map_err(|e| format!("png: {e}"))?;
            ensure!(
                (png.width(), png.height()) == (200, 100),
                "{}×{}",
                png.width(),
                png.height()
            );
            let svg = std::fs::read_to_string(&paths[1]).map_err(|e| e.to_string())?;
            ensure!(svg.contains("<svg"), "svg");
            Ok(())
        }),
        case(
            "report::huge_size_is_clamped_and_drawn_within_memory",
            || {
                let fig = ok(report::figure("fig-bspline-bases"))?.with_size(u32::MAX, 0);
                if fig.size() != (splinelab::report::figure::MAX_SIDE, 64) {
                    return Err(format!("size {:?}", fig.size()));
                }
                ok(fig.to_rgb()).map(drop)
            },
        ),
    ]
}

fn heat(x: Vec<f64>, y: Vec<f64>, values: Grid<f64>, scale: ColorScale) -> Figure {
    HeatMap {
        title: "map".into(),
        x_label: "x".into(),
        y_label: "y".into(),
        bar_label: "v".into(),
        x,
        y,
        values,
        x_lines: vec![f64::NAN, 0.5, f64::INFINITY, 1e300],
        y_lines: vec![-f64::MAX, 0.25],
        scale,
        footnote: Some("note".into()),
    }
    .into()
}

/// Figures of panels in a layout; heat maps.
fn layout_and_heatmap_cases() -> Vec<Case> {
    vec![
        case("report::layout_without_cells", || {
            for layout in [(0, 0), (0, 3), (3, 0)] {
                let fig = draw::panels("t", vec![Plot2d::new("p", "x", "y").panel()], layout);
                expect_err!(fig.to_svg(), RError::Figure { .. })?;
                expect_err!(fig.to_rgb(), RError::Figure { .. })?;
            }
            Ok(())
        }),
        risky("report::layout_usize_max", || {
            for layout in [
                (usize::MAX, usize::MAX),
                (usize::MAX, 1),
                (1 << 40, 1 << 40),
            ] {
                let fig = draw::panels("t", vec![Plot2d::new("p", "x", "y").panel()], layout);
                expect_err!(fig.to_svg(), RError::Figure { .. })?;
            }
            Ok(())
        }),
        case("report::layout_max_panels", || {
            let one = || {
                vec![Plot2d::new("p", "x", "y")
                    .series("s", vec![(0.0, 1.0)])
                    .panel()]
            };
            expect_err!(
                draw::panels("t", one(), (1, MAX_PANELS + 1)).to_svg(),
                RError::Figure { .. }
            )?;
            ok(draw::panels("t", one(), (32, 32)).to_svg()).map(drop)
        }),
        case("report::more_cells_or_more_panels_than_the_layout", || {
            let panel = || {
                Plot2d::new("p", "x", "y")
                    .series("s", vec![(0.0, 1.0), (1.0, 0.0)])
                    .panel()
            };
            draws(draw::panels("few", vec![panel()], (3, 3)))?;
            draws(draw::panels(
                "many",
                (0..7).map(|_| panel()).collect(),
                (1, 2),
            ))?;
            draws(draw::panels("none", vec![], (2, 2)))
        }),
        case("report::very_long_and_empty_titles", || {
            draws(draw::panels("", vec![], (1, 1)))?;
            let long = "a very long title ".repeat(600);
            draws(Plot2d::new(long, "x", "y").figure())
        }),
        case("report::heatmap_non_finite_values", || {
            let v = [
                f64::NAN,
                f64::INFINITY,
                f64::NEG_INFINITY,
                0.0,
                5e-324,
                f64::MAX,
            ];
            for scale in [ColorScale::Linear, ColorScale::Log { decades: 4.0 }] {
                drawable(heat(
                    vec![0.0, 1.0, 2.0],
                    vec![0.0, 1.0],
                    Grid::from_fn(3, 2, |i, j| v[2 * i + j]),
                    scale,
                ))?;
            }
            Ok(())
        }),
        case("report::heatmap_mismatched_and_empty", || {
            drawable(heat(
                vec![0.0, 1.0, 2.0, 3.0],
                vec![0.0],
                Grid::from_fn(2, 5, |i, j| (i * j) as f64),
                ColorScale::Linear,
            ))?;
            drawable(heat(
                vec![],
                vec![],
                Grid::from_fn(0, 0, |_, _| 0.0),
                ColorScale::Log { decades: 3.0 },
            ))
        }),
        case("report::heatmap_log_scale_degenerate_decades", || {
            for decades in [f64::NAN, -1.0, 0.0, 1e300, f64::INFINITY] {
                drawable(heat(
                    vec![0.0, 1.0],
                    vec![0.0, 1.0],
                    Grid::from_fn(2, 2, |_, _| 0.0),
                    ColorScale::Log { decades },
                ))
                .map_err(|e| format!("{decades} decades: {e}"))?;
            }
            Ok(())
        }),
        risky("report::heatmap_extreme_axes", || {
            for (x, y) in [
                (vec![-f64::MAX, f64::MAX], vec![0.0, 1e-300]),
                (vec![0.0, 5e-324], vec![f64::NAN, 1.0]),
                (vec![1e300, 1e300], vec![-1e300, 1e300]),
            ] {
                drawable(heat(
                    x,
                    y,
                    Grid::from_fn(2, 2, |i, j| (i + 2 * j) as f64 * 1e300),
                    ColorScale::Linear,
                ))?;
            }
            Ok(())
        }),
    ]
}

fn extreme_frame() -> Result<frame::Frame, String> {
    use frame::Column;
    ok(frame::frame(
        "extreme",
        vec![
            Column::new(
                "v".into(),
                vec![
                    f64::NAN,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::MAX,
                    5e-324,
                    -0.0,
                    0.1 + 0.2,
                ],
            ),
            Column::new(
                "name".into(),
                vec!["a", "<b>", "c|d", "e,f", "\"g\"", "", "ü"],
            ),
        ],
    ))
}

/// Frames and tables: Markdown, HTML, CSV, files.
fn frame_and_table_cases() -> Vec<Case> {
    use frame::Column;
    vec![
        case("report::frame_mismatched_lengths", || {
            expect_err!(
                frame::frame(
                    "t",
                    vec![
                        Column::new("a".into(), vec![1.0, 2.0]),
                        Column::new("b".into(), vec![1.0]),
                    ]
                ),
                RError::Table { .. }
            )
        }),
        case("report::frame_duplicate_names", || {
            expect_err!(
                frame::frame(
                    "t",
                    vec![
                        Column::new("a".into(), vec![1.0]),
                        Column::new("a".into(), vec![2.0]),
                    ]
                ),
                RError::Table { .. }
            )
        }),
        case("report::try_new_ragged_third_column", || {
            let got = frame::Frame::try_new(vec![
                Column::new("a".into(), vec![1.0, 2.0]),
                Column::new("b".into(), vec!["x", "y"]),
                Column::new("c".into(), vec![Some(true)]),
            ]);
            match got {
                Err(frame::FrameError::Ragged {
                    name,
                    len: 1,
                    height: 2,
                    ..
                }) if name == "c" => Ok(()),
                other => Err(format!("{other:?}")),
            }
        }),
        case("report::try_new_names_repeated_apart", || {
            let got = frame::Frame::try_new(vec![
                Column::new("a".into(), vec![1u32]),
                Column::new("b".into(), vec![2i64]),
                Column::new("a".into(), vec![3usize]),
            ]);
            match got {
                Err(frame::FrameError::DuplicateName(n)) if n == "a" => Ok(()),
                other => Err(format!("{other:?}")),
            }
        }),
        case("report::try_new_zero_rows", || {
            let f = ok(frame::Frame::try_new(vec![
                Column::new("a".into(), Vec::<f64>::new()),
                Column::new("b".into(), Vec::<Option<String>>::new()),
            ]))?;
            ensure!(f.shape() == (0, 2), "{:?}", f.shape());
            ensure!(f.columns()[0].get(0).is_none(), "a cell past the end");
            let csv = ok(table::csv(&f))?;
            ensure!(csv == b"a,b\n", "{:?}", String::from_utf8_lossy(&csv));
            Ok(())
        }),
        case("report::frame_of_nothing", || {
            let df = ok(frame::frame("empty", vec![]))?;
            let t = Table::new("empty", "", df.clone());
            ok(t.to_markdown())?;
            ok(t.to_html())?;
            ok(table::csv(&df))?;
            let (names, rows) = ok(table::display_rows(&df))?;
            ensure!(names.is_empty() && rows.is_empty(), "{names:?} {rows:?}");
            Ok(())
        }),
        case("report::non_finite_cells_in_every_format", || {
            let df = extreme_frame()?;
            let md = ok(table::markdown(&df))?;
            ensure!(md.contains("NaN") && md.contains("inf"), "{md}");
            let html = ok(table::html_table(&df))?;
            ensure!(!html.contains("<b>"), "unescaped cell: {html}");
            let csv = String::from_utf8(ok(table::csv(&df))?).map_err(|e| e.to_string())?;
            ensure!(csv.lines().count() == 8, "{csv}");
            Ok(())
        }),
        case("report::csv_keeps_full_precision", || {
            let df = extreme_frame()?;
            let csv = String::from_utf8(ok(table::csv(&df))?).map_err(|e| e.to_string())?;
            let values: Vec<f64> = csv
                .lines()
                .skip(1)
                .filter_map(|l| l.split(',').next()?.parse().ok())
                .collect();
            for want in [f64::MAX, 5e-324, 0.1 + 0.2] {
                ensure!(values.contains(&want), "{want:e} not read back from {csv}");
            }
            Ok(())
        }),
        case("report::html_escapes_title_and_notes", || {
            let t = Table::new("t", "<script>x</script>", ok(frame::frame("t", vec![]))?)
                .note("a & b < c");
            let html = ok(t.to_html())?;
            ensure!(
                !html.contains("<script>") && !html.contains("a & b"),
                "{html}"
            );
            Ok(())
        }),
        case("report::write_below_a_file", || {
            let (_dir, file) = plain_file()?;
            let t = Table::new("t", "t", extreme_frame()?);
            expect_err!(t.write(&file.join("sub")), RError::Io { .. })?;
            expect_err!(
                table::write_csv(&t.df, &file.join("t.csv")),
                RError::Io { .. }
            )
        }),
        case("report::write_an_id_in_a_missing_folder", || {
            let dir = tempdir()?;
            let t = Table::new("missing/t", "t", extreme_frame()?);
            expect_err!(t.write(dir.path()), RError::Io { .. })
        }),
        case("report::write_csv_to_a_directory", || {
            let dir = tempdir()?;
            expect_err!(
                table::write_csv(&extreme_frame()?, dir.path()),
                RError::Io { .. }
            )
        }),
        case("report::write_and_read_back", || {
            let dir = tempdir()?;
            let paths = ok(Table::new("t", "title", extreme_frame()?).write(dir.path()))?;
            ensure!(
                paths.len() == 2 && paths.iter().all(|p| p.exists()),
                "{paths:?}"
            );
            Ok(())
        }),
    ]
}

/// The tables built from studies: tabulation, coordinate errors, seam continuity,
/// error study.
fn study_table_cases() -> Vec<Case> {
    vec![
        case("report::tabulation_too_few_samples", || {
            for (ns, nt) in [(0, 5), (5, 1), (0, 0)] {
                expect_err!(
                    table::tabulation(&surface(), &Rect::unit(), ns, nt),
                    RError::Core(Error::TooFewSamples { .. })
                )?;
            }
            Ok(())
        }),
        risky("report::tabulation_huge_counts", || {
            for (ns, nt) in [
                (usize::MAX, 2),
                (2, 1 << 40),
                (1 << 32, 1 << 32),
                (MAX_ELEMENTS + 1, 2),
            ] {
                expect_err!(
                    table::tabulation(&surface(), &Rect::unit(), ns, nt),
                    RError::Core(Error::TooLarge { .. })
                )
                .map_err(|e| format!("{ns} × {nt}: {e}"))?;
            }
            Ok(())
        }),
        case("report::tabulation_of_a_nan_surface", || {
            let f =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, (s - 0.5).ln()));
            expect_err!(
                table::tabulation(&f, &Rect::unit(), 5, 5),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("report::study_tables_of_nothing", || {
            let t = ok(table::coord_errors("e", "t", &[]))?;
            ensure!(t.df.height() == 0, "{} rows", t.df.height());
            ok(t.to_markdown())?;
            let t = ok(table::convergence("c", "t", &[]))?;
            ensure!(t.df.height() == 0, "{} rows", t.df.height());
            let t = ok(table::error_study(&surface(), &Rect::unit(), &[], 5))?;
            ensure!(t.df.height() == 0, "{} rows", t.df.height());
            Ok(())
        }),
        case("report::coord_errors_non_finite", || {
            let e = CoordErrors {
                report_norm: v3(f64::NAN, f64::INFINITY, f64::NEG_INFINITY),
                max_abs: v3(f64::MAX, 5e-324, -0.0),
                rms: v3(1e-300, 0.0, 1.0),
            };
            let t = ok(table::coord_errors("e", "t", &[("bad".into(), e)]))?;
            ensure!(t.df.height() == 3, "{} rows", t.df.height());
            let md = ok(t.to_markdown())?;
            ensure!(md.contains("NaN"), "{md}");
            Ok(())
        }),
        case("report::seam_continuity_too_few_samples", || {
            let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 3))?;
            for n in [0, 1] {
                expect_err!(
                    table::seam_continuity(&s, n),
                    RError::Core(Error::TooFewSamples { .. })
                )?;
            }
            let t = ok(table::seam_continuity(&s, 5))?;
            ensure!(t.df.height() == 3, "{} seams", t.df.height());
            Ok(())
        }),
        risky("report::seam_continuity_huge_samples", || {
            let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
            for n in [usize::MAX, MAX_ELEMENTS + 1] {
                expect_err!(
                    table::seam_continuity(&s, n),
                    RError::Core(Error::TooLarge { .. })
                )?;
            }
            Ok(())
        }),
        case("report::error_study_bad_cases", || {
            expect_err!(
                table::error_study(&surface(), &Rect::unit(), &[(0, 1)], 5),
                RError::Core(Error::ZeroPatches { .. })
            )?;
            expect_err!(
                table::error_study(&surface(), &Rect::unit(), &[(2, 2)], 1),
                RError::Core(Error::TooFewSamples { what, .. }) if what.starts_with("prec")
            )
        }),
        risky("report::error_study_huge_cases", || {
            for case in [(usize::MAX, 1), (1 << 20, 1 << 20), (1, 1 << 40)] {
                expect_err!(
                    table::error_study(&surface(), &Rect::unit(), &[case], 5),
                    RError::Core(Error::TooLarge { .. })
                )
                .map_err(|e| format!("{case:?}: {e}"))?;
            }
            expect_err!(
                table::error_study(&surface(), &Rect::unit(), &[(2, 2)], usize::MAX),
                RError::Core(Error::TooLarge { .. })
            )
        }),
        case("report::tabulation_bad_samples", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            expect_err!(
                report::table::tabulation(&f, &Rect::unit(), 1, 5),
                RError::Core(Error::TooFewSamples { what, .. }) if *what == "ns"
            )?;
            expect_err!(
                report::table::tabulation(&f, &Rect::unit(), 1 << 14, 1 << 14),
                RError::Core(Error::TooLarge { .. })
            )
        }),
        case("report::seed_figures_with_nothing_to_draw", || {
            use splinelab::report::{seed001, seed003, seed004};
            expect_err!(seed004::figures::angular_pieces(&[]), RError::Figure { .. })?;
            expect_err!(
                seed004::figures::cardinal_a(&Shape::Circle, 4, &[]),
                RError::Figure { .. }
            )?;
            expect_err!(
                seed004::figures::cardinal_a(&Shape::Sinusoid { periods: 1.0 }, 4, &[0.5]),
                RError::Core(Error::Degenerate { .. })
            )?;
            expect_err!(
                seed004::figures::cardinal_a(&Shape::Circle, 0, &[0.5]),
                RError::Core(_)
            )?;
            expect_err!(
                seed004::figures::shape_methods(&Shape::Circle, &[]),
                RError::Figure { .. }
            )?;
            expect_err!(
                seed004::figures::sicily_decimated(7, &[]),
                RError::Figure { .. }
            )?;
            expect_err!(seed004::figures::bezier(&[]), RError::Core(_))?;
            expect_err!(seed001::figures::bspline_bases(&[]), RError::Figure { .. })?;
            expect_err!(seed001::figures::nurbs_circles(&[]), RError::Figure { .. })?;
            expect_err!(seed001::figures::parametrizations(&[]), RError::Core(_))?;
            expect_err!(
                seed001::figures::cubic_spline_ends("f", |x| x, &[], &[EndCondition::Natural]),
                RError::Core(_)
            )?;
            expect_err!(seed003::figures::four_way(&[], 5), RError::Figure { .. })?;
            expect_err!(seed003::figures::blending_curves(&[]), RError::Core(_))?;
            let curve = ok(seed001_locality())?;
            expect_err!(
                seed001::figures::bspline_locality(&curve, 99, Vector2::new(0.0, 0.0)),
                RError::Core(_)
            )?;
            expect_err!(
                seed001::figures::bspline_locality(&curve, 1, Vector2::new(f64::NAN, 0.0)),
                RError::Core(_)
            )?;
            Ok(())
        }),
        case("report::animations_bad_sizes", || {
            use splinelab::report::animation::{self, Animation, MAX_FRAMES};
            let pts = [
                Vector2::new(0.0, 0.0),
                Vector2::new(1.0, 1.0),
                Vector2::new(2.0, 0.0),
            ];
            for frames in [0, 1, MAX_FRAMES + 1, usize::MAX] {
                expect_err!(
                    animation::de_casteljau(&pts, frames, "a"),
                    RError::Figure { .. }
                )?;
            }
            expect_err!(animation::de_casteljau(&[], 5, "a"), RError::Core(_))?;
            expect_err!(
                animation::de_casteljau(
                    &[Vector2::new(f64::NAN, 0.0), Vector2::new(1.0, 0.0)],
                    5,
                    "a"
                ),
                RError::Core(_)
            )?;
            let window = ok(splinelab::blending::window::WindowCurve::printed_bspline(
                &pts,
            ))?;
            for steps in [0, 25, usize::MAX] {
                expect_err!(
                    animation::sliding_window(&window, &pts, steps, "w"),
                    RError::Figure { .. }
                )?;
            }
            expect_err!(Animation::try_new(Vec::new(), 100), RError::Figure { .. })?;
            let frame = || {
                Plot2d::new("f", "x", "y")
                    .function("x", 0.0, 1.0, |x| x)
                    .figure()
            };
            for delay in [0, 19, 10_001, u32::MAX] {
                expect_err!(
                    Animation::try_new(vec![frame()], delay),
                    RError::Figure { .. }
                )?;
            }
            expect_err!(
                Animation::try_new(vec![frame(), frame().with_size(100, 100)], 100),
                RError::Figure { .. }
            )?;
            Ok(())
        }),
    ]
}

fn seed001_locality() -> Result<BSplineCurve<2>, Error> {
    splinelab::seeds::seed001::locality_curve()
}
