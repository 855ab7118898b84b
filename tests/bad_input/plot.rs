//! plot (feature `report`): the figure builders: `Plot2d`, `Figure2d`, `Panel`, `Series` and the
//! plane figures of `draw`; `Plot3d` (scenes, views, surfaces, patches, nets) and the surface
//! figures of `draw`

use super::*;
use splinelab::interp::choice::{fewest_points, Family};
use splinelab::report::draw::{self, Plot3d};
use splinelab::report::plot2d::{self, Figure2d, Panel, Series, Style};
use splinelab::report::render3d::{Marker, Segment, View, SCENE_LIMIT};
use splinelab::CoordErrors;
use std::f64::consts::PI;

/// Every case of this area.
pub(super) fn cases() -> Vec<Case> {
    let mut all = Vec::new();
    all.extend(series_and_axes_cases());
    all.extend(decoration_cases());
    all.extend(plane_figure_cases());
    all.extend(draw_surface_cases());
    all.extend(scene_cases());
    all.extend(scene_builder_cases());
    all
}

/// `Plot2d`: series of extreme data; log, equal and fixed axes.
fn series_and_axes_cases() -> Vec<Case> {
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
    ]
}

/// Notes, strokes and marks, dashes, legends, tangents, functions.
fn decoration_cases() -> Vec<Case> {
    vec![
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
    ]
}

/// `plot2d`'s sampling and the plane figures of `draw`.
fn plane_figure_cases() -> Vec<Case> {
    vec![
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
                splinelab::study::hermite_error::ConvergenceRow {
                    n: 0,
                    h: f64::NAN,
                    errors: e(f64::INFINITY),
                    order: None,
                    rounding: f64::NAN,
                },
                splinelab::study::hermite_error::ConvergenceRow {
                    n: usize::MAX,
                    h: 0.0,
                    errors: e(5e-324),
                    order: None,
                    rounding: -1.0,
                },
                splinelab::study::hermite_error::ConvergenceRow {
                    n: 1,
                    h: f64::MAX,
                    errors: e(f64::MAX),
                    order: None,
                    rounding: f64::INFINITY,
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

/// Black, for markers in the report cases.
const RGB_BLACK: plotters::style::RGBColor = plotters::style::RGBColor(0, 0, 0);

/// `draw`'s surface and error-map figures; degenerate data of every builder.
fn draw_surface_cases() -> Vec<Case> {
    vec![
        case("plot::surface_too_few_or_too_many_samples", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            for n in [0, 1] {
                expect_err!(
                    Plot3d::new("x").surface(&f, &Rect::unit(), n),
                    RError::Core(Error::TooFewSamples { what, .. }) if *what == "samples"
                )?;
            }
            expect_err!(
                Plot3d::new("x").surface(&f, &Rect::unit(), 1 << 20),
                RError::Core(Error::TooLarge { .. })
            )
        }),
        case("plot::surface_nan_anywhere", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, (s - 0.5).ln()));
            expect_err!(
                Plot3d::new("x").surface(&f, &Rect::unit(), 11),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("plot::error_map_bad_samples_and_nan_surface", || {
            let f = FnSurface::new(|s, t| Vector3::new(s, t, s * t));
            let spline = ok(HermiteSurface::uniform(&f, &Rect::unit(), 2, 2))?;
            expect_err!(
                draw::error_map(&f, &spline, 1),
                RError::Core(Error::TooFewSamples { what, .. }) if *what == "samples"
            )?;
            let g = FnSurface::new(|s, t| Vector3::new(s, t, (s - 0.3).sqrt()));
            expect_err!(
                draw::error_map(&g, &spline, 11),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case("plot::degenerate_data_draws_without_panic", || {
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
    ]
}

fn scene_of(points: &[Vector3<f64>]) -> Figure {
    Plot3d::new("scene")
        .points(points, BLUE, "points")
        .polyline(points, BLUE, "line")
        .figure()
}

/// `Plot3d`: scenes of extreme points, views, grids.
fn scene_cases() -> Vec<Case> {
    vec![
        case("plot::points_beyond_the_scene_limit", || {
            for far in [1e301, f64::MAX, -f64::MAX, 2.0 * SCENE_LIMIT] {
                let fig = scene_of(&[v3(0.0, 0.0, 0.0), v3(far, 1.0, 0.0)]);
                expect_err!(fig.to_svg(), RError::Figure { .. })?;
                expect_err!(fig.to_rgb(), RError::Figure { .. })?;
            }
            Ok(())
        }),
        risky("plot::points_at_the_scene_limit", || {
            let m = SCENE_LIMIT;
            drawable(scene_of(&[v3(-m, -m, -m), v3(m, m, m), v3(m, -m, 0.0)]))
        }),
        risky("plot::points_of_tiny_and_subnormal_extent", || {
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
        case("plot::non_finite_primitives_are_dropped", || {
            let nan = [
                v3(f64::NAN, 0.0, 0.0),
                v3(0.0, f64::INFINITY, 0.0),
                v3(0.0, 0.0, f64::NEG_INFINITY),
                v3(1.0, 1.0, 1.0),
            ];
            drawable(scene_of(&nan))?;
            drawable(scene_of(&nan[..3]))
        }),
        case("plot::views_non_finite_and_extreme", || {
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
        case("plot::view_drawable_clamps", || {
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
        case("plot::grids_empty_single_row_and_non_finite", || {
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
    ]
}

/// `Plot3d`'s builders: surfaces, segments and markers, curves, legends, patches,
/// outlines, corners and derivatives, nets.
fn scene_builder_cases() -> Vec<Case> {
    vec![
        risky("plot::surface_huge_samples", || {
            for n in [usize::MAX, 1 << 40, MAX_ELEMENTS + 1] {
                expect_err!(
                    Plot3d::new("s").surface(&surface(), &Rect::unit(), n),
                    RError::Core(Error::TooLarge { .. })
                )?;
            }
            Ok(())
        }),
        case("plot::surface_colored_alpha_extremes", || {
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
        case("plot::segments_and_markers_of_extreme_sizes", || {
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
        case("plot::space_curve_and_its_tangents", || {
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
        case("plot::many_legend_entries", || {
            let plot = (0..400).fold(Plot3d::new("legend"), |p, k| {
                p.legend(format!("entry {k}"), BLUE)
            });
            drawable(plot.points(&[v3(0.0, 0.0, 0.0)], BLUE, "p").figure())
        }),
        case("plot::patches_too_few_samples", || {
            let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
            for n in [0, 1] {
                expect_err!(
                    Plot3d::new("p").patches(&s, n, 1.0, true, |_, _| BLUE),
                    RError::Core(Error::TooFewSamples { what, .. }) if *what == "samples"
                )?;
            }
            draws(ok(Plot3d::new("p").spline(&s))?.figure())
        }),
        risky("plot::patches_huge_samples", || {
            let s = ok(HermiteSurface::uniform(&surface(), &Rect::unit(), 2, 2))?;
            for n in [usize::MAX, 1 << 40] {
                expect_err!(
                    Plot3d::new("p").patches(&s, n, 1.0, false, |_, _| BLUE),
                    RError::Core(Error::TooLarge { .. })
                )?;
            }
            Ok(())
        }),
        case("plot::outline_of_a_nan_surface", || {
            let f = FnSurface::new(|s: HyperDual64, t: HyperDual64| {
                Vector3::new(s, t, (s - 0.5).sqrt())
            });
            expect_err!(
                Plot3d::new("o").outline(&f, &Rect::unit(), BLUE),
                RError::Core(Error::NonFiniteSurface { .. })
            )
        }),
        case(
            "plot::corners_and_derivatives_of_an_overflowing_surface",
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
        case("plot::nets_degenerate", || {
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
