//! The normal form formulas are simplified into: a sum of terms, each a coefficient times a
//! product of powers of atoms (variables, functions, grouped sums, …).
//!
//! Rules (each valid wherever both sides are defined):
//! - like terms are collected (`a·b + 2·b·a = 3·a·b`: the factors compared as a multiset), and
//!   a term whose coefficient is `0` dropped;
//! - equal bases multiply by adding exponents (`x²·x⁻¹ = x`, `√x·√x = x`), a factor whose
//!   exponent becomes `0` is dropped;
//! - constants fold, and a constant multiplies into a sum (`2·(1 + t) = 2 + 2t`);
//! - a sum that is a factor of a product is kept whole, its sign out if all its terms are
//!   negative (`(−a − b)·c = −(a + b)·c`); `(x·y)ⁿ = xⁿ·yⁿ` and `(xᵃ)ⁿ = xᵃⁿ` for integer `n`,
//!   `(c·x·y)ᵖ = cᵖ·xᵖ·yᵖ` for `c > 0`, any `p` and bases that are `≥ 0` by their structure
//!   ([`Atom::nonnegative`]: `exp`, `cosh`, `|·|`, …), and `(c·xᵃ)ᵖ = cᵖ·xᵃᵖ` for one base
//!   with an odd integer `a` (`√(1/x) = x^(−1/2)`); a power `p` of anything else stays
//!   whole (`√(s·t)` is not `√s·√t`, `√(x²)` is not `x`).
//! - Equality is structural and ignores order: terms and factors compare as multisets
//!   (`sin(x + y) − sin(y + x) = 0`).
//!
//! Every rule gives a right side defined (and equal) wherever the left side is; the capture
//! check ([`crate::symbolic`]) evaluates each formula at its trace point against the traced
//! value.
//!
//! Order: terms and factors keep the order in which the traced code first produced them (the
//! formula reads like the code that computed it), with a product's coefficient first.
//!
//! Products of sums are *not* multiplied out unless asked ([`Sum::expanded`]), so the
//! Bernstein polynomial `3t(1 − t)²` stays as the report prints it.

use super::coef::Coef;
use super::expr::FastMap;
use super::expr::Func;
use std::rc::Rc;

/// The most nodes a formula may have when written out as a tree (shared subexpressions
/// counted each time they occur), the bound that keeps printing and evaluation finite.
pub const MAX_FORMULA_SIZE: usize = 1 << 20;

/// The most terms [`crate::symbolic::Formula::expanded`] produces (a typed error beyond: multiplying out is
/// refused, not attempted).
pub const MAX_EXPANDED_TERMS: usize = 1 << 14;

/// The deepest nesting a formula may have (functions of functions of …): printing and
/// evaluation recurse this deep at most.
pub const MAX_FORMULA_DEPTH: usize = 256;

/// A factor's base.
#[derive(Debug, Clone, PartialEq)]
pub enum Atom {
    /// A variable, by its index in the trace's names.
    Var(u32),
    /// `f(a)`.
    Func(Func, Sum),
    /// A sum (or, under a non-integer power, a product) kept whole.
    Group(Sum),
    /// `aᵇ` with an exponent that is not a constant.
    Pow(Sum, Sum),
    /// `atan2(a, b)`.
    Atan2(Sum, Sum),
    /// An operation without a formula (`%`), its argument and its value at the trace point.
    Opaque(&'static str, Sum, f64),
}

/// `coef · Π baseᵉ`, the factors in the order they were produced (printing orders them).
#[derive(Debug, Clone)]
pub struct Term {
    /// The coefficient.
    pub coef: Coef,
    /// Bases and their exponents (never `0`), no base twice.
    pub factors: Vec<(Rc<Atom>, f64)>,
}

/// A sum of terms in display order (`0` is the empty sum), with its size and depth.
#[derive(Debug, Clone, Default)]
pub struct Sum {
    /// The terms.
    pub terms: Vec<Term>,
    size: usize,
    depth: usize,
    /// A structural hash, independent of the terms' order (equal sums hash equal).
    hash: u64,
}

/// Terms are equal when their coefficients are and their factors are the same multiset
/// (`x·y = y·x`).
impl PartialEq for Term {
    fn eq(&self, other: &Term) -> bool {
        self.coef.value().to_bits() == other.coef.value().to_bits() && self.like(other)
    }
}

/// Sums are equal when their terms are the same multiset (`x + y = y + x`): a sum's terms are
/// pairwise unlike (collected), so each term of one must equal one term of the other.
impl PartialEq for Sum {
    fn eq(&self, other: &Sum) -> bool {
        if self.hash != other.hash || self.terms.len() != other.terms.len() {
            return false;
        }
        if self.terms.len() <= 8 {
            return self
                .terms
                .iter()
                .all(|t| other.terms.iter().any(|u| t == u));
        }
        let mut index: FastMap<u64, Vec<&Term>> = FastMap::default();
        for u in &other.terms {
            index.entry(u.monomial_hash()).or_default().push(u);
        }
        self.terms.iter().all(|t| {
            index
                .get(&t.monomial_hash())
                .is_some_and(|us| us.contains(&t))
        })
    }
}

/// A 64-bit mix (SplitMix64's finaliser): structural hashes of atoms, terms and sums.
fn mix(mut x: u64) -> u64 {
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

fn mix2(a: u64, b: u64) -> u64 {
    mix(a.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ b)
}

impl Atom {
    /// A structural hash (equal atoms hash equal).
    fn hash(&self) -> u64 {
        match self {
            Atom::Var(i) => mix2(1, u64::from(*i)),
            Atom::Func(f, a) => mix2(mix2(2, *f as u64), a.hash),
            Atom::Group(a) => mix2(3, a.hash),
            Atom::Pow(a, b) => mix2(mix2(4, a.hash), b.hash),
            Atom::Atan2(a, b) => mix2(mix2(5, a.hash), b.hash),
            Atom::Opaque(w, a, v) => mix2(mix2(mix2(6, w.len() as u64), a.hash), v.to_bits()),
        }
    }

    fn size(&self) -> usize {
        match self {
            Atom::Var(_) => 1,
            Atom::Func(_, a) | Atom::Group(a) | Atom::Opaque(_, a, _) => a.size.saturating_add(1),
            Atom::Pow(a, b) | Atom::Atan2(a, b) => a.size.saturating_add(b.size).saturating_add(1),
        }
    }

    fn depth(&self) -> usize {
        match self {
            Atom::Var(_) => 1,
            Atom::Func(_, a) | Atom::Group(a) | Atom::Opaque(_, a, _) => a.depth + 1,
            Atom::Pow(a, b) | Atom::Atan2(a, b) => a.depth.max(b.depth) + 1,
        }
    }

    /// The atom's value with the variables set to `values`.
    pub fn eval(&self, values: &[f64]) -> f64 {
        match self {
            Atom::Var(i) => values.get(*i as usize).copied().unwrap_or(f64::NAN),
            Atom::Func(f, a) => f.apply(a.eval(values)),
            Atom::Group(a) => a.eval(values),
            Atom::Pow(a, b) => a.eval(values).powf(b.eval(values)),
            Atom::Atan2(a, b) => a.eval(values).atan2(b.eval(values)),
            Atom::Opaque(_, _, v) => *v,
        }
    }

    /// The atom's value at `values` and a first-order bound of its rounding error in units
    /// of `ε` (module docs of [`crate::symbolic`]: the capture check).
    pub(crate) fn eval_bound(&self, values: &[f64]) -> (f64, f64) {
        match self {
            Atom::Var(i) => (values.get(*i as usize).copied().unwrap_or(f64::NAN), 0.0),
            Atom::Func(f, a) => {
                let (x, e) = a.eval_bound(values);
                apply_bound(*f, x, e)
            }
            Atom::Group(a) => a.eval_bound(values),
            Atom::Pow(a, b) => {
                let ((x, ex), (y, ey)) = (a.eval_bound(values), b.eval_bound(values));
                let v = x.powf(y);
                (v, pow_bound(x, ex, y, ey, v))
            }
            Atom::Atan2(a, b) => {
                let ((y, ey), (x, ex)) = (a.eval_bound(values), b.eval_bound(values));
                let v = y.atan2(x);
                (v, atan2_bound(y, ey, x, ex, v))
            }
            Atom::Opaque(_, _, v) => (*v, 0.0),
        }
    }

    /// Whether the atom is `≥ 0` wherever it is defined, by its structure (not by its value
    /// at a point): `exp`, `cosh`, `|x|`, `acos`, and groups and powers of such.
    pub fn nonnegative(&self) -> bool {
        match self {
            Atom::Func(f, _) => matches!(f, Func::Exp | Func::Cosh | Func::Abs | Func::Acos),
            Atom::Group(s) => s.nonnegative(),
            Atom::Pow(a, _) => a.nonnegative(),
            Atom::Var(_) | Atom::Atan2(..) | Atom::Opaque(..) => false,
        }
    }

    /// Whether this is a variable.
    pub fn is_var(&self) -> bool {
        matches!(self, Atom::Var(_))
    }
}

/// `f(x)` and its rounding bound (units of `ε`) from the bound `ex` of `x`: the argument's
/// error carried by `|f′(x)|`, and the function's own rounding (a library function is
/// within an ulp or two).
pub(crate) fn apply_bound(f: Func, x: f64, ex: f64) -> (f64, f64) {
    let y = f.apply(x);
    (y, f.slope(x) * ex + 2.0 * y.abs())
}

/// The rounding bound of `v = xʸ` (in units of `ε`) from the bounds `ex`, `ey` of `x`, `y`.
pub(crate) fn pow_bound(x: f64, ex: f64, y: f64, ey: f64, v: f64) -> f64 {
    let dx = if ex == 0.0 {
        0.0
    } else {
        (y * x.powf(y - 1.0)).abs() * ex
    };
    let dy = if ey == 0.0 {
        0.0
    } else {
        (v * x.ln()).abs() * ey
    };
    dx + dy + 2.0 * v.abs()
}

/// The rounding bound of `v = atan2(y, x)` (in units of `ε`).
pub(crate) fn atan2_bound(y: f64, ey: f64, x: f64, ex: f64, v: f64) -> f64 {
    let r2 = x * x + y * y;
    (x.abs() * ey + y.abs() * ex) / r2 + 2.0 * v.abs()
}

/// `x^e` as evaluated (square roots exactly as `sqrt`).
pub(crate) fn power(x: f64, e: f64) -> f64 {
    if e == 1.0 {
        x
    } else if e == 0.5 {
        x.sqrt()
    } else if e == -0.5 {
        1.0 / x.sqrt()
    } else if e.fract() == 0.0 && e.abs() <= i32::MAX as f64 {
        x.powi(e as i32)
    } else {
        x.powf(e)
    }
}

impl Term {
    pub(crate) fn constant(c: Coef) -> Term {
        Term {
            coef: c,
            factors: Vec::new(),
        }
    }

    /// A hash of the factors alone, independent of their order: like terms hash equal.
    fn monomial_hash(&self) -> u64 {
        self.factors.iter().fold(0u64, |h, (a, e)| {
            h.wrapping_add(mix2(a.hash(), e.to_bits()))
        })
    }

    fn size(&self) -> usize {
        self.factors
            .iter()
            .fold(1usize, |n, (a, _)| n.saturating_add(a.size()))
    }

    fn depth(&self) -> usize {
        self.factors
            .iter()
            .map(|(a, _)| a.depth())
            .max()
            .unwrap_or(0)
    }

    /// Whether the two terms have the same factors (in any order).
    pub fn like(&self, other: &Term) -> bool {
        self.factors.len() == other.factors.len()
            && self
                .factors
                .iter()
                .all(|(a, e)| other.factors.iter().any(|(b, f)| e == f && same_atom(a, b)))
    }

    fn eval(&self, values: &[f64]) -> f64 {
        self.factors
            .iter()
            .fold(self.coef.value(), |p, (a, e)| p * power(a.eval(values), *e))
    }

    /// The term's value and rounding bound (units of `ε`): the factors' errors carried by
    /// their partial derivatives, plus one rounding per multiplication and the coefficient's.
    fn eval_bound(&self, values: &[f64]) -> (f64, f64) {
        // Σⱼ dⱼ Πₖ≠ⱼ |vₖ| in one pass: the product of the non-zero |vₖ|, and the carried sum
        // Σ dⱼ / |vⱼ| over the non-zero factors (or the one zero factor's dⱼ)
        let (mut value, mut product, mut ratio) = (self.coef.value(), 1.0f64, 0.0f64);
        let (mut zeros, mut zero_d) = (0usize, 0.0f64);
        for (a, e) in &self.factors {
            let (x, ex) = a.eval_bound(values);
            let v = power(x, *e);
            let d = if ex == 0.0 {
                0.0
            } else {
                (e * power(x, e - 1.0)).abs() * ex
            } + 2.0 * v.abs();
            value *= v;
            if v == 0.0 {
                zeros += 1;
                zero_d = d;
            } else {
                product *= v.abs();
                ratio += d / v.abs();
            }
        }
        let carried = match zeros {
            0 => product * ratio,
            1 => zero_d * product,
            _ => 0.0,
        };
        let n = self.factors.len();
        let bound = self.coef.value().abs() * carried + (n as f64 + 2.0) * value.abs();
        (value, bound)
    }

    /// `self · other`, equal bases merged.
    pub(crate) fn times(&self, other: &Term) -> Term {
        let mut factors = self.factors.clone();
        for (b, f) in &other.factors {
            match factors.iter().position(|(a, _)| same_atom(a, b)) {
                Some(k) => {
                    let e = factors[k].1 + f;
                    if e == 0.0 {
                        factors.remove(k);
                    } else {
                        factors[k].1 = e;
                    }
                }
                None => factors.push((b.clone(), *f)),
            }
        }
        Term {
            coef: self.coef.mul(other.coef),
            factors,
        }
    }
}

fn same_atom(a: &Rc<Atom>, b: &Rc<Atom>) -> bool {
    Rc::ptr_eq(a, b) || a == b
}

impl Sum {
    pub(crate) fn from_terms(terms: Vec<Term>) -> Sum {
        let size = terms.iter().fold(1usize, |n, t| n.saturating_add(t.size()));
        let depth = terms.iter().map(Term::depth).max().unwrap_or(0);
        let hash = terms.iter().fold(7u64, |h, t| {
            h.wrapping_add(mix2(t.monomial_hash(), t.coef.value().to_bits()))
        });
        Sum {
            terms,
            size,
            depth,
            hash,
        }
    }

    /// The constant `c`.
    pub fn num(c: f64) -> Sum {
        Sum::constant(Coef::of(c))
    }

    /// The constant `c`, a coefficient.
    pub(crate) fn constant(c: Coef) -> Sum {
        if c.is_zero() {
            Sum::from_terms(Vec::new())
        } else {
            Sum::from_terms(vec![Term::constant(c)])
        }
    }

    /// The atom alone.
    pub fn atom(a: Atom) -> Sum {
        Sum::from_terms(vec![Term {
            coef: Coef::ONE,
            factors: vec![(Rc::new(a), 1.0)],
        }])
    }

    /// A term as a sum: a term that is only `c·(a + b)` becomes `c·a + c·b`.
    pub(crate) fn from_term(t: Term) -> Sum {
        if t.coef.is_zero() {
            return Sum::num(0.0);
        }
        if let [(a, e)] = t.factors.as_slice() {
            if let (Atom::Group(inner), 1.0) = (a.as_ref(), *e) {
                return inner.scale(t.coef);
            }
        }
        Sum::from_terms(vec![t])
    }

    /// Whether the sum is `≥ 0` wherever it is defined, by its structure: every coefficient
    /// `≥ 0` and every factor an even power, a real power (defined only where its base is
    /// `≥ 0`, and then `≥ 0`) or a [nonnegative](Atom::nonnegative) atom (`1 + t²`, `eˢ·√x`).
    pub fn nonnegative(&self) -> bool {
        self.terms.iter().all(|t| {
            t.coef.value() >= 0.0
                && t.factors.iter().all(|(a, e)| {
                    (e.fract() == 0.0 && e % 2.0 == 0.0) || e.fract() != 0.0 || a.nonnegative()
                })
        })
    }

    /// Whether the sum is a rational function of its variables: only variables and groups
    /// of such sums as factors, integer exponents.
    pub fn is_rational(&self) -> bool {
        self.terms.iter().all(|t| {
            t.factors.iter().all(|(a, e)| {
                e.fract() == 0.0
                    && match a.as_ref() {
                        Atom::Var(_) => true,
                        Atom::Group(s) => s.is_rational(),
                        _ => false,
                    }
            })
        })
    }

    /// The number of nodes written out as a tree.
    pub fn size(&self) -> usize {
        self.size
    }

    /// The nesting depth.
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// The constant this sum is, if it is one.
    pub fn as_constant(&self) -> Option<f64> {
        self.as_coef().map(Coef::value)
    }

    /// The constant this sum is, as a coefficient, if it is one.
    pub(crate) fn as_coef(&self) -> Option<Coef> {
        match self.terms.as_slice() {
            [] => Some(Coef::of(0.0)),
            [t] if t.factors.is_empty() => Some(t.coef),
            _ => None,
        }
    }

    /// The value with the variables set to `values` (in the trace's order; a missing one is
    /// NaN).
    pub fn eval(&self, values: &[f64]) -> f64 {
        self.terms.iter().map(|t| t.eval(values)).sum()
    }

    /// The value at `values` and a first-order bound of its rounding error in units of `ε`:
    /// the terms' bounds plus one rounding of the running sum per term.
    pub(crate) fn eval_bound(&self, values: &[f64]) -> (f64, f64) {
        let mut value = 0.0;
        let (mut bound, mut size) = (0.0, 0.0);
        for t in &self.terms {
            let (v, e) = t.eval_bound(values);
            value += v;
            bound += e;
            size += v.abs();
        }
        (value, bound + self.terms.len() as f64 * size)
    }

    fn scale(&self, c: Coef) -> Sum {
        if c.value() == 1.0 {
            return self.clone();
        }
        Sum::from_terms(
            self.terms
                .iter()
                .map(|t| Term {
                    coef: t.coef.mul(c),
                    factors: t.factors.clone(),
                })
                .filter(|t| !t.coef.is_zero())
                .collect(),
        )
    }

    /// `a + b`, like terms collected.
    pub fn add(a: &Sum, b: &Sum) -> Sum {
        if b.terms.is_empty() {
            return a.clone();
        }
        if a.terms.is_empty() {
            return b.clone();
        }
        Sum::collect(a.terms.iter().chain(&b.terms).cloned())
    }

    /// The sum of `terms`, like terms collected (found through their monomial hash, then
    /// compared, so collecting is linear in the number of terms), zero terms dropped; the
    /// first occurrence of each keeps its place.
    fn collect(terms: impl Iterator<Item = Term>) -> Sum {
        let mut out: Vec<Term> = Vec::new();
        let mut index: FastMap<u64, Vec<usize>> = FastMap::default();
        for t in terms {
            let slot = index.entry(t.monomial_hash()).or_default();
            match slot.iter().copied().find(|&k| out[k].like(&t)) {
                Some(k) => out[k].coef = out[k].coef.add(t.coef),
                None => {
                    slot.push(out.len());
                    out.push(t);
                }
            }
        }
        out.retain(|t| !t.coef.is_zero());
        if let Some(fewer) = pythagoras(&out) {
            // an identity merged two terms: the result may be like another term
            return Sum::collect(fewer.into_iter());
        }
        Sum::from_terms(out)
    }

    /// This sum with every coefficient within a few units in the last place of a simple
    /// fraction (denominator ≤ 64) set to it, every term whose coefficient is rounding
    /// residue beside the others' (below `64 ε` of the largest) dropped — inside functions
    /// and groups too — and a sum that is only a constant of at most `floor` (the rounding of
    /// the traced computation that cancelled to it) made `0`. Whether the result still gives the traced value is for the capture
    /// check to say ([`crate::symbolic::Formula`] keeps the unrounded form if not).
    /// This sum with, from the inside out, every sum whose terms have denominators that are
    /// powers of one atom `D` written over `D` — where that makes it smaller: the numerator
    /// is collected (like terms, the Pythagorean identities) and, for a sum `D`, multiplied
    /// out, so `2 − 2·sinh²/cosh² = 2/cosh²` and `1/2 + x/(8·(1 − x/4)) = 1/(2·(1 − x/4))`.
    /// Equal as functions wherever the original is defined (the capture check confirms it
    /// at the trace point).
    pub(crate) fn combined(&self) -> Sum {
        if !self.has_denominator() {
            return self.clone();
        }
        // the terms rebuilt as products of their combined factors (a group that became one
        // term is multiplied in)
        let mut inner = Sum::num(0.0);
        for t in &self.terms {
            let t = quotients(t);
            let mut product = Sum::constant(t.coef);
            for (a, e) in &t.factors {
                let factor = match a.combined() {
                    Atom::Group(g) => Sum::powf(&g, *e),
                    other => Sum::from_term(Term {
                        coef: Coef::ONE,
                        factors: vec![(Rc::new(other), *e)],
                    }),
                };
                product = Sum::mul(&product, &factor);
            }
            inner = Sum::add(&inner, &product);
        }
        if inner.terms.len() < 2 || inner.size > 4096 {
            return inner;
        }
        let mut best = inner.clone();
        let mut dens: Vec<Rc<Atom>> = Vec::new();
        for t in &inner.terms {
            for (a, e) in &t.factors {
                if *e < 0.0 && !dens.iter().any(|d| same_atom(d, a)) {
                    dens.push(a.clone());
                }
            }
        }
        for d in dens.iter().take(4) {
            let k = inner
                .terms
                .iter()
                .flat_map(|t| t.factors.iter())
                .filter(|(a, _)| same_atom(a, d))
                .map(|(_, e)| -e)
                .fold(0.0, f64::max);
            // every term's power of D lifted by k must be a whole power (√D·D^(−3/2) = 1/D, but
            // a term without D cannot take a half power)
            let power_of = |t: &Term| {
                t.factors
                    .iter()
                    .find(|(a, _)| same_atom(a, d))
                    .map_or(0.0, |(_, e)| *e)
            };
            let whole = inner.terms.iter().all(|t| {
                let lifted = power_of(t) + k;
                lifted >= 0.0 && lifted.fract() == 0.0
            });
            if k <= 0.0 || k > 16.0 || !whole {
                continue;
            }
            let lift = Term {
                coef: Coef::ONE,
                factors: vec![(d.clone(), k)],
            };
            let lifted = inner.terms.iter().map(|t| Sum::from_term(t.times(&lift)));
            let mut numerator = Sum::num(0.0);
            for part in lifted {
                numerator = Sum::add(&numerator, &part);
            }
            // multiplied out, so that terms can cancel and identities meet
            match numerator.expanded() {
                Some(n) if n.size <= 4 * inner.size => numerator = n,
                _ => {
                    if matches!(d.as_ref(), Atom::Group(_)) {
                        continue;
                    }
                }
            }
            let over = Term {
                coef: Coef::ONE,
                factors: vec![(d.clone(), -k)],
            };
            let candidate = Sum::mul(&numerator, &Sum::from_term(over));
            if candidate.size < best.size {
                best = candidate;
            }
        }
        best
    }

    /// Whether a factor anywhere in it has a negative power (only then can
    /// [`Sum::combined`] change it).
    fn has_denominator(&self) -> bool {
        self.terms.iter().any(|t| {
            t.factors.iter().any(|(a, e)| {
                *e < 0.0
                    || match a.as_ref() {
                        Atom::Var(_) => false,
                        Atom::Func(_, x) | Atom::Group(x) | Atom::Opaque(_, x, _) => {
                            x.has_denominator()
                        }
                        Atom::Pow(x, y) | Atom::Atan2(x, y) => {
                            x.has_denominator() || y.has_denominator()
                        }
                    }
            })
        })
    }

    /// Whether [`Sum::snapped`] would change anything (a read-only scan: most formulas have
    /// nothing to clean, and rebuilding them costs more than looking).
    pub(crate) fn needs_snap(&self, floor: f64) -> bool {
        if self.terms.iter().any(|t| !t.coef.value().is_finite()) {
            return false;
        }
        let largest = self
            .terms
            .iter()
            .map(|t| t.coef.value().abs())
            .fold(0.0, f64::max);
        self.terms.iter().any(|t| {
            let c = t.coef.value();
            (!t.coef.is_exact() && snap(c) != c)
                || (self.terms.len() > 1 && c.abs() <= RESIDUE * largest)
                || (self.terms.len() == 1 && t.factors.is_empty() && c.abs() <= floor)
                || t.factors.iter().any(|(a, _)| a.needs_snap())
        })
    }

    pub(crate) fn snapped(&self, floor: f64) -> Sum {
        if self.terms.iter().any(|t| !t.coef.value().is_finite()) {
            return self.clone();
        }
        let largest = self
            .terms
            .iter()
            .map(|t| t.coef.value().abs())
            .fold(0.0, f64::max);
        let terms: Vec<Term> = self
            .terms
            .iter()
            .filter(|t| self.terms.len() == 1 || t.coef.value().abs() > RESIDUE * largest)
            .filter(|t| {
                self.terms.len() > 1 || !t.factors.is_empty() || t.coef.value().abs() > floor
            })
            .map(|t| Term {
                coef: if t.coef.is_exact() {
                    t.coef
                } else {
                    Coef::of(snap(t.coef.value()))
                },
                factors: t
                    .factors
                    .iter()
                    .map(|(a, e)| (Rc::new(a.snapped()), *e))
                    .collect(),
            })
            .collect();
        Sum::collect(terms.into_iter())
    }

    /// `−a`.
    pub fn neg(a: &Sum) -> Sum {
        a.scale(Coef::of(-1.0))
    }

    /// This sum as one term: itself if it has one term, else a group (its sign out when every
    /// term is negative).
    fn as_term(&self) -> Term {
        match self.terms.as_slice() {
            [] => Term::constant(Coef::of(0.0)),
            [t] => t.clone(),
            terms => {
                let sign = Coef::of(if terms.iter().all(|t| t.coef.value() < 0.0) {
                    -1.0
                } else {
                    1.0
                });
                Term {
                    coef: sign,
                    factors: vec![(Rc::new(Atom::Group(self.scale(sign))), 1.0)],
                }
            }
        }
    }

    /// `a · b`: constants multiply into sums, other sums are kept whole.
    pub fn mul(a: &Sum, b: &Sum) -> Sum {
        match (a.as_coef(), b.as_coef()) {
            (Some(x), _) => b.scale(x),
            (_, Some(y)) => a.scale(y),
            _ => Sum::from_term(a.as_term().times(&b.as_term())),
        }
    }

    /// `aⁿ`.
    pub fn powi(a: &Sum, n: i32) -> Sum {
        match n {
            0 => return Sum::num(1.0),
            1 => return a.clone(),
            _ => {}
        }
        if let Some(c) = a.as_coef() {
            return Sum::constant(c.powi(n));
        }
        let t = a.as_term();
        let e = f64::from(n);
        Sum::from_term(Term {
            coef: t.coef.powi(n),
            factors: t.factors.iter().map(|(b, f)| (b.clone(), f * e)).collect(),
        })
    }

    /// `aᵖ` for a real `p`.
    pub fn powf(a: &Sum, p: f64) -> Sum {
        if p.fract() == 0.0 && p.abs() <= i32::MAX as f64 {
            return Sum::powi(a, p as i32);
        }
        if let Some(c) = a.as_constant() {
            return Sum::num(c.powf(p));
        }
        if let [t] = a.terms.as_slice() {
            // (c·x·y)ᵖ = cᵖ·xᵖ·yᵖ for c > 0 and bases that are ≥ 0 wherever defined: for a
            // base that can be negative the right side is undefined where the
            // left is not (√(s·t) at s = t = −1 is 1, √s·√t is not real); and (c·xᵃ)ᵖ =
            // cᵖ·xᵃᵖ for one base with an odd integer exponent (xᵃ and x have one sign, so
            // both sides are undefined for x < 0: √(1/x) = x^(−1/2))
            let odd = |e: f64| e.fract() == 0.0 && e % 2.0 != 0.0;
            let single_odd = matches!(t.factors.as_slice(), [(_, e)] if odd(*e));
            if t.coef.value() > 0.0
                && (single_odd || t.factors.iter().all(|(a, _)| a.nonnegative()))
            {
                return Sum::from_term(Term {
                    coef: Coef::of(t.coef.value().powf(p)),
                    factors: t.factors.iter().map(|(b, e)| (b.clone(), e * p)).collect(),
                });
            }
        }
        Sum::from_term(Term {
            coef: Coef::ONE,
            factors: vec![(Rc::new(Atom::Group(a.clone())), p)],
        })
    }

    /// `aᵇ`.
    pub fn pow(a: &Sum, b: &Sum) -> Sum {
        match b.as_constant() {
            Some(y) => Sum::powf(a, y),
            None => Sum::atom(Atom::Pow(a.clone(), b.clone())),
        }
    }

    /// `f(a)` (`sqrt` as the power ½).
    pub fn apply(f: Func, a: &Sum) -> Sum {
        if let Some(c) = a.as_constant() {
            return Sum::num(f.apply(c));
        }
        if f == Func::Sqrt {
            return Sum::powf(a, 0.5);
        }
        Sum::atom(Atom::Func(f, a.clone()))
    }

    /// `atan2(a, b)`.
    pub fn atan2(a: &Sum, b: &Sum) -> Sum {
        match (a.as_constant(), b.as_constant()) {
            (Some(x), Some(y)) => Sum::num(x.atan2(y)),
            _ => Sum::atom(Atom::Atan2(a.clone(), b.clone())),
        }
    }

    /// This sum with every product of sums multiplied out and every positive integer power
    /// of a sum expanded (inside functions and denominators too); `None` if a sum on the way
    /// would exceed [`MAX_EXPANDED_TERMS`] terms or [`MAX_FORMULA_SIZE`] nodes.
    pub fn expanded(&self) -> Option<Sum> {
        let mut all: Vec<Term> = Vec::new();
        for t in &self.terms {
            let mut product = Sum::constant(t.coef);
            for (a, e) in &t.factors {
                let inner = a.expanded()?;
                let factor = match (&inner, *e) {
                    (Atom::Group(s), e) if e > 0.0 && e.fract() == 0.0 => {
                        // a sum of two or more terms to a power e has more than e terms
                        // in general: refused before any work beyond the limit
                        if e > MAX_EXPANDED_TERMS as f64 {
                            return None;
                        }
                        let mut p = Sum::num(1.0);
                        for _ in 0..(e as u64) {
                            p = Sum::multiply_out(&p, s)?;
                        }
                        p
                    }
                    (Atom::Group(s), e) => Sum::powf(s, e),
                    (atom, e) => Sum::from_term(Term {
                        coef: Coef::ONE,
                        factors: vec![(Rc::new(atom.clone()), e)],
                    }),
                };
                product = Sum::multiply_out(&product, &factor)?;
            }
            all.extend(product.terms);
            if all.len() > MAX_EXPANDED_TERMS.saturating_mul(4) {
                return None;
            }
        }
        let mut out = Sum::collect(all.into_iter());
        if out.size > MAX_FORMULA_SIZE || out.terms.len() > MAX_EXPANDED_TERMS {
            return None;
        }
        // a monomial's variables in the trace's order (`s^2*t`, not `t*s^2`)
        for t in &mut out.terms {
            t.factors.sort_by_key(|(a, _)| match a.as_ref() {
                Atom::Var(i) => *i,
                _ => u32::MAX,
            });
        }
        Some(out)
    }

    /// This sum over one common denominator, when every denominator among its terms is a
    /// power of one and the same group `D` — a rational function and its derivatives:
    /// `N′/D − N·D′/D²` becomes `(N′·D − N·D′)/D²`, the numerator multiplied out. `None` when
    /// no term has a denominator, when there are several different ones, or beyond
    /// [`MAX_EXPANDED_TERMS`].
    pub fn over_common_denominator(&self) -> Option<Sum> {
        let is_den = |(a, e): &(Rc<Atom>, f64)| *e < 0.0 && matches!(a.as_ref(), Atom::Group(_));
        let mut den: Option<Rc<Atom>> = None;
        let mut highest = 0.0f64;
        let mut parts: Vec<(Term, f64)> = Vec::with_capacity(self.terms.len());
        for t in &self.terms {
            let mut rest = t.clone();
            let mut k = 0.0;
            let mut found = t.factors.iter().enumerate().filter(|(_, f)| is_den(f));
            if let Some((pos, (a, e))) = found.next() {
                if found.next().is_some() || e.fract() != 0.0 {
                    return None;
                }
                match &den {
                    None => den = Some(a.clone()),
                    Some(d) if same_atom(d, a) => {}
                    Some(_) => return None,
                }
                k = -e;
                rest.factors.remove(pos);
            }
            highest = highest.max(k);
            parts.push((rest, k));
        }
        let d = den?;
        let Atom::Group(inner) = d.as_ref() else {
            return None;
        };
        if highest > MAX_EXPANDED_TERMS as f64 {
            return None;
        }
        // the powers D⁰ … D^K, multiplied out once each
        let mut powers = vec![Sum::num(1.0)];
        for _ in 0..highest as usize {
            let next = Sum::multiply_out(powers.last()?, inner)?;
            powers.push(next);
        }
        let mut numerator: Vec<Term> = Vec::new();
        for (rest, k) in parts {
            let product = Sum::multiply_out(
                &Sum::from_terms(vec![rest]),
                &powers[(highest - k) as usize],
            )?;
            numerator.extend(product.terms);
            if numerator.len() > MAX_EXPANDED_TERMS.saturating_mul(4) {
                return None;
            }
        }
        let numerator = Sum::collect(numerator.into_iter());
        if numerator.terms.len() > MAX_EXPANDED_TERMS {
            return None;
        }
        let over = Term {
            coef: Coef::ONE,
            factors: vec![(d.clone(), -highest)],
        };
        Some(Sum::mul(&numerator, &Sum::from_term(over)))
    }

    /// `a · b` with both multiplied out term by term (`None` beyond
    /// [`MAX_EXPANDED_TERMS`] products).
    fn multiply_out(a: &Sum, b: &Sum) -> Option<Sum> {
        if a.terms.len().saturating_mul(b.terms.len()) > MAX_EXPANDED_TERMS.saturating_mul(4)
            || a.size.saturating_mul(b.size) > MAX_FORMULA_SIZE.saturating_mul(4)
        {
            return None;
        }
        // a product whose only factor is a group again (x·x⁻¹·(…)) is unwrapped
        let products = a.terms.iter().flat_map(|x| {
            b.terms
                .iter()
                .flat_map(move |y| Sum::from_term(x.times(y)).terms)
        });
        let out = Sum::collect(products);
        (out.terms.len() <= MAX_EXPANDED_TERMS).then_some(out)
    }
}

/// `t` with `sinᵉu·cos⁻ᵉu` written `tanᵉu` and `sinhᵉu·cosh⁻ᵉu` written `tanhᵉu` (equal
/// wherever the left side is defined).
fn quotients(t: &Term) -> Term {
    let mut out = t.clone();
    for (num, den, quotient) in [
        (Func::Sin, Func::Cos, Func::Tan),
        (Func::Sinh, Func::Cosh, Func::Tanh),
    ] {
        let find = |factors: &[(Rc<Atom>, f64)], f: Func| {
            factors
                .iter()
                .position(|(a, _)| matches!(a.as_ref(), Atom::Func(g, _) if *g == f))
        };
        let (Some(i), Some(j)) = (find(&out.factors, num), find(&out.factors, den)) else {
            continue;
        };
        let (Atom::Func(_, u), Atom::Func(_, v)) =
            (out.factors[i].0.as_ref(), out.factors[j].0.as_ref())
        else {
            continue;
        };
        let (e, f) = (out.factors[i].1, out.factors[j].1);
        if u != v || e <= 0.0 || f != -e {
            continue;
        }
        let tan = Rc::new(Atom::Func(quotient, u.clone()));
        out.factors[i] = (tan, e);
        out.factors.remove(j);
    }
    out
}

/// A coefficient below this fraction of the largest in its sum is rounding residue.
const RESIDUE: f64 = 64.0 * f64::EPSILON;

/// The most units in the last place a coefficient may be from a simple fraction to be set to
/// it.
const SNAP_ULPS: f64 = 32.0;

/// `c`, or the fraction `p/q` (`q ≤ 64`, `|p| < 10¹⁵`) within [`SNAP_ULPS`] of it.
fn snap(c: f64) -> f64 {
    if !c.is_finite() || c == 0.0 || c.fract() == 0.0 {
        return c;
    }
    let ulp = f64::EPSILON * c.abs();
    for q in 1..=64u32 {
        let p = (c * f64::from(q)).round();
        if p.abs() >= 1e15 {
            break;
        }
        let r = p / f64::from(q);
        if (r - c).abs() <= SNAP_ULPS * ulp {
            return r;
        }
    }
    c
}

/// The partner of `sin²`, `cos²`, `cosh²`, `sinh²` in a Pythagorean identity and the ratio of
/// coefficients it needs: `sin² + cos² = 1`, `cosh² − sinh² = 1`.
fn partner(f: Func) -> Option<(Func, f64)> {
    match f {
        Func::Sin => Some((Func::Cos, 1.0)),
        Func::Cos => Some((Func::Sin, 1.0)),
        Func::Cosh => Some((Func::Sinh, -1.0)),
        Func::Sinh => Some((Func::Cosh, -1.0)),
        _ => None,
    }
}

/// The terms with one Pythagorean pair merged (`c·R·sin²u + c·R·cos²u = c·R`,
/// `c·R·cosh²u − c·R·sinh²u = c·R`, the squares taken out of higher powers too:
/// `2 sinh u cosh²u − 2 sinh³u = 2 sinh u`), or `None` if there is none. Only equal rests `R`
/// and matching coefficients: an identity, never an approximation.
fn pythagoras(terms: &[Term]) -> Option<Vec<Term>> {
    // a factor sin(u)ᵉ with an integer e ≥ 2 holds the square sin²u (the rest keeps sinᵉ⁻²u)
    let square = |t: &Term, k: usize| match &t.factors[k] {
        (a, e) if *e >= 2.0 && e.fract() == 0.0 => match a.as_ref() {
            Atom::Func(f, u) => partner(*f).map(|p| (*f, p, u.clone())),
            _ => None,
        },
        _ => None,
    };
    let rest = |t: &Term, k: usize| {
        let mut r = t.clone();
        if r.factors[k].1 == 2.0 {
            r.factors.remove(k);
        } else {
            r.factors[k].1 -= 2.0;
        }
        r
    };
    let candidates: Vec<(usize, usize)> = terms
        .iter()
        .enumerate()
        .flat_map(|(i, t)| (0..t.factors.len()).map(move |k| (i, k)))
        .filter(|&(i, k)| square(&terms[i], k).is_some())
        .collect();
    for &(i, k) in &candidates {
        let Some((f, (g, ratio), u)) = square(&terms[i], k) else {
            continue;
        };
        let ri = rest(&terms[i], k);
        for &(j, l) in &candidates {
            if j == i {
                continue;
            }
            let Some((h, _, v)) = square(&terms[j], l) else {
                continue;
            };
            if h != g || v != u || terms[j].coef.value() != ratio * terms[i].coef.value() {
                continue;
            }
            let rj = rest(&terms[j], l);
            if !ri.like(&rj) {
                continue;
            }
            // sin² and cos² (or cosh² and −sinh²): the pair is the rest times the first's
            // coefficient; for sinh² first (c·sinh² − c·cosh²) it is −c
            let coef = if f == Func::Sinh {
                terms[i].coef.neg()
            } else {
                terms[i].coef
            };
            let mut out: Vec<Term> = Vec::with_capacity(terms.len() - 1);
            for (m, t) in terms.iter().enumerate() {
                if m == i {
                    out.push(Term {
                        coef,
                        factors: ri.factors.clone(),
                    });
                } else if m != j {
                    out.push(t.clone());
                }
            }
            return Some(out);
        }
    }
    None
}

impl Atom {
    /// The atom with its sums [combined](Sum::combined).
    fn combined(&self) -> Atom {
        match self {
            Atom::Var(i) => Atom::Var(*i),
            Atom::Func(f, a) => Atom::Func(*f, a.combined()),
            Atom::Group(a) => Atom::Group(a.combined()),
            Atom::Pow(a, b) => Atom::Pow(a.combined(), b.combined()),
            Atom::Atan2(a, b) => Atom::Atan2(a.combined(), b.combined()),
            Atom::Opaque(w, a, v) => Atom::Opaque(w, a.combined(), *v),
        }
    }

    /// Whether any of its sums [needs snapping](Sum::needs_snap).
    fn needs_snap(&self) -> bool {
        match self {
            Atom::Var(_) => false,
            Atom::Func(_, a) | Atom::Group(a) | Atom::Opaque(_, a, _) => a.needs_snap(0.0),
            Atom::Pow(a, b) | Atom::Atan2(a, b) => a.needs_snap(0.0) || b.needs_snap(0.0),
        }
    }

    /// The atom with its sums [snapped](Sum::snapped).
    fn snapped(&self) -> Atom {
        match self {
            Atom::Var(i) => Atom::Var(*i),
            Atom::Func(f, a) => Atom::Func(*f, a.snapped(0.0)),
            Atom::Group(a) => Atom::Group(a.snapped(0.0)),
            Atom::Pow(a, b) => Atom::Pow(a.snapped(0.0), b.snapped(0.0)),
            Atom::Atan2(a, b) => Atom::Atan2(a.snapped(0.0), b.snapped(0.0)),
            Atom::Opaque(w, a, v) => Atom::Opaque(w, a.snapped(0.0), *v),
        }
    }

    fn expanded(&self) -> Option<Atom> {
        Some(match self {
            Atom::Var(i) => Atom::Var(*i),
            Atom::Func(f, a) => Atom::Func(*f, a.expanded()?),
            Atom::Group(a) => Atom::Group(a.expanded()?),
            Atom::Pow(a, b) => Atom::Pow(a.expanded()?, b.expanded()?),
            Atom::Atan2(a, b) => Atom::Atan2(a.expanded()?, b.expanded()?),
            Atom::Opaque(w, a, v) => Atom::Opaque(w, a.expanded()?, *v),
        })
    }
}
