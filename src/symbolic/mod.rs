//! Symbolic and numeric from one code path: an expression type ([`Expr`]) that num-dual's
//! dual numbers carry as their inner type, so the very generic `eval` that computes numbers
//! records the formulas of its derivatives — the chain rule is num-dual's own, nothing here
//! differentiates.
//!
//! ```
//! use splinelab::symbolic::surface_formulas;
//! use splinelab::Torus;
//! let f = surface_formulas(&Torus::new(2.0, 1.0), 0.3, 0.7)?;
//! assert_eq!(f.point[0].plain(), "cos(s)*(2 + cos(t))");   // f_x of Codice 3
//! assert_eq!(f.ds[0].plain(), "-sin(s)*(2 + cos(t))");     // diff(f_x, s)
//! assert_eq!(f.dst[0].plain(), "sin(s)*sin(t)");           // diff(f_x, s, t)
//! assert!((f.dst[0].eval(&[0.3, 0.7]) - 0.3f64.sin() * 0.7f64.sin()).abs() < 1e-15);
//! # Ok::<(), splinelab::Error>(())
//! ```
//!
//! **The API.** [`surface_formulas`] (any [`crate::surface::ParametricSurface`]: `X`, `X_s`, `X_t`,
//! `X_st`), [`surface_formulas_with_parameters`] (the same with the surface's parameters as
//! symbols: `cos(s)*(R + r*cos(t))`), [`curve_formulas`] (any [`crate::curve::ParametricCurve`]: `C`, `C′`, `C″` on the piece of
//! `t`), [`hermite_basis_formulas`], [`bernstein_formulas`], [`bspline_basis_formulas`] (on a
//! knot span), [`patch_formulas`] (`H(s)ᵀ C H(t)`), and [`trace`] for any generic code of
//! one's own; [`crate::surface!`] writes a user surface once for numbers and formulas. Each
//! result has a [`MathTable`] (`table()`) that a notebook shows as rendered mathematics, and
//! prints as a plain-text table (`Display`, [`MathTable::plain`]):
//!
//! ```
//! use splinelab::prelude::*;
//! surface!(pub Saddle { c: f64 } = |s, t| Vector3::new(s, t, s * t * c));
//! let f = symbolic::surface_formulas_with_parameters(&Saddle { c: 0.5 }, 0.3, 0.7)?;
//! let table = f.to_string();
//! assert!(table.lines().any(|l| l.starts_with("X_st") && l.trim_end().ends_with('c')));
//! println!("{table}");
//! # Ok::<(), splinelab::Error>(())
//! ```
//!
//! **Expressions.** An [`Expr`] is `Copy`: an index into a per-thread arena of hash-consed
//! nodes (equal subexpressions are one node) and its value at the trace point, so `re()`,
//! comparisons and `abs` follow the numeric path. A [`Trace`] owns the arena: it is emptied
//! when a trace starts and freed when it ends, so a long session does not grow; a trace holds
//! at most [`MAX_NODES`] nodes ([`crate::error::Error::TooLarge`] beyond). One trace per thread at a
//! time.
//!
//! **Trust.** Nothing is printed that was not checked.
//! - *Identity*: every trace has an identity unique in the process (a global counter, as
//!   CppAD's tape ids), every handle names it, and handles and traces cannot leave their
//!   thread (`Expr` is neither `Send` nor `Sync`). A handle of an ended trace is refused; an
//!   operation given one (`old + y`) poisons the running trace, and every formula of it is
//!   then [`crate::error::Error::Degenerate`].
//! - *Capture check*: each formula, simplified, is evaluated at the trace point and compared
//!   with the value the traced code computed, within 8 ε times the sum of both computations'
//!   first-order rounding bounds ([`crate::error::Error::FormulaCheck`] beyond). Multiplied-out and
//!   cleaned forms are checked again; a cleaned form that fails is not used.
//! - *Where it holds*: see **Branches**.
//!
//! **Simplification** (on capture, into a normal form: a sum of terms, each a coefficient times
//! a product of powers). Every rule's right side is defined, and equal, wherever its left side
//! is:
//! - constants folded and multiplied into sums; `0` and `1` removed;
//! - like terms collected, factors compared as multisets (`x·y + 2y·x = 3x·y`,
//!   `sin(x + y) − sin(y + x) = 0`);
//! - equal bases merged by their exponents (`x²·x⁻¹ = x`, `√(1+x²)·√(1+x²) = 1 + x²`);
//! - `(x·y)ⁿ = xⁿ·yⁿ` and `(xᵃ)ⁿ = xᵃⁿ` for integer `n`; `(c·x·y)ᵖ = cᵖ·xᵖ·yᵖ` for real `p`
//!   only when `c > 0` and every base is `≥ 0` by its structure (`exp`, `cosh`, `|·|`, `acos`,
//!   sums of such), or for one base with an odd integer power (`√(1/x) = x^(−1/2)`: `xᵃ` and
//!   `x` have one sign): `√(s·t)` stays whole (at `s = t = −1` it is 1, `√s·√t` is not real), and
//!   `√(x²)` stays (it is `|x|`);
//! - the Pythagorean identities on squares with equal rests and matching coefficients:
//!   `c·R·sin²u + c·R·cos²u = c·R`, `c·R·cosh²u − c·R·sinh²u = c·R` (so `d/dt tanh t` is
//!   `1/cosh(t)^2`);
//! - a sum that is a factor keeps its sign outside (`(−a − b)·c = −(a + b)·c`);
//! - on capture, a sum whose terms' denominators are powers of one atom is written over it
//!   when that is shorter, the numerator multiplied out so that terms cancel and the
//!   identities meet (`2 − 2 sinh²/cosh² = 2/cosh²`, `d²/ds dt asin(st/2)` as
//!   `1/(2*(1 - s^2*t^2/4)^(3/2))`), and `sinᵉu/cosᵉu`, `sinhᵉu/coshᵉu` are `tanᵉu`, `tanhᵉu`;
//! - constants that are fractions within rounding read as those fractions, and the
//!   arithmetic of coefficients exact on them: a spline patch on data computed from fractions
//!   prints `29/81 - s^3/81`, not `0.35802469135802467 - 0.012345679012345734*s^3`; numbers
//!   that are only floating point (`cos(π/4)`) stay numbers (a denominator up to `2²⁰`, within
//!   16 units in the last place; a formula so read that fails the capture check is captured
//!   again without reading);
//! - rounding residue cleaned where the capture check allows it: a coefficient within 32 ulps
//!   of a fraction with denominator ≤ 64 becomes it (`3/5`, not `0.6000000000000001`), a
//!   coefficient below 64 ε of the largest in its sum is dropped, and a formula that is only
//!   a constant within the traced computation's own rounding is `0`.
//!
//! Polynomial and rational pieces (splines, bases, a patch) are multiplied out in powers of
//! the variables ([`Formula::tidy`], [`Formula::expanded`]), over one denominator where all
//! denominators are powers of one polynomial (a NURBS piece's derivatives:
//! `(N′·D − N·D′)/D^2`); other formulas keep their products (`cos(s)*(2 + cos(t))`).
//! [`curve_formulas`] prints a piece in the global `t`; [`curve_formulas_local`] in the
//! piece's local variable `u = t − tᵢ`, which keeps the digits a power form in `t` loses far
//! from 0. *Not done:* other function identities (`sin 2x = 2 sin x cos x`), common
//! denominators of different atoms, cancelling common factors of a numerator and
//! denominator other than equal bases, factoring polynomials.
//!
//! **Printing.** Plain text with ASCII operators ([`Formula::plain`]: `-sin(s)*(2 + cos(t))`,
//! `3*t^2/2`, readable back by a parser with the usual precedence), LaTeX
//! ([`Formula::latex`]) and presentation MathML ([`Formula::mathml`], which browsers render
//! without a script: a notebook's HTML copy shows it); brackets only where precedence needs
//! them (none around a sum alone above or below a fraction bar); one print order — a
//! product's variables first, then functions, powers and groups, each by the variables they
//! depend on (`-cos(s)*sin(t)` wherever that product occurs); a sum by ascending powers with
//! constants first and a positive term leading (the report's `1 - 3*t^2 + 2*t^3`); a constant
//! that is exactly a small rational prints as a fraction (`1/4`), others as the shortest
//! decimal that reads back to the same `f64`, with an exponent below `10⁻⁴` ([`number`]).
//!
//! **Branches.** A formula claims no more than the traced code recorded. Where the code picks
//! a piece by a value, it does so through one helper that picks and records the interval the
//! choice holds for, so the claim cannot differ from the branch taken (`t ∈ [1/4, 1/2)`, the
//! Angular spline's `t > 3` beyond its end: [`Trace::pieces`]). Comparisons, `abs`,
//! `signum` and `is_positive` record their condition ([`Trace::branches`]). Any other read
//! of a value (`re()` in a user's curve, num-dual's `sph_j0` near 0) is recorded as such
//! ([`Trace::unrecorded_reads`]), and the formulas are then claimed at the trace point only.
//!
//! **Limits.** [`MAX_NODES`] per trace; a formula written out as a tree at most
//! [`MAX_FORMULA_SIZE`] nodes and [`MAX_FORMULA_DEPTH`] deep (so printing and evaluation
//! terminate and cannot overflow the stack); multiplying out at most [`MAX_EXPANDED_TERMS`]
//! terms. Beyond each: [`crate::error::Error::TooLarge`], never a panic.
//!
//! **No formula:** `%` gives an opaque node carrying its numeric value (printed `rem[…]`);
//! parsing (`Num::from_str_radix`) is an error.
//!
//! **Checked elsewhere:** [`corpus`] lists objects of every kind with their formulas and
//! reference values, for `splinelab formulas` and `scripts/check_formulas.py` (sympy).

mod canon;
mod coef;
pub mod corpus;
mod display;
// HTML/MathML escaping, also the report layer's (one function for both)
#[cfg(feature = "report")]
pub(crate) use print::escape;
mod expr;
mod formulas;
mod ops;
mod print;

pub use crate::branch::Condition;
pub use canon::{MAX_EXPANDED_TERMS, MAX_FORMULA_DEPTH, MAX_FORMULA_SIZE};
pub use display::{Math, MathTable};
pub use expr::{Expr, Func, Node, MAX_NODES};
pub use formulas::{
    bernstein_formulas, bspline_basis_formulas, curve_formulas, curve_formulas_local,
    hermite_basis_formulas, patch_formulas, surface_formulas, surface_formulas_with_parameters,
    trace, BasisFormulas, CurveFormulas, PatchFormulas, SurfaceFormulas, Traced,
};
pub use print::{number, Formula};

use crate::error::{Error, Result};
use expr::ARENA;
use std::cell::RefCell;

thread_local! {
    /// The running trace's variables: names and values at the trace point.
    static VARS: RefCell<(Vec<String>, Vec<f64>)> = const { RefCell::new((Vec::new(), Vec::new())) };
}

pub(crate) fn current_names() -> Vec<String> {
    VARS.with(|v| v.borrow().0.clone())
}

/// The running trace's variables' values at the trace point.
pub(crate) fn current_point() -> Vec<f64> {
    VARS.with(|v| v.borrow().1.clone())
}

/// A running trace (module docs): variables, then formulas of what was computed from them.
/// Dropping it frees the arena. Its identity is unique in the process; like its
/// expressions, it cannot leave its thread.
#[derive(Debug)]
pub struct Trace {
    generation: u64,
    local: expr::ThreadBound,
}

impl Trace {
    /// Starts a trace on this thread (any earlier one's handles go stale).
    pub fn new() -> Trace {
        VARS.with(|v| {
            let mut v = v.borrow_mut();
            v.0.clear();
            v.1.clear();
        });
        let generation = ARENA.with(|a| {
            let mut a = a.borrow_mut();
            a.reset();
            a.generation
        });
        Trace {
            generation,
            local: std::marker::PhantomData,
        }
    }

    /// A variable named `name` with the value `value` at the trace point.
    pub fn var(&mut self, name: &str, value: f64) -> Expr {
        let index = VARS.with(|v| {
            let mut v = v.borrow_mut();
            v.0.push(name.to_string());
            v.1.push(value);
            v.0.len() as u32 - 1
        });
        Expr::make(Node::Var(index), value, &[])
    }

    fn live(&self) -> bool {
        ARENA.with(|a| a.borrow().generation == self.generation)
    }

    /// The formula of `e`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] if the trace exceeded [`MAX_NODES`]; [`Error::Degenerate`] for a
    /// handle of another trace (ended, or another thread's), or for any formula of a trace
    /// that was given one; [`Error::FormulaCheck`] if the simplified formula does not equal
    /// the traced value at the trace point.
    pub fn formula(&self, e: &Expr) -> Result<Formula> {
        self.check_live(std::slice::from_ref(e))?;
        Formula::capture(e, &current_names(), &current_point())
    }

    /// That the trace did not overflow and that every handle is this trace's.
    fn check_live(&self, es: &[Expr]) -> Result<()> {
        let (overflowed, nodes, poisoned) = ARENA.with(|a| {
            let a = a.borrow();
            (a.overflowed, a.nodes.len(), a.poisoned)
        });
        if poisoned {
            return Err(Error::Degenerate {
                what: "symbolic trace",
                reason: "an expression of another trace (ended, or another thread's) was combined with this trace's: none of its formulas can be trusted",
            });
        }
        if overflowed {
            return Err(Error::TooLarge {
                what: "expression nodes of a trace",
                got: nodes + 1,
                max: MAX_NODES,
            });
        }
        if !self.live() || es.iter().any(|e| e.generation != self.generation) {
            return Err(Error::Degenerate {
                what: "symbolic formula",
                reason: "the expression belongs to a trace that has ended",
            });
        }
        Ok(())
    }

    /// The formulas of `es`, copied out in one pass (their shared subexpressions simplified
    /// once): what [`Trace::formula`] gives for each, faster.
    ///
    /// # Errors
    /// As [`Trace::formula`].
    pub fn formulas(&self, es: &[Expr]) -> Result<Vec<Formula>> {
        self.check_live(es)?;
        Formula::capture_many(es, &current_names(), &current_point())
    }

    /// The pieces the traced code picked by a value, as it recorded them
    /// (through one helper that picks and records): the expression read (`t`, `u - 2`) and the interval of its values
    /// on which the choice holds, in order.
    ///
    /// A condition on an affine function of one variable (`u - 1 ≥ 1/2`, the second arc of
    /// an Angular inflection piece) is a condition on that variable, and the conditions on
    /// one variable are intersected into one (`u ∈ [3/2, 2)`).
    pub fn pieces(&self) -> Vec<(String, Condition)> {
        let claims = ARENA.with(|a| a.borrow().claims.clone());
        let (names, point) = (current_names(), current_point());
        let mut out: Vec<(String, Condition)> = Vec::new();
        for (id, c) in claims {
            let e = Expr::from_id(id, f64::NAN, self.generation);
            let (what, c) = match Formula::capture(&e, &names, &point) {
                Ok(f) => match f.affine() {
                    Some((i, a, b)) => (
                        names.get(i as usize).cloned().unwrap_or_default(),
                        c.pulled_back(a, b),
                    ),
                    None => (f.plain(), c),
                },
                Err(err) => (format!("<{err}>"), c),
            };
            match out.iter_mut().find(|(w, _)| *w == what) {
                Some((_, known)) => *known = known.intersect(&c),
                None => out.push((what, c)),
            }
        }
        out
    }

    /// The values the traced code read without recording a condition (`t = 0.3`): the
    /// formulas hold at the trace point, and nothing is claimed beyond it.
    pub fn unrecorded_reads(&self) -> Vec<String> {
        let reads = ARENA.with(|a| a.borrow().reads.clone());
        reads
            .into_iter()
            .map(|(id, value)| format!("{} = {}", self.describe_node(id, value), number(value)))
            .collect()
    }

    /// The plain formula of node `id` of this trace, whose traced value is `value` (for
    /// conditions).
    fn describe_node(&self, id: u32, value: f64) -> String {
        let e = Expr::from_id(id, value, self.generation);
        match Formula::capture(&e, &current_names(), &current_point()) {
            Ok(f) => f.plain(),
            Err(err) => format!("<{err}>"),
        }
    }

    /// The conditions the numeric path took on the way (`s - 1/4 > 0`, …), in order.
    pub fn branches(&self) -> Vec<String> {
        let branches = ARENA.with(|a| a.borrow().branches.clone());
        branches
            .into_iter()
            .map(|(id, what, value)| format!("{} {what}", self.describe_node(id, value)))
            .collect()
    }
}

impl Default for Trace {
    fn default() -> Self {
        Trace::new()
    }
}

impl Drop for Trace {
    fn drop(&mut self) {
        ARENA.with(|a| {
            let mut a = a.borrow_mut();
            if a.generation == self.generation {
                a.release();
            }
        });
    }
}
