//! The formulas of the library's objects — and of anything generic a user writes — traced
//! through their own generic `eval`: surfaces and their partials, curves and their
//! derivatives on a piece, the Hermite, Bernstein and B-spline bases, a Hermite patch as
//! `H(s)ᵀ C H(t)`.

use super::display::{Math, MathTable};
use super::{Expr, Formula, Trace};
use crate::bspline::basis::BSplineBasis;
use crate::curve::ParametricCurve;
use crate::domain::Span;
use crate::error::{Error, Result};
use crate::hermite::patch::HermitePatch;
use crate::surface::ParametricSurface;
use nalgebra::Matrix4;
use num_dual::{Dual2, HyperDual};

/// Formulas traced from any code, with the conditions under which they hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Traced {
    /// One formula per value the code returned.
    pub formulas: Vec<Formula>,
    /// Where the formulas hold, as the code recorded it: the pieces it picked
    /// (`t ∈ [1/4, 1/2)`), the branches it took (`s - 1/4 > 0`), and — if it read a value
    /// without recording a condition — `only at t = 0.3 …`: nothing is claimed beyond what
    /// was recorded.
    pub branches: Vec<String>,
    /// The pieces, structured: the expression read and the interval of its values.
    pub pieces: Vec<(String, super::Condition)>,
    /// Whether the formulas are claimed at the trace point only (a value was read without a
    /// recorded condition).
    pub pointwise: bool,
}

/// One formula per line (`plain` text), then where they hold.
impl std::fmt::Display for Traced {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let lines: Vec<String> = self
            .formulas
            .iter()
            .map(Formula::plain)
            .chain(holds_where(&self.branches))
            .collect();
        f.write_str(&lines.join("\n"))
    }
}

/// Traces `f` at the variables `vars` (`(name, value)`): `f` runs once on [`Expr`] values,
/// and whatever it returns comes back as formulas.
///
/// ```
/// use num_dual::DualNum;
/// let out = splinelab::symbolic::trace([("x", 0.5)], |[x]| vec![x.sin() * x * 2.0])?;
/// assert_eq!(out.formulas[0].plain(), "2*x*sin(x)");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// [`Error::TooLarge`] beyond [`super::MAX_NODES`] nodes, or formulas beyond
/// [`super::MAX_FORMULA_SIZE`] / [`super::MAX_FORMULA_DEPTH`].
pub fn trace<const K: usize>(
    vars: [(&str, f64); K],
    f: impl FnOnce([Expr; K]) -> Vec<Expr>,
) -> Result<Traced> {
    trace_vars(&vars, |x| f(std::array::from_fn(|k| x[k])))
}

/// [`trace`] for a number of variables known only at run time.
fn trace_vars(vars: &[(&str, f64)], f: impl FnOnce(&[Expr]) -> Vec<Expr>) -> Result<Traced> {
    let mut trace = Trace::new();
    let x: Vec<Expr> = vars
        .iter()
        .map(|&(name, value)| trace.var(name, value))
        .collect();
    let values = f(&x);
    let formulas = trace.formulas(&values)?;
    let pieces = trace.pieces();
    let reads = trace.unrecorded_reads();
    let mut branches: Vec<String> = pieces.iter().map(|(what, c)| c.describe(what)).collect();
    branches.extend(trace.branches());
    if !reads.is_empty() {
        let at = vars
            .iter()
            .map(|(name, value)| format!("{name} = {}", super::number(*value)))
            .collect::<Vec<_>>()
            .join(", ");
        branches.push(format!(
            "only at {at}: the code read {} without recording a condition",
            reads.join(", ")
        ));
    }
    Ok(Traced {
        formulas,
        branches,
        pieces,
        pointwise: !reads.is_empty(),
    })
}

/// The formulas of `X`, `X_s`, `X_t`, `X_st` of a surface (each a coordinate triple), traced
/// at `(s, t)`, with the conditions under which they hold.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFormulas {
    /// `X(s, t)`.
    pub point: [Formula; 3],
    /// `X_s`.
    pub ds: [Formula; 3],
    /// `X_t`.
    pub dt: [Formula; 3],
    /// `X_st`.
    pub dst: [Formula; 3],
    /// Where the formulas hold: the piece of a piecewise surface (`s ∈ [1/4, 1/2)`), then the
    /// branches the evaluation took. Empty: everywhere the evaluation is defined.
    pub branches: Vec<String>,
    /// The parameters the formulas name as symbols, with the values they were checked at
    /// ([`surface_formulas_with_parameters`]; empty for [`surface_formulas`]).
    pub parameters: Vec<(String, f64)>,
}

/// The plain-text table a terminal shows ([`MathTable::plain`] of the `table()`).
impl std::fmt::Display for SurfaceFormulas {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(&self.table(), f)
    }
}

impl SurfaceFormulas {
    /// The four rows `X`, `X_s`, `X_t`, `X_st` by coordinate, the conditions as notes.
    pub fn table(&self) -> MathTable {
        let rows = [
            (Math::symbol("X", ""), &self.point),
            (Math::symbol("X", "s"), &self.ds),
            (Math::symbol("X", "t"), &self.dt),
            (Math::symbol("X", "st"), &self.dst),
        ];
        MathTable {
            header: ["", "x", "y", "z"].map(Math::text).to_vec(),
            rows: rows
                .into_iter()
                .map(|(label, f)| {
                    let mut row = vec![label];
                    row.extend(f.iter().map(Math::from));
                    row
                })
                .collect(),
            notes: {
                let mut notes = holds_where(&self.branches);
                if !self.parameters.is_empty() {
                    let values: Vec<String> = self
                        .parameters
                        .iter()
                        .map(|(name, value)| format!("{name} = {}", super::number(*value)))
                        .collect();
                    notes.push(format!("Checked at {}.", values.join(", ")));
                }
                notes
            },
        }
    }

    /// Shows [`SurfaceFormulas::table`] as rendered mathematics (the evcxr kernel calls this
    /// for a cell's value).
    pub fn evcxr_display(&self) {
        self.table().evcxr_display();
    }
}

/// The formulas of any [`ParametricSurface`]: its own generic `eval` run on hyper-dual
/// numbers of expressions, variables `s` and `t`. For a piecewise surface they hold on the
/// piece of `(s, t)` ([`ParametricSurface::span_at`]), recorded first in the branches.
///
/// ```
/// use splinelab::symbolic::surface_formulas;
/// use splinelab::Torus;
/// let f = surface_formulas(&Torus::new(2.0, 1.0), 0.3, 0.7)?;
/// assert_eq!(f.point[0].plain(), "cos(s)*(2 + cos(t))"); // f_x of Codice 3
/// assert_eq!(f.dst[0].plain(), "sin(s)*sin(t)");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// As [`trace`]; [`Error::NonFinite`] for a NaN or infinite trace point.
pub fn surface_formulas<S: ParametricSurface + ?Sized>(
    surface: &S,
    s: f64,
    t: f64,
) -> Result<SurfaceFormulas> {
    traced_surface(surface, s, t, false)
}

/// [`surface_formulas`] with the surface's parameters ([`ParametricSurface::parameters`]) as
/// symbols: the torus as `cos(s)*(R + r*cos(t))`, a [`crate::surface!`] with fields by its
/// fields' names. The parameters keep their values for the capture check, so each formula
/// is checked at the surface's own values. A surface without parameters gives what
/// [`surface_formulas`] gives.
///
/// ```
/// use splinelab::symbolic::surface_formulas_with_parameters;
/// use splinelab::Torus;
/// let f = surface_formulas_with_parameters(&Torus::default(), 0.3, 0.7)?;
/// assert_eq!(f.point[0].plain(), "cos(s)*(R + r*cos(t))");
/// assert_eq!(f.dst[2].plain(), "0");
/// assert_eq!(f.parameters, vec![("R".to_string(), 2.0), ("r".to_string(), 1.0)]);
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// As [`surface_formulas`]; [`Error::Degenerate`] for a parameter named `s` or `t`, or two
/// parameters of one name; [`Error::NonFinite`] for a parameter that is NaN or infinite.
pub fn surface_formulas_with_parameters<S: ParametricSurface + ?Sized>(
    surface: &S,
    s: f64,
    t: f64,
) -> Result<SurfaceFormulas> {
    traced_surface(surface, s, t, true)
}

/// The surface's formulas, its parameters as symbols or as numbers.
fn traced_surface<S: ParametricSurface + ?Sized>(
    surface: &S,
    s: f64,
    t: f64,
    symbols: bool,
) -> Result<SurfaceFormulas> {
    crate::error::finite("trace point s", s)?;
    crate::error::finite("trace point t", t)?;
    let parameters = if symbols {
        surface.parameters()
    } else {
        Vec::new()
    };
    for (k, &(name, value)) in parameters.iter().enumerate() {
        crate::error::finite("surface parameter", value)?;
        if ["s", "t"].contains(&name) || parameters[..k].iter().any(|p| p.0 == name) {
            return Err(Error::Degenerate {
                what: "surface parameters",
                reason: "a parameter is named s or t, or two parameters have one name: the formulas could not tell them apart",
            });
        }
    }
    let mut vars = vec![("s", s), ("t", t)];
    vars.extend(parameters.iter().copied());
    let traced = trace_vars(&vars, |x| {
        let (zero, one) = (Expr::constant(0.0), Expr::constant(1.0));
        let (sv, tv) = (x[0], x[1]);
        // with no parameters given, `eval_with` takes the surface's own values (as numbers)
        let given: Vec<HyperDual<Expr>> = x[2..]
            .iter()
            .map(|&p| HyperDual::new(p, zero, zero, zero))
            .collect();
        let x = surface.eval_with(
            HyperDual::new(sv, one, zero, zero),
            HyperDual::new(tv, zero, one, zero),
            &given,
        );
        let mut out = Vec::with_capacity(12);
        let parts: [fn(&HyperDual<Expr>) -> Expr; 4] =
            [|d| d.re, |d| d.eps1, |d| d.eps2, |d| d.eps1eps2];
        for part in parts {
            out.extend(x.iter().map(part));
        }
        out
    })?;
    let branches = traced.branches;
    let f: Vec<Formula> = traced.formulas.iter().map(Formula::tidy).collect();
    let three = |k: usize| [f[k].clone(), f[k + 1].clone(), f[k + 2].clone()];
    Ok(SurfaceFormulas {
        point: three(0),
        ds: three(3),
        dt: three(6),
        dst: three(9),
        branches,
        parameters: parameters
            .into_iter()
            .map(|(name, value)| (name.to_string(), value))
            .collect(),
    })
}

/// The formulas of a curve `C(t)`, `C′(t)`, `C″(t)` by coordinate, on the piece they hold on.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveFormulas {
    /// `C(t)`, one formula per coordinate.
    pub point: Vec<Formula>,
    /// `C′(t)`.
    pub d1: Vec<Formula>,
    /// `C″(t)`.
    pub d2: Vec<Formula>,
    /// The piece of `t` the evaluation picked and recorded; `None` for a curve whose code
    /// picked none (one formula, or the formulas hold at `t` only: see `branches`).
    pub span: Option<Span>,
    /// Where the formulas hold, as recorded ([`Traced::branches`]): the pieces, the
    /// branches, and `only at t = …` when the code read `t` without recording a condition.
    pub branches: Vec<String>,
    /// `Some(tᵢ)` when the formulas are written in the piece's local variable `u = t − tᵢ`
    /// ([`curve_formulas_local`]); `None` for the global `t` ([`curve_formulas`]).
    pub origin: Option<f64>,
}

/// The plain-text table a terminal shows ([`MathTable::plain`] of the `table()`).
impl std::fmt::Display for CurveFormulas {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(&self.table(), f)
    }
}

impl CurveFormulas {
    /// Whether the formulas are claimed at the trace point only.
    fn branches_pointwise(&self) -> bool {
        self.branches.iter().any(|b| b.starts_with("only at "))
    }

    /// Rows `C`, `C′`, `C″` by coordinate; the piece and branches as notes.
    pub fn table(&self) -> MathTable {
        let coords = ["x", "y", "z", "w"];
        let mut header = vec![Math::text("")];
        header.extend(
            (0..self.point.len()).map(|k| Math::text(coords.get(k).copied().unwrap_or("·"))),
        );
        let rows = [
            (Math::text("C"), &self.point),
            (Math::text("C′"), &self.d1),
            (Math::text("C″"), &self.d2),
        ]
        .into_iter()
        .map(|(label, f)| {
            let mut row = vec![label];
            row.extend(f.iter().map(Math::from));
            row
        })
        .collect();
        let mut notes = holds_where(&self.branches);
        if let Some(o) = self.origin {
            notes.push(format!(
                "In the piece's local variable u = {}.",
                local_variable(o)
            ));
        }
        MathTable {
            header,
            rows,
            notes,
        }
    }

    /// Shows [`CurveFormulas::table`] as rendered mathematics in a notebook.
    pub fn evcxr_display(&self) {
        self.table().evcxr_display();
    }
}

/// The formulas of any [`ParametricCurve`] and its first two derivatives on the piece that
/// holds `t` — its own generic `eval` run on a second-order dual number of expressions. A
/// B-spline's piece is a polynomial, a NURBS piece the rational form `Σ wᵢPᵢNᵢ / Σ wᵢNᵢ`;
/// polynomial pieces are multiplied out in powers of `t`. A Bézier curve is the B-spline of
/// order `n + 1` on its control points (`BSplineCurve::with_order(points, points.len())`):
/// one polynomial on `[0, 1]`.
///
/// # Errors
/// As [`trace`]; [`Error::NonFinite`] for a NaN or infinite `t`.
pub fn curve_formulas<const N: usize, C: ParametricCurve<N> + ?Sized>(
    curve: &C,
    t: f64,
) -> Result<CurveFormulas> {
    crate::error::finite("trace point", t)?;
    let (traced, f) = trace_curve(curve, "t", t, 0.0)?;
    let span = traced
        .pieces
        .iter()
        .find(|(what, _)| what == "t")
        .and_then(|(_, c)| c.as_span());
    Ok(CurveFormulas {
        point: f[..N].to_vec(),
        d1: f[N..2 * N].to_vec(),
        d2: f[2 * N..].to_vec(),
        span,
        branches: traced.branches,
        origin: None,
    })
}

/// The trace of `C`, `C′`, `C″` at `t = origin + v`, the variable `v` named `name` with the
/// value `value`; the formulas [tidied](Formula::tidy), coordinates of `C`, then `C′`, `C″`.
fn trace_curve<const N: usize, C: ParametricCurve<N> + ?Sized>(
    curve: &C,
    name: &str,
    value: f64,
    origin: f64,
) -> Result<(Traced, Vec<Formula>)> {
    let traced = trace([(name, value)], |[v]| {
        let (zero, one) = (Expr::constant(0.0), Expr::constant(1.0));
        let c = curve.eval(Dual2::new(v + origin, one, zero));
        let mut out: Vec<Expr> = c.iter().map(|d| d.re).collect();
        out.extend(c.iter().map(|d| d.v1));
        // num-dual's Dual2 carries f″ in v2
        out.extend(c.iter().map(|d| d.v2));
        out
    })?;
    let f = traced.formulas.iter().map(Formula::tidy).collect();
    Ok((traced, f))
}

/// `t - 2`, `t + 1/4`, `t` for the origin `2`, `−1/4`, `0`.
fn local_variable(origin: f64) -> String {
    if origin == 0.0 {
        "t".into()
    } else if origin < 0.0 {
        format!("t + {}", super::number(-origin))
    } else {
        format!("t - {}", super::number(origin))
    }
}

/// [`curve_formulas`] in the local variable of the piece that holds `t`, `u = t − tᵢ` with
/// `tᵢ` the piece's start, as the seeds write a piece (`u ∈ [0, tᵢ₊₁ − tᵢ)`): a polynomial
/// piece far from 0 printed in powers of the global `t` amplifies its rounding (a degree-5
/// B-spline piece on `[1.21, 1.5]` loses four digits), in powers of `u` it does not. The
/// conditions stay in `t`; where the code recorded no finite piece the origin is 0 (the
/// global variable, said in `origin`).
///
/// ```
/// use nalgebra::Vector2;
/// use splinelab::{BSplineCurve, symbolic::curve_formulas_local};
/// let pts: Vec<_> = (0..6).map(|i| Vector2::new(i as f64, (i % 2) as f64)).collect();
/// let curve = BSplineCurve::with_order(pts, 4)?;
/// let f = curve_formulas_local(&curve, 2.5)?;
/// assert_eq!(f.origin, Some(2.0));
/// assert!(f.point[0].names() == ["u"]);
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// # Errors
/// As [`curve_formulas`].
pub fn curve_formulas_local<const N: usize, C: ParametricCurve<N> + ?Sized>(
    curve: &C,
    t: f64,
) -> Result<CurveFormulas> {
    let global = curve_formulas(curve, t)?;
    let origin = global.span.map_or(0.0, |s| s.lo);
    let (traced, f) = trace_curve(curve, "u", t - origin, origin)?;
    let pointwise = global.branches_pointwise();
    let mut branches = global.branches;
    if traced.pointwise && !pointwise {
        branches.push(format!(
            "only at t = {}: the code read a value without recording a condition",
            super::number(t)
        ));
    }
    Ok(CurveFormulas {
        point: f[..N].to_vec(),
        d1: f[N..2 * N].to_vec(),
        d2: f[2 * N..].to_vec(),
        span: global.span,
        branches,
        origin: Some(origin),
    })
}

/// The cubic Hermite basis `H₀ … H₃` as formulas in `t`, traced from
/// [`crate::hermite::basis::hermite_basis`]: `1 - 3*t^2 + 2*t^3`, `t - 2*t^2 + t^3`, `t^3 - t^2`,
/// `3*t^2 - 2*t^3`, as the report prints them (seed 000 §1).
///
/// # Errors
/// None in practice (the trace is small); typed as [`trace`].
pub fn hermite_basis_formulas() -> Result<[Formula; 4]> {
    let traced = trace([("t", 0.5)], |[t]| {
        crate::hermite::basis::hermite_basis(t).to_vec()
    })?;
    let f = traced.formulas;
    Ok([f[0].clone(), f[1].clone(), f[2].clone(), f[3].clone()])
}

/// The Bernstein polynomials `B₀ⁿ … Bₙⁿ` as formulas in `t`, traced from
/// [`crate::bezier::bernstein::bernstein_all`]: for `n = 3`, `(1 - t)^3`, `3*t*(1 - t)^2`, `3*t^2*(1 - t)`,
/// `t^3` (seed 000 §4).
///
/// # Errors
/// [`Error::TooLarge`] above degree 64 (formulas of that size are not for reading); the
/// errors of [`crate::bezier::bernstein::bernstein_all`].
pub fn bernstein_formulas(n: usize) -> Result<Vec<Formula>> {
    const MAX_DEGREE: usize = 64;
    if n > MAX_DEGREE {
        return Err(Error::TooLarge {
            what: "degree of Bernstein formulas",
            got: n,
            max: MAX_DEGREE,
        });
    }
    let mut out = Err(Error::TooFewPoints {
        what: "Bernstein formulas",
        needed: 1,
        got: 0,
    });
    let traced = trace([("t", 0.5)], |[t]| {
        out = crate::bezier::bernstein::bernstein_all(n, t);
        out.clone().unwrap_or_default()
    })?;
    out?;
    Ok(traced.formulas)
}

/// The B-spline basis functions that are non-zero on one knot span, as polynomials in `t`.
#[derive(Debug, Clone, PartialEq)]
pub struct BasisFormulas {
    /// The index `i` of the first function, `N_{i,p}`.
    pub first: usize,
    /// The degree `p`.
    pub degree: usize,
    /// `N_{first,p}, …, N_{first+p,p}` on the span, in powers of `t`.
    pub functions: Vec<Formula>,
    /// The span they hold on.
    pub span: Span,
}

/// The plain-text table a terminal shows ([`MathTable::plain`] of the `table()`).
impl std::fmt::Display for BasisFormulas {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(&self.table(), f)
    }
}

impl BasisFormulas {
    /// One row per function, the span as a note.
    pub fn table(&self) -> MathTable {
        MathTable {
            header: vec![Math::text(""), Math::text("on the span")],
            rows: self
                .functions
                .iter()
                .enumerate()
                .map(|(j, f)| {
                    let sub = format!("{},{}", self.first + j, self.degree);
                    vec![Math::symbol("N", &sub), Math::from(f)]
                })
                .collect(),
            notes: holds_where(&[format!("t ∈ {}", self.span)]),
        }
    }

    /// Shows [`BasisFormulas::table`] as rendered mathematics in a notebook.
    pub fn evcxr_display(&self) {
        self.table().evcxr_display();
    }
}

/// The B-spline basis functions non-zero on the knot span of `t`, by the Cox–de Boor
/// recurrence as printed in seed 001 ([`BSplineBasis::cox_de_boor`]) traced on that span and
/// multiplied out in powers of `t`.
///
/// # Errors
/// [`Error::NonFinite`] for a NaN or infinite `t`; [`Error::TooLarge`] above degree 32; as
/// [`trace`].
pub fn bspline_basis_formulas(basis: &BSplineBasis, t: f64) -> Result<BasisFormulas> {
    const MAX_DEGREE: usize = 32;
    crate::error::finite("trace point", t)?;
    let p = basis.degree();
    if p > MAX_DEGREE {
        return Err(Error::TooLarge {
            what: "degree of B-spline basis formulas",
            got: p,
            max: MAX_DEGREE,
        });
    }
    let span = basis.find_span(t);
    let first = span - p;
    let traced = trace([("t", t)], |[tv]| {
        (first..=span)
            .map(|i| basis.cox_de_boor(i, p, tv))
            .collect()
    })?;
    Ok(BasisFormulas {
        first,
        degree: p,
        functions: traced.formulas.iter().map(Formula::tidy).collect(),
        span: basis.span_of(t),
    })
}

/// A bicubic Hermite patch as `X(s, t) = H(s)ᵀ C H(t)`: the basis exact, the matrix numeric,
/// and the polynomial it multiplies out to.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchFormulas {
    /// `H(s)`, traced from [`crate::hermite::basis::hermite_basis`].
    pub h_s: [Formula; 4],
    /// `H(t)`.
    pub h_t: [Formula; 4],
    /// The planes `C_x`, `C_y`, `C_z` of the Hermite matrix.
    pub c: [Matrix4<f64>; 3],
    /// `X(s, t)` by coordinate, multiplied out in powers of `s` and `t` (local parameters).
    pub x: [Formula; 3],
}

/// The plain-text table a terminal shows ([`MathTable::plain`] of the `table()`).
impl std::fmt::Display for PatchFormulas {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(&self.table(), f)
    }
}

impl PatchFormulas {
    /// The basis, the three planes and the polynomials.
    pub fn table(&self) -> MathTable {
        let h = |f: &[Formula; 4], v: &str| -> Vec<Vec<Math>> {
            f.iter()
                .enumerate()
                .map(|(i, f)| {
                    vec![
                        Math::text(&format!("H{}({v})", subscript_digit(i))),
                        Math::from(f),
                    ]
                })
                .collect()
        };
        let mut rows = h(&self.h_s, "s");
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            rows.push(vec![Math::symbol("C", axis), Math::matrix(&self.c[k])]);
        }
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            rows.push(vec![Math::text(axis), Math::from(&self.x[k])]);
        }
        MathTable {
            header: vec![Math::text(""), Math::text("X(s, t) = H(s)ᵀ C H(t)")],
            rows,
            notes: vec![
                "H(t) is H(s) with t for s; the polynomials are in the patch's local parameters s, t ∈ [0, 1].".into(),
            ],
        }
    }

    /// Shows [`PatchFormulas::table`] as rendered mathematics in a notebook.
    pub fn evcxr_display(&self) {
        self.table().evcxr_display();
    }
}

fn subscript_digit(i: usize) -> char {
    char::from_u32(0x2080 + (i as u32 % 10)).unwrap_or('?')
}

/// The formulas of a Hermite patch ([`PatchFormulas`]).
///
/// # Errors
/// As [`trace`].
pub fn patch_formulas(patch: &HermitePatch) -> Result<PatchFormulas> {
    let traced = trace([("s", 0.5), ("t", 0.5)], |[s, t]| {
        let mut out = crate::hermite::basis::hermite_basis(s).to_vec();
        out.extend(crate::hermite::basis::hermite_basis(t));
        out.extend(patch.eval(s, t).iter().copied());
        out
    })?;
    let f: Vec<Formula> = traced.formulas;
    let x: Vec<Formula> = f[8..].iter().map(Formula::tidy).collect();
    Ok(PatchFormulas {
        h_s: [f[0].clone(), f[1].clone(), f[2].clone(), f[3].clone()],
        h_t: [f[4].clone(), f[5].clone(), f[6].clone(), f[7].clone()],
        c: patch.planes(),
        x: [x[0].clone(), x[1].clone(), x[2].clone()],
    })
}

/// The note under a table of formulas that hold only under `conditions` (none if empty).
fn holds_where(conditions: &[String]) -> Vec<String> {
    let (only, rest): (Vec<&String>, Vec<&String>) =
        conditions.iter().partition(|c| c.starts_with("only at "));
    let mut out = Vec::new();
    if !rest.is_empty() {
        out.push(format!(
            "These formulas hold where {}.",
            rest.iter()
                .map(|c| c.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    out.extend(only.iter().map(|c| format!("They are claimed {c}.")));
    out
}
