//! `fig-bench-scaling`: throughput against size for every swept workload, and each compared
//! workload's peer time over ours ([`scaling_figure`]).

use super::peers::PeerPoint;
use super::run::BenchResult;
use crate::report::figure::Figure;

/// `fig-bench-scaling`: throughput (points per second) against size (points per run),
/// log-log, one line per workload of `results` (a [`super::sweep`] of each), in two panels — curves
/// and splines, surfaces and studies. A flat line is a cost proportional to the size; a line
/// that rises at small sizes is paying a fixed cost per run (setup, threads), one that falls
/// at large sizes has left the caches for main memory. With `peers` ([`super::parse_peers`]) a third
/// panel draws each compared workload's peer time over ours against size, parity (1) dashed:
/// where a line falls to it, the lead is gone.
pub fn scaling_figure(results: &[BenchResult], peers: &[PeerPoint], machine: &str) -> Figure {
    use crate::report::plot2d::{Figure2d, Series};
    let mut ids: Vec<&str> = Vec::new();
    for r in results {
        if !ids.contains(&r.workload) {
            ids.push(r.workload);
        }
    }
    let surfaces = [
        "t6-row",
        "patch-matrix",
        "patch-decasteljau",
        "corner-data",
        "corner-data-by-hand",
        "torus-grid",
        "torus-grid-1core",
    ];
    let mut panels = Vec::new();
    for (title, want_surfaces) in [
        ("curves and splines", false),
        ("surfaces and studies", true),
    ] {
        let mut panel =
            crate::report::plot2d::Panel::new(title, "points per run", "throughput (points / s)")
                .log(true, true)
                .legend_at(plotters::prelude::SeriesLabelPosition::LowerRight);
        let mine: Vec<&str> = ids
            .iter()
            .copied()
            .filter(|id| surfaces.contains(id) == want_surfaces)
            .collect();
        for (k, id) in mine.iter().enumerate() {
            let points = results
                .iter()
                .filter(|r| r.workload == *id)
                .map(|r| (r.points as f64, r.throughput()))
                .collect();
            let (color, style) = line_style(k);
            panel = panel.with(Series::line(*id, points, color).styled(style));
        }
        // an empty band below the data for the legend, whatever the data: the legend's share
        // of the plot's height (about 24 px per entry and 30 more of a 700-px plot) kept free
        // on the log axis
        let ys = results
            .iter()
            .filter(|r| mine.contains(&r.workload))
            .map(|r| r.throughput())
            .filter(|y| y.is_finite() && *y > 0.0);
        let (lo, hi) = ys.fold((f64::INFINITY, 0.0f64), |(lo, hi), y| {
            (lo.min(y), hi.max(y))
        });
        if lo < hi {
            let band = ((24 * mine.len() + 30) as f64 / 700.0).min(0.6);
            let decades = (hi / lo).log10().max(0.5) * 1.1;
            let below = decades * band / (1.0 - band);
            panel = panel.y_range(
                lo / 10f64.powf(below + 0.05 * decades),
                hi * 10f64.powf(0.05 * decades),
            );
        }
        panels.push(panel);
    }
    if !peers.is_empty() {
        panels.push(peer_panel(peers));
    }
    let columns = panels.len();
    Figure::from(Figure2d::new(
        format!("Throughput against size, each workload swept ({machine})"),
        panels,
        (1, columns),
    ))
    .with_size(800 * columns as u32, 800)
}

/// The colour and style of the `k`-th line of a panel: the palette, then two more colours,
/// lines with points; beyond, the same colours dashed.
fn line_style(k: usize) -> (plotters::style::RGBColor, crate::report::plot2d::Style) {
    use crate::report::plot2d::Style;
    let extra = [
        plotters::style::RGBColor(120, 120, 120),
        plotters::style::RGBColor(150, 30, 30),
    ];
    let colors: Vec<_> = crate::report::style::LINE_PALETTE
        .iter()
        .chain(&extra)
        .copied()
        .collect();
    let style = if k < colors.len() {
        Style::LinePoints(4)
    } else {
        Style::Dashed
    };
    (colors[k % colors.len()], style)
}

/// The panel of peer time over ours against size (see [`scaling_figure`]).
fn peer_panel(peers: &[PeerPoint]) -> crate::report::plot2d::Panel {
    use crate::report::plot2d::{Panel, Series, Style};
    let mut ids: Vec<(&str, &str)> = Vec::new();
    for p in peers {
        if !ids.contains(&(p.workload.as_str(), p.peer_name.as_str())) {
            ids.push((p.workload.as_str(), p.peer_name.as_str()));
        }
    }
    let mut panel = Panel::new(
        "peer time ÷ splinelab time (above 1: splinelab faster)",
        "points per run",
        "ratio",
    )
    .log(true, true)
    .legend_at(plotters::prelude::SeriesLabelPosition::UpperLeft);
    let sizes = peers.iter().map(|p| p.points as f64);
    let (lo, hi) = sizes.fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    for (k, (id, peer)) in ids.iter().enumerate() {
        let points: Vec<(f64, f64)> = peers
            .iter()
            .filter(|p| p.workload == *id && p.peer_name == *peer)
            .map(|p| (p.points as f64, p.ratio()))
            .collect();
        let (color, style) = line_style(k);
        panel = panel.with(Series::line(format!("{id} ({peer})"), points, color).styled(style));
    }
    if lo < hi {
        let grey = plotters::style::RGBColor(110, 110, 110);
        panel = panel
            .with(Series::line("parity", vec![(lo, 1.0), (hi, 1.0)], grey).styled(Style::Dashed));
    }
    panel
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::bench::{parse_peers, workload, PEER_HEADER};

    #[test]
    fn the_scaling_figure_draws() {
        let results: Vec<BenchResult> = [("bspline-curve", 1e3), ("torus-grid", 4096.0)]
            .iter()
            .flat_map(|&(id, base)| {
                let w = workload(id).expect("known");
                (0..4).map(move |k| BenchResult {
                    workload: w.id,
                    size: k,
                    points: (base * 10f64.powi(k as i32)) as usize,
                    seconds: 1e-3 * (k + 1) as f64,
                })
            })
            .collect();
        let svg = scaling_figure(&results, &[], "test").to_svg().expect("svg");
        assert!(svg.contains("bspline-curve") && svg.contains("torus-grid"));
        let text = format!("{PEER_HEADER}\ncubic-spline-eval,1000,1000,1e-5,3e-5,scipy\ncubic-spline-eval,10000,10000,1e-4,2e-4,scipy\n");
        let peers = parse_peers("peers", &text).expect("parses");
        assert_eq!(peers.len(), 2);
        assert!((peers[0].ratio() - 3.0).abs() < 1e-12);
        let svg = scaling_figure(&results, &peers, "test")
            .to_svg()
            .expect("svg");
        assert!(svg.contains("parity") && svg.contains("cubic-spline-eval (scipy)"));
    }
}
