//! The symbolic expression type (src/symbolic): formulas traced through the library's own
//! generic surface code, checked against the hyper-dual values they came from, against an
//! independent parser of their printed text, and against bad input.

use nalgebra::Vector3;
use num_dual::DualNum;
use num_traits::Signed;
use proptest::prelude::*;
use splinelab::symbolic::{number, surface_formulas, Expr, Trace, MAX_NODES};
use splinelab::{Error, ParametricSurface, Sphere, SurfaceDerivatives, Torus};

/// `|a − b| ≤ 1e-12 · max(1, |b|)`.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

/// A second evaluator: a recursive-descent parser of the plain text, evaluating as it reads.
struct Parser<'a> {
    s: &'a [u8],
    i: usize,
    vars: &'a [(&'a str, f64)],
}

impl Parser<'_> {
    fn peek(&mut self) -> Option<u8> {
        while self.i < self.s.len() && self.s[self.i] == b' ' {
            self.i += 1;
        }
        self.s.get(self.i).copied()
    }
    fn expr(&mut self) -> f64 {
        let mut v = self.term();
        while let Some(c) = self.peek() {
            match c {
                b'+' => {
                    self.i += 1;
                    v += self.term();
                }
                b'-' => {
                    self.i += 1;
                    v -= self.term();
                }
                _ => break,
            }
        }
        v
    }
    fn term(&mut self) -> f64 {
        let mut v = self.unary();
        while let Some(c) = self.peek() {
            match c {
                b'*' => {
                    self.i += 1;
                    v *= self.unary();
                }
                b'/' => {
                    self.i += 1;
                    v /= self.unary();
                }
                _ => break,
            }
        }
        v
    }
    fn unary(&mut self) -> f64 {
        if self.peek() == Some(b'-') {
            self.i += 1;
            return -self.unary();
        }
        self.power()
    }
    fn power(&mut self) -> f64 {
        let base = self.atom();
        if self.peek() == Some(b'^') {
            self.i += 1;
            let e = self.atom();
            return base.powf(e);
        }
        base
    }
    fn atom(&mut self) -> f64 {
        match self.peek() {
            Some(b'(') => {
                self.i += 1;
                let v = self.expr();
                assert_eq!(self.peek(), Some(b')'));
                self.i += 1;
                v
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                let start = self.i;
                while self.i < self.s.len()
                    && (self.s[self.i].is_ascii_digit()
                        || matches!(self.s[self.i], b'.' | b'e' | b'E')
                        || (matches!(self.s[self.i], b'-' | b'+')
                            && matches!(self.s[self.i - 1], b'e' | b'E')))
                {
                    self.i += 1;
                }
                std::str::from_utf8(&self.s[start..self.i])
                    .unwrap()
                    .parse()
                    .unwrap()
            }
            Some(_) => {
                let start = self.i;
                while self.i < self.s.len() && (self.s[self.i].is_ascii_alphanumeric()) {
                    self.i += 1;
                }
                let name = std::str::from_utf8(&self.s[start..self.i]).unwrap();
                if self.peek() == Some(b'(') {
                    self.i += 1;
                    let a = self.expr();
                    let b = if self.peek() == Some(b',') {
                        self.i += 1;
                        Some(self.expr())
                    } else {
                        None
                    };
                    assert_eq!(self.peek(), Some(b')'));
                    self.i += 1;
                    return match (name, b) {
                        ("atan2", Some(b)) => a.atan2(b),
                        ("sin", _) => a.sin(),
                        ("cos", _) => a.cos(),
                        ("tan", _) => a.tan(),
                        ("exp", _) => a.exp(),
                        ("ln", _) => a.ln(),
                        ("sqrt", _) => a.sqrt(),
                        ("atan", _) => a.atan(),
                        ("tanh", _) => a.tanh(),
                        ("sinh", _) => a.sinh(),
                        ("cosh", _) => a.cosh(),
                        ("asin", _) => a.asin(),
                        ("acos", _) => a.acos(),
                        ("asinh", _) => a.asinh(),
                        ("acosh", _) => a.acosh(),
                        ("atanh", _) => a.atanh(),
                        ("cbrt", _) => a.cbrt(),
                        ("abs", _) => a.abs(),
                        (other, _) => panic!("unknown function {other}"),
                    };
                }
                self.vars
                    .iter()
                    .find(|v| v.0 == name)
                    .unwrap_or_else(|| panic!("unknown name {name}"))
                    .1
            }
            None => panic!("unexpected end"),
        }
    }
}

fn parse_eval(text: &str, vars: &[(&str, f64)]) -> f64 {
    let mut p = Parser {
        s: text.as_bytes(),
        i: 0,
        vars,
    };
    let v = p.expr();
    assert_eq!(p.peek(), None, "trailing text in {text:?}");
    v
}

fn check_surface<S: ParametricSurface + SurfaceDerivatives>(surface: &S, s: f64, t: f64) {
    let f = surface_formulas(surface, s, t).unwrap();
    let d = surface.partials(s, t);
    let parts = [
        (&f.point, d.point),
        (&f.ds, d.ds),
        (&f.dt, d.dt),
        (&f.dst, d.dst),
    ];
    for (formulas, values) in parts {
        for k in 0..3 {
            let v = formulas[k].eval(&[s, t]);
            assert!(
                close(v, values[k]),
                "{}: {v} vs {}",
                formulas[k].plain(),
                values[k]
            );
            let text = formulas[k].plain();
            let parsed = parse_eval(&text, &[("s", s), ("t", t)]);
            assert!(
                close(parsed, values[k]),
                "{text}: parsed {parsed} vs {}",
                values[k]
            );
        }
    }
}

#[test]
fn torus_partials_are_codice_3s_formulas() {
    let torus = Torus::new(2.0, 1.0);
    let f = surface_formulas(&torus, 0.3, 0.7).unwrap();
    let texts: Vec<[String; 3]> = [&f.point, &f.ds, &f.dt, &f.dst]
        .iter()
        .map(|p| [p[0].plain(), p[1].plain(), p[2].plain()])
        .collect();
    // Codice 3's closed forms (seed 000 §2), as the same eval that computes the numbers
    // traced them; every one is also checked by evaluation below
    let expected = [
        ["(cos(t) + 2)*cos(s)", "(cos(t) + 2)*sin(s)", "sin(t)"],
        ["-sin(s)*(cos(t) + 2)", "cos(s)*(cos(t) + 2)", "0"],
        ["-sin(t)*cos(s)", "-sin(t)*sin(s)", "cos(t)"],
        ["sin(s)*sin(t)", "-cos(s)*sin(t)", "0"],
    ];
    for (got, want) in texts.iter().zip(expected) {
        assert_eq!(got, &want.map(String::from));
    }
    for (s, t) in [(0.3, 0.7), (2.0, -1.0), (5.5, 3.1)] {
        check_surface(&torus, s, t);
        // the formulas traced at one point hold at every other
        let d = torus.partials(s + 1.0, t - 0.5);
        assert!(close(f.ds[0].eval(&[s + 1.0, t - 0.5]), d.ds.x));
        assert!(close(f.dst[1].eval(&[s + 1.0, t - 0.5]), d.dst.y));
    }
    check_surface(&Sphere::new(1.5), 0.4, 1.1);
}

/// A random surface: three expression trees in `s` and `t` built from the supported
/// operations, evaluated generically.
#[derive(Debug, Clone)]
enum Tree {
    S,
    T,
    C(f64),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    Sin(Box<Tree>),
    Cos(Box<Tree>),
    Exp(Box<Tree>),
    /// `sqrt(1 + x²)`: defined everywhere
    Hyp(Box<Tree>),
    Atan(Box<Tree>),
    Tanh(Box<Tree>),
    Powi(Box<Tree>, i32),
}

impl Tree {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> D {
        match self {
            Tree::S => s,
            Tree::T => t,
            Tree::C(c) => D::from(*c),
            Tree::Add(a, b) => a.eval(s, t) + b.eval(s, t),
            Tree::Sub(a, b) => a.eval(s, t) - b.eval(s, t),
            Tree::Mul(a, b) => a.eval(s, t) * b.eval(s, t),
            // 2 + sin²: never zero
            Tree::Div(a, b) => {
                let d = b.eval(s, t).sin();
                a.eval(s, t) / (d * d + 2.0)
            }
            Tree::Sin(a) => a.eval(s, t).sin(),
            Tree::Cos(a) => a.eval(s, t).cos(),
            Tree::Exp(a) => (a.eval(s, t).sin()).exp(),
            Tree::Hyp(a) => {
                let x = a.eval(s, t);
                (x * x + 1.0).sqrt()
            }
            Tree::Atan(a) => a.eval(s, t).atan(),
            Tree::Tanh(a) => a.eval(s, t).tanh(),
            Tree::Powi(a, n) => a.eval(s, t).powi(*n),
        }
    }
}

struct Random([Tree; 3]);

impl ParametricSurface for Random {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        Vector3::new(
            self.0[0].eval(s, t),
            self.0[1].eval(s, t),
            self.0[2].eval(s, t),
        )
    }
}

fn tree() -> impl Strategy<Value = Tree> {
    let leaf = prop_oneof![
        Just(Tree::S),
        Just(Tree::T),
        (-3i32..=3).prop_map(|k| Tree::C(k as f64 / 2.0)),
    ];
    leaf.prop_recursive(4, 24, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Add(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Sub(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Mul(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Div(Box::new(a), Box::new(b))),
            inner.clone().prop_map(|a| Tree::Sin(Box::new(a))),
            inner.clone().prop_map(|a| Tree::Cos(Box::new(a))),
            inner.clone().prop_map(|a| Tree::Exp(Box::new(a))),
            inner.clone().prop_map(|a| Tree::Hyp(Box::new(a))),
            inner.clone().prop_map(|a| Tree::Atan(Box::new(a))),
            inner.clone().prop_map(|a| Tree::Tanh(Box::new(a))),
            (inner, 0i32..=3).prop_map(|(a, n)| Tree::Powi(Box::new(a), n)),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Every formula of a random surface equals the hyper-dual value at the trace point and
    /// at another point, and its printed text, parsed back independently, does too.
    #[test]
    fn random_surfaces_formulas_equal_their_values(
        x in tree(), y in tree(), z in tree(),
        s in -2.0f64..2.0, t in -2.0f64..2.0,
    ) {
        let surface = Random([x, y, z]);
        let f = surface_formulas(&surface, s, t).unwrap();
        for (s2, t2) in [(s, t), (s * 0.5 + 0.3, t * 0.7 - 0.2)] {
            let d = surface.partials(s2, t2);
            let parts = [(&f.point, d.point), (&f.ds, d.ds), (&f.dt, d.dt), (&f.dst, d.dst)];
            for (formulas, values) in parts {
                for k in 0..3 {
                    let v = formulas[k].eval(&[s2, t2]);
                    let scale = values[k].abs().max(1.0);
                    prop_assert!((v - values[k]).abs() <= 1e-10 * scale, "{}: {} vs {}", formulas[k].plain(), v, values[k]);
                    let parsed = parse_eval(&formulas[k].plain(), &[("s", s2), ("t", t2)]);
                    prop_assert!((parsed - values[k]).abs() <= 1e-10 * scale, "{} parsed: {} vs {}", formulas[k].plain(), parsed, values[k]);
                }
            }
        }
    }
}

#[test]
fn numbers_print_as_fractions_or_shortest_decimals() {
    assert_eq!(number(0.25), "1/4");
    assert_eq!(number(-0.5), "-1/2");
    assert_eq!(number(1.0 / 3.0), "1/3");
    assert_eq!(number(3.0), "3");
    assert_eq!(number(0.1), "1/10");
    assert_eq!(number(0.123456789), "0.123456789");
    assert_eq!(number(f64::NAN), "NaN");
}

#[test]
fn branches_are_recorded_and_stale_handles_refused() {
    let mut trace = Trace::new();
    let s = trace.var("s", -0.5);
    let a = s.abs();
    let f = trace.formula(&a).unwrap();
    assert_eq!(f.plain(), "abs(s)");
    assert_eq!(trace.branches(), vec!["s < 0".to_string()]);
    let r = s % 0.3;
    assert!(trace.formula(&r).unwrap().plain().starts_with("rem["));
    drop(trace);
    let trace = Trace::new();
    assert!(matches!(trace.formula(&a), Err(Error::Degenerate { .. })));
    assert!(!a.is_live());
}

#[test]
fn a_trace_beyond_the_node_limit_is_a_typed_error() {
    let mut trace = Trace::new();
    let s = trace.var("s", 0.1);
    let mut e: Expr = s;
    for k in 0..MAX_NODES {
        // distinct nodes: s·k + … never folds
        e += s * (k as f64 + 2.0);
    }
    assert!(matches!(trace.formula(&e), Err(Error::TooLarge { .. })));
    assert!(e.value().is_finite());
    // printing an overflowed expression terminates and says so
    assert!(format!("{e}").contains("<expression too large>"));
}
