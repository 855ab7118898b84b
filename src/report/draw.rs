//! Figures from data: the public drawing API behind every figure of the CLI and the notebooks.
//!
//! Everything here takes the user's objects — any [`SurfaceDerivatives`] (a closure in
//! [`crate::surface::FnSurface`], a patch, a spline surface) on a [`Rect`], any [`ParametricCurve`] in
//! the plane or in space, a basis, a study's rows, a series of numbers — and returns a
//! [`Figure`], which draws on any plotters backend, writes anti-aliased PNG and SVG, and shows
//! itself inline in a notebook. Defaults (camera, colours, labels, samples) are chosen so a
//! one-line call gives a readable figure; the builders change them.
//!
//! ```
//! use splinelab::prelude::*;
//! use splinelab::report::draw::{Plot2d, Plot3d};
//!
//! // a surface of one's own, with its corner points and derivative arrows
//! let bump = FnSurface::new(|s, t| Vector3::new(s, t, (s * t).sin()));
//! let rect = Rect::new(0.0, 2.0, 0.0, 1.5);
//! let fig = Plot3d::new("my surface")
//!     .surface(&bump, &rect, 25)?
//!     .corners(&bump, &rect)
//!     .derivatives(&bump, &rect)
//!     .figure();
//! assert!(fig.to_svg()?.contains("<svg"));
//!
//! // a curve and its control polygon
//! let knots = KnotVector::open_uniform(3, 5, 0.0, 1.0)?;
//! let points = vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0), Vector2::new(2.0, -1.0),
//!                   Vector2::new(3.0, 1.0), Vector2::new(4.0, 0.0)];
//! let curve = BSplineCurve::try_new(BSplineBasis::try_new(knots, 3)?, points.clone())?;
//! let fig = Plot2d::new("a cubic B-spline", "x", "y")
//!     .control_polygon("control polygon", &points)
//!     .curve("curve", &curve)?
//!     .tangents(&curve, &[0.25, 0.5, 0.75], 0.2)
//!     .figure();
//! assert!(fig.to_svg()?.contains("<svg"));
//! # Ok::<(), splinelab::report::Error>(())
//! ```

use crate::bspline::basis::BSplineBasis;
use crate::curve::ParametricCurve;
use crate::domain::{linspace, Rect};
use crate::grid::Grid;
use crate::hermite::spline_surface::HermiteSurface;
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::heatmap::{ColorScale, HeatMap};
use crate::report::legend::Legend;
use crate::report::plot2d::{xy, Figure2d, Panel, Series, Style, INK, SAMPLES};
use crate::report::render3d::{Figure3d, Marker, Scene, Segment, View};
use crate::report::style::{LINE_PALETTE, PATCH_PALETTE};
use crate::study::hermite_error::ConvergenceRow;
use crate::surface::{tabulate, SurfaceDerivatives};
use nalgebra::{Vector2, Vector3};
use plotters::style::RGBColor;

/// The colours of `X_s`, `X_t`, `X_st` arrows (Okabe–Ito vermillion, blue, bluish green).
pub const DERIVATIVE_COLORS: [RGBColor; 3] = [
    RGBColor(213, 94, 0),
    RGBColor(0, 114, 178),
    RGBColor(0, 158, 115),
];

/// A 3-D figure built layer by layer: surfaces, patches, corner points, derivative arrows,
/// control nets, curves and points, over one camera.
#[derive(Debug, Clone)]
pub struct Plot3d {
    title: String,
    view: View,
    scene: Scene,
}

impl Plot3d {
    /// An empty figure with a title, the default camera and mesh lines on the faces.
    pub fn new(title: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            view: View::default(),
            scene: Scene {
                mesh_lines: true,
                ..Scene::default()
            },
        }
    }

    /// With another camera.
    pub fn view(mut self, view: View) -> Self {
        self.view = view;
        self
    }

    /// With or without face outlines.
    pub fn mesh(mut self, on: bool) -> Self {
        self.scene.mesh_lines = on;
        self
    }

    /// Adds a legend entry.
    pub fn legend(mut self, label: impl Into<String>, color: RGBColor) -> Self {
        self.scene.legend.push((label.into(), color));
        self
    }

    /// Adds `surface` on `rect`, sampled `samples × samples`, coloured by height (with a
    /// colour bar).
    ///
    /// # Errors
    /// As [`tabulate`] (too few samples, a non-finite point).
    pub fn surface<S: SurfaceDerivatives + ?Sized>(
        mut self,
        surface: &S,
        rect: &Rect,
        samples: usize,
    ) -> Result<Self> {
        crate::error::samples("samples", samples)?;
        self.scene
            .add_surface(&tabulate(surface, rect, samples, samples)?, None, 1.0);
        Ok(self)
    }

    /// Adds `surface` on `rect` in one colour with opacity `alpha`.
    ///
    /// # Errors
    /// As [`tabulate`].
    pub fn surface_colored<S: SurfaceDerivatives + ?Sized>(
        mut self,
        surface: &S,
        rect: &Rect,
        samples: usize,
        color: RGBColor,
        alpha: f64,
    ) -> Result<Self> {
        crate::error::samples("samples", samples)?;
        self.scene.add_surface(
            &tabulate(surface, rect, samples, samples)?,
            Some(color),
            alpha,
        );
        Ok(self)
    }

    /// Adds an already tabulated surface `grid[i][j]`, by height (`None`) or in one colour.
    pub fn grid(mut self, grid: &Grid<Vector3<f64>>, color: Option<RGBColor>, alpha: f64) -> Self {
        self.scene.add_surface(grid, color, alpha);
        self
    }

    /// Adds every patch of a spline surface, each sampled `samples × samples` and coloured by
    /// `color(i, j)` with opacity `alpha`; with `outline`, each patch boundary is drawn dark
    /// on top.
    ///
    /// # Errors
    /// As [`crate::hermite::patch::HermitePatch::tabulate`].
    pub fn patches(
        mut self,
        spline: &HermiteSurface,
        samples: usize,
        alpha: f64,
        outline: bool,
        color: impl Fn(usize, usize) -> RGBColor,
    ) -> Result<Self> {
        crate::error::samples("samples", samples)?;
        let (n, m) = spline.patch_counts();
        for i in 0..n {
            for j in 0..m {
                let grid = spline.patch(i, j).tabulate(samples, samples)?;
                self.scene.add_surface(&grid, Some(color(i, j)), alpha);
                if outline {
                    self.outline_grid(&grid, RGBColor(30, 30, 30));
                }
            }
        }
        Ok(self)
    }

    /// Adds a spline surface with the defaults: 15 × 15 samples per patch, neighbouring
    /// patches in different colours, outlines.
    ///
    /// # Errors
    /// As [`Plot3d::patches`].
    pub fn spline(self, spline: &HermiteSurface) -> Result<Self> {
        self.patches(spline, 15, 0.9, true, |i, j| {
            PATCH_PALETTE[(i + 2 * j) % PATCH_PALETTE.len()]
        })
    }

    /// The boundary of a tabulated surface as dark segments.
    fn outline_grid(&mut self, grid: &Grid<Vector3<f64>>, color: RGBColor) {
        let (r, c) = (grid.rows(), grid.cols());
        if r == 0 || c == 0 {
            return;
        }
        let edges: [Vec<(usize, usize)>; 4] = [
            (0..c).map(|k| (0, k)).collect(),
            (0..c).map(|k| (r - 1, k)).collect(),
            (0..r).map(|k| (k, 0)).collect(),
            (0..r).map(|k| (k, c - 1)).collect(),
        ];
        for edge in &edges {
            for w in edge.windows(2) {
                self.scene.segments.push(Segment::line(
                    *grid.get(w[0].0, w[0].1),
                    *grid.get(w[1].0, w[1].1),
                    color,
                    2,
                ));
            }
        }
    }

    /// Adds the boundary curves of `surface` over `rect` in `color`.
    ///
    /// # Errors
    /// As [`tabulate`].
    pub fn outline<S: SurfaceDerivatives + ?Sized>(
        mut self,
        surface: &S,
        rect: &Rect,
        color: RGBColor,
    ) -> Result<Self> {
        let grid = tabulate(surface, rect, SAMPLES / 4, SAMPLES / 4)?;
        self.outline_grid(&grid, color);
        Ok(self)
    }

    /// Adds the four corner points `X` of `surface` over `rect` as black dots.
    pub fn corners<S: SurfaceDerivatives + ?Sized>(mut self, surface: &S, rect: &Rect) -> Self {
        for (s, t) in corners(rect) {
            self.scene.markers.push(Marker {
                at: surface.point(s, t),
                color: INK,
                radius: 6,
            });
        }
        self.scene.legend.push(("corner points X".into(), INK));
        self
    }

    /// Adds the derivative vectors at the four corners of `rect` as arrows: `X_s Δs/3`,
    /// `X_t Δt/3` and `X_st Δs Δt/3` — the first two end at the Bézier control points next
    /// to the corner (seed 000 §4), and at the far corners they point back into the patch so
    /// they stay readable.
    pub fn derivatives<S: SurfaceDerivatives + ?Sized>(mut self, surface: &S, rect: &Rect) -> Self {
        let (du, dv) = (rect.s.width(), rect.t.width());
        for (s, t) in corners(rect) {
            let p = surface.partials(s, t);
            let sign_s = if s == rect.s.start() { 1.0 } else { -1.0 };
            let sign_t = if t == rect.t.start() { 1.0 } else { -1.0 };
            let vectors = [
                p.ds * (sign_s * du),
                p.dt * (sign_t * dv),
                p.dst * (sign_s * sign_t * du * dv),
            ];
            for (v, color) in vectors.iter().zip(DERIVATIVE_COLORS) {
                if v.iter().all(|x| x.is_finite()) {
                    self.scene
                        .segments
                        .push(Segment::arrow(p.point, p.point + v / 3.0, color, 3));
                }
            }
        }
        let names = ["X_s Δs/3", "X_t Δt/3", "X_st ΔsΔt/3"];
        for (name, color) in names.iter().zip(DERIVATIVE_COLORS) {
            self.scene.legend.push((name.to_string(), color));
        }
        self
    }

    /// Adds a control net `net[i][j]` (lines between neighbours, dots at the points).
    pub fn net(mut self, net: &Grid<Vector3<f64>>, color: RGBColor, label: &str) -> Self {
        let (r, c) = (net.rows(), net.cols());
        for i in 0..r {
            for j in 0..c {
                for (a, b) in [(i + 1, j), (i, j + 1)] {
                    if a < r && b < c {
                        self.scene.segments.push(Segment::line(
                            *net.get(i, j),
                            *net.get(a, b),
                            color,
                            2,
                        ));
                    }
                }
                self.scene.markers.push(Marker {
                    at: *net.get(i, j),
                    color,
                    radius: 5,
                });
            }
        }
        if !label.is_empty() {
            self.scene.legend.push((label.into(), color));
        }
        self
    }

    /// Adds the 16 control points and the net of a Bézier patch.
    pub fn bezier_net(
        self,
        patch: &crate::bezier::patch::BezierPatch,
        color: RGBColor,
        label: &str,
    ) -> Self {
        let net = patch.net();
        self.net(&Grid::from_fn(4, 4, |i, j| net[i][j]), color, label)
    }

    /// Adds points as dots.
    pub fn points(mut self, points: &[Vector3<f64>], color: RGBColor, label: &str) -> Self {
        self.scene.markers.extend(points.iter().map(|&at| Marker {
            at,
            color,
            radius: 6,
        }));
        if !label.is_empty() {
            self.scene.legend.push((label.into(), color));
        }
        self
    }

    /// Adds a polyline through `points` (a control polygon in space).
    pub fn polyline(mut self, points: &[Vector3<f64>], color: RGBColor, label: &str) -> Self {
        for w in points.windows(2) {
            self.scene
                .segments
                .push(Segment::line(w[0], w[1], color, 2));
        }
        if !label.is_empty() {
            self.scene.legend.push((label.into(), color));
        }
        self
    }

    /// Adds a space curve sampled over its domain.
    ///
    /// # Errors
    /// As [`ParametricCurve::polyline`].
    pub fn curve<C: ParametricCurve<3> + ?Sized>(
        self,
        curve: &C,
        color: RGBColor,
        label: &str,
    ) -> Result<Self> {
        let points = curve.polyline(SAMPLES)?;
        Ok(self.polyline(&points, color, label))
    }

    /// Adds the tangent `C′(t)` of a space curve at each parameter as an arrow from `C(t)` to
    /// `C(t) + length · C′(t)`.
    pub fn tangents<C: ParametricCurve<3> + ?Sized>(
        mut self,
        curve: &C,
        params: &[f64],
        length: f64,
    ) -> Self {
        for &t in params {
            let [p, d, _] = curve.derivatives2(t);
            let q = p + d * length;
            if p.iter().chain(q.iter()).all(|x| x.is_finite()) {
                self.scene.segments.push(Segment::arrow(p, q, INK, 2));
            }
        }
        if !params.is_empty() {
            self.scene.legend.push(("tangent C′(t)".into(), INK));
        }
        self
    }

    /// The scene as it stands (to add raw segments or markers).
    pub fn scene_mut(&mut self) -> &mut Scene {
        &mut self.scene
    }

    /// The finished figure.
    pub fn figure(self) -> Figure {
        Figure3d {
            title: self.title,
            scene: self.scene,
            view: self.view,
        }
        .into()
    }
}

/// The corners of `rect` in order around it.
fn corners(rect: &Rect) -> [(f64, f64); 4] {
    let (s0, s1, t0, t1) = (rect.s.start(), rect.s.end(), rect.t.start(), rect.t.end());
    [(s0, t0), (s1, t0), (s1, t1), (s0, t1)]
}

/// A plane figure of one panel, built series by series; curves take the palette's colours
/// in turn.
#[derive(Debug, Clone)]
pub struct Plot2d {
    panel: Panel,
    next_color: usize,
}

impl Plot2d {
    /// An empty panel with a title and axis labels.
    pub fn new(title: impl Into<String>, x_label: &str, y_label: &str) -> Self {
        Self {
            panel: Panel::new(title, x_label, y_label),
            next_color: 0,
        }
    }

    fn color(&mut self) -> RGBColor {
        let c = LINE_PALETTE[self.next_color % LINE_PALETTE.len()];
        self.next_color += 1;
        c
    }

    /// Equal units in x and y (for shapes).
    pub fn equal(mut self) -> Self {
        self.panel.equal_aspect = true;
        self
    }

    /// Logarithmic axes.
    pub fn log(mut self, x: bool, y: bool) -> Self {
        self.panel = self.panel.log(x, y);
        self
    }

    /// The legend at `pos` (default: upper right).
    pub fn legend_at(mut self, pos: plotters::prelude::SeriesLabelPosition) -> Self {
        self.panel = self.panel.legend_at(pos);
        self
    }

    /// Adds a series as it is (any style and colour).
    pub fn with(mut self, series: Series) -> Self {
        self.panel.series.push(series);
        self
    }

    /// Adds a plane curve sampled over its domain.
    ///
    /// # Errors
    /// As [`ParametricCurve::polyline`].
    pub fn curve<C: ParametricCurve<2> + ?Sized>(mut self, label: &str, curve: &C) -> Result<Self> {
        let color = self.color();
        Ok(self.with(Series::curve(label, curve, color)?))
    }

    /// Adds a control polygon (grey, dots at the vertices).
    pub fn control_polygon(self, label: &str, points: &[Vector2<f64>]) -> Self {
        self.with(Series::polygon(label, points))
    }

    /// Adds points as dots.
    pub fn points(mut self, label: &str, points: &[Vector2<f64>]) -> Self {
        let color = self.color();
        self.with(Series::line(label, xy(points), color).styled(Style::Points(5)))
    }

    /// Adds the tangent `C′(t)` at each parameter as an arrow from `C(t)` to
    /// `C(t) + length · C′(t)`, with a dot at the foot (the head is drawn in data units, so it
    /// is true to shape on an [`Plot2d::equal`] panel).
    pub fn tangents<C: ParametricCurve<2> + ?Sized>(
        mut self,
        curve: &C,
        params: &[f64],
        length: f64,
    ) -> Self {
        for (k, &t) in params.iter().enumerate() {
            let [p, d, _] = curve.derivatives2(t);
            let q = p + d * length;
            let back = (p - q) * 0.18;
            let side = Vector2::new(-back.y, back.x) * 0.5;
            let (l, r) = (q + back + side, q + back - side);
            let arrow = vec![(p.x, p.y), (q.x, q.y), (l.x, l.y), (q.x, q.y), (r.x, r.y)];
            let shaft = Series::line("tangent C′(t)", arrow, INK).width(2);
            let foot = Series::line("", vec![(p.x, p.y)], INK)
                .styled(Style::Points(4))
                .unlabeled();
            self.panel
                .series
                .push(if k == 0 { shaft } else { shaft.unlabeled() });
            self.panel.series.push(foot);
        }
        self
    }

    /// Adds `y = f(x)` on `[a, b]`.
    pub fn function(mut self, label: &str, a: f64, b: f64, f: impl Fn(f64) -> f64) -> Self {
        let color = self.color();
        let points = crate::report::plot2d::sampled(a, b, |x| (x, f(x)));
        self.with(Series::line(label, points, color))
    }

    /// Adds a series of `(x, y)` points joined by a line with dots.
    pub fn series(mut self, label: &str, points: Vec<(f64, f64)>) -> Self {
        let color = self.color();
        self.with(Series::line(label, points, color).styled(Style::LinePoints(4)))
    }

    /// The panel (to lay several out with [`panels`]).
    pub fn panel(self) -> Panel {
        self.panel
    }

    /// The finished figure.
    pub fn figure(self) -> Figure {
        let title = self.panel.title.clone();
        let mut panel = self.panel;
        panel.title = String::new();
        Figure2d::new(title, vec![panel], (1, 1)).into()
    }
}

/// One interpolation panel as seed 004 draws its cells: `curve` over the dashed `reference`
/// shape, the points it was given as crosses (`polygon`: joined by a thin line, for a B-spline's
/// control polygon), on equal axes.
///
/// # Errors
/// As [`ParametricCurve::polyline`].
pub fn interpolation<C: ParametricCurve<2> + ?Sized>(
    title: impl Into<String>,
    reference: &[Vector2<f64>],
    points: &[Vector2<f64>],
    polygon: bool,
    curve: &C,
) -> Result<Panel> {
    let mut panel = Panel::new(title, "x", "y")
        .equal()
        .with(
            Series::line("shape", xy(reference), crate::report::plot2d::GREY)
                .styled(Style::Dashed)
                .width(1),
        )
        .with(Series::line("curve", xy(&curve.polyline(4 * SAMPLES)?), LINE_PALETTE[0]).width(3));
    if polygon {
        panel = panel.with(
            Series::line("", xy(points), crate::report::plot2d::GREY)
                .width(1)
                .unlabeled(),
        );
    }
    Ok(panel.with(Series::line("points", xy(points), INK).styled(Style::Crosses(5))))
}

/// The panel of an automatic point choice ([`crate::interp::choice::fewest_points`]): the
/// curve over the target's reference, its points marked (the B-spline's control polygon
/// drawn), titled `title`, with the count, the error in % of the target's size and whether it
/// is within the tolerance under the drawing.
///
/// # Errors
/// The method's construction errors on the choice's points; as
/// [`ParametricCurve::polyline`].
pub fn choice_panel(
    title: impl Into<String>,
    target: &crate::interp::choice::Target,
    choice: &crate::interp::choice::Choice,
) -> Result<Panel> {
    let closed = target.is_closed();
    let curve = choice.method.curve(&choice.points, closed)?;
    let drawn = choice.method.prepared(&choice.points, closed);
    let polygon = matches!(
        choice.method,
        crate::interp::methods::Method::BSpline { .. }
    );
    let mut panel = interpolation(title, target.reference(), &drawn, polygon, &curve)?;
    panel.x_label = format!(
        "{} pts, error {:.2} %{}",
        choice.measure.counted,
        100.0 * choice.measure.distances.hausdorff() / target.size(),
        if choice.within_tolerance {
            ""
        } else {
            " (over the tolerance)"
        }
    );
    panel.y_label = String::new();
    Ok(panel)
}

/// [`choice_panel`] as a figure of its own, titled with the method and the tolerance.
///
/// # Errors
/// As [`choice_panel`].
pub fn choice(
    target: &crate::interp::choice::Target,
    choice: &crate::interp::choice::Choice,
) -> Result<Figure> {
    let title = format!(
        "the fewest points found: {} within {:.2} % of the size",
        choice.method.legend(),
        100.0 * target.tolerance() / target.size()
    );
    Ok(panels(
        title.clone(),
        vec![choice_panel(title, target, choice)?],
        (1, 1),
    ))
}

/// A comparison of interpolation methods over one shape: one [`interpolation`] panel per
/// `(method, points, closed)`, titled with the method and its point count as the paper counts
/// them, `layout = (rows, cols)`, one legend for all. Points through which the method has no
/// smooth curve ([`crate::error::Error::NoSmoothPiece`]: an Angular spline through collinear points
/// beside a turn, say) get a panel of the shape and the points with the refusal written under
/// it: that is the answer for those points.
///
/// # Errors
/// The method's other construction errors (a bad parameter, too few or non-finite points); as
/// [`ParametricCurve::polyline`].
pub fn methods(
    title: impl Into<String>,
    reference: &[Vector2<f64>],
    cases: &[(crate::interp::methods::Method, Vec<Vector2<f64>>, bool)],
    layout: (usize, usize),
) -> Result<Figure> {
    let panels = cases
        .iter()
        .map(|(method, points, closed)| {
            let counted = method.counted_points(points.len(), *closed);
            let drawn = method.prepared(points, *closed);
            let title = format!("{} — {counted} points", method.legend());
            match method.curve(points, *closed) {
                Ok(curve) => interpolation(
                    title,
                    reference,
                    &drawn,
                    matches!(method, crate::interp::methods::Method::BSpline { .. }),
                    &curve,
                ),
                Err(e @ crate::error::Error::NoSmoothPiece { .. }) => {
                    let mut panel = Panel::new(format!("{title}: refused"), "", "")
                        .equal()
                        .with(
                            Series::line("shape", xy(reference), crate::report::plot2d::GREY)
                                .styled(Style::Dashed)
                                .width(1),
                        )
                        .with(Series::line("points", xy(&drawn), INK).styled(Style::Crosses(5)));
                    // the error's first clause (which piece, which rule): a line a reader
                    // can read under the panel; the whole message is the API's
                    let message = e.to_string();
                    panel.x_label = match message.split_once(": ") {
                        Some((head, _)) if message.chars().count() > 90 => head.to_string(),
                        _ => message,
                    };
                    Ok(panel)
                }
                Err(e) => Err(e.into()),
            }
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Figure2d::new(title, panels, layout).shared_legend().into())
}

/// Several panels under one title, `rows × cols`.
pub fn panels(title: impl Into<String>, panels: Vec<Panel>, layout: (usize, usize)) -> Figure {
    Figure2d::new(title, panels, layout).into()
}

/// A line plot of named series (`log`: logarithmic x and y axes).
pub fn series(
    title: &str,
    x_label: &str,
    y_label: &str,
    data: &[(&str, Vec<(f64, f64)>)],
    log: (bool, bool),
) -> Figure {
    data.iter()
        .fold(
            Plot2d::new(title, x_label, y_label).log(log.0, log.1),
            |p, (label, pts)| p.series(label, pts.clone()),
        )
        .figure()
}

/// Every basis function `N_{i,p}` of `basis` over its domain, one colour each.
pub fn bases(basis: &BSplineBasis, title: &str) -> Figure {
    let (a, b) = basis.domain();
    let ts = linspace(a, b, SAMPLES);
    let values: Vec<Vec<f64>> = ts.iter().map(|&t| basis.all(t)).collect();
    let p = basis.degree();
    let mut plot = Plot2d::new(title, "t", "N_{i,p}(t)");
    for i in 0..basis.len() {
        let pts = ts.iter().zip(&values).map(|(&t, v)| (t, v[i])).collect();
        let color = LINE_PALETTE[i % LINE_PALETTE.len()];
        plot = plot.with(Series::line(format!("N{i},{p}"), pts, color));
    }
    plot.figure()
}

/// The error `‖X_h(u, v) − X(u, v)‖` of a spline surface against the surface it interpolates,
/// over the spline's domain on `samples × samples` points, on a log colour scale over four
/// decades, with the patch boundaries in white.
///
/// # Errors
/// As [`tabulate`] and [`HermiteSurface::tabulate`].
pub fn error_map<S: SurfaceDerivatives + ?Sized>(
    exact: &S,
    spline: &HermiteSurface,
    samples: usize,
) -> Result<Figure> {
    let rect = spline.domain();
    let u = rect.s.linspace(samples)?;
    let v = rect.t.linspace(samples)?;
    let approx = spline.tabulate(&u, &v)?;
    let truth = tabulate(exact, &rect, samples, samples)?;
    let err = Grid::from_fn(samples, samples, |i, j| {
        (approx.get(i, j) - truth.get(i, j)).norm()
    });
    let (n, m) = spline.patch_counts();
    Ok(HeatMap {
        title: format!("Error |X_h − X| over the parameters, {n}×{m} patches"),
        x_label: "u (the s direction)".into(),
        y_label: "v (the t direction)".into(),
        bar_label: "|X_h − X|".into(),
        x: u,
        y: v,
        values: err,
        x_lines: spline.u().nodes().to_vec(),
        y_lines: spline.v().nodes().to_vec(),
        scale: ColorScale::Log { decades: 4.0 },
        footnote: Some("white lines: patch boundaries; the error vanishes at the nodes".into()),
    }
    .into())
}

/// The convergence plot of a study ([`crate::study::hermite_error::convergence`]): max-abs error per
/// coordinate against the patch size `h`, log-log (ticks at powers of ten), with the
/// reference slope `C·h⁴` through the largest error of the coarsest row, down to the rounding
/// level; where an error reaches the rounding level ([`ConvergenceRow::rounding`]) the level is
/// drawn, and below it no order is measured.
pub fn convergence(rows: &[ConvergenceRow], title: &str) -> Figure {
    let colors = [LINE_PALETTE[1], LINE_PALETTE[0], LINE_PALETTE[2]];
    let mut plot =
        Plot2d::new(title, "patch size h = 1/n", "max |X_h − X| per coordinate").log(true, true);
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        let pts = rows.iter().map(|r| (r.h, r.errors.max_abs[k])).collect();
        // a coordinate the spline reproduces says so (an error of exactly 0 has no place on a
        // log axis)
        let reproduced =
            !rows.is_empty() && rows.iter().all(|r| r.at_rounding(r.errors.max_abs[k]));
        let label = if reproduced {
            format!("coordinate {name}: at rounding level")
        } else {
            format!("coordinate {name}")
        };
        plot = plot.with(Series::line(label, pts, colors[k]).styled(Style::LinePoints(5)));
    }
    let usable = |v: f64| v.is_finite() && v > 0.0;
    let rounding = rows
        .iter()
        .map(|r| r.rounding)
        .filter(|r| usable(*r))
        .fold(0.0, f64::max);
    let coarsest = rows
        .iter()
        .filter(|r| usable(r.h))
        .max_by(|a, b| a.h.total_cmp(&b.h));
    let h_min = rows
        .iter()
        .map(|r| r.h)
        .filter(|h| usable(*h))
        .fold(f64::INFINITY, f64::min);
    if let Some(first) = coarsest {
        // C·h⁴ through the largest error of the coarsest row, down to the rounding level
        let e0 = first
            .errors
            .max_abs
            .iter()
            .copied()
            .filter(|e| usable(*e))
            .fold(0.0, f64::max);
        if e0 > rounding && h_min < first.h {
            let reach = if rounding > 0.0 {
                first.h * (rounding / e0).powf(0.25)
            } else {
                0.0
            };
            let end = h_min.max(reach);
            let reference = [first.h, end]
                .iter()
                .map(|&h| (h, e0 * (h / first.h).powi(4)))
                .collect();
            plot = plot.with(
                Series::line("reference slope 4 (C·h⁴)", reference, INK).styled(Style::Dashed),
            );
        }
    }
    // the rounding level, where some error reaches it: below it no order is measured
    let reached = rows.iter().any(|r| {
        r.errors
            .max_abs
            .iter()
            .any(|e| *e > 0.0 && r.at_rounding(*e))
    });
    if rounding > 0.0 && reached && h_min.is_finite() {
        let h_max = coarsest.map_or(h_min, |r| r.h);
        plot = plot.with(
            Series::line(
                "rounding level (no order below it)",
                vec![(h_min, rounding), (h_max, rounding)],
                crate::report::plot2d::GREY,
            )
            .styled(Style::Dashed),
        );
    }
    plot.legend_at(plotters::prelude::SeriesLabelPosition::UpperLeft)
        .figure()
}

/// The Bézier curve of `points` at [`SAMPLES`] parameters of `[0, 1]`, by de Casteljau, as
/// `(x, y)` pairs: the curve every de Casteljau figure and animation draws.
///
/// # Errors
/// No points; a non-finite point.
pub(crate) fn bezier_samples(points: &[Vector2<f64>]) -> Result<Vec<(f64, f64)>> {
    crate::error::finite_points("de Casteljau control points", points)?;
    let curve: Vec<Vector2<f64>> = linspace(0.0, 1.0, SAMPLES)
        .into_iter()
        .map(|u| crate::bezier::de_casteljau::de_casteljau(points, u))
        .collect::<crate::error::Result<_>>()?;
    Ok(xy(&curve))
}

/// One panel of de Casteljau's construction at `u`: the control polygon, the curve (`curve`,
/// sampled), every level of interpolation down to `P(u)`; with `traced`, the curve drawn
/// dashed and the part traced so far solid (a frame of an animation).
pub(crate) fn de_casteljau_panel(
    points: &[Vector2<f64>],
    curve: &[(f64, f64)],
    u: f64,
    traced: Option<Vec<(f64, f64)>>,
) -> Result<Panel> {
    let levels = crate::bezier::de_casteljau::de_casteljau_levels(points, u)?;
    let mut panel = Panel::new(format!("u = {u}"), "x", "y")
        .equal()
        .legend_at(plotters::prelude::SeriesLabelPosition::LowerMiddle)
        .with(Series::polygon("control points", points));
    panel = match traced {
        None => panel.with(Series::line("Bézier curve", curve.to_vec(), LINE_PALETTE[0]).width(3)),
        Some(part) => panel
            .with(
                Series::line("Bézier curve", curve.to_vec(), crate::report::plot2d::GREY)
                    .styled(Style::Dashed)
                    .width(1),
            )
            .with(Series::line("traced so far", part, LINE_PALETTE[0]).width(3)),
    };
    for (level, pts) in levels.iter().enumerate().skip(1) {
        let style = if pts.len() == 1 {
            Style::Points(7)
        } else {
            Style::LinePoints(4)
        };
        let label = if pts.len() == 1 {
            format!("P(u), level {level}")
        } else {
            format!("level {level}")
        };
        panel = panel.with(
            Series::line(label, xy(pts), LINE_PALETTE[level % LINE_PALETTE.len()]).styled(style),
        );
    }
    Ok(panel)
}

/// de Casteljau's construction for any control points, one panel per parameter `u` (at most
/// six): the control polygon, the curve, and every level of repeated linear interpolation
/// down to the point `P(u)`.
///
/// # Errors
/// As [`crate::bezier::de_casteljau::de_casteljau`] (no points, non-finite coordinates).
pub fn de_casteljau(points: &[Vector2<f64>], us: &[f64], title: &str) -> Result<Figure> {
    let curve = bezier_samples(points)?;
    // the layout whose panels show the shape largest at equal axes (panel sizes estimated
    // from the figure size less the title, legend, axis labels and margins)
    let (lo, hi) = points.iter().fold(
        (
            Vector2::repeat(f64::INFINITY),
            Vector2::repeat(f64::NEG_INFINITY),
        ),
        |(lo, hi), p| (lo.inf(p), hi.sup(p)),
    );
    let extent = (hi - lo).map(|e| if e.is_finite() && e > 0.0 { e } else { 1.0 });
    let n = us.len().clamp(1, 6);
    let (fw, fh) = crate::report::style::FIGURE_SIZE;
    let scale = |(rows, cols): (usize, usize)| {
        let w = f64::from(fw) / cols as f64 - 90.0;
        let h = (f64::from(fh) - 90.0) / rows as f64 - 100.0;
        (w / extent.x).min(h / extent.y)
    };
    let layout = [(1, n), (n, 1), (2, n.div_ceil(2)), (n.div_ceil(2), 2)]
        .into_iter()
        .filter(|&(r, c)| r * c >= n)
        .max_by(|&a, &b| scale(a).total_cmp(&scale(b)))
        .unwrap_or((1, n));
    let panels = us
        .iter()
        .take(6)
        .map(|&u| de_casteljau_panel(points, &curve, u, None))
        .collect::<Result<Vec<_>>>()?;
    Ok(Figure::from(
        Figure2d::new(title, panels, layout).shared_legend(),
    ))
}
