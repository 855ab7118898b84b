//! Formulas owned outside the arena (in the normal form of [`super::canon`]), their
//! evaluation and their printing as plain text and as LaTeX, from one printer: operator
//! precedence respected and no redundant brackets; constants that are exactly small
//! rationals printed as fractions, others as the shortest decimal that reads back to the
//! same `f64`.

use super::canon::{
    apply_bound, atan2_bound, pow_bound, Atom, Sum, Term, MAX_FORMULA_DEPTH, MAX_FORMULA_SIZE,
};
use super::coef::Coef;
use super::expr::{Expr, FastMap, Func, Node, ARENA};
use crate::error::{Error, Result};
pub use crate::printed::number;
use crate::printed::{decimal, fraction};
use std::rc::Rc;

/// A formula copied out of a trace and simplified ([`crate::symbolic`]): evaluate it, print it
/// as plain text or LaTeX, multiply it out.
#[derive(Debug, Clone)]
pub struct Formula {
    root: Sum,
    names: Vec<String>,
    /// What the formula was checked against at capture, and every rewrite of it is again.
    witness: Witness,
}

/// Two formulas are equal when they are the same expression in the same variables (wherever
/// they were traced).
impl PartialEq for Formula {
    fn eq(&self, other: &Formula) -> bool {
        self.root == other.root && self.names == other.names
    }
}

/// The trace point, the value the traced code computed there and that computation's
/// rounding bound (units of `ε`): a formula must give the same value within both bounds.
#[derive(Debug, Clone, PartialEq)]
struct Witness {
    point: Vec<f64>,
    traced: f64,
    bound: f64,
}

/// Differences up to this many times the first-order rounding bounds (in units of `ε`) are
/// accepted by the capture check: the bounds are worst cases of first order, so a true
/// formula stays far inside; a wrong one (a rewrite that changes the value, a corrupted
/// node) misses by far more.
const CHECK_SLACK: f64 = 8.0;

impl Witness {
    /// `root` [snapped](Sum::snapped) (rounding residue cleaned: `3/5` for
    /// `0.6000000000000001`, no `4.9e-17` term), if the snapped form still passes the check;
    /// else `root` as it is.
    fn snapped(&self, root: Sum, names: &[String]) -> Sum {
        // a constant term within the traced computation's own rounding is that rounding
        let floor = CHECK_SLACK * f64::EPSILON * self.bound;
        let floor = if floor.is_finite() { floor } else { 0.0 };
        if !root.needs_snap(floor) {
            return root;
        }
        let snapped = root.snapped(floor);
        if snapped != root && self.check(&snapped, names).is_ok() {
            snapped
        } else {
            root
        }
    }

    /// That `root` gives the traced value at the trace point ([`Error::FormulaCheck`] if not).
    /// A traced NaN has no value to vouch for (`x/x` is `1` where the trace divided 0 by 0):
    /// accepted; a traced infinity must be the formula's value too.
    fn check(&self, root: &Sum, names: &[String]) -> Result<()> {
        if self.traced.is_nan() {
            return Ok(());
        }
        let (value, bound) = root.eval_bound(&self.point);
        if self.traced.is_infinite() && (value == self.traced || value.is_nan()) {
            return Ok(());
        }
        let allowed = CHECK_SLACK * f64::EPSILON * (bound + self.bound) + 16.0 * f64::MIN_POSITIVE;
        // a bound that is not finite (a pole within rounding) cannot refuse a finite value
        if self.traced.is_finite()
            && ((value - self.traced).abs() <= allowed || !allowed.is_finite())
        {
            return Ok(());
        }
        let mut formula = Printer {
            style: Style::Plain,
            names,
        }
        .sum(root);
        if formula.chars().count() > 200 {
            formula = formula.chars().take(200).collect::<String>() + "…";
        }
        Err(Error::FormulaCheck {
            formula,
            evaluated: value,
            traced: self.traced,
            bound: allowed,
        })
    }
}

impl Formula {
    /// The formula of `e`, copied out of the running trace and simplified, with variable
    /// names `names` and values `point` at the trace point, checked against `e`'s value.
    ///
    /// # Errors
    /// [`Error::Degenerate`] for a handle of another trace; [`Error::TooLarge`] beyond
    /// [`MAX_FORMULA_SIZE`] or [`MAX_FORMULA_DEPTH`]; [`Error::FormulaCheck`] if the
    /// simplified formula does not give the traced value at the trace point.
    pub(crate) fn capture(e: &Expr, names: &[String], point: &[f64]) -> Result<Formula> {
        let mut all = Formula::capture_many(std::slice::from_ref(e), names, point)?;
        Ok(all.remove(0))
    }

    /// The formulas of `roots`, copied out of the running trace in one pass (subexpressions
    /// they share are simplified once), each checked against its traced value.
    ///
    /// # Errors
    /// As [`Formula::capture`].
    pub(crate) fn capture_many(
        roots: &[Expr],
        names: &[String],
        point: &[f64],
    ) -> Result<Vec<Formula>> {
        // constants read as the fractions they are within rounding (`coef` module), unless a
        // formula so read does not pass the capture check: then as the numbers they are
        let read = Formula::normal_forms(roots, point, true)?;
        let captured = if read.iter().all(|(root, w)| w.check(root, names).is_ok()) {
            read
        } else {
            Formula::normal_forms(roots, point, false)?
        };
        captured
            .into_iter()
            .map(|(root, witness)| {
                witness.check(&root, names)?;
                // fractions over one denominator where that is shorter, if still checked
                let combined = root.combined();
                let root = if combined != root && witness.check(&combined, names).is_ok() {
                    combined
                } else {
                    root
                };
                Ok(Formula {
                    root: witness.snapped(root, names),
                    names: names.to_vec(),
                    witness,
                })
            })
            .collect()
    }

    /// The normal forms of `roots` and their witnesses, the constants read as fractions
    /// ([`Coef::read`]) or taken as they are.
    fn normal_forms(roots: &[Expr], point: &[f64], read: bool) -> Result<Vec<(Sum, Witness)>> {
        ARENA.with(|a| {
            let a = a.borrow();
            if roots
                .iter()
                .any(|e| a.generation != e.generation || e.id as usize >= a.nodes.len())
            {
                return Err(Error::Degenerate {
                    what: "symbolic formula",
                    reason: "the expression belongs to a trace that has ended",
                });
            }
            // the nodes the roots depend on; children always precede parents in the arena
            let mut reach: Vec<u32> = Vec::new();
            let mut seen: FastMap<u32, ()> = FastMap::default();
            for e in roots {
                if seen.insert(e.id, ()).is_none() {
                    reach.push(e.id);
                }
            }
            let mut k = 0;
            while k < reach.len() {
                for c in children(&a.nodes[reach[k] as usize]).into_iter().flatten() {
                    if seen.insert(c, ()).is_none() {
                        reach.push(c);
                    }
                }
                k += 1;
            }
            reach.sort_unstable();
            // the size of the data: the largest constant the roots depend on
            let scale = reach
                .iter()
                .filter_map(|&id| match a.nodes[id as usize] {
                    Node::Num(c) if c.is_finite() => Some(c.abs()),
                    _ => None,
                })
                .fold(0.0, f64::max);
            // all or nothing: a single constant that is not a fraction keeps every one a number
            let read = read
                && reach.iter().all(|&id| match a.nodes[id as usize] {
                    Node::Num(c) => Coef::readable(c, scale),
                    _ => true,
                });
            let mut done: FastMap<u32, Sum> = FastMap::default();
            done.reserve(reach.len());
            // each node's value at the trace point as the traced code computed it, and that
            // computation's rounding bound: the witness of the capture check
            let mut traced: FastMap<u32, (f64, f64)> = FastMap::default();
            traced.reserve(reach.len());
            for id in reach {
                let bound = traced_bound(a.nodes[id as usize], point, |k| traced[&k]);
                traced.insert(id, bound);
                let s = |k: u32| &done[&k];
                let sum = match a.nodes[id as usize] {
                    Node::Num(c) if read => Sum::constant(Coef::read(c, scale)),
                    Node::Num(c) => Sum::num(c),
                    Node::Var(i) => Sum::atom(Atom::Var(i)),
                    Node::Add(x, y) => Sum::add(s(x), s(y)),
                    Node::Mul(x, y) => Sum::mul(s(x), s(y)),
                    Node::Div(x, y) => Sum::mul(s(x), &Sum::powi(s(y), -1)),
                    Node::Neg(x) => Sum::neg(s(x)),
                    Node::Powi(x, n) => Sum::powi(s(x), n),
                    Node::Powf(x, p) => Sum::powf(s(x), p),
                    Node::Pow(x, y) => Sum::pow(s(x), s(y)),
                    Node::Apply(f, x) => Sum::apply(f, s(x)),
                    Node::Atan2(x, y) => Sum::atan2(s(x), s(y)),
                    Node::Opaque(w, x, v) => Sum::atom(Atom::Opaque(w, s(x).clone(), v)),
                    Node::TooLarge => {
                        return Err(too_large("expression nodes of a trace", usize::MAX));
                    }
                };
                check(&sum)?;
                done.insert(id, sum);
            }
            Ok(roots
                .iter()
                .map(|e| {
                    let root = done.get(&e.id).cloned().unwrap_or_default();
                    let witness = Witness {
                        point: point.to_vec(),
                        traced: e.value,
                        bound: traced.get(&e.id).map_or(0.0, |t| t.1),
                    };
                    (root, witness)
                })
                .collect::<Vec<(Sum, Witness)>>())
        })
    }

    /// The number of nodes written out as a tree.
    pub fn len(&self) -> usize {
        self.root.size()
    }

    /// Whether the formula is empty (never: a formula has at least its root).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// `(i, a, b)` when the formula is `a·xᵢ + b` with `a ≠ 0` (an affine function of one
    /// variable): a condition on it is a condition on `xᵢ`.
    pub(crate) fn affine(&self) -> Option<(u32, f64, f64)> {
        let (mut var, mut a, mut b) = (None, 0.0, 0.0);
        for t in &self.root.terms {
            match t.factors.as_slice() {
                [] => b += t.coef.value(),
                [(atom, e)] if *e == 1.0 => match atom.as_ref() {
                    Atom::Var(i) if var.is_none() => {
                        var = Some(*i);
                        a = t.coef.value();
                    }
                    _ => return None,
                },
                _ => return None,
            }
        }
        var.filter(|_| a != 0.0 && a.is_finite() && b.is_finite())
            .map(|i| (i, a, b))
    }

    /// The names of the variables, in the order [`Formula::eval`] takes their values.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The constant this formula is, if it is one.
    pub fn as_constant(&self) -> Option<f64> {
        self.root.as_constant()
    }

    /// The formula's value with the variables set to `values` (in the order of
    /// [`Formula::names`]; a missing one is NaN). Opaque nodes give their traced value.
    pub fn eval(&self, values: &[f64]) -> f64 {
        self.root.eval(values)
    }

    /// The formula with every product of sums multiplied out (a polynomial in power form),
    /// inside functions and denominators too.
    ///
    /// # Errors
    /// [`Error::TooLarge`] if the result would exceed [`MAX_FORMULA_SIZE`].
    pub fn expanded(&self) -> Result<Formula> {
        let root = self
            .root
            .expanded()
            .ok_or_else(|| too_large("nodes of an expanded formula", self.len()))?;
        check(&root)?;
        self.witness.check(&root, &self.names)?;
        Ok(Formula {
            root: self.witness.snapped(root, &self.names),
            names: self.names.clone(),
            witness: self.witness.clone(),
        })
    }

    /// [`Formula::expanded`] if the formula is rational in its variables (no function of
    /// them: the polynomial or rational piece of a spline, which reads best in powers), over
    /// one common denominator where its denominators are powers of one polynomial (a NURBS
    /// piece and its derivatives: `(N′·D − N·D′)/D^2`), else
    /// the formula as it is (the torus's `cos(s)*(2 + cos(t))`); also as it is where
    /// multiplying out would exceed [`MAX_FORMULA_SIZE`] or where the multiplied-out form
    /// would not pass the capture check.
    pub fn tidy(&self) -> Formula {
        if !self.root.is_rational() {
            return self.clone();
        }
        match self.expanded() {
            Ok(f) => match f.root.over_common_denominator() {
                Some(root) if check(&root).is_ok() && f.witness.check(&root, &f.names).is_ok() => {
                    Formula {
                        root: f.witness.snapped(root, &f.names),
                        names: f.names,
                        witness: f.witness,
                    }
                }
                _ => f,
            },
            Err(_) => self.clone(),
        }
    }

    /// Plain text: `-sin(s)*(2 + cos(t))`, `3*t*(1 - t)^2`, `t/4` (ASCII, readable back by
    /// a parser with the usual precedence).
    pub fn plain(&self) -> String {
        Printer {
            style: Style::Plain,
            names: &self.names,
        }
        .sum(&self.root)
    }

    /// LaTeX (for a math environment): `-\sin(s) \left(2 + \cos(t)\right)`, `\frac{t}{4}`.
    pub fn latex(&self) -> String {
        Printer {
            style: Style::Latex,
            names: &self.names,
        }
        .sum(&self.root)
    }

    /// Presentation MathML (the contents of a `<math>` element), which browsers render
    /// without a script: the form a notebook's HTML copy shows.
    pub fn mathml(&self) -> String {
        Printer {
            style: Style::MathMl,
            names: &self.names,
        }
        .sum(&self.root)
    }
}

impl std::fmt::Display for Formula {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.plain())
    }
}

/// The value at the trace point of `node`, as the traced code computed it (from its
/// children's values `v`), and that computation's first-order rounding bound in units of
/// `ε`: the capture check's witness.
fn traced_bound(node: Node, point: &[f64], v: impl Fn(u32) -> (f64, f64)) -> (f64, f64) {
    match node {
        Node::Num(c) => (c, 0.0),
        Node::Var(i) => (point.get(i as usize).copied().unwrap_or(f64::NAN), 0.0),
        Node::Add(x, y) => {
            let ((x, ex), (y, ey)) = (v(x), v(y));
            (x + y, ex + ey + (x + y).abs())
        }
        Node::Mul(x, y) => {
            let ((x, ex), (y, ey)) = (v(x), v(y));
            (x * y, y.abs() * ex + x.abs() * ey + (x * y).abs())
        }
        Node::Div(x, y) => {
            let ((x, ex), (y, ey)) = (v(x), v(y));
            let q = x / y;
            (q, (ex + q.abs() * ey) / y.abs() + q.abs())
        }
        Node::Neg(x) => {
            let (x, ex) = v(x);
            (-x, ex)
        }
        Node::Powi(x, n) => {
            let (x, ex) = v(x);
            let p = x.powi(n);
            let d = if ex == 0.0 {
                0.0
            } else {
                (f64::from(n) * x.powi(n - 1)).abs() * ex
            };
            (p, d + f64::from(n).abs() * p.abs())
        }
        Node::Powf(x, p) => {
            let (x, ex) = v(x);
            let r = x.powf(p);
            (r, pow_bound(x, ex, p, 0.0, r))
        }
        Node::Pow(x, y) => {
            let ((x, ex), (y, ey)) = (v(x), v(y));
            let r = x.powf(y);
            (r, pow_bound(x, ex, y, ey, r))
        }
        Node::Apply(f, x) => {
            let (x, ex) = v(x);
            apply_bound(f, x, ex)
        }
        Node::Atan2(y, x) => {
            let ((y, ey), (x, ex)) = (v(y), v(x));
            let r = y.atan2(x);
            (r, atan2_bound(y, ey, x, ex, r))
        }
        Node::Opaque(_, _, value) => (value, 0.0),
        Node::TooLarge => (f64::NAN, 0.0),
    }
}

fn too_large(what: &'static str, got: usize) -> Error {
    Error::TooLarge {
        what,
        got,
        max: MAX_FORMULA_SIZE,
    }
}

fn check(s: &Sum) -> Result<()> {
    if s.size() > MAX_FORMULA_SIZE {
        return Err(too_large("nodes of a formula written out", s.size()));
    }
    if s.depth() > MAX_FORMULA_DEPTH {
        return Err(Error::TooLarge {
            what: "nesting depth of a formula",
            got: s.depth(),
            max: MAX_FORMULA_DEPTH,
        });
    }
    Ok(())
}

pub(crate) fn children(node: &Node) -> [Option<u32>; 2] {
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

/// The plain text of a live expression (variables named as the running trace named them).
pub(crate) fn plain(e: &Expr) -> String {
    match Formula::capture(e, &super::current_names(), &super::current_point()) {
        Ok(f) => f.plain(),
        Err(err) => format!("<{err}>"),
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Style {
    Plain,
    Latex,
    MathMl,
}

/// One printer for every style: the structure (order, brackets, fractions, common factors)
/// is decided once, only the tokens differ.
struct Printer<'a> {
    style: Style,
    names: &'a [String],
}

impl Printer<'_> {
    fn paren(&self, s: &str) -> String {
        match self.style {
            Style::Plain => format!("({s})"),
            Style::Latex => format!("\\left({s}\\right)"),
            Style::MathMl => format!("<mrow><mo>(</mo>{s}<mo>)</mo></mrow>"),
        }
    }

    /// An operator between or before operands (`+`, `-`).
    fn op(&self, o: char) -> String {
        match self.style {
            Style::MathMl => format!("<mo>{}</mo>", if o == '-' { '\u{2212}' } else { o }),
            _ => o.to_string(),
        }
    }

    fn frac(&self, top: &str, bottom: &str, bottom_parts: usize) -> String {
        match self.style {
            Style::Plain if bottom_parts == 1 => format!("{top}/{bottom}"),
            Style::Plain => format!("{top}/({bottom})"),
            Style::Latex => format!("\\frac{{{top}}}{{{bottom}}}"),
            Style::MathMl => format!("<mfrac><mrow>{top}</mrow><mrow>{bottom}</mrow></mfrac>"),
        }
    }

    fn sup(&self, base: &str, exp: &str) -> String {
        match self.style {
            Style::Plain => format!("{base}^{exp}"),
            Style::Latex => format!("{base}^{{{exp}}}"),
            Style::MathMl => format!("<msup><mrow>{base}</mrow><mrow>{exp}</mrow></msup>"),
        }
    }

    fn sqrt(&self, x: &str) -> String {
        match self.style {
            Style::Plain => format!("sqrt({x})"),
            Style::Latex => format!("\\sqrt{{{x}}}"),
            Style::MathMl => format!("<msqrt>{x}</msqrt>"),
        }
    }

    fn num(&self, c: f64) -> String {
        match (self.style, fraction(c)) {
            (Style::Plain, _) => number(c),
            (_, Some((p, 1))) => self.digits(&p.unsigned_abs().to_string(), p < 0),
            (_, Some((p, q))) => {
                let f = self.frac(
                    &self.digits(&p.unsigned_abs().to_string(), false),
                    &self.digits(&q.to_string(), false),
                    1,
                );
                if p < 0 {
                    format!("{}{f}", self.op('-'))
                } else {
                    f
                }
            }
            (Style::Latex, None) if c.is_nan() => "\\mathrm{NaN}".into(),
            (Style::Latex, None) if c.is_infinite() => {
                if c > 0.0 { "\\infty" } else { "-\\infty" }.into()
            }
            (Style::MathMl, None) if !c.is_finite() => {
                format!("<mi>{}</mi>", number(c).replace("inf", "\u{221e}"))
            }
            (_, None) => {
                let text = decimal(c.abs());
                let body = match text.split_once('e') {
                    Some((m, e)) => {
                        let (m, e) = (self.digits(m, false), self.digits(e, false));
                        let ten = self.digits("10", false);
                        match self.style {
                            Style::Latex => format!("{m} \\cdot {}", self.sup(&ten, &e)),
                            _ => format!("{m}<mo>\u{22c5}</mo>{}", self.sup(&ten, &e)),
                        }
                    }
                    None => self.digits(&text, false),
                };
                if c < 0.0 {
                    format!("{}{body}", self.op('-'))
                } else {
                    body
                }
            }
        }
    }

    fn digits(&self, d: &str, negative: bool) -> String {
        let sign = if negative {
            self.op('-')
        } else {
            String::new()
        };
        match self.style {
            Style::MathMl => format!("{sign}<mn>{d}</mn>"),
            _ => format!("{sign}{d}"),
        }
    }

    fn var(&self, i: u32) -> String {
        let name = self
            .names
            .get(i as usize)
            .cloned()
            .unwrap_or_else(|| format!("x{i}"));
        let stem_len = name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
        let (head, digits) = name.split_at(stem_len);
        let subscript = !digits.is_empty() && head.chars().count() == 1;
        match self.style {
            Style::Plain => name,
            Style::Latex if subscript => format!("{head}_{{{digits}}}"),
            Style::Latex if name.chars().count() > 1 => format!("\\mathit{{{name}}}"),
            Style::Latex => name,
            Style::MathMl if subscript => {
                format!("<msub><mi>{head}</mi><mn>{digits}</mn></msub>")
            }
            Style::MathMl => format!("<mi>{}</mi>", escape(&name)),
        }
    }

    /// A sum: common factors and signs out, the first term positive where one is.
    fn sum(&self, s: &Sum) -> String {
        match s.terms.as_slice() {
            [] => self.num(0.0),
            [t] => self.term(t),
            terms => {
                if let Some(factored) = factor_out(terms) {
                    return self.term(&factored);
                }
                // ascending powers of the variables, constants first, as the report prints
                // its bases and Codice 3 its torus (`2 + cos(t)`); then a positive term
                // first where there is one
                let mut order: Vec<&Term> = terms.iter().collect();
                order.sort_by(|a, b| {
                    (degree(a), !a.factors.is_empty())
                        .cmp(&(degree(b), !b.factors.is_empty()))
                        .then_with(|| self.cmp_terms(a, b))
                });
                if order[0].coef.value() < 0.0 {
                    if let Some(k) = order.iter().position(|t| t.coef.value() >= 0.0) {
                        let first = order.remove(k);
                        order.insert(0, first);
                    }
                }
                let gap = if self.style == Style::MathMl { "" } else { " " };
                let mut out = self.term(order[0]);
                for t in &order[1..] {
                    let (o, t) = if t.coef.value() < 0.0 {
                        ('-', negated(t))
                    } else {
                        ('+', (*t).clone())
                    };
                    out.push_str(&format!("{gap}{}{gap}{}", self.op(o), self.term(&t)));
                }
                out
            }
        }
    }

    /// A term: sign, numerator (coefficient first), denominator.
    fn term(&self, t: &Term) -> String {
        let value = t.coef.value();
        let sign = if value < 0.0 || (value == 0.0 && value.is_sign_negative()) {
            self.op('-')
        } else {
            String::new()
        };
        let c = value.abs();
        let (mut num, mut den): (Vec<String>, Vec<String>) = (Vec::new(), Vec::new());
        match t.coef.fraction() {
            Some((p, q)) if q > 64 || !t.factors.is_empty() => {
                // an exact fraction beyond what the value's printing finds (`29/81`)
                let p = p.unsigned_abs();
                if p != 1 || t.factors.is_empty() {
                    num.push(self.num(p as f64));
                }
                if q > 1 {
                    den.push(self.num(q as f64));
                }
            }
            _ => num.push(self.num(c)),
        }
        // a sum alone above or below a fraction bar needs no brackets in LaTeX and MathML
        let (mut num_bare, mut den_bare) = (None, None);
        for (a, e) in self.canonical(&t.factors) {
            let bare = match (a.as_ref(), e.abs()) {
                (Atom::Group(s), 1.0) => Some(self.sum(s)),
                _ => None,
            };
            if *e > 0.0 {
                num.push(self.factor(a, *e));
                num_bare = bare;
            } else {
                den.push(self.factor(a, -e));
                den_bare = bare;
            }
        }
        let body = match (num.is_empty(), den.is_empty()) {
            (true, true) => self.num(1.0),
            (_, true) => self.times(&num),
            _ => {
                let stacked = self.style != Style::Plain;
                let top = match (num.len(), num_bare) {
                    (0, _) => self.num(1.0),
                    (1, Some(bare)) if stacked => bare,
                    _ => self.times(&num),
                };
                let bottom = match (den.len(), den_bare) {
                    (1, Some(bare)) if stacked => bare,
                    _ => self.times(&den),
                };
                self.frac(&top, &bottom, den.len())
            }
        };
        format!("{sign}{body}")
    }

    /// A product's factors in the one print order: variables (in the trace's order), then
    /// functions, powers, groups (`sin(s)*(2 + cos(t))`), `atan2`, opaque nodes; within a
    /// kind, by the variables they depend on (`cos(s)` before `sin(t)`), a function's name,
    /// then the printed text. So
    /// `x·y` and `y·x` print alike wherever they occur.
    fn canonical<'f>(&self, factors: &'f [(Rc<Atom>, f64)]) -> Vec<&'f (Rc<Atom>, f64)> {
        let mut order: Vec<&(Rc<Atom>, f64)> = factors.iter().collect();
        if order.len() > 1 {
            order.sort_by(|x, y| self.cmp_atoms(&x.0, &y.0));
        }
        order
    }

    fn cmp_atoms(&self, a: &Atom, b: &Atom) -> std::cmp::Ordering {
        let rank = |a: &Atom| match a {
            Atom::Var(i) => (0, *i, 0, ""),
            Atom::Func(f, _) => (1, 0, first_var(a), f.name()),
            Atom::Pow(..) => (2, 0, first_var(a), ""),
            Atom::Group(_) => (3, 0, first_var(a), ""),
            Atom::Atan2(..) => (4, 0, first_var(a), ""),
            Atom::Opaque(w, ..) => (5, 0, first_var(a), *w),
        };
        rank(a).cmp(&rank(b)).then_with(|| {
            let plain = Printer {
                style: Style::Plain,
                names: self.names,
            };
            plain.atom(a).cmp(&plain.atom(b))
        })
    }

    /// Terms in the one print order: their factors compared in order, then exponents, then
    /// coefficients.
    fn cmp_terms(&self, a: &Term, b: &Term) -> std::cmp::Ordering {
        let (fa, fb) = (self.canonical(&a.factors), self.canonical(&b.factors));
        for (x, y) in fa.iter().zip(&fb) {
            let o = self.cmp_atoms(&x.0, &y.0).then_with(|| y.1.total_cmp(&x.1));
            if o.is_ne() {
                return o;
            }
        }
        fa.len()
            .cmp(&fb.len())
            .then_with(|| a.coef.value().total_cmp(&b.coef.value()))
    }

    /// Factors side by side: `*` in plain text; juxtaposed in LaTeX and MathML, with a dot
    /// before a factor that starts with a number.
    fn times(&self, parts: &[String]) -> String {
        let mut out = String::new();
        for (k, p) in parts.iter().enumerate() {
            if k > 0 {
                out.push_str(match self.style {
                    Style::Plain => "*",
                    Style::Latex if p.starts_with(|c: char| c.is_ascii_digit()) => " \\cdot ",
                    Style::Latex if p.starts_with("\\frac") => " \\cdot ",
                    Style::Latex => " ",
                    Style::MathMl if p.starts_with("<mn>") || p.starts_with("<mfrac>") => {
                        "<mo>\u{22c5}</mo>"
                    }
                    Style::MathMl => "<mo>\u{2062}</mo>",
                });
            }
            out.push_str(p);
        }
        out
    }

    /// `baseᵉ`, `e > 0`.
    fn factor(&self, a: &Atom, e: f64) -> String {
        if e == 0.5 {
            let inner = match a {
                Atom::Group(s) => self.sum(s),
                other => self.atom(other),
            };
            return self.sqrt(&inner);
        }
        let base = match a {
            Atom::Group(s) if !is_atomic(s) => self.paren(&self.sum(s)),
            Atom::Group(s) => self.sum(s),
            Atom::Pow(..) if e != 1.0 => self.paren(&self.atom(a)),
            other => self.atom(other),
        };
        if e == 1.0 {
            return base;
        }
        let exp = self.num(e);
        match (self.style, a) {
            // sin²(t), as mathematics writes it
            (Style::Latex | Style::MathMl, Atom::Func(f, arg)) if e.fract() == 0.0 => {
                match self.func_name(*f) {
                    Some(name) => format!("{}{}", self.sup(&name, &exp), self.arg(arg)),
                    None => self.sup(&base, &exp),
                }
            }
            (Style::Plain, _) if e.fract() != 0.0 => format!("{base}^({exp})"),
            _ => self.sup(&base, &exp),
        }
    }

    fn atom(&self, a: &Atom) -> String {
        match a {
            Atom::Var(i) => self.var(*i),
            Atom::Group(s) => self.paren(&self.sum(s)),
            Atom::Func(f, x) => self.func(*f, x),
            Atom::Pow(x, y) => {
                let base = if is_atomic(x) {
                    self.sum(x)
                } else {
                    self.paren(&self.sum(x))
                };
                let exp = match self.style {
                    Style::Plain if !is_atomic(y) => self.paren(&self.sum(y)),
                    _ => self.sum(y),
                };
                self.sup(&base, &exp)
            }
            Atom::Atan2(x, y) => {
                let args = match self.style {
                    Style::MathMl => format!("{}<mo>,</mo>{}", self.sum(x), self.sum(y)),
                    _ => format!("{}, {}", self.sum(x), self.sum(y)),
                };
                format!("{}{}", self.named("atan2"), self.paren(&args))
            }
            Atom::Opaque(what, x, _) => {
                let x = self.sum(x);
                match self.style {
                    Style::Plain => format!("{what}[{x}]"),
                    Style::Latex => format!("\\operatorname{{{what}}}\\left[{x}\\right]"),
                    Style::MathMl => format!("<mi>{what}</mi><mo>[</mo>{x}<mo>]</mo>"),
                }
            }
        }
    }

    /// A name set upright (`atan2`, `arsinh`).
    fn named(&self, name: &str) -> String {
        match self.style {
            Style::Plain => name.into(),
            Style::Latex => format!("\\operatorname{{{name}}}"),
            Style::MathMl => format!("<mi mathvariant=\"normal\">{name}</mi><mo>\u{2061}</mo>"),
        }
    }

    /// The function's name as set in the style (`None` for those set as notation: `√`, `|x|`).
    fn func_name(&self, f: Func) -> Option<String> {
        match (self.style, f) {
            (_, Func::Sqrt | Func::Cbrt | Func::Abs) => None,
            (Style::Plain, _) => Some(f.name().into()),
            (Style::Latex, _) => {
                Some(latex_func(f).map_or_else(|| self.named(f.name()), String::from))
            }
            (Style::MathMl, Func::SphJ0 | Func::SphJ1 | Func::SphJ2) => Some(format!(
                "<msub><mi>j</mi><mn>{}</mn></msub>",
                &f.name()[1..]
            )),
            (Style::MathMl, _) => Some(format!("<mi>{}</mi>", f.name())),
        }
    }

    /// A function's argument in brackets.
    fn arg(&self, x: &Sum) -> String {
        match self.style {
            Style::Latex if is_atomic(x) => format!("({})", self.sum(x)),
            _ => self.paren(&self.sum(x)),
        }
    }

    fn func(&self, f: Func, x: &Sum) -> String {
        let inner = self.sum(x);
        match (self.style, f) {
            (Style::Plain, _) => format!("{}({inner})", f.name()),
            (_, Func::Sqrt) => self.sqrt(&inner),
            (Style::Latex, Func::Abs) => format!("\\left|{inner}\\right|"),
            (Style::Latex, Func::Cbrt) => format!("\\sqrt[3]{{{inner}}}"),
            (Style::MathMl, Func::Abs) => format!("<mrow><mo>|</mo>{inner}<mo>|</mo></mrow>"),
            (Style::MathMl, Func::Cbrt) => format!("<mroot><mrow>{inner}</mrow><mn>3</mn></mroot>"),
            (Style::MathMl, _) => format!(
                "{}<mo>\u{2061}</mo>{}",
                self.func_name(f).unwrap_or_default(),
                self.arg(x)
            ),
            (Style::Latex, _) => {
                format!("{}{}", self.func_name(f).unwrap_or_default(), self.arg(x))
            }
        }
    }
}

/// The LaTeX command of a function that has one (`\sin`, `\arctan`, `j_0`).
fn latex_func(f: Func) -> Option<&'static str> {
    Some(match f {
        Func::Sin => "\\sin",
        Func::Cos => "\\cos",
        Func::Tan => "\\tan",
        Func::Exp => "\\exp",
        Func::Ln => "\\ln",
        Func::Asin => "\\arcsin",
        Func::Acos => "\\arccos",
        Func::Atan => "\\arctan",
        Func::Sinh => "\\sinh",
        Func::Cosh => "\\cosh",
        Func::Tanh => "\\tanh",
        Func::Asinh => "\\operatorname{arsinh}",
        Func::Acosh => "\\operatorname{arcosh}",
        Func::Atanh => "\\operatorname{artanh}",
        Func::SphJ0 => "j_0",
        Func::SphJ1 => "j_1",
        Func::SphJ2 => "j_2",
        Func::Sqrt | Func::Cbrt | Func::Abs => return None,
    })
}

/// Whether a sum prints as one atom (a variable, a function, a positive integer): no
/// brackets needed under a power.
fn is_atomic(s: &Sum) -> bool {
    match s.terms.as_slice() {
        [] => true,
        [t] if t.factors.is_empty() => t.coef.value() >= 0.0 && t.coef.value().fract() == 0.0,
        [t] => {
            t.coef.value() == 1.0
                && t.factors.len() == 1
                && t.factors[0].1 == 1.0
                && !matches!(*t.factors[0].0, Atom::Pow(..) | Atom::Group(_))
        }
        _ => false,
    }
}

/// The smallest variable index an atom depends on (`u32::MAX` for none).
fn first_var(a: &Atom) -> u32 {
    let of_sum = |s: &Sum| {
        s.terms
            .iter()
            .flat_map(|t| t.factors.iter().map(|(a, _)| first_var(a)))
            .min()
            .unwrap_or(u32::MAX)
    };
    match a {
        Atom::Var(i) => *i,
        Atom::Func(_, s) | Atom::Group(s) | Atom::Opaque(_, s, _) => of_sum(s),
        Atom::Pow(x, y) | Atom::Atan2(x, y) => of_sum(x).min(of_sum(y)),
    }
}

/// The total power of the variables in a term (a polynomial's degree; other factors count
/// nothing).
fn degree(t: &Term) -> u64 {
    t.factors
        .iter()
        .filter(|(a, e)| a.is_var() && *e > 0.0 && e.fract() == 0.0)
        .map(|(_, e)| *e as u64)
        .sum()
}

fn negated(t: &Term) -> Term {
    Term {
        coef: t.coef.neg(),
        factors: t.factors.clone(),
    }
}

/// `Σ tᵢ` as `±c·(Σ tᵢ/c)` when every term shares a factor that is not a plain variable
/// (`−sin s·cos t − 2 sin s = −sin s·(cos t + 2)`) or every term is negative; `None` if
/// nothing is common. Powers of variables stay in place, so a polynomial prints expanded in
/// powers, as the report prints its bases.
fn factor_out(terms: &[Term]) -> Option<Term> {
    let sign = Coef::of(if terms.iter().all(|t| t.coef.value() < 0.0) {
        -1.0
    } else {
        1.0
    });
    let mut common: Vec<(Rc<Atom>, f64)> = Vec::new();
    for (a, e) in &terms[0].factors {
        if a.is_var() {
            continue;
        }
        let mut exp = *e;
        let everywhere = terms[1..].iter().all(|t| {
            t.factors.iter().any(|(b, f)| {
                let found = (Rc::ptr_eq(a, b) || a == b) && f.signum() == e.signum();
                if found && f.abs() < exp.abs() {
                    exp = *f;
                }
                found
            })
        });
        if everywhere {
            common.push((a.clone(), exp));
        }
    }
    if common.is_empty() && sign.value() > 0.0 {
        return None;
    }
    let rest: Vec<Term> = terms
        .iter()
        .map(|t| {
            let mut factors = t.factors.clone();
            for (a, e) in &common {
                if let Some(k) = factors.iter().position(|(b, _)| Rc::ptr_eq(a, b) || a == b) {
                    let left = factors[k].1 - e;
                    if left == 0.0 {
                        factors.remove(k);
                    } else {
                        factors[k].1 = left;
                    }
                }
            }
            Term {
                coef: t.coef.mul(sign),
                factors,
            }
        })
        .collect();
    // the rest collected again: a term that was a group alone is flattened into it
    let inner = rest
        .into_iter()
        .fold(Sum::num(0.0), |acc, t| Sum::add(&acc, &Sum::from_term(t)));
    let outside = Term {
        coef: sign,
        factors: common,
    };
    Some(match inner.terms.as_slice() {
        [] => Term::constant(Coef::of(0.0)),
        [t] => outside.times(t),
        _ => {
            let mut factors = outside.factors;
            factors.push((Rc::new(Atom::Group(inner)), 1.0));
            Term {
                coef: sign,
                factors,
            }
        }
    })
}

pub(crate) use crate::printed::escape;

#[cfg(test)]
mod tests {
    use super::super::{Node, Trace};
    use super::ARENA;
    use crate::error::Error;

    /// The capture check catches a formula that differs from what was traced: here a node
    /// corrupted after the trace computed its value.
    #[test]
    fn the_capture_check_catches_a_corrupted_node() {
        let mut trace = Trace::new();
        let x = trace.var("x", 0.5);
        let e = x * 2.0 + 1.0;
        assert_eq!(trace.formula(&e).unwrap().plain(), "1 + 2*x");
        ARENA.with(|a| {
            for n in a.borrow_mut().nodes.iter_mut() {
                if *n == Node::Num(2.0) {
                    *n = Node::Num(3.0);
                }
            }
        });
        match trace.formula(&e) {
            Err(Error::FormulaCheck {
                evaluated, traced, ..
            }) => {
                assert_eq!(traced, 2.0);
                assert_eq!(evaluated, 2.5);
            }
            other => panic!("not refused: {other:?}"),
        }
    }
}
