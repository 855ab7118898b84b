//! The report's tables, computed from scratch.

use crate::bezier::codice7::report_codice7_net;
use crate::bezier::patch::BezierPatch;
use crate::domain::Rect;
use crate::hermite::patch::HermitePatch;
use crate::report::error::Result;
use crate::report::table::{self, frame, Table, COORDS};
use crate::report::table::{Column, Frame};
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

/// Rows of an error table (T3 or T6): for every printed case and coordinate, the printed
/// value, the report's listing run literally, our value by the Hermite matrix form and by
/// de Casteljau on the correct net, max-abs and RMS.
fn error_table(id: &'static str, printed: &[PrintedRow]) -> Result<Frame> {
    let torus = Torus::default();
    let mut case = Vec::new();
    let (mut ns, mut ms, mut coord, mut printed_col) = (vec![], vec![], vec![], vec![]);
    let (mut listing, mut listing_ok, mut ours, mut ours_ok, mut ours_dc) =
        (vec![], vec![], vec![], vec![], vec![]);
    let (mut max_abs, mut rms, mut verdicts) = (vec![], vec![], vec![]);
    for row in printed {
        let rect = Rect::square(0.0, row.side)?;
        let run = |eval| uniform_spline_errors(&torus, &rect, row.n, row.m, REPORT_PREC, eval);
        let lit = run(PatchEvaluation::ReportListing)?;
        let mat = run(PatchEvaluation::HermiteMatrix)?;
        let dc = run(PatchEvaluation::DeCasteljau)?;
        for (k, axis) in COORDS.iter().enumerate() {
            let l_ok = agrees_to_printed(row.values[k], lit.report_norm[k]);
            let o_ok = agrees_to_printed(row.values[k], mat.report_norm[k]);
            case.push(format!("[0,{}]², {}×{}", row.side, row.n, row.m));
            ns.push(row.n as u32);
            ms.push(row.m as u32);
            coord.push(*axis);
            printed_col.push(row.values[k]);
            listing.push(lit.report_norm[k]);
            listing_ok.push(l_ok);
            ours.push(mat.report_norm[k]);
            ours_ok.push(o_ok);
            ours_dc.push(dc.report_norm[k]);
            max_abs.push(mat.max_abs[k]);
            rms.push(mat.rms[k]);
            verdicts.push(verdict(l_ok, o_ok));
        }
    }
    frame(
        id,
        vec![
            Column::new("case".into(), case),
            Column::new("n".into(), ns),
            Column::new("m".into(), ms),
            Column::new("coord".into(), coord),
            Column::new("printed".into(), printed_col),
            Column::new("report_listing".into(), listing),
            Column::new("listing_agrees".into(), listing_ok),
            Column::new("ours".into(), ours),
            Column::new("ours_agrees".into(), ours_ok),
            Column::new("ours_de_casteljau".into(), ours_dc),
            Column::new("max_abs".into(), max_abs),
            Column::new("rms".into(), rms),
            Column::new("verdict".into(), verdicts),
        ],
    )
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
    let (mut rect_col, mut net_col, mut dev_col, mut ok_col) = (vec![], vec![], vec![], vec![]);
    for (label, rect) in rects {
        let h = HermitePatch::from_surface(&torus, &rect);
        for (net_label, net) in [
            ("correct M = A C Aᵀ", BezierPatch::from_hermite(&h)),
            ("Codice 7 as printed", report_codice7_net(&h)),
        ] {
            let dev = max_deviation(&h, &net)?;
            rect_col.push(label);
            net_col.push(net_label);
            dev_col.push(dev);
            ok_col.push(dev < 1e-13);
        }
    }
    Ok(Table {
        id: id.into(),
        title: "Hermite ≡ Bézier (Codice 10) for the correct net and for Codice 7 as printed".into(),
        df: frame(
            id,
            vec![
                Column::new("rectangle".into(), rect_col),
                Column::new("bezier_net".into(), net_col),
                Column::new("max_abs_deviation".into(), dev_col),
                Column::new("equivalent_1e-13".into(), ok_col),
            ],
        )?,
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
    let (mut s_col, mut t_col, mut what, mut coord) = (vec![], vec![], vec![], vec![]);
    let (mut formula, mut dual, mut closed, mut diff) = (vec![], vec![], vec![], vec![]);
    let (mut formula_value, mut formula_diff) = (vec![], vec![]);
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
                s_col.push(s);
                t_col.push(t);
                what.push(name);
                coord.push(*axis);
                formula.push(traced[k].plain());
                dual.push(ours[k]);
                closed.push(exact[k]);
                diff.push((ours[k] - exact[k]).abs());
                let v = traced[k].eval(&[s, t]);
                formula_value.push(v);
                formula_diff.push((v - ours[k]).abs());
            }
        }
    }
    Ok(Table {
        id: id.into(),
        title: "Exact partials of the torus: their formulas and hyper-dual values vs the closed forms of Codice 3".into(),
        df: frame(
            id,
            vec![
                Column::new("s".into(), s_col),
                Column::new("t".into(), t_col),
                Column::new("partial".into(), what),
                Column::new("coord".into(), coord),
                Column::new("formula".into(), formula),
                Column::new("hyper_dual".into(), dual),
                Column::new("closed_form".into(), closed),
                Column::new("abs_difference".into(), diff),
                Column::new("formula_value".into(), formula_value),
                Column::new("formula_abs_difference".into(), formula_diff),
            ],
        )?,
        notes: vec![
            "hyper_dual: one evaluation of the torus formula at s + ε₁, t + ε₂ (num-dual HyperDual64); closed_form: the derivatives MATLAB's diff returns (Codice 3).".into(),
            "formula: the same generic eval run once on hyper-dual numbers of symbolic expressions (splinelab::symbolic), simplified and printed; formula_value: that formula evaluated at (s, t), checked against hyper_dual.".into(),
            "X_st vanishes wherever sin t = 0, e.g. on the whole line t = 0 — the fact that hid the sign error of Codice 7 (see T6).".into(),
        ],
    })
}
