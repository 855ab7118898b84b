//! Parameter intervals, rectangles and partitions, validated once on construction.

use crate::error::{derived, finite, size_sum, Error, Result};

/// A closed interval `[start, end]` with finite bounds and `start < end`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    start: f64,
    end: f64,
}

impl Interval {
    /// The interval `[start, end]`.
    ///
    /// # Panics
    /// If a bound is not finite or `start >= end`; see [`Interval::try_new`].
    pub fn new(start: f64, end: f64) -> Self {
        Self::try_new(start, end).expect("invalid interval")
    }

    /// The interval `[start, end]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite bound, [`Error::EmptyInterval`] unless
    /// `start < end`; [`Error::Overflow`] if the width `end − start` overflows,
    /// [`Error::GapTooSmall`] if it is below `f64::MIN_POSITIVE` (its reciprocal, used by
    /// [`Interval::to_local`], would overflow).
    pub fn try_new(start: f64, end: f64) -> Result<Self> {
        Self::named("interval", start, end)
    }

    pub(crate) fn named(what: &'static str, start: f64, end: f64) -> Result<Self> {
        finite(what, start)?;
        finite(what, end)?;
        if start >= end {
            return Err(Error::EmptyInterval { what, start, end });
        }
        gap(what, 1, start, end)?;
        Ok(Self { start, end })
    }

    /// Left end.
    pub fn start(&self) -> f64 {
        self.start
    }

    /// Right end.
    pub fn end(&self) -> f64 {
        self.end
    }

    /// Width `end − start` (the Δu or Δv of seed 000 §5), always positive.
    pub fn width(&self) -> f64 {
        self.end - self.start
    }

    /// Local parameter `(x − start) / width` of a global one (seed 000 §5, "parametri locali").
    pub fn to_local(&self, x: f64) -> f64 {
        (x - self.start) / self.width()
    }

    /// `n` equally spaced samples from `start` to `end`, both included (MATLAB `linspace`).
    ///
    /// # Errors
    /// [`Error::TooFewSamples`] if `n < 2`.
    pub fn linspace(&self, n: usize) -> Result<Vec<f64>> {
        self.linspace_named("samples", n)
    }

    /// [`Interval::linspace`] whose error names the caller's argument `what` (`ns`, `prec`).
    pub(crate) fn linspace_named(&self, what: &'static str, n: usize) -> Result<Vec<f64>> {
        crate::error::samples(what, n)?;
        Ok(linspace(self.start, self.end, n))
    }

    /// Whether `x` lies in the closed interval.
    pub fn contains(&self, x: f64) -> bool {
        self.start <= x && x <= self.end
    }
}

/// Checks the gap `b − a > 0` between consecutive values `index − 1` and `index` is finite
/// and at least `f64::MIN_POSITIVE`, so that it and its reciprocal are representable.
///
/// # Errors
/// [`Error::Overflow`] for an infinite gap, [`Error::GapTooSmall`] for a subnormal one.
pub(crate) fn gap(what: &'static str, index: usize, a: f64, b: f64) -> Result<f64> {
    let g = derived(what, b - a)?;
    if g < f64::MIN_POSITIVE {
        return Err(Error::GapTooSmall {
            what,
            index,
            gap: g,
        });
    }
    Ok(g)
}

/// MATLAB's `linspace(a, b, n)` for `n ≥ 2`: `a + k (b − a)/(n − 1)`, `k = 0 … n−1`, with the
/// last sample set to `b` exactly, as MATLAB does, so both ends are included bit for bit.
pub(crate) fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    debug_assert!(n >= 2);
    let step = (b - a) / (n - 1) as f64;
    let mut v: Vec<f64> = (0..n).map(|k| a + k as f64 * step).collect();
    v[n - 1] = b;
    v
}

/// A parameter rectangle `[sₐ, s_b] × [tₐ, t_b]` (seed 000 §2: the portion of the surface a
/// patch interpolates).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// The s side `[sₐ, s_b]` (the rows of the Hermite matrix).
    pub s: Interval,
    /// The t side `[tₐ, t_b]` (the columns of the Hermite matrix).
    pub t: Interval,
}

impl Rect {
    /// The rectangle `[s_a, s_b] × [t_a, t_b]`.
    ///
    /// # Panics
    /// On invalid bounds; see [`Rect::try_new`].
    pub fn new(s_a: f64, s_b: f64, t_a: f64, t_b: f64) -> Self {
        Self::try_new(s_a, s_b, t_a, t_b).expect("invalid rectangle")
    }

    /// The rectangle `[s_a, s_b] × [t_a, t_b]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite bound; [`Error::EmptyInterval`] for a side
    /// of zero or negative width.
    pub fn try_new(s_a: f64, s_b: f64, t_a: f64, t_b: f64) -> Result<Self> {
        Ok(Self {
            s: Interval::named("rectangle side s", s_a, s_b)?,
            t: Interval::named("rectangle side t", t_a, t_b)?,
        })
    }

    /// The unit square `[0, 1]²`, the domain of the report's §3 and §6 experiments.
    pub fn unit() -> Self {
        Self::new(0.0, 1.0, 0.0, 1.0)
    }

    /// The square `[a, b]²`.
    ///
    /// # Errors
    /// As [`Rect::try_new`].
    pub fn square(a: f64, b: f64) -> Result<Self> {
        Self::try_new(a, b, a, b)
    }
}

/// A partition `u₀ < u₁ < … < uₙ` of an interval into `n ≥ 1` sub-intervals (seed 000 §5).
#[derive(Debug, Clone, PartialEq)]
pub struct Partition {
    nodes: Vec<f64>,
}

impl Partition {
    /// A partition from its nodes.
    ///
    /// # Panics
    /// On invalid nodes; see [`Partition::try_new`].
    pub fn new(nodes: Vec<f64>) -> Self {
        Self::try_new(nodes).expect("invalid partition")
    }

    /// A partition from its nodes.
    ///
    /// # Errors
    /// [`Error::PartitionTooShort`] for fewer than 2 nodes, [`Error::NonFinite`] for a NaN or
    /// infinite node, [`Error::RepeatedParameter`] for two equal nodes, [`Error::NotIncreasing`]
    /// for a decrease (the rule of `domain::check_nodes`, shared with every interpolation routine);
    /// [`Error::GapTooSmall`] for two nodes closer than `f64::MIN_POSITIVE`, [`Error::Overflow`]
    /// if the whole width overflows.
    pub fn try_new(nodes: Vec<f64>) -> Result<Self> {
        Self::named("partition", nodes)
    }

    /// [`Partition::try_new`] with `what` naming the input in errors.
    pub(crate) fn named(what: &'static str, nodes: Vec<f64>) -> Result<Self> {
        if nodes.len() < 2 {
            return Err(Error::PartitionTooShort {
                what,
                got: nodes.len(),
            });
        }
        check_nodes(what, &nodes)?;
        Ok(Self { nodes })
    }

    /// `n` equal sub-intervals of `[a, b]`: nodes `linspace(a, b, n + 1)` as in Codice 14.
    ///
    /// The nodes are validated as [`Partition::try_new`] does: `n` so large that consecutive
    /// nodes coincide in `f64` (e.g. `uniform(1, 1 + ε, 4)`) is an error, not a partition with
    /// repeated nodes.
    ///
    /// # Errors
    /// [`Error::ZeroPatches`] if `n = 0`; [`Error::TooLarge`] if `n + 1` exceeds
    /// [`crate::error::MAX_ELEMENTS`]; the errors of [`Interval::try_new`] for the bounds;
    /// [`Error::RepeatedParameter`], [`Error::NotIncreasing`] or [`Error::GapTooSmall`] if the
    /// nodes are not distinct in `f64`.
    pub fn uniform(a: f64, b: f64, n: usize) -> Result<Self> {
        if n == 0 {
            return Err(Error::ZeroPatches { what: "partition" });
        }
        let count = size_sum("uniform partition nodes", n, 1)?;
        Interval::named("partition", a, b)?;
        Self::named(
            "uniform partition nodes (too many sub-intervals for the width at f64 resolution)",
            linspace(a, b, count),
        )
    }

    /// The nodes `u₀ … uₙ`.
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// Number of sub-intervals `n`.
    pub fn len(&self) -> usize {
        self.nodes.len() - 1
    }

    /// Always false: a valid partition has at least one sub-interval.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The `i`-th sub-interval `[uᵢ, uᵢ₊₁]`.
    ///
    /// # Panics
    /// If `i >= self.len()`.
    pub fn interval(&self, i: usize) -> Interval {
        Interval {
            start: self.nodes[i],
            end: self.nodes[i + 1],
        }
    }

    /// The whole interval `[u₀, uₙ]`.
    pub fn span(&self) -> Interval {
        Interval {
            start: self.nodes[0],
            end: self.nodes[self.nodes.len() - 1],
        }
    }

    /// Index `i` of the sub-interval `[uᵢ, uᵢ₊₁)` holding `x`; the right end `uₙ` belongs to
    /// the last one, and points outside the span are assigned to the nearest end piece.
    pub fn locate(&self, x: f64) -> usize {
        locate(&self.nodes, x)
    }
}

/// The parameter interval of one piece of a piecewise curve or surface, on which one formula
/// holds: `[lo, hi)`, or `[lo, hi]` for the last piece (within the domain; the end pieces also
/// extrapolate beyond it where the object does).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    /// The left end (included).
    pub lo: f64,
    /// The right end.
    pub hi: f64,
    /// Whether `hi` is included (the last piece).
    pub closed: bool,
}

impl Span {
    /// Piece `k` of increasing `nodes`: `[nodes[k], nodes[k + 1])`, closed if it is the last.
    pub(crate) fn of(nodes: &[f64], k: usize) -> Span {
        Span {
            lo: nodes[k],
            hi: nodes[k + 1],
            closed: k + 2 == nodes.len(),
        }
    }

    /// Whether `x` lies in the span.
    pub fn contains(&self, x: f64) -> bool {
        x >= self.lo && (x < self.hi || (self.closed && x == self.hi))
    }
}

impl std::fmt::Display for Span {
    /// `[1/4, 1/2)`, `[3/4, 1]` (ends printed as [`crate::symbolic::number`]).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::printed::number;
        let close = if self.closed { ']' } else { ')' };
        write!(f, "[{}, {}{close}", number(self.lo), number(self.hi))
    }
}

/// Index `i` of the interval `[xᵢ, xᵢ₊₁)` of increasing `nodes` (at least 2) holding `x`: the
/// right end belongs to the last interval, points outside go to the nearest end interval
/// (which the piecewise objects extrapolate), NaN to the first. The one interval search of the
/// crate (partitions, cubic splines, piecewise linear interpolants, the batch cursor).
pub(crate) fn locate(nodes: &[f64], x: f64) -> usize {
    let inner = &nodes[1..nodes.len() - 1];
    inner.partition_point(|&node| node <= x)
}

/// [`locate`] started from the interval `hint` (any index; clamped): the same interval, found
/// by galloping from `hint` ([`partition_point_from`]), so a query `d` intervals away costs
/// `O(log d)` comparisons near the previous one instead of a search of the whole partition —
/// the batch paths' search for sorted queries.
pub(crate) fn locate_from(nodes: &[f64], hint: usize, x: f64) -> usize {
    let inner = &nodes[1..nodes.len() - 1];
    partition_point_from(inner, hint, |node| node <= x)
}

/// A guess of the index of `x` in a partition of `[lo, hi]` into `count` parts, as if they
/// were equal: `⌊(x − lo) / (hi − lo) · count⌋`, clamped to `0 … count − 1` (NaN: 0). The
/// batch cursors gallop from it when it proved near on the previous query: a query then
/// costs a few comparisons near one place whatever the previous query was, and consecutive
/// queries' memory accesses do not wait for each other (the search from the previous
/// interval makes each query's loads depend on the last one's result).
#[derive(Debug, Clone, Copy)]
pub(crate) struct UniformGuess {
    lo: f64,
    scale: f64,
    last: usize,
    /// Whether the last guess was within [`GUESS_SLACK`] of the answer.
    trusted: bool,
}

impl UniformGuess {
    /// The guess for `count ≥ 1` parts of `[lo, hi]` (a zero or non-finite scale guesses 0).
    pub(crate) fn new(lo: f64, hi: f64, count: usize) -> Self {
        let scale = count as f64 / (hi - lo);
        UniformGuess {
            lo,
            scale: if scale.is_finite() { scale } else { 0.0 },
            last: count.saturating_sub(1),
            trusted: true,
        }
    }

    /// `search(hint)` from the guess `offset + of(x)` while the guesses prove near, else
    /// from `previous`; the answer decides whether the next guess is trusted. The answer is
    /// `search`'s, whatever the hint.
    #[inline]
    pub(crate) fn search(
        &mut self,
        x: f64,
        offset: usize,
        previous: usize,
        search: impl FnOnce(usize) -> usize,
    ) -> usize {
        let g = offset + self.of(x);
        let found = search(if self.trusted { g } else { previous });
        self.trusted = found.abs_diff(g) <= GUESS_SLACK;
        found
    }

    /// The guessed index of `x`.
    #[inline]
    pub(crate) fn of(&self, x: f64) -> usize {
        // `as` saturates: negative and NaN give 0, huge values usize::MAX
        (((x - self.lo) * self.scale) as usize).min(self.last)
    }
}

/// How far (in intervals) the guess may miss and still be trusted for the next query.
pub(crate) const GUESS_SLACK: usize = 2;

/// `slice.partition_point(pred)` for a predicate true on a prefix and false after it, found
/// by galloping (exponential search) from `hint` — steps 1, 2, 4, … away from it in the
/// direction the predicate says, then a binary search of the last step. The same index as
/// `partition_point`, for every monotone `pred` and every `hint` (beyond the slice: its end).
pub(crate) fn partition_point_from(
    slice: &[f64],
    hint: usize,
    pred: impl Fn(f64) -> bool,
) -> usize {
    let len = slice.len();
    let h = hint.min(len);
    // every index below `lo` is true, every index from `hi` on false
    let (lo, hi) = if h < len && pred(slice[h]) {
        let (mut lo, mut step) = (h + 1, 1usize);
        loop {
            let j = lo.saturating_add(step - 1);
            if j >= len {
                break (lo, len);
            }
            if !pred(slice[j]) {
                break (lo, j);
            }
            lo = j + 1;
            step = step.saturating_mul(2);
        }
    } else {
        let (mut hi, mut step) = (h, 1usize);
        loop {
            if hi < step {
                break (0, hi);
            }
            let j = hi - step;
            if pred(slice[j]) {
                break (j + 1, hi);
            }
            hi = j;
            step = step.saturating_mul(2);
        }
    };
    lo + slice[lo..hi].partition_point(|&v| pred(v))
}

/// The one rule for nodes (partition nodes, interpolation abscissae, parameters): finite and
/// strictly increasing, every gap at least `f64::MIN_POSITIVE` and the whole width finite;
/// returns the widest gap `max (xᵢ₊₁ − xᵢ)` (0 below two values).
///
/// # Errors
/// [`Error::TooLarge`] beyond [`crate::error::MAX_ELEMENTS`] values; [`Error::NonFinite`];
/// [`Error::RepeatedParameter`] for two equal values; [`Error::NotIncreasing`] for a
/// decrease; [`Error::GapTooSmall`] for two values closer than `f64::MIN_POSITIVE`;
/// [`Error::Overflow`] if the whole width overflows.
pub(crate) fn check_nodes(what: &'static str, x: &[f64]) -> Result<f64> {
    crate::error::size(what, x.len())?;
    // the common case in one branch-free pass: finite, and every gap at least MIN_POSITIVE
    // (which implies strictly increasing); the loop below names the first failure
    // (gaps ≥ MIN_POSITIVE and a finite total width leave no room for a NaN or an infinity:
    // an infinite value inside makes its next gap NaN or −∞, one at an end the width infinite)
    let (gaps_ok, widest) = x.windows(2).fold((true, 0.0_f64), |(ok, widest), w| {
        let g = w[1] - w[0];
        (ok & (g >= f64::MIN_POSITIVE), widest.max(g))
    });
    let width_ok = match x {
        [] => true,
        [only] => only.is_finite(),
        [first, .., last] => (last - first).is_finite(),
    };
    if gaps_ok && width_ok {
        return Ok(widest);
    }
    let mut prev = f64::NEG_INFINITY;
    for (index, &v) in x.iter().enumerate() {
        finite(what, v)?;
        if v <= prev {
            return Err(if v < prev {
                Error::NotIncreasing {
                    what,
                    index,
                    value: v,
                    prev,
                }
            } else {
                Error::RepeatedParameter {
                    what,
                    index,
                    value: v,
                }
            });
        }
        if index > 0 {
            gap(what, index, prev, v)?;
        }
        prev = v;
    }
    if x.len() > 1 {
        gap(what, x.len() - 1, x[0], x[x.len() - 1])?;
    }
    Ok(widest)
}

/// Checks `x` is finite and in `[a, b]`: the one domain rule of curves, spline surfaces and
/// collocation sites.
///
/// # Errors
/// [`Error::NonFinite`], [`Error::OutOfDomain`].
pub(crate) fn check_domain(what: &'static str, x: f64, (a, b): (f64, f64)) -> Result<f64> {
    finite(what, x)?;
    if a <= x && x <= b {
        Ok(x)
    } else {
        Err(Error::OutOfDomain {
            what,
            value: x,
            start: a,
            end: b,
        })
    }
}

/// Finds the interval `[xᵢ, xᵢ₊₁)` of a sequence of points by galloping
/// ([`locate_from`]) from a hint: the uniform guess of the point's interval
/// ([`UniformGuess`]) while it proves within [`GUESS_SLACK`]
/// intervals, else the previous interval. Dense sorted input costs a comparison or two per
/// point, sparse input on nearly uniform nodes a few comparisons near the guess (and
/// consecutive points' loads overlap), sparse input on other nodes `O(log d)` comparisons
/// near the previous interval; any order stays correct — the interval is
/// [`locate`]'s whatever the hint. The right end belongs to the last
/// interval; points outside go to the nearest end interval, NaN to the first.
pub(crate) struct IntervalCursor<'a> {
    nodes: &'a [f64],
    i: usize,
    guess: UniformGuess,
}

impl<'a> IntervalCursor<'a> {
    /// A cursor over `nodes` (at least 2, increasing).
    pub(crate) fn new(nodes: &'a [f64]) -> Self {
        let n = nodes.len() - 1;
        Self {
            nodes,
            i: 0,
            guess: UniformGuess::new(nodes[0], nodes[n], n),
        }
    }

    /// The interval index of `x`.
    #[inline]
    pub(crate) fn find(&mut self, x: f64) -> usize {
        let (nodes, i) = (self.nodes, self.i);
        // the current interval or the next (dense sorted input): no guess needed
        let last = nodes.len() - 2;
        if (i == 0 || nodes[i] <= x) && (i + 1 >= last || x < nodes[i + 2]) {
            self.i = locate_from(nodes, i, x);
            return self.i;
        }
        self.i = self
            .guess
            .search(x, 0, i, |hint| locate_from(nodes, hint, x));
        self.i
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The galloping search is `partition_point`, exhaustively: every slice length to 40
    /// (with repeated values), every hint (beyond the end too), every query between, on and
    /// around the values, infinities and NaN; and `locate_from` is `locate`.
    #[test]
    fn galloping_search_is_partition_point() {
        for len in 0..=40usize {
            let slice: Vec<f64> = (0..len).map(|i| (i / 3) as f64).collect();
            let mut queries: Vec<f64> = (0..=2 * len + 2).map(|i| i as f64 / 6.0 - 0.5).collect();
            queries.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -0.0]);
            for &x in &queries {
                for pred in [&(|v: f64| v <= x) as &dyn Fn(f64) -> bool, &|v: f64| v < x] {
                    let want = slice.partition_point(|&v| pred(v));
                    for hint in 0..=len + 3 {
                        assert_eq!(
                            partition_point_from(&slice, hint, pred),
                            want,
                            "len {len}, hint {hint}, x {x}"
                        );
                    }
                }
            }
            if len >= 2 {
                let nodes: Vec<f64> = (0..len).map(|i| i as f64 * 0.5).collect();
                for &x in &queries {
                    for hint in 0..len + 2 {
                        assert_eq!(locate_from(&nodes, hint, x), locate(&nodes, x));
                    }
                }
            }
        }
    }

    #[test]
    fn linspace_includes_both_ends() {
        let v = linspace(0.0, 0.7, 8);
        assert_eq!(v.len(), 8);
        assert_eq!(v[0], 0.0);
        assert_eq!(v[7], 0.7, "last sample must be b exactly: {v:?}");
    }

    #[test]
    fn locate_assigns_right_end_to_last_piece() {
        let p = Partition::new(vec![0.0, 0.5, 0.9, 1.0]);
        assert_eq!(p.locate(0.0), 0);
        assert_eq!(p.locate(0.49), 0);
        assert_eq!(p.locate(0.5), 1);
        assert_eq!(p.locate(0.95), 2);
        assert_eq!(p.locate(1.0), 2);
        assert_eq!(p.locate(-3.0), 0);
        assert_eq!(p.locate(7.0), 2);
    }
}
