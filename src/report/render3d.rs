//! A small 3-D scene renderer on plotters' `Cartesian3d`: shaded quads drawn back to front
//! (painter's algorithm, since plotters has no depth buffer), segments, arrows and markers on
//! top, equal axis scaling (MATLAB's `axis equal`), the projected scene scaled and centred to
//! fill the canvas, and a colour bar when colour carries height.

use crate::report::heatmap::{draw_color_bar, ColorScale};
use crate::report::plot2d::{axis_range, Drawn, MAX_MARK};
use crate::report::style::{FONT, LABEL_SIZE, TICK_SIZE, TITLE_SIZE};
use nalgebra::Vector3;
use plotters::coord::Shift;
use plotters::prelude::*;

/// A filled quadrilateral face.
#[derive(Debug, Clone, Copy)]
pub struct Quad {
    /// Corners in order around the face.
    pub corners: [Vector3<f64>; 4],
    /// Base colour before shading.
    pub color: RGBColor,
    /// Opacity in `[0, 1]`.
    pub alpha: f64,
}

/// A straight segment (derivative vectors, control net).
#[derive(Debug, Clone, Copy)]
pub struct Segment {
    /// Start.
    pub a: Vector3<f64>,
    /// End.
    pub b: Vector3<f64>,
    /// Colour.
    pub color: RGBColor,
    /// Stroke width in pixels.
    pub width: u32,
    /// Whether to draw an arrowhead at `b` (derivative vectors).
    pub arrow: bool,
}

impl Segment {
    /// A plain segment from `a` to `b`.
    pub fn line(a: Vector3<f64>, b: Vector3<f64>, color: RGBColor, width: u32) -> Self {
        Self {
            a,
            b,
            color,
            width,
            arrow: false,
        }
    }

    /// An arrow from `a` to `b` (its head at `b`).
    pub fn arrow(a: Vector3<f64>, b: Vector3<f64>, color: RGBColor, width: u32) -> Self {
        Self {
            arrow: true,
            ..Self::line(a, b, color, width)
        }
    }
}

/// A round marker (corner points, control points).
#[derive(Debug, Clone, Copy)]
pub struct Marker {
    /// Position.
    pub at: Vector3<f64>,
    /// Colour.
    pub color: RGBColor,
    /// Radius in pixels.
    pub radius: u32,
}

/// Everything one 3-D figure shows.
#[derive(Debug, Clone, Default)]
pub struct Scene {
    /// Faces.
    pub quads: Vec<Quad>,
    /// Whether to outline faces (MATLAB `surf` draws its mesh lines).
    pub mesh_lines: bool,
    /// Segments, drawn over the faces.
    pub segments: Vec<Segment>,
    /// Markers, drawn last.
    pub markers: Vec<Marker>,
    /// Legend entries (label, colour), drawn in the top-left corner.
    pub legend: Vec<(String, RGBColor)>,
    /// The height range `(z_min, z_max)` of surfaces coloured by height, shown as a colour
    /// bar (set by [`Scene::add_surface`] without a colour).
    pub height_bar: Option<(f64, f64)>,
}

/// A 3-D figure: title, scene and camera.
#[derive(Debug, Clone)]
pub struct Figure3d {
    /// Title.
    pub title: String,
    /// What is drawn.
    pub scene: Scene,
    /// The camera.
    pub view: View,
}

impl Figure3d {
    /// Draws the figure into `area` (already filled with the background).
    ///
    /// # Errors
    /// Whatever the backend reports.
    pub fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        draw_scene(area, &self.title, &self.scene, self.view)
    }
}

impl Scene {
    /// Adds the faces of a tabulated surface `grid[i][j]` (rows × cols points) in one colour,
    /// or coloured by height through `color_by_height` when it is `None`.
    pub fn add_surface(
        &mut self,
        grid: &crate::grid::Grid<Vector3<f64>>,
        color: Option<RGBColor>,
        alpha: f64,
    ) {
        let (zmin, zmax) = grid
            .as_slice()
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.z), hi.max(p.z))
            });
        if color.is_none() && zmin <= zmax {
            let bar = self.height_bar.get_or_insert((zmin, zmax));
            *bar = (bar.0.min(zmin), bar.1.max(zmax));
        }
        for i in 0..grid.rows().saturating_sub(1) {
            for j in 0..grid.cols().saturating_sub(1) {
                let corners = [
                    *grid.get(i, j),
                    *grid.get(i + 1, j),
                    *grid.get(i + 1, j + 1),
                    *grid.get(i, j + 1),
                ];
                let c = color.unwrap_or_else(|| {
                    let z = corners.iter().map(|p| p.z).sum::<f64>() / 4.0;
                    crate::report::style::colormap((z - zmin) / (zmax - zmin).max(1e-300))
                });
                self.quads.push(Quad {
                    corners,
                    color: c,
                    alpha,
                });
            }
        }
    }

    /// What keeps the scene from being drawn, if anything: a finite coordinate beyond
    /// [`SCENE_LIMIT`] (the extents and the projection would overflow).
    pub fn problem(&self) -> Option<String> {
        let far = self.points().find_map(|p| {
            p.iter()
                .copied()
                .find(|v| v.is_finite() && v.abs() > SCENE_LIMIT)
        });
        far.map(|v| format!("a scene coordinate {v:e} beyond ±{SCENE_LIMIT:e}"))
    }

    /// Every point of the scene: corners, segment ends, markers.
    fn points(&self) -> impl Iterator<Item = Vector3<f64>> + '_ {
        self.quads
            .iter()
            .flat_map(|q| q.corners)
            .chain(self.segments.iter().flat_map(|s| [s.a, s.b]))
            .chain(self.markers.iter().map(|m| m.at))
    }

    /// The scene without the primitives that have a non-finite coordinate (and with a
    /// non-finite height bar dropped).
    fn finite(&self) -> Scene {
        let ok = |p: &Vector3<f64>| p.iter().all(|v| v.is_finite());
        Scene {
            quads: self
                .quads
                .iter()
                .filter(|q| q.corners.iter().all(ok))
                .cloned()
                .collect(),
            segments: self
                .segments
                .iter()
                .filter(|s| ok(&s.a) && ok(&s.b))
                .cloned()
                .collect(),
            markers: self.markers.iter().filter(|m| ok(&m.at)).cloned().collect(),
            height_bar: self
                .height_bar
                .filter(|(a, b)| a.is_finite() && b.is_finite()),
            ..self.clone()
        }
    }

    fn bounds(&self) -> (Vector3<f64>, Vector3<f64>) {
        self.points().fold(
            (
                Vector3::repeat(f64::INFINITY),
                Vector3::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), p| (lo.inf(&p), hi.sup(&p)),
        )
    }
}

/// Camera: plotters' yaw (rotation about the vertical axis) and pitch (tilt), in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Rotation about the vertical (z) axis.
    pub yaw: f64,
    /// Tilt towards the viewer.
    pub pitch: f64,
    /// Zoom relative to the fit that fills the plotting area (1: fill it).
    pub scale: f64,
}

impl View {
    /// The view as drawn: a non-finite angle is the default's, and the zoom is clamped to
    /// `[1/16, 16]` (a non-finite or non-positive zoom is 1), so the projected scene stays
    /// within a few figure sizes of the plotting area.
    pub fn drawable(self) -> Self {
        let default = Self::default();
        let pick = |v: f64, d: f64| if v.is_finite() { v } else { d };
        Self {
            yaw: pick(self.yaw, default.yaw),
            pitch: pick(self.pitch, default.pitch),
            scale: if self.scale.is_finite() && self.scale > 0.0 {
                self.scale.clamp(1.0 / 16.0, 16.0)
            } else {
                1.0
            },
        }
    }
}

impl Default for View {
    /// Close to MATLAB's default 3-D view (azimuth −37.5°, elevation 30°).
    fn default() -> Self {
        Self {
            yaw: 0.65,
            pitch: 0.5,
            scale: 1.0,
        }
    }
}

/// Diffuse shading of a face: ambient 0.45 plus 0.55 |n · l| (two-sided), light from the
/// upper front.
fn shade(q: &Quad) -> RGBColor {
    let n = (q.corners[2] - q.corners[0]).cross(&(q.corners[3] - q.corners[1]));
    let light = Vector3::new(-0.4, -0.5, 0.77).normalize();
    let k = match n.try_normalize(1e-300) {
        Some(n) => 0.45 + 0.55 * n.dot(&light).abs(),
        None => 1.0,
    };
    let f = |c: u8| (c as f64 * k).round().min(255.0) as u8;
    RGBColor(f(q.color.0), f(q.color.1), f(q.color.2))
}

/// Our `(x, y, z)` as plotters' `(X, Y, Z)`. Plotters' frame is right-handed with Y upwards,
/// so our z goes to Y; the cyclic permutation `(x, y, z) → (Z, X, Y)` keeps the handedness
/// (swapping only y and z would mirror every figure).
fn to_plot(p: &Vector3<f64>) -> (f64, f64, f64) {
    (p.y, p.z, p.x)
}

/// The largest coordinate magnitude a scene may have (`10³⁰⁰`): its extents, padding and
/// projection then stay finite.
pub const SCENE_LIMIT: f64 = 1e300;

/// Width of the colour bar strip on the right of a height-coloured scene.
const BAR_WIDTH: u32 = 150;

/// Draws `scene` with `title` into `area` (any plotters backend).
///
/// The camera's `yaw` and `pitch` orient the scene; its projection is then scaled and
/// centred so the scene and its axes box fill the plotting area (`view.scale` multiplies
/// that fit, so 1 fills it exactly).
///
/// # Errors
/// Whatever the backend reports.
pub fn draw_scene<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    scene: &Scene,
    view: View,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    lay_out(area, title, scene, view, true).map(|_| ())
}

/// The height a figure of `size` needs for `scene`: the scene is scaled to fill the plotting
/// area's width or height, whichever binds first; where the width binds, the rows above and
/// below the fitted scene would be blank, and this height leaves them out (the scene keeps
/// its scale). `size.1` where nothing is left over, or the scene cannot be laid out.
pub fn fitted_height(title: &str, scene: &Scene, view: View, size: (u32, u32)) -> u32 {
    let mut svg = String::new();
    let spare = {
        let area = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        lay_out(&area, title, scene, view, false).unwrap_or(0)
    };
    // a few pixels kept for rounding
    size.1 - spare.saturating_sub(4).min(size.1 / 2)
}

/// Lays `scene` out in `area` and, if `draw`, draws it; the plotting area's rows the fitted
/// scene leaves blank (see [`fitted_height`]).
fn lay_out<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    scene: &Scene,
    view: View,
    draw: bool,
) -> Result<u32, DrawingAreaErrorKind<DB::ErrorType>> {
    let (area, bar) = match scene.height_bar {
        Some(_) => {
            let (a, b) = area.split_horizontally(area.dim_in_pixel().0.saturating_sub(BAR_WIDTH));
            (a, Some(b))
        }
        None => (area.clone(), None),
    };
    if scene.problem().is_some() {
        return Err(DrawingAreaErrorKind::LayoutError);
    }
    let view = view.drawable();
    // the finite primitives only (a NaN or infinite corner has no place in the picture)
    let scene = &scene.finite();
    let b = padded_box(scene);
    let mut chart = ChartBuilder::on(&area)
        .caption(title, (FONT, TITLE_SIZE))
        .margin(20)
        .build_cartesian_3d(b.lo.y..b.hi.y, b.lo.z..b.hi.z, b.lo.x..b.hi.x)?;
    // axis equal: pixel extents proportional to data extents
    let (w, h) = area.dim_in_pixel();
    let base = (w.min(h) as f64) * 0.8 / b.ext.amax();
    let px = |e: f64| ((e * base).round() as i32).max(1);
    let size = (px(b.ext.y), px(b.ext.z), px(b.ext.x));
    chart.set_3d_pixel_range(size);
    chart.with_projection(|mut pb| {
        pb.yaw = view.yaw;
        pb.pitch = view.pitch;
        pb.scale = 1.0;
        pb.into_matrix()
    });
    let Fit {
        scale: fit,
        screen: (sx, sy),
        offset: (mx, my),
        spare,
    } = fit_to_area(&chart, scene, &b, view);
    if !draw {
        return Ok(spare);
    }
    chart.with_projection(|mut pb| {
        pb.yaw = view.yaw;
        pb.pitch = view.pitch;
        pb.scale = fit;
        let after = (
            sx - (mx as f64 * fit).round() as i32,
            sy - (my as f64 * fit).round() as i32,
        );
        pb.set_pivot((size.0 / 2, size.1 / 2, size.2 / 2), after);
        pb.into_matrix()
    });
    draw_axes(&mut chart, &b)?;
    draw_faces(&mut chart, scene)?;
    draw_segments(&mut chart, &area, scene)?;
    chart.draw_series(
        scene
            .markers
            .iter()
            .map(|m| Circle::new(to_plot(&m.at), m.radius.min(MAX_MARK), m.color.filled())),
    )?;
    draw_legend(&area, &scene.legend)?;
    if let (Some(bar), Some((z0, z1))) = (bar, scene.height_bar) {
        let range = axis_range(z0, z1.max(z0), 0.0).unwrap_or((0.0, 1.0));
        draw_color_bar(&bar, "height z", range, ColorScale::Linear)?;
    }
    Ok(spare)
}

/// The 3-D chart of a scene: plotters' axes are (our y, our z, our x).
type Chart3d<'a, DB> = ChartContext<
    'a,
    DB,
    plotters::coord::cartesian::Cartesian3d<
        plotters::coord::types::RangedCoordf64,
        plotters::coord::types::RangedCoordf64,
        plotters::coord::types::RangedCoordf64,
    >,
>;

/// The scene's bounding box, padded so that a degenerate side keeps some width.
struct PaddedBox {
    lo: Vector3<f64>,
    hi: Vector3<f64>,
    ext: Vector3<f64>,
    pad: f64,
}

/// The box of the scene's finite primitives (the unit cube if there are none), padded by 4 %
/// of its largest side.
fn padded_box(scene: &Scene) -> PaddedBox {
    let (lo, hi) = scene.bounds();
    let (lo, hi) = if lo.iter().chain(hi.iter()).all(|v| v.is_finite()) {
        (lo, hi)
    } else {
        (Vector3::zeros(), Vector3::repeat(1.0))
    };
    // within SCENE_LIMIT (checked above) no extent overflows; the pad keeps a degenerate
    // side some width relative to its coordinates
    let size = lo.amax().max(hi.amax());
    let pad = ((hi - lo).amax() * 0.04).max(1e-9 * size.max(1.0));
    let (lo, hi) = (lo.add_scalar(-pad), hi.add_scalar(pad));
    PaddedBox {
        lo,
        hi,
        ext: hi - lo,
        pad,
    }
}

/// The scale that fits the projected box and every point into the plotting area (room left
/// for the tick labels), the screen centre and the picture's centre offset, and the rows to
/// spare below it: the box corners and every point projected once.
fn fit_to_area<DB: DrawingBackend>(
    chart: &Chart3d<'_, DB>,
    scene: &Scene,
    b: &PaddedBox,
    view: View,
) -> Fit {
    let (lo, hi) = (b.lo, b.hi);
    let coord = chart.as_coord_spec();
    let corners = (0..8).map(|k| {
        Vector3::new(
            if k & 1 == 0 { lo.x } else { hi.x },
            if k & 2 == 0 { lo.y } else { hi.y },
            if k & 4 == 0 { lo.z } else { hi.z },
        )
    });
    let points = scene
        .quads
        .iter()
        .flat_map(|q| q.corners)
        .chain(scene.segments.iter().flat_map(|s| [s.a, s.b]))
        .chain(scene.markers.iter().map(|m| m.at))
        .chain(corners);
    let (mut x0, mut x1, mut y0, mut y1) = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);
    for p in points {
        let (x, y) = coord.translate(&to_plot(&p));
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    let (rx, ry) = chart.plotting_area().get_pixel_range();
    // room for the tick labels plotters draws outside the box
    let margin = 2 * TICK_SIZE as i32 + 16;
    let avail_w = (rx.end - rx.start - 2 * margin).max(1) as f64;
    let avail_h = (ry.end - ry.start - 2 * margin).max(1) as f64;
    let fit = (avail_w / (x1 - x0).max(1) as f64).min(avail_h / (y1 - y0).max(1) as f64);
    let screen = ((rx.start + rx.end) / 2, (ry.start + ry.end) / 2);
    let mid = ((x0 + x1) / 2 - screen.0, (y0 + y1) / 2 - screen.1);
    let spare = (avail_h - fit * view.scale * (y1 - y0).max(1) as f64).max(0.0);
    Fit {
        scale: fit * view.scale,
        screen,
        offset: mid,
        spare: spare as u32,
    }
}

/// How the projected scene sits in the plotting area ([`fit_to_area`]).
struct Fit {
    /// The projection's scale.
    scale: f64,
    /// The plotting area's centre, in pixels.
    screen: (i32, i32),
    /// The unscaled picture's centre relative to `screen`.
    offset: (i32, i32),
    /// Rows to spare below the picture.
    spare: u32,
}

/// The box's light grid and ticks, and the axis names beside the middle of the edges plotters
/// labels for these views (yaw in (0, π/2)): its X axis (our y) along the front edge, its Z
/// axis (our x) along the right edge, its Y axis (our z) at the back-left corner.
fn draw_axes<DB: DrawingBackend>(
    chart: &mut Chart3d<'_, DB>,
    b: &PaddedBox,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    // The labelled edges of our x and y meet at a corner of the box; a label of x close to
    // either end of its range could print on top of y's label there (two "4.0" at one
    // corner), so x's labels keep clear of its ends.
    let (x_lo, x_hi) = (b.lo.x, b.hi.x);
    let clear = 0.12 * (x_hi - x_lo);
    let x_label = move |v: &f64| {
        if (v - x_lo).abs() < clear || (x_hi - v).abs() < clear {
            String::new()
        } else {
            format!("{v:.1}")
        }
    };
    chart
        .configure_axes()
        .light_grid_style(BLACK.mix(0.08))
        .max_light_lines(3)
        .x_labels(5)
        .y_labels(5)
        .z_labels(5)
        .label_style((FONT, TICK_SIZE))
        .x_formatter(&|v| format!("{v:.1}"))
        .y_formatter(&|v| format!("{v:.1}"))
        .z_formatter(&x_label)
        .draw()?;
    // positions in plotters' coordinates
    let label = (FONT, LABEL_SIZE + 4).into_font().color(&BLACK);
    let (lo, hi) = (b.lo, b.hi);
    let mid = (lo + hi) / 2.0;
    let off = b.ext.amax() * 0.16;
    let names = [
        ("y", (mid.y, lo.z, hi.x + off)),
        ("x", (hi.y + off, lo.z, mid.x)),
        ("z", (lo.y, hi.z + b.pad, lo.x)),
    ];
    chart.draw_series(
        names
            .iter()
            .map(|(n, p)| Text::new(n.to_string(), *p, label.clone())),
    )?;
    Ok(())
}

/// The faces, back to front (plotters has no depth buffer), shaded, with mesh lines if asked.
fn draw_faces<DB: DrawingBackend>(
    chart: &mut Chart3d<'_, DB>,
    scene: &Scene,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let coord = chart.as_coord_spec().clone();
    let depth = |q: &Quad| {
        let c = (q.corners[0] + q.corners[1] + q.corners[2] + q.corners[3]) / 4.0;
        let (x, y, z) = to_plot(&c);
        coord.projected_depth(&x, &y, &z)
    };
    let mut order: Vec<(i32, &Quad)> = scene.quads.iter().map(|q| (depth(q), q)).collect();
    order.sort_by_key(|(d, _)| std::cmp::Reverse(*d));
    let edge = BLACK.mix(0.25);
    for (_, q) in order {
        let pts: Vec<(f64, f64, f64)> = q.corners.iter().map(to_plot).collect();
        chart.draw_series(std::iter::once(Polygon::new(
            pts.clone(),
            shade(q).mix(q.alpha).filled(),
        )))?;
        if scene.mesh_lines {
            let mut ring = pts;
            ring.push(ring[0]);
            chart.draw_series(std::iter::once(PathElement::new(ring, edge)))?;
        }
    }
    Ok(())
}

/// The segments, each with its arrowhead (drawn in screen space on `area`) if it has one.
fn draw_segments<DB: DrawingBackend>(
    chart: &mut Chart3d<'_, DB>,
    area: &DrawingArea<DB, Shift>,
    scene: &Scene,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let coord = chart.as_coord_spec().clone();
    let (bx, by) = area.get_base_pixel();
    for s in &scene.segments {
        let width = s.width.min(MAX_MARK);
        chart.draw_series(std::iter::once(PathElement::new(
            vec![to_plot(&s.a), to_plot(&s.b)],
            s.color.stroke_width(width),
        )))?;
        if s.arrow {
            let (a, b) = (
                coord.translate(&to_plot(&s.a)),
                coord.translate(&to_plot(&s.b)),
            );
            if let Some(head) = arrowhead(a, b, 6.0 + 2.5 * width as f64) {
                let head: Vec<(i32, i32)> = head.iter().map(|&(x, y)| (x - bx, y - by)).collect();
                area.draw(&Polygon::new(head, s.color.filled()))?;
            }
        }
    }
    Ok(())
}

/// The triangle of an arrowhead of length `len` pixels at `b`, pointing from `a` to `b`;
/// `None` for a segment too short on screen to carry one.
fn arrowhead(a: (i32, i32), b: (i32, i32), len: f64) -> Option<[(i32, i32); 3]> {
    let (dx, dy) = ((b.0 - a.0) as f64, (b.1 - a.1) as f64);
    let d = dx.hypot(dy);
    if d < 2.0 * len / 3.0 {
        return None;
    }
    let (ux, uy) = (dx / d, dy / d);
    let (px, py) = (-uy, ux);
    let base = (b.0 as f64 - ux * len, b.1 as f64 - uy * len);
    let half = 0.45 * len;
    let r = |x: f64, y: f64| (x.round() as i32, y.round() as i32);
    Some([
        b,
        r(base.0 + px * half, base.1 + py * half),
        r(base.0 - px * half, base.1 - py * half),
    ])
}

/// A legend box in the top-left corner of `area`: a colour swatch and a label per entry.
pub fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    entries: &[(String, RGBColor)],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    if entries.is_empty() {
        return Ok(());
    }
    let (x0, y0, line) = (20, 50, LABEL_SIZE as i32 + 8);
    let width = 40
        + entries
            .iter()
            .map(|(l, _)| l.chars().count())
            .max()
            .unwrap_or(0) as i32
            * 10;
    area.draw(&Rectangle::new(
        [(x0, y0), (x0 + width, y0 + line * entries.len() as i32 + 8)],
        WHITE.mix(0.85).filled(),
    ))?;
    area.draw(&Rectangle::new(
        [(x0, y0), (x0 + width, y0 + line * entries.len() as i32 + 8)],
        BLACK.mix(0.4),
    ))?;
    for (k, (text, color)) in entries.iter().enumerate() {
        let y = y0 + 6 + line * k as i32;
        area.draw(&Rectangle::new(
            [(x0 + 8, y + 3), (x0 + 28, y + line - 8)],
            color.filled(),
        ))?;
        area.draw(&Text::new(
            text.clone(),
            (x0 + 36, y),
            (FONT, LABEL_SIZE).into_font().color(&BLACK),
        ))?;
    }
    Ok(())
}
