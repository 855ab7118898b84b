//! Interpolating cubic splines with clamped, natural, periodic and anticyclic ends, built in
//! O(n) (seed 001, "Spline cubiche di interpolazione"; seed 004 §2 for the anticyclic ends).

use crate::curve::ParametricCurve;
use crate::domain::IntervalCursor;
use crate::error::{finite_points, Error, Result};
use crate::lanes::SPARSE_BLOCK;
use crate::param::Parametrization;
use crate::tridiagonal::{solve, solve_twisted, Band, Row};
use nalgebra::{SVector, Vector1};
use num_dual::{Dual2_64, DualNum};

/// The two extra conditions that make the interpolating cubic spline unique.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndCondition<const N: usize> {
    /// Given end derivatives `s′(x₀) = start`, `s′(x_n) = end` (seed 001 "derivata agli
    /// estremi data"; seed 004 *clamped end*).
    Clamped {
        /// `s′(x₀)`.
        start: SVector<f64, N>,
        /// `s′(x_n)`.
        end: SVector<f64, N>,
    },
    /// `s″(x₀) = s″(x_n) = 0` (seed 001 "naturale"; seed 004 *relaxed*).
    Natural,
    /// `s′(x₀) = s′(x_n)`, `s″(x₀) = s″(x_n)`, for data with `y₀ = y_n` (seed 001 "periodica";
    /// seed 004 *cyclic*).
    Periodic,
    /// `s′(x₀) = s′(x_n)`, `s″(x₀) = s″(x_n)` for data whose ends need not coincide: seed
    /// 004's *cyclic* as the paper uses it, "for pieces of a curve that repeats at intervals"
    /// (one period of a sinusoid, whose end points differ; spec decision A7). The moment
    /// equations are those of [`EndCondition::Periodic`]; only the end values are left alone.
    Cyclic,
    /// `s′(x₀) = −s′(x_n)`, `s″(x₀) = −s″(x_n)` (seed 004 *anticyclic*, `P′₁ = −P′ₙ`,
    /// `P″₁ = −P″ₙ`); the data ends are free.
    Anticyclic,
}

impl EndCondition<1> {
    /// Clamped ends for a spline function: `s′(x₀) = start`, `s′(x_n) = end`.
    pub fn clamped(start: f64, end: f64) -> Self {
        EndCondition::Clamped {
            start: Vector1::new(start),
            end: Vector1::new(end),
        }
    }
}

impl<const N: usize> EndCondition<N> {
    /// Fewest data points the condition needs.
    fn min_points(&self) -> usize {
        match self {
            EndCondition::Clamped { .. } | EndCondition::Natural => 2,
            EndCondition::Periodic | EndCondition::Cyclic | EndCondition::Anticyclic => 3,
        }
    }
}

/// Relative tolerance for "the ends of periodic data match":
/// `‖y₀ − y_n‖_∞ ≤ 1e-12 · max ‖yᵢ‖_∞` (data read from files rarely repeat the first point bit
/// for bit). `y_n` is then replaced by `y₀`, so the spline misses `y_n` by at most this much
/// of the data scale — within [`crate::interp::RESIDUAL_TOLERANCE`].
pub const PERIODIC_MATCH: f64 = 1e-12;

/// An interpolating cubic spline `s : [x₀, x_n] → ℝᴺ` (`N = 1`: a spline function `y(x)`;
/// `N = 2, 3`: a parametric curve), stored as its nodes `xᵢ`, values `yᵢ` and second
/// derivatives (moments) `Mᵢ = s″(xᵢ)`.
///
/// The moments satisfy at every interior node (continuity of `s′`)
///
/// `hᵢ₋₁ Mᵢ₋₁ + 2(hᵢ₋₁ + hᵢ) Mᵢ + hᵢ Mᵢ₊₁ = 6(δᵢ − δᵢ₋₁)`, `hᵢ = xᵢ₊₁ − xᵢ`, `δᵢ = (yᵢ₊₁ − yᵢ)/hᵢ`,
///
/// closed by the [`EndCondition`]: a tridiagonal system (clamped, natural) or a cyclic one
/// (periodic: corners `+h_{n−1}`; anticyclic: `M_n = −M₀` gives corners `−h_{n−1}`), all
/// strictly diagonally dominant and solved in O(n) for all coordinates at once. On
/// `[xᵢ, xᵢ₊₁]`, with `u = (x − xᵢ)/hᵢ` and `v = 1 − u`, the spline is evaluated in its
/// moment form
///
/// `s(x) = yᵢ v + yᵢ₊₁ u + (hᵢ²/6)[Mᵢ (v³ − v) + Mᵢ₊₁ (u³ − u)]
///       = yᵢ v + yᵢ₊₁ u − u v [Mᵢ (1 + v) + Mᵢ₊₁ (1 + u)] hᵢ²/6`
///
/// (de Boor, *A Practical Guide to Splines*, ch. IV), which reproduces both end values of
/// every piece exactly (`u = 0` and `u = (xᵢ₊₁ − xᵢ)/hᵢ = 1` are exact), so the spline
/// interpolates its data bit for bit, and involves no large power coefficient that could
/// cancel (the power form `aᵢ + bᵢ h + …` with `bᵢ = δᵢ − hᵢ(2Mᵢ + Mᵢ₊₁)/6` loses digits at
/// the right end of a piece when the mesh is very uneven). A spline costs 3 numbers per
/// node and coordinate; each piece's data are gathered once per piece in
/// [`CubicSpline::eval_many`].
///
/// # Examples
/// ```
/// use splinelab::{CubicSpline, EndCondition, ParametricCurve};
/// let x = [0.0, 1.0, 2.0, 3.0];
/// let y = [0.0, 1.0, 0.0, 1.0];
/// let s = CubicSpline::function(&x, &y, EndCondition::Natural).unwrap();
/// assert!((s.value(2.0) - 0.0).abs() < 1e-15);
/// assert!(s.second_derivative(0.0).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CubicSpline<const N: usize> {
    x: Vec<f64>,
    y: Vec<SVector<f64, N>>,
    m: Vec<SVector<f64, N>>,
    end: EndCondition<N>,
}

impl<const N: usize> CubicSpline<N> {
    /// The spline with `s(xᵢ) = yᵢ` and the end condition `end`.
    ///
    /// # Errors
    /// [`Error::CountMismatch`] unless `x` and `y` have the same length;
    /// [`Error::TooFewPoints`] below 2 points (3 for periodic, cyclic and anticyclic ends);
    /// [`Error::NonFinite`] for NaN or infinite data; [`Error::RepeatedParameter`] or
    /// [`Error::NotIncreasing`] unless `x` strictly increases; [`Error::GapTooSmall`] for
    /// abscissae closer than `f64::MIN_POSITIVE`; [`Error::TooLarge`] beyond
    /// [`crate::error::MAX_ELEMENTS`] points; [`Error::PeriodicEndsMismatch`] for periodic
    /// ends with `y₀ ≠ y_n` (beyond [`PERIODIC_MATCH`]); [`Error::Overflow`] if a derived
    /// slope, moment or scaled moment overflows. (No residual can fail: the moment form
    /// reproduces the data exactly, and the moment system is strictly diagonally dominant,
    /// so its solve is stable whatever the mesh.)
    pub fn try_new(x: &[f64], y: &[SVector<f64, N>], end: EndCondition<N>) -> Result<Self> {
        Self::unbuilt(end).refit(x, y)
    }

    /// A spline with empty buffers, only to be rebuilt (by [`CubicSpline::rebuild`]): the one
    /// path of a new spline and a refit.
    fn unbuilt(end: EndCondition<N>) -> Self {
        Self {
            x: Vec::new(),
            y: Vec::new(),
            m: Vec::new(),
            end,
        }
    }

    /// The spline through new data `(xᵢ, yᵢ)` with the same end condition, built in the
    /// buffers of `self`: for data of the size `self` was built for, nothing is allocated and
    /// no fresh memory is touched (its first touch costs as much as the solve on large data).
    /// On error the buffers are freed with `self`.
    ///
    /// # Examples
    /// ```
    /// use nalgebra::Vector1;
    /// use splinelab::{CubicSpline, EndCondition};
    /// let x = [0.0, 1.0, 2.0, 3.0];
    /// let s = CubicSpline::function(&x, &[0.0, 1.0, 0.0, 1.0], EndCondition::Natural).unwrap();
    /// let s = s.refit(&x, &[1.0, 0.0, 1.0, 0.0].map(Vector1::new)).unwrap();
    /// assert_eq!(s.value(1.0), 0.0);
    /// ```
    ///
    /// # Errors
    /// As [`CubicSpline::try_new`].
    pub fn refit(self, x: &[f64], y: &[SVector<f64, N>]) -> Result<Self> {
        self.rebuild(x, y.len(), |ys| ys.extend_from_slice(y))
    }

    /// The spline through `x` and the `len` values `fill` writes into the emptied value buffer,
    /// built in the buffers of `self` (empty ones for a new spline, [`CubicSpline::unbuilt`]);
    /// buffers too small are replaced by new ones asked for in huge pages where the system
    /// can (their first touch costs as much as the solve on large data).
    fn rebuild(
        self,
        x: &[f64],
        len: usize,
        fill: impl FnOnce(&mut Vec<SVector<f64, N>>),
    ) -> Result<Self> {
        let Self {
            x: mut xs,
            mut y,
            mut m,
            end,
        } = self;
        y.clear();
        crate::memory::reserve(&mut y, len);
        fill(&mut y);
        let widest = check_spline_data(x, &y, &end)?;
        let n = x.len() - 1;
        if let EndCondition::Periodic = end {
            y[n] = y[0]; // equal within PERIODIC_MATCH: make it exact
        }
        if xs.capacity() < x.len() {
            // zeroed by the allocator, untouched until the solve writes it (on two cores)
            xs = vec![0.0; x.len()];
            crate::memory::advise(&xs);
        } else {
            xs.resize(x.len(), 0.0);
        }
        crate::memory::reserve(&mut m, x.len());
        m.resize(x.len(), SVector::zeros());
        let largest = moments(x, &y, &end, &mut xs, &mut m)?;
        let spline = Self { x: xs, y, m, end };
        spline.verify(widest, largest)?;
        Ok(spline)
    }

    /// Checks what the build derived: every moment is finite, and so is the bound
    /// `|yᵢ| + |yᵢ₊₁| + (|Mᵢ| + |Mᵢ₊₁|) hᵢ²/6` of the piece on its interval, so every
    /// evaluation in the domain is finite. Interpolation
    /// itself needs no check: the moment form reproduces `yᵢ` and `yᵢ₊₁` exactly.
    ///
    /// # Errors
    /// [`Error::Overflow`] for a moment, scaled moment or bound that is not finite (slopes
    /// `Δy/h` that overflow, say).
    ///
    /// `widest` is the largest gap of the abscissae and `largest` the largest `‖Mᵢ‖₁` (both
    /// known from the build): where `2 · largest · widest² ≤ f64::MAX / 4` every bound is
    /// finite (the values are within `MAX_COORDINATE`) and no pass over the pieces is needed.
    fn verify(&self, widest: f64, largest: f64) -> Result<()> {
        use crate::tridiagonal::l1;
        // NaN fails the comparison
        if 2.0 * largest * widest * widest <= f64::MAX / 4.0 {
            return Ok(());
        }
        // |d e| ≤ h²/4 and |1 + u|, |1 + v| ≤ 2 on the piece; a NaN or infinite moment makes
        // the bound non-finite too (as does an infinite one times an underflowed h²)
        let bound = |i: usize| {
            let h = self.x[i + 1] - self.x[i];
            l1(&self.y[i]) + l1(&self.y[i + 1]) + (l1(&self.m[i]) + l1(&self.m[i + 1])) * h * h
        };
        match (0..self.x.len() - 1).find(|&i| !bound(i).is_finite()) {
            None => Ok(()),
            Some(i) => Err(Error::Overflow {
                what: "cubic spline piece (moments Mᵢ hᵢ²/6 and values)",
                value: bound(i),
            }),
        }
    }

    /// The interpolating spline curve through `points` at parameters chosen by `param`
    /// (seed 001, "Curve spline di interpolazione": parameters first, then one spline per
    /// coordinate — here one solve for all coordinates). For periodic ends the first and last
    /// points must coincide (a closed curve).
    ///
    /// # Errors
    /// As [`Parametrization::parameters`] and [`CubicSpline::try_new`].
    pub fn curve(
        points: &[SVector<f64, N>],
        param: Parametrization,
        end: EndCondition<N>,
    ) -> Result<Self> {
        let t = param.parameters(points)?;
        Self::try_new(&t, points, end)
    }

    /// The abscissae (or parameters) `x₀ < … < x_n`.
    pub fn nodes(&self) -> &[f64] {
        &self.x
    }

    /// The end condition it was built with.
    pub fn end_condition(&self) -> &EndCondition<N> {
        &self.end
    }

    /// Index `i` of the interval `[xᵢ, xᵢ₊₁)` holding `x` (the right end belongs to the last;
    /// outside points to the nearest end interval, which is extrapolated).
    fn interval(&self, x: f64) -> usize {
        crate::domain::locate(&self.x, x)
    }

    /// The data of piece `i` on `[xᵢ, xᵢ₊₁]` for the moment form.
    fn piece(&self, i: usize) -> Piece<N> {
        Piece {
            x0: self.x[i],
            x1: self.x[i + 1],
            h: self.x[i + 1] - self.x[i],
            y0: self.y[i],
            y1: self.y[i + 1],
            m0: self.m[i] / 6.0,
            m1: self.m[i + 1] / 6.0,
        }
    }

    /// One-sided derivatives at the ends, `(s′(x₀), s″(x₀), s′(x_n), s″(x_n))`, each from its
    /// own end piece (what the end conditions constrain).
    pub fn end_derivatives(&self) -> [SVector<f64, N>; 4] {
        let (a, b) = self.domain();
        let last = self.x.len() - 2;
        let at = |i: usize, x: f64| {
            let c = self.piece(i).eval(Dual2_64::from_re(x).derivative());
            (c.map(|d| d.v1), c.map(|d| d.v2))
        };
        let (d1a, d2a) = at(0, a);
        let (d1b, d2b) = at(last, b);
        [d1a, d2a, d1b, d2b]
    }

    /// Evaluates at every `x` of `xs` into `out` (resized to `xs.len()`, former contents
    /// overwritten), writing `map(s(x))`. For sorted input the interval search costs a
    /// comparison or two per run of points in one piece, each piece's data are gathered once,
    /// and each run is evaluated in one branch-free loop; a lone point in its piece starts a
    /// block of [`SPARSE_BLOCK`] points (as the B-spline batches) whose intervals are found before their values. From
    /// [`crate::bspline::curve::EVAL_PARALLEL_MIN`] points (8 192 when there are fewer than four
    /// per piece, [`crate::bspline::curve::two_threads`]) the two halves of `xs` are
    /// evaluated on two threads (each point by the same arithmetic, so the values do not
    /// depend on the split). The same formula as [`CubicSpline::eval`].
    fn fill_values<T: Copy + Send>(
        &self,
        xs: &[f64],
        out: &mut Vec<T>,
        zero: T,
        map: impl Fn(SVector<f64, N>) -> T + Sync,
    ) {
        let fill = |xs: &[f64], out: &mut [T]| {
            let mut cursor = IntervalCursor::new(&self.x);
            let mut k = 0;
            while k < xs.len() {
                let i = cursor.find(xs[k]);
                let piece = self.piece(i);
                // the run that stays in [xᵢ, xᵢ₊₁) (at least xs[k], which may be the right end
                // or outside the domain)
                let (lo, hi) = (self.x[i], self.x[i + 1]);
                let run = 1 + xs[k + 1..]
                    .iter()
                    .position(|&x| !(lo <= x && x < hi))
                    .unwrap_or(xs.len() - k - 1);
                for (o, &x) in out[k..k + run].iter_mut().zip(&xs[k..k + run]) {
                    *o = map(piece.eval(x));
                }
                k += run;
                if run == 1 {
                    // a lone point in its piece (sparse or unsorted input): the next points
                    // likely too, so a block of them is taken at once — their intervals
                    // first, then their pieces, with no branch between the points, so that
                    // their cache misses are in flight together instead of one by one
                    let len = SPARSE_BLOCK.min(xs.len() - k);
                    let mut at = [0usize; SPARSE_BLOCK];
                    for (i, &x) in at.iter_mut().zip(&xs[k..k + len]) {
                        *i = cursor.find(x);
                    }
                    for ((o, &x), &i) in out[k..k + len].iter_mut().zip(&xs[k..k + len]).zip(&at) {
                        *o = map(self.piece(i).eval(x));
                    }
                    k += len;
                }
            }
        };
        // sparse points (a few per piece or fewer) each wait on memory the previous ones did
        // not bring (20 ns and more where the spline outgrows the caches), so they are worth
        // two threads from fewer points than dense ones: the B-spline batches' rule
        let parallel = crate::bspline::curve::two_threads(xs.len(), self.x.len() - 1);
        crate::parallel::fill_halves(xs, out, zero, parallel, fill);
    }

    /// Evaluates at every `x` of `xs` into `out` (resized to `xs.len()`, former contents
    /// overwritten): sorted input costs a comparison or two per piece, large batches use two
    /// cores (see `CubicSpline::fill_values`).
    pub fn eval_many(&self, xs: &[f64], out: &mut Vec<SVector<f64, N>>) {
        self.fill_values(xs, out, SVector::zeros(), |v| v);
    }
}

impl<const N: usize> ParametricCurve<N> for CubicSpline<N> {
    /// `s(x)` for any number type: at `x + ε` the derivative comes too, exact.
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, x: D) -> SVector<D, N> {
        self.piece(crate::branch::piece(&self.x, &x)).eval(x)
    }

    /// `[x₀, x_n]`.
    fn domain(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }

    /// `[xᵢ, xᵢ₊₁)`, the interval of `x`.
    fn span_at(&self, x: f64) -> Option<crate::domain::Span> {
        Some(crate::domain::Span::of(&self.x, self.interval(x)))
    }
}

impl CubicSpline<1> {
    /// The spline function through `(xᵢ, yᵢ)`.
    ///
    /// # Errors
    /// As [`CubicSpline::try_new`].
    pub fn function(x: &[f64], y: &[f64], end: EndCondition<1>) -> Result<Self> {
        Self::unbuilt(end).refit_function(x, y)
    }

    /// [`CubicSpline::refit`] for a spline function: the spline through new data
    /// `(xᵢ, yᵢ)` with the same end condition, in the buffers of `self`.
    ///
    /// # Errors
    /// As [`CubicSpline::try_new`].
    pub fn refit_function(self, x: &[f64], y: &[f64]) -> Result<Self> {
        self.rebuild(x, y.len(), |ys| {
            ys.extend(y.iter().map(|&v| Vector1::new(v)))
        })
    }

    /// `s(x)`.
    pub fn value(&self, x: f64) -> f64 {
        self.point(x).x
    }

    /// `s″(x)`, exact.
    pub fn second_derivative(&self, x: f64) -> f64 {
        self.derivatives2(x)[2].x
    }

    /// Evaluates at every `x` of `xs` into `out` (replacing its contents): [`CubicSpline::eval_many`]
    /// for scalars.
    pub fn values_into(&self, xs: &[f64], out: &mut Vec<f64>) {
        self.fill_values(xs, out, 0.0, |v| v.x);
    }
}

/// One piece of a cubic spline in moment form,
/// `s = y₀ v + y₁ u − [M₀ (1 + v) + M₁ (1 + u)] d e / 6` with `d = x − x₀`, `e = x₁ − x`,
/// `u = d/h`, `v = 1 − u` (`u v h² = d e`, so this is the form of [`CubicSpline`]). Written
/// with `d e` rather than `u v h²`, no intermediate carries a factor `1/h²`: second
/// derivatives of pieces narrower than `10⁻¹⁵⁴` stay finite.
#[derive(Debug, Clone, Copy)]
struct Piece<const N: usize> {
    x0: f64,
    x1: f64,
    h: f64,
    y0: SVector<f64, N>,
    y1: SVector<f64, N>,
    /// `M₀ / 6`.
    m0: SVector<f64, N>,
    /// `M₁ / 6`.
    m1: SVector<f64, N>,
}

impl<const N: usize> Piece<N> {
    /// `s(x)` for any number type (the piece's polynomial, also outside its interval).
    #[inline]
    fn eval<D: DualNum<Primitive = f64> + Copy>(&self, x: D) -> SVector<D, N> {
        let d = x - self.x0;
        let e = -x + self.x1;
        let u = d / self.h;
        let v = -u + 1.0;
        let lift = |w: &SVector<f64, N>| w.map(D::from);
        if D::NDERIV == 0 {
            // plain numbers: the convex chord and one product order (only derivative parts need
            // the care below); branch-free, so batch evaluation vectorizes
            return lift(&self.y0) * v + lift(&self.y1) * u
                - (lift(&self.m0) * (v + 1.0) + lift(&self.m1) * (u + 1.0)) * d * e;
        }
        let chord = crate::interp::chord(&self.y0, &self.y1, u);
        // The same product in the order that keeps every intermediate, value and derivative
        // parts alike, within the size of the true value: on a wide piece (h ≥ 1) the moments
        // first, ((M/6)(1 + v) · d) · e, so d e never overflows before it is scaled; on a narrow
        // one (M/6) · ((1 + v) · d e), so the factor 1/h in the derivative of 1 + v meets
        // d e ≤ h²/4 before it meets a large moment.
        if self.h >= 1.0 {
            chord - (lift(&self.m0) * (v + 1.0) + lift(&self.m1) * (u + 1.0)) * d * e
        } else {
            let de = d * e;
            chord - (lift(&self.m0) * ((v + 1.0) * de) + lift(&self.m1) * ((u + 1.0) * de))
        }
    }
}

/// The checks every interpolating cubic spline makes of its data, whatever the route:
/// one value per abscissa, enough points for `end`, strictly increasing finite abscissae,
/// finite values and end derivatives, and for periodic ends `y₀ = y_n` within
/// [`PERIODIC_MATCH`].
///
/// # Errors
/// As [`CubicSpline::try_new`].
pub(crate) fn check_spline_data<const N: usize>(
    x: &[f64],
    y: &[SVector<f64, N>],
    end: &EndCondition<N>,
) -> Result<f64> {
    if x.len() != y.len() {
        return Err(Error::CountMismatch {
            what: "values (one per abscissa)",
            expected: x.len(),
            got: y.len(),
        });
    }
    if x.len() < end.min_points() {
        return Err(Error::TooFewPoints {
            what: "cubic spline data",
            needed: end.min_points(),
            got: x.len(),
        });
    }
    let widest = crate::domain::check_nodes("cubic spline abscissae", x)?;
    finite_points("cubic spline value", y)?;
    match end {
        EndCondition::Clamped { start, end } => {
            finite_points("clamped end derivative", &[*start, *end])?;
        }
        EndCondition::Periodic => {
            let (first, last) = (y[0], y[y.len() - 1]);
            let scale = y.iter().map(|p| p.amax()).fold(0.0, f64::max);
            if (first - last).amax() > PERIODIC_MATCH * scale {
                return Err(Error::PeriodicEndsMismatch {
                    distance: (first - last).norm(),
                });
            }
        }
        EndCondition::Natural | EndCondition::Cyclic | EndCondition::Anticyclic => {}
    }
    Ok(widest)
}

/// The moment equations of a natural or clamped spline, row `r` being the equation of node
/// `r + offset` (natural: `offset = 1`, unknowns `M₁ … M_{n−1}`; clamped: `offset = 0`,
/// unknowns `M₀ … M_n`, whose first and last rows come from the end slopes `ends`):
///
/// - interior node `i`: `hᵢ₋₁ Mᵢ₋₁ + 2(hᵢ₋₁ + hᵢ) Mᵢ + hᵢ Mᵢ₊₁ = 6(δᵢ − δᵢ₋₁)`;
/// - clamped node 0: `2h₀M₀ + h₀M₁ = 6(δ₀ − s′(x₀))`;
/// - clamped node n: `h_{n−1}M_{n−1} + 2h_{n−1}M_n = 6(s′(x_n) − δ_{n−1})`.
struct MomentRows<'a, const N: usize> {
    x: &'a [f64],
    y: &'a [SVector<f64, N>],
    offset: usize,
    ends: Option<(SVector<f64, N>, SVector<f64, N>)>,
}

impl<const N: usize> MomentRows<'_, N> {
    #[inline(always)]
    fn h(&self, i: usize) -> f64 {
        self.x[i + 1] - self.x[i]
    }

    #[inline(always)]
    fn delta(&self, i: usize) -> SVector<f64, N> {
        (self.y[i + 1] - self.y[i]) / self.h(i)
    }
}

impl<const N: usize> Band<N> for MomentRows<'_, N> {
    #[inline(always)]
    fn row(&self, r: usize) -> Row {
        let i = r + self.offset;
        let n = self.x.len() - 1;
        if self.ends.is_some() && i == 0 {
            let h = self.h(0);
            return Row {
                sub: 0.0,
                diag: 2.0 * h,
                sup: h,
            };
        }
        if self.ends.is_some() && i == n {
            let h = self.h(n - 1);
            return Row {
                sub: h,
                diag: 2.0 * h,
                sup: 0.0,
            };
        }
        let (a, b) = (self.h(i - 1), self.h(i));
        Row {
            sub: a,
            diag: 2.0 * (a + b),
            sup: b,
        }
    }

    #[inline(always)]
    fn rhs(&self, r: usize) -> SVector<f64, N> {
        let i = r + self.offset;
        let n = self.x.len() - 1;
        match self.ends {
            Some((start, _)) if i == 0 => (self.delta(0) - start) * 6.0,
            Some((_, end)) if i == n => (end - self.delta(n - 1)) * 6.0,
            _ => (self.delta(i) - self.delta(i - 1)) * 6.0,
        }
    }
}

/// The moments `M₀ … M_n` (into `m`, `n + 1` entries) of the spline through `(xᵢ, yᵢ)` with
/// end condition `end`, and the abscissae copied into `xs` (`n + 1` entries, lent to the
/// solve as scratch first); the matrix rows are formed on the fly from the data. Natural and
/// clamped ends are solved by the twisted factorization on two cores
/// ([`crate::tridiagonal::solve_twisted`]), the cyclic systems by Thomas's algorithm with
/// Sherman–Morrison ([`crate::tridiagonal::solve`], the reference path). Returns the largest
/// `‖Mᵢ‖₁`.
fn moments<const N: usize>(
    x: &[f64],
    y: &[SVector<f64, N>],
    end: &EndCondition<N>,
    xs: &mut [f64],
    m: &mut [SVector<f64, N>],
) -> Result<f64> {
    let n = x.len() - 1;
    let h = |i: usize| x[i + 1] - x[i];
    let delta = |i: usize| (y[i + 1] - y[i]) / h(i);
    // the equation of interior node i (1 ≤ i ≤ n−1)
    let interior = |i: usize| Row {
        sub: h(i - 1),
        diag: 2.0 * (h(i - 1) + h(i)),
        sup: h(i),
    };
    let interior_rhs = |i: usize| (delta(i) - delta(i - 1)) * 6.0;
    // the largest ‖Mᵢ‖₁, tracked by the solver (M_n = ±M₀ adds nothing new)
    let largest: f64;
    match end {
        EndCondition::Natural => {
            // unknowns M₁ … M_{n−1}; M₀ = M_n = 0
            m[0] = SVector::zeros();
            m[n] = SVector::zeros();
            (xs[0], xs[n]) = (x[0], x[n]);
            let system = MomentRows {
                x,
                y,
                offset: 1,
                ends: None,
            };
            largest = solve_twisted(&system, &mut xs[1..n], &x[1..n], &mut m[1..n])?;
        }
        EndCondition::Clamped { start, end } => {
            // unknowns M₀ … M_n; rows 0 and n from s′(x₀) = start, s′(x_n) = end (see
            // MomentRows)
            let system = MomentRows {
                x,
                y,
                offset: 0,
                ends: Some((*start, *end)),
            };
            largest = solve_twisted(&system, xs, x, m)?;
        }
        EndCondition::Periodic | EndCondition::Cyclic | EndCondition::Anticyclic => {
            // unknowns M₀ … M_{n−1}; M_n = σM₀ with σ = +1 (periodic, cyclic) or −1
            // (anticyclic); the end values enter only through δ₀ and δ_{n−1}.
            // Row 0 from s′(x₀) = σ s′(x_n):
            // 2(h₀ + h_{n−1})M₀ + h₀M₁ + σh_{n−1}M_{n−1} = 6(δ₀ − σδ_{n−1});
            // node n−1's equation refers to M_n = σM₀: a corner instead of its sup entry.
            let sigma = if matches!(end, EndCondition::Anticyclic) {
                -1.0
            } else {
                1.0
            };
            let row = |i: usize| {
                if i == 0 {
                    Row {
                        sub: 0.0,
                        diag: 2.0 * (h(0) + h(n - 1)),
                        sup: h(0),
                    }
                } else {
                    let mut r = interior(i);
                    if i == n - 1 {
                        r.sup = 0.0;
                    }
                    r
                }
            };
            let rhs = |i: usize| {
                if i == 0 {
                    (delta(0) - delta(n - 1) * sigma) * 6.0
                } else {
                    interior_rhs(i)
                }
            };
            let corner = sigma * h(n - 1);
            largest = solve(row, rhs, Some((corner, corner)), &mut m[..n])?;
            m[n] = m[0] * sigma;
            xs.copy_from_slice(x);
        }
    }
    Ok(largest)
}
