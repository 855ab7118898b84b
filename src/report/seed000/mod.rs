//! Seed 000, the course report *Interpolazione di superfici alla Hermite*: its tables T3 and
//! T6 (printed vs the report's listing vs ours), figures 1–8, and the outputs beyond it.

pub mod figures;
pub mod tables;

use crate::domain::Rect;
use crate::hermite::spline_surface::HermiteSurface;
use crate::report::Output;
use crate::surface::Torus;
use std::f64::consts::TAU;

/// Seed 000's outputs, in generation order.
pub const OUTPUTS: &[Output] = &[
    Output::table("torus-partials", "Exact partials of the torus from hyper-dual numbers beside the closed forms of Codice 3 (seed 000 §2)", tables::torus_partials),
    Output::table("t3-error", "Table T3: error of one Hermite patch of the torus on [0,1]² and [0,0.5]² (seed 000 §3), printed vs ours", tables::t3),
    Output::table("t4-equivalence", "Hermite ≡ Bézier check (Codice 10) for the correct net and Codice 7 as printed", tables::equivalence),
    Output::table("t6-spline-error", "Table T6: error of n×m Hermite spline patches of the torus (seed 000 §6), printed vs report's listing vs ours", tables::t6),
    Output::table("convergence", "Convergence study n = m = 1…64 with max-abs, RMS, the report's measure and observed orders", tables::convergence_table),
    Output::figure("fig1-patch-derivatives", "Fig 1: a Hermite patch with its corner points and X_s, X_t, X_st at each corner", || figures::fig1(&Torus::default(), &Rect::new(0.0, 1.2, 0.5, 1.6))),
    Output::figure("fig2-torus", "Fig 2: the torus, s, t in [0, 7] on a 50×50 grid (Codice 1)", figures::fig2),
    Output::figure("fig3-torus-corners", "Fig 3: the torus with the corners of the portion [0,1]² in red (Codice 2)", figures::fig3),
    Output::figure("fig4-hermite-patch", "Fig 4: the bicubic Hermite patch of the portion (Codice 5)", || figures::fig4(&Torus::default(), &figures::portion(), 30)),
    Output::figure("fig5-bezier-net", "Fig 5: the de Casteljau surface with its 16 Bézier control points and net", || figures::fig5(&Torus::default(), &figures::portion())),
    Output::figure("fig6-spline-patches", "Fig 6: spline patches with u split as [0, 0.5, 0.9, 1], Codice 14 colours", figures::fig6),
    Output::figure("fig7-whole-torus", "Fig 7: the whole torus as 4×4 = 16 Hermite patches", || figures::fig7(&HermiteSurface::uniform(&Torus::default(), &Rect::new(0.0, TAU, 0.0, TAU), 4, 4)?, 13)),
    Output::figure("fig8-nine-patches", "Fig 8: the 9 patches of the n = m = 3 case (Codice 14)", || figures::fig8(&HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 3, 3)?)),
    Output::figure("fig-convergence", "Beyond: log-log max-abs error vs patch size h, with the h⁴ slope", figures::convergence_figure),
    Output::figure("fig-error-map", "Beyond: interpolation error |X_h − X| over the parameter domain, n = m = 3", figures::error_map),
];
