//! Interpolation: polynomial (power basis, Lagrange), piecewise linear, cubic splines with
//! four end conditions, B-spline collocation, and parametrizations (seeds 001 and 004).

pub mod collocation;
pub mod cubic;
pub mod linear;
pub mod param;
pub mod polynomial;

use crate::error::{finite, Error, Result};

/// Checks interpolation abscissae (or parameters): finite and strictly increasing.
///
/// # Errors
/// [`Error::NonFinite`]; [`Error::RepeatedParameter`] for two equal values;
/// [`Error::NotIncreasing`] for a decrease.
pub(crate) fn check_sites(what: &'static str, x: &[f64]) -> Result<()> {
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
        prev = v;
    }
    Ok(())
}

/// Finds the interval `[xᵢ, xᵢ₊₁)` of a sequence of points, starting at the previous one, so
/// sorted input costs a comparison or two per point; any order stays correct. The right end
/// belongs to the last interval; points outside go to the nearest end interval.
pub(crate) struct IntervalCursor<'a> {
    nodes: &'a [f64],
    i: usize,
}

impl<'a> IntervalCursor<'a> {
    /// A cursor over `nodes` (at least 2, increasing).
    pub(crate) fn new(nodes: &'a [f64]) -> Self {
        Self { nodes, i: 0 }
    }

    /// The interval index of `x`.
    #[inline]
    pub(crate) fn find(&mut self, x: f64) -> usize {
        let last = self.nodes.len() - 2;
        let i = self.i;
        let in_current = (i == 0 || self.nodes[i] <= x) && (i == last || x < self.nodes[i + 1]);
        if !in_current {
            if i < last && self.nodes[i + 1] <= x && (i + 1 == last || x < self.nodes[i + 2]) {
                self.i = i + 1;
            } else {
                let inner = &self.nodes[1..self.nodes.len() - 1];
                self.i = inner.partition_point(|&node| node <= x);
            }
        }
        self.i
    }
}
