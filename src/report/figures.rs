//! Every figure: the report's figures 1–8 and two beyond it, and the figures of the lecture
//! seeds 001 and 003, drawn with plotters by functions generic over the drawing backend, so
//! files (PNG, SVG) and notebooks (`evcxr_figure`) show one picture.
//!
//! Seed 000 lost its figures; only captions and the listings that drew them remain. Each
//! figure here is rebuilt from those (Codice 1, 2, 5, 9, 14 and the prose). The plane figures
//! of seeds 001 and 003 are built in [`crate::report::curve_figures`].

use crate::bezier::patch::BezierPatch;
use crate::blending::functions::Blending;
use crate::blending::surface::SlidingBicubic;
use crate::domain::{Partition, Rect};
use crate::error::{Error, Result};
use crate::grid::Grid;
use crate::hermite::patch::HermitePatch;
use crate::hermite::spline_surface::HermiteSpline;
use crate::report::plot2d::Figure2d;
use crate::report::render3d::{draw_scene, Marker, Scene, Segment, View};
use crate::report::style::{
    codice14_color, colormap, ensure_font, CODICE14_COLORS, FACE_ALPHA, FONT, LABEL_SIZE,
    LINE_PALETTE, PATCH_PALETTE, TICK_SIZE, TITLE_SIZE,
};
use crate::study::{convergence, ConvergenceRow, REPORT_PREC};
use crate::surface::{tabulate, SurfaceDerivatives, Torus};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::f64::consts::TAU;

/// The portion of the torus used for the single-patch figures: `[0, 1]²`, the domain of the
/// report's §3 (whose Figs 3–5 do not print their bounds).
fn portion() -> Rect {
    Rect::unit()
}

/// Every figure, in generation order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FigureId {
    /// Fig 1: a patch, its corners and the vectors X_s, X_t, X_st there.
    PatchDerivatives,
    /// Fig 2: the torus, s, t ∈ [0, 7], 50 × 50 (Codice 1).
    Torus,
    /// Fig 3: the torus with the four corners of the portion (Codice 2).
    TorusCorners,
    /// Fig 4: the Hermite patch of the portion (Codice 5).
    HermitePatch,
    /// Fig 5: the de Casteljau surface with its 16 control points and net (Codice 9, 11).
    BezierNet,
    /// Fig 6: spline patches, u split as [0, 0.5, 0.9, 1].
    SplinePatches,
    /// Fig 7: the whole torus as 4 × 4 patches.
    WholeTorus,
    /// Fig 8: the 9 patches of n = m = 3 (Codice 14).
    NinePatches,
    /// Beyond: log-log convergence of the max-abs error with the h⁴ slope.
    Convergence,
    /// Beyond: where the error lives, over the parameter domain of the n = m = 3 case.
    ErrorMap,
    /// Seed 001: the B-spline bases of degree 1 and 2.
    BSplineBases,
    /// Seed 001: locality — moving P₄ of a cubic changes it only on [¼, 1).
    BSplineLocality,
    /// Seed 001: the quadratic spline curve with knots at eighths.
    BSplineQuadratic,
    /// Seed 001: the exact circles from 7 and 9 weighted control points.
    NurbsCircles,
    /// Seed 001: one NURBS weight as a shape parameter.
    NurbsWeights,
    /// Seed 001: Runge's phenomenon.
    Runge,
    /// Seed 001: uniform, chord-length and centripetal parameters.
    Parametrizations,
    /// Seeds 001 and 004: the four end conditions of the cubic spline.
    CubicSplineEnds,
    /// Seed 003: de Casteljau's construction at u = 0.3, 0.5, 0.7.
    DeCasteljau,
    /// Seed 003: Lagrange and uniform cubic B-spline blending functions.
    BlendingFunctions,
    /// Seed 003: sliding windows, Lagrange vs the printed `bspline` procedure.
    BlendingCurves,
    /// Seed 003: the four-way comparison for 6 and 7 control points.
    FourWay,
    /// Seed 003: the OpenGL-evaluator spline, intended vs as printed.
    OpenGlEvaluator,
    /// Seed 003: the bicubic surface over a sliding 4×4 window.
    SlidingBicubic,
}

impl FigureId {
    /// All figures.
    pub const ALL: [FigureId; 24] = [
        FigureId::PatchDerivatives,
        FigureId::Torus,
        FigureId::TorusCorners,
        FigureId::HermitePatch,
        FigureId::BezierNet,
        FigureId::SplinePatches,
        FigureId::WholeTorus,
        FigureId::NinePatches,
        FigureId::Convergence,
        FigureId::ErrorMap,
        FigureId::BSplineBases,
        FigureId::BSplineLocality,
        FigureId::BSplineQuadratic,
        FigureId::NurbsCircles,
        FigureId::NurbsWeights,
        FigureId::Runge,
        FigureId::Parametrizations,
        FigureId::CubicSplineEnds,
        FigureId::DeCasteljau,
        FigureId::BlendingFunctions,
        FigureId::BlendingCurves,
        FigureId::FourWay,
        FigureId::OpenGlEvaluator,
        FigureId::SlidingBicubic,
    ];

    /// Output id (file stem).
    pub fn id(self) -> &'static str {
        match self {
            FigureId::PatchDerivatives => "fig1-patch-derivatives",
            FigureId::Torus => "fig2-torus",
            FigureId::TorusCorners => "fig3-torus-corners",
            FigureId::HermitePatch => "fig4-hermite-patch",
            FigureId::BezierNet => "fig5-bezier-net",
            FigureId::SplinePatches => "fig6-spline-patches",
            FigureId::WholeTorus => "fig7-whole-torus",
            FigureId::NinePatches => "fig8-nine-patches",
            FigureId::Convergence => "fig-convergence",
            FigureId::ErrorMap => "fig-error-map",
            FigureId::BSplineBases => "fig-bspline-bases",
            FigureId::BSplineLocality => "fig-bspline-locality",
            FigureId::BSplineQuadratic => "fig-bspline-quadratic",
            FigureId::NurbsCircles => "fig-nurbs-circles",
            FigureId::NurbsWeights => "fig-nurbs-weights",
            FigureId::Runge => "fig-runge",
            FigureId::Parametrizations => "fig-parametrizations",
            FigureId::CubicSplineEnds => "fig-cubic-spline-ends",
            FigureId::DeCasteljau => "fig-de-casteljau",
            FigureId::BlendingFunctions => "fig-blending-functions",
            FigureId::BlendingCurves => "fig-blending-curves",
            FigureId::FourWay => "fig-four-way",
            FigureId::OpenGlEvaluator => "fig-opengl-evaluator",
            FigureId::SlidingBicubic => "fig-sliding-bicubic",
        }
    }

    /// One-line description for `--list`.
    pub fn description(self) -> &'static str {
        match self {
            FigureId::PatchDerivatives => {
                "Fig 1: a Hermite patch with its corner points and X_s, X_t, X_st at each corner"
            }
            FigureId::Torus => "Fig 2: the torus, s, t in [0, 7] on a 50×50 grid (Codice 1)",
            FigureId::TorusCorners => {
                "Fig 3: the torus with the corners of the portion [0,1]² in red (Codice 2)"
            }
            FigureId::HermitePatch => "Fig 4: the bicubic Hermite patch of the portion (Codice 5)",
            FigureId::BezierNet => {
                "Fig 5: the de Casteljau surface with its 16 Bézier control points and net"
            }
            FigureId::SplinePatches => {
                "Fig 6: spline patches with u split as [0, 0.5, 0.9, 1], Codice 14 colours"
            }
            FigureId::WholeTorus => "Fig 7: the whole torus as 4×4 = 16 Hermite patches",
            FigureId::NinePatches => "Fig 8: the 9 patches of the n = m = 3 case (Codice 14)",
            FigureId::Convergence => {
                "Beyond: log-log max-abs error vs patch size h, with the h⁴ slope"
            }
            FigureId::ErrorMap => {
                "Beyond: interpolation error |X_h − X| over the parameter domain, n = m = 3"
            }
            FigureId::BSplineBases => {
                "Seed 001: B-spline bases n = 1, knots (0,0,1,2,3,4,5,5), and n = 2, (0,0,0,1,2,3,4,4,4)"
            }
            FigureId::BSplineLocality => {
                "Seed 001: moving P₄ of the cubic on {0,0,0,0,¼,½,¾,1,1,1,1} changes it only on [¼, 1)"
            }
            FigureId::BSplineQuadratic => {
                "Seed 001: quadratic spline curve, knots {0,0,0,1/8,…,7/8,1,1,1}"
            }
            FigureId::NurbsCircles => "Seed 001: the exact NURBS circle from 7 and from 9 control points",
            FigureId::NurbsWeights => "Seed 001: the effect of one NURBS weight on the curve",
            FigureId::Runge => {
                "Seed 001: Runge's phenomenon, degree 9, equispaced vs Chebyshev nodes, error vs degree"
            }
            FigureId::Parametrizations => {
                "Seed 001: uniform, chord-length and centripetal parameters for a spline curve"
            }
            FigureId::CubicSplineEnds => {
                "Seeds 001, 004: cubic spline with clamped, natural, periodic and anticyclic ends"
            }
            FigureId::DeCasteljau => "Seed 003: de Casteljau's construction at u = 0.3, 0.5, 0.7",
            FigureId::BlendingFunctions => {
                "Seed 003: Lagrange 4-point and uniform cubic B-spline blending functions"
            }
            FigureId::BlendingCurves => {
                "Seed 003: sliding windows, Lagrange (interpolating) vs the bspline procedure"
            }
            FigureId::FourWay => {
                "Seed 003: cubic spline, OpenGL spline, Casteljau, Bézier for 6 and 7 points"
            }
            FigureId::OpenGlEvaluator => {
                "Seed 003: the OpenGL-evaluator spline, last group intended vs as printed"
            }
            FigureId::SlidingBicubic => {
                "Seed 003: bicubic surface of a 4×4 window sliding over a 7×7 grid"
            }
        }
    }

    /// Whether the figure is a plane chart (curves on Cartesian axes) rather than a shaded 3-D
    /// scene or a colour map.
    pub fn is_plane(self) -> bool {
        matches!(self.figure2d(), Ok(Some(_))) || self == FigureId::Convergence
    }

    /// Finds a figure by id.
    pub fn from_id(id: &str) -> Option<FigureId> {
        Self::ALL.into_iter().find(|f| f.id() == id)
    }

    /// Draws the figure on a white background into `area` (any plotters backend).
    ///
    /// # Errors
    /// [`Error::Figure`] if the font cannot be registered or the backend fails; errors of
    /// the computations behind the figure.
    pub fn render<DB: DrawingBackend>(self, area: &DrawingArea<DB, Shift>) -> Result<()> {
        let fail = |message: String| Error::Figure {
            id: self.id().to_string(),
            message,
        };
        let plot = |e: DrawingAreaErrorKind<DB::ErrorType>| fail(e.to_string());
        ensure_font().map_err(fail)?;
        area.fill(&WHITE).map_err(plot)?;
        match self {
            FigureId::Convergence => {
                let rows = convergence(
                    &Torus::default(),
                    &Rect::unit(),
                    &crate::report::tables::CONVERGENCE_NS,
                    REPORT_PREC,
                )?;
                draw_convergence(area, &rows).map_err(plot)
            }
            FigureId::ErrorMap => draw_error_map(area, &error_map()?).map_err(plot),
            other => match other.figure2d()? {
                Some(figure) => figure.draw(area).map_err(plot),
                None => {
                    let f = other.figure3d()?;
                    draw_scene(area, f.title, &f.scene, f.view).map_err(plot)
                }
            },
        }
    }

    /// The plane figures of the lecture seeds; `None` for the others.
    fn figure2d(self) -> Result<Option<Figure2d>> {
        use crate::report::curve_figures as cf;
        Ok(Some(match self {
            FigureId::BSplineBases => cf::bspline_bases()?,
            FigureId::BSplineLocality => cf::bspline_locality()?,
            FigureId::BSplineQuadratic => cf::bspline_quadratic()?,
            FigureId::NurbsCircles => cf::nurbs_circles()?,
            FigureId::NurbsWeights => cf::nurbs_weights()?,
            FigureId::Runge => cf::runge_figure()?,
            FigureId::Parametrizations => cf::parametrizations()?,
            FigureId::CubicSplineEnds => cf::cubic_spline_ends()?,
            FigureId::DeCasteljau => cf::de_casteljau_figure()?,
            FigureId::BlendingFunctions => cf::blending_functions()?,
            FigureId::BlendingCurves => cf::blending_curves()?,
            FigureId::FourWay => cf::four_way()?,
            FigureId::OpenGlEvaluator => cf::opengl_last_group()?,
            _ => return Ok(None),
        }))
    }

    /// The scene of a 3-D figure (all but the two 2-D ones).
    fn figure3d(self) -> Result<Figure3d> {
        match self {
            FigureId::PatchDerivatives => fig1(),
            FigureId::Torus => fig2(false),
            FigureId::TorusCorners => fig2(true),
            FigureId::HermitePatch => fig4(),
            FigureId::BezierNet => fig5(),
            FigureId::SplinePatches => fig6(),
            FigureId::WholeTorus => fig7(),
            FigureId::NinePatches => fig8(),
            FigureId::SlidingBicubic => sliding_bicubic(),
            _ => Err(Error::Figure {
                id: self.id().to_string(),
                message: "not a 3-D figure".into(),
            }),
        }
    }
}

/// A 3-D figure: title, scene and camera.
struct Figure3d {
    title: &'static str,
    scene: Scene,
    view: View,
}

/// The camera for the single-patch figures (looking at the portion from outside the torus).
const PATCH_VIEW: View = View {
    yaw: 0.9,
    pitch: 0.45,
    scale: 0.95,
};

fn meshed() -> Scene {
    Scene {
        mesh_lines: true,
        ..Scene::default()
    }
}

fn fig1() -> Result<Figure3d> {
    // A portion with non-zero twist at every corner, so all three vectors show.
    let rect = Rect::new(0.0, 1.2, 0.5, 1.6);
    let patch = HermitePatch::from_surface(&Torus::default(), &rect);
    let mut scene = meshed();
    scene.add_surface(
        &patch.tabulate(20, 20)?,
        Some(RGBColor(120, 165, 235)),
        0.85,
    );
    let (xs, xt, xst) = (
        RGBColor(213, 94, 0),
        RGBColor(0, 114, 178),
        RGBColor(0, 158, 115),
    );
    let c = patch.matrix();
    // Row/column of a corner's value and of its derivative in C (Codice 4); at the far
    // corners the vectors point back into the patch (sign −1) so they stay readable.
    for (vi, di, sign_s) in [(0usize, 1usize, 1.0), (3, 2, -1.0)] {
        for (vj, dj, sign_t) in [(0usize, 1usize, 1.0), (3, 2, -1.0)] {
            let p = c[vi][vj];
            // 1/3 of the Δ-scaled entries: X_s/3 and X_t/3 end at the Bézier control points
            for (v, color) in [
                (c[di][vj] * sign_s, xs),
                (c[vi][dj] * sign_t, xt),
                (c[di][dj] * (sign_s * sign_t), xst),
            ] {
                scene.segments.push(Segment {
                    a: p,
                    b: p + v / 3.0,
                    color,
                    width: 4,
                });
            }
            scene.markers.push(Marker {
                at: p,
                color: RGBColor(0, 0, 0),
                radius: 6,
            });
        }
    }
    scene.legend = vec![
        ("corner points X".into(), RGBColor(0, 0, 0)),
        ("X_s (Δu-scaled, ÷3)".into(), xs),
        ("X_t (Δv-scaled, ÷3)".into(), xt),
        ("X_st (ΔuΔv-scaled, ÷3)".into(), xst),
    ];
    Ok(Figure3d {
        title: "Fig 1 — corner points and derivatives of a Hermite patch",
        scene,
        view: View {
            yaw: 0.2,
            pitch: 0.45,
            scale: 0.95,
        },
    })
}

fn fig2(corners: bool) -> Result<Figure3d> {
    // Codice 1: s, t = linspace(0, 7, 50)
    let torus = Torus::default();
    let mut scene = meshed();
    scene.add_surface(
        &tabulate(&torus, &Rect::new(0.0, 7.0, 0.0, 7.0), 50, 50)?,
        None,
        1.0,
    );
    let title = if corners {
        let r = portion();
        for (s, t) in [
            (r.s.start(), r.t.start()),
            (r.s.start(), r.t.end()),
            (r.s.end(), r.t.end()),
            (r.s.end(), r.t.start()),
        ] {
            scene.markers.push(Marker {
                at: torus.point(s, t),
                color: RGBColor(220, 0, 0),
                radius: 9,
            });
        }
        scene.legend = vec![("corners of [0,1]² (Codice 2)".into(), RGBColor(220, 0, 0))];
        "Fig 3 — corners of the portion [0,1]² of the torus"
    } else {
        "Fig 2 — test surface: torus, s, t ∈ [0, 7], 50×50"
    };
    Ok(Figure3d {
        title,
        scene,
        view: View::default(),
    })
}

fn fig4() -> Result<Figure3d> {
    let patch = HermitePatch::from_surface(&Torus::default(), &portion());
    let mut scene = meshed();
    scene.add_surface(&patch.tabulate(30, 30)?, None, 1.0);
    Ok(Figure3d {
        title: "Fig 4 — bicubic Hermite patch H(s)ᵀ C H(t) of the portion [0,1]²",
        scene,
        view: PATCH_VIEW,
    })
}

fn fig5() -> Result<Figure3d> {
    let bezier =
        BezierPatch::from_hermite(&HermitePatch::from_surface(&Torus::default(), &portion()));
    let mut scene = meshed();
    scene.add_surface(&bezier.tabulate_de_casteljau(30, 30)?, None, 0.75);
    let net = bezier.net();
    let red = RGBColor(200, 0, 0);
    for i in 0..4 {
        for j in 0..4 {
            let neighbours = [(i + 1, j), (i, j + 1)];
            for (a, b) in neighbours.into_iter().filter(|&(a, b)| a < 4 && b < 4) {
                scene.segments.push(Segment {
                    a: net[i][j],
                    b: net[a][b],
                    color: red,
                    width: 2,
                });
            }
            scene.markers.push(Marker {
                at: net[i][j],
                color: red,
                radius: 6,
            });
        }
    }
    scene.legend = vec![("16 Bézier control points and net".into(), red)];
    Ok(Figure3d {
        title: "Fig 5 — de Casteljau surface with its control net",
        scene,
        view: PATCH_VIEW,
    })
}

/// Adds every patch of `spline`, each tabulated on `prec × prec` local samples, coloured by
/// `color(i, j)`; with `outline`, each patch's boundary is drawn as a dark curve on top (for
/// surfaces seen from one side, where no boundary is hidden).
fn add_spline_patches(
    scene: &mut Scene,
    spline: &HermiteSpline,
    prec: usize,
    alpha: f64,
    outline: bool,
    color: impl Fn(usize, usize) -> RGBColor,
) -> Result<()> {
    let (n, m) = spline.patch_counts();
    for i in 0..n {
        for j in 0..m {
            let grid = spline.patch(i, j).tabulate(prec, prec)?;
            scene.add_surface(&grid, Some(color(i, j)), alpha);
            if outline {
                let last = prec - 1;
                let edges: [Vec<(usize, usize)>; 4] = [
                    (0..prec).map(|k| (0, k)).collect(),
                    (0..prec).map(|k| (last, k)).collect(),
                    (0..prec).map(|k| (k, 0)).collect(),
                    (0..prec).map(|k| (k, last)).collect(),
                ];
                for edge in &edges {
                    for w in edge.windows(2) {
                        scene.segments.push(Segment {
                            a: *grid.get(w[0].0, w[0].1),
                            b: *grid.get(w[1].0, w[1].1),
                            color: RGBColor(30, 30, 30),
                            width: 2,
                        });
                    }
                }
            }
        }
    }
    Ok(())
}

fn fig6() -> Result<Figure3d> {
    let spline = HermiteSpline::from_surface(
        &Torus::default(),
        Partition::try_new(vec![0.0, 0.5, 0.9, 1.0])?,
        Partition::try_new(vec![0.0, 1.0])?,
    );
    let mut scene = meshed();
    // §5's prose: u₁ = [0, 0.5] blue, u₃ = [0.9, 1] yellow, i.e. colors(i) in order
    // (Codice 14's mod(i,3)+1 would start with green; Fig 8 uses that one).
    add_spline_patches(
        &mut scene,
        &spline,
        REPORT_PREC,
        FACE_ALPHA,
        true,
        |i, _| CODICE14_COLORS[i % 3],
    )?;
    scene.legend = vec![
        ("u ∈ [0, 0.5]".into(), CODICE14_COLORS[0]),
        ("u ∈ [0.5, 0.9]".into(), CODICE14_COLORS[1]),
        ("u ∈ [0.9, 1]".into(), CODICE14_COLORS[2]),
    ];
    Ok(Figure3d {
        title: "Fig 6 — spline patches, u split as [0, 0.5, 0.9, 1], 15×15 samples each",
        scene,
        view: PATCH_VIEW,
    })
}

fn fig7() -> Result<Figure3d> {
    let spline = HermiteSpline::uniform(&Torus::default(), &Rect::new(0.0, TAU, 0.0, TAU), 4, 4)?;
    let mut scene = meshed();
    // (i + 2j) mod 5 differs between neighbours in u and in v, across the wrap-around too.
    add_spline_patches(&mut scene, &spline, 13, 1.0, false, |i, j| {
        PATCH_PALETTE[(i + 2 * j) % PATCH_PALETTE.len()]
    })?;
    Ok(Figure3d {
        title: "Fig 7 — the whole torus as 4×4 = 16 Hermite patches",
        scene,
        view: View::default(),
    })
}

fn fig8() -> Result<Figure3d> {
    let spline = HermiteSpline::uniform(&Torus::default(), &Rect::unit(), 3, 3)?;
    let mut scene = meshed();
    // Codice 14: colors(mod(i,3)+1, :) for patch row i (1-based)
    add_spline_patches(
        &mut scene,
        &spline,
        REPORT_PREC,
        FACE_ALPHA,
        true,
        |i, _| codice14_color(i),
    )?;
    scene.legend = (0..3)
        .map(|i| (format!("patch row i = {}", i + 1), codice14_color(i)))
        .collect();
    Ok(Figure3d {
        title: "Fig 8 — the 9 patches of n = m = 3 on [0,1]² (Codice 14)",
        scene,
        view: PATCH_VIEW,
    })
}

/// Seed 003: the bicubic surface of a 4×4 window sliding over a 7×7 grid of points
/// `z = f(x, y)`, uniform cubic B-spline blending, one colour per cell, the grid as markers.
fn sliding_bicubic() -> Result<Figure3d> {
    let grid = crate::report::curve_data::sliding_grid();
    let surface = SlidingBicubic::try_new(&grid, Blending::UniformBSpline)?;
    let mut scene = meshed();
    let (rows, cols) = surface.cells();
    for i in 0..rows {
        for j in 0..cols {
            let patch = surface.tabulate_cell((i, j), 9)?;
            scene.add_surface(
                &patch,
                Some(PATCH_PALETTE[(i + 2 * j) % PATCH_PALETTE.len()]),
                0.9,
            );
        }
    }
    let dark = RGBColor(40, 40, 40);
    for i in 0..grid.rows() {
        for j in 0..grid.cols() {
            for (a, b) in [(i + 1, j), (i, j + 1)] {
                if a < grid.rows() && b < grid.cols() {
                    scene.segments.push(Segment {
                        a: *grid.get(i, j),
                        b: *grid.get(a, b),
                        color: RGBColor(150, 150, 150),
                        width: 1,
                    });
                }
            }
            scene.markers.push(Marker {
                at: *grid.get(i, j),
                color: dark,
                radius: 4,
            });
        }
    }
    scene.legend = vec![
        ("7×7 grid of points z = f(x, y) and its net".into(), dark),
        (
            "one colour per cell (4×4 window position)".into(),
            PATCH_PALETTE[0],
        ),
    ];
    Ok(Figure3d {
        title: "Sliding 4×4 window, uniform cubic B-spline blending (seed 003)",
        scene,
        view: View {
            yaw: 0.7,
            pitch: 0.55,
            scale: 0.95,
        },
    })
}

type Drawn<DB> = std::result::Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

const SERIES_COLORS: [RGBColor; 3] = [LINE_PALETTE[1], LINE_PALETTE[0], LINE_PALETTE[2]];

fn draw_convergence<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    rows: &[ConvergenceRow],
) -> Drawn<DB> {
    let hmin = rows.iter().map(|r| r.h).fold(f64::INFINITY, f64::min);
    let hmax = rows.iter().map(|r| r.h).fold(0.0, f64::max);
    let emin = rows
        .iter()
        .map(|r| r.errors.max_abs.min())
        .fold(f64::INFINITY, f64::min);
    let emax = rows
        .iter()
        .map(|r| r.errors.max_abs.max())
        .fold(0.0, f64::max);
    let mut chart = ChartBuilder::on(area)
        .caption(
            "Convergence: max-abs error vs patch size h, n × n patches on [0,1]²",
            (FONT, TITLE_SIZE - 4),
        )
        .margin(20)
        .x_label_area_size(55)
        .y_label_area_size(85)
        .build_cartesian_2d(
            (hmin * 0.8..hmax * 1.25).log_scale(),
            (emin * 0.03..emax * 3.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("patch size h = 1/n")
        .y_desc("max |X_h − X| over 15×15 samples per patch")
        .axis_desc_style((FONT, LABEL_SIZE))
        .label_style((FONT, TICK_SIZE))
        .x_labels(8)
        .x_label_formatter(&|v| format!("{v}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        let pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.h, r.errors.max_abs[k])).collect();
        let c = SERIES_COLORS[k];
        chart
            .draw_series(LineSeries::new(pts.clone(), c.stroke_width(2)))?
            .label(format!("coordinate {name}"))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(3)));
        chart.draw_series(pts.iter().map(|p| Circle::new(*p, 5, c.filled())))?;
    }
    // h⁴ reference through the finest x point, one decade below it
    if let Some(last) = rows.last() {
        let (h0, e0) = (last.h, last.errors.max_abs.min() * 0.1);
        let reference: Vec<(f64, f64)> = [hmin, hmax]
            .iter()
            .map(|&h| (h, e0 * (h / h0).powi(4)))
            .collect();
        chart
            .draw_series(LineSeries::new(reference, BLACK.stroke_width(2)))?
            .label("reference slope 4 (C·h⁴)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font((FONT, LABEL_SIZE))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .draw()?;
    Ok(())
}

/// Samples per side of the error map.
const MAP_SAMPLES: usize = 121;

/// Data of the error map: samples, `|X_h − X|` on the grid, and the patch boundaries.
struct ErrorMap {
    samples: Vec<f64>,
    err: Grid<f64>,
    boundaries: Vec<f64>,
}

fn error_map() -> Result<ErrorMap> {
    let torus = Torus::default();
    let spline = HermiteSpline::uniform(&torus, &Rect::unit(), 3, 3)?;
    let samples = crate::domain::linspace(0.0, 1.0, MAP_SAMPLES);
    let approx = spline.tabulate(&samples, &samples)?;
    let exact = tabulate(&torus, &Rect::unit(), MAP_SAMPLES, MAP_SAMPLES)?;
    let err = Grid::from_fn(MAP_SAMPLES, MAP_SAMPLES, |i, j| {
        (approx.get(i, j) - exact.get(i, j)).norm()
    });
    Ok(ErrorMap {
        samples,
        err,
        boundaries: spline.u().nodes().to_vec(),
    })
}

fn draw_error_map<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, map: &ErrorMap) -> Drawn<DB> {
    let emax = map
        .err
        .as_slice()
        .iter()
        .copied()
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    // log colour scale over four decades below the maximum
    let decades = 4.0;
    let floor = emax * 10f64.powf(-decades);
    let level = |e: f64| (e.max(floor) / emax).log10() / decades + 1.0;
    let (main, bar) = area.split_horizontally(area.dim_in_pixel().0 - 150);
    let mut chart = ChartBuilder::on(&main)
        .caption(
            "Error |X_h − X| over the parameters, 3×3 patches of [0,1]²",
            (FONT, TITLE_SIZE - 4),
        )
        .margin(20)
        .x_label_area_size(55)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, 0.0..1.0)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("u (the s direction)")
        .y_desc("v (the t direction)")
        .axis_desc_style((FONT, LABEL_SIZE))
        .label_style((FONT, TICK_SIZE))
        .draw()?;
    let u = &map.samples;
    let half = 0.5 / (u.len() - 1) as f64;
    let cell = |i: usize, j: usize| {
        let (x, y) = (u[i], u[j]);
        Rectangle::new(
            [
                ((x - half).max(0.0), (y - half).max(0.0)),
                ((x + half).min(1.0), (y + half).min(1.0)),
            ],
            colormap(level(*map.err.get(i, j))).filled(),
        )
    };
    chart.draw_series((0..u.len()).flat_map(|i| (0..u.len()).map(move |j| cell(i, j))))?;
    for &k in &map.boundaries {
        chart.draw_series([
            PathElement::new(vec![(k, 0.0), (k, 1.0)], WHITE.stroke_width(2)),
            PathElement::new(vec![(0.0, k), (1.0, k)], WHITE.stroke_width(2)),
        ])?;
    }
    // colour bar
    let mut cb = ChartBuilder::on(&bar)
        .margin_top(80)
        .margin_bottom(80)
        .margin_right(20)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..1.0, (floor..emax).log_scale())?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .label_style((FONT, TICK_SIZE))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    let steps = 100;
    let at = |k: usize| floor * 10f64.powf(decades * k as f64 / steps as f64);
    cb.draw_series((0..steps).map(|k| {
        Rectangle::new(
            [(0.0, at(k)), (1.0, at(k + 1))],
            colormap(k as f64 / steps as f64).filled(),
        )
    }))?;
    main.draw(&Text::new(
        "white lines: patch boundaries; the error vanishes at the nodes",
        (90, main.dim_in_pixel().1 as i32 - 20),
        (FONT, TICK_SIZE).into_font().color(&BLACK),
    ))?;
    Ok(())
}
