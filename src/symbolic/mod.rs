//! Symbolic and numeric from one code path: an expression type ([`Expr`]) that num-dual's
//! dual numbers carry as their inner type, so the very generic `eval` that computes numbers
//! records the formulas of its derivatives — the chain rule is num-dual's own, nothing here
//! differentiates.
//!
//! ```
//! use splinelab::symbolic::surface_formulas;
//! use splinelab::Torus;
//! let f = surface_formulas(&Torus::new(2.0, 1.0), 0.3, 0.7)?;
//! assert_eq!(f.dst[0].plain(), "sin(s)*sin(t)");          // x_st of Codice 3
//! assert!((f.dst[0].eval(&[0.3, 0.7]) - 0.3f64.sin() * 0.7f64.sin()).abs() < 1e-15);
//! # Ok::<(), splinelab::Error>(())
//! ```
//!
//! **Expressions.** An [`Expr`] is `Copy`: an index into a per-thread arena of hash-consed
//! nodes (equal subexpressions are one node) and its value at the trace point, so `re()`,
//! comparisons and `abs` follow the numeric path. A [`Trace`] owns the arena: it is emptied
//! when a trace starts and freed when it ends, so a long session does not grow; a trace holds
//! at most [`MAX_NODES`] nodes ([`crate::Error::TooLarge`] beyond). One trace per thread at a
//! time: starting another makes the first one's handles stale, and their formulas are refused.
//!
//! **Simplification, on construction:** constants folded; `x + 0`, `x·1`, `x/1`, `x⁰`, `x¹`
//! removed; `x·0 = 0`; `x − x = 0`, `x + x = 2x`, `x·x = x²`, `x/x = 1`; signs pulled out of
//! products (`(−a)·b = −(a·b)`), double negation removed, constants first in products. *Not
//! done* (yet): collecting like terms beyond `x + x`, common factors, common denominators,
//! trigonometric identities.
//!
//! **Printing.** Plain text with ASCII operators (`-sin(s)*(cos(t) + 2)`), operator
//! precedence respected and no redundant brackets; a constant that is exactly a small rational
//! prints as a fraction (`1/4`), others as the shortest decimal that reads back to the same
//! `f64` ([`number`]).
//!
//! **Branches.** Where the numeric path branched on a value (`abs`, `signum`, comparisons), the
//! condition is recorded ([`Trace::branches`]): a formula holds only where they hold.
//!
//! **No formula:** `%` gives an opaque node carrying its numeric value (printed `rem[…]`);
//! parsing (`Num::from_str_radix`) is an error.

mod expr;
mod ops;
mod print;

pub use expr::{Expr, Func, Node, MAX_NODES};
pub use print::{number, Formula};

use crate::error::{Error, Result};
use crate::surface::ParametricSurface;
use expr::ARENA;
use num_dual::HyperDual;
use std::cell::RefCell;

thread_local! {
    static NAMES: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

pub(crate) fn current_names() -> Vec<String> {
    NAMES.with(|n| n.borrow().clone())
}

/// A running trace (module docs): variables, then formulas of what was computed from them.
/// Dropping it frees the arena.
#[derive(Debug)]
pub struct Trace {
    generation: u32,
}

impl Trace {
    /// Starts a trace on this thread (any earlier one's handles go stale).
    pub fn new() -> Trace {
        NAMES.with(|n| n.borrow_mut().clear());
        let generation = ARENA.with(|a| {
            let mut a = a.borrow_mut();
            a.reset();
            a.generation
        });
        Trace { generation }
    }

    /// A variable named `name` with the value `value` at the trace point.
    pub fn var(&mut self, name: &str, value: f64) -> Expr {
        let index = NAMES.with(|n| {
            let mut n = n.borrow_mut();
            n.push(name.to_string());
            n.len() as u32 - 1
        });
        Expr::make(Node::Var(index), value)
    }

    fn live(&self) -> bool {
        ARENA.with(|a| a.borrow().generation == self.generation)
    }

    /// The formula of `e`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] if the trace exceeded [`MAX_NODES`]; [`Error::Degenerate`] for a
    /// handle of another (ended) trace.
    pub fn formula(&self, e: &Expr) -> Result<Formula> {
        let (overflowed, nodes) = ARENA.with(|a| {
            let a = a.borrow();
            (a.overflowed, a.nodes.len())
        });
        if overflowed {
            return Err(Error::TooLarge {
                what: "expression nodes of a trace",
                got: nodes + 1,
                max: MAX_NODES,
            });
        }
        if !self.live() || e.generation != self.generation {
            return Err(Error::Degenerate {
                what: "symbolic formula",
                reason: "the expression belongs to a trace that has ended",
            });
        }
        Ok(Formula::capture(e, &current_names()))
    }

    /// The conditions the numeric path took on the way (`s - 1/4 > 0`, …), in order.
    pub fn branches(&self) -> Vec<String> {
        let branches = ARENA.with(|a| a.borrow().branches.clone());
        let names = current_names();
        branches
            .into_iter()
            .map(|(id, what, value)| {
                let e = Expr {
                    id,
                    generation: self.generation,
                    value,
                };
                format!("{} {what}", Formula::capture(&e, &names).plain())
            })
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

/// The formulas of `X`, `X_s`, `X_t`, `X_st` of a surface (each a coordinate triple), traced
/// at `(s, t)`, with the branches the evaluation took there.
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
    /// The conditions under which the formulas hold (empty: everywhere the evaluation is
    /// defined).
    pub branches: Vec<String>,
}

/// The formulas of any [`ParametricSurface`]: its own generic `eval` run on hyper-dual
/// numbers of expressions, variables `s` and `t`.
///
/// # Errors
/// As [`Trace::formula`] (an expression beyond [`MAX_NODES`]).
pub fn surface_formulas<S: ParametricSurface + ?Sized>(
    surface: &S,
    s: f64,
    t: f64,
) -> Result<SurfaceFormulas> {
    let mut trace = Trace::new();
    let (sv, tv) = (trace.var("s", s), trace.var("t", t));
    let (zero, one) = (Expr::constant(0.0), Expr::constant(1.0));
    let sh = HyperDual::new(sv, one, zero, zero);
    let th = HyperDual::new(tv, zero, one, zero);
    let x = surface.eval(sh, th);
    let part = |f: &dyn Fn(&HyperDual<Expr>) -> Expr| -> Result<[Formula; 3]> {
        Ok([
            trace.formula(&f(&x[0]))?,
            trace.formula(&f(&x[1]))?,
            trace.formula(&f(&x[2]))?,
        ])
    };
    let out = SurfaceFormulas {
        point: part(&|d| d.re)?,
        ds: part(&|d| d.eps1)?,
        dt: part(&|d| d.eps2)?,
        dst: part(&|d| d.eps1eps2)?,
        branches: trace.branches(),
    };
    Ok(out)
}
