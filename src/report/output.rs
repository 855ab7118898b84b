//! The registry of outputs and their files: `<dir>/tables/<id>.csv` and `.md`.

use crate::error::{Error, Result};
use crate::report::tables::{self, Table};
use polars::prelude::{AnyValue, CsvWriter, SerWriter};
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

/// One output the CLI can regenerate.
#[derive(Debug, Clone, Copy)]
pub struct OutputSpec {
    /// Id used by `--only` and as the file stem.
    pub id: &'static str,
    /// One-line description for `--list`.
    pub description: &'static str,
    build: fn() -> Result<Table>,
}

impl OutputSpec {
    /// Computes the table.
    ///
    /// # Errors
    /// Whatever the computation reports.
    pub fn build(&self) -> Result<Table> {
        (self.build)()
    }
}

const OUTPUTS: [OutputSpec; 4] = [
    OutputSpec {
        id: "t3-error",
        description: "Table T3: error of one Hermite patch of the torus on [0,1]² and [0,0.5]² (seed 000 §3), printed vs ours",
        build: tables::t3,
    },
    OutputSpec {
        id: "t4-equivalence",
        description: "Hermite ≡ Bézier check (Codice 10) for the correct net and Codice 7 as printed",
        build: tables::equivalence,
    },
    OutputSpec {
        id: "t6-spline-error",
        description: "Table T6: error of n×m Hermite spline patches of the torus (seed 000 §6), printed vs report's listing vs ours",
        build: tables::t6,
    },
    OutputSpec {
        id: "convergence",
        description: "Convergence study n = m = 1…64 with max-abs, RMS, the report's measure and observed orders",
        build: tables::convergence_table,
    },
];

/// Every output, in generation order.
pub fn list_outputs() -> &'static [OutputSpec] {
    &OUTPUTS
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

/// The table as Markdown: title, a pipe table, notes.
///
/// # Errors
/// [`Error::Table`] if polars cannot read a cell.
pub fn to_markdown(table: &Table) -> Result<String> {
    let df = &table.df;
    let mut md = format!("# {}\n\n", table.title);
    let names: Vec<String> = df
        .get_column_names()
        .iter()
        .map(|n| n.to_string())
        .collect();
    let _ = writeln!(md, "| {} |", names.join(" | "));
    let _ = writeln!(md, "|{}", "---|".repeat(names.len()));
    for i in 0..df.height() {
        let row: Result<Vec<String>> = df
            .columns()
            .iter()
            .map(|c| {
                c.get(i).map(|v| cell(&v)).map_err(|e| Error::Table {
                    id: table.id.to_string(),
                    message: e.to_string(),
                })
            })
            .collect();
        let _ = writeln!(md, "| {} |", row?.join(" | "));
    }
    if !table.notes.is_empty() {
        md.push('\n');
        for note in &table.notes {
            let _ = writeln!(md, "- {note}");
        }
    }
    Ok(md)
}

/// Writes `<dir>/tables/<id>.csv` (full precision) and `.md`; returns the paths written.
///
/// # Errors
/// [`Error::Io`] if the folder or a file cannot be written.
pub fn write_table(table: &Table, dir: &Path) -> Result<Vec<PathBuf>> {
    let folder = dir.join("tables");
    fs::create_dir_all(&folder).map_err(io_err(&folder))?;
    let csv_path = folder.join(format!("{}.csv", table.id));
    let mut file = fs::File::create(&csv_path).map_err(io_err(&csv_path))?;
    CsvWriter::new(&mut file)
        .finish(&mut table.df.clone())
        .map_err(|e| Error::Io {
            path: csv_path.clone(),
            message: e.to_string(),
        })?;
    let md_path = folder.join(format!("{}.md", table.id));
    fs::write(&md_path, to_markdown(table)?).map_err(io_err(&md_path))?;
    Ok(vec![csv_path, md_path])
}

/// Regenerates one output by id into `dir`.
///
/// # Errors
/// [`Error::UnknownId`] for an unknown id; the errors of [`write_table`].
pub fn write_only(dir: &Path, id: &str) -> Result<Vec<PathBuf>> {
    let spec = OUTPUTS
        .iter()
        .find(|o| o.id == id)
        .ok_or_else(|| Error::UnknownId {
            what: "output",
            id: id.to_string(),
        })?;
    write_table(&spec.build()?, dir)
}

/// Regenerates every output into `dir`.
///
/// # Errors
/// The first error of [`write_only`].
pub fn write_all(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    for spec in &OUTPUTS {
        written.extend(write_only(dir, spec.id)?);
    }
    Ok(written)
}
