//! The registry of outputs and their files: `<dir>/tables/<id>.csv` and `.md`,
//! `<dir>/figures/<id>.png` and `.svg`.

use crate::error::{Error, Result};
use crate::report::curve_tables;
use crate::report::figures::FigureId;
use crate::report::style::FIGURE_SIZE;
use crate::report::tables::{self, Table};
use plotters::prelude::{BitMapBackend, IntoDrawingArea, SVGBackend};
use polars::prelude::{AnyValue, CsvWriter, SerWriter};
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

/// One table the CLI can regenerate.
#[derive(Debug, Clone, Copy)]
pub struct TableSpec {
    /// Id used by `--only` and as the file stem.
    pub id: &'static str,
    /// One-line description for `--list`.
    pub description: &'static str,
    build: fn() -> Result<Table>,
}

impl TableSpec {
    /// Computes the table.
    ///
    /// # Errors
    /// Whatever the computation reports.
    pub fn build(&self) -> Result<Table> {
        (self.build)()
    }
}

/// One output: a table or a figure.
#[derive(Debug, Clone, Copy)]
pub enum OutputSpec {
    /// A table (CSV and Markdown).
    Table(TableSpec),
    /// A figure (PNG and SVG).
    Figure(FigureId),
}

impl OutputSpec {
    /// Id used by `--only` and as the file stem.
    pub fn id(&self) -> &'static str {
        match self {
            OutputSpec::Table(t) => t.id,
            OutputSpec::Figure(f) => f.id(),
        }
    }

    /// One-line description.
    pub fn description(&self) -> &'static str {
        match self {
            OutputSpec::Table(t) => t.description,
            OutputSpec::Figure(f) => f.description(),
        }
    }

    /// Writes the output's files into `dir`; returns their paths.
    ///
    /// # Errors
    /// [`Error::Io`] if a file cannot be written; errors of the computation or drawing.
    pub fn write(&self, dir: &Path) -> Result<Vec<PathBuf>> {
        match self {
            OutputSpec::Table(t) => write_table(&t.build()?, dir),
            OutputSpec::Figure(f) => write_figure(*f, dir),
        }
    }
}

const TABLES: [TableSpec; 12] = [
    TableSpec {
        id: "torus-partials",
        description: "Exact partials of the torus from hyper-dual numbers beside the closed forms of Codice 3 (seed 000 §2)",
        build: tables::torus_partials,
    },
    TableSpec {
        id: "t3-error",
        description: "Table T3: error of one Hermite patch of the torus on [0,1]² and [0,0.5]² (seed 000 §3), printed vs ours",
        build: tables::t3,
    },
    TableSpec {
        id: "t4-equivalence",
        description: "Hermite ≡ Bézier check (Codice 10) for the correct net and Codice 7 as printed",
        build: tables::equivalence,
    },
    TableSpec {
        id: "t6-spline-error",
        description: "Table T6: error of n×m Hermite spline patches of the torus (seed 000 §6), printed vs report's listing vs ours",
        build: tables::t6,
    },
    TableSpec {
        id: "convergence",
        description: "Convergence study n = m = 1…64 with max-abs, RMS, the report's measure and observed orders",
        build: tables::convergence_table,
    },
    TableSpec {
        id: "knot-vectors",
        description: "Seed 001: knot vectors printed vs constructed (extended partition), open/uniform, basis size",
        build: curve_tables::knot_vectors,
    },
    TableSpec {
        id: "partition-of-unity",
        description: "Seed 001: degree 2, knots (0,0,0,1,2,2,2), t = 0.6 — printed vs Cox–de Boor vs one-pass",
        build: curve_tables::partition_of_unity,
    },
    TableSpec {
        id: "nurbs-circle",
        description: "Seed 001: radius and curvature error of the 7- and 9-point NURBS circles",
        build: curve_tables::nurbs_circle,
    },
    TableSpec {
        id: "runge-errors",
        description: "Seed 001: Runge's phenomenon, max error vs degree, equispaced vs Chebyshev, Vandermonde",
        build: curve_tables::runge_errors,
    },
    TableSpec {
        id: "cubic-spline-ends",
        description: "Seeds 001, 004: the four end conditions, residuals, tridiagonal vs collocation",
        build: curve_tables::cubic_spline_ends,
    },
    TableSpec {
        id: "de-casteljau",
        description: "Seed 003: de Casteljau at u = 0.3, 0.5, 0.7, recursive vs iterative vs Bernstein",
        build: curve_tables::de_casteljau_table,
    },
    TableSpec {
        id: "seed003-checks",
        description: "Seed 003: the printed procedures (setbval, Lagrange B4, bspline, glMap1f) checked",
        build: curve_tables::seed003_checks,
    },
];

/// Every output, in generation order: tables, then figures.
pub fn list_outputs() -> Vec<OutputSpec> {
    TABLES
        .iter()
        .copied()
        .map(OutputSpec::Table)
        .chain(FigureId::ALL.into_iter().map(OutputSpec::Figure))
        .collect()
}

/// Every output id with its one-line description, one per line (what `--list` prints).
pub fn describe_outputs() -> String {
    list_outputs()
        .iter()
        .map(|o| format!("{:<24} {}", o.id(), o.description()))
        .collect::<Vec<_>>()
        .join("\n")
}

fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> Error + '_ {
    move |e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

/// Formats one cell for Markdown: floats with 5 significant digits, missing values as `—`.
fn cell(v: &AnyValue) -> String {
    match v {
        AnyValue::Null => "—".into(),
        AnyValue::Float64(x) => {
            let a = x.abs();
            if *x == 0.0 {
                "0".into()
            } else if (1e-3..1e4).contains(&a) {
                let decimals = (4 - a.log10().floor() as i32).max(0) as usize;
                format!("{x:.decimals$}")
            } else {
                format!("{x:.4e}")
            }
        }
        AnyValue::Boolean(b) => if *b { "yes" } else { "no" }.into(),
        AnyValue::String(s) => s.to_string(),
        other => other.to_string(),
    }
}

/// Column names and every row of the table as display strings (the cell format of
/// [`to_markdown`] and [`to_html`]).
///
/// # Errors
/// [`Error::Table`] if polars cannot read a cell.
pub fn display_rows(table: &Table) -> Result<(Vec<String>, Vec<Vec<String>>)> {
    let df = &table.df;
    let names = df
        .get_column_names()
        .iter()
        .map(|n| n.to_string())
        .collect();
    let rows = (0..df.height())
        .map(|i| {
            df.columns()
                .iter()
                .map(|c| {
                    c.get(i).map(|v| cell(&v)).map_err(|e| Error::Table {
                        id: table.id.to_string(),
                        message: e.to_string(),
                    })
                })
                .collect()
        })
        .collect::<Result<_>>()?;
    Ok((names, rows))
}

/// The table as Markdown: title, a pipe table, notes.
///
/// # Errors
/// [`Error::Table`] if polars cannot read a cell.
pub fn to_markdown(table: &Table) -> Result<String> {
    let (names, rows) = display_rows(table)?;
    let mut md = format!("# {}\n\n", table.title);
    let _ = writeln!(md, "| {} |", names.join(" | "));
    let _ = writeln!(md, "|{}", "---|".repeat(names.len()));
    for row in rows {
        let _ = writeln!(md, "| {} |", row.join(" | "));
    }
    if !table.notes.is_empty() {
        md.push('\n');
        for note in &table.notes {
            let _ = writeln!(md, "- {note}");
        }
    }
    Ok(md)
}

fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The table as an HTML fragment with every row and column (for notebooks, where polars'
/// text display would elide rows): title, table, notes.
///
/// # Errors
/// [`Error::Table`] if polars cannot read a cell.
pub fn to_html(table: &Table) -> Result<String> {
    let (names, rows) = display_rows(table)?;
    let mut html = format!(
        "<h4>{}</h4>\n<table>\n<thead><tr>",
        escape_html(&table.title)
    );
    for n in &names {
        let _ = write!(html, "<th>{}</th>", escape_html(n));
    }
    html.push_str("</tr></thead>\n<tbody>\n");
    for row in rows {
        html.push_str("<tr>");
        for c in row {
            let _ = write!(html, "<td>{}</td>", escape_html(&c));
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</tbody>\n</table>\n<ul>\n");
    for note in &table.notes {
        let _ = writeln!(html, "<li>{}</li>", escape_html(note));
    }
    html.push_str("</ul>");
    Ok(html)
}

/// A temporary path beside `path`, in the same folder (so a rename is atomic), keeping its
/// extension (plotters picks the image format from it): `.<stem>.<pid>.tmp.<ext>`.
fn temporary_beside(path: &Path) -> PathBuf {
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("output");
    let ext = path.extension().and_then(|s| s.to_str()).unwrap_or("tmp");
    path.with_file_name(format!(".{stem}.{}.tmp.{ext}", std::process::id()))
}

/// Produces `path` atomically: `make` writes a temporary file beside it, which is renamed
/// over `path` only if `make` succeeded; on failure the temporary file is removed, so a
/// failed run (a full disk, a file-size limit) never leaves a truncated file under an
/// output's name.
fn produce(path: &Path, make: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    let tmp = temporary_beside(path);
    let result = make(&tmp).and_then(|()| fs::rename(&tmp, path).map_err(io_err(path)));
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// Writes `bytes` to `path` atomically (see [`produce`]), flushing them to the file first.
fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    produce(path, |tmp| {
        let mut file = fs::File::create(tmp).map_err(io_err(path))?;
        std::io::Write::write_all(&mut file, bytes).map_err(io_err(path))?;
        file.sync_all().map_err(io_err(path))
    })
}

/// Writes `<dir>/tables/<id>.csv` (full precision) and `.md`; returns the paths written.
/// Each file is written to a temporary file beside it and renamed into place.
///
/// # Errors
/// [`Error::Io`] if the folder or a file cannot be written.
pub fn write_table(table: &Table, dir: &Path) -> Result<Vec<PathBuf>> {
    let folder = dir.join("tables");
    fs::create_dir_all(&folder).map_err(io_err(&folder))?;
    let csv_path = folder.join(format!("{}.csv", table.id));
    let mut csv = Vec::new();
    CsvWriter::new(&mut csv)
        .finish(&mut table.df.clone())
        .map_err(|e| Error::Io {
            path: csv_path.clone(),
            message: e.to_string(),
        })?;
    write_atomic(&csv_path, &csv)?;
    let md_path = folder.join(format!("{}.md", table.id));
    write_atomic(&md_path, to_markdown(table)?.as_bytes())?;
    Ok(vec![csv_path, md_path])
}

/// Draws `figure` into `<dir>/figures/<id>.png` and `.svg` ([`FIGURE_SIZE`] pixels), each
/// through a temporary file beside it renamed into place.
///
/// # Errors
/// [`Error::Io`] if the folder cannot be created or a file written; [`Error::Figure`] if
/// drawing or encoding fails.
pub fn write_figure(figure: FigureId, dir: &Path) -> Result<Vec<PathBuf>> {
    let folder = dir.join("figures");
    fs::create_dir_all(&folder).map_err(io_err(&folder))?;
    let fail = |e: &dyn std::fmt::Display| Error::Figure {
        id: figure.id().to_string(),
        message: e.to_string(),
    };
    let png = folder.join(format!("{}.png", figure.id()));
    produce(&png, |tmp| {
        let root = BitMapBackend::new(tmp, FIGURE_SIZE).into_drawing_area();
        figure.render(&root)?;
        root.present().map_err(|e| fail(&e))
    })?;
    let svg = folder.join(format!("{}.svg", figure.id()));
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, FIGURE_SIZE).into_drawing_area();
        figure.render(&root)?;
        root.present().map_err(|e| fail(&e))?;
    }
    write_atomic(&svg, text.as_bytes())?;
    Ok(vec![png, svg])
}

/// Regenerates one output by id into `dir`.
///
/// # Errors
/// [`Error::UnknownId`] for an unknown id; the errors of [`OutputSpec::write`].
pub fn write_only(dir: &Path, id: &str) -> Result<Vec<PathBuf>> {
    let spec = list_outputs()
        .into_iter()
        .find(|o| o.id() == id)
        .ok_or_else(|| Error::UnknownId {
            what: "output",
            id: id.to_string(),
        })?;
    spec.write(dir)
}

/// Regenerates every output into `dir`.
///
/// # Errors
/// The first error of [`OutputSpec::write`].
pub fn write_all(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    for spec in list_outputs() {
        written.extend(spec.write(dir)?);
    }
    Ok(written)
}
