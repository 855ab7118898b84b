//! The subcommands on a user's own data: `fit`, `fewest`, `surface`. Each parses its
//! arguments and calls the library (`splinelab::study::outline`, `splinelab::report::user`); no
//! mathematics here.

use anyhow::Context;
use clap::{ArgGroup, Args, ValueEnum};
use splinelab::input::Columns;
use splinelab::interp::choice::{Family, SearchOptions};
use splinelab::report::export;
use splinelab::report::user::fewest;
use splinelab::report::user::fit::{Fit, FormulaStyle};
use splinelab::report::user::outline::{
    read_contour_points, read_outline, read_points, ReadOptions,
};
use splinelab::report::user::surface::{BuiltIn, MeshFormat, PartitionSpec, SurfaceMesh};
use splinelab::study::outline::{Progress, Tolerance};
use splinelab::study::{self, table_i};
use splinelab::{CubicEnd, Method};
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// A method of seed 004 on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodName {
    /// The Angular spline.
    Angular,
    /// The cardinal spline (`--a`).
    Cardinal,
    /// The parametric cubic spline (`--end`).
    Cubic,
    /// The B-spline through the points as its control polygon (`--order`).
    Bspline,
    /// The polygon.
    Linear,
}

impl MethodName {
    fn family(self) -> Family {
        match self {
            MethodName::Angular => Family::Angular,
            MethodName::Cardinal => Family::Cardinal,
            MethodName::Cubic => Family::Cubic,
            MethodName::Bspline => Family::BSpline,
            MethodName::Linear => Family::Linear,
        }
    }
}

/// The cubic spline's end condition on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum EndName {
    /// `P″ = 0` at both ends.
    Relaxed,
    /// Periodic on a closed curve.
    Cyclic,
    /// `P′₁ = −P′ₙ`, `P″₁ = −P″ₙ`.
    Anticyclic,
}

/// How the formulas are printed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FormulaName {
    /// Plain text.
    Plain,
    /// LaTeX.
    Latex,
}

/// The CSV column choice: `x,y` header names or `0,1` indices.
fn columns(spec: Option<&str>) -> Columns {
    match spec {
        None => Columns::First,
        Some(s) => {
            let parts: Vec<&str> = s.split(',').map(str::trim).collect();
            match parts.iter().map(|p| p.parse::<usize>()).collect() {
                Ok(indices) => Columns::Indices(indices),
                Err(_) => Columns::Names(parts.iter().map(|p| p.to_string()).collect()),
            }
        }
    }
}

/// `fit`: one method's curve through the points of a CSV file.
#[derive(Args, Debug)]
#[command(
    after_help = "Example:\n  splinelab fit --method cubic --end cyclic --closed --formulas plain data/examples/points.csv\n  writes out/fit/points-samples.csv, points.png, points.svg and points-path.svg"
)]
pub struct FitArgs {
    /// The method.
    #[arg(long, value_enum)]
    method: MethodName,
    /// Close the curve (as seed 004 closes curves).
    #[arg(long)]
    closed: bool,
    /// The cubic spline's end condition.
    #[arg(long, value_enum, default_value = "relaxed")]
    end: EndName,
    /// The cardinal spline's tangent factor `a > 0`.
    #[arg(long, default_value_t = 0.5)]
    a: f64,
    /// The B-spline's order `k ≥ 2` (degree k − 1).
    #[arg(long, default_value_t = 4)]
    order: usize,
    /// The CSV columns of x and y: header names (`lon,lat`) or 0-based indices (`2,3`);
    /// the first two by default.
    #[arg(long, value_name = "X,Y")]
    columns: Option<String>,
    /// Samples a piece in the CSV.
    #[arg(long, default_value_t = 32)]
    samples: usize,
    /// Print the formulas of x and y on every piece.
    #[arg(long, value_enum, value_name = "STYLE")]
    formulas: Option<FormulaName>,
    /// The SVG path's tolerance where a piece is not cubic (a distance); 10⁻⁴ of the curve's
    /// size by default.
    #[arg(long)]
    tolerance: Option<f64>,
    /// Output folder.
    #[arg(long, default_value = "out/fit")]
    out: PathBuf,
    /// Only the rows of this contour, by the CSV's `contour` column (the answers `fewest`
    /// writes, NAME-METHOD-points.csv); x and y are then named columns (`x,y` by default).
    #[arg(long, value_name = "K")]
    contour: Option<u32>,
    /// The points: a CSV file (`x,y` rows; a header, `;` or blanks are fine).
    points: PathBuf,
}

/// `fewest`: for each method the fewest points drawing an outline within a tolerance.
#[derive(Args, Debug)]
#[command(
    group(ArgGroup::new("input").required(true).args(["outline", "shape"])),
    after_help = "Examples:\n  splinelab fewest --shape ellipse-0.4\n  splinelab fewest --tolerance 0.5% --method angular,cubic data/examples/leaf.svg\n  splinelab fewest --glyph g assets/fonts/DejaVuSans.ttf"
)]
pub struct FewestArgs {
    /// The tolerance: a percentage of the outline's size (`1%`) or a distance (`0.05`).
    #[arg(long, default_value = "1%")]
    tolerance: String,
    /// The methods searched.
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "angular,cardinal,cubic,bspline"
    )]
    method: Vec<MethodName>,
    /// A CSV outline is closed (default: closed when its last point is its first).
    #[arg(long, conflicts_with = "open")]
    closed: bool,
    /// A CSV outline is open.
    #[arg(long)]
    open: bool,
    /// The CSV columns of x and y (names or 0-based indices).
    #[arg(long, value_name = "X,Y")]
    columns: Option<String>,
    /// The character of a font file.
    #[arg(long)]
    glyph: Option<char>,
    /// The distance within which an SVG's outline lies of its curves (arcs included, which
    /// an SVG document's parser replaces by cubics within 2.7·10⁻⁴ of their radius); by
    /// default curves are flattened within 10⁻⁴ of the size, plus that bound.
    #[arg(long)]
    flatten: Option<f64>,
    /// One of the paper's shapes instead of a file, as its reference polyline (circle,
    /// ellipse-0.7, ellipse-0.4, parabola-2, parabola-1, hyperbola-2, hyperbola-0.5,
    /// sinusoid-1, rectangle-2x1): the counts are Table I's.
    #[arg(long, value_name = "NAME")]
    shape: Option<String>,
    /// The most points a contour is tried with (as counted).
    #[arg(long, default_value_t = study::outline::DEFAULT_MAX_POINTS)]
    max_points: usize,
    /// Error evaluations per count and start, per free coordinate.
    #[arg(long, default_value_t = study::outline::DEFAULT_BUDGET)]
    budget: usize,
    /// After the default search, Table I's search started from its answer (never worse): 40
    /// evaluations per coordinate, every count below the answer searched in full (slower;
    /// `--shape` uses Table I's search alone, so its counts are Table I's).
    #[arg(long)]
    thorough: bool,
    /// Output folder.
    #[arg(long, default_value = "out/fewest")]
    out: PathBuf,
    /// The outline: CSV points, an SVG document, SVG path data (.path) or a font (.ttf/.otf).
    /// An SVG document's outline is what a viewer draws, in its viewBox's units: a filled
    /// shape's boundary, a stroke's centre line (not its width); hidden content and
    /// definitions are not outline; clips are applied; text, images and masks are refused,
    /// naming the element (convert text to paths first).
    outline: Option<PathBuf>,
}

/// `surface`: a built-in surface's Hermite spline surface on a partition, as a mesh.
#[derive(Args, Debug)]
#[command(
    group(ArgGroup::new("surface-kind").required(true).args(["torus", "sphere", "exp"])),
    group(ArgGroup::new("cuts").args(["partition", "s_nodes"])),
    after_help = "Examples:\n  splinelab surface --torus --partition 8x6 --export torus.obj\n  splinelab surface --sphere 2 --s-nodes 0,1,2,3,4,5,6.283185307179586 --t-nodes -1.5707963267948966,0,1.5707963267948966 --export sphere.stl"
)]
pub struct SurfaceArgs {
    /// The torus of seed 000, `R,r` (default 2,1), on [0, 2π]².
    #[arg(long, value_name = "R,r", num_args = 0..=1, default_missing_value = "2,1")]
    torus: Option<String>,
    /// The sphere of radius ρ (default 1), longitude [0, 2π] × latitude [−π/2, π/2].
    #[arg(long, value_name = "RADIUS", num_args = 0..=1, default_missing_value = "1")]
    sphere: Option<f64>,
    /// The test surface (e^{s+t}, e^{s−t}, sinh s sinh t) on [0, 1]².
    #[arg(long)]
    exp: bool,
    /// `NxM` equal patches of the surface's domain (N along s, M along t); 8x8 when neither
    /// this nor the nodes are given.
    #[arg(long, value_name = "NxM")]
    partition: Option<String>,
    /// The nodes along s (increasing), instead of `--partition`.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        requires = "t_nodes"
    )]
    s_nodes: Option<Vec<f64>>,
    /// The nodes along t (increasing).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        requires = "s_nodes"
    )]
    t_nodes: Option<Vec<f64>>,
    /// Mesh steps a patch in each direction.
    #[arg(long, default_value_t = 8)]
    samples: usize,
    /// Write a .ply as ASCII (binary by default).
    #[arg(long)]
    ascii: bool,
    /// The mesh file: .obj, .ply or .stl.
    #[arg(long, value_name = "FILE")]
    export: PathBuf,
}

/// Writes `bytes` atomically and says so.
fn write(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    export::save(path, bytes)?;
    crate::say(format_args!("wrote {}", path.display()))
}

/// The file stem of `path` (`points` for `data/points.csv`).
fn stem(path: &Path) -> String {
    path.file_stem()
        .map_or_else(|| "curve".into(), |s| s.to_string_lossy().into_owned())
}

/// `splinelab fit`.
pub fn fit(args: FitArgs) -> anyhow::Result<()> {
    let columns = columns(args.columns.as_deref());
    let points = match args.contour {
        Some(k) => read_contour_points(&args.points, &columns, k),
        None => read_points(&args.points, &columns),
    }
    .with_context(|| format!("reading {}", args.points.display()))?;
    let method = match args.method {
        MethodName::Angular => Method::Angular,
        MethodName::Cardinal => Method::Cardinal { a: args.a },
        MethodName::Cubic => Method::Cubic {
            end: match args.end {
                EndName::Relaxed => CubicEnd::Relaxed,
                EndName::Cyclic => CubicEnd::Cyclic,
                EndName::Anticyclic => CubicEnd::Anticyclic,
            },
        },
        MethodName::Bspline => Method::BSpline { order: args.order },
        MethodName::Linear => Method::Linear,
    };
    let fit = Fit::try_new(&points, method, args.closed).context("fitting the curve")?;
    if fit.dropped_ring_repeat() {
        crate::say(format_args!(
            "the last point repeats the first: the closed curve is the ring of the first {} points",
            points.len() - 1
        ))?;
    }
    let name = stem(&args.points);
    // everything is computed before anything is written
    let csv = fit.samples_csv(args.samples)?;
    let svg = fit.svg_document(args.tolerance)?;
    let formulas = match args.formulas {
        Some(FormulaName::Plain) => Some(fit.formulas(FormulaStyle::Plain)?),
        Some(FormulaName::Latex) => Some(fit.formulas(FormulaStyle::Latex)?),
        None => None,
    };
    let figure = fit.figure()?;
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    write(
        &args.out.join(format!("{name}-samples.csv")),
        csv.as_bytes(),
    )?;
    for path in figure.save(&args.out, &name)? {
        crate::say(format_args!("wrote {}", path.display()))?;
    }
    write(&args.out.join(format!("{name}-path.svg")), svg.as_bytes())?;
    if let Some(f) = formulas {
        crate::say(f.trim_end())?;
    }
    Ok(())
}

/// Draws the search's progress on stderr: a bar redrawn in place on a terminal (with the time,
/// every quarter second), one line a finished search otherwise.
struct Bar {
    started: Instant,
    done: AtomicUsize,
    total: usize,
    terminal: bool,
    finished: AtomicBool,
}

impl Bar {
    fn draw(&self, last: Option<Progress>) {
        let done = self.done.load(Ordering::Relaxed);
        let width = 30;
        let filled = (done * width).checked_div(self.total).unwrap_or(width);
        let bar = format!("{}{}", "#".repeat(filled), "-".repeat(width - filled));
        let what = last.map_or(String::new(), |p| {
            format!(", {} ended", fewest::family_name(p.family))
        });
        let line = format!(
            "searching [{bar}] {done}/{} searches{what}, {:.1} s",
            self.total,
            self.started.elapsed().as_secs_f64()
        );
        let mut err = std::io::stderr().lock();
        // a closed stderr only loses the bar
        let _ = if self.terminal {
            write!(err, "\r{line}\x1b[K")
        } else if last.is_some() {
            writeln!(err, "{line}")
        } else {
            Ok(())
        };
        let _ = err.flush();
    }
}

/// `splinelab fewest`.
pub fn fewest(args: FewestArgs) -> anyhow::Result<()> {
    let tolerance: Tolerance = args.tolerance.parse()?;
    let (outline, name) = match (&args.shape, &args.outline) {
        (Some(shape), _) => (vec![table_i::shape_outline(shape)?], shape.clone()),
        (None, Some(path)) => {
            let options = ReadOptions {
                columns: columns(args.columns.as_deref()),
                closed: match (args.closed, args.open) {
                    (true, _) => Some(true),
                    (_, true) => Some(false),
                    _ => None,
                },
                glyph: args.glyph,
                flatten: args.flatten,
            };
            let contours = read_outline(path, &options)
                .with_context(|| format!("reading {}", path.display()))?;
            (contours, stem(path))
        }
        (None, None) => anyhow::bail!("give an OUTLINE file or --shape"),
    };
    // the outline as read, first: it is there to look at whatever the search says
    let points = args.out.join(format!("{name}-outline.csv"));
    std::fs::create_dir_all(&args.out)?;
    splinelab::report::table::write_csv(
        &fewest::outline_frame(&format!("{name}-outline"), &outline)?,
        &points,
    )?;
    crate::say(format_args!("wrote {}", points.display()))?;
    let families: Vec<Family> = args.method.iter().map(|m| m.family()).collect();
    let first = SearchOptions {
        max_points: args.max_points,
        budget_per_coordinate: args.budget,
        ..study::outline::default_options()
    };
    let stages = if args.shape.is_some() {
        vec![table_i::table_i_options()]
    } else if args.thorough {
        let then = table_i::thorough_options(&first);
        vec![first, then]
    } else {
        vec![first]
    };
    let bar = Bar {
        started: Instant::now(),
        done: AtomicUsize::new(0),
        total: families.len() * outline.len(),
        terminal: std::io::stderr().is_terminal(),
        finished: AtomicBool::new(false),
    };
    let found = std::thread::scope(|scope| {
        if bar.terminal {
            scope.spawn(|| {
                while !bar.finished.load(Ordering::Relaxed) {
                    bar.draw(None);
                    std::thread::sleep(Duration::from_millis(250));
                }
            });
        }
        let found =
            study::outline::fewest_in_stages(&outline, tolerance, &families, &stages, &|p| {
                bar.done.store(p.done, Ordering::Relaxed);
                bar.draw(Some(p));
            });
        bar.finished.store(true, Ordering::Relaxed);
        found
    });
    if bar.terminal {
        let _ = writeln!(std::io::stderr());
    }
    let found = found?;
    let table = fewest::table(&format!("{name}-fewest"), &found)?;
    let figures = fewest::figures(&found)?;
    for path in table.write(&args.out)? {
        crate::say(format_args!("wrote {}", path.display()))?;
    }
    for (family, figure) in figures {
        let stem = format!("{name}-{}", fewest::family_name(family));
        for path in figure.save(&args.out, &stem)? {
            crate::say(format_args!("wrote {}", path.display()))?;
        }
    }
    // each answer as points, parameters and curve, for `fit` and other tools
    for method in &found.methods {
        let stem = format!("{name}-{}", fewest::family_name(method.family));
        let points_file = format!("{stem}-points.csv");
        let points = fewest::answer_points(&points_file, method)?;
        let parameters = fewest::answer_parameters(&stem, method, found.size, &points_file)?;
        let svg = fewest::answer_svg(method, found.size)?;
        for (file, bytes) in [
            (points_file.clone(), splinelab::report::table::csv(&points)?),
            (
                format!("{stem}-parameters.csv"),
                splinelab::report::table::csv(&parameters)?,
            ),
            (format!("{stem}-curve.svg"), svg.into_bytes()),
        ] {
            write(&args.out.join(file), &bytes)?;
        }
    }
    crate::say(table.to_markdown()?.trim_end())
}

/// `splinelab surface`.
pub fn surface(args: SurfaceArgs) -> anyhow::Result<()> {
    let surface = if let Some(radii) = &args.torus {
        let r: Vec<f64> = radii
            .split(',')
            .map(|v| v.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .with_context(|| format!("--torus {radii}: expected R,r (2,1)"))?;
        let [major, minor] = r[..] else {
            anyhow::bail!("--torus {radii}: expected two radii R,r (2,1)");
        };
        BuiltIn::Torus { major, minor }
    } else if let Some(radius) = args.sphere {
        BuiltIn::Sphere { radius }
    } else {
        BuiltIn::Exp
    };
    let spec = match (&args.partition, &args.s_nodes, &args.t_nodes) {
        (Some(p), _, _) => p.parse::<PartitionSpec>()?,
        (None, Some(s), Some(t)) => PartitionSpec::Nodes(s.clone(), t.clone()),
        (None, None, None) => PartitionSpec::DEFAULT,
        _ => anyhow::bail!("give --partition NxM or --s-nodes and --t-nodes"),
    };
    let format = MeshFormat::of_path(&args.export, args.ascii)?;
    let (s, t) = spec.partitions(&surface)?;
    let (n, m) = (s.len(), t.len());
    let made = SurfaceMesh::try_new(&surface, s, t, args.samples)?;
    let bytes = format.encode(&made.mesh)?;
    write(&args.export, &bytes)?;
    crate::say(format_args!(
        "{n} x {m} bicubic Hermite patches; mesh of {} vertices, {} triangles, normals from the exact partials",
        made.mesh.positions().len(),
        made.mesh.triangles().len()
    ))
}
