//! A user's own surfaces as a new user writes them (issue 48): `surface!` with a visibility
//! and parameters, formulas with the parameters as numbers or as symbols, the plain-text
//! tables of every formula set, formulas exact where the data are fractions, and studies that
//! say when an error is the rounding of `f64`.

use nalgebra::Vector3;
use proptest::prelude::*;
use splinelab::prelude::*;
use splinelab::study::hermite_error::{convergence, ROUNDING_ULPS};
use splinelab::symbolic::{
    bspline_basis_formulas, curve_formulas, patch_formulas, surface_formulas,
    surface_formulas_with_parameters, trace,
};

// the visibility is the struct's (and its fields'): these are used from another module below
mod mine {
    use splinelab::prelude::*;

    surface!(
        /// `z = a sin(k s)`, a wave of two parameters.
        pub Wave { k: f64, a: f64 } = |s, t| Vector3::new(s, t, (s * k).sin() * a)
    );

    surface!(pub Enneper = |s, t| Vector3::new(
        s - s.powi(3) / 3.0 + s * t * t,
        t - t.powi(3) / 3.0 + t * s * s,
        s * s - t * t,
    ));

    // a parameter that shadows a variable's name is refused when traced as a symbol
    surface!(pub Named { s: f64 } = |u, v| Vector3::new(u, v, u * s));
}
use mine::{Enneper, Named, Wave};

/// Within `1e-12` relative (the crate's tolerance for exact derivatives).
fn close(a: Vector3<f64>, b: Vector3<f64>) -> bool {
    (a - b).norm() <= 1e-12 * (1.0 + b.norm())
}

#[test]
fn a_surface_with_fields_has_exact_partials_and_its_parameters() {
    let w = Wave { k: 2.0, a: 0.5 };
    assert_eq!(w.parameters(), vec![("k", 2.0), ("a", 0.5)]);
    for (s, t) in [(0.3, 0.7), (-1.2, 2.0), (0.0, 0.0)] {
        let d = w.partials(s, t);
        assert!(close(d.ds, Vector3::new(1.0, 0.0, (2.0 * s).cos())));
        assert!(close(d.dt, Vector3::new(0.0, 1.0, 0.0)));
        assert_eq!(d.dst, Vector3::zeros());
        // eval_with takes other values, in the order of `parameters`; a missing one is the
        // surface's own
        let other: Vector3<f64> = w.eval_with(s, t, &[1.0, 3.0]);
        assert!(close(other, Vector3::new(s, t, 3.0 * s.sin())));
        let own: Vector3<f64> = w.eval_with(s, t, &[]);
        assert_eq!(own, w.point(s, t));
    }
    // a unit struct from the macro has no parameters, and defaults
    assert!(Enneper.parameters().is_empty());
    assert_eq!(Enneper, Enneper);
}

#[test]
fn parameters_print_as_numbers_or_as_symbols() -> splinelab::Result<()> {
    let w = Wave { k: 2.0, a: 0.5 };
    let numbers = surface_formulas(&w, 0.3, 0.7)?;
    assert_eq!(numbers.point[2].plain(), "sin(2*s)/2");
    assert!(numbers.parameters.is_empty());
    let symbols = surface_formulas_with_parameters(&w, 0.3, 0.7)?;
    assert_eq!(symbols.point[2].plain(), "a*sin(s*k)");
    assert_eq!(symbols.ds[2].plain(), "k*a*cos(s*k)");
    assert_eq!(
        symbols.parameters,
        vec![("k".to_string(), 2.0), ("a".to_string(), 0.5)]
    );
    // the symbols' values are the trace point's: the formula evaluates to the surface
    let z = symbols.point[2].eval(&[0.3, 0.7, 2.0, 0.5]);
    assert!((z - w.point(0.3, 0.7).z).abs() < 1e-15);
    // the torus
    let torus = surface_formulas_with_parameters(&Torus::new(3.0, 0.5), 0.3, 0.7)?;
    assert_eq!(torus.point[0].plain(), "cos(s)*(R + r*cos(t))");
    assert_eq!(torus.dst[0].plain(), "r*sin(s)*sin(t)");
    // a surface without parameters gives what surface_formulas gives
    assert_eq!(
        surface_formulas_with_parameters(&Enneper, 0.3, 0.7)?,
        surface_formulas(&Enneper, 0.3, 0.7)?
    );
    Ok(())
}

#[test]
fn parameters_that_cannot_be_symbols_are_refused() {
    assert!(matches!(
        surface_formulas_with_parameters(&Named { s: 1.0 }, 0.3, 0.7),
        Err(Error::Degenerate { .. })
    ));
    // as numbers they are fine
    assert_eq!(
        surface_formulas(&Named { s: 2.0 }, 0.3, 0.7).unwrap().point[2].plain(),
        "2*s"
    );
    assert!(matches!(
        surface_formulas_with_parameters(
            &Wave {
                k: f64::NAN,
                a: 1.0
            },
            0.3,
            0.7
        ),
        Err(Error::NonFinite { .. })
    ));
    struct Twice;
    impl ParametricSurface for Twice {
        fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
            Vector3::new(s, t, s * t)
        }
        fn parameters(&self) -> Vec<(&'static str, f64)> {
            vec![("c", 1.0), ("c", 2.0)]
        }
    }
    assert!(matches!(
        surface_formulas_with_parameters(&Twice, 0.3, 0.7),
        Err(Error::Degenerate { .. })
    ));
}

/// The lines of a plain table, each cell starting in its column.
fn aligned(table: &str, cells: &[&str]) {
    let starts: Vec<usize> = cells
        .iter()
        .map(|c| {
            let line = table
                .lines()
                .find(|l| l.contains(c))
                .unwrap_or_else(|| panic!("{c} in\n{table}"));
            line.find(c).unwrap()
        })
        .collect();
    assert!(
        starts.windows(2).all(|w| w[0] == w[1]),
        "{starts:?} in\n{table}"
    );
}

#[test]
fn every_formula_set_prints_as_a_plain_table() -> splinelab::Result<()> {
    let f = surface_formulas(&Enneper, 0.5, 0.25)?;
    let text = f.to_string();
    for row in ["X ", "X_s", "X_t", "X_st"] {
        assert!(text.lines().any(|l| l.starts_with(row)), "{row} in\n{text}");
    }
    // the y column: one start for every row
    aligned(&text, &["t + s^2*t - t^3/3", "1 + s^2 - t^2"]);
    aligned(&text, &["s^2 - t^2", "-2*t"]);
    assert!(!text.contains("Sum {"), "no expression tree: {text}");

    let spline = HermiteSurface::uniform(&Enneper, &Rect::new(0.0, 1.0, 0.0, 1.0), 3, 3)?;
    let patch = patch_formulas(&spline.patch(1, 1))?.to_string();
    for part in [
        "H₀(s)",
        "1 - 3*s^2 + 2*s^3",
        "C_x",
        "[29/81, 2/27, 4/27, 38/81;",
        "z ",
    ] {
        assert!(patch.contains(part), "{part} in\n{patch}");
    }
    let basis = BSplineBasis::try_new(KnotVector::open_uniform(2, 4, 0.0, 1.0)?, 2)?;
    let b = bspline_basis_formulas(&basis, 0.3)?.to_string();
    assert!(b.contains("N") && b.lines().count() >= 3, "{b}");
    let curve = BSplineCurve::try_new(
        basis,
        vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 2.0),
            Vector2::new(2.0, 0.0),
            Vector2::new(3.0, 1.0),
        ],
    )?;
    let c = curve_formulas(&curve, 0.3)?.to_string();
    assert!(c.contains("C") && c.contains("t"), "{c}");
    let traced = trace([("x", 0.5)], |[x]| vec![x.sin() * 2.0, x * x])?;
    assert_eq!(traced.to_string(), "2*sin(x)\nx^2");
    Ok(())
}

#[test]
fn a_spline_on_fractions_prints_fractions() -> splinelab::Result<()> {
    // the case: thirds of [0, 1], data computed in f64 from fractions
    let spline = HermiteSurface::uniform(&Enneper, &Rect::new(0.0, 1.0, 0.0, 1.0), 3, 3)?;
    let patch = patch_formulas(&spline.patch(1, 1))?;
    assert_eq!(
        patch.x[0].plain(),
        "29/81 + s/3 + 2*t/27 - s^2/27 + 2*s*t/27 + t^2/27 - s^3/81 + s*t^2/27"
    );
    // in global parameters it is Enneper's polynomial, every rounding term gone
    let global = surface_formulas(&spline, 0.5, 0.5)?;
    assert_eq!(global.point[1].plain(), "t + s^2*t - t^3/3");
    assert_eq!(global.dst[1].plain(), "2*s");
    // sevenths: data with denominators up to 3 · 7³
    let sevenths = HermiteSurface::uniform(&Enneper, &Rect::new(0.0, 1.0, 0.0, 1.0), 7, 7)?;
    let global = surface_formulas(&sevenths, 0.5, 0.5)?;
    assert_eq!(global.point[0].plain(), "s - s^3/3 + s*t^2");
    // numbers that are only floating point stay numbers: the torus's spline data are cosines
    let torus = HermiteSurface::uniform(&Torus::default(), &Rect::unit(), 2, 2)?;
    let t = patch_formulas(&torus.patch(0, 0))?;
    assert!(t.x[0].plain().contains('.'), "{}", t.x[0].plain());
    // and no entry of its matrices is printed as a fraction by chance (all or nothing:
    // -2.524413 is within rounding of -2158055/854874, and is not a fraction)
    for k in 0..4 {
        let text = patch_formulas(&torus.patch(k / 2, k % 2))?.to_string();
        for line in text.lines().filter(|l| l.starts_with("C_")) {
            assert!(!line.contains('/'), "{line}");
        }
    }
    let seed = HermiteSurface::uniform(&Torus::default(), &Rect::new(0.0, 1.0, 0.0, 1.0), 1, 1)?;
    let text = patch_formulas(&seed.patch(0, 0))?.to_string();
    assert!(!text.contains("2158055"), "{text}");
    Ok(())
}

/// A polynomial surface of degree ≤ 3 in each variable with small fractions as
/// coefficients: `z = Σ c_ij sⁱ tʲ` (`x = s`, `y = t`).
#[derive(Debug, Clone)]
struct Bicubic {
    c: [[f64; 4]; 4],
}

impl ParametricSurface for Bicubic {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        let mut z = D::from(0.0);
        for (i, row) in self.c.iter().enumerate() {
            for (j, c) in row.iter().enumerate() {
                z += s.powi(i as i32) * t.powi(j as i32) * *c;
            }
        }
        Vector3::new(s, t, z)
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The spline of a bicubic with fractional coefficients, on a partition of `[0, 1]` into
    /// halves, thirds or quarters, reproduces it, and its formulas print its fractions: no
    /// decimal anywhere (before, the rounding of the data printed as `0.9999999999999902*t`
    /// and `1.7985612998927536e-14*s^2`), and the formula is the polynomial (evaluated at
    /// three points against the exact sum).
    #[test]
    fn splines_of_fractional_bicubics_print_fractions(
        num in proptest::collection::vec(-9i32..=9, 16),
        // every datum a fraction with a denominator within the reading's 2²⁰: the data of
        // c sⁱ tʲ at nodes k/n have denominators up to 12 · 4⁶
        den in proptest::collection::vec(prop::sample::select(vec![1i32, 2, 3, 4]), 16),
        n in 1usize..=4,
    ) {
        let mut c = [[0.0; 4]; 4];
        for k in 0..16 {
            c[k / 4][k % 4] = f64::from(num[k]) / f64::from(den[k]);
        }
        let surface = Bicubic { c };
        let spline = HermiteSurface::uniform(&surface, &Rect::unit(), n, n).unwrap();
        let f = surface_formulas(&spline, 0.5, 0.5).unwrap();
        let z = f.point[2].plain();
        prop_assert!(!z.contains('.') && !z.contains('e'), "{}", z);
        for (s, t) in [(0.1, 0.9), (0.45, 0.55), (0.7, 0.2)] {
            let exact: f64 = (0..16).map(|k| c[k / 4][k % 4] * f64::powi(s, (k / 4) as i32) * f64::powi(t, (k % 4) as i32)).sum();
            prop_assert!((f.point[2].eval(&[s, t]) - exact).abs() <= 1e-12 * (1.0 + exact.abs()));
        }
    }
}

#[test]
fn studies_say_when_the_error_is_rounding() -> splinelab::Result<()> {
    let rect = Rect::new(-1.0, 1.0, -1.0, 1.0);
    let ns = [1, 2, 4, 8];
    // Enneper is bicubic: the spline reproduces it, every error is rounding, no order
    let rows = convergence(&Enneper, &rect, &ns, 15)?;
    for row in &rows {
        assert!(row.rounding > 0.0 && row.rounding < 1e-12);
        for k in 0..3 {
            assert!(row.at_rounding(row.errors.max_abs[k]), "{row:?}");
        }
        if let Some(o) = row.order {
            assert_eq!(o.max_abs, [None; 3]);
            assert_eq!(o.rms, [None; 3]);
            assert_eq!(o.report_norm, [None; 3]);
        }
    }
    // the rounding level: ROUNDING_ULPS ε × the largest coordinate (5/3 at s = t = ±1)
    let expected = ROUNDING_ULPS * f64::EPSILON * 5.0 / 3.0;
    assert!((rows[0].rounding - expected).abs() < 1e-3 * expected);
    // the associate-like wave: x, y linear (reproduced), z converging as h⁴
    let w = Wave { k: 2.0, a: 1.0 };
    let rows = convergence(&w, &rect, &[2, 4, 8, 16], 15)?;
    let last = rows.last().unwrap().order.unwrap();
    assert_eq!(last.max_abs[0], None);
    assert!((last.max_abs[2].unwrap() - 4.0).abs() < 0.15, "{last:?}");
    Ok(())
}

#[cfg(feature = "report")]
#[test]
fn the_convergence_table_and_figure_say_so_too() -> Result<(), splinelab::report::Error> {
    use splinelab::report::{draw, table};
    let rect = Rect::new(-1.0, 1.0, -1.0, 1.0);
    let rows = convergence(&Enneper, &rect, &[1, 2, 4], 9)?;
    let t = table::convergence("enneper", "Enneper", &rows)?;
    assert!(
        t.notes
            .iter()
            .any(|n| n.contains("Coordinates x, y, z reach the rounding level")),
        "{:?}",
        t.notes
    );
    let svg = draw::convergence(&rows, "Enneper").to_svg()?;
    assert!(svg.contains("rounding level"), "the level is drawn");
    assert!(svg.contains("coordinate x: at rounding level"));
    assert!(
        !svg.contains("reference slope"),
        "no slope drawn through rounding"
    );
    // a converging coordinate: the slope is anchored on the coarsest row's largest error
    let rows = convergence(&Wave { k: 2.0, a: 1.0 }, &rect, &[1, 2, 4], 9)?;
    let svg = draw::convergence(&rows, "wave").to_svg()?;
    assert!(svg.contains("reference slope"));
    // log ticks at powers of ten only: no 0.0631 or 0.158 beside data at h = 0.0625…
    for odd in [">0.0631<", ">0.158<", ">0.251<", ">0.398<", ">0.631<"] {
        assert!(!svg.contains(odd), "{odd}");
    }
    let svg_text = svg.replace('\n', "");
    assert!(
        svg_text.contains(">0.1<") && svg_text.contains(">1<"),
        "{svg}"
    );
    Ok(())
}

/// The labelled edges of x and y meet at a corner of a 3-D figure's box: Enneper's surface
/// on `[-1.5, 1.5]²` has both x and y ranges ending near ±4, and both axes printed a "4.0"
/// there, one on top of the other. Now x's labels keep clear of its ends: one "4.0" is left.
#[cfg(feature = "report")]
#[test]
fn a_3d_figure_prints_one_label_at_the_corner_x_and_y_share() -> Result<(), splinelab::report::Error>
{
    let r = Rect::new(-1.5, 1.5, -1.5, 1.5);
    let svg = Plot3d::new("Enneper")
        .surface(&Enneper, &r, 20)?
        .figure()
        .to_svg()?;
    let text = svg.replace('\n', "");
    assert_eq!(text.matches(">4.0<").count(), 1, "one 4.0 label");
    assert!(
        text.contains(">2.0<") && text.contains(">-2.0<"),
        "the other labels stay"
    );
    Ok(())
}
