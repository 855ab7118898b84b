//! Timing a workload ([`run`], [`run_sized`], [`sweep`]): a warm-up, then repeated runs for
//! a time budget, the median reported as a [`BenchResult`] (one JSON line each).

use super::workloads::{traffic, workload, Workload};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// One measured workload at one size.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchResult {
    /// Workload id.
    pub workload: &'static str,
    /// The workload's size parameter (its [`Workload::unit`]).
    pub size: usize,
    /// Points (or nodes) produced by one run.
    pub points: usize,
    /// Median wall time of one run, seconds.
    pub seconds: f64,
}

/// The HTML class of a notebook output that is a timing (scripts/check_notebooks.py skips it
/// when it compares a notebook's stored outputs with a fresh run's).
pub const TIMING_CLASS: &str = "timing";

impl BenchResult {
    /// Points per second.
    pub fn throughput(&self) -> f64 {
        self.points as f64 / self.seconds
    }

    /// The least bytes one run moves between the processor and memory ([`traffic`]) per
    /// second, if the workload's traffic is modelled.
    pub fn bandwidth(&self) -> Option<f64> {
        traffic(self.workload, self.size).map(|b| b as f64 / self.seconds)
    }

    /// The run as a labelled one-row table (size, points, median seconds, points per
    /// second) for a notebook.
    pub fn html(&self) -> crate::report::notebook::Html {
        crate::report::notebook::values(
            self.workload,
            &["size", "points", "median time (s)", "points / s"],
            &[(
                "one run",
                &[
                    self.size as f64,
                    self.points as f64,
                    self.seconds,
                    self.throughput(),
                ],
            )],
        )
    }

    /// Shows [`BenchResult::html`] in a notebook (the evcxr kernel calls this for a cell's
    /// value), inside a `<div class="timing">`: the one output of a notebook that differs from
    /// run to run by design, which the check of the stored notebooks leaves out.
    pub fn evcxr_display(&self) {
        let mut html = self.html();
        html.html = format!("<div class=\"{TIMING_CLASS}\">{}</div>", html.html);
        html.evcxr_display();
    }

    /// `{"workload": …, "size": …, "points": …, "seconds": …, "throughput": …}`, with
    /// `"bytes"` and `"bytes_per_second"` where [`traffic`] models the workload.
    pub fn to_json(&self) -> String {
        let memory = match (traffic(self.workload, self.size), self.bandwidth()) {
            (Some(b), Some(bw)) => format!(r#", "bytes": {b}, "bytes_per_second": {bw:e}"#),
            _ => String::new(),
        };
        format!(
            r#"{{"workload": "{}", "size": {}, "points": {}, "seconds": {:e}, "throughput": {:e}{memory}}}"#,
            self.workload,
            self.size,
            self.points,
            self.seconds,
            self.throughput()
        )
    }
}

/// Runs one workload at its default size: a warm-up, then repeated runs for at least
/// `budget` (and at least 5 times, or 2 when one run outlasts the budget), reporting the median.
///
/// # Errors
/// [`crate::report::Error::UnknownId`] for an unknown id; errors of the workload.
pub fn run(id: &str, budget: Duration) -> crate::report::Result<BenchResult> {
    let w = workload(id)?;
    run_sized(w, w.size, budget)
}

/// Runs workload `w` at `size` as [`run`] does (inputs prepared outside the timing).
///
/// # Errors
/// Errors of the workload (a size it cannot take among them).
pub fn run_sized(
    w: &'static Workload,
    size: usize,
    budget: Duration,
) -> crate::report::Result<BenchResult> {
    if !w.sweep.is_empty() {
        // every sized workload needs at least 1 (t6-row) or 2 points; none more than the
        // crate's element limit
        crate::error::size("bench size", size)?;
    }
    let mut runner = (w.setup)(size)?;
    let first = Instant::now();
    let points = runner()?;
    // five timed runs at least; two for a workload whose one run outlasts the budget
    let min_runs = if first.elapsed() > budget { 2 } else { 5 };
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < min_runs || start.elapsed() < budget {
        let t = Instant::now();
        black_box(runner()?);
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    Ok(BenchResult {
        workload: w.id,
        size,
        points,
        seconds: times[times.len() / 2],
    })
}

/// The sweep of one workload: [`run_sized`] at each of its [`Workload::sweep`] sizes, each
/// result passed to `each` as it comes (for printing), all returned.
///
/// # Errors
/// As [`run_sized`], and the error of `each`.
pub fn sweep(
    id: &str,
    budget: Duration,
    mut each: impl FnMut(&BenchResult) -> crate::report::Result<()>,
) -> crate::report::Result<Vec<BenchResult>> {
    let w = workload(id)?;
    let mut all = Vec::new();
    for &size in w.sweep {
        let r = run_sized(w, size, budget)?;
        each(&r)?;
        all.push(r);
    }
    Ok(all)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::bench::workloads::{POINT_SWEEP, WORKLOADS};

    /// Every point and grid workload has a traffic model, in its JSON; the studies none;
    /// huge sizes give `None`, not an overflow.
    #[test]
    fn traffic_is_modelled_for_the_batch_workloads() {
        for w in &WORKLOADS {
            let modelled = traffic(w.id, w.size);
            let batch = w.sweep == POINT_SWEEP || matches!(w.unit, "nodes per side");
            assert_eq!(modelled.is_some(), batch, "{}", w.id);
        }
        let r = BenchResult {
            workload: "memory-copy",
            size: 1000,
            points: 1000,
            seconds: 1e-6,
        };
        assert!(r
            .to_json()
            .contains(r#""bytes": 16000, "bytes_per_second": 1.6e10"#));
        assert_eq!(traffic("corner-data", usize::MAX), None);
        assert_eq!(traffic("t6-row", 8), None);
    }
}
