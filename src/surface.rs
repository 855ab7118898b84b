//! Parametric surfaces written once, generic over the number type, with exact partials.
//!
//! Seed 000 §2 (Codice 3) obtains `X_s`, `X_t` and `X_st` of the torus with MATLAB's
//! Symbolic Math Toolbox (`diff`). Here a surface is one formula generic over
//! [`DualNum`]; evaluated at hyper-dual numbers `s + ε₁`, `t + ε₂` it returns
//! `X + X_s ε₁ + X_t ε₂ + X_st ε₁ε₂` exactly (to rounding), with no symbolic algebra and no
//! finite differences.

use crate::domain::Rect;
use crate::error::{Error, Result};
use crate::grid::Grid;
use nalgebra::Vector3;
use num_dual::{DualNum, HyperDual64};

/// A parametric surface `X(s, t) ∈ ℝ³` given by one formula generic over the number type.
///
/// Implement [`ParametricSurface::eval`] once; `f64` gives points, [`num_dual::Dual64`] first
/// derivatives, [`HyperDual64`] the point with `X_s`, `X_t` and the mixed `X_st` (see
/// [`SurfaceDerivatives`], implemented for every `ParametricSurface`).
///
/// # Examples
/// ```
/// use splinelab::{ParametricSurface, SurfaceDerivatives, Torus};
/// let torus = Torus::default();
/// let d = torus.partials(0.3, 0.7);
/// // X_st of the x coordinate is sin t sin s (seed 000 §2, Codice 3)
/// assert!((d.dst.x - 0.7f64.sin() * 0.3f64.sin()).abs() < 1e-15);
/// assert_eq!(torus.parameters(), vec![("R", 2.0), ("r", 1.0)]);
/// ```
///
/// Written out by hand (what [`crate::surface!`] writes for you), a surface with a parameter:
/// ```
/// use nalgebra::Vector3;
/// use num_dual::DualNum;
/// use splinelab::{ParametricSurface, SurfaceDerivatives};
///
/// /// A helicoid of pitch `c`.
/// pub struct Helicoid {
///     pub c: f64,
/// }
///
/// impl ParametricSurface for Helicoid {
///     fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
///         self.eval_with(s, t, &[D::from(self.c)])
///     }
///     fn parameters(&self) -> Vec<(&'static str, f64)> {
///         vec![("c", self.c)]
///     }
///     fn eval_with<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D, p: &[D]) -> Vector3<D> {
///         let c = p.first().copied().unwrap_or(D::from(self.c));
///         Vector3::new(t * s.cos(), t * s.sin(), c * s)
///     }
/// }
///
/// let h = Helicoid { c: 0.5 };
/// assert_eq!(h.partials(0.0, 2.0).ds, Vector3::new(0.0, 2.0, 0.5)); // (−t sin s, t cos s, c)
/// let f = splinelab::symbolic::surface_formulas_with_parameters(&h, 0.0, 2.0)?;
/// assert_eq!(f.ds[2].plain(), "c");
/// # Ok::<(), splinelab::Error>(())
/// ```
pub trait ParametricSurface {
    /// `X(s, t)`. Must be written only with operations of [`DualNum`] so that derivatives
    /// propagate.
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D>;

    /// The pieces of a piecewise surface that [`ParametricSurface::eval`] uses at `(s, t)`:
    /// the spans in `s` and in `t` on which the formula traced there holds
    /// ([`crate::symbolic::surface_formulas`]). `None` (the default) for a surface that is one
    /// formula everywhere; the spline surfaces of the crate override it.
    fn span_at(&self, s: f64, t: f64) -> Option<[crate::domain::Span; 2]> {
        let _ = (s, t);
        None
    }

    /// The surface's named parameters and their values, in the order
    /// [`ParametricSurface::eval_with`] takes them: `[("R", 2.0), ("r", 1.0)]` for
    /// [`Torus::default`], the fields of a [`crate::surface!`] with fields. Empty (the
    /// default) for a surface without parameters.
    fn parameters(&self) -> Vec<(&'static str, f64)> {
        Vec::new()
    }

    /// `X(s, t)` with the parameters given as numbers of the evaluation's type, in the order
    /// of [`ParametricSurface::parameters`] (a missing one takes the surface's own value):
    /// what lets [`crate::symbolic::surface_formulas_with_parameters`] print them as symbols
    /// (`cos(s)*(R + r*cos(t))`). A surface with parameters writes its formula here once and
    /// its `eval` calls this with its own values; the default ignores `parameters` and calls
    /// `eval`.
    fn eval_with<D: DualNum<Primitive = f64> + Copy>(
        &self,
        s: D,
        t: D,
        parameters: &[D],
    ) -> Vector3<D> {
        let _ = parameters;
        self.eval(s, t)
    }
}

/// A point and its first partials and mixed second partial, `X, X_s, X_t, X_st`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Partials {
    /// `X(s, t)`.
    pub point: Vector3<f64>,
    /// `∂X/∂s`.
    pub ds: Vector3<f64>,
    /// `∂X/∂t`.
    pub dt: Vector3<f64>,
    /// `∂²X/∂s∂t`.
    pub dst: Vector3<f64>,
}

impl Partials {
    /// Reads the four parts of a hyper-dual vector `X + X_s ε₁ + X_t ε₂ + X_st ε₁ε₂`.
    pub fn from_hyperdual(x: &Vector3<HyperDual64>) -> Self {
        Self {
            point: x.map(|d| d.re),
            ds: x.map(|d| d.eps1),
            dt: x.map(|d| d.eps2),
            dst: x.map(|d| d.eps1eps2),
        }
    }
}

/// What the Hermite machinery needs of a surface: points and exact partials in `f64`.
///
/// Every [`ParametricSurface`] has it (through hyper-dual numbers); [`FnSurface`] gives it
/// to a user closure written over [`HyperDual64`].
pub trait SurfaceDerivatives {
    /// `X(s, t)`.
    fn point(&self, s: f64, t: f64) -> Vector3<f64>;
    /// `X, X_s, X_t, X_st` at `(s, t)`.
    fn partials(&self, s: f64, t: f64) -> Partials;
}

/// Seeds `s + ε₁` and `t + ε₂` (num-dual's `derivative1`/`derivative2`).
fn seeded(s: f64, t: f64) -> (HyperDual64, HyperDual64) {
    (
        HyperDual64::from_re(s).derivative1(),
        HyperDual64::from_re(t).derivative2(),
    )
}

impl<S: ParametricSurface + ?Sized> SurfaceDerivatives for S {
    fn point(&self, s: f64, t: f64) -> Vector3<f64> {
        self.eval(s, t)
    }

    fn partials(&self, s: f64, t: f64) -> Partials {
        let (s, t) = seeded(s, t);
        Partials::from_hyperdual(&self.eval(s, t))
    }
}

/// Defines a [`ParametricSurface`] `Name` by one expression in `s` and `t`, generic over the
/// number type — the way to write one's own surface once and get its points, its exact
/// partials (hyper-dual numbers) *and* its formulas ([`crate::symbolic::surface_formulas`]),
/// since a closure cannot be generic.
///
/// - `surface!(pub Enneper = |s, t| …)` defines a unit struct; the visibility (`pub`,
///   `pub(crate)`, none) is the struct's, so a library crate can export its surfaces.
/// - `surface!(pub Associate { theta: f64 } = |s, t| …)` defines a struct with `f64` fields
///   (its parameters, as visible as the struct). In the expression each field is a number of
///   the evaluation's type (`theta.cos()`), so
///   [`crate::symbolic::surface_formulas_with_parameters`] prints it as a symbol
///   (`cos(theta)`) and [`crate::symbolic::surface_formulas`] as its value.
/// - Attributes and doc comments before the name go on the struct.
///
/// Literals go on the right of an operator (`s * 2.0`); the expression sees
/// [`num_dual::DualNum`]'s functions (`sin`, `exp`, `powi`, `sqrt`, …) and whatever is in
/// scope where the macro is called (`Vector3` from the prelude).
///
/// ```
/// use splinelab::prelude::*;
/// use splinelab::symbolic::{surface_formulas, surface_formulas_with_parameters};
///
/// surface!(
///     /// Enneper's minimal surface.
///     pub Enneper = |s, t| Vector3::new(
///         s - s.powi(3) / 3.0 + s * t * t,
///         t - t.powi(3) / 3.0 + t * s * s,
///         s * s - t * t,
///     )
/// );
/// // the catenoid (θ = π/2) bent into the helicoid (θ = 0)
/// surface!(pub Associate { theta: f64 } = |s, t| {
///     let (c, d) = (theta.cos(), theta.sin());
///     Vector3::new(
///         c * t.sinh() * s.sin() + d * t.cosh() * s.cos(),
///         d * t.cosh() * s.sin() - c * t.sinh() * s.cos(),
///         c * s + d * t,
///     )
/// });
///
/// assert_eq!(Enneper.partials(0.5, 0.25).dst, Vector3::new(0.5, 1.0, 0.0)); // (2t, 2s, 0)
/// assert_eq!(surface_formulas(&Enneper, 0.5, 0.25)?.point[0].plain(), "s - s^3/3 + s*t^2");
///
/// let bent = Associate { theta: std::f64::consts::FRAC_PI_4 };
/// assert_eq!(bent.parameters(), vec![("theta", std::f64::consts::FRAC_PI_4)]);
/// let f = surface_formulas_with_parameters(&bent, 0.5, 0.25)?;
/// assert_eq!(f.point[2].plain(), "s*cos(theta) + t*sin(theta)");
/// # Ok::<(), splinelab::Error>(())
/// ```
///
/// **In an evcxr notebook** put the call in a module and import the struct: evcxr keeps the
/// items of a cell (structs, modules, `use`) from cell to cell but runs a macro call alone
/// inside a function, where its struct would not outlive the cell (notebook 02's *Try it*):
///
/// ```
/// mod mine {
///     use splinelab::prelude::*;
///     surface!(pub Wave { k: f64 } = |s, t| Vector3::new(s, t, (s * k).sin()));
/// }
/// use mine::Wave;
/// use splinelab::prelude::*;
/// let wave = Wave { k: 2.0 };
/// assert_eq!(wave.partials(0.0, 0.0).ds.z, 2.0);
/// ```
#[macro_export]
macro_rules! surface {
    ($(#[$meta:meta])* $vis:vis $name:ident = |$s:ident, $t:ident| $body:expr $(,)?) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
        $vis struct $name;
        impl $crate::ParametricSurface for $name {
            fn eval<D: $crate::num_dual::DualNum<Primitive = f64> + Copy>(
                &self,
                $s: D,
                $t: D,
            ) -> $crate::nalgebra::Vector3<D> {
                #[allow(unused_imports)]
                use $crate::num_dual::DualNum as _;
                $body
            }
        }
    };
    ($(#[$meta:meta])* $vis:vis $name:ident { $($field:ident : f64),+ $(,)? }
        = |$s:ident, $t:ident| $body:expr $(,)?) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq)]
        $vis struct $name {
            $(
                #[allow(missing_docs)]
                $vis $field: f64,
            )+
        }
        impl $crate::ParametricSurface for $name {
            fn eval<D: $crate::num_dual::DualNum<Primitive = f64> + Copy>(
                &self,
                s: D,
                t: D,
            ) -> $crate::nalgebra::Vector3<D> {
                self.eval_with(s, t, &[$(D::from(self.$field)),+])
            }
            fn parameters(&self) -> ::std::vec::Vec<(&'static str, f64)> {
                ::std::vec![$((::std::stringify!($field), self.$field)),+]
            }
            fn eval_with<D: $crate::num_dual::DualNum<Primitive = f64> + Copy>(
                &self,
                $s: D,
                $t: D,
                parameters: &[D],
            ) -> $crate::nalgebra::Vector3<D> {
                #[allow(unused_imports)]
                use $crate::num_dual::DualNum as _;
                let mut given = parameters.iter().copied();
                $(
                    let $field: D = given.next().unwrap_or_else(|| D::from(self.$field));
                )+
                $body
            }
        }
    };
}

/// A user surface given as a closure over hyper-dual numbers.
///
/// Rust closures cannot be generic, so the closure is written for [`HyperDual64`], the
/// richest type needed; points are its real part.
///
/// # Examples
/// ```
/// use nalgebra::Vector3;
/// use num_dual::{DualNum, HyperDual64};
/// use splinelab::{FnSurface, SurfaceDerivatives};
/// let saddle = FnSurface::new(|s: HyperDual64, t: HyperDual64| Vector3::new(s, t, s * t));
/// assert_eq!(saddle.partials(2.0, 3.0).dst.z, 1.0);
/// ```
pub struct FnSurface<F> {
    f: F,
}

impl<F> FnSurface<F>
where
    F: Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64>,
{
    /// Wraps the closure `f(s, t)`.
    pub fn new(f: F) -> Self {
        Self { f }
    }
}

/// The closure type of [`FnSurface::boxed`]: a boxed `Fn(HyperDual64, HyperDual64) ->
/// Vector3<HyperDual64>`, a type that can be named, so the surface can be kept in a variable
/// of a notebook (evcxr must name the type of every variable it keeps between cells, and a
/// closure's own type has no name).
pub type SurfaceFn = Box<dyn Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64> + Send + Sync>;

impl FnSurface<SurfaceFn> {
    /// Wraps the closure `f(s, t)` in a box, for a surface kept in a notebook variable.
    ///
    /// # Examples
    /// ```
    /// use splinelab::prelude::*;
    /// let bump = FnSurface::boxed(|s, t| Vector3::new(s, t, (s * t).sin()));
    /// assert_eq!(bump.partials(0.0, 2.0).ds.z, 2.0);
    /// ```
    pub fn boxed(
        f: impl Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64> + Send + Sync + 'static,
    ) -> Self {
        Self { f: Box::new(f) }
    }
}

impl<F> SurfaceDerivatives for FnSurface<F>
where
    F: Fn(HyperDual64, HyperDual64) -> Vector3<HyperDual64>,
{
    fn point(&self, s: f64, t: f64) -> Vector3<f64> {
        (self.f)(HyperDual64::from_re(s), HyperDual64::from_re(t)).map(|d| d.re)
    }

    fn partials(&self, s: f64, t: f64) -> Partials {
        let (s, t) = seeded(s, t);
        Partials::from_hyperdual(&(self.f)(s, t))
    }
}

use crate::error::positive;

/// The torus of seed 000 §2 (Codice 1):
/// `x = (R + r cos t) cos s`, `y = (R + r cos t) sin s`, `z = r sin t`, with `R = 2`, `r = 1`
/// by default.
///
/// Closed-form partials (used by the tests): `X_s = (−(R + r cos t) sin s, (R + r cos t) cos s, 0)`,
/// `X_t = (−r sin t cos s, −r sin t sin s, r cos t)`, `X_st = (r sin t sin s, −r sin t cos s, 0)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Torus {
    major: f64,
    minor: f64,
}

impl Default for Torus {
    /// The report's torus, `R = 2`, `r = 1`.
    fn default() -> Self {
        Self {
            major: 2.0,
            minor: 1.0,
        }
    }
}

impl Torus {
    /// A torus with major radius `major` (`R`) and minor radius `minor` (`r`).
    ///
    /// # Panics
    /// On a non-positive or non-finite radius; see [`Torus::try_new`].
    pub fn new(major: f64, minor: f64) -> Self {
        Self::try_new(major, minor).expect("invalid torus radii")
    }

    /// A torus with major radius `major` (`R`) and minor radius `minor` (`r`).
    ///
    /// # Errors
    /// [`Error::NotPositive`] unless both radii are positive and finite;
    /// [`Error::CoordinateTooLarge`] if `R + r` (the largest coordinate of a point, and a
    /// bound on every partial) exceeds [`crate::error::MAX_COORDINATE`].
    pub fn try_new(major: f64, minor: f64) -> Result<Self> {
        let torus = Self {
            major: positive("torus major radius", major)?,
            minor: positive("torus minor radius", minor)?,
        };
        crate::error::derived_coordinate("torus R + r", major + minor)?;
        Ok(torus)
    }

    /// Major radius `R`.
    pub fn major(&self) -> f64 {
        self.major
    }

    /// Minor radius `r`.
    pub fn minor(&self) -> f64 {
        self.minor
    }
}

impl ParametricSurface for Torus {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        self.eval_with(s, t, &[D::from(self.major), D::from(self.minor)])
    }

    /// `R` (major) and `r` (minor).
    fn parameters(&self) -> Vec<(&'static str, f64)> {
        vec![("R", self.major), ("r", self.minor)]
    }

    fn eval_with<D: DualNum<Primitive = f64> + Copy>(
        &self,
        s: D,
        t: D,
        parameters: &[D],
    ) -> Vector3<D> {
        let major = parameters.first().copied().unwrap_or(D::from(self.major));
        let minor = parameters.get(1).copied().unwrap_or(D::from(self.minor));
        let (sin_s, cos_s) = s.sin_cos();
        let (sin_t, cos_t) = t.sin_cos();
        let ring = cos_t * minor + major;
        Vector3::new(ring * cos_s, ring * sin_s, sin_t * minor)
    }
}

/// A sphere of radius `ρ` in longitude `s` and latitude `t`:
/// `X = ρ (cos t cos s, cos t sin s, sin t)`; `X_st = ρ (sin t sin s, −sin t cos s, 0)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    radius: f64,
}

impl Default for Sphere {
    /// The unit sphere.
    fn default() -> Self {
        Self { radius: 1.0 }
    }
}

impl Sphere {
    /// A sphere of radius `radius`.
    ///
    /// # Panics
    /// On a non-positive or non-finite radius; see [`Sphere::try_new`].
    pub fn new(radius: f64) -> Self {
        Self::try_new(radius).expect("invalid sphere radius")
    }

    /// A sphere of radius `radius`.
    ///
    /// # Errors
    /// [`Error::NotPositive`] unless the radius is positive and finite;
    /// [`Error::CoordinateTooLarge`] above [`crate::error::MAX_COORDINATE`].
    pub fn try_new(radius: f64) -> Result<Self> {
        Ok(Self {
            radius: crate::error::coordinate("sphere radius", positive("sphere radius", radius)?)?,
        })
    }

    /// Radius `ρ`.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

impl ParametricSurface for Sphere {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        let (sin_s, cos_s) = s.sin_cos();
        let (sin_t, cos_t) = t.sin_cos();
        Vector3::new(cos_t * cos_s, cos_t * sin_s, sin_t) * D::from(self.radius)
    }
}

/// A test surface whose mixed partial is non-zero everywhere in every coordinate:
/// `X = (e^{s+t}, e^{s−t}, sinh s sinh t)`, so `X_st = (e^{s+t}, −e^{s−t}, cosh s cosh t)`.
///
/// On the torus `X_st` vanishes wherever `sin t = 0`, which hides mistakes in the twist
/// entries of the Hermite and Bézier matrices (see the README's finding on Codice 7); this
/// surface hides none.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ExpSurface;

impl ParametricSurface for ExpSurface {
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, s: D, t: D) -> Vector3<D> {
        Vector3::new((s + t).exp(), (s - t).exp(), s.sinh() * t.sinh())
    }
}

/// Tabulates `X` on the `ns × nt` grid `linspace(sₐ, s_b, ns) × linspace(tₐ, t_b, nt)`;
/// row `i` is `sᵢ`, column `j` is `tⱼ` (the layout of `X'` in Codice 14).
///
/// # Errors
/// [`Error::TooFewSamples`] if `ns < 2` or `nt < 2`; [`Error::TooLarge`] if `ns · nt`
/// exceeds [`crate::error::MAX_ELEMENTS`]; [`Error::NonFiniteSurface`] where the surface
/// returns a NaN or infinite point.
pub fn tabulate<S: SurfaceDerivatives + ?Sized>(
    surface: &S,
    rect: &Rect,
    ns: usize,
    nt: usize,
) -> Result<Grid<Vector3<f64>>> {
    let s = rect.s.linspace_named("ns", ns)?;
    let t = rect.t.linspace_named("nt", nt)?;
    let grid = Grid::try_from_fn(ns, nt, |i, j| surface.point(s[i], t[j]))?;
    if let Some(k) = grid
        .as_slice()
        .iter()
        .position(|p| !p.iter().all(|x| x.is_finite()))
    {
        return Err(Error::NonFiniteSurface {
            s: s[k / nt],
            t: t[k % nt],
        });
    }
    Ok(grid)
}

/// Whether every component of a partials record is finite.
/// `0` if every value of `p` is finite, NaN otherwise (branch-free: `Σ v · 0`).
#[inline]
fn zero_unless_non_finite(p: &Partials) -> f64 {
    let z = |v: &Vector3<f64>| (v.x * 0.0 + v.y * 0.0) + v.z * 0.0;
    (z(&p.point) + z(&p.ds)) + (z(&p.dt) + z(&p.dst))
}

pub(crate) fn partials_finite(p: &Partials) -> bool {
    [p.point, p.ds, p.dt, p.dst]
        .iter()
        .all(|v| v.iter().all(|x| x.is_finite()))
}

/// `X, X_s, X_t, X_st` at every node of `s_nodes × t_nodes` (row `i` is `s_nodes[i]`).
///
/// Large grids are split into blocks of rows evaluated on all available cores.
///
/// # Errors
/// As [`partials_on_grid_into`].
pub fn partials_on_grid<S: SurfaceDerivatives + Sync + ?Sized>(
    surface: &S,
    s_nodes: &[f64],
    t_nodes: &[f64],
) -> Result<Grid<Partials>> {
    let mut out = Vec::new();
    partials_on_grid_into(surface, s_nodes, t_nodes, &mut out)?;
    Ok(Grid::from_vec(s_nodes.len(), t_nodes.len(), out).expect("filled rows × cols"))
}

/// Below this many nodes a grid is evaluated on the calling thread only.
const PARALLEL_MIN_NODES: usize = 16_384;

/// As [`partials_on_grid`], writing row-major into `out` (resized) so a caller that
/// evaluates repeatedly reuses one buffer.
///
/// # Errors
/// [`Error::TooLarge`] if the node count overflows or exceeds
/// [`crate::error::MAX_ELEMENTS`] (nothing is allocated); [`Error::NonFiniteSurface`] at the
/// first node (in row-major order) where a point or partial is NaN or infinite (`out` then
/// holds the values computed, unchecked).
pub fn partials_on_grid_into<S: SurfaceDerivatives + Sync + ?Sized>(
    surface: &S,
    s_nodes: &[f64],
    t_nodes: &[f64],
    out: &mut Vec<Partials>,
) -> Result<()> {
    let zero = Partials {
        point: Vector3::zeros(),
        ds: Vector3::zeros(),
        dt: Vector3::zeros(),
        dst: Vector3::zeros(),
    };
    let cols = t_nodes.len();
    let len = crate::error::size_product("surface grid nodes", s_nodes.len(), cols)?;
    // every slot is written below: a buffer of the right length is reused as it is (not
    // cleared first, which would write its megabytes once more)
    out.resize(len, zero);
    if cols == 0 {
        return Ok(());
    }
    // each block reports whether all its values are finite: branch-free, folded into the
    // loop that computes them (`v · 0` is 0 for a finite `v` and NaN otherwise, and a sum
    // with a NaN is NaN), so the check costs a few multiply-adds per node
    let fill = |rows: &[f64], block: &mut [Partials]| -> bool {
        let mut ok = true;
        for (&s, row) in rows.iter().zip(block.chunks_mut(cols)) {
            for (&t, p) in t_nodes.iter().zip(row.iter_mut()) {
                *p = surface.partials(s, t);
            }
            // the row again while it is in the cache, in a loop of its own that vectorises
            let nan_if_not_finite: f64 = row.iter().map(zero_unless_non_finite).sum();
            ok &= nan_if_not_finite == 0.0;
        }
        ok
    };
    let threads = crate::parallel::cores();
    let all_finite = if threads == 1 || out.len() < PARALLEL_MIN_NODES {
        fill(s_nodes, out)
    } else {
        let rows_per = s_nodes.len().div_ceil(threads);
        std::thread::scope(|scope| {
            let mut blocks = s_nodes
                .chunks(rows_per)
                .zip(out.chunks_mut(rows_per * cols));
            // the first block here, the others on threads of their own (one spawn fewer)
            let first = blocks.next();
            let handles: Vec<_> = blocks
                .map(|(rows, block)| scope.spawn(move || fill(rows, block)))
                .collect();
            let here = first.is_none_or(|(rows, block)| fill(rows, block));
            // a panic in the user's surface is propagated as it would be on one thread
            handles.into_iter().fold(here, |ok, h| {
                ok & h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))
            })
        })
    };
    if !all_finite {
        let k = out.iter().position(|p| !partials_finite(p)).unwrap_or(0);
        return Err(Error::NonFiniteSurface {
            s: s_nodes[k / cols],
            t: t_nodes[k % cols],
        });
    }
    Ok(())
}
