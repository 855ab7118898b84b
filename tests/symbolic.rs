//! The symbolic expression type (src/symbolic): formulas traced through the library's own
//! generic surface code, checked against the hyper-dual values they came from, against an
//! independent parser of their printed text, and against bad input.

use nalgebra::Vector3;
use num_dual::DualNum;
use num_traits::Signed;
use proptest::prelude::*;
use splinelab::symbolic::{
    bernstein_formulas, bspline_basis_formulas, curve_formulas, hermite_basis_formulas, number,
    patch_formulas, surface_formulas, trace, Expr, Trace, MAX_FORMULA_DEPTH, MAX_NODES,
};
use splinelab::{
    BSplineBasis, BSplineCurve, Error, HermitePatch, HermiteSurface, KnotVector, NurbsCurve,
    ParametricCurve, ParametricSurface, Rect, Sphere, SurfaceDerivatives, Torus,
};

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
    // Codice 3's closed forms (seed 000 §2: f_x = (2 + cos(t)).*cos(s), …, and their
    // derivatives), as the same eval that computes the numbers traced them; every one is
    // also checked by evaluation below
    let expected = [
        ["cos(s)*(2 + cos(t))", "sin(s)*(2 + cos(t))", "sin(t)"],
        ["-sin(s)*(2 + cos(t))", "cos(s)*(2 + cos(t))", "0"],
        ["-cos(s)*sin(t)", "-sin(s)*sin(t)", "cos(t)"],
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
    /// `a / (b² + 1)`: rational, never divides by zero
    Rat(Box<Tree>, Box<Tree>),
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
            Tree::Rat(a, b) => {
                let d = b.eval(s, t);
                a.eval(s, t) / (d * d + 1.0)
            }
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
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Rat(Box::new(a), Box::new(b))),
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
                    prop_assert!((v - values[k]).abs() <= 1e-12 * scale, "{}: {} vs {}", formulas[k].plain(), v, values[k]);
                    let parsed = parse_eval(&formulas[k].plain(), &[("s", s2), ("t", t2)]);
                    prop_assert!((parsed - values[k]).abs() <= 1e-12 * scale, "{} parsed: {} vs {}", formulas[k].plain(), parsed, values[k]);
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
    assert!(format!("{e}").contains("expression nodes of a trace"));
}

#[test]
fn torus_formulas_print_as_latex_and_well_formed_mathml() {
    let f = surface_formulas(&Torus::new(2.0, 1.0), 0.3, 0.7).unwrap();
    assert_eq!(f.point[0].latex(), "\\cos(s) \\left(2 + \\cos(t)\\right)");
    assert_eq!(f.ds[0].latex(), "-\\sin(s) \\left(2 + \\cos(t)\\right)");
    assert_eq!(f.dst[1].latex(), "-\\cos(s) \\sin(t)");
    for p in [&f.point, &f.ds, &f.dt, &f.dst] {
        for x in p {
            balanced_tags(&x.mathml());
        }
    }
    let table = f.table();
    balanced_tags(&table.html().replace("<p>", "").replace("</p>", ""));
    assert!(table.latex().starts_with("\\begin{array}{llll}"));
}

/// Every MathML tag is closed in order (a minimal well-formedness check).
fn balanced_tags(xml: &str) {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = xml;
    while let Some(start) = rest.find('<') {
        let end = rest[start..].find('>').expect("unclosed tag") + start;
        let tag = &rest[start + 1..end];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name), "in {xml}");
        } else if !tag.ends_with('/') {
            stack.push(tag.split_whitespace().next().unwrap().to_string());
        }
        rest = &rest[end + 1..];
    }
    assert!(stack.is_empty(), "unclosed {stack:?} in {xml}");
}

#[test]
fn the_bases_print_as_the_report_prints_them() {
    let h: Vec<String> = hermite_basis_formulas()
        .unwrap()
        .iter()
        .map(|f| f.plain())
        .collect();
    // seed 000 §1: H₀ = 1 − 3t² + 2t³; H₁ = t − 2t² + t³; H₂ = t³ − t²; H₃ = 3t² − 2t³
    assert_eq!(
        h,
        [
            "1 - 3*t^2 + 2*t^3",
            "t - 2*t^2 + t^3",
            "t^3 - t^2",
            "3*t^2 - 2*t^3"
        ]
    );
    let b: Vec<String> = bernstein_formulas(3)
        .unwrap()
        .iter()
        .map(|f| f.plain())
        .collect();
    // seed 000 §4: B₀ = (1−t)³, B₁ = 3t(1−t)², B₂ = 3t²(1−t), B₃ = t³
    assert_eq!(b, ["(1 - t)^3", "3*t*(1 - t)^2", "3*t^2*(1 - t)", "t^3"]);
    // the Bernstein formulas of degree 7 equal C(7, i) tⁱ (1 − t)⁷⁻ⁱ, expanded too
    let b7 = bernstein_formulas(7).unwrap();
    for (i, f) in b7.iter().enumerate() {
        let binomial = [1.0, 7.0, 21.0, 35.0, 35.0, 21.0, 7.0, 1.0][i];
        for t in [0.1, 0.37, 0.9] {
            let exact = binomial * t.powi(i as i32) * (1.0 - t).powi(7 - i as i32);
            assert!(close(f.eval(&[t]), exact));
            assert!(close(f.expanded().unwrap().eval(&[t]), exact));
        }
    }
    assert!(matches!(
        bernstein_formulas(65),
        Err(Error::TooLarge { .. })
    ));
}

#[test]
fn like_terms_common_factors_and_signs() {
    let out = trace([("x", 0.3), ("y", -1.2)], |[x, y]| {
        vec![
            x * y + y * x * 2.0,                         // 3*x*y
            -(x.sin() * y) - x.sin() * 2.0,              // -sin(x)*(2 + y)
            x * x.powi(-1),                              // 1
            (x + 1.0) * 2.0 - x * 2.0,                   // 2
            (x * x + 1.0).sqrt() * (x * x + 1.0).sqrt(), // 1 + x^2
            x / 4.0 - y * 0.75,                          // x/4 - 3*y/4
            (x * x).sqrt(),                              // sqrt(x^2): not x
        ]
    })
    .unwrap();
    let texts: Vec<String> = out.formulas.iter().map(|f| f.plain()).collect();
    assert_eq!(
        texts,
        [
            "3*x*y",
            "-sin(x)*(2 + y)",
            "1",
            "2",
            "1 + x^2",
            "x/4 - 3*y/4",
            "sqrt(x^2)"
        ]
    );
}

#[test]
fn bspline_basis_formulas_hold_on_their_span() {
    // seed 001's quadratic example, and near-coincident knots
    for knots in [
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
        vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5 + 1e-6, 1.0, 1.0, 1.0, 1.0],
    ] {
        let p = if knots.len() == 7 { 2 } else { 3 };
        let basis = BSplineBasis::new(KnotVector::new(knots), p);
        for t0 in [0.1, 0.5, 0.7, 1.0] {
            let b = bspline_basis_formulas(&basis, t0).unwrap();
            assert!(b.span.contains(t0));
            for k in 0..=4 {
                let t = b.span.lo + (b.span.hi - b.span.lo) * k as f64 / 4.0;
                if !b.span.contains(t) {
                    continue;
                }
                for (j, f) in b.functions.iter().enumerate() {
                    let want = basis.cox_de_boor(b.first + j, p, t);
                    let v = f.eval(&[t]);
                    assert!(
                        (v - want).abs() <= 1e-9,
                        "N_{} at {t}: {} = {v} vs {want}",
                        b.first + j,
                        f.plain()
                    );
                }
            }
        }
    }
    let basis = BSplineBasis::new(KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]), 2);
    let b = bspline_basis_formulas(&basis, 0.6).unwrap();
    assert_eq!(b.span.to_string(), "[0, 1)");
    let texts: Vec<String> = b.functions.iter().map(|f| f.plain()).collect();
    assert_eq!(texts, ["1 - 2*t + t^2", "2*t - 3*t^2/2", "t^2/2"]);
    assert_eq!(
        bspline_basis_formulas(&basis, 2.0)
            .unwrap()
            .span
            .to_string(),
        "[1, 2]"
    );
    assert!(matches!(
        bspline_basis_formulas(&basis, f64::NAN),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn curve_formulas_hold_on_their_piece() {
    use nalgebra::{Vector2, Vector3};
    let circle = NurbsCurve::circle9(Vector2::new(0.5, -1.0), 2.0).unwrap();
    let basis = BSplineBasis::new(
        KnotVector::new(vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0, 1.0]),
        3,
    );
    let pts: Vec<Vector3<f64>> = (0..6)
        .map(|i| Vector3::new(i as f64, (i as f64).sin(), (i * i) as f64 / 4.0))
        .collect();
    let cubic = BSplineCurve::new(basis, pts);
    for t0 in [0.1, 0.5, 0.95] {
        let f = curve_formulas(&circle, t0).unwrap();
        let span = f.span.unwrap();
        assert!(span.contains(t0));
        for t in [span.lo, 0.5 * (span.lo + span.hi), t0] {
            let [p, d1, d2] = circle.derivatives2(t);
            for k in 0..2 {
                assert!(close(f.point[k].eval(&[t]), p[k]), "{}", f.point[k]);
                assert!((f.d1[k].eval(&[t]) - d1[k]).abs() <= 1e-9 * d1.norm());
                assert!((f.d2[k].eval(&[t]) - d2[k]).abs() <= 1e-8 * d2.norm().max(1.0));
            }
        }
        // the rational form over one denominator: (N′·D − N·D′)/D², (…)/D³
        assert!(f.d1[0].plain().ends_with(")^2"), "{}", f.d1[0]);
        assert!(f.d2[1].plain().ends_with(")^3"), "{}", f.d2[1]);
        let g = curve_formulas(&cubic, t0).unwrap();
        let span = g.span.unwrap();
        for t in [span.lo, 0.5 * (span.lo + span.hi)] {
            let [p, d1, d2] = cubic.derivatives2(t);
            for k in 0..3 {
                assert!(close(g.point[k].eval(&[t]), p[k]), "{}", g.point[k]);
                assert!(close(g.d1[k].eval(&[t]), d1[k]));
                assert!((g.d2[k].eval(&[t]) - d2[k]).abs() <= 1e-9 * d2.norm().max(1.0));
            }
            // a cubic piece: the second derivative is linear, the formula a polynomial
            let d2 = g.d2[0].plain();
            assert!(!d2.contains("/(") && !d2.contains("/t"), "{d2}");
        }
    }
    assert!(matches!(
        curve_formulas(&circle, f64::INFINITY),
        Err(Error::NonFinite { .. })
    ));
    // a Bézier curve (the B-spline of order n + 1): one polynomial on its whole domain,
    // equal to de Casteljau's point everywhere
    let pts = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 2.0),
        Vector2::new(3.0, 3.0),
        Vector2::new(4.0, -1.0),
        Vector2::new(6.0, 0.5),
    ];
    let bezier = BSplineCurve::with_order(pts.clone(), pts.len()).unwrap();
    let f = curve_formulas(&bezier, 0.4).unwrap();
    let span = f.span.unwrap();
    assert_eq!((span.lo, span.hi, span.closed), (0.0, 1.0, true));
    for t in [0.0, 0.25, 0.6, 1.0] {
        let p = splinelab::de_casteljau(&pts, t).unwrap();
        for k in 0..2 {
            assert!(close(f.point[k].eval(&[t]), p[k]), "{}", f.point[k]);
        }
    }
    assert!(f.point[0].plain().contains("t^4"), "{}", f.point[0]);
}

#[test]
fn spline_surface_formulas_name_their_patch() {
    let torus = Torus::new(2.0, 1.0);
    let spline = HermiteSurface::uniform(&torus, &Rect::unit(), 4, 4).unwrap();
    let f = surface_formulas(&spline, 0.3, 0.6).unwrap();
    assert_eq!(f.branches[..2], ["s ∈ [1/4, 1/2)", "t ∈ [1/2, 3/4)"]);
    for (s, t) in [(0.3, 0.6), (0.26, 0.74), (0.49, 0.5)] {
        let d = spline.partials(s, t);
        for k in 0..3 {
            assert!(close(f.point[k].eval(&[s, t]), d.point[k]));
            assert!(close(f.ds[k].eval(&[s, t]), d.ds[k]));
            assert!(close(f.dt[k].eval(&[s, t]), d.dt[k]));
            assert!((f.dst[k].eval(&[s, t]) - d.dst[k]).abs() <= 1e-10);
        }
    }
    // a patch: H(s)ᵀ C H(t) with the basis exact, multiplied out to the same values
    let patch = HermitePatch::from_surface(&torus, &Rect::unit());
    let p = patch_formulas(&patch).unwrap();
    assert_eq!(p.h_s[0].plain(), "1 - 3*s^2 + 2*s^3");
    assert_eq!(p.h_t[3].plain(), "3*t^2 - 2*t^3");
    for (s, t) in [(0.0, 0.0), (0.3, 0.8), (1.0, 1.0)] {
        let x = patch.eval(s, t);
        for k in 0..3 {
            assert!(close(p.x[k].eval(&[s, t]), x[k]));
        }
    }
}

#[test]
fn bad_input_gets_typed_errors() {
    // NaN trace points
    assert!(matches!(
        surface_formulas(&Torus::default(), f64::NAN, 0.0),
        Err(Error::NonFinite { .. })
    ));
    // a formula nested deeper than the printer recurses
    let deep = trace([("x", 0.1)], |[x]| {
        let mut e = x;
        for _ in 0..MAX_FORMULA_DEPTH + 10 {
            e = e.sin();
        }
        vec![e]
    });
    assert!(matches!(deep, Err(Error::TooLarge { .. })));
    // multiplying out a huge power is refused, not attempted
    let big = trace([("x", 0.1), ("y", 0.2)], |[x, y]| {
        vec![(x + y + 1.0).powi(4000)]
    })
    .unwrap();
    assert_eq!(big.formulas[0].plain(), "(1 + x + y)^4000");
    assert!(matches!(
        big.formulas[0].expanded(),
        Err(Error::TooLarge { .. })
    ));
    assert_eq!(big.formulas[0].tidy().plain(), "(1 + x + y)^4000");
    // NaN and infinite constants print and evaluate as themselves
    let odd = trace([("x", 0.1)], |[x]| vec![x * f64::NAN, x + f64::INFINITY]).unwrap();
    assert!(odd.formulas[0].eval(&[1.0]).is_nan());
    assert_eq!(odd.formulas[1].eval(&[1.0]), f64::INFINITY);
    assert!(odd.formulas[0].latex().contains("NaN"));
}

#[test]
fn tables_of_formulas_in_latex_and_mathml() {
    use splinelab::symbolic::MathTable;
    let h = hermite_basis_formulas().unwrap();
    let table = MathTable::named("H", "t", &h);
    let latex = table.latex();
    assert!(
        latex.contains("H_{0}(t) = & 1 - 3 t^{2} + 2 t^{3}"),
        "{latex}"
    );
    assert!(latex.contains("H_{2}(t) = & t^{3} - t^{2}"), "{latex}");
    balanced_tags(&table.html());
    // a piecewise curve's table says where its formulas hold
    let basis = BSplineBasis::new(KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]), 2);
    let b = bspline_basis_formulas(&basis, 1.5).unwrap().table();
    assert_eq!(b.notes, ["These formulas hold where t ∈ [1, 2]."]);
    // the patch: basis exact, matrix numeric (its brackets drawn by CSS), polynomials
    let patch = HermitePatch::from_surface(&Torus::default(), &Rect::unit());
    let p = patch_formulas(&patch).unwrap().table();
    balanced_tags(&p.html().replace("<p>", "").replace("</p>", ""));
    assert!(
        p.latex().contains("\\begin{pmatrix}3 & 0 & "),
        "{}",
        p.latex()
    );
}

// ---- issue 24: a trace that cannot print a wrong formula without an error ----

#[test]
fn a_stale_handle_combined_with_a_live_one_poisons_the_trace() {
    let mut first = Trace::new();
    let old = first.var("x", 1.0) * 2.0 + 1.0;
    drop(first);
    let mut second = Trace::new();
    let y = second.var("y", 3.0);
    let z = y.sin() * y;
    let mixed = old + y;
    // the mixed expression, and every other formula of the trace, are refused
    assert!(
        matches!(second.formula(&mixed), Err(Error::Degenerate { .. })),
        "{:?}",
        second.formula(&mixed)
    );
    assert!(matches!(second.formula(&z), Err(Error::Degenerate { .. })));
    assert!(matches!(
        second.formulas(&[y, z]),
        Err(Error::Degenerate { .. })
    ));
    // a new trace starts clean
    drop(second);
    let mut third = Trace::new();
    let w = third.var("w", 0.5);
    assert_eq!(third.formula(&(w * 2.0)).unwrap().plain(), "2*w");
}

#[test]
fn trace_identities_are_unique_across_threads() {
    // each thread's first trace: with per-thread counters they would share an identity
    let here = Trace::new();
    let mut mine = Trace::new();
    let x = mine.var("x", 1.0);
    let f = std::thread::spawn(|| {
        let mut t = Trace::new();
        let y = t.var("y", 2.0) * 3.0;
        t.formula(&y).map(|f| f.plain())
    })
    .join()
    .unwrap();
    assert_eq!(f.unwrap(), "3*y");
    assert_eq!(mine.formula(&(x + 1.0)).unwrap().plain(), "1 + x");
    drop(here);
}

#[test]
fn a_root_of_a_product_is_not_split_where_its_factors_can_be_negative() {
    let out = trace([("s", -1.0), ("t", -1.0)], |[s, t]| vec![(s * t).sqrt()]).unwrap();
    let f = &out.formulas[0];
    assert_eq!(f.eval(&[-1.0, -1.0]), 1.0, "{f}");
    assert_eq!(f.plain(), "sqrt(s*t)");
    // with bases that are positive by their structure the rule fires
    let out = trace([("s", -1.0), ("t", -1.0)], |[s, t]| {
        vec![(s.exp() * t.cosh() * 4.0).sqrt()]
    })
    .unwrap();
    assert_eq!(out.formulas[0].plain(), "2*sqrt(exp(s))*sqrt(cosh(t))");
    assert!(close(
        out.formulas[0].eval(&[-1.0, -1.0]),
        (4.0 * (-1.0f64).exp() * 1.0f64.cosh()).sqrt()
    ));
}

#[test]
fn sums_and_products_are_equal_in_any_order() {
    let out = trace([("x", 0.3), ("y", 0.4)], |[x, y]| {
        vec![(x + y).sin() - (y + x).sin(), (x * y).cos() - (y * x).cos()]
    })
    .unwrap();
    assert_eq!(out.formulas[0].plain(), "0");
    assert_eq!(out.formulas[1].plain(), "0");
    // one print order: the same product prints alike whichever way it was computed
    let a = trace([("s", 0.3), ("t", 0.7)], |[s, t]| {
        vec![-(t.sin() * s.cos()), -(s.cos() * t.sin())]
    })
    .unwrap();
    assert_eq!(a.formulas[0].plain(), a.formulas[1].plain());
    assert_eq!(a.formulas[0].plain(), "-cos(s)*sin(t)");
}

/// The open Angular spline through `points` (the first and last are guides).
fn angular_through(points: &[(f64, f64)]) -> splinelab::AngularSpline {
    let points = points
        .iter()
        .map(|&(x, y)| nalgebra::Vector2::new(x, y))
        .collect();
    splinelab::AngularSpline::try_new(points).unwrap()
}

#[test]
fn the_angular_spline_beyond_its_end_claims_no_piece() {
    let angular = angular_through(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.5), (3.0, 2.0), (4.0, 1.0)]);
    let (_, b) = angular.domain();
    let f = curve_formulas(&angular, b + 1.0).unwrap();
    // the constant end point is not "the last piece"
    assert_eq!(f.span, None, "{:?}", f.branches);
    assert_eq!(f.branches[0], format!("t > {}", number(b)));
    assert!(f.d1.iter().all(|d| d.as_constant() == Some(0.0)));
    // inside, the piece the evaluation picked
    let g = curve_formulas(&angular, 0.25).unwrap();
    let span = g.span.expect("a recorded piece");
    assert!(
        span.lo == 0.0 && span.hi <= 1.0 && span.contains(0.25),
        "{:?}",
        g.branches
    );
}

/// A user's curve that branches on the value of `t` and names no piece.
struct Kinked;

impl ParametricCurve<1> for Kinked {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> nalgebra::SVector<D, 1> {
        if t.re() < 0.5 {
            nalgebra::SVector::<D, 1>::new(t)
        } else {
            nalgebra::SVector::<D, 1>::new(t * t)
        }
    }
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
}

#[test]
fn a_user_curve_that_reads_its_parameter_is_claimed_at_the_trace_point_only() {
    let f = curve_formulas(&Kinked, 0.75).unwrap();
    assert_eq!(f.point[0].plain(), "t^2");
    assert_eq!(f.span, None);
    assert!(
        f.branches.iter().any(|b| b.starts_with("only at t = 3/4")),
        "{:?}",
        f.branches
    );
    let notes = f.table().notes;
    assert!(
        notes.iter().any(|n| n.contains("claimed only at t = 3/4")),
        "{notes:?}"
    );
}

/// Random formulas with roots and logarithms of expressions that can be negative (and
/// products of such): the simplifier must not rewrite them into forms undefined where the
/// traced value is defined.
#[derive(Debug, Clone)]
enum Rooted {
    Leaf(Tree),
    Sqrt(Box<Rooted>),
    SqrtProd(Box<Rooted>, Box<Rooted>),
    Ln(Box<Rooted>),
    LnProd(Box<Rooted>, Box<Rooted>),
    Powf(Box<Rooted>, f64),
    Mul(Box<Rooted>, Box<Rooted>),
    Add(Box<Rooted>, Box<Rooted>),
}

impl Rooted {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> D {
        match self {
            Rooted::Leaf(x) => x.eval(s, t),
            Rooted::Sqrt(a) => a.eval(s, t).sqrt(),
            Rooted::SqrtProd(a, b) => (a.eval(s, t) * b.eval(s, t)).sqrt(),
            Rooted::Ln(a) => a.eval(s, t).ln(),
            Rooted::LnProd(a, b) => (a.eval(s, t) * b.eval(s, t)).ln(),
            Rooted::Powf(a, p) => a.eval(s, t).powf(*p),
            Rooted::Mul(a, b) => a.eval(s, t) * b.eval(s, t),
            Rooted::Add(a, b) => a.eval(s, t) + b.eval(s, t),
        }
    }

    /// The smallest `|argument|` of a root or logarithm at `(s, t)` (how near a branch
    /// point the trace point is).
    fn nearest_branch(&self, s: f64, t: f64) -> f64 {
        match self {
            Rooted::Leaf(_) => f64::INFINITY,
            Rooted::Sqrt(a) | Rooted::Ln(a) | Rooted::Powf(a, _) => {
                a.eval(s, t).abs().min(a.nearest_branch(s, t))
            }
            Rooted::SqrtProd(a, b) | Rooted::LnProd(a, b) => (a.eval(s, t) * b.eval(s, t))
                .abs()
                .min(a.nearest_branch(s, t))
                .min(b.nearest_branch(s, t)),
            Rooted::Mul(a, b) | Rooted::Add(a, b) => {
                a.nearest_branch(s, t).min(b.nearest_branch(s, t))
            }
        }
    }
}

struct RootedSurface(Rooted);

impl ParametricSurface for RootedSurface {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        let v = self.0.eval(s, t);
        Vector3::new(v, s, t)
    }
}

fn rooted() -> impl Strategy<Value = Rooted> {
    let leaf = prop_oneof![
        Just(Rooted::Leaf(Tree::S)),
        Just(Rooted::Leaf(Tree::T)),
        (-3i32..=3).prop_map(|k| Rooted::Leaf(Tree::C(k as f64 / 2.0))),
        tree().prop_map(Rooted::Leaf),
    ];
    leaf.prop_recursive(3, 12, 2, |inner| {
        prop_oneof![
            inner.clone().prop_map(|a| Rooted::Sqrt(Box::new(a))),
            (inner.clone(), inner.clone())
                .prop_map(|(a, b)| Rooted::SqrtProd(Box::new(a), Box::new(b))),
            inner.clone().prop_map(|a| Rooted::Ln(Box::new(a))),
            (inner.clone(), inner.clone())
                .prop_map(|(a, b)| Rooted::LnProd(Box::new(a), Box::new(b))),
            (
                inner.clone(),
                prop_oneof![Just(0.5), Just(1.5), Just(-0.5), Just(1.0 / 3.0)]
            )
                .prop_map(|(a, p)| Rooted::Powf(Box::new(a), p)),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Rooted::Mul(Box::new(a), Box::new(b))),
            (inner.clone(), inner).prop_map(|(a, b)| Rooted::Add(Box::new(a), Box::new(b))),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Roots and logarithms of expressions of any sign: every formula is captured (the
    /// capture check passes) and equals the hyper-dual value at the trace point wherever
    /// that value is finite — never a NaN formula for a defined value.
    #[test]
    fn roots_and_logs_of_negative_expressions_keep_their_values(
        r in rooted(), s in -2.0f64..2.0, t in -2.0f64..2.0,
    ) {
        prop_assume!(r.nearest_branch(s, t) > 1e-3);
        let surface = RootedSurface(r);
        let f = surface_formulas(&surface, s, t).unwrap();
        let d = surface.partials(s, t);
        let parts = [(&f.point, d.point), (&f.ds, d.ds), (&f.dt, d.dt), (&f.dst, d.dst)];
        for (formulas, values) in parts {
            let v = formulas[0].eval(&[s, t]);
            if values[0].is_finite() {
                let scale = values[0].abs().max(1.0);
                prop_assert!((v - values[0]).abs() <= 1e-9 * scale, "{}: {} vs {}", formulas[0].plain(), v, values[0]);
            }
        }
    }
}

// ---- issue 24: formulas as a person writes them ----

#[test]
fn identities_a_reader_expects() {
    let out = trace([("t", 0.3), ("x", 0.7)], |[t, x]| {
        let d = num_dual::Dual::new(t, Expr::constant(1.0));
        vec![
            d.tanh().eps,
            x.sin() * x.sin() + x.cos() * x.cos(),
            t.cosh().powi(2) * 3.0 - t.sinh().powi(2) * 3.0 + x,
            (x * 2.0).sin().powi(2) * t + t * (x * 2.0).cos().powi(2),
        ]
    })
    .unwrap();
    let texts: Vec<String> = out.formulas.iter().map(|f| f.plain()).collect();
    assert_eq!(texts, ["1/cosh(t)^2", "1", "3 + x", "t"]);
}

#[test]
fn rounding_residue_prints_as_the_number_it_stands_for() {
    let out = trace([("s", 0.3), ("t", 0.7)], |[s, t]| {
        vec![
            s * s * t * t * (0.1 + 0.2 + 0.3),
            (s + 0.1 + 0.2 - 0.3) * 64.0 - s * 64.0,
        ]
    })
    .unwrap();
    assert_eq!(out.formulas[0].plain(), "3*s^2*t^2/5");
    assert_eq!(out.formulas[1].plain(), "0");
    // a NURBS arc's numerator has no 5.6e-17 constant term, and a tiny constant that is
    // real prints with an exponent, not seventeen zeros
    let circle = NurbsCurve::circle9(nalgebra::Vector2::new(0.0, 0.0), 1.0).unwrap();
    let f = curve_formulas(&circle, 0.1).unwrap();
    assert!(f.point[0].plain().starts_with("("), "{}", f.point[0]);
    assert!(!f.point[0].plain().contains("e-1"), "{}", f.point[0]);
    assert_eq!(number(5.551115123125783e-17), "5.551115123125783e-17");
}

#[test]
fn a_polynomial_piece_in_its_local_variable_keeps_its_digits() {
    // degree 5, the interior span [1.21, 1.5] (the review's case)
    let mut knots = vec![0.0; 6];
    knots.extend([1.21, 1.5]);
    knots.extend(vec![2.0; 6]);
    let basis = BSplineBasis::new(KnotVector::new(knots), 5);
    let pts: Vec<nalgebra::Vector2<f64>> = (0..8)
        .map(|i| nalgebra::Vector2::new(i as f64 * 0.3, ((i * 3) % 4) as f64 * 0.7))
        .collect();
    let curve = BSplineCurve::new(basis, pts);
    let local = splinelab::symbolic::curve_formulas_local(&curve, 1.3).unwrap();
    assert_eq!(local.origin, Some(1.21));
    assert_eq!(local.point[0].names(), ["u"]);
    assert!(local
        .table()
        .notes
        .iter()
        .any(|n| n.contains("u = t - 1.21")));
    let global = curve_formulas(&curve, 1.3).unwrap();
    let (mut worst_local, mut worst_global) = (0.0f64, 0.0f64);
    for k in 0..=20 {
        let t = 1.21 + 0.29 * k as f64 / 20.0;
        let want = curve.point(t);
        for c in 0..2 {
            let scale = want[c].abs().max(1.0);
            worst_local =
                worst_local.max((local.point[c].eval(&[t - 1.21]) - want[c]).abs() / scale);
            worst_global = worst_global.max((global.point[c].eval(&[t]) - want[c]).abs() / scale);
        }
    }
    assert!(worst_local <= 1e-14, "local {worst_local:e}");
    assert!(worst_global <= 1e-10, "global {worst_global:e}");
}

#[test]
fn latex_brackets_only_where_precedence_needs_them() {
    let out = trace([("t", 0.3)], |[t]| {
        vec![(t + 1.0) / (t * t + 2.0), t / (t + 1.0).powi(2)]
    })
    .unwrap();
    assert_eq!(out.formulas[0].latex(), "\\frac{1 + t}{2 + t^{2}}");
    assert_eq!(
        out.formulas[1].latex(),
        "\\frac{t}{\\left(1 + t\\right)^{2}}"
    );
    assert_eq!(out.formulas[0].plain(), "(1 + t)/(2 + t^2)");
}

#[test]
fn an_inflection_piece_claims_the_half_its_arc_holds_on() {
    let angular = angular_through(&[(0.0, 0.0), (1.0, 2.0), (3.0, 3.0), (4.0, 0.0), (5.0, 1.0)]);
    let f = curve_formulas(&angular, 1.7).unwrap();
    let span = f.span.expect("a recorded piece");
    assert_eq!(
        (span.lo, span.hi, span.closed),
        (1.5, 2.0, true),
        "{:?}",
        f.branches
    );
    assert_eq!(f.branches[0], "t ∈ [3/2, 2]");
    // and the formula holds on all of it
    for t in [1.5, 1.6, 1.8, 2.0] {
        let p = angular.point(t);
        for k in 0..2 {
            assert!((f.point[k].eval(&[t]) - p[k]).abs() <= 1e-12, "{t}");
        }
    }
    // a root of a reciprocal is the reciprocal of the root (one sign: defined alike)
    let r = trace([("x", 2.0)], |[x]| vec![(x.recip()).sqrt()]).unwrap();
    assert_eq!(r.formulas[0].plain(), "1/sqrt(x)");
}

#[test]
fn fractions_over_one_denominator_where_that_is_shorter() {
    let out = trace([("s", 0.6), ("t", 0.7)], |[s, t]| {
        vec![s.sinh() / s.cosh() + t]
    })
    .unwrap();
    assert_eq!(out.formulas[0].plain(), "tanh(s) + t");
    // the mixed partials of tanh(s − t) and asin(st/2): one fraction each, as short as
    // sympy's simplified forms
    let tanh = surface_formulas(&TanhSurface, 0.6, 0.7).unwrap();
    assert_eq!(tanh.point[2].plain(), "tanh(s - t)");
    assert_eq!(tanh.dst[2].plain(), "tanh(s - t)*(2 - 2*tanh(s - t)^2)");
    let asin = surface_formulas(&AsinSurface, 0.6, 0.7).unwrap();
    assert_eq!(asin.dst[2].plain(), "1/(2*(1 - s^2*t^2/4)^(3/2))");
    for (s, t) in [(0.6, 0.7), (-0.3, 0.9)] {
        let want = TanhSurface.partials(s, t).dst.z;
        assert!(close(tanh.dst[2].eval(&[s, t]), want));
        let want = AsinSurface.partials(s, t).dst.z;
        assert!(close(asin.dst[2].eval(&[s, t]), want));
    }
}

struct TanhSurface;
impl ParametricSurface for TanhSurface {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        Vector3::new(s, t, (s - t).tanh())
    }
}

struct AsinSurface;
impl ParametricSurface for AsinSurface {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        Vector3::new(s, t, (s * t * 0.5).asin())
    }
}

#[cfg(feature = "report")]
#[test]
fn local_formulas_and_the_corpus_refuse_bad_points() {
    use splinelab::symbolic::corpus::{curve_entry, surface_entry};
    let pts: Vec<nalgebra::Vector2<f64>> = (0..6)
        .map(|i| nalgebra::Vector2::new(i as f64, (i % 2) as f64))
        .collect();
    let curve = BSplineCurve::with_order(pts, 4).unwrap();
    for t in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(
            splinelab::symbolic::curve_formulas_local(&curve, t),
            Err(Error::NonFinite { .. })
        ));
        assert!(curve_entry("bad", &curve, t, true).is_err());
        assert!(surface_entry("bad", &Torus::new(2.0, 1.0), (t, 0.5), [(0.0, 1.0); 2]).is_err());
    }
    // far outside the domain: the end piece's extrapolation, claimed beyond the domain
    let far = splinelab::symbolic::curve_formulas_local(&curve, 1e300).unwrap();
    assert_eq!(far.span, None, "{:?}", far.branches);
    assert!(
        far.branches.iter().any(|b| b.contains("t ≥")),
        "{:?}",
        far.branches
    );
    // the corpus as shipped builds, every entry with samples and finite references
    let corpus = splinelab::symbolic::corpus::corpus().unwrap();
    assert!(corpus.len() >= 40);
    for e in &corpus {
        assert!(!e.samples.is_empty(), "{}", e.name);
        for (at, values) in &e.samples {
            assert_eq!(values.len(), e.formulas.len(), "{}", e.name);
            assert!(at.iter().chain(values).all(|v| v.is_finite()), "{}", e.name);
        }
    }
}
