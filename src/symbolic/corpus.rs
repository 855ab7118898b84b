//! A corpus of objects and their traced formulas, for checking them against an independent
//! computer algebra system (`scripts/check_formulas.py` runs sympy on it): surfaces of every
//! supported function, B-spline, NURBS and Bézier curves and the interpolating splines, the
//! bases and a patch. Each entry carries its formulas as printed, which formula is the
//! derivative of which, a box where they hold, and reference values from the numeric
//! (hyper-dual) path at points of that box.

use crate::curve::ParametricCurve;
use crate::error::Result;
use crate::surface::{ParametricSurface, SurfaceDerivatives};
use crate::symbolic::{self, Formula};
use nalgebra::{SVector, Vector2, Vector3};

/// One printed formula of an entry.
#[derive(Debug, Clone, PartialEq)]
pub struct CorpusFormula {
    /// Its label (`X_x`, `X_s_x`, `C″_y`, `N_3`).
    pub label: String,
    /// The plain text as printed ([`Formula::plain`]).
    pub plain: String,
    /// The label of the formula it is a derivative of, and the variables differentiated by
    /// (`("X_x", ["s", "t"])` for `X_st_x`); `None` for a primary formula.
    pub derivative_of: Option<(String, Vec<String>)>,
}

/// One object of the corpus.
#[derive(Debug, Clone, PartialEq)]
pub struct CorpusEntry {
    /// A name (`torus`, `bspline-deg5-local`).
    pub name: String,
    /// `surface`, `curve`, `basis` or `patch`.
    pub kind: &'static str,
    /// The variables, in the formulas' order.
    pub vars: Vec<String>,
    /// For each variable, an interval where the formulas hold.
    pub region: Vec<(f64, f64)>,
    /// The formulas.
    pub formulas: Vec<CorpusFormula>,
    /// Points of the region and, at each, the value of every formula from the numeric path.
    pub samples: Vec<(Vec<f64>, Vec<f64>)>,
}

impl CorpusEntry {
    /// One JSON object (a line of `splinelab formulas`).
    pub fn to_json(&self) -> String {
        let list = |xs: &[f64]| {
            xs.iter()
                .map(|x| format!("{x:e}"))
                .collect::<Vec<_>>()
                .join(",")
        };
        let formulas = self
            .formulas
            .iter()
            .map(|f| {
                let of = match &f.derivative_of {
                    None => "null".to_string(),
                    Some((base, wrt)) => format!(
                        "{{\"base\":{},\"wrt\":[{}]}}",
                        json_string(base),
                        wrt.iter()
                            .map(|w| json_string(w))
                            .collect::<Vec<_>>()
                            .join(",")
                    ),
                };
                format!(
                    "{{\"label\":{},\"plain\":{},\"derivative_of\":{of}}}",
                    json_string(&f.label),
                    json_string(&f.plain)
                )
            })
            .collect::<Vec<_>>()
            .join(",");
        let samples = self
            .samples
            .iter()
            .map(|(at, v)| format!("{{\"at\":[{}],\"values\":[{}]}}", list(at), list(v)))
            .collect::<Vec<_>>()
            .join(",");
        format!(
            "{{\"name\":{},\"kind\":{},\"vars\":[{}],\"region\":[{}],\"formulas\":[{formulas}],\"samples\":[{samples}]}}",
            json_string(&self.name),
            json_string(self.kind),
            self.vars.iter().map(|v| json_string(v)).collect::<Vec<_>>().join(","),
            self.region
                .iter()
                .map(|(a, b)| format!("[{a:e},{b:e}]"))
                .collect::<Vec<_>>()
                .join(",")
        )
    }
}

/// A JSON string literal.
fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Points of a box: a 5-per-side grid strictly inside it.
fn grid(region: &[(f64, f64)]) -> Vec<Vec<f64>> {
    let at = |(a, b): (f64, f64), k: usize| a + (b - a) * (0.1 + 0.8 * k as f64 / 4.0);
    match region {
        [r] => (0..5).map(|k| vec![at(*r, k)]).collect(),
        [r, q] => (0..5)
            .flat_map(|i| (0..5).map(move |j| vec![at(*r, i), at(*q, j)]))
            .collect(),
        _ => Vec::new(),
    }
}

const XYZ: [&str; 3] = ["x", "y", "z"];

/// The entry of a surface traced at `(s, t)`, its formulas holding on `region`.
pub fn surface_entry<S: ParametricSurface + ?Sized>(
    name: &str,
    surface: &S,
    (s, t): (f64, f64),
    region: [(f64, f64); 2],
) -> Result<CorpusEntry> {
    let f = symbolic::surface_formulas(surface, s, t)?;
    let parts: [(&str, &[Formula; 3], &[&str]); 4] = [
        ("X", &f.point, &[]),
        ("X_s", &f.ds, &["s"]),
        ("X_t", &f.dt, &["t"]),
        ("X_st", &f.dst, &["s", "t"]),
    ];
    let mut formulas = Vec::new();
    for (label, fs, wrt) in parts {
        for (k, formula) in fs.iter().enumerate() {
            formulas.push(CorpusFormula {
                label: format!("{label}_{}", XYZ[k]),
                plain: formula.plain(),
                derivative_of: (!wrt.is_empty()).then(|| {
                    (
                        format!("X_{}", XYZ[k]),
                        wrt.iter().map(|w| w.to_string()).collect(),
                    )
                }),
            });
        }
    }
    let samples = grid(&region)
        .into_iter()
        .map(|at| {
            let d = surface.partials(at[0], at[1]);
            let values = [d.point, d.ds, d.dt, d.dst]
                .iter()
                .flat_map(|v| v.iter().copied())
                .collect();
            (at, values)
        })
        .collect();
    Ok(CorpusEntry {
        name: name.into(),
        kind: "surface",
        vars: vec!["s".into(), "t".into()],
        region: region.to_vec(),
        formulas,
        samples,
    })
}

/// The entry of a curve traced at `t` on its piece, in the piece's local variable
/// ([`symbolic::curve_formulas_local`]) when `local`.
pub fn curve_entry<const N: usize, C: ParametricCurve<N> + ?Sized>(
    name: &str,
    curve: &C,
    t: f64,
    local: bool,
) -> Result<CorpusEntry> {
    let f = if local {
        symbolic::curve_formulas_local(curve, t)?
    } else {
        symbolic::curve_formulas(curve, t)?
    };
    let origin = f.origin.unwrap_or(0.0);
    let var = if f.origin.is_some() { "u" } else { "t" };
    let (a, b) = curve.domain();
    let (lo, hi) = f.span.map_or((a, b), |s| (s.lo, s.hi));
    let region = (lo - origin, hi - origin);
    let coords = ["x", "y", "z", "w"];
    let mut formulas = Vec::new();
    for (label, fs, order) in [("C", &f.point, 0), ("C′", &f.d1, 1), ("C″", &f.d2, 2)] {
        for (k, formula) in fs.iter().enumerate() {
            formulas.push(CorpusFormula {
                label: format!("{label}_{}", coords[k % 4]),
                plain: formula.plain(),
                derivative_of: (order > 0)
                    .then(|| (format!("C_{}", coords[k % 4]), vec![var.to_string(); order])),
            });
        }
    }
    let samples = grid(&[region])
        .into_iter()
        .map(|at| {
            let [p, d1, d2] = curve.derivatives2(at[0] + origin);
            let values = [p, d1, d2]
                .iter()
                .flat_map(|v: &SVector<f64, N>| v.iter().copied())
                .collect();
            (at, values)
        })
        .collect();
    Ok(CorpusEntry {
        name: name.into(),
        kind: "curve",
        vars: vec![var.into()],
        region: vec![region],
        formulas,
        samples,
    })
}

/// The entry of functions of one variable `t` on `region` (bases), with their values from
/// the numeric path.
fn functions_entry(
    name: &str,
    labels: &str,
    fs: &[Formula],
    region: (f64, f64),
    values: impl Fn(f64) -> Vec<f64>,
) -> CorpusEntry {
    let formulas = fs
        .iter()
        .enumerate()
        .map(|(k, f)| CorpusFormula {
            label: format!("{labels}_{k}"),
            plain: f.plain(),
            derivative_of: None,
        })
        .collect();
    let samples = grid(&[region])
        .into_iter()
        .map(|at| {
            let v = values(at[0]);
            (at, v)
        })
        .collect();
    CorpusEntry {
        name: name.into(),
        kind: "basis",
        vars: vec!["t".into()],
        region: vec![region],
        formulas,
        samples,
    }
}

/// The corpus (module docs): 48 entries.
///
/// # Errors
/// The errors of the objects' constructors and of the traces (none for the corpus as
/// shipped; a formula that failed its capture check would be one).
pub fn corpus() -> Result<Vec<CorpusEntry>> {
    let mut out = surfaces()?;
    out.extend(curves()?);
    out.extend(bases()?);
    out.push(torus_patch()?);
    Ok(out)
}

/// The surfaces: the torus, the sphere, a surface of every supported function, and a Hermite
/// spline surface of the torus.
fn surfaces() -> Result<Vec<CorpusEntry>> {
    use crate::surface;
    let mut out = Vec::new();
    let unit = [(0.2, 1.2), (0.3, 1.1)];
    let at = (0.6, 0.7);
    out.push(surface_entry(
        "torus",
        &crate::surface::Torus::new(2.0, 1.0),
        at,
        unit,
    )?);
    out.push(surface_entry(
        "sphere",
        &crate::surface::Sphere::new(1.5),
        at,
        unit,
    )?);
    macro_rules! surfaces {
        ($($name:literal => |$s:ident, $t:ident| $body:expr,)*) => {
            $({
                surface!(S = |$s, $t| $body);
                out.push(surface_entry($name, &S, at, unit)?);
            })*
        };
    }
    surfaces! {
        "saddle" => |s, t| Vector3::new(s, t, s * t),
        "monkey-saddle" => |s, t| Vector3::new(s, t, s * s * s - s * t * t * 3.0),
        "helicoid" => |s, t| Vector3::new(s * t.cos(), s * t.sin(), t),
        "catenoid" => |s, t| Vector3::new(t.cosh() * s.cos(), t.cosh() * s.sin(), t),
        "enneper" => |s, t| Vector3::new(
            s - s * s * s / 3.0 + s * t * t,
            t - t * t * t / 3.0 + s * s * t,
            s * s - t * t
        ),
        "exp" => |s, t| Vector3::new(s, t, (s * t).exp()),
        "gaussian" => |s, t| Vector3::new(s, t, (-(s * s) - t * t).exp()),
        "ln" => |s, t| Vector3::new(s, t, (s * s + t * t + 1.0).ln()),
        "ln-product" => |s, t| Vector3::new(s, t, s.ln() * t),
        "sqrt" => |s, t| Vector3::new(s, t, (s * t + 1.0).sqrt()),
        "sqrt-product" => |s, t| Vector3::new(s, t, (s * t).sqrt()),
        "cbrt" => |s, t| Vector3::new(s, t, (s + t + 2.0).cbrt()),
        "tan" => |s, t| Vector3::new(s, t, (s * t * 0.5).tan()),
        "asin" => |s, t| Vector3::new(s, t, (s * t * 0.5).asin()),
        "acos" => |s, t| Vector3::new(s, t, (s * t * 0.5).acos()),
        "atan" => |s, t| Vector3::new(s, t, (s / t).atan()),
        "sinh-cosh" => |s, t| Vector3::new(s.sinh() * t, s.cosh() * t, s),
        "tanh" => |s, t| Vector3::new(s, t, (s - t).tanh()),
        "asinh" => |s, t| Vector3::new(s, t, (s * t).asinh()),
        "acosh" => |s, t| Vector3::new(s, t, (s + t + 1.5).acosh()),
        "atanh" => |s, t| Vector3::new(s, t, (s * t / 3.0).atanh()),
        "powf" => |s, t| Vector3::new(s, t, (s * s + t * t + 1.0).powf(1.5)),
        "atan2" => |s, t| Vector3::new(s, t, t.atan2(s)),
        "trig-mix" => |s, t| Vector3::new(s.sin() * t.cos(), s.cos() * t.sin(), (s + t).sin()),
        "rational" => |s, t| Vector3::new(s / (t * t + 1.0), t / (s * s + 1.0), s * t / (s + t)),
    }
    let torus = crate::surface::Torus::new(2.0, 1.0);
    let spline = crate::hermite::spline_surface::HermiteSurface::uniform(
        &torus,
        &crate::domain::Rect::unit(),
        4,
        4,
    )?;
    out.push(surface_entry(
        "hermite-spline-of-torus",
        &spline,
        (0.3, 0.6),
        [(0.25, 0.5), (0.5, 0.75)],
    )?);
    Ok(out)
}

/// The curves: B-splines (in `t` and in the piece's local variable), a Bézier, NURBS circles,
/// cubic, Hermite, cardinal, Angular and linear splines, and two exact shapes.
fn curves() -> Result<Vec<CorpusEntry>> {
    let mut out = Vec::new();
    let zigzag: Vec<Vector2<f64>> = (0..8)
        .map(|i| Vector2::new(i as f64, ((i * 7) % 5) as f64))
        .collect();
    for (order, t) in [(3, 2.5), (4, 1.3), (6, 2.7)] {
        let c = crate::bspline::curve::BSplineCurve::with_order(zigzag.clone(), order)?;
        let (a, b) = c.domain();
        let at = a + (b - a) * t / 3.0;
        out.push(curve_entry(
            &format!("bspline-order{order}"),
            &c,
            at,
            false,
        )?);
        out.push(curve_entry(
            &format!("bspline-order{order}-local"),
            &c,
            at,
            true,
        )?);
    }
    let mut knots = vec![0.0; 6];
    knots.extend([1.21, 1.5]);
    knots.extend(vec![2.0; 6]);
    let deg5 = crate::bspline::curve::BSplineCurve::new(
        crate::bspline::basis::BSplineBasis::new(crate::bspline::knots::KnotVector::new(knots), 5),
        (0..8)
            .map(|i| Vector2::new(i as f64 * 0.3, ((i * 3) % 4) as f64 * 0.7))
            .collect(),
    );
    out.push(curve_entry("bspline-deg5-interior", &deg5, 1.3, false)?);
    out.push(curve_entry(
        "bspline-deg5-interior-local",
        &deg5,
        1.3,
        true,
    )?);
    let control: Vec<Vector2<f64>> = [(0.0, 0.0), (1.0, 2.0), (3.0, 3.0), (4.0, 0.0), (5.0, 1.0)]
        .iter()
        .map(|&(x, y)| Vector2::new(x, y))
        .collect();
    let bezier = crate::bspline::curve::BSplineCurve::with_order(control.clone(), control.len())?;
    out.push(curve_entry("bezier-quartic", &bezier, 0.4, false)?);
    let circle9 = crate::nurbs::NurbsCurve::circle9(Vector2::new(0.0, 0.0), 1.0)?;
    out.push(curve_entry("nurbs-circle9", &circle9, 0.1, true)?);
    let circle7 = crate::nurbs::NurbsCurve::circle7(Vector2::new(1.0, 2.0), 2.0)?;
    out.push(curve_entry("nurbs-circle7", &circle7, 0.4, true)?);
    let x = [0.0, 0.7, 1.5, 2.0, 3.1];
    let y: Vec<SVector<f64, 2>> = x
        .iter()
        .map(|&v: &f64| SVector::<f64, 2>::new(v.sin(), v.cos() * 0.5))
        .collect();
    let cubic = crate::interp::cubic::CubicSpline::try_new(
        &x,
        &y,
        crate::interp::cubic::EndCondition::Natural,
    )?;
    out.push(curve_entry("cubic-spline-natural", &cubic, 1.7, true)?);
    let hermite = crate::hermite::curve::HermiteCurve::try_new(
        vec![0.0, 1.0, 2.5],
        vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 1.0),
            Vector2::new(2.0, 0.0),
        ],
        vec![
            Vector2::new(1.0, 0.0),
            Vector2::new(1.0, 0.5),
            Vector2::new(0.0, -1.0),
        ],
    )?;
    out.push(curve_entry("hermite-curve", &hermite, 1.6, true)?);
    let cardinal = crate::interp::cardinal::CardinalSpline::try_new(control.clone(), 0.5)?;
    out.push(curve_entry("cardinal", &cardinal, 1.4, true)?);
    let angular = crate::interp::angular::AngularSpline::try_new(control.clone())?;
    out.push(curve_entry("angular", &angular, 0.3, true)?);
    out.push(curve_entry("angular-second-piece", &angular, 1.7, true)?);
    let linear = crate::interp::linear::PiecewiseLinear::try_new(&x, &y)?;
    out.push(curve_entry("piecewise-linear", &linear, 1.1, true)?);
    out.push(curve_entry(
        "ellipse",
        &crate::shapes::Shape::Ellipse { ratio: 0.4 },
        1.0,
        false,
    )?);
    out.push(curve_entry(
        "hyperbola",
        &crate::shapes::Shape::Hyperbola { b: 2.0 },
        0.5,
        false,
    )?);
    Ok(out)
}

/// The bases: Hermite, Bernstein of two degrees, a B-spline basis on a span.
fn bases() -> Result<Vec<CorpusEntry>> {
    let mut out = Vec::new();
    let h = symbolic::hermite_basis_formulas()?;
    out.push(functions_entry("hermite-basis", "H", &h, (0.0, 1.0), |t| {
        crate::hermite::basis::hermite_basis(t).to_vec()
    }));
    for n in [3, 5] {
        let b = symbolic::bernstein_formulas(n)?;
        out.push(functions_entry(
            &format!("bernstein-{n}"),
            "B",
            &b,
            (0.0, 1.0),
            move |t| crate::bezier::bernstein::bernstein_all(n, t).unwrap_or_default(),
        ));
    }
    let basis = crate::bspline::basis::BSplineBasis::new(
        crate::bspline::knots::KnotVector::new(vec![
            0.0, 0.0, 0.0, 0.0, 0.5, 1.2, 2.0, 2.0, 2.0, 2.0,
        ]),
        3,
    );
    let bf = symbolic::bspline_basis_formulas(&basis, 0.8)?;
    let first = bf.first;
    out.push(functions_entry(
        "bspline-basis-span",
        "N",
        &bf.functions,
        (bf.span.lo, bf.span.hi),
        |t| {
            (0..=3)
                .map(|j| basis.cox_de_boor(first + j, 3, t))
                .collect()
        },
    ));
    Ok(out)
}

/// The Hermite patch of the torus as `H(s)ᵀ C H(t)`.
fn torus_patch() -> Result<CorpusEntry> {
    let torus = crate::surface::Torus::new(2.0, 1.0);
    let patch =
        crate::hermite::patch::HermitePatch::from_surface(&torus, &crate::domain::Rect::unit());
    let pf = symbolic::patch_formulas(&patch)?;
    let formulas =
        pf.x.iter()
            .enumerate()
            .map(|(k, f)| CorpusFormula {
                label: format!("X_{}", XYZ[k]),
                plain: f.plain(),
                derivative_of: None,
            })
            .collect();
    let region = [(0.0, 1.0), (0.0, 1.0)];
    let samples = grid(&region)
        .into_iter()
        .map(|at| {
            let v = patch.eval(at[0], at[1]);
            (at, v.iter().copied().collect())
        })
        .collect();
    Ok(CorpusEntry {
        name: "hermite-patch-of-torus".into(),
        kind: "patch",
        vars: vec!["s".into(), "t".into()],
        region: region.to_vec(),
        formulas,
        samples,
    })
}
