//! The report layer: figures, plane and 3-D builders, tables, glyphs (feature `report`).

use super::*;
use plotters::style::RGBColor;
use splinelab::report::draw::{self, Plot2d, Plot3d};
use splinelab::report::figure::{Figure, MAX_SIDE};
use splinelab::report::frame;
use splinelab::report::heatmap::{ColorScale, HeatMap};
use splinelab::report::plot2d::{self, Figure2d, Panel, Series, Style, MAX_PANELS};
use splinelab::report::render3d::{Marker, Segment, View, SCENE_LIMIT};
use splinelab::report::seed004::figures;
use splinelab::report::table::{self, Table};
use splinelab::report::Error as RError;
use splinelab::seeds::letters::letter_a;
use splinelab::CoordErrors;

pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(figure_cases());
    all.extend(plot_cases());
    all.extend(plot3_cases());
    all.extend(table_cases());
    all.extend(letters_cases());
    all
}

const BLUE: RGBColor = RGBColor(0, 0, 255);

/// A figure drawn as SVG: `Ok` (an SVG document) or a typed [`RError::Figure`] —
/// never a panic or a hang.
fn svg_or_refused(fig: &Figure) -> CaseResult {
    match fig.to_svg() {
        Ok(svg) => {
            ensure!(svg.contains("<svg"), "not an SVG document");
            Ok(())
        }
        Err(RError::Figure { .. }) => Ok(()),
        Err(e) => Err(format!("unexpected Err({e})")),
    }
}

/// A figure drawn both as SVG and as pixels (at a small size): `Ok` or a typed
/// [`RError::Figure`], the pixel buffer of the figure's size.
fn drawable(fig: Figure) -> CaseResult {
    let fig = fig.with_size(320, 240);
    svg_or_refused(&fig)?;
    match fig.to_rgb() {
        Ok(px) => {
            ensure!(px.len() == 320 * 240 * 3, "{} bytes", px.len());
            Ok(())
        }
        Err(RError::Figure { .. }) => Ok(()),
        Err(e) => Err(format!("unexpected Err({e})")),
    }
}

/// A figure that must draw (finite, ordinary data): SVG and pixels.
fn draws(fig: Figure) -> CaseResult {
    let fig = fig.with_size(320, 240);
    let svg = ok(fig.to_svg())?;
    ensure!(svg.contains("<svg"), "not an SVG document");
    let px = ok(fig.to_rgb())?;
    ensure!(px.len() == 320 * 240 * 3, "{} bytes", px.len());
    Ok(())
}

/// One panel of one series `points`, as a figure.
fn series_figure(points: Vec<(f64, f64)>) -> Figure {
    Plot2d::new("extreme data", "x", "y")
        .series("data", points)
        .figure()
}

fn simple_figure() -> Figure {
    series_figure(vec![(0.0, 0.0), (1.0, 2.0), (2.0, 1.0)])
}

fn surface() -> FnSurface<impl Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64> + Sync> {
    FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * t))
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

fn tempdir() -> Result<tempfile::TempDir, String> {
    tempfile::tempdir().map_err(|e| format!("tempdir: {e}"))
}

// -----------------------------------------------------------------------------------------
// figure: the Figure value and its outputs
// -----------------------------------------------------------------------------------------

fn figure_cases() -> Vec<Case> {
    vec![
        case("figure::with_size_zero_is_clamped_to_64", || {
            let fig = simple_figure().with_size(0, 0);
            ensure!(fig.size() == (64, 64), "{:?}", fig.size());
            let px = ok(fig.to_rgb())?;
            ensure!(px.len() == 64 * 64 * 3, "{} bytes", px.len());
            Ok(())
        }),
        risky("figure::with_size_u32_max_both_sides", || {
            let fig = simple_figure().with_size(u32::MAX, u32::MAX);
            ensure!(fig.size() == (MAX_SIDE, MAX_SIDE), "{:?}", fig.size());
            let px = ok(fig.to_rgb())?;
            let side = MAX_SIDE as usize;
            ensure!(px.len() == side * side * 3, "{} bytes", px.len());
            Ok(())
        }),
        risky("figure::to_rgb_huge_size_of_a_scene_and_a_map", || {
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
        case("figure::write_png_below_a_file", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                simple_figure().write_png(&file.join("f.png")),
                RError::Io { .. }
            )
        }),
        case("figure::write_svg_below_a_file", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                simple_figure().write_svg(&file.join("f.svg")),
                RError::Io { .. }
            )
        }),
        case("figure::save_below_a_file", || {
            let (_dir, file) = plain_file()?;
            expect_err!(
                simple_figure().save(&file.join("a").join("b"), "f"),
                RError::Io { .. }
            )
        }),
        case("figure::save_stem_in_a_missing_folder", || {
            let dir = tempdir()?;
            expect_err!(
                simple_figure().save(dir.path(), "no-such-folder/f"),
                RError::Io { .. }
            )
        }),
        case("figure::write_to_an_existing_directory", || {
            let dir = tempdir()?;
            expect_err!(simple_figure().write_png(dir.path()), RError::Io { .. })?;
            expect_err!(simple_figure().write_svg(dir.path()), RError::Io { .. })
        }),
        case("figure::save_writes_a_png_of_its_size_and_an_svg", || {
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
        case("figure::layout_without_cells", || {
            for layout in [(0, 0), (0, 3), (3, 0)] {
                let fig = draw::panels("t", vec![Plot2d::new("p", "x", "y").panel()], layout);
                expect_err!(fig.to_svg(), RError::Figure { .. })?;
                expect_err!(fig.to_rgb(), RError::Figure { .. })?;
            }
            Ok(())
        }),
        risky("figure::layout_usize_max", || {
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
        case("figure::layout_max_panels", || {
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
        case("figure::more_cells_or_more_panels_than_the_layout", || {
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
        case("figure::very_long_and_empty_titles", || {
            draws(draw::panels("", vec![], (1, 1)))?;
            let long = "a very long title ".repeat(600);
            draws(Plot2d::new(long, "x", "y").figure())
        }),
        case("figure::heatmap_non_finite_values", || {
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
        case("figure::heatmap_mismatched_and_empty", || {
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
        case("figure::heatmap_log_scale_degenerate_decades", || {
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
        risky("figure::heatmap_extreme_axes", || {
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

// -----------------------------------------------------------------------------------------
// plot: Plot2d, Figure2d, Panel, Series and the plane figures of draw
// -----------------------------------------------------------------------------------------

fn plot_cases() -> Vec<Case> {
    vec![
        risky("plot::series_spanning_f64_max", || {
            drawable(series_figure(vec![
                (-f64::MAX, -f64::MAX),
                (f64::MAX, f64::MAX),
            ]))
        }),
        risky("plot::series_spanning_f64_max_in_x_only", || {
            drawable(series_figure(vec![(-f64::MAX, 0.0), (f64::MAX, 1.0)]))
        }),
        risky("plot::series_near_f64_max_of_one_sign", || {
            drawable(series_figure(vec![
                (f64::MAX / 2.0, 1.0),
                (f64::MAX, 2.0),
                (0.75 * f64::MAX, f64::MAX),
            ]))
        }),
        risky("plot::series_spanning_twice_the_coordinate_limit", || {
            let m = 2.0 * MAX_COORDINATE;
            drawable(series_figure(vec![(-m, m), (m, -m), (0.0, 0.0)]))
        }),
        case("plot::series_of_non_finite_points_only", || {
            drawable(series_figure(vec![
                (f64::NAN, f64::NAN),
                (f64::INFINITY, 1.0),
                (1.0, f64::NEG_INFINITY),
            ]))?;
            drawable(series_figure(vec![]))
        }),
        risky("plot::series_of_a_tiny_span", || {
            drawable(series_figure(vec![
                (0.0, 0.0),
                (1e-300, 1e-300),
                (2e-300, 0.0),
            ]))
        }),
        risky("plot::series_of_a_subnormal_span", || {
            drawable(series_figure(vec![
                (0.0, 0.0),
                (5e-324, 5e-324),
                (1e-310, 0.0),
            ]))
        }),
        risky("plot::series_far_from_zero_and_narrow", || {
            drawable(series_figure(vec![
                (1e300, -1e300),
                (1e300 * (1.0 + 2.0 * f64::EPSILON), -1e300),
            ]))?;
            drawable(series_figure(vec![(1e7, 1e7), (1e7 + 1e-9, 1e7 + 2e-9)]))
        }),
        risky("plot::series_of_every_extreme_value", || {
            let v = [
                f64::NAN,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::MAX,
                -f64::MAX,
                1e-300,
                -5e-324,
                0.0,
            ];
            let pts = v
                .iter()
                .flat_map(|&x| v.iter().map(move |&y| (x, y)))
                .collect();
            drawable(series_figure(pts))
        }),
        risky(
            "plot::log_axes_with_non_positive_and_extreme_values",
            || {
                let fig = Plot2d::new("log", "x", "y")
                    .log(true, true)
                    .series(
                        "s",
                        vec![
                            (0.0, 0.0),
                            (-1.0, -1.0),
                            (f64::MAX, f64::MAX),
                            (5e-324, 5e-324),
                            (f64::NAN, 1.0),
                        ],
                    )
                    .figure();
                drawable(fig)?;
                let only_bad = Plot2d::new("log", "x", "y")
                    .log(true, true)
                    .series("s", vec![(0.0, -1.0), (-5.0, 0.0)])
                    .figure();
                drawable(only_bad)
            },
        ),
        risky("plot::log_axes_from_subnormal_to_f64_max", || {
            drawable(
                Plot2d::new("log", "x", "y")
                    .log(true, false)
                    .series("s", vec![(5e-324, 0.0), (f64::MAX, 1.0)])
                    .figure(),
            )
        }),
        risky("plot::equal_axes_of_an_extreme_aspect", || {
            for pts in [
                vec![(0.0, 0.0), (1e300, 1e-300)],
                vec![(0.0, 0.0), (5e-324, f64::MAX)],
                vec![(-f64::MAX, 0.0), (f64::MAX, 0.0)],
            ] {
                drawable(
                    Plot2d::new("equal", "x", "y")
                        .equal()
                        .series("s", pts)
                        .figure(),
                )?;
            }
            Ok(())
        }),
        risky("plot::fixed_ranges_non_finite_reversed_or_empty", || {
            for (x, y) in [
                ((f64::NAN, f64::NAN), (f64::NEG_INFINITY, f64::INFINITY)),
                ((1.0, 0.0), (2.0, 2.0)),
                ((-f64::MAX, f64::MAX), (-f64::MAX, f64::MAX)),
                ((0.0, 5e-324), (1e300, f64::INFINITY)),
            ] {
                let panel = Panel::new("p", "x", "y")
                    .x_range(x.0, x.1)
                    .y_range(y.0, y.1)
                    .with(Series::line("s", vec![(0.0, 0.0), (1.0, 1.0)], BLUE));
                drawable(draw::panels("ranges", vec![panel], (1, 1)))
                    .map_err(|e| format!("x {x:?}, y {y:?}: {e}"))?;
            }
            Ok(())
        }),
        case("plot::notes_at_extreme_positions", || {
            let mut panel = Panel::new("p", "x", "y").with(Series::line(
                "s",
                vec![(0.0, 0.0), (1.0, 1.0)],
                BLUE,
            ));
            for (x, y) in [
                (f64::NAN, 0.5),
                (f64::MAX, -f64::MAX),
                (f64::NEG_INFINITY, 0.0),
                (1e-300, 0.5),
            ] {
                panel = panel.note(x, y, "note");
            }
            drawable(draw::panels("notes", vec![panel], (1, 1)))
        }),
        case("plot::stroke_widths_and_marks_u32_max", || {
            let pts = vec![(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)];
            let panel = Panel::new("p", "x", "y")
                .with(Series::line("w", pts.clone(), BLUE).width(u32::MAX))
                .with(Series::line("p", pts.clone(), BLUE).styled(Style::Points(u32::MAX)))
                .with(Series::line("c", pts.clone(), BLUE).styled(Style::Crosses(u32::MAX)))
                .with(Series::line("l", pts.clone(), BLUE).styled(Style::LinePoints(u32::MAX)))
                .with(
                    Series::line("z", pts, BLUE)
                        .width(0)
                        .styled(Style::Points(0)),
                );
            draws(
                Figure2d::new("marks", vec![panel], (1, 1))
                    .shared_legend()
                    .into(),
            )
        }),
        risky("plot::dashed_line_across_f64_max", || {
            let panel = Panel::new("p", "x", "y").with(
                Series::line("d", vec![(-f64::MAX, 0.0), (f64::MAX, 1.0)], BLUE)
                    .styled(Style::Dashed),
            );
            drawable(draw::panels("dashes", vec![panel], (1, 1)))
        }),
        case("plot::dashed_line_with_gaps", || {
            let panel = Panel::new("p", "x", "y").with(
                Series::line(
                    "d",
                    vec![
                        (0.0, 0.0),
                        (f64::NAN, 1.0),
                        (1.0, 1.0),
                        (2.0, 0.0),
                        (2.0, 0.0),
                    ],
                    BLUE,
                )
                .styled(Style::Dashed),
            );
            drawable(draw::panels("dashes", vec![panel], (1, 1)))
        }),
        risky("plot::shared_legend_of_thousands_of_entries", || {
            let panels = (0..4)
                .map(|p| {
                    (0..500).fold(Plot2d::new("p", "x", "y"), |plot, k| {
                        plot.series(&format!("series {p}-{k}"), vec![(k as f64, p as f64)])
                    })
                })
                .map(Plot2d::panel)
                .collect();
            drawable(
                Figure2d::new("legend", panels, (2, 2))
                    .shared_legend()
                    .into(),
            )
        }),
        case("plot::tangents_at_bad_parameters_and_lengths", || {
            let c = ok(AngularSpline::try_new(six_points(1.0)))?;
            for length in [1.0, f64::MAX, f64::NAN, -1e300, 5e-324] {
                let fig = Plot2d::new("tangents", "x", "y")
                    .tangents(&c, &[f64::NAN, f64::INFINITY, 1e300, -1e300, 0.5], length)
                    .figure();
                drawable(fig).map_err(|e| format!("length {length:e}: {e}"))?;
            }
            Ok(())
        }),
        case("plot::function_over_a_non_finite_interval", || {
            for (a, b) in [
                (f64::NAN, 1.0),
                (0.0, f64::INFINITY),
                (f64::NEG_INFINITY, f64::INFINITY),
                (1.0, 0.0),
            ] {
                let fig = Plot2d::new("f", "x", "y")
                    .function("f", a, b, |x| x * x)
                    .figure();
                drawable(fig).map_err(|e| format!("[{a}, {b}]: {e}"))?;
            }
            Ok(())
        }),
        risky("plot::function_over_an_f64_max_interval", || {
            let fig = Plot2d::new("f", "x", "y")
                .function("f", -f64::MAX, f64::MAX, |x| x)
                .function("g", -f64::MAX, f64::MAX, |x| x * x)
                .figure();
            drawable(fig)
        }),
        case("plot::curve_trace_and_sampling", || {
            let t = ok(plot2d::trace(&Shape::Circle))?;
            ensure!(t.len() == plot2d::SAMPLES, "{} samples", t.len());
            let s = plot2d::sampled(f64::NAN, 1.0, |x| (x, x));
            ensure!(s.len() == plot2d::SAMPLES, "{} samples", s.len());
            ensure!(plot2d::xy(&[]).is_empty(), "xy of nothing");
            let c = ok(AngularSpline::try_new(six_points(1.0)))?;
            draws(
                ok(Plot2d::new("c", "x", "y").curve("angular", &c))?
                    .control_polygon("polygon", &six_points(1.0))
                    .points("points", &six_points(1.0))
                    .figure(),
            )
        }),
        case("plot::interpolation_panel_of_empty_or_nan_data", || {
            let c = ok(AngularSpline::try_new(six_points(1.0)))?;
            let empty = ok(draw::interpolation("empty", &[], &[], true, &c))?;
            let nan = [v2(f64::NAN, 0.0), v2(1.0, f64::INFINITY)];
            let bad = ok(draw::interpolation("nan", &nan, &nan, false, &c))?;
            drawable(draw::panels("interpolation", vec![empty, bad], (1, 2)))
        }),
        case("plot::methods_figure_refuses_a_bad_method", || {
            let cases = vec![
                (Method::Angular, six_points(1.0), false),
                (Method::BSpline { order: 0 }, six_points(1.0), false),
            ];
            expect_err!(
                draw::methods("m", &six_points(1.0), &cases, (1, 2)),
                RError::Core(Error::DegreeTooLow { .. })
            )?;
            let nan = vec![(Method::Linear, vec![v2(f64::NAN, 0.0), v2(1.0, 1.0)], false)];
            expect_err!(
                draw::methods("m", &[], &nan, (1, 1)),
                RError::Core(Error::NonFinite { .. })
            )
        }),
        case("plot::methods_figure_of_no_cases_or_no_layout", || {
            draws(ok(draw::methods("none", &[], &[], (1, 1)))?)?;
            let cases: Vec<_> = all_methods()
                .into_iter()
                .map(|m| (m, six_points(1.0), true))
                .collect();
            draws(ok(draw::methods("all", &six_points(1.0), &cases, (3, 3)))?)?;
            let fig = ok(draw::methods("zero", &[], &cases, (0, 0)))?;
            expect_err!(fig.to_svg(), RError::Figure { .. })
        }),
        case("plot::choice_figure_of_a_search", || {
            let t = ok(rectangle_target(40))?;
            let c = ok(fewest_points(&t, Family::Linear, &options(12)))?;
            draws(ok(draw::choice(&t, &c))?)?;
            let bad = bogus_choice(Method::Angular, vec![v2(f64::NAN, 0.0); 4], 7);
            expect_err!(
                draw::choice_panel("bad", &t, &bad),
                RError::Core(Error::NonFinite { .. })
            )
        }),
        case("plot::series_figure_on_log_axes_with_zeros", || {
            let fig = draw::series(
                "s",
                "x",
                "y",
                &[
                    ("zeros", vec![(0.0, 0.0), (1.0, 0.0)]),
                    ("negative", vec![(-1.0, -1.0), (2.0, -3.0)]),
                    ("fine", vec![(1e-3, 1e3), (1e3, 1e-3)]),
                    ("empty", vec![]),
                ],
                (true, true),
            );
            drawable(fig)
        }),
        case("plot::bases_of_degree_zero_and_high_degree", || {
            draws(draw::bases(&basis(0, 3)?, "degree 0"))?;
            draws(draw::bases(&basis(12, 40)?, "degree 12"))
        }),
        case("plot::convergence_of_degenerate_rows", || {
            draws(draw::convergence(&[], "no rows"))?;
            let e = |v: f64| CoordErrors {
                report_norm: v3(v, v, v),
                max_abs: v3(v, -v, 0.0),
                rms: v3(v, v, v),
            };
            let rows = vec![
                splinelab::ConvergenceRow {
                    n: 0,
                    h: f64::NAN,
                    errors: e(f64::INFINITY),
                    order: None,
                },
                splinelab::ConvergenceRow {
                    n: usize::MAX,
                    h: 0.0,
                    errors: e(5e-324),
                    order: None,
                },
                splinelab::ConvergenceRow {
                    n: 1,
                    h: f64::MAX,
                    errors: e(f64::MAX),
                    order: None,
                },
            ];
            drawable(draw::convergence(&rows, "bad rows"))
        }),
        case("plot::de_casteljau_bad_input", || {
            expect_err!(
                draw::de_casteljau(&[], &[0.5], "none"),
                RError::Core(Error::TooFewPoints { .. })
            )?;
            for u in [f64::NAN, f64::INFINITY, 1e300] {
                match draw::de_casteljau(&six_points(1.0), &[u], "bad u") {
                    Ok(fig) => drawable(fig)?,
                    Err(RError::Core(Error::NonFinite { .. } | Error::OutOfDomain { .. })) => {}
                    Err(e) => return Err(format!("u = {u}: unexpected {e}")),
                }
            }
            Ok(())
        }),
        case("plot::de_casteljau_no_or_many_parameters", || {
            draws(ok(draw::de_casteljau(&six_points(1.0), &[], "no u"))?)?;
            let us: Vec<f64> = (0..1000).map(|k| k as f64 / 999.0).collect();
            draws(ok(draw::de_casteljau(&six_points(1.0), &us, "many u"))?)
        }),
        risky("plot::de_casteljau_at_the_coordinate_limit", || {
            let m = MAX_COORDINATE / 2.0;
            let p = vec![v2(-m, -m), v2(m, -m), v2(m, m), v2(-m, m)];
            match draw::de_casteljau(&p, &[0.5, 0.25], "huge") {
                Ok(fig) => drawable(fig),
                Err(RError::Core(Error::CoordinateTooLarge { .. } | Error::Overflow { .. })) => {
                    Ok(())
                }
                Err(e) => Err(format!("unexpected {e}")),
            }
        }),
    ]
}

// -----------------------------------------------------------------------------------------
// plot3: Plot3d, Figure3d, Scene, View
// -----------------------------------------------------------------------------------------

fn scene_of(points: &[Vector3<f64>]) -> Figure {
    Plot3d::new("scene")
        .points(points, BLUE, "points")
        .polyline(points, BLUE, "line")
        .figure()
}

fn plot3_cases() -> Vec<Case> {
    vec![
        case("plot3::points_beyond_the_scene_limit", || {
            for far in [1e301, f64::MAX, -f64::MAX, 2.0 * SCENE_LIMIT] {
                let fig = scene_of(&[v3(0.0, 0.0, 0.0), v3(far, 1.0, 0.0)]);
                expect_err!(fig.to_svg(), RError::Figure { .. })?;
                expect_err!(fig.to_rgb(), RError::Figure { .. })?;
            }
            Ok(())
        }),
        risky("plot3::points_at_the_scene_limit", || {
            let m = SCENE_LIMIT;
            drawable(scene_of(&[v3(-m, -m, -m), v3(m, m, m), v3(m, -m, 0.0)]))
        }),
        risky("plot3::points_of_tiny_and_subnormal_extent", || {
            for s in [1e-300, 5e-324, 1e-310] {
                drawable(scene_of(&[
                    v3(0.0, 0.0, 0.0),
                    v3(s, s, s),
                    v3(s, 0.0, 2.0 * s),
                ]))
                .map_err(|e| format!("{s:e}: {e}"))?;
            }
            drawable(scene_of(&[v3(1e300, 1e300, 1e300); 3]))
        }),
        case("plot3::non_finite_primitives_are_dropped", || {
            let nan = [
                v3(f64::NAN, 0.0, 0.0),
                v3(0.0, f64::INFINITY, 0.0),
                v3(0.0, 0.0, f64::NEG_INFINITY),
                v3(1.0, 1.0, 1.0),
            ];
            drawable(scene_of(&nan))?;
            drawable(scene_of(&nan[..3]))
        }),
        case("plot3::views_non_finite_and_extreme", || {
            for (yaw, pitch, scale) in [
                (f64::NAN, f64::INFINITY, f64::NEG_INFINITY),
                (1e300, -1e300, 1e300),
                (0.0, 0.0, 0.0),
                (-5e-324, 5e-324, 5e-324),
                (PI / 2.0, PI / 2.0, -1.0),
            ] {
                let fig = Plot3d::new("view")
                    .view(View { yaw, pitch, scale })
                    .points(&[v3(0.0, 0.0, 0.0), v3(1.0, 2.0, 3.0)], BLUE, "p")
                    .figure();
                drawable(fig).map_err(|e| format!("view ({yaw}, {pitch}, {scale}): {e}"))?;
            }
            Ok(())
        }),
        case("plot3::view_drawable_clamps", || {
            let d = View::default();
            let v = View {
                yaw: f64::NAN,
                pitch: f64::NEG_INFINITY,
                scale: f64::NAN,
            }
            .drawable();
            ensure!(
                v.yaw == d.yaw && v.pitch == d.pitch && v.scale == 1.0,
                "{v:?}"
            );
            for (scale, want) in [(0.0, 1.0), (-3.0, 1.0), (1e10, 16.0), (5e-324, 1.0 / 16.0)] {
                let v = View { scale, ..d }.drawable();
                ensure!(v.scale == want, "scale {scale:e} → {}", v.scale);
            }
            Ok(())
        }),
        case("plot3::grids_empty_single_row_and_non_finite", || {
            let g0: Grid<Vector3<f64>> = Grid::from_fn(0, 0, |_, _| Vector3::zeros());
            let g1 = Grid::from_fn(1, 5, |_, j| v3(j as f64, 0.0, 1.0));
            let bad = Grid::from_fn(4, 4, |i, j| {
                let z = match (i + j) % 4 {
                    0 => f64::NAN,
                    1 => f64::INFINITY,
                    2 => -1e300,
                    _ => (i * j) as f64,
                };
                v3(i as f64, j as f64, z)
            });
            for g in [&g0, &g1, &bad] {
                drawable(Plot3d::new("grid").grid(g, None, 1.0).figure())?;
                drawable(Plot3d::new("grid").grid(g, Some(BLUE), 0.5).figure())?;
            }
            Ok(())
        }),
        risky("plot3::surface_huge_samples", || {
            for n in [usize::MAX, 1 << 40, MAX_ELEMENTS + 1] {
                expect_err!(
                    Plot3d::new("s").surface(&surface(), &Rect::unit(), n),
                    RError::Core(Error::TooLarge { .. })
                )?;
            }
            Ok(())
        }),
        case("plot3::surface_colored_alpha_extremes", || {
            for alpha in [f64::NAN, -1.0, 1e300, f64::INFINITY, 0.0] {
                let fig = ok(Plot3d::new("s").surface_colored(
                    &surface(),
                    &Rect::unit(),
                    6,
                    BLUE,
                    alpha,
                ))?
                .figure();
                drawable(fig).map_err(|e| format!("alpha {alpha}: {e}"))?;
            }
            Ok(())
        }),
        case("plot3::segments_and_markers_of_extreme_sizes", || {
            let mut plot = Plot3d::new("s").points(&[v3(1.0, 1.0, 1.0)], BLUE, "");
            let o = v3(0.0, 0.0, 0.0);
            let scene = plot.scene_mut();
            scene.segments.push(Segment::arrow(o, o, BLUE, 3));
            scene
                .segments
                .push(Segment::line(o, v3(1.0, 0.0, 0.0), BLUE, u32::MAX));
            scene
                .segments
                .push(Segment::arrow(o, v3(0.0, 1.0, 0.0), BLUE, 0));
            scene.markers.push(Marker {
                at: o,
                color: BLUE,
                radius: u32::MAX,
            });
            draws(plot.mesh(false).figure())
        }),
        case("plot3::space_curve_and_its_tangents", || {
            let k = ok(KnotVector::open_uniform(3, 5, 0.0, 1.0))?;
            let pts = vec![
                v3(0.0, 0.0, 0.0),
                v3(1.0, 2.0, 0.0),
                v3(2.0, -1.0, 1.0),
                v3(3.0, 1.0, 2.0),
                v3(4.0, 0.0, 0.0),
            ];
            let c = ok(BSplineCurve::try_new(ok(BSplineBasis::try_new(k, 3))?, pts))?;
            let fig = ok(Plot3d::new("curve").curve(&c, BLUE, "c"))?
                .tangents(&c, &[f64::NAN, 0.5, 1e300, f64::NEG_INFINITY], 0.3)
                .tangents(&c, &[0.25], f64::MAX)
                .figure();
            drawable(fig)
        }),
        case("plot3::many_legend_entries", || {
            let plot = (0..400).fold(Plot3d::new("legend"), |p, k| {
                p.legend(format!("entry {k}"), BLUE)
            });
            drawable(plot.points(&[v3(0.0, 0.0, 0.0)], BLUE, "p").figure())
        }),
        case("plot3::patches_too_few_samples", || {
            let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
            for n in [0, 1] {
                expect_err!(
                    Plot3d::new("p").patches(&s, n, 1.0, true, |_, _| BLUE),
                    RError::Core(Error::TooFewSamples { .. })
                )?;
            }
            draws(ok(Plot3d::new("p").spline(&s))?.figure())
        }),
        risky("plot3::patches_huge_samples", || {
            let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
            for n in [usize::MAX, 1 << 40] {
                expect_err!(
                    Plot3d::new("p").patches(&s, n, 1.0, false, |_, _| BLUE),
                    RError::Core(Error::TooLarge { .. })
                )?;
            }
            Ok(())
        }),
        case("plot3::outline_of_a_nan_surface", || {
            let f = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                Vector3::new(s, t, (s - 0.5).sqrt())
            });
            expect_err!(
                Plot3d::new("o").outline(&f, &Rect::unit(), BLUE),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case(
            "plot3::corners_and_derivatives_of_an_overflowing_surface",
            || {
                let f = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                    Vector3::new(s, t, (s * 700.0).exp() * (t * 10.0).exp())
                });
                let fig = Plot3d::new("d")
                    .corners(&f, &Rect::unit())
                    .derivatives(&f, &Rect::unit())
                    .figure();
                drawable(fig)?;
                let g =
                    FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s.ln(), t, s * t));
                drawable(
                    Plot3d::new("ln")
                        .corners(&g, &Rect::unit())
                        .derivatives(&g, &Rect::unit())
                        .figure(),
                )
            },
        ),
        case("plot3::nets_degenerate", || {
            let g0: Grid<Vector3<f64>> = Grid::from_fn(0, 3, |_, _| Vector3::zeros());
            let g1 = Grid::from_fn(1, 1, |_, _| v3(1.0, 1.0, 1.0));
            let gn = Grid::from_fn(2, 2, |i, _| v3(f64::NAN, i as f64, 0.0));
            drawable(
                Plot3d::new("nets")
                    .net(&g0, BLUE, "empty")
                    .net(&g1, BLUE, "")
                    .net(&gn, BLUE, "nan")
                    .figure(),
            )
        }),
    ]
}

// -----------------------------------------------------------------------------------------
// table: frames, Markdown, HTML, CSV, files and the tables built from studies
// -----------------------------------------------------------------------------------------

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

fn table_cases() -> Vec<Case> {
    use frame::Column;
    vec![
        case("table::frame_mismatched_lengths", || {
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
        case("table::frame_duplicate_names", || {
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
        case("frame::try_new_ragged_third_column", || {
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
        case("frame::try_new_names_repeated_apart", || {
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
        case("frame::try_new_zero_rows", || {
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
        case("table::frame_of_nothing", || {
            let df = ok(frame::frame("empty", vec![]))?;
            let t = Table::new("empty", "", df.clone());
            ok(t.to_markdown())?;
            ok(t.to_html())?;
            ok(table::csv(&df))?;
            let (names, rows) = ok(table::display_rows(&df))?;
            ensure!(names.is_empty() && rows.is_empty(), "{names:?} {rows:?}");
            Ok(())
        }),
        case("table::non_finite_cells_in_every_format", || {
            let df = extreme_frame()?;
            let md = ok(table::markdown(&df))?;
            ensure!(md.contains("NaN") && md.contains("inf"), "{md}");
            let html = ok(table::html_table(&df))?;
            ensure!(!html.contains("<b>"), "unescaped cell: {html}");
            let csv = String::from_utf8(ok(table::csv(&df))?).map_err(|e| e.to_string())?;
            ensure!(csv.lines().count() == 8, "{csv}");
            Ok(())
        }),
        case("table::csv_keeps_full_precision", || {
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
        case("table::html_escapes_title_and_notes", || {
            let t = Table::new("t", "<script>x</script>", ok(frame::frame("t", vec![]))?)
                .note("a & b < c");
            let html = ok(t.to_html())?;
            ensure!(
                !html.contains("<script>") && !html.contains("a & b"),
                "{html}"
            );
            Ok(())
        }),
        case("table::write_below_a_file", || {
            let (_dir, file) = plain_file()?;
            let t = Table::new("t", "t", extreme_frame()?);
            expect_err!(t.write(&file.join("sub")), RError::Io { .. })?;
            expect_err!(
                table::write_csv(&t.df, &file.join("t.csv")),
                RError::Io { .. }
            )
        }),
        case("table::write_an_id_in_a_missing_folder", || {
            let dir = tempdir()?;
            let t = Table::new("missing/t", "t", extreme_frame()?);
            expect_err!(t.write(dir.path()), RError::Io { .. })
        }),
        case("table::write_csv_to_a_directory", || {
            let dir = tempdir()?;
            expect_err!(
                table::write_csv(&extreme_frame()?, dir.path()),
                RError::Io { .. }
            )
        }),
        case("table::write_and_read_back", || {
            let dir = tempdir()?;
            let paths = ok(Table::new("t", "title", extreme_frame()?).write(dir.path()))?;
            ensure!(
                paths.len() == 2 && paths.iter().all(|p| p.exists()),
                "{paths:?}"
            );
            Ok(())
        }),
        case("table::tabulation_too_few_samples", || {
            for (ns, nt) in [(0, 5), (5, 1), (0, 0)] {
                expect_err!(
                    table::tabulation(&surface(), &Rect::unit(), ns, nt),
                    RError::Core(Error::TooFewSamples { .. })
                )?;
            }
            Ok(())
        }),
        risky("table::tabulation_huge_counts", || {
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
        case("table::tabulation_of_a_nan_surface", || {
            let f =
                FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, (s - 0.5).ln()));
            expect_err!(
                table::tabulation(&f, &Rect::unit(), 5, 5),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("table::study_tables_of_nothing", || {
            let t = ok(table::coord_errors("e", "t", &[]))?;
            ensure!(t.df.height() == 0, "{} rows", t.df.height());
            ok(t.to_markdown())?;
            let t = ok(table::convergence("c", "t", &[]))?;
            ensure!(t.df.height() == 0, "{} rows", t.df.height());
            let t = ok(table::error_study(&surface(), &Rect::unit(), &[], 5))?;
            ensure!(t.df.height() == 0, "{} rows", t.df.height());
            Ok(())
        }),
        case("table::coord_errors_non_finite", || {
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
        case("table::seam_continuity_too_few_samples", || {
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
        risky("table::seam_continuity_huge_samples", || {
            let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
            for n in [usize::MAX, MAX_ELEMENTS + 1] {
                expect_err!(
                    table::seam_continuity(&s, n),
                    RError::Core(Error::TooLarge { .. })
                )?;
            }
            Ok(())
        }),
        case("table::error_study_bad_cases", || {
            expect_err!(
                table::error_study(&surface(), &Rect::unit(), &[(0, 1)], 5),
                RError::Core(Error::ZeroPatches { .. })
            )?;
            expect_err!(
                table::error_study(&surface(), &Rect::unit(), &[(2, 2)], 1),
                RError::Core(Error::TooFewSamples { .. })
            )
        }),
        risky("table::error_study_huge_cases", || {
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
    ]
}

// -----------------------------------------------------------------------------------------
// letters: the glyph outlines of the letter "a" and the seed-004 figures built on them
// -----------------------------------------------------------------------------------------

fn letters_cases() -> Vec<Case> {
    vec![
        case("letters::unknown_versions", || {
            for v in [0, 5, usize::MAX] {
                expect_err!(letter_a(v), Error::IndexOutOfRange { .. })?;
                expect_err!(
                    figures::letter(v),
                    RError::Core(Error::IndexOutOfRange { .. })
                )?;
            }
            Ok(())
        }),
        case("letters::every_version_is_a_valid_target", || {
            for v in 1..=4 {
                let l = ok(letter_a(v))?;
                ensure!(!l.contours.is_empty(), "version {v}: no contour");
                for c in &l.contours {
                    ensure!(
                        c.points.len() >= 3 && finite_vecs(&c.points),
                        "version {v}: {} points",
                        c.points.len()
                    );
                    ensure!(
                        c.outline.len() > c.points.len()
                            && c.outline[0] == c.outline[c.outline.len() - 1],
                        "version {v}: outline not closed"
                    );
                    ensure!(
                        c.points.iter().all(|p| p.amax() <= 2.0),
                        "version {v}: beyond the em square"
                    );
                    ok(Target::polyline(&c.outline, true, 0.01))
                        .map_err(|e| format!("version {v}: {e}"))?;
                }
            }
            Ok(())
        }),
        case("letters::every_version_with_the_letter_methods", || {
            for v in 1..=4 {
                for c in ok(letter_a(v))?.contours {
                    for m in [
                        Method::Angular,
                        Method::Cardinal { a: 0.8 },
                        Method::Cubic {
                            end: CubicEnd::Relaxed,
                        },
                    ] {
                        match m.curve(&c.points, true) {
                            Ok(curve) => check_curve(&m, &c.points, true, &curve)
                                .map_err(|e| format!("version {v}: {e}"))?,
                            // the polygonal letter's collinear triples
                            Err(Error::NoSmoothPiece { .. }) if m == Method::Angular => {}
                            Err(e) => {
                                return Err(format!(
                                    "version {v}, {}: {e}",
                                    format_args!("{:?}", m)
                                ))
                            }
                        }
                    }
                }
            }
            Ok(())
        }),
        case("letters::shape_column_out_of_range", || {
            for column in [9, usize::MAX] {
                expect_err!(figures::shape_column(column), RError::UnknownId { .. })?;
            }
            Ok(())
        }),
    ]
}
