//! What a notebook cell displays beyond figures and tables: 4×4 matrices in the report's
//! layout (rows ↔ s, columns ↔ t) with labels, partials with their names, any matrix with
//! row and column labels. Each returns an [`Html`] value, which the evcxr kernel shows as a
//! table and which prints as aligned text elsewhere.
//!
//! nalgebra's own `Debug` of a `Matrix4` prints its column-major storage, i.e. the transpose
//! of the matrix as written in the report; these views never do.

use crate::bezier::patch::BezierPatch;
use crate::hermite::patch::HermitePatch;
use crate::surface::Partials;
use nalgebra::{Matrix4, Vector3};
use std::fmt::Write as _;

/// An HTML fragment for a notebook, with a plain-text twin for `Display`.
#[derive(Debug, Clone, PartialEq)]
pub struct Html {
    /// The HTML.
    pub html: String,
    /// The same content as aligned text.
    pub text: String,
}

impl Html {
    /// Shows the fragment in a notebook (the evcxr kernel calls this for a cell's value).
    pub fn evcxr_display(&self) {
        println!(
            "EVCXR_BEGIN_CONTENT text/html\n{}\nEVCXR_END_CONTENT",
            self.html
        );
    }
}

impl std::fmt::Display for Html {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text)
    }
}

/// Text for HTML: `&`, `<`, `>` escaped (the formula layer's function).
pub(crate) use crate::symbolic::escape;

/// A number for reading: 6 significant digits, `0` for exact zero.
fn num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 {
        "0".into()
    } else if !x.is_finite() {
        x.to_string()
    } else if (1e-4..1e5).contains(&a) {
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{x:.decimals$}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        s.to_string()
    } else {
        format!("{x:.5e}")
    }
}

/// Matrices with labelled rows and columns, side by side: `blocks[k] = (caption, rows)` where
/// `rows[i][j]` is row `i`, column `j` exactly as written on paper.
pub fn labelled_matrices(
    title: &str,
    row_labels: &[&str],
    col_labels: &[&str],
    blocks: &[(String, Vec<Vec<f64>>)],
) -> Html {
    let mut html = format!(
        "<div><b>{}</b><div style=\"display:flex;gap:2em;flex-wrap:wrap\">",
        escape(title)
    );
    let mut text = format!("{title}\n");
    for (caption, rows) in blocks {
        let _ = write!(
            html,
            "<table><caption>{}</caption><thead><tr><th></th>",
            escape(caption)
        );
        for c in col_labels {
            let _ = write!(html, "<th>{}</th>", escape(c));
        }
        html.push_str("</tr></thead><tbody>");
        let cells: Vec<Vec<String>> = rows
            .iter()
            .map(|r| r.iter().map(|&x| num(x)).collect())
            .collect();
        let width = cells
            .iter()
            .flatten()
            .map(|s| s.chars().count())
            .chain(col_labels.iter().map(|c| c.chars().count()))
            .max()
            .unwrap_or(1);
        let label_width = row_labels
            .iter()
            .map(|l| l.chars().count())
            .max()
            .unwrap_or(0);
        let _ = writeln!(text, "\n{caption}");
        let _ = write!(text, "{:label_width$}", "");
        for c in col_labels {
            let _ = write!(text, "  {c:>width$}");
        }
        text.push('\n');
        for (i, row) in cells.iter().enumerate() {
            let label = row_labels.get(i).copied().unwrap_or("");
            let _ = write!(html, "<tr><th>{}</th>", escape(label));
            let _ = write!(text, "{label:label_width$}");
            for c in row {
                let _ = write!(html, "<td style=\"text-align:right\">{c}</td>");
                let _ = write!(text, "  {c:>width$}");
            }
            html.push_str("</tr>");
            text.push('\n');
        }
        html.push_str("</tbody></table>");
    }
    html.push_str("</div></div>");
    Html { html, text }
}

/// The three coordinate planes of a 4×4 net of points, row `i` ↔ s, column `j` ↔ t.
fn planes_of(net: &[[Vector3<f64>; 4]; 4]) -> Vec<(String, Vec<Vec<f64>>)> {
    ["x", "y", "z"]
        .iter()
        .enumerate()
        .map(|(k, axis)| {
            let rows = (0..4)
                .map(|i| (0..4).map(|j| net[i][j][k]).collect())
                .collect();
            (format!("{axis} plane"), rows)
        })
        .collect()
}

/// The Hermite matrix `C` of a patch in the report's layout (seed 000 §1, Codice 4): rows
/// `X(0,·), X_s(0,·), X_s(1,·), X(1,·)` ↔ s, columns `X(·,0), X_t(·,0), X_t(·,1), X(·,1)` ↔ t,
/// one table per coordinate.
pub fn hermite_matrix(patch: &HermitePatch) -> Html {
    labelled_matrices(
        "Hermite matrix C (rows ↔ s, columns ↔ t)",
        &["s=0: X", "s=0: ∂s", "s=1: ∂s", "s=1: X"],
        &["t=0: X", "t=0: ∂t", "t=1: ∂t", "t=1: X"],
        &planes_of(patch.matrix()),
    )
}

/// The Bézier control net `M` of a patch, `b_ij` with row `i` ↔ s, column `j` ↔ t.
pub fn bezier_net(patch: &BezierPatch) -> Html {
    labelled_matrices(
        "Bézier control net M = A C Aᵀ (rows ↔ s, columns ↔ t)",
        &["i=0", "i=1", "i=2", "i=3"],
        &["j=0", "j=1", "j=2", "j=3"],
        &planes_of(patch.net()),
    )
}

/// A 4×4 matrix as written on paper (row `i`, column `j`), with labels.
pub fn matrix4(title: &str, m: &Matrix4<f64>, row_labels: &[&str], col_labels: &[&str]) -> Html {
    let rows = (0..4)
        .map(|i| (0..4).map(|j| m[(i, j)]).collect())
        .collect();
    labelled_matrices(title, row_labels, col_labels, &[(String::new(), rows)])
}

/// A few named rows of numbers as a table — `rows[k] = (label, values)`, a column per entry
/// of `col_labels` — so that a cell shows what each number is instead of a tuple's `Debug`
/// text: `notebook::values("ends", &["x", "y"], &[("P′(start)", &[1.0, 2.0])])`.
pub fn values(title: &str, col_labels: &[&str], rows: &[(&str, &[f64])]) -> Html {
    let labels: Vec<&str> = rows.iter().map(|r| r.0).collect();
    let numbers = rows.iter().map(|r| r.1.to_vec()).collect();
    labelled_matrices(title, &labels, col_labels, &[(String::new(), numbers)])
}

/// A point's partials `X, X_s, X_t, X_st` as a table: one row per partial, columns x, y, z.
pub fn partials(p: &Partials) -> Html {
    let rows = [p.point, p.ds, p.dt, p.dst]
        .iter()
        .map(|v| v.iter().copied().collect())
        .collect();
    labelled_matrices(
        "partials",
        &["X", "X_s", "X_t", "X_st"],
        &["x", "y", "z"],
        &[(String::new(), rows)],
    )
}

/// The one call of a notebook's setup cell, after its `:dep` line: draws a small figure with
/// text in memory, so that a missing font or a broken backend shows here, by name, and not in
/// the first figure. Called with `?`, it also settles how the kernel shows the session's later
/// results (evcxr shows the value of the first cell that uses `?` as `Debug` text; after this
/// call, figures, tables and formulas display as themselves).
///
/// # Errors
/// The error of drawing or encoding the test figure.
pub fn setup() -> crate::report::Result<()> {
    let figure = crate::report::draw::Plot2d::new("setup", "x", "y")
        .function("x", 0.0, 1.0, |x| x)
        .figure()
        .with_size(120, 90);
    figure.to_png().map(|_| ())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every label and number of [`values`] is in its table, in order, and a run of the
    /// benchmark shows as such a table, never as its `Debug` text.
    #[test]
    fn values_are_labelled() {
        let v = values(
            "ends <1>",
            &["x", "y"],
            &[("P′(start)", &[1.5, -2.0]), ("P″(end)", &[0.0, 1e-14])],
        );
        for needle in [
            "ends &lt;1&gt;",
            "P′(start)",
            "P″(end)",
            "<th>x</th>",
            "1.5",
            "-2",
            "1.00000e-14",
        ] {
            assert!(v.html.contains(needle), "{needle} in {}", v.html);
        }
        assert!(v.html.find("P′(start)") < v.html.find("P″(end)"));
        // no rows, rows of different lengths, non-finite values: shown as they are
        assert!(values("none", &["x"], &[]).html.contains("none"));
        let odd = values(
            "odd",
            &["x", "y"],
            &[
                ("a", &[f64::NAN]),
                ("b", &[f64::INFINITY, -f64::MAX, 1.0]),
                ("c", &[]),
            ],
        );
        for needle in ["NaN", "inf", "-1.79769e308"] {
            assert!(odd.html.contains(needle), "{needle} in {}", odd.html);
        }
        let run = crate::report::bench::BenchResult {
            workload: "patch-matrix",
            size: 15,
            points: 225,
            seconds: 1.5e-6,
        }
        .html();
        assert!(run.html.contains("patch-matrix") && run.html.contains("points / s"));
        assert!(!run.text.contains("BenchResult"));
    }
}
