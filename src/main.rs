//! `splinelab`: regenerate every figure and table of the reports, run the benchmarks, or run
//! the methods on a user's own data (`fit`, `fewest`, `surface`).

mod cli;

use cli::user;

use anyhow::Context;
use clap::{Parser, Subcommand};
use splinelab::report::{bench, describe_outputs, write_all, write_only};

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

/// Regenerates the figures and tables of the splinelab reports (default: all, into `out/`).
#[derive(Parser, Debug)]
#[command(
    name = "splinelab",
    version,
    about,
    args_conflicts_with_subcommands = true
)]
struct Cli {
    /// Output folder.
    #[arg(long, default_value = "out")]
    out: PathBuf,
    /// List output ids with a one-line description, and exit.
    #[arg(long)]
    list: bool,
    /// Regenerate only this output (repeatable).
    #[arg(long, value_name = "ID")]
    only: Vec<String>,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Fit one of seed 004's methods through your points: the curve sampled (CSV), drawn over
    /// its points (PNG, SVG), as an SVG path of cubic Béziers, its formulas on request.
    Fit(user::FitArgs),
    /// For each method, the fewest points drawing your outline within a tolerance (Table I's
    /// search): a table (CSV, Markdown) and one figure per method; progress on stderr.
    Fewest(user::FewestArgs),
    /// A built-in surface's bicubic Hermite spline surface on your partition, exported as a
    /// mesh (OBJ, PLY, STL) with normals from the exact partials.
    Surface(user::SurfaceArgs),
    /// Run the speed workloads and print one JSON object per line.
    Bench {
        /// Run only this workload (repeatable).
        #[arg(long, value_name = "ID")]
        only: Vec<String>,
        /// Minimum measuring time per workload, in milliseconds.
        #[arg(long, default_value_t = 500)]
        millis: u64,
        /// List the workloads and exit.
        #[arg(long)]
        list: bool,
        /// Run each workload over its sizes (10³ … 10⁷ points and the like), one JSON line
        /// per size, and draw `fig-bench-scaling` (throughput against size, log-log) into
        /// `--out`'s figures folder; `--millis` is then per size.
        #[arg(long)]
        sweep: bool,
        /// Output folder of the sweep's figure and its JSON lines.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Run the workloads at this size instead of their default (one of their sweep's
        /// sizes or any other they take).
        #[arg(long, value_name = "N", conflicts_with = "sweep")]
        size: Option<usize>,
        /// Print each workload's sweep sizes (`id size size …`) and exit.
        #[arg(long)]
        sizes: bool,
        /// With `--sweep`: a peer comparison's CSV (`scripts/bench_peers.py --sweep` writes
        /// `out/tables/bench-peers-sweep.csv`), drawn as a panel of the peer's time over ours.
        #[arg(long, value_name = "FILE", requires = "sweep")]
        peers: Option<PathBuf>,
    },
    /// Print the formula corpus (surfaces, curves, bases, a patch: their traced formulas,
    /// which is the derivative of which, and reference values), one JSON object per line,
    /// for `scripts/check_formulas.py`.
    ///
    /// Example: `splinelab formulas > corpus.jsonl`
    Formulas,
    /// Write `OUT/site/index.html` (the default run writes it too): the notebooks' HTML
    /// copies and the API documentation where `scripts/notebooks.sh --site` put them, every
    /// figure with its id and caption, every table; opens from the file system.
    ///
    /// Example: `splinelab site --out out`, then open `out/site/index.html`
    Site {
        /// The run's output folder (its `figures/` and `tables/`).
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
}

fn main() -> ExitCode {
    splinelab::report::remove_temporaries_on_interrupt();
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // a closed stderr must not turn the error into a panic either
            let _ = writeln!(std::io::stderr(), "splinelab: error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// Prints one line on standard output; a closed or full stdout is an error (exit 1 with a
/// message), never a panic as `println!` would give.
fn say(line: impl std::fmt::Display) -> anyhow::Result<()> {
    let mut out = std::io::stdout().lock();
    writeln!(out, "{line}")
        .and_then(|()| out.flush())
        .context("writing to standard output")
}

/// `bench --sweep`: every workload of `ids` over its sizes (fixed studies skipped), the JSON
/// lines printed as they come and written to `out/tables/bench-sweep.jsonl`, and the figure
/// `fig-bench-scaling` to `out/figures/`.
fn sweep_all(
    ids: &[String],
    budget: Duration,
    out: &std::path::Path,
    peers: Option<&std::path::Path>,
) -> anyhow::Result<()> {
    let peers = match peers {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("reading {}", path.display()))?;
            bench::parse_peers(&path.display().to_string(), &text)?
        }
        None => Vec::new(),
    };
    let mut all = Vec::new();
    for id in ids {
        let results = bench::sweep(id, budget, |r| {
            say(r.to_json()).map_err(|e| splinelab::report::Error::Io {
                path: "<stdout>".into(),
                message: e.to_string(),
            })
        })?;
        all.extend(results);
    }
    let tables = out.join("tables");
    std::fs::create_dir_all(&tables).with_context(|| format!("creating {}", tables.display()))?;
    let lines: String = all.iter().map(|r| r.to_json() + "\n").collect();
    let jsonl = tables.join("bench-sweep.jsonl");
    std::fs::write(&jsonl, lines).with_context(|| format!("writing {}", jsonl.display()))?;
    say(format_args!("wrote {}", jsonl.display()))?;
    let machine = format!(
        "{} threads, {}",
        std::thread::available_parallelism().map_or(1, |n| n.get()),
        std::env::consts::ARCH
    );
    let figure = bench::scaling_figure(&all, &peers, &machine);
    for path in figure.save(&out.join("figures"), "fig-bench-scaling")? {
        say(format_args!("wrote {}", path.display()))?;
    }
    Ok(())
}

fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Some(Command::Fit(args)) => return user::fit(args),
        Some(Command::Fewest(args)) => return user::fewest(args),
        Some(Command::Surface(args)) => return user::surface(args),
        _ => {}
    }
    if let Some(Command::Site { out }) = &cli.command {
        return site(out);
    }
    if let Some(Command::Formulas) = cli.command {
        for entry in splinelab::symbolic::corpus::corpus()? {
            say(entry.to_json())?;
        }
        return Ok(());
    }
    if let Some(Command::Bench {
        only,
        millis,
        list,
        sweep,
        out,
        size,
        sizes,
        peers,
    }) = cli.command
    {
        if list {
            for w in &bench::WORKLOADS {
                say(format_args!("{:<24} {}", w.id, w.description))?;
            }
            return Ok(());
        }
        if sizes {
            for w in &bench::WORKLOADS {
                let s: Vec<String> = w.sweep.iter().map(|n| n.to_string()).collect();
                say(format_args!("{} {}", w.id, s.join(" ")))?;
            }
            return Ok(());
        }
        let ids: Vec<String> = if only.is_empty() {
            bench::WORKLOADS.iter().map(|w| w.id.to_string()).collect()
        } else {
            only
        };
        let budget = Duration::from_millis(millis);
        if sweep {
            return sweep_all(&ids, budget, &out, peers.as_deref());
        }
        for id in ids {
            let r = match size {
                Some(n) => bench::run_sized(bench::workload(&id)?, n, budget)?,
                None => bench::run(&id, budget)?,
            };
            say(r.to_json())?;
        }
        return Ok(());
    }
    if cli.list {
        say(describe_outputs())?;
        return Ok(());
    }
    let written = if cli.only.is_empty() {
        write_all(&cli.out)
    } else {
        let mut all = Vec::new();
        for id in &cli.only {
            all.extend(write_only(&cli.out, id)?);
        }
        Ok(all)
    }
    .with_context(|| format!("regenerating outputs into {}", cli.out.display()))?;
    for path in &written {
        say(format_args!("wrote {}", path.display()))?;
    }
    if cli.only.is_empty() {
        site(&cli.out)?;
    }
    Ok(())
}

/// Writes `out/site/` (the `site` command, and the end of the default run).
fn site(out: &std::path::Path) -> anyhow::Result<()> {
    let index = splinelab::report::site::write_site(out)?;
    say(format_args!("wrote {}", index.display()))
}
