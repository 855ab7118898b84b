//! How generic code picks a piece of a piecewise object by a value, and what is recorded when
//! the value is an expression's.
//!
//! Generic code reads `t.re()` to pick a piece. For plain and dual numbers that is all. Under a
//! symbolic trace ([`crate::symbolic`]) the value read is an expression's, and a formula of the
//! trace holds only where the same piece would be picked; the one honest record of that is made
//! where the piece is picked: [`choose`] reads the value and hands the trace, in the same step,
//! the interval on which the choice holds ([`Condition`]) — so the claim and the branch taken
//! cannot differ. A read that provably does not choose the formula (an expansion point, two
//! equal forms of one polynomial) goes through [`read_quietly`].
//!
//! The numeric core knows nothing of expressions: a running trace installs an [`Observer`] on
//! its thread (and removes it when it ends), and the functions here tell it when a choice or a
//! quiet read begins and ends. The dependency runs one way, from the formula layer to the core.

use crate::domain::Span;
use num_dual::DualStruct;
use std::cell::Cell;

/// An interval of values of an expression: the condition under which a traced formula holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Condition {
    /// The left end (`−∞` for none).
    pub lo: f64,
    /// Whether `lo` belongs to it.
    pub lo_closed: bool,
    /// The right end (`+∞` for none).
    pub hi: f64,
    /// Whether `hi` belongs to it.
    pub hi_closed: bool,
}

impl Condition {
    /// Every value below `hi` (`hi` included if `closed`).
    pub fn below(hi: f64, closed: bool) -> Condition {
        Condition {
            lo: f64::NEG_INFINITY,
            lo_closed: false,
            hi,
            hi_closed: closed,
        }
    }

    /// Every value above `lo` (`lo` included if `closed`).
    pub fn above(lo: f64, closed: bool) -> Condition {
        Condition {
            lo,
            lo_closed: closed,
            hi: f64::INFINITY,
            hi_closed: false,
        }
    }

    /// Whether `x` satisfies it.
    pub fn contains(&self, x: f64) -> bool {
        let left = if self.lo_closed {
            x >= self.lo
        } else {
            x > self.lo
        };
        let right = if self.hi_closed {
            x <= self.hi
        } else {
            x < self.hi
        };
        left && right
    }

    /// The condition on `what`: `t ∈ [1/4, 1/2)`, `t < 0`, `t ≥ 3`.
    pub fn describe(&self, what: &str) -> String {
        use crate::printed::number;
        match (self.lo.is_finite(), self.hi.is_finite()) {
            (true, true) => format!(
                "{what} ∈ {}{}, {}{}",
                if self.lo_closed { '[' } else { '(' },
                number(self.lo),
                number(self.hi),
                if self.hi_closed { ']' } else { ')' }
            ),
            (false, true) => format!(
                "{what} {} {}",
                if self.hi_closed { "≤" } else { "<" },
                number(self.hi)
            ),
            (true, false) => format!(
                "{what} {} {}",
                if self.lo_closed { "≥" } else { ">" },
                number(self.lo)
            ),
            (false, false) => format!("{what} any"),
        }
    }

    /// The condition on `x` where `a·x + b` satisfies this one (`a ≠ 0`).
    pub fn pulled_back(&self, a: f64, b: f64) -> Condition {
        let (lo, hi) = ((self.lo - b) / a, (self.hi - b) / a);
        if a > 0.0 {
            Condition {
                lo,
                lo_closed: self.lo_closed,
                hi,
                hi_closed: self.hi_closed,
            }
        } else {
            Condition {
                lo: hi,
                lo_closed: self.hi_closed,
                hi: lo,
                hi_closed: self.lo_closed,
            }
        }
    }

    /// Both conditions at once.
    pub fn intersect(&self, other: &Condition) -> Condition {
        let (lo, lo_closed) = if self.lo > other.lo {
            (self.lo, self.lo_closed)
        } else if other.lo > self.lo {
            (other.lo, other.lo_closed)
        } else {
            (self.lo, self.lo_closed && other.lo_closed)
        };
        let (hi, hi_closed) = if self.hi < other.hi {
            (self.hi, self.hi_closed)
        } else if other.hi < self.hi {
            (other.hi, other.hi_closed)
        } else {
            (self.hi, self.hi_closed && other.hi_closed)
        };
        Condition {
            lo,
            lo_closed,
            hi,
            hi_closed,
        }
    }

    /// As a [`Span`] (`[lo, hi)` or `[lo, hi]`), if it is a finite interval closed on the left.
    pub fn as_span(&self) -> Option<Span> {
        (self.lo.is_finite() && self.hi.is_finite() && self.lo_closed).then_some(Span {
            lo: self.lo,
            hi: self.hi,
            closed: self.hi_closed,
        })
    }
}

impl From<Span> for Condition {
    fn from(s: Span) -> Condition {
        Condition {
            lo: s.lo,
            lo_closed: true,
            hi: s.hi,
            hi_closed: s.closed,
        }
    }
}

/// What a running trace does when generic code reads a value to choose by it: four hooks,
/// called in pairs (`begin_choice`/`end_choice`, `begin_quiet`/`end_quiet`, nested in stack
/// order) around the reads of the value.
#[derive(Debug)]
pub(crate) struct Observer {
    /// A choice begins: the value read until `end_choice` is the one it chooses by.
    pub(crate) begin_choice: fn(),
    /// The choice ends; the condition is the set of values on which it holds.
    pub(crate) end_choice: fn(Condition),
    /// A read that chooses nothing begins.
    pub(crate) begin_quiet: fn(),
    /// It ends.
    pub(crate) end_quiet: fn(),
}

thread_local! {
    /// The observer of the trace running on this thread, if one is.
    static OBSERVER: Cell<Option<&'static Observer>> = const { Cell::new(None) };
}

/// Installs the observer of a trace starting on this thread (`None` when it ends).
pub(crate) fn observe(observer: Option<&'static Observer>) {
    OBSERVER.with(|o| o.set(observer));
}

/// Whether a trace runs on this thread: values may be expressions', so generic code that uses
/// the numeric value of its argument beyond branching (a truncated Taylor expansion, exact only
/// for dual numbers of plain numbers) takes its exact form instead.
pub(crate) fn traced() -> bool {
    OBSERVER.with(|o| o.get().is_some())
}

/// Picks by the value of `t`: `pick(x)` gives the choice made for the value `x` and the set
/// of values on which that choice holds (it must contain `x`). Under a symbolic trace the set
/// is recorded as the condition on the expression read, in the same step as the choice, so
/// the formulas of the trace claim exactly the piece the code picked.
pub(crate) fn choose<D: DualStruct<Real = f64>, R>(
    t: &D,
    pick: impl FnOnce(f64) -> (R, Condition),
) -> R {
    let Some(observer) = OBSERVER.with(Cell::get) else {
        return pick(t.re()).0;
    };
    (observer.begin_choice)();
    let x = t.re();
    let (choice, condition) = pick(x);
    (observer.end_choice)(condition);
    choice
}

/// The value of `t` for a use that does not choose the formula (an expansion point, a choice
/// between two forms of one function): not recorded as a condition.
pub(crate) fn read_quietly<D: DualStruct<Real = f64>>(t: &D) -> f64 {
    let Some(observer) = OBSERVER.with(Cell::get) else {
        return t.re();
    };
    (observer.begin_quiet)();
    let x = t.re();
    (observer.end_quiet)();
    x
}

/// The piece `k` of increasing `nodes` holding `t` ([`crate::domain::locate`]), recorded as
/// the formula's condition: `[nodes[k], nodes[k + 1])` (the last closed) inside the domain,
/// and for a value beyond it the end piece extended to `∓∞` (which piecewise objects
/// extrapolate).
pub(crate) fn piece<D: DualStruct<Real = f64>>(nodes: &[f64], t: &D) -> usize {
    choose(t, |x| {
        let k = crate::domain::locate(nodes, x);
        (k, piece_condition(nodes, k, x))
    })
}

/// The piece `j = ⌊t⌋` of the unit pieces `[0, 1)`, …, `[n − 1, n]` holding `t` (the right end
/// in the last; outside, the end pieces, and NaN the first), recorded as [`piece`] records it.
pub(crate) fn unit_piece<D: DualStruct<Real = f64>>(n: usize, t: &D) -> usize {
    choose(t, |x| {
        let span = unit_span(x, n);
        (span.lo as usize, beyond(span, x, (0.0, n as f64)))
    })
}

/// Piece `j = ⌊u⌋` of `pieces` unit pieces, `[j, j + 1)`, clamped to the first and last (the
/// last closed).
pub(crate) fn unit_span(u: f64, pieces: usize) -> Span {
    let j = unit_index(u, pieces);
    Span {
        lo: j as f64,
        hi: j as f64 + 1.0,
        closed: j + 1 >= pieces,
    }
}

/// `⌊x⌋` clamped to `0 … n − 1` (NaN and negative values to 0).
pub(crate) fn unit_index(x: f64, n: usize) -> usize {
    if x.is_nan() || x <= 0.0 {
        0
    } else {
        (x.floor() as usize).min(n.saturating_sub(1))
    }
}

/// The condition of piece `k` for the value `x` (see [`piece`]).
pub(crate) fn piece_condition(nodes: &[f64], k: usize, x: f64) -> Condition {
    beyond(Span::of(nodes, k), x, (nodes[0], nodes[nodes.len() - 1]))
}

/// The condition of the piece `span` picked for `x` on the domain `[a, b]`: the span itself,
/// extended to `−∞` when `x < a` and to `+∞` when `x > b` (the end pieces that piecewise
/// objects extrapolate hold there).
pub(crate) fn beyond(span: Span, x: f64, (a, b): (f64, f64)) -> Condition {
    let mut c = Condition::from(span);
    if x < a {
        c.lo = f64::NEG_INFINITY;
        c.lo_closed = false;
    }
    if x > b {
        c.hi = f64::INFINITY;
        c.hi_closed = false;
    }
    c
}
