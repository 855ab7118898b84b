//! Tables: a [`Frame`] of named columns with an id, a title and notes; Markdown, HTML and
//! CSV for any frame; and tables built from any tabulation, error study or convergence study.
//! With the `polars` feature a table is one call from a polars `DataFrame`
//! (`Table::to_polars`) and any DataFrame converts to a frame (`Frame::try_from`).

use crate::domain::Rect;
use crate::metrics::surface::CoordErrors;
use crate::report::error::{io_err, Result};
use crate::report::files::write_atomic;
use crate::report::frame::{frame, Cell, Column, Frame};
use crate::report::notebook::escape;
use crate::study::hermite_error::{ConvergenceOrders, ConvergenceRow};
use crate::surface::{partials_on_grid, SurfaceDerivatives};
use nalgebra::Vector3;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A table ready to be shown or written: an id, a title, the data and notes for the reader.
#[derive(Debug, Clone)]
pub struct Table {
    /// Id (file stem).
    pub id: String,
    /// One-line title.
    pub title: String,
    /// The data.
    pub df: Frame,
    /// What the columns mean and what follows from them.
    pub notes: Vec<String>,
}

/// The names of the three coordinates.
pub const COORDS: [&str; 3] = ["x", "y", "z"];

impl Table {
    /// A table without notes.
    pub fn new(id: impl Into<String>, title: impl Into<String>, df: Frame) -> Self {
        Self {
            id: id.into(),
            title: title.into(),
            df,
            notes: Vec::new(),
        }
    }

    /// The same table with one more note.
    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }

    /// The table as Markdown: title, a pipe table (floats with 5 significant digits), notes.
    ///
    /// # Errors
    /// None today (see [`display_rows`]).
    pub fn to_markdown(&self) -> Result<String> {
        let mut md = format!("# {}\n\n", self.title);
        md.push_str(&markdown(&self.df)?);
        if !self.notes.is_empty() {
            md.push('\n');
            for note in &self.notes {
                let _ = writeln!(md, "- {note}");
            }
        }
        Ok(md)
    }

    /// The table as an HTML fragment with every row and column (for notebooks, where a text
    /// display would elide rows): title, table, notes.
    ///
    /// # Errors
    /// None today (see [`display_rows`]).
    pub fn to_html(&self) -> Result<String> {
        let mut html = format!("<h4>{}</h4>\n", escape(&self.title));
        html.push_str(&html_table(&self.df)?);
        html.push_str("\n<ul>\n");
        for note in &self.notes {
            let _ = writeln!(html, "<li>{}</li>", escape(note));
        }
        html.push_str("</ul>");
        Ok(html)
    }

    /// Writes `<dir>/<id>.csv` (full precision) and `<dir>/<id>.md`, each through a
    /// temporary file renamed into place; returns the paths.
    ///
    /// # Errors
    /// [`crate::report::Error::Io`] if the folder or a file cannot be written.
    pub fn write(&self, dir: &Path) -> Result<Vec<PathBuf>> {
        std::fs::create_dir_all(dir).map_err(io_err(dir))?;
        let csv_path = dir.join(format!("{}.csv", self.id));
        write_atomic(&csv_path, &csv(&self.df)?)?;
        let md_path = dir.join(format!("{}.md", self.id));
        write_atomic(&md_path, self.to_markdown()?.as_bytes())?;
        Ok(vec![csv_path, md_path])
    }

    /// The data as a polars `DataFrame` (feature `polars`), for polars' queries.
    ///
    /// # Errors
    /// [`crate::report::Error::Table`] if polars refuses the columns.
    #[cfg(feature = "polars")]
    pub fn to_polars(&self) -> Result<polars::prelude::DataFrame> {
        self.df
            .to_polars()
            .map_err(|e| crate::report::Error::Table {
                name: self.id.clone(),
                message: e.to_string(),
            })
    }

    /// Shows the table in a notebook as HTML (title, every row, notes); falls back to
    /// plain text if the HTML cannot be made.
    pub fn evcxr_display(&self) {
        match self.to_html() {
            Ok(html) => println!("EVCXR_BEGIN_CONTENT text/html\n{html}\nEVCXR_END_CONTENT"),
            Err(_) => println!("{}\n\n{}", self.title, self.df),
        }
    }
}

/// Formats one cell for reading: floats with 5 significant digits, missing values as `—`.
fn cell(v: Cell) -> String {
    match v {
        Cell::Null => "—".into(),
        Cell::Float(x) => {
            let a = x.abs();
            if x == 0.0 {
                "0".into()
            } else if !x.is_finite() {
                x.to_string()
            } else if (1e-3..1e4).contains(&a) {
                let decimals = (4 - a.log10().floor() as i32).max(0) as usize;
                format!("{x:.decimals$}")
            } else {
                format!("{x:.4e}")
            }
        }
        Cell::Bool(b) => if b { "yes" } else { "no" }.into(),
        other => other.to_string(),
    }
}

/// Column names and every row of a frame as display strings.
///
/// # Errors
/// None today (kept for callers written against the fallible polars-backed version).
pub fn display_rows(df: &Frame) -> Result<(Vec<String>, Vec<Vec<String>>)> {
    let names = df.names().iter().map(|n| n.to_string()).collect();
    let rows = (0..df.height())
        .map(|i| {
            df.columns()
                .iter()
                .map(|c| c.get(i).map_or_else(String::new, cell))
                .collect()
        })
        .collect();
    Ok((names, rows))
}

/// Any frame as a Markdown pipe table.
///
/// # Errors
/// None today (see [`display_rows`]).
pub fn markdown(df: &Frame) -> Result<String> {
    let (names, rows) = display_rows(df)?;
    let mut md = String::new();
    let _ = writeln!(md, "| {} |", names.join(" | "));
    let _ = writeln!(md, "|{}", "---|".repeat(names.len()));
    for row in rows {
        let _ = writeln!(md, "| {} |", row.join(" | "));
    }
    Ok(md)
}

/// Any frame as an HTML `<table>` with every row and column.
///
/// # Errors
/// None today (see [`display_rows`]).
pub fn html_table(df: &Frame) -> Result<String> {
    let (names, rows) = display_rows(df)?;
    Ok(html_rows(&names, &rows))
}

/// An HTML `<table>` of a header row and body rows of display strings (escaped here), for
/// frames ([`html_table`]) and for tables read back from their CSV (the site).
pub(crate) fn html_rows(names: &[String], rows: &[Vec<String>]) -> String {
    let mut html = String::from("<table>\n<thead><tr>");
    for n in names {
        let _ = write!(html, "<th>{}</th>", escape(n));
    }
    html.push_str("</tr></thead>\n<tbody>\n");
    for row in rows {
        html.push_str("<tr>");
        for c in row {
            let _ = write!(html, "<td>{}</td>", escape(c));
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</tbody>\n</table>");
    html
}

/// Any frame as CSV (RFC 4180): a header row, then one row per record; floats in the
/// shortest form that reads back to the same `f64` (full precision), missing values empty,
/// text quoted when it holds a comma, a quote or a line break.
///
/// # Errors
/// None today (see [`display_rows`]).
pub fn csv(df: &Frame) -> Result<Vec<u8>> {
    fn field(v: Cell) -> String {
        let text = match v {
            Cell::Null => String::new(),
            Cell::Float(x) => format!("{x:?}"),
            other => other.to_string(),
        };
        if text.contains([',', '"', '\n', '\r']) {
            format!("\"{}\"", text.replace('"', "\"\""))
        } else {
            text
        }
    }
    let mut out = String::new();
    let names: Vec<String> = df
        .names()
        .into_iter()
        .map(|n| field(Cell::Text(n)))
        .collect();
    out.push_str(&names.join(","));
    out.push('\n');
    for i in 0..df.height() {
        let row: Vec<String> = df
            .columns()
            .iter()
            .map(|c| c.get(i).map_or_else(String::new, field))
            .collect();
        out.push_str(&row.join(","));
        out.push('\n');
    }
    Ok(out.into_bytes())
}

/// Writes any frame to `path` as CSV (through a temporary file renamed into place).
///
/// # Errors
/// [`crate::report::Error::Io`] if the file cannot be written.
pub fn write_csv(df: &Frame, path: &Path) -> Result<()> {
    write_atomic(path, &csv(df)?)
}

/// A surface tabulated on `ns × nt` points of `rect` with its exact partials: columns `s`, `t`,
/// then `x, y, z`, `x_s, y_s, z_s`, `x_t, …`, `x_st, …` (hyper-dual numbers, one evaluation
/// per point).
///
/// # Errors
/// As [`partials_on_grid`] (too few or too many samples, a non-finite surface).
pub fn tabulation<S: SurfaceDerivatives + Sync + ?Sized>(
    surface: &S,
    rect: &Rect,
    ns: usize,
    nt: usize,
) -> Result<Table> {
    let s = rect.s.linspace_named("ns", ns)?;
    let t = rect.t.linspace_named("nt", nt)?;
    let grid = partials_on_grid(surface, &s, &t)?;
    let mut columns = vec![
        Column::new(
            "s".into(),
            (0..ns * nt).map(|k| s[k / nt]).collect::<Vec<f64>>(),
        ),
        Column::new(
            "t".into(),
            (0..ns * nt).map(|k| t[k % nt]).collect::<Vec<f64>>(),
        ),
    ];
    type Part = fn(&crate::surface::Partials) -> Vector3<f64>;
    let parts: [(&str, Part); 4] = [
        ("", |p| p.point),
        ("_s", |p| p.ds),
        ("_t", |p| p.dt),
        ("_st", |p| p.dst),
    ];
    for (suffix, get) in parts {
        for (k, axis) in COORDS.iter().enumerate() {
            let values: Vec<f64> = grid.as_slice().iter().map(|p| get(p)[k]).collect();
            columns.push(Column::new(format!("{axis}{suffix}"), values));
        }
    }
    let title = format!(
        "Surface and exact partials on {ns}×{nt} points of [{}, {}] × [{}, {}]",
        rect.s.start(),
        rect.s.end(),
        rect.t.start(),
        rect.t.end()
    );
    Ok(Table::new("tabulation", title, frame("tabulation", columns)?)
        .note("Partials from one hyper-dual evaluation per point (num-dual HyperDual64): exact to rounding."))
}

crate::record! {
    /// A row of an error-study table: one case and coordinate.
    struct CoordErrorRow {
        case: String => "case",
        coord: &'static str => "coord",
        report_norm: f64 => "report_norm",
        max_abs: f64 => "max_abs",
        rms: f64 => "rms",
    }
}

/// Error studies side by side: one row per case and coordinate with the report's measure
/// (mean of per-patch matrix 2-norms), max-abs and RMS.
///
/// # Errors
/// [`crate::report::Error::Table`] only if the columns came out ragged (an internal error).
pub fn coord_errors(id: &str, title: &str, cases: &[(String, CoordErrors)]) -> Result<Table> {
    let rows: Vec<CoordErrorRow> = cases
        .iter()
        .flat_map(|(name, e)| {
            COORDS
                .iter()
                .enumerate()
                .map(move |(k, axis)| CoordErrorRow {
                    case: name.clone(),
                    coord: axis,
                    report_norm: e.report_norm[k],
                    max_abs: e.max_abs[k],
                    rms: e.rms[k],
                })
        })
        .collect();
    let df = crate::report::record::frame_of(id, &rows)?;
    Ok(Table::new(id, title, df)
        .note("report_norm: the report's measure, the mean over patches of the matrix 2-norm of each patch's error samples (MATLAB norm); max_abs and rms over all samples."))
}

/// A convergence study ([`crate::study::hermite_error::convergence`]) as a table: per `n` and coordinate,
/// max-abs, RMS and the report's measure with the observed order against the previous row.
///
/// # Errors
/// [`crate::report::Error::Table`] only if the columns came out ragged (an internal error).
pub fn convergence(id: &str, title: &str, rows: &[ConvergenceRow]) -> Result<Table> {
    let (mut n_col, mut h_col, mut coord) = (vec![], vec![], vec![]);
    // value and order (None on the first row, which has no previous row) of each measure
    type Measure = fn(&CoordErrors) -> Vector3<f64>;
    type Order = fn(&ConvergenceOrders) -> [Option<f64>; 3];
    let measures: [(&str, Measure, Order); 3] = [
        ("max_abs", |e| e.max_abs, |o| o.max_abs),
        ("rms", |e| e.rms, |o| o.rms),
        ("report_norm", |e| e.report_norm, |o| o.report_norm),
    ];
    let mut values: [Vec<f64>; 3] = Default::default();
    let mut orders: [Vec<Option<f64>>; 3] = Default::default();
    for row in rows {
        for (k, axis) in COORDS.iter().enumerate() {
            n_col.push(row.n as u32);
            h_col.push(row.h);
            coord.push(*axis);
            for (q, (_, get, order)) in measures.iter().enumerate() {
                values[q].push(get(&row.errors)[k]);
                orders[q].push(row.order.as_ref().and_then(|o| order(o)[k]));
            }
        }
    }
    let mut columns = vec![
        Column::new("n".into(), n_col),
        Column::new("h".into(), h_col),
        Column::new("coord".into(), coord),
    ];
    for (q, (name, _, _)) in measures.iter().enumerate() {
        columns.push(Column::new((*name).into(), std::mem::take(&mut values[q])));
        columns.push(Column::new(
            format!("order_{name}"),
            std::mem::take(&mut orders[q]),
        ));
    }
    let mut table = Table::new(id, title, frame(id, columns)?)
        .note("order_*: log(e_prev/e)/log(h_prev/h) against the previous row; bicubic Hermite interpolation converges as h⁴ (— on the first row, and where an error is at rounding level).")
        .note("report_norm is the report's measure (mean over patches of per-patch matrix 2-norms).");
    let at_rounding: Vec<String> = COORDS
        .iter()
        .enumerate()
        .filter(|&(k, _)| rows.iter().any(|r| r.at_rounding(r.errors.max_abs[k])))
        .map(|(_, axis)| (*axis).to_string())
        .collect();
    if let Some(level) = rows.first().map(|r| r.rounding) {
        if !at_rounding.is_empty() {
            let (which, reach) = if at_rounding.len() == 1 {
                ("Coordinate", "reaches")
            } else {
                ("Coordinates", "reach")
            };
            table = table.note(format!(
                "{which} {} {reach} the rounding level {} (128 ε × the surface's largest coordinate): there the error is the rounding of f64 (the spline reproduces it), and no order is computed from it.",
                at_rounding.join(", "),
                crate::printed::rounded(level, 2)
            ));
        }
    }
    Ok(table)
}

/// The continuity of a spline surface across its seams: for every interior node `uᵢ` (and
/// `vⱼ`), sampled at `samples` points along it, the largest jump of `X` and of the
/// cross-seam derivative (`X_u` across a u-seam, `X_v` across a v-seam) between the patch
/// on the left and the patch on the right, each read from its own Hermite matrix at its own
/// edge (`s = 1` vs `s = 0`) and scaled by its own width (`X_u = X_s / Δu`), and the size of
/// that derivative for scale. C¹ interpolation makes both jumps zero up to rounding.
///
/// # Errors
/// [`crate::error::Error::TooFewSamples`] if `samples < 2`; [`crate::report::Error::Table`] only if the
/// columns came out ragged (an internal error).
pub fn seam_continuity(
    spline: &crate::hermite::spline_surface::HermiteSurface,
    samples: usize,
) -> Result<Table> {
    let local = crate::domain::Interval::try_new(0.0, 1.0)?.linspace(samples)?;
    let (n, m) = spline.patch_counts();
    let (u, v) = (spline.u().nodes(), spline.v().nodes());
    let mut rows = Vec::new();
    let mut seam = |name: &'static str, at: f64, pairs: Vec<(Partials2, Partials2)>| {
        let mut row = SeamRow {
            seam: name,
            node: at,
            jump_x: 0.0,
            jump_derivative: 0.0,
            derivative: 0.0,
        };
        for (a, b) in pairs {
            row.jump_x = row.jump_x.max((a.0 - b.0).amax());
            row.jump_derivative = row.jump_derivative.max((a.1 - b.1).amax());
            row.derivative = row.derivative.max(a.1.amax());
        }
        rows.push(row);
    };
    for i in 1..n {
        let (wl, wr) = (u[i] - u[i - 1], u[i + 1] - u[i]);
        let pairs = (0..m)
            .flat_map(|j| local.iter().map(move |&t| (j, t)))
            .map(|(j, t)| {
                let l =
                    crate::surface::SurfaceDerivatives::partials(&spline.patch(i - 1, j), 1.0, t);
                let r = crate::surface::SurfaceDerivatives::partials(&spline.patch(i, j), 0.0, t);
                ((l.point, l.ds / wl), (r.point, r.ds / wr))
            })
            .collect();
        seam("u", u[i], pairs);
    }
    for j in 1..m {
        let (wl, wr) = (v[j] - v[j - 1], v[j + 1] - v[j]);
        let pairs = (0..n)
            .flat_map(|i| local.iter().map(move |&s| (i, s)))
            .map(|(i, s)| {
                let l =
                    crate::surface::SurfaceDerivatives::partials(&spline.patch(i, j - 1), s, 1.0);
                let r = crate::surface::SurfaceDerivatives::partials(&spline.patch(i, j), s, 0.0);
                ((l.point, l.dt / wl), (r.point, r.dt / wr))
            })
            .collect();
        seam("v", v[j], pairs);
    }
    let df = crate::report::record::frame_of("seams", &rows)?;
    Ok(Table::new("seams", "Continuity across the seams of the spline surface", df)
        .note("Each side read from its own patch at its own edge; the cross derivative is X_u = X_s/Δu across a u-seam and X_v = X_t/Δv across a v-seam. Zero jumps (to rounding) are C¹ continuity."))
}

crate::record! {
    /// A row of the seam table: one seam.
    struct SeamRow {
        seam: &'static str => "seam",
        node: f64 => "node",
        jump_x: f64 => "max_jump_X",
        jump_derivative: f64 => "max_jump_cross_derivative",
        derivative: f64 => "max_cross_derivative",
    }
}

/// A point and the cross-seam derivative.
type Partials2 = (Vector3<f64>, Vector3<f64>);

/// An error study of `surface` on `rect` for several patch counts `(n, m)`: each case's
/// uniform `n × m` Hermite spline, `prec × prec` samples per patch, measured by the report's
/// norm, max-abs and RMS ([`crate::study::hermite_error::uniform_spline_errors`] with the Hermite matrix form).
///
/// # Errors
/// As [`crate::study::hermite_error::uniform_spline_errors`].
pub fn error_study<S: SurfaceDerivatives + Sync + ?Sized>(
    surface: &S,
    rect: &Rect,
    cases: &[(usize, usize)],
    prec: usize,
) -> Result<Table> {
    let rows = cases
        .iter()
        .map(|&(n, m)| {
            let e = crate::study::hermite_error::uniform_spline_errors(
                surface,
                rect,
                n,
                m,
                prec,
                crate::study::hermite_error::PatchEvaluation::HermiteMatrix,
            )?;
            Ok((format!("{n}×{m}"), e))
        })
        .collect::<crate::error::Result<Vec<_>>>()?;
    coord_errors(
        "error-study",
        &format!("Error of the n × m Hermite spline, {prec}×{prec} samples per patch"),
        &rows,
    )
}
