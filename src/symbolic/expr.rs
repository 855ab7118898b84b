//! The expression type: a `Copy` handle into a per-thread arena of hash-consed nodes, carrying
//! its value at the trace point (so `re()`, comparisons and `abs` follow the numeric path);
//! and where a traced formula holds, as the arena records it (below, *Claims*).

use crate::branch::Observer;
use std::cell::RefCell;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::marker::PhantomData;
use std::sync::atomic::{AtomicU64, Ordering};

/// A multiply-rotate hasher for the small integer keys of the symbolic module (arena nodes,
/// node ids, structural hashes): the keys are not attacker-chosen, and SipHash's cost
/// dominated hash-consing.
#[derive(Default, Clone, Copy)]
pub(crate) struct FastHasher(u64);

impl Hasher for FastHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.write_u64(u64::from_le_bytes(word));
        }
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
    fn write_u32(&mut self, x: u32) {
        self.write_u64(u64::from(x));
    }
    fn write_u8(&mut self, x: u8) {
        self.write_u64(u64::from(x));
    }
    fn write_usize(&mut self, x: usize) {
        self.write_u64(x as u64);
    }
}

/// A `HashMap` with [`FastHasher`].
pub(crate) type FastMap<K, V> = HashMap<K, V, BuildHasherDefault<FastHasher>>;

/// The most nodes one trace may create ([`crate::symbolic::Trace::formula`] returns
/// [`crate::error::Error::TooLarge`] beyond).
pub const MAX_NODES: usize = 1 << 20;

/// A function of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Func {
    /// `sin`.
    Sin,
    /// `cos`.
    Cos,
    /// `tan`.
    Tan,
    /// `exp`.
    Exp,
    /// `ln`.
    Ln,
    /// `sqrt`.
    Sqrt,
    /// `cbrt`.
    Cbrt,
    /// `asin`.
    Asin,
    /// `acos`.
    Acos,
    /// `atan`.
    Atan,
    /// `sinh`.
    Sinh,
    /// `cosh`.
    Cosh,
    /// `tanh`.
    Tanh,
    /// `asinh`.
    Asinh,
    /// `acosh`.
    Acosh,
    /// `atanh`.
    Atanh,
    /// `abs` (the numeric branch is recorded, see [`crate::symbolic`]).
    Abs,
    /// The spherical Bessel function `j₀`.
    SphJ0,
    /// `j₁`.
    SphJ1,
    /// `j₂`.
    SphJ2,
}

impl Func {
    /// The function's name as printed.
    pub fn name(&self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Exp => "exp",
            Func::Ln => "ln",
            Func::Sqrt => "sqrt",
            Func::Cbrt => "cbrt",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan => "atan",
            Func::Sinh => "sinh",
            Func::Cosh => "cosh",
            Func::Tanh => "tanh",
            Func::Asinh => "asinh",
            Func::Acosh => "acosh",
            Func::Atanh => "atanh",
            Func::Abs => "abs",
            Func::SphJ0 => "j0",
            Func::SphJ1 => "j1",
            Func::SphJ2 => "j2",
        }
    }

    /// The function at `x`.
    pub fn apply(&self, x: f64) -> f64 {
        self.apply_to(x)
    }

    /// `|f′(x)|`, exact (one dual-number evaluation): how much an error in the argument
    /// moves the value, for the rounding bound of the capture check.
    pub(crate) fn slope(&self, x: f64) -> f64 {
        use num_dual::Dual64;
        self.apply_to(Dual64::from(x).derivative()).eps.abs()
    }

    /// The function at any number type (one definition for values and slopes).
    fn apply_to<D: num_dual::DualNum<Primitive = f64>>(&self, x: D) -> D {
        match self {
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Exp => x.exp(),
            Func::Ln => x.ln(),
            Func::Sqrt => x.sqrt(),
            Func::Cbrt => x.cbrt(),
            Func::Asin => x.asin(),
            Func::Acos => x.acos(),
            Func::Atan => x.atan(),
            Func::Sinh => x.sinh(),
            Func::Cosh => x.cosh(),
            Func::Tanh => x.tanh(),
            Func::Asinh => x.asinh(),
            Func::Acosh => x.acosh(),
            Func::Atanh => x.atanh(),
            Func::Abs => x.abs(),
            Func::SphJ0 => x.sph_j0(),
            Func::SphJ1 => x.sph_j1(),
            Func::SphJ2 => x.sph_j2(),
        }
    }
}

/// One node of an expression (children are arena indices).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Node {
    /// A constant.
    Num(f64),
    /// A variable, by its index in the trace's names.
    Var(u32),
    /// `a + b`.
    Add(u32, u32),
    /// `a · b`.
    Mul(u32, u32),
    /// `a / b`.
    Div(u32, u32),
    /// `−a`.
    Neg(u32),
    /// `aⁿ`, `n` an integer.
    Powi(u32, i32),
    /// `aˣ`, `x` a real constant.
    Powf(u32, f64),
    /// `aᵇ`, both expressions.
    Pow(u32, u32),
    /// `f(a)`.
    Apply(Func, u32),
    /// `atan2(a, b)`.
    Atan2(u32, u32),
    /// An operation without a formula (`%`, …), with its value at the trace point.
    Opaque(&'static str, u32, f64),
    /// Every node beyond [`MAX_NODES`] (a leaf: the trace's formulas are refused).
    TooLarge,
}

impl Node {
    /// The node as plain data — a tag, two payload words (floats by their bits, so `-0.0`
    /// and `0.0` stay apart and NaN equals itself) and a name — for hash-consing.
    fn parts(&self) -> (u8, u64, u64, &'static str) {
        let w = |x: u32| u64::from(x);
        match *self {
            Node::Num(x) => (0, x.to_bits(), 0, ""),
            Node::Var(i) => (1, w(i), 0, ""),
            Node::Add(a, b) => (2, w(a), w(b), ""),
            Node::Mul(a, b) => (3, w(a), w(b), ""),
            Node::Div(a, b) => (4, w(a), w(b), ""),
            Node::Neg(a) => (5, w(a), 0, ""),
            Node::Powi(a, n) => (6, w(a), n as u64, ""),
            Node::Powf(a, x) => (7, w(a), x.to_bits(), ""),
            Node::Pow(a, b) => (8, w(a), w(b), ""),
            Node::Apply(f, a) => (9, w(a), f as u64, ""),
            Node::Atan2(a, b) => (10, w(a), w(b), ""),
            Node::Opaque(n, a, v) => (11, w(a), v.to_bits(), n),
            Node::TooLarge => (12, 0, 0, ""),
        }
    }
}

/// The identity of the next trace, unique across threads and the whole process (as CppAD's
/// tape ids): a handle names its trace by it, so a handle of an ended trace or of another
/// thread's never matches the running one. `0` is no trace.
static NEXT_TRACE: AtomicU64 = AtomicU64::new(1);

/// A marker that makes a type neither `Send` nor `Sync`: expressions index a per-thread arena.
pub(crate) type ThreadBound = PhantomData<*const ()>;

/// The per-thread arena of one trace.
#[derive(Debug, Default)]
pub(crate) struct Arena {
    pub(crate) nodes: Vec<Node>,
    index: FastMap<(u8, u64, u64, &'static str), u32>,
    /// The running trace's identity (from [`NEXT_TRACE`]): handles of any other are stale.
    pub(crate) generation: u64,
    /// Set when an operation was given a handle of another trace (stale or foreign): every
    /// formula of the trace is then refused.
    pub(crate) poisoned: bool,
    /// Set when [`MAX_NODES`] was reached; later nodes all collapse onto one opaque node.
    pub(crate) overflowed: bool,
    /// Conditions the trace's values took on `re()` branches (`abs`, comparisons…).
    pub(crate) branches: Vec<(u32, &'static str, f64)>,
    /// Whether a trace is running (from its start to its end).
    pub(crate) live: bool,
    /// The conditions the traced code recorded where it picked a piece by a value
    /// ([`crate::branch::choose`]): node and interval of its values.
    pub(crate) claims: Vec<(u32, crate::branch::Condition)>,
    /// Values read through `re()` without a condition (node and value).
    pub(crate) reads: Vec<(u32, f64)>,
    /// How a read through `re()` is recorded now.
    pub(crate) read_mode: ReadMode,
    /// The modes that choices and quiet reads in progress replaced (innermost last).
    pub(crate) read_modes: Vec<ReadMode>,
}

thread_local! {
    pub(crate) static ARENA: RefCell<Arena> = RefCell::new(Arena::default());
}

impl Arena {
    /// The index of `node`, created if new.
    pub(crate) fn intern(&mut self, node: Node) -> u32 {
        let key = node.parts();
        if let Some(&i) = self.index.get(&key) {
            return i;
        }
        if self.nodes.len() >= MAX_NODES {
            self.overflowed = true;
            return self.overflow_node();
        }
        let i = self.nodes.len() as u32;
        self.nodes.push(node);
        self.index.insert(key, i);
        i
    }

    fn overflow_node(&mut self) -> u32 {
        // the first node is reserved at a trace's start for this purpose
        0
    }

    /// Ends a trace: empties the arena and gives its memory back.
    pub(crate) fn release(&mut self) {
        self.reset();
        self.live = false;
        self.nodes.shrink_to_fit();
        self.index = FastMap::default();
        self.branches = Vec::new();
        self.claims = Vec::new();
        self.reads = Vec::new();
        self.read_modes = Vec::new();
        crate::branch::observe(None);
    }

    /// Starts a trace: empties the arena (node 0 is the overflow marker) and takes a new
    /// identity.
    pub(crate) fn reset(&mut self) {
        self.nodes.clear();
        self.index.clear();
        self.branches.clear();
        self.claims.clear();
        self.reads.clear();
        self.read_mode = ReadMode::default();
        self.read_modes.clear();
        self.overflowed = false;
        self.poisoned = false;
        self.live = true;
        crate::branch::observe(Some(&OBSERVER));
        // 2⁶⁴ traces cannot be started: the identity never wraps
        self.generation = NEXT_TRACE.fetch_add(1, Ordering::Relaxed);
        self.nodes.push(Node::TooLarge);
    }
}

/// Whether two node ids are one expression: equal, and not the overflow marker (node 0, which
/// every node beyond [`MAX_NODES`] collapses onto).
fn same(a: u32, b: u32) -> bool {
    a == b && a != 0
}

/// An expression: a handle into the current trace's arena and its value at the trace point.
/// `Copy`, so it is the inner type of num-dual's `Dual`, `Dual2` and `HyperDual` under the
/// library's bound (`D: DualNum<Primitive = f64> + Copy`).
///
/// A handle names its trace by an identity unique in the process, and it cannot leave its
/// thread (it indexes that thread's arena):
///
/// ```compile_fail
/// fn send<T: Send>(_: T) {}
/// let mut trace = splinelab::symbolic::Trace::new();
/// send(trace.var("x", 1.0)); // `Expr` is not `Send`
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Expr {
    pub(crate) id: u32,
    pub(crate) generation: u64,
    /// The value at the trace point.
    pub(crate) value: f64,
    pub(crate) local: ThreadBound,
}

impl Expr {
    /// The value at the trace point.
    pub fn value(&self) -> f64 {
        self.value
    }

    /// Whether this handle belongs to the running trace.
    pub fn is_live(&self) -> bool {
        ARENA.with(|a| a.borrow().generation == self.generation)
    }

    /// The handle of `node` (interned in the running trace) with the value `value`, built
    /// from `operands`: an operand of another trace (ended, or another thread's) poisons the
    /// trace, and the result is the overflow marker, which no formula reads.
    pub(crate) fn make(node: Node, value: f64, operands: &[Expr]) -> Expr {
        ARENA.with(|a| {
            let mut a = a.borrow_mut();
            if a.nodes.is_empty() {
                // used outside a trace: start one implicitly
                a.reset();
            }
            let generation = a.generation;
            let id = if operands.iter().any(|e| e.generation != generation) {
                a.poisoned = true;
                0
            } else {
                a.intern(node)
            };
            Expr {
                id,
                generation,
                value,
                local: PhantomData,
            }
        })
    }

    /// The constant `x`.
    pub fn constant(x: f64) -> Expr {
        Expr::make(Node::Num(x), x, &[])
    }

    pub(crate) fn node(&self) -> Option<Node> {
        ARENA.with(|a| {
            let a = a.borrow();
            (a.generation == self.generation)
                .then(|| a.nodes.get(self.id as usize).copied())
                .flatten()
        })
    }

    /// The constant this expression is, if it is one.
    pub fn as_constant(&self) -> Option<f64> {
        match self.node() {
            Some(Node::Num(x)) => Some(x),
            _ => None,
        }
    }

    /// Records that the numeric path branched on this expression (`what` of its value).
    pub(crate) fn branch(&self, what: &'static str) {
        if self.as_constant().is_some() {
            return;
        }
        ARENA.with(|a| {
            let mut a = a.borrow_mut();
            if a.generation == self.generation {
                let entry = (self.id, what, self.value);
                if !a.branches.contains(&entry) {
                    a.branches.push(entry);
                }
            }
        });
    }

    // ---- constructors that simplify (module docs of `crate::symbolic`) ----

    pub(crate) fn add(a: Expr, b: Expr) -> Expr {
        let value = a.value + b.value;
        match (a.as_constant(), b.as_constant()) {
            (Some(x), Some(y)) => Expr::constant(x + y),
            (Some(0.0), _) => b,
            (_, Some(0.0)) => a,
            _ => {
                if let Some(Node::Neg(na)) = a.node() {
                    if same(na, b.id) {
                        return Expr::constant(0.0);
                    }
                }
                if let Some(Node::Neg(nb)) = b.node() {
                    if same(nb, a.id) {
                        return Expr::constant(0.0);
                    }
                }
                if same(a.id, b.id) {
                    return Expr::mul(Expr::constant(2.0), a);
                }
                Expr::make(Node::Add(a.id, b.id), value, &[a, b])
            }
        }
    }

    pub(crate) fn neg(a: Expr) -> Expr {
        match (a.as_constant(), a.node()) {
            (Some(x), _) => Expr::constant(-x),
            (_, Some(Node::Neg(inner))) => Expr::from_id(inner, -a.value, a.generation),
            _ => Expr::make(Node::Neg(a.id), -a.value, &[a]),
        }
    }

    pub(crate) fn from_id(id: u32, value: f64, generation: u64) -> Expr {
        Expr {
            id,
            generation,
            value,
            local: PhantomData,
        }
    }

    pub(crate) fn sub(a: Expr, b: Expr) -> Expr {
        Expr::add(a, Expr::neg(b))
    }

    pub(crate) fn mul(a: Expr, b: Expr) -> Expr {
        let value = a.value * b.value;
        match (a.as_constant(), b.as_constant()) {
            (Some(x), Some(y)) => Expr::constant(x * y),
            (Some(0.0), _) | (_, Some(0.0)) => Expr::constant(0.0),
            (Some(1.0), _) => b,
            (_, Some(1.0)) => a,
            (Some(-1.0), _) => Expr::neg(b),
            (_, Some(-1.0)) => Expr::neg(a),
            // constants first, signs pulled out
            (None, Some(_)) => Expr::mul(b, a),
            _ => match (a.node(), b.node()) {
                (Some(Node::Neg(x)), _) => {
                    Expr::neg(Expr::mul(Expr::from_id(x, -a.value, a.generation), b))
                }
                (_, Some(Node::Neg(y))) => {
                    Expr::neg(Expr::mul(a, Expr::from_id(y, -b.value, b.generation)))
                }
                _ if same(a.id, b.id) => Expr::powi(a, 2),
                _ => Expr::make(Node::Mul(a.id, b.id), value, &[a, b]),
            },
        }
    }

    pub(crate) fn div(a: Expr, b: Expr) -> Expr {
        let value = a.value / b.value;
        match (a.as_constant(), b.as_constant()) {
            (Some(x), Some(y)) => Expr::constant(x / y),
            (Some(0.0), _) => Expr::constant(0.0),
            (_, Some(1.0)) => a,
            (_, Some(-1.0)) => Expr::neg(a),
            _ if same(a.id, b.id) => Expr::constant(1.0),
            _ => Expr::make(Node::Div(a.id, b.id), value, &[a, b]),
        }
    }

    pub(crate) fn powi(a: Expr, n: i32) -> Expr {
        let value = a.value.powi(n);
        match (a.as_constant(), n) {
            (Some(x), _) => Expr::constant(x.powi(n)),
            (_, 0) => Expr::constant(1.0),
            (_, 1) => a,
            _ => Expr::make(Node::Powi(a.id, n), value, &[a]),
        }
    }

    pub(crate) fn powf(a: Expr, x: f64) -> Expr {
        if x.fract() == 0.0 && x.abs() <= i32::MAX as f64 {
            return Expr::powi(a, x as i32);
        }
        if x == 0.5 {
            return Expr::apply(Func::Sqrt, a);
        }
        match a.as_constant() {
            Some(c) => Expr::constant(c.powf(x)),
            None => Expr::make(Node::Powf(a.id, x), a.value.powf(x), &[a]),
        }
    }

    pub(crate) fn pow(a: Expr, b: Expr) -> Expr {
        match (a.as_constant(), b.as_constant()) {
            (Some(x), Some(y)) => Expr::constant(x.powf(y)),
            (_, Some(y)) => Expr::powf(a, y),
            _ => Expr::make(Node::Pow(a.id, b.id), a.value.powf(b.value), &[a, b]),
        }
    }

    pub(crate) fn apply(f: Func, a: Expr) -> Expr {
        if f == Func::Abs {
            a.branch(if a.value >= 0.0 { "≥ 0" } else { "< 0" });
        }
        match a.as_constant() {
            Some(x) => Expr::constant(f.apply(x)),
            None => Expr::make(Node::Apply(f, a.id), f.apply(a.value), &[a]),
        }
    }

    pub(crate) fn atan2(a: Expr, b: Expr) -> Expr {
        match (a.as_constant(), b.as_constant()) {
            (Some(x), Some(y)) => Expr::constant(x.atan2(y)),
            _ => Expr::make(Node::Atan2(a.id, b.id), a.value.atan2(b.value), &[a, b]),
        }
    }

    pub(crate) fn opaque(what: &'static str, a: Expr, value: f64) -> Expr {
        Expr::make(Node::Opaque(what, a.id, value), value, &[a])
    }
}

// Claims. Where a traced formula holds, as the traced code recorded it: the trace's side of
// [`crate::branch`]. The core tells the running trace when it picks a piece by a value
// ([`crate::branch::choose`]) or reads one quietly; every other read of a value (`re()` in
// the code, or in num-dual's own functions, such as `sph_j0` near 0) is recorded as a read
// without a condition: the formula is then claimed at the trace point only.

/// The hooks a running trace installs ([`crate::branch::observe`]).
pub(crate) static OBSERVER: Observer = Observer {
    begin_choice: || enter(ReadMode::Piece(None)),
    end_choice: |condition| {
        ARENA.with(|a| {
            let mut a = a.borrow_mut();
            if let ReadMode::Piece(Some(id)) = a.read_mode {
                a.claims.push((id, condition));
            }
            a.read_mode = a.read_modes.pop().unwrap_or_default();
        })
    },
    begin_quiet: || enter(ReadMode::Quiet),
    end_quiet: || {
        ARENA.with(|a| {
            let mut a = a.borrow_mut();
            a.read_mode = a.read_modes.pop().unwrap_or_default();
        })
    },
};

/// Enters `mode`, keeping the one it replaces for the matching end.
fn enter(mode: ReadMode) {
    ARENA.with(|a| {
        let mut a = a.borrow_mut();
        let before = std::mem::replace(&mut a.read_mode, mode);
        a.read_modes.push(before);
    })
}

/// How an expression's value read through `re()` is recorded.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) enum ReadMode {
    /// A read without a condition (the formula is claimed at the trace point only).
    #[default]
    Unrecorded,
    /// Inside [`crate::branch::choose`]: the node read is kept for its condition.
    Piece(Option<u32>),
    /// Inside [`crate::branch::read_quietly`]: not recorded.
    Quiet,
}

/// Records that the value of node `id` (of trace `generation`) was read through `re()`.
pub(crate) fn note_read(id: u32, generation: u64, value: f64) {
    ARENA.with(|a| {
        let mut a = a.borrow_mut();
        if a.generation != generation || !a.live {
            return;
        }
        if matches!(a.nodes.get(id as usize), Some(Node::Num(_)) | None) {
            // a constant's value chooses nothing
            return;
        }
        match a.read_mode {
            ReadMode::Piece(_) => a.read_mode = ReadMode::Piece(Some(id)),
            ReadMode::Quiet => {}
            ReadMode::Unrecorded => {
                if !a.reads.iter().any(|&(i, _)| i == id) {
                    a.reads.push((id, value));
                }
            }
        }
    })
}
