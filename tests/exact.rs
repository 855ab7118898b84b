//! The exact linear algebra (`splinelab::exact`) against independent references: the
//! Leibniz expansion of the determinant, the defining property `A A⁻¹ = I` checked exactly,
//! nalgebra's LU for the same routine run on `f64`, and the closed forms of the seeds (the
//! Hermite basis of seed 000 §1, `2s³ − 3s² + 1` …).
//!
//! # Tolerance policy
//! Exact results are compared with `==` (tolerance 0). The `f64` path is compared with
//! nalgebra's LU relative to the size of the problem: `|x − x_LU| ≤ F64_TOL · κ∞ · max|x|`,
//! `κ∞` the condition number from the exact inverse.

use nalgebra::DMatrix;
use num_bigint::BigInt;
use num_traits::{One, Zero};
use proptest::prelude::*;
use splinelab::exact::{self, Polynomial, Rational};
use splinelab::symbolic::{Math, MathTable};

/// `f64` solves agree with nalgebra's LU to this, times the condition number.
const F64_TOL: f64 = 1e-13;

fn q(p: i64, d: i64) -> Rational {
    exact::ratio(p, d).unwrap()
}

/// Leibniz: `det A = Σ_σ sgn σ Π aᵢσ(i)`, over all permutations (n ≤ 6).
fn leibniz(a: &DMatrix<Rational>) -> Rational {
    fn permutations(n: usize) -> Vec<(Vec<usize>, bool)> {
        if n == 0 {
            return vec![(Vec::new(), false)];
        }
        let mut out = Vec::new();
        for (p, odd) in permutations(n - 1) {
            for k in 0..n {
                let mut v = p.clone();
                v.insert(k, n - 1);
                // inserting n−1 at k passes it over n−1−k elements
                out.push((v, odd ^ ((n - 1 - k) % 2 == 1)));
            }
        }
        out
    }
    permutations(a.nrows())
        .into_iter()
        .map(|(p, odd)| {
            let term = p
                .iter()
                .enumerate()
                .fold(Rational::one(), |acc, (i, &j)| acc * a[(i, j)].clone());
            if odd {
                -term
            } else {
                term
            }
        })
        .fold(Rational::zero(), |acc, t| acc + t)
}

fn rational_matrix() -> impl Strategy<Value = DMatrix<Rational>> {
    (1usize..=6).prop_flat_map(|n| {
        proptest::collection::vec((-9i64..=9, 1i64..=5), n * n)
            .prop_map(move |v| DMatrix::from_iterator(n, n, v.into_iter().map(|(p, d)| q(p, d))))
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    /// The determinant equals Leibniz's expansion; the inverse exists exactly when it is not 0,
    /// and then `A A⁻¹ = A⁻¹ A = I` and `A (A⁻¹ b) = b`, with no rounding at all.
    #[test]
    fn exact_solve_inverse_and_determinant(a in rational_matrix(), seed in 0i64..1000) {
        let det = exact::determinant(&a).unwrap();
        prop_assert_eq!(&det, &leibniz(&a));
        let n = a.nrows();
        match exact::inverse(&a) {
            Ok(inv) => {
                prop_assert!(!det.is_zero());
                prop_assert!(exact::is_identity(&(&a * &inv)));
                prop_assert!(exact::is_identity(&(&inv * &a)));
                let b = DMatrix::from_fn(n, 2, |i, j| q((i as i64 * 7 + j as i64 * 3 + seed) % 11 - 5, 1 + j as i64));
                let x = exact::solve(&a, &b).unwrap();
                prop_assert_eq!(&a * &x, b);
            }
            Err(splinelab::Error::SingularSystem { .. }) => prop_assert!(det.is_zero()),
            Err(e) => prop_assert!(false, "unexpected error {e}"),
        }
    }

    /// The same code on `f64` agrees with nalgebra's LU, relative to the condition number;
    /// a matrix it calls singular is singular or nearly so (κ beyond 10¹²).
    #[test]
    fn the_f64_path_agrees_with_nalgebra(a in rational_matrix()) {
        let n = a.nrows();
        let af = a.map(|x| exact::to_f64(&x));
        let exact_af = exact::from_f64_matrix(&af).unwrap();
        let Ok(exact_inv) = exact::inverse(&exact_af) else {
            prop_assert!(exact::inverse(&af).is_err());
            return Ok(());
        };
        let norm = |m: &DMatrix<f64>| m.row_iter().map(|r| r.iter().map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max);
        let inv_exact_f = exact_inv.map(|x| exact::to_f64(&x));
        let kappa = norm(&af) * norm(&inv_exact_f);
        match exact::inverse(&af) {
            Ok(inv) => {
                let lu = af.clone().lu().try_inverse().unwrap();
                let scale = inv_exact_f.amax();
                for (x, y) in inv.iter().zip(lu.iter()) {
                    prop_assert!((x - y).abs() <= F64_TOL * kappa * scale,
                        "{x} vs nalgebra's {y}, κ = {kappa:e}, n = {n}");
                }
                let det = exact::determinant(&af).unwrap();
                let det_ref = exact::to_f64(&exact::determinant(&exact_af).unwrap());
                prop_assert!((det - det_ref).abs() <= F64_TOL * kappa * det_ref.abs().max(1e-300) * n as f64,
                    "determinant {det} vs exact {det_ref}");
            }
            Err(e) => prop_assert!(kappa > 1e12, "refused ({e}) at κ = {kappa:e}"),
        }
    }

    /// Polynomial arithmetic is arithmetic on values: `(p·r)(x) = p(x) r(x)`, `(p ± r)(x)`,
    /// and the derivative is exact: `p′(x) = lim` checked on `p(x + h) − p(x) = Σ p⁽ᵏ⁾(x) hᵏ/k!`.
    #[test]
    fn polynomials_are_their_values(
        a in proptest::collection::vec(-20i64..20, 0..6),
        b in proptest::collection::vec(-20i64..20, 0..6),
        x in -7i64..7, h in 1i64..5,
    ) {
        let p = Polynomial::new(a.iter().map(|&c| exact::int(c)).collect());
        let r = Polynomial::new(b.iter().map(|&c| q(c, 3)).collect());
        let x = q(x, 2);
        prop_assert_eq!((&p * &r).eval(&x), p.eval(&x) * r.eval(&x));
        prop_assert_eq!((&p + &r).eval(&x), p.eval(&x) + r.eval(&x));
        prop_assert_eq!((&p - &r).eval(&x), p.eval(&x) - r.eval(&x));
        prop_assert_eq!(p.compose(&r).eval(&x), p.eval(&r.eval(&x)));
        let h = exact::int(h);
        let mut taylor = Rational::zero();
        let mut factorial = Rational::one();
        let mut power = Rational::one();
        for k in 0..=p.degree().unwrap_or(0) {
            if k > 0 {
                factorial *= exact::int(k as i64);
                power *= h.clone();
            }
            taylor += p.derivative_n(k).eval(&x) * power.clone() / factorial.clone();
        }
        prop_assert_eq!(p.eval(&(x.clone() + h)), taylor);
    }
}

#[test]
fn the_hermite_conditions_give_the_hermite_basis() {
    // seed 000 §1, in its order: K c = (p(0), p′(0), p′(1), p(1)) for p = c₀ + c₁s + c₂s² + c₃s³
    let k = exact::conditions(4, &[(0, 0), (1, 0), (1, 1), (0, 1)]).unwrap();
    let expected_k = exact::matrix(&[
        &[(1, 1), (0, 1), (0, 1), (0, 1)],
        &[(0, 1), (1, 1), (0, 1), (0, 1)],
        &[(0, 1), (1, 1), (2, 1), (3, 1)],
        &[(1, 1), (1, 1), (1, 1), (1, 1)],
    ])
    .unwrap();
    assert_eq!(k, expected_k);
    let k_inv = exact::inverse(&k).unwrap();
    let basis: Vec<String> = (0..4)
        .map(|i| Polynomial::from_column(&k_inv, i).plain("s"))
        .collect();
    assert_eq!(
        basis,
        [
            "1 - 3*s^2 + 2*s^3",
            "s - 2*s^2 + s^3",
            "-s^2 + s^3",
            "3*s^2 - 2*s^3"
        ]
    );
    // the conditions applied to the basis they define give the identity; §1's printed basis
    let polys: Vec<Polynomial<Rational>> =
        (0..4).map(|i| Polynomial::from_column(&k_inv, i)).collect();
    let conds = [(0, 0), (1, 0), (1, 1), (0, 1)];
    assert!(exact::is_identity(
        &exact::conditions_on(&polys, &conds).unwrap()
    ));
    assert_eq!(polys, splinelab::seeds::seed000::hermite_basis_printed());
    // reversing t swaps the ends and flips the slopes: H₃(t) = H₀(1 − t), H₂(t) = −H₁(1 − t)
    let one_minus_t = Polynomial::new(vec![q(1, 1), q(-1, 1)]);
    assert_eq!(polys[3], polys[0].compose(&one_minus_t));
    assert_eq!(polys[2], polys[1].compose(&one_minus_t).scale(&q(-1, 1)));
    // and each equals the library's f64 Hermite basis at every sixteenth
    for i in 0..=16 {
        let s = i as f64 / 16.0;
        let h = splinelab::hermite_basis(s);
        for (j, hj) in h.iter().enumerate() {
            let exact = Polynomial::from_column(&k_inv, j).eval(&exact::from_f64(s).unwrap());
            assert_eq!(exact::to_f64(&exact), *hj, "H{j}({s})");
        }
    }
}

#[test]
fn exact_numbers_are_written_as_fractions() {
    let p = Polynomial::new(vec![q(1, 1), q(-3, 2), q(0, 1), q(1, 3)]);
    assert_eq!(p.plain("s"), "1 - 3*s/2 + s^3/3");
    assert_eq!(p.latex("s"), "1 - \\frac{3}{2}s + \\frac{1}{3}s^{3}");
    assert!(p
        .mathml("s")
        .contains("<mfrac><mn>1</mn><mn>3</mn></mfrac><msup><mi>s</mi><mn>3</mn></msup>"));
    assert_eq!(Polynomial::<Rational>::new(vec![]).plain("t"), "0");
    let m = exact::matrix(&[&[(1, 2), (-3, 1)]]).unwrap();
    assert_eq!(exact::plain(&m), "[1/2, -3]");
    assert_eq!(
        exact::latex(&m),
        "\\begin{pmatrix}\\frac{1}{2} & -3\\end{pmatrix}"
    );
    assert_eq!(exact::latex(&q(-7, 4)), "-\\frac{7}{4}");
    // a name as LaTeX writes it, in MathML
    for (name, mathml) in [
        (
            "K^{-1}",
            "<msup><mi>K</mi><mrow><mo>\u{2212}</mo><mn>1</mn></mrow></msup>",
        ),
        ("H_0", "<msub><mi>H</mi><mrow><mn>0</mn></mrow></msub>"),
        ("A^T", "<msup><mi>A</mi><mrow><mi>T</mi></mrow></msup>"),
        (
            "\\lambda_k(H_{j})",
            "<msub><mi>λ</mi><mrow><mi>k</mi></mrow></msub><mo>(</mo><msub><mi>H</mi><mrow><mi>j</mi></mrow></msub><mo>)</mo>",
        ),
        ("\\det K", "<mi>det</mi><mo>\u{2061}</mo><mi>K</mi>"),
    ] {
        assert_eq!(Math::name(name).mathml, mathml, "{name}");
    }
    let t = MathTable::new().eq("K", &m);
    assert_eq!(t.rows.len(), 1);
    assert!(t.latex().contains("K = & \\begin{pmatrix}"));
}

#[test]
fn numbers_beyond_i64_stay_exact() {
    // a Hilbert matrix: its inverse has integer entries far beyond what f64 holds exactly
    let n = 16;
    let h = DMatrix::from_fn(n, n, |i, j| q(1, (i + j + 1) as i64));
    let inv = exact::inverse(&h).unwrap();
    assert!(exact::is_identity(&(&h * &inv)));
    assert!(inv.iter().all(|x| x.is_integer()));
    let largest = inv.iter().map(|x| x.abs()).max().unwrap();
    assert!(largest > Rational::from(BigInt::from(1u64 << 53)));
    // the f64 path refuses it or solves it within its residual check; never a silent answer
    let hf = h.map(|x| exact::to_f64(&x));
    if let Ok(x) = exact::inverse(&hf) {
        assert!(x.iter().all(|v| v.is_finite()));
    }
}

#[test]
fn bernstein_polynomials_are_the_closed_form_and_sum_to_one() {
    for n in 0..=8usize {
        let b = exact::bernstein(n).unwrap();
        assert_eq!(b.len(), n + 1);
        // Σ Bᵢⁿ = ((1 − t) + t)ⁿ = 1, exactly
        let sum = b.iter().fold(Polynomial::new(vec![]), |acc, p| &acc + p);
        assert_eq!(sum, Polynomial::constant(q(1, 1)), "n = {n}");
        // Bᵢⁿ(x) = C(n, i) xⁱ (1 − x)ⁿ⁻ⁱ at x = 2/7, with the binomial from Pascal's triangle
        let mut pascal = vec![1i64];
        for _ in 0..n {
            pascal = (0..=pascal.len())
                .map(|k| {
                    pascal.get(k).copied().unwrap_or(0) + if k > 0 { pascal[k - 1] } else { 0 }
                })
                .collect();
        }
        let x = q(2, 7);
        for (i, p) in b.iter().enumerate() {
            let mut v = exact::int(pascal[i]);
            for _ in 0..i {
                v *= x.clone();
            }
            for _ in i..n {
                v *= q(1, 1) - x.clone();
            }
            assert_eq!(p.eval(&x), v, "B_{i}^{n}");
        }
    }
}

#[test]
fn the_hermite_basis_is_a_transpose_b_and_codice_7_errs_in_one_entry() {
    let conds = [(0, 0), (1, 0), (1, 1), (0, 1)];
    let b = exact::bernstein(3).unwrap();
    let a = exact::inverse(&exact::conditions_on(&b, &conds).unwrap()).unwrap();
    let expected_a = exact::matrix(&[
        &[(1, 1), (0, 1), (0, 1), (0, 1)],
        &[(1, 1), (1, 3), (0, 1), (0, 1)],
        &[(0, 1), (0, 1), (-1, 3), (1, 1)],
        &[(0, 1), (0, 1), (0, 1), (1, 1)],
    ])
    .unwrap();
    assert_eq!(a, expected_a);
    assert_eq!(
        exact::in_basis(&b, &a).unwrap(),
        splinelab::seeds::seed000::hermite_basis_printed()
    );
    // Codice 7 against A E Aᵀ on the 16 unit matrices: only E₂₁, by 2/9 at (2, 1)
    for k in 0..4 {
        for l in 0..4 {
            let e = exact::unit(4, 4, k, l).unwrap();
            let diff = splinelab::codice7_plane(&e).unwrap() - &a * &e * a.transpose();
            if (k, l) == (2, 1) {
                assert_eq!(diff, exact::unit(4, 4, 2, 1).unwrap() * q(2, 9));
            } else {
                assert!(exact::is_zero(&diff), "E_{k}{l}: {diff}");
            }
        }
    }
    // the same code in f64 is the report's net, plane by plane
    let patch = splinelab::HermitePatch::from_surface(
        &splinelab::Torus::default(),
        &splinelab::Rect::new(0.0, 1.0, 0.5, 1.5),
    );
    let net = splinelab::report_codice7_net(&patch);
    for (k, plane) in patch.planes().iter().enumerate() {
        let c = DMatrix::from_fn(4, 4, |i, j| plane[(i, j)]);
        let m = splinelab::codice7_plane(&c).unwrap();
        assert_eq!(m, DMatrix::from_fn(4, 4, |i, j| net.planes()[k][(i, j)]));
    }
}

/// Strictly increasing integer nodes (steps 1–4) and integer values, 3–9 points.
fn integer_data() -> impl Strategy<Value = (Vec<i64>, Vec<i64>)> {
    (3usize..=9).prop_flat_map(|n| {
        (
            proptest::collection::vec(1i64..=4, n - 1),
            proptest::collection::vec(-9i64..=9, n),
        )
            .prop_map(|(steps, y)| {
                let mut x = vec![0i64];
                for s in steps {
                    x.push(x.last().unwrap() + s);
                }
                (x, y)
            })
    })
}

fn ends() -> [splinelab::EndCondition<1>; 4] {
    [
        splinelab::EndCondition::clamped(1.0, -0.5),
        splinelab::EndCondition::Natural,
        splinelab::EndCondition::Cyclic,
        splinelab::EndCondition::Anticyclic,
    ]
}

proptest! {
    /// The dense moment system, solved exactly, gives the moments of the O(n) tridiagonal
    /// solve of `CubicSpline` (its `s″` at the nodes) to rounding, for every end condition;
    /// and the same system in `f64` is the exact one rounded.
    #[test]
    fn the_moment_system_solved_exactly_is_the_splines_second_derivative((x, y) in integer_data()) {
        let xq: Vec<Rational> = x.iter().map(|&v| exact::int(v)).collect();
        let yq: Vec<Rational> = y.iter().map(|&v| exact::int(v)).collect();
        let xf: Vec<f64> = x.iter().map(|&v| v as f64).collect();
        let yf: Vec<f64> = y.iter().map(|&v| v as f64).collect();
        for end in ends() {
            let (a, r) = splinelab::moment_system(&xq, &yq, &end).unwrap();
            let m = exact::solve(&a, &r).unwrap();
            let spline = splinelab::CubicSpline::function(&xf, &yf, end).unwrap();
            let scale = m.iter().map(|v| exact::to_f64(v).abs()).fold(1.0, f64::max);
            for (i, &xi) in xf.iter().enumerate() {
                // s″ at a node, from the piece on its right (the last node: its left)
                let fast = spline.second_derivative(xi);
                prop_assert!((fast - exact::to_f64(&m[(i, 0)])).abs() <= 1e-12 * scale,
                    "{end:?} node {i}: {fast} vs {}", m[(i, 0)]);
            }
            let (af, rf) = splinelab::moment_system(&xf, &yf, &end).unwrap();
            prop_assert_eq!(exact::from_f64_matrix(&af).unwrap(), a);
            let rf_exact = exact::from_f64_matrix(&rf).unwrap();
            for (p, q) in rf_exact.iter().zip(r.iter()) {
                prop_assert!((exact::to_f64(p) - exact::to_f64(q)).abs() <= 1e-13 * (1.0 + exact::to_f64(q).abs()));
            }
        }
    }

    /// Cox–de Boor on exact rationals: each row of the triangle sums to exactly 1 inside the
    /// domain, and every value is the `f64` recurrence's to rounding.
    #[test]
    fn cox_de_boor_in_fractions_is_a_partition_of_unity(
        steps in proptest::collection::vec(0i64..=3, 4..10),
        degree in 1usize..=3,
        (p, d) in (0i64..=1000, 1i64..=1000),
    ) {
        let mut knots = vec![0.0];
        for s in &steps {
            knots.push(knots.last().unwrap() + *s as f64);
        }
        let Ok(kv) = splinelab::KnotVector::try_new(knots) else { return Ok(()) };
        let Ok(basis) = splinelab::BSplineBasis::try_new(kv, degree) else { return Ok(()) };
        let (a, b) = basis.domain();
        if a >= b { return Ok(()); }
        // t = a + (b − a) p/d, clamped to [a, b]
        let t = exact::from_f64(a).unwrap() + exact::from_f64(b - a).unwrap() * q(p.min(d), d);
        let table = basis.cox_de_boor_table(t.clone()).unwrap();
        let row = table.row(degree);
        let sum = row.iter().fold(Rational::zero(), |s, v| s + v.clone());
        prop_assert_eq!(sum, Rational::one());
        let tf = exact::to_f64(&t);
        for i in 0..basis.len() {
            let f = basis.cox_de_boor(i, degree, tf);
            prop_assert!((f - exact::to_f64(&table[(degree, i)])).abs() <= 1e-12);
        }
    }

    /// de Casteljau on exact points is the Bernstein sum exactly, and the recursive `castel`
    /// reaches the same point with `2ⁿ⁻¹ − 1` calls.
    #[test]
    fn de_casteljau_in_fractions_is_the_bernstein_sum(
        pts in proptest::collection::vec((-9i64..=9, -9i64..=9), 2..8),
        (p, d) in (0i64..=50, 1i64..=50),
    ) {
        let points = exact::plane_points(&pts);
        let u = q(p, d);
        let levels = splinelab::de_casteljau_levels(&points, u.clone()).unwrap();
        let n = points.len() - 1;
        let b = exact::bernstein(n).unwrap();
        let mut want = nalgebra::Vector2::new(Rational::zero(), Rational::zero());
        for (bi, pi) in b.iter().zip(&points) {
            let w = bi.eval(&u);
            want += pi * w;
        }
        prop_assert_eq!(&levels[n][0], &want);
        let (castel, calls) = splinelab::de_casteljau_recursive_counted(&points, u).unwrap();
        prop_assert_eq!(castel, want);
        prop_assert_eq!(calls, (1u64 << n) - 1);
    }
}
