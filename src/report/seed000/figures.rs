//! The report's figures 1–8 and two beyond it (convergence, error map), each a thin call of
//! [`crate::report::draw`] with the report's data.
//!
//! Seed 000 lost its figures; only captions and the listings that drew them remain. Each
//! figure here is rebuilt from those (Codice 1, 2, 5, 9, 14 and the prose).

use crate::bezier::patch::BezierPatch;
use crate::domain::{Partition, Rect};
use crate::grid::Grid;
use crate::hermite::patch::HermitePatch;
use crate::hermite::spline_surface::HermiteSurface;
use crate::report::draw::{self, Plot3d};
use crate::report::error::Result;
use crate::report::figure::Figure;
use crate::report::render3d::View;
use crate::report::style::{codice14_color, CODICE14_COLORS, FACE_ALPHA, PATCH_PALETTE};
use crate::study::hermite_error::REPORT_PREC;
use crate::surface::{ParametricSurface, Torus};
use plotters::style::RGBColor;

/// The portion of the torus used for the single-patch figures: `[0, 1]²`, the domain of the
/// report's §3 (whose Figs 3–5 do not print their bounds).
pub fn portion() -> Rect {
    Rect::unit()
}

/// The camera for the single-patch figures (looking at the portion from outside the torus).
pub const PATCH_VIEW: View = View {
    yaw: 0.9,
    pitch: 0.45,
    scale: 1.0,
};

/// Fig 1: the Hermite patch of `surface` on `rect`, its corner points and the vectors `X_s`,
/// `X_t`, `X_st` there (Δ-scaled and divided by 3, so the first two end at the Bézier control
/// points). The seed's: the torus on `[0, 1.2] × [0.5, 1.6]`, a patch with non-zero twist at
/// every corner.
///
/// # Errors
/// The errors of [`HermitePatch::try_from_surface`] (a surface not finite at a corner).
pub fn fig1<S: ParametricSurface + ?Sized>(surface: &S, rect: &Rect) -> Result<Figure> {
    let patch = HermitePatch::try_from_surface(surface, rect)?;
    let local = Rect::unit();
    Ok(
        Plot3d::new("Fig 1 — corner points and derivatives of a Hermite patch")
            .view(View {
                yaw: 0.2,
                pitch: 0.45,
                scale: 1.0,
            })
            .surface_colored(&patch, &local, 20, RGBColor(120, 165, 235), 0.85)?
            .corners(&patch, &local)
            .derivatives(&patch, &local)
            .figure(),
    )
}

/// Figs 2 and 3: `surface` on `domain` on an `n × n` grid (Codice 1: the torus,
/// `s, t ∈ [0, 7]`, 50 × 50); with `corners` of a portion, its four corners in red (Codice 2:
/// the portion `[0, 1]²`).
///
/// # Errors
/// Fewer than 2 samples; a surface not finite on the grid.
pub fn torus_figure<S: ParametricSurface + ?Sized>(
    surface: &S,
    domain: &Rect,
    n: usize,
    corners: Option<&Rect>,
) -> Result<Figure> {
    let title = match corners {
        Some(r) => format!(
            "Fig 3 — corners of the portion [{}, {}] × [{}, {}]",
            r.s.start(),
            r.s.end(),
            r.t.start(),
            r.t.end()
        ),
        None => format!(
            "Fig 2 — the surface, s ∈ [{}, {}], t ∈ [{}, {}], {n}×{n}",
            domain.s.start(),
            domain.s.end(),
            domain.t.start(),
            domain.t.end()
        ),
    };
    let plot = Plot3d::new(title).surface(surface, domain, n)?;
    Ok(if let Some(r) = corners {
        let points: Vec<_> = [
            (r.s.start(), r.t.start()),
            (r.s.start(), r.t.end()),
            (r.s.end(), r.t.end()),
            (r.s.end(), r.t.start()),
        ]
        .iter()
        .map(|&(s, t)| crate::surface::SurfaceDerivatives::point(surface, s, t))
        .collect();
        plot.points(
            &points,
            RGBColor(220, 0, 0),
            "corners of the portion (Codice 2)",
        )
    } else {
        plot
    }
    .figure())
}

/// Fig 2.
///
/// # Errors
/// Never in practice.
pub fn fig2() -> Result<Figure> {
    torus_figure(&Torus::default(), &Rect::new(0.0, 7.0, 0.0, 7.0), 50, None)
}

/// Fig 3.
///
/// # Errors
/// Never in practice.
pub fn fig3() -> Result<Figure> {
    torus_figure(
        &Torus::default(),
        &Rect::new(0.0, 7.0, 0.0, 7.0),
        50,
        Some(&portion()),
    )
}

/// Fig 4: the bicubic Hermite patch of `surface` on `rect` (Codice 5: the torus on the portion
/// `[0, 1]²`), tabulated on `n × n` points.
///
/// # Errors
/// A surface not finite at a corner; fewer than 2 samples.
pub fn fig4<S: ParametricSurface + ?Sized>(surface: &S, rect: &Rect, n: usize) -> Result<Figure> {
    let patch = HermitePatch::try_from_surface(surface, rect)?;
    Ok(
        Plot3d::new("Fig 4 — bicubic Hermite patch H(s)ᵀ C H(t) of the portion")
            .view(PATCH_VIEW)
            .surface(&patch, &Rect::unit(), n)?
            .figure(),
    )
}

/// Fig 5: the de Casteljau surface of the patch of `surface` on `rect` with its 16 control
/// points and net (Codice 9, 11: the torus on the portion `[0, 1]²`).
///
/// # Errors
/// A surface not finite at a corner.
pub fn fig5<S: ParametricSurface + ?Sized>(surface: &S, rect: &Rect) -> Result<Figure> {
    let bezier = BezierPatch::from_hermite(&HermitePatch::try_from_surface(surface, rect)?);
    let net = bezier.net();
    let net = Grid::from_fn(4, 4, |i, j| net[i][j]);
    Ok(
        Plot3d::new("Fig 5 — de Casteljau surface with its control net")
            .view(PATCH_VIEW)
            .grid(&bezier.tabulate_de_casteljau(30, 30)?, None, 0.75)
            .net(
                &net,
                RGBColor(200, 0, 0),
                "16 Bézier control points and net",
            )
            .figure(),
    )
}

/// Fig 6: spline patches with u split as `[0, 0.5, 0.9, 1]`, in §5's colours.
///
/// # Errors
/// Never in practice.
pub fn fig6() -> Result<Figure> {
    let spline = HermiteSurface::try_from_surface(
        &Torus::default(),
        Partition::try_new(vec![0.0, 0.5, 0.9, 1.0])?,
        Partition::try_new(vec![0.0, 1.0])?,
    )?;
    // §5's prose: u₁ = [0, 0.5] blue, u₃ = [0.9, 1] yellow, i.e. colors(i) in order
    // (Codice 14's mod(i,3)+1 would start with green; Fig 8 uses that one).
    Ok(
        Plot3d::new("Fig 6 — spline patches, u split as [0, 0.5, 0.9, 1], 15×15 samples each")
            .view(PATCH_VIEW)
            .patches(&spline, REPORT_PREC, FACE_ALPHA, true, |i, _| {
                CODICE14_COLORS[i % 3]
            })?
            .legend("u ∈ [0, 0.5]", CODICE14_COLORS[0])
            .legend("u ∈ [0.5, 0.9]", CODICE14_COLORS[1])
            .legend("u ∈ [0.9, 1]", CODICE14_COLORS[2])
            .figure(),
    )
}

/// Fig 7: a spline surface patch by patch, opaque, `samples` per patch side (the seed's: the
/// whole torus as 4 × 4 = 16 Hermite patches, 13 samples).
///
/// # Errors
/// Fewer than 2 samples.
pub fn fig7(spline: &HermiteSurface, samples: usize) -> Result<Figure> {
    let (n, m) = (spline.u().len(), spline.v().len());
    // (i + 2j) mod 5 differs between neighbours in u and in v, across the wrap-around too;
    // 13 samples per patch side keep the 16 patches' mesh lines apart at this size.
    Ok(Plot3d::new(format!(
        "Fig 7 — the surface as {n}×{m} = {} Hermite patches",
        n * m
    ))
    .patches(spline, samples, 1.0, false, |i, j| {
        PATCH_PALETTE[(i + 2 * j) % PATCH_PALETTE.len()]
    })?
    .figure())
}

/// Fig 8: the patches of a spline surface in Codice 14's colours, `REPORT_PREC` samples per
/// side (the seed's: the 9 patches of `n = m = 3` on `[0, 1]²`).
///
/// # Errors
/// Never in practice.
pub fn fig8(spline: &HermiteSurface) -> Result<Figure> {
    let (n, m) = (spline.u().len(), spline.v().len());
    // Codice 14: colors(mod(i,3)+1, :) for patch row i (1-based)
    let plot = Plot3d::new(format!(
        "Fig 8 — the {} patches of n = {n}, m = {m} (Codice 14)",
        n * m
    ))
    .view(PATCH_VIEW)
    .patches(spline, REPORT_PREC, FACE_ALPHA, true, |i, _| {
        codice14_color(i)
    })?;
    Ok((0..n.min(3))
        .fold(plot, |p, i| {
            p.legend(format!("patch row i = {}", i + 1), codice14_color(i))
        })
        .figure())
}

/// Beyond the report: the log-log convergence of the max-abs error with the `h⁴` slope.
///
/// # Errors
/// Never in practice.
pub fn convergence_figure() -> Result<Figure> {
    Ok(draw::convergence(
        &crate::report::seed000::tables::torus_convergence()?,
        "Convergence: max-abs error vs patch size h, n × n patches of the torus on [0,1]²",
    ))
}

/// Beyond the report: where the error lives, `|X_h − X|` over the parameters, `n = m = 3`.
///
/// # Errors
/// Never in practice.
pub fn error_map() -> Result<Figure> {
    let torus = Torus::default();
    let spline = HermiteSurface::uniform(&torus, &Rect::unit(), 3, 3)?;
    draw::error_map(&torus, &spline, 121)
}
