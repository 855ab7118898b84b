//! The crate's one error type ([`Error`], with the policy on what is checked), its limits
//! ([`MAX_ELEMENTS`], [`MAX_COORDINATE`]) and the checks every routine shares.

use thiserror::Error;

/// The largest number of elements (samples, nodes, patches, grid cells, points) any routine
/// of the crate will allocate in one piece: `2²⁷ ≈ 1.3 · 10⁸`. A request beyond it (or
/// whose size arithmetic overflows) is [`Error::TooLarge`], never an allocation failure.
/// At 24 bytes a 3-D point this is 3 GiB, far beyond any figure or table of the reports and
/// ten times the largest benchmark workload.
pub const MAX_ELEMENTS: usize = 1 << 27;

/// The largest magnitude of a coordinate of a control point, data value or corner datum:
/// `f64::MAX / 64 ≈ 2.8 · 10³⁰⁶`. Every evaluation form of the crate is a combination of such
/// coordinates with weights whose absolute sum is at most 16 on the domain (Hermite and
/// blending bases) or 1 (B-spline, NURBS, Bézier: convex combinations), so within this
/// limit no evaluation in the domain overflows.
pub const MAX_COORDINATE: f64 = f64::MAX / 64.0;

/// Everything that can go wrong when building or evaluating splinelab objects.
///
/// Construction and tabulation return `Result<_, Error>`; evaluation of an object that was
/// validated on construction does not fail.
///
/// # What a value of this crate guarantees
///
/// - **Constructors validate what they are given and what they derive.** Inputs must be
///   finite and well formed (sorted, distinct, positive where the mathematics needs it), and so
///   must every quantity derived from them that the object relies on: interval widths, knot
///   gaps and their reciprocals, chord lengths and their sums, nodes of a uniform partition,
///   corner data of a surface, polynomial coefficients, NURBS weight ratios. A failure is a
///   typed [`Error`](enum@Error) that names the real cause.
/// - **An `Ok` value is finite and satisfies its defining property**: an interpolant
///   reproduces its data (routes that solve a possibly ill-conditioned system check their
///   residual and return [`Error::IllConditioned`] when `f64` cannot deliver it; the cubic
///   spline's moment form interpolates exactly), a basis sums to one, a partition strictly
///   increases.
/// - **Evaluation of a validated object at a finite parameter in its domain is finite** and
///   does not fail. (Polynomial interpolants are the one bounded exception: between its
///   nodes an interpolant of degree `n` can exceed its data by its Lebesgue constant, up to
///   about `2ⁿ` for equispaced nodes, so it is finite wherever its true value is below
///   `f64::MAX`.) Derivatives are exact to rounding (dual numbers, or the derivative
///   recurrence of *The NURBS Book* A2.3 where knots nearly coincide), finite wherever their
///   true value is representable. Outside the domain, curves extrapolate their end pieces.
/// - **The domain's right end is the left limit**: a piecewise object evaluated at the last
///   point of its domain gives the limit from the left of its last non-empty piece (B-spline
///   spans, partitions, cubic-spline pieces), at every derivative order. Interior breakpoints
///   belong to the piece on their right.
/// - **Sizes are limited**: a count of elements to allocate (samples, nodes, patches, grid
///   cells, control points of a printed recursive procedure) above [`MAX_ELEMENTS`], or whose
///   arithmetic overflows `usize`, is [`Error::TooLarge`]; no allocation is attempted. No
///   routine recurses to a depth that grows with its input beyond a stated limit, and every
///   iterative routine (the SVD of the report's norm) has a bounded number of iterations.
/// - **No panic, hang or abort** on any input through the `try_*` and `Result` APIs; the
///   `new`-style shorthands document the panics they turn errors into.
///
/// `Debug` prints the same message as `Display`, so an `.expect(…)`, a `?` in a notebook cell
/// or an `unwrap` shows what went wrong in words, not a dump of the variant's fields.
#[derive(Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter (bound, node, evaluation point) was NaN or infinite.
    #[error("{what} must be finite, got {value}")]
    NonFinite {
        /// Which input was not finite.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// An interval or rectangle side has zero or negative width.
    #[error("{what}: interval [{start}, {end}] must satisfy start < end")]
    EmptyInterval {
        /// Which interval.
        what: &'static str,
        /// Its start.
        start: f64,
        /// Its end.
        end: f64,
    },
    /// A partition needs at least two nodes (one patch).
    #[error("{what}: a partition needs at least 2 nodes, got {got}")]
    PartitionTooShort {
        /// Which partition.
        what: &'static str,
        /// How many nodes were given.
        got: usize,
    },
    /// Partition nodes must be strictly increasing.
    #[error("{what}: nodes must be strictly increasing, but node {index} ({value}) <= node {prev_index} ({prev})", prev_index = index - 1)]
    NotIncreasing {
        /// Which partition.
        what: &'static str,
        /// Index of the first node that is not larger than its predecessor.
        index: usize,
        /// Its value.
        value: f64,
        /// The predecessor's value.
        prev: f64,
    },
    /// A parameter must be finite and at least 0.
    #[error("{what} must be finite and at least 0, got {value}")]
    Negative {
        /// Which parameter.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A shape parameter (a radius, say) must be positive and finite.
    #[error("{what} must be positive and finite, got {value}")]
    NotPositive {
        /// Which parameter.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A count of patches was zero.
    #[error("{what}: the number of patches must be at least 1, got 0")]
    ZeroPatches {
        /// Which count.
        what: &'static str,
    },
    /// A tabulation needs at least two samples per side (both ends of the interval).
    #[error("{what}: at least 2 samples are needed, got {got}")]
    TooFewSamples {
        /// Which sample count.
        what: &'static str,
        /// How many were asked for.
        got: usize,
    },
    /// A parameter lies outside the domain of the object evaluated.
    #[error("{what} = {value} lies outside the domain [{start}, {end}]")]
    OutOfDomain {
        /// Which parameter.
        what: &'static str,
        /// Its value.
        value: f64,
        /// Domain start.
        start: f64,
        /// Domain end.
        end: f64,
    },
    /// A curve or net needs more control points than it was given.
    #[error("{what}: at least {needed} points are needed, got {got}")]
    TooFewPoints {
        /// Which input.
        what: &'static str,
        /// How many are needed.
        needed: usize,
        /// How many were given.
        got: usize,
    },
    /// Two grids that are compared have different shapes.
    #[error("grid shapes differ: {left_rows}x{left_cols} vs {right_rows}x{right_cols}")]
    ShapeMismatch {
        /// Rows of the first grid.
        left_rows: usize,
        /// Columns of the first grid.
        left_cols: usize,
        /// Rows of the second grid.
        right_rows: usize,
        /// Columns of the second grid.
        right_cols: usize,
    },
    /// A knot vector (or a basis) needs more knots.
    #[error("knot vector: at least {needed} knots are needed, got {got}")]
    TooFewKnots {
        /// How many are needed.
        needed: usize,
        /// How many were given.
        got: usize,
    },
    /// Knots must be non-decreasing.
    #[error("knot vector: knot {index} ({value}) is smaller than knot {prev_index} ({prev})", prev_index = index - 1)]
    KnotsNotSorted {
        /// Index of the first knot smaller than its predecessor.
        index: usize,
        /// Its value.
        value: f64,
        /// The predecessor's value.
        prev: f64,
    },
    /// A knot is repeated more often than the order allows (or a multiplicity is 0).
    #[error(
        "knot multiplicity {multiplicity} at breakpoint {index} is not in 1..={max} (the order)"
    )]
    MultiplicityTooHigh {
        /// Index of the breakpoint (distinct knot value).
        index: usize,
        /// Its multiplicity.
        multiplicity: usize,
        /// The largest allowed, the order `p + 1`.
        max: usize,
    },
    /// A spline order of 0 was asked for (the order is degree + 1 ≥ 1).
    #[error("the order of a spline must be at least 1, got 0")]
    ZeroOrder,
    /// A degree (or order) too low for the method.
    #[error("degree (or order) {got} is too low: at least {min} is needed")]
    DegreeTooLow {
        /// The smallest allowed.
        min: usize,
        /// What was given.
        got: usize,
    },
    /// Two inputs that must match in length do not.
    #[error("{what}: expected {expected}, got {got}")]
    CountMismatch {
        /// What is counted.
        what: &'static str,
        /// The count required.
        expected: usize,
        /// The count given.
        got: usize,
    },
    /// An index past the end of a collection.
    #[error("{what} index {index} is out of range (length {len})")]
    IndexOutOfRange {
        /// Which collection.
        what: &'static str,
        /// The index given.
        index: usize,
        /// The collection's length.
        len: usize,
    },
    /// A NURBS weight that is not positive and finite.
    #[error("weight {index} must be positive and finite, got {value}")]
    NonPositiveWeight {
        /// Index of the weight.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// NURBS weights so unequal that the rational denominator could underflow.
    #[error("weight {index} ({value:e}) is below {ratio:e} times the largest weight ({max:e})")]
    WeightRatio {
        /// Index of the weight.
        index: usize,
        /// Its value.
        value: f64,
        /// The largest weight.
        max: f64,
        /// The smallest ratio allowed ([`crate::nurbs::MIN_WEIGHT_RATIO`]).
        ratio: f64,
    },
    /// Two nodes that must strictly increase are equal (partition nodes, interpolation
    /// abscissae or parameters, breakpoints).
    #[error(
        "{what}: value {index} ({value}) repeats the previous one; the values must be distinct"
    )]
    RepeatedParameter {
        /// Which input.
        what: &'static str,
        /// Index of the repeated value.
        index: usize,
        /// The value.
        value: f64,
    },
    /// Two consecutive points coincide (a chord-based parametrization could not separate them;
    /// an Angular piece would have no chord).
    #[error("point {index} coincides with point {prev_index} (indices from 0): consecutive points must be distinct", prev_index = index.saturating_sub(1))]
    RepeatedPoint {
        /// Index of the second of the two points.
        index: usize,
    },
    /// A point returns to the one before its predecessor, `Pᵢ₊₁ = Pᵢ₋₁`: no circle passes through
    /// the three, so the Angular spline has no tangent at `Pᵢ`.
    #[error("point {next} returns to point {prev}: no circle passes through points {prev}, {index}, {next}", prev = index.saturating_sub(1), next = index.saturating_add(1))]
    ReversedPoints {
        /// Index of the middle point `i`.
        index: usize,
    },
    /// An Angular spline piece has no G¹ curve: one end tangent lies on the chord line and
    /// the other does not, or a tangent on it points back along the chord (collinear points
    /// that reverse direction). The construction's limit there is the chord with a corner at
    /// the other end, or a spike (seed 004 §3; derived in `interp::angular`).
    #[error("no G¹ Angular piece from point {point} to point {next}: {reason}", next = point.saturating_add(1))]
    NoSmoothPiece {
        /// Index of the piece's first point among the spline's points (guides included); 0
        /// from [`crate::interp::angular::classify`], which sees angles only.
        point: usize,
        /// Which limit it is.
        reason: &'static str,
    },
    /// A construction has no valid result for these inputs (a guide for a tangent pointing away
    /// from the next point, an inflection rule whose split is unusable).
    #[error("{what}: {reason}")]
    Degenerate {
        /// Which construction.
        what: &'static str,
        /// Why.
        reason: &'static str,
    },
    /// A formula captured from a trace does not equal the value the trace computed, at the
    /// trace point, within the rounding bound of both computations: a simplification (or the
    /// trace itself) is wrong, so the formula is refused rather than printed.
    #[error("the formula {formula} gives {evaluated:e} at the trace point, where the traced value is {traced:e} (allowed difference {bound:e}): it is refused")]
    FormulaCheck {
        /// The formula, as plain text (shortened if long).
        formula: String,
        /// Its value at the trace point.
        evaluated: f64,
        /// The value the traced code computed there.
        traced: f64,
        /// The largest difference rounding explains.
        bound: f64,
    },
    /// Periodic (cyclic) end conditions need data whose first and last values coincide.
    #[error(
        "periodic ends need the first and last data points to coincide; they are {distance} apart"
    )]
    PeriodicEndsMismatch {
        /// Distance between the first and last values.
        distance: f64,
    },
    /// A linear system has no unique solution (or its solve broke down numerically).
    #[error("{what} is singular")]
    SingularSystem {
        /// Which system.
        what: &'static str,
    },
    /// The Schoenberg–Whitney condition fails: a collocation site lies outside the support of
    /// its basis function, so the interpolation problem has no unique solution.
    #[error("Schoenberg–Whitney condition fails: site {index} ({site}) is outside the support [{support_start}, {support_end}) of basis function {index}")]
    SchoenbergWhitney {
        /// Index `j` of the site and of the basis function.
        index: usize,
        /// The site `x_j`.
        site: f64,
        /// Start `t_j` of the support.
        support_start: f64,
        /// End `t_{j+p+1}` of the support.
        support_end: f64,
    },
    /// A size (a count of samples, nodes, patches, points or a degree) beyond the documented
    /// limit, or whose size arithmetic overflows.
    #[error("{what}: {got} exceeds the limit of {max}")]
    TooLarge {
        /// What is counted.
        what: &'static str,
        /// The size asked for (`usize::MAX` when its computation overflowed).
        got: usize,
        /// The largest allowed.
        max: usize,
    },
    /// A quantity derived from finite inputs is not representable: a width, sum or product
    /// that overflows, a value of the user's surface that is NaN, a coefficient that
    /// overflows.
    #[error("{what} is {value}: not representable in f64 although the inputs are finite")]
    Overflow {
        /// Which derived quantity.
        what: &'static str,
        /// Its value (infinite or NaN).
        value: f64,
    },
    /// Two consecutive distinct values (knots, nodes, abscissae) are so close that the
    /// reciprocal of their gap overflows (the gap is below `f64::MIN_POSITIVE`).
    #[error("{what}: gap {gap:e} between value {index} and its predecessor is below f64::MIN_POSITIVE, its reciprocal overflows")]
    GapTooSmall {
        /// Which input.
        what: &'static str,
        /// Index of the second value.
        index: usize,
        /// The gap.
        gap: f64,
    },
    /// The computed result misses its defining property (an interpolant its data) by more
    /// than the stated tolerance: the problem is too ill-conditioned for `f64` arithmetic.
    #[error("{what}: the computed solution misses its data by {residual:e} relative to the data scale, above the tolerance {tolerance:e} (ill-conditioned)")]
    IllConditioned {
        /// Which problem.
        what: &'static str,
        /// The largest relative residual found.
        residual: f64,
        /// The tolerance it was checked against.
        tolerance: f64,
    },
    /// An iterative routine did not converge within its bounded number of iterations.
    #[error("{what} did not converge within {iterations} iterations")]
    NoConvergence {
        /// Which routine.
        what: &'static str,
        /// The bound.
        iterations: usize,
    },
    /// A surface (the user's closure, or a built-in one at parameters where its formula
    /// overflows) returned a NaN or infinite point or partial.
    #[error("the surface is not finite at (s, t) = ({s}, {t}): a point or partial derivative is NaN or infinite")]
    NonFiniteSurface {
        /// The s parameter.
        s: f64,
        /// The t parameter.
        t: f64,
    },
    /// A coordinate larger in magnitude than [`MAX_COORDINATE`].
    #[error("{what} {value:e} exceeds the coordinate limit ±{max:e} (sums of weighted points would overflow)")]
    CoordinateTooLarge {
        /// Which input.
        what: &'static str,
        /// The value.
        value: f64,
        /// The limit, [`MAX_COORDINATE`].
        max: f64,
    },
    /// A text input (a CSV file of points, an SVG path) could not be read: where and why.
    #[error("{what}, line {line}, column {column}: {message}")]
    Parse {
        /// Which input.
        what: &'static str,
        /// The line (1-based).
        line: usize,
        /// The column (1-based, in characters; for a CSV field, the field's first character).
        column: usize,
        /// What is wrong there.
        message: String,
    },
    /// A font's glyph could not be read: the bytes are not a font the reader knows, the font
    /// has no glyph for the character, or the glyph has no outline (a space).
    #[error("the glyph {ch:?}: {message}")]
    Glyph {
        /// The character asked for.
        ch: char,
        /// What is wrong.
        message: String,
    },
    /// An error of a layer built on the mathematics (the report layer's figures, files and
    /// tables) carried here by `?`, so that a function returning [`Result`] can draw and
    /// write. The conversion goes both ways and never nests: the report layer takes its own
    /// error back out of it, and one of its errors that only carries a mathematical error
    /// converts to that error.
    #[error("{0}")]
    Layer(LayerError),
}

/// The error of a layer above the mathematics, kept whole inside [`Error::Layer`] (shared,
/// so [`Error`](enum@Error) stays `Clone`), to be taken back out by the layer that made it.
#[derive(Clone)]
pub struct LayerError(std::sync::Arc<dyn std::error::Error + Send + Sync + 'static>);

impl LayerError {
    /// Keeps `error`.
    pub fn new(error: impl std::error::Error + Send + Sync + 'static) -> LayerError {
        LayerError(std::sync::Arc::new(error))
    }

    /// The error kept, if it is a `T`.
    pub fn downcast_ref<T: std::error::Error + 'static>(&self) -> Option<&T> {
        self.0.downcast_ref::<T>()
    }
}

/// Equal when they are the same error or say the same.
impl PartialEq for LayerError {
    fn eq(&self, other: &LayerError) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0) || self.0.to_string() == other.0.to_string()
    }
}

impl std::fmt::Display for LayerError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(&self.0, f)
    }
}

impl std::fmt::Debug for LayerError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(&self.0, f)
    }
}

impl std::fmt::Debug for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
    }
}

/// Shorthand for `Result<T, splinelab::Error>`. Not in the prelude (it would shadow std's
/// two-parameter `Result`): write `splinelab::Result<T>` or `Result<T, splinelab::Error>`.
///
/// # Which error type
/// The mathematics returns [`Error`](enum@Error); drawing, tables and files return
/// [`crate::report::Error`] (feature `report`), which wraps [`Error`](enum@Error). Either type takes the
/// other with `?`, so a program that computes and draws picks one for its own functions:
///
/// ```
/// # #[cfg(feature = "report")]
/// # {
/// use splinelab::prelude::*;
/// // the mathematics' error type, with a figure drawn inside
/// fn torus_figure() -> splinelab::Result<Figure> {
///     let torus = Torus::default();
///     let spline = HermiteSurface::uniform(&torus, &Rect::unit(), 2, 2)?; // splinelab::Error
///     Ok(Plot3d::new("torus").spline(&spline)?.figure()) // report::Error, converted
/// }
/// // or the report's, with the mathematics inside; std's `Result` is not shadowed
/// fn main() -> Result<(), splinelab::report::Error> {
///     let figure = torus_figure()?;
///     assert!(figure.to_png()?.len() > 1000);
///     Ok(())
/// }
/// # main().unwrap();
/// # }
/// ```
pub type Result<T> = std::result::Result<T, Error>;

/// Returns `value` if it is finite, else [`Error::NonFinite`].
pub(crate) fn finite(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NonFinite { what, value })
    }
}

/// Returns `value` if it is finite and positive, else [`Error::NotPositive`]: the one rule for
/// widths, radii and spacings.
pub(crate) fn positive(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::NotPositive { what, value })
    }
}

/// Checks that `value` is finite and at least 0.
pub(crate) fn non_negative(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::Negative { what, value })
    }
}

/// Checks that every coordinate of every point is finite and at most [`MAX_COORDINATE`] in
/// magnitude.
pub(crate) fn finite_points<const N: usize>(
    what: &'static str,
    points: &[nalgebra::SVector<f64, N>],
) -> Result<()> {
    // one branch-free pass for the common case (NaN fails the comparison too)
    let ok = points
        .iter()
        .flat_map(|p| p.iter())
        .fold(true, |ok, x| ok & (x.abs() <= MAX_COORDINATE));
    if ok {
        return Ok(());
    }
    for p in points {
        for &x in p.iter() {
            coordinate(what, x)?;
        }
    }
    Ok(())
}

/// A derived coordinate (a scaled datum, a sum of radii): [`Error::Overflow`] if NaN,
/// [`Error::CoordinateTooLarge`] if infinite or beyond [`MAX_COORDINATE`].
pub(crate) fn derived_coordinate(what: &'static str, value: f64) -> Result<f64> {
    if value.is_nan() {
        return Err(Error::Overflow { what, value });
    }
    if value.abs() <= MAX_COORDINATE {
        Ok(value)
    } else {
        Err(Error::CoordinateTooLarge {
            what,
            value,
            max: MAX_COORDINATE,
        })
    }
}

/// Returns `value` if it is finite and at most [`MAX_COORDINATE`] in magnitude.
pub(crate) fn coordinate(what: &'static str, value: f64) -> Result<f64> {
    finite(what, value)?;
    if value.abs() <= MAX_COORDINATE {
        Ok(value)
    } else {
        Err(Error::CoordinateTooLarge {
            what,
            value,
            max: MAX_COORDINATE,
        })
    }
}

/// Returns `n` if it is at least 2 and at most [`MAX_ELEMENTS`], else
/// [`Error::TooFewSamples`] or [`Error::TooLarge`].
pub(crate) fn samples(what: &'static str, n: usize) -> Result<usize> {
    if n < 2 {
        return Err(Error::TooFewSamples { what, got: n });
    }
    size(what, n)
}

/// Returns `n` if it is at most [`MAX_ELEMENTS`], else [`Error::TooLarge`].
pub(crate) fn size(what: &'static str, n: usize) -> Result<usize> {
    if n <= MAX_ELEMENTS {
        Ok(n)
    } else {
        Err(Error::TooLarge {
            what,
            got: n,
            max: MAX_ELEMENTS,
        })
    }
}

/// `a · b` if it does not overflow and is at most [`MAX_ELEMENTS`], else [`Error::TooLarge`].
pub(crate) fn size_product(what: &'static str, a: usize, b: usize) -> Result<usize> {
    size(what, a.saturating_mul(b))
}

/// `a + b` if it does not overflow and is at most [`MAX_ELEMENTS`], else [`Error::TooLarge`].
pub(crate) fn size_sum(what: &'static str, a: usize, b: usize) -> Result<usize> {
    size(what, a.saturating_add(b))
}

/// Returns `value` if it is finite, else [`Error::Overflow`] (a derived quantity).
pub(crate) fn derived(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::Overflow { what, value })
    }
}

/// Checks that every coordinate of every derived point is finite ([`Error::Overflow`]).
pub(crate) fn derived_points<const N: usize>(
    what: &'static str,
    points: &[nalgebra::SVector<f64, N>],
) -> Result<()> {
    for p in points {
        for &x in p.iter() {
            derived(what, x)?;
        }
    }
    Ok(())
}
