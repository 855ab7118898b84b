//! The report's tables, computed from scratch.

use crate::bezier::codice7::report_codice7_net;
use crate::bezier::patch::BezierPatch;
use crate::domain::Rect;
use crate::hermite::patch::HermitePatch;
use crate::report::error::Result;
use crate::report::frame::Frame;
use crate::report::record::frame_of;
use crate::report::table::{self, Table, COORDS};
use crate::seeds::seed000::{agrees_to_printed, PrintedRow, T3, T6};
use crate::study::hermite_error::{
    convergence, uniform_spline_errors, PatchEvaluation, REPORT_PREC,
};
use crate::surface::Torus;
use nalgebra::Vector3;

/// What the comparison of the printed value with the two reproductions shows.
fn verdict(listing_agrees: bool, ours_agrees: bool) -> &'static str {
    match (listing_agrees, ours_agrees) {
        (true, true) => "agrees",
        (true, false) => "report's listing reproduces the printed value; the correct value differs (Codice 7 sign error)",
        (false, true) => "printed value matches the correct method, not the listing",
        (false, false) => "unexplained: printed value matches neither reproduction",
    }
}

crate::record! {
    /// A row of an error table: one printed case and coordinate.
    struct ErrorRow {
        case: String => "case",
        n: u32 => "n",
        m: u32 => "m",
        coord: &'static str => "coord",
        printed: &'static str => "printed",
        report_listing: f64 => "report_listing",
        listing_agrees: bool => "listing_agrees",
        ours: f64 => "ours",
        ours_agrees: bool => "ours_agrees",
        ours_de_casteljau: f64 => "ours_de_casteljau",
        max_abs: f64 => "max_abs",
        rms: f64 => "rms",
        verdict: &'static str => "verdict",
    }
}

/// Rows of an error table (T3 or T6): for every printed case and coordinate, the printed
/// value, the report's listing run literally, our value by the Hermite matrix form and by
/// de Casteljau on the correct net, max-abs and RMS.
fn error_table(id: &'static str, printed: &[PrintedRow]) -> Result<Frame> {
    let torus = Torus::default();
    let mut rows = Vec::new();
    for row in printed {
        let rect = Rect::square(0.0, row.side)?;
        let run = |eval| uniform_spline_errors(&torus, &rect, row.n, row.m, REPORT_PREC, eval);
        let lit = run(PatchEvaluation::ReportListing)?;
        let mat = run(PatchEvaluation::HermiteMatrix)?;
        let dc = run(PatchEvaluation::DeCasteljau)?;
        for (k, axis) in COORDS.iter().enumerate() {
            let listing_agrees = agrees_to_printed(row.values[k], lit.report_norm[k]);
            let ours_agrees = agrees_to_printed(row.values[k], mat.report_norm[k]);
            rows.push(ErrorRow {
                case: format!("[0,{}]², {}×{}", row.side, row.n, row.m),
                n: row.n as u32,
                m: row.m as u32,
                coord: axis,
                printed: row.values[k],
                report_listing: lit.report_norm[k],
                listing_agrees,
                ours: mat.report_norm[k],
                ours_agrees,
                ours_de_casteljau: dc.report_norm[k],
                max_abs: mat.max_abs[k],
                rms: mat.rms[k],
                verdict: verdict(listing_agrees, ours_agrees),
            });
        }
    }
    frame_of(id, &rows)
}

fn error_notes() -> Vec<String> {
    vec![
        format!("Measure: the report's norm(abs(X_hermite − X)) per patch, the largest singular value of the {p}×{p} matrix of absolute errors (MATLAB norm of a matrix), averaged over patches (Codice 14, prec = {p}).", p = REPORT_PREC),
        "report_listing: the report's printed code path run literally — Hermite matrix (Codice 13), Bézier net by Codice 7 exactly as printed, de Casteljau tabulation (Codice 11–12).".into(),
        "ours: the Hermite matrix form H(s)ᵀ C H(t); ours_de_casteljau: de Casteljau on the correct Bézier net M = A C Aᵀ. The two agree to rounding.".into(),
        "*_agrees: the value rounds to the printed value at the printed precision.".into(),
        "Codice 7 prints M(3,2) = C(4,1) + C(4,2)/3 − C(3,1)/3 + C(3,2)/9; the correct sign of the C(3,2)/9 term is minus. On the torus X_st = (sin t sin s, −sin t cos s, 0) vanishes at t = 0, so patches with tₐ = 0 (all of T3 and the rows with m = 1) are unaffected.".into(),
        "max_abs and rms (per coordinate, over all samples, Hermite matrix form) are error measures in their own right; the report's norm grows with the number of samples.".into(),
    ]
}

/// T3: seed 000 §3, a single patch of the torus on `[0, 1]²` and `[0, 0.5]²`.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn t3() -> Result<Table> {
    let id = "t3-error";
    Ok(Table {
        id: id.into(),
        title: "T3 — interpolation error of one Hermite patch of the torus (seed 000 §3)".into(),
        df: error_table(id, &T3)?,
        notes: error_notes(),
    })
}

/// T6: seed 000 §6, `n × m` patches of the torus on `[0, 1]²`.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn t6() -> Result<Table> {
    let id = "t6-spline-error";
    Ok(Table {
        id: id.into(),
        title: "T6 — interpolation error of the Hermite spline surface, n × m patches on [0,1]² (seed 000 §6)".into(),
        df: error_table(id, &T6)?,
        notes: error_notes(),
    })
}

/// Largest deviation `max |X_hermite − X_bezier|` over a `101 × 101` grid, all coordinates.
fn max_deviation(h: &HermitePatch, b: &BezierPatch) -> Result<f64> {
    let a = h.tabulate(101, 101)?;
    let c = b.tabulate_de_casteljau(101, 101)?;
    Ok(a.as_slice()
        .iter()
        .zip(c.as_slice())
        .map(|(p, q)| (p - q).amax())
        .fold(0.0, f64::max))
}

crate::record! {
    /// A row of the Hermite ≡ Bézier check: a rectangle and a net.
    struct EquivalenceRow {
        rectangle: &'static str => "rectangle",
        bezier_net: &'static str => "bezier_net",
        max_abs_deviation: f64 => "max_abs_deviation",
        equivalent: bool => "equivalent_1e-13",
    }
}

/// The Hermite ≡ Bézier check of Codice 10, on the report's rectangle and on rectangles where
/// the torus's mixed partial is non-zero at every corner, for the correct net and for the
/// net of Codice 7 as printed.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn equivalence() -> Result<Table> {
    let id = "t4-equivalence";
    let torus = Torus::default();
    let rects = [
        ("[0,1]² (report, Codice 10)", Rect::unit()),
        ("[0,1]×[0.5,1]", Rect::new(0.0, 1.0, 0.5, 1.0)),
        ("[0.3,1.4]×[0.5,1.7]", Rect::new(0.3, 1.4, 0.5, 1.7)),
    ];
    let mut rows = Vec::new();
    for (label, rect) in rects {
        let h = HermitePatch::from_surface(&torus, &rect);
        for (net_label, net) in [
            ("correct M = A C Aᵀ", BezierPatch::from_hermite(&h)),
            ("Codice 7 as printed", report_codice7_net(&h)),
        ] {
            let deviation = max_deviation(&h, &net)?;
            rows.push(EquivalenceRow {
                rectangle: label,
                bezier_net: net_label,
                max_abs_deviation: deviation,
                equivalent: deviation < 1e-13,
            });
        }
    }
    Ok(Table {
        id: id.into(),
        title: "Hermite ≡ Bézier (Codice 10) for the correct net and for Codice 7 as printed".into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "max_abs_deviation: largest |X_hermite − X_bezier| over a 101×101 grid of the patch, all coordinates; Bézier by de Casteljau.".into(),
            "The report's check (Codice 10) used [0,1]², where the torus's X_st vanishes at the corner (s_b, t_a) = (1, 0), so the wrong sign in Codice 7's M(3,2) cannot show; on rectangles with tₐ ≠ 0 it does.".into(),
        ],
    })
}

/// Patch counts of the convergence study.
pub const CONVERGENCE_NS: [usize; 7] = [1, 2, 4, 8, 16, 32, 64];

/// The convergence study of the torus on `[0, 1]²` behind the convergence table and figure:
/// `n × n` patches for `n` in [`CONVERGENCE_NS`], [`REPORT_PREC`] samples per patch side.
///
/// # Errors
/// Never in practice (the data are fixed and valid).
pub fn torus_convergence() -> Result<Vec<crate::study::hermite_error::ConvergenceRow>> {
    Ok(convergence(
        &Torus::default(),
        &Rect::unit(),
        &CONVERGENCE_NS,
        REPORT_PREC,
    )?)
}

/// Convergence of the torus's Hermite spline on `[0, 1]²`, `n × n` patches,
/// `n = 1, 2, 4, …, 64`, with observed orders between rows (expected: 4).
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn convergence_table() -> Result<Table> {
    let rows = torus_convergence()?;
    Ok(table::convergence(
        "convergence",
        "Convergence of the bicubic Hermite spline of the torus on [0,1]², n × n patches",
        &rows,
    )?
    .note(format!(
        "Each patch sampled on {p}×{p} points as in Codice 14; h = 1/n.",
        p = REPORT_PREC
    )))
}

crate::record! {
    /// A row of the torus's partials: one point, partial and coordinate.
    struct PartialRow {
        s: f64 => "s",
        t: f64 => "t",
        partial: &'static str => "partial",
        coord: &'static str => "coord",
        formula: String => "formula",
        hyper_dual: f64 => "hyper_dual",
        closed_form: f64 => "closed_form",
        abs_difference: f64 => "abs_difference",
        formula_value: f64 => "formula_value",
        formula_abs_difference: f64 => "formula_abs_difference",
    }
}

/// The partials of the torus from hyper-dual numbers beside the closed forms MATLAB's `diff`
/// returns in Codice 3, at a few points: what §2 computes symbolically, here exact to rounding.
///
/// Closed forms (R = 2, r = 1): `X_s = (−(R + r cos t) sin s, (R + r cos t) cos s, 0)`,
/// `X_t = (−r sin t cos s, −r sin t sin s, r cos t)`, `X_st = (r sin t sin s, −r sin t cos s, 0)`.
///
/// # Errors
/// Only on a ragged frame, an internal error ([`crate::report::Error::Table`]).
pub fn torus_partials() -> Result<Table> {
    use crate::surface::SurfaceDerivatives;
    let id = "torus-partials";
    let torus = Torus::default();
    let (big_r, r) = (torus.major(), torus.minor());
    // the formulas, traced once through the same `eval` that gives the numbers
    let formulas = crate::symbolic::surface_formulas(&torus, 0.3, 0.7)?;
    let points = [(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0), (0.3, 2.1)];
    let mut rows = Vec::new();
    for (s, t) in points {
        let d = torus.partials(s, t);
        let (ss, cs, st, ct) = (s.sin(), s.cos(), t.sin(), t.cos());
        let ring = big_r + r * ct;
        let closed_forms = [
            (
                "X",
                d.point,
                Vector3::new(ring * cs, ring * ss, r * st),
                &formulas.point,
            ),
            (
                "X_s",
                d.ds,
                Vector3::new(-ring * ss, ring * cs, 0.0),
                &formulas.ds,
            ),
            (
                "X_t",
                d.dt,
                Vector3::new(-r * st * cs, -r * st * ss, r * ct),
                &formulas.dt,
            ),
            (
                "X_st",
                d.dst,
                Vector3::new(r * st * ss, -r * st * cs, 0.0),
                &formulas.dst,
            ),
        ];
        for (name, ours, exact, traced) in closed_forms {
            for (k, axis) in COORDS.iter().enumerate() {
                let value = traced[k].eval(&[s, t]);
                rows.push(PartialRow {
                    s,
                    t,
                    partial: name,
                    coord: axis,
                    formula: traced[k].plain(),
                    hyper_dual: ours[k],
                    closed_form: exact[k],
                    abs_difference: (ours[k] - exact[k]).abs(),
                    formula_value: value,
                    formula_abs_difference: (value - ours[k]).abs(),
                });
            }
        }
    }
    Ok(Table {
        id: id.into(),
        title: "Exact partials of the torus: their formulas and hyper-dual values vs the closed forms of Codice 3".into(),
        df: frame_of(id, &rows)?,
        notes: vec![
            "hyper_dual: one evaluation of the torus formula at s + ε₁, t + ε₂ (num-dual HyperDual64); closed_form: the derivatives MATLAB's diff returns (Codice 3).".into(),
            "formula: the same generic eval run once on hyper-dual numbers of symbolic expressions (splinelab::symbolic), simplified and printed; formula_value: that formula evaluated at (s, t), checked against hyper_dual.".into(),
            "X_st vanishes wherever sin t = 0, e.g. on the whole line t = 0 — the fact that hid the sign error of Codice 7 (see T6).".into(),
        ],
    })
}
