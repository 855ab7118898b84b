//! Formulas owned outside the arena, their evaluation and their printing (plain text, with
//! operator precedence and no redundant brackets; constants that are small rationals exactly
//! printed as fractions, others as the shortest decimal that reads back to the same `f64`).

use super::expr::{Expr, Node, ARENA};
use std::collections::HashMap;

/// A formula copied out of a trace: its nodes (children before parents, the root last) and
/// the names of its variables.
#[derive(Debug, Clone, PartialEq)]
pub struct Formula {
    nodes: Vec<Node>,
    names: Vec<String>,
}

impl Formula {
    /// The formula of `e`, copied out of the running trace, with variable names `names`
    /// (a stale handle gives the constant NaN, flagged as not live by [`Expr::is_live`]).
    pub(crate) fn capture(e: &Expr, names: &[String]) -> Formula {
        ARENA.with(|a| {
            let a = a.borrow();
            let mut nodes = Vec::new();
            if a.generation != e.generation || e.id as usize >= a.nodes.len() {
                nodes.push(Node::Num(f64::NAN));
                return Formula {
                    nodes,
                    names: names.to_vec(),
                };
            }
            let mut map: HashMap<u32, u32> = HashMap::new();
            // iterative post-order copy
            let mut stack = vec![(e.id, false)];
            while let Some((id, done)) = stack.pop() {
                if map.contains_key(&id) {
                    continue;
                }
                let node = a.nodes[id as usize];
                let kids = children(&node);
                if !done {
                    stack.push((id, true));
                    for k in kids.into_iter().flatten() {
                        if !map.contains_key(&k) {
                            stack.push((k, false));
                        }
                    }
                    continue;
                }
                let m = |k: u32| map[&k];
                let copied = match node {
                    Node::Add(x, y) => Node::Add(m(x), m(y)),
                    Node::Mul(x, y) => Node::Mul(m(x), m(y)),
                    Node::Div(x, y) => Node::Div(m(x), m(y)),
                    Node::Neg(x) => Node::Neg(m(x)),
                    Node::Powi(x, n) => Node::Powi(m(x), n),
                    Node::Powf(x, p) => Node::Powf(m(x), p),
                    Node::Pow(x, y) => Node::Pow(m(x), m(y)),
                    Node::Apply(f, x) => Node::Apply(f, m(x)),
                    Node::Atan2(x, y) => Node::Atan2(m(x), m(y)),
                    Node::Opaque(w, x, v) => Node::Opaque(w, m(x), v),
                    leaf => leaf,
                };
                map.insert(id, nodes.len() as u32);
                nodes.push(copied);
            }
            Formula {
                nodes,
                names: names.to_vec(),
            }
        })
    }

    /// The number of distinct nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the formula is empty (never: a formula has at least its root).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The formula's value with the variables set to `values` (in the order of the trace's
    /// names; a missing one is NaN). Opaque nodes give their traced value.
    pub fn eval(&self, values: &[f64]) -> f64 {
        let mut v: Vec<f64> = Vec::with_capacity(self.nodes.len());
        for node in &self.nodes {
            let x = match *node {
                Node::Num(c) => c,
                Node::Var(i) => values.get(i as usize).copied().unwrap_or(f64::NAN),
                Node::Add(a, b) => v[a as usize] + v[b as usize],
                Node::Mul(a, b) => v[a as usize] * v[b as usize],
                Node::Div(a, b) => v[a as usize] / v[b as usize],
                Node::Neg(a) => -v[a as usize],
                Node::Powi(a, n) => v[a as usize].powi(n),
                Node::Powf(a, p) => v[a as usize].powf(p),
                Node::Pow(a, b) => v[a as usize].powf(v[b as usize]),
                Node::Apply(f, a) => f.apply(v[a as usize]),
                Node::Atan2(a, b) => v[a as usize].atan2(v[b as usize]),
                Node::Opaque(_, _, value) => value,
                Node::TooLarge => f64::NAN,
            };
            v.push(x);
        }
        v.last().copied().unwrap_or(f64::NAN)
    }

    /// Plain text: `-sin(s)*(cos(t) + 2)`, `x^2`, `1/4` (ASCII, readable back by a parser).
    pub fn plain(&self) -> String {
        match self.nodes.len() {
            0 => String::new(),
            n => self.text(n as u32 - 1).0,
        }
    }

    /// The text of node `i` and its precedence (1 sum, 2 product, 3 unary minus, 4 power,
    /// 5 atom).
    fn text(&self, i: u32) -> (String, u8) {
        let wrap = |(s, p): (String, u8), min: u8| {
            if p < min {
                format!("({s})")
            } else {
                s
            }
        };
        match self.nodes[i as usize] {
            Node::Num(c) => {
                let s = number(c);
                let p = if s.starts_with('-') || s.contains('/') {
                    2
                } else {
                    5
                };
                (s, p)
            }
            Node::Var(k) => (
                self.names
                    .get(k as usize)
                    .cloned()
                    .unwrap_or_else(|| format!("x{k}")),
                5,
            ),
            Node::Add(a, b) => {
                let left = self.text(a).0;
                match self.nodes[b as usize] {
                    Node::Neg(c) => (format!("{left} - {}", wrap(self.text(c), 2)), 1),
                    Node::Num(c) if c < 0.0 => (format!("{left} - {}", number(-c)), 1),
                    _ => (format!("{left} + {}", self.text(b).0), 1),
                }
            }
            Node::Mul(a, b) => (
                format!("{}*{}", wrap(self.text(a), 2), wrap(self.text(b), 3)),
                2,
            ),
            Node::Div(a, b) => (
                format!("{}/{}", wrap(self.text(a), 2), wrap(self.text(b), 4)),
                2,
            ),
            Node::Neg(a) => (format!("-{}", wrap(self.text(a), 2)), 3),
            Node::Powi(a, n) => {
                let e = if n < 0 {
                    format!("({n})")
                } else {
                    n.to_string()
                };
                (format!("{}^{e}", wrap(self.text(a), 5)), 4)
            }
            Node::Powf(a, x) => (format!("{}^({})", wrap(self.text(a), 5), number(x)), 4),
            Node::Pow(a, b) => (
                format!("{}^{}", wrap(self.text(a), 5), wrap(self.text(b), 5)),
                4,
            ),
            Node::Apply(f, a) => (format!("{}({})", f.name(), self.text(a).0), 5),
            Node::Atan2(a, b) => (format!("atan2({}, {})", self.text(a).0, self.text(b).0), 5),
            Node::Opaque(what, a, _) => (format!("{what}[{}]", self.text(a).0), 5),
            Node::TooLarge => ("<expression too large>".into(), 5),
        }
    }
}

fn children(node: &Node) -> [Option<u32>; 2] {
    match *node {
        Node::Add(a, b)
        | Node::Mul(a, b)
        | Node::Div(a, b)
        | Node::Pow(a, b)
        | Node::Atan2(a, b) => [Some(a), Some(b)],
        Node::Neg(a)
        | Node::Powi(a, _)
        | Node::Powf(a, _)
        | Node::Apply(_, a)
        | Node::Opaque(_, a, _) => [Some(a), None],
        Node::Num(_) | Node::Var(_) | Node::TooLarge => [None, None],
    }
}

/// A constant as printed: an integer, a fraction `p/q` with `q ≤ 64` when it is exactly one,
/// else the shortest decimal that reads back to the same `f64`.
pub fn number(c: f64) -> String {
    if c.is_finite() && c.fract() == 0.0 && c.abs() < 1e15 {
        return format!("{}", c as i64);
    }
    if c.is_finite() {
        for q in 2..=64u32 {
            let p = c * q as f64;
            if p.fract() == 0.0 && p.abs() < 1e15 && p / q as f64 == c {
                return format!("{}/{q}", p as i64);
            }
        }
    }
    format!("{c}")
}

/// The plain text of a live expression (with variables named `x0`, `x1`, … unless a trace
/// named them).
pub(crate) fn plain(e: &Expr) -> String {
    let names = super::current_names();
    Formula::capture(e, &names).plain()
}
