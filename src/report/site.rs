//! A static site of a run's outputs, opened from the file system with no server and no
//! network: `site/index.html` links the notebooks' HTML copies, shows every figure of the
//! registry ([`super::outputs`]) as its PNG with its id and caption, every table rendered
//! from its CSV (with the CSV and Markdown beside it), and the API documentation.
//!
//! [`write_site`] reads what a run wrote under `out/` (`figures/<id>.png`,
//! `tables/<id>.csv|md`) and copies it into `out/site/`, so the folder stands alone; the
//! notebooks' pages (`site/notebooks/*.html`) and `cargo doc`'s (`site/doc/`) are put there by
//! `scripts/notebooks.sh --site`, and linked when present. Outputs not generated yet are
//! listed as such, never drawn from elsewhere.

use crate::report::error::{io_err, Result};
use crate::report::files::write_atomic;
use crate::report::notebook::escape;
use crate::report::table::html_rows;
use crate::report::{outputs, Output};
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

/// The fields of one CSV record as our writer quotes them ([`crate::report::table::csv`]:
/// a field in double quotes when it holds a comma, a quote or a line break, a quote doubled).
/// Records end at a line break outside quotes.
fn csv_records(text: &str) -> Vec<Vec<String>> {
    let mut records = Vec::new();
    let (mut record, mut field) = (Vec::new(), String::new());
    let (mut quoted, mut chars) = (false, text.chars().peekable());
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            ('"', true) => quoted = false,
            ('"', false) if field.is_empty() => quoted = true,
            (',', false) => record.push(std::mem::take(&mut field)),
            ('\r', false) => {}
            ('\n', false) => {
                record.push(std::mem::take(&mut field));
                records.push(std::mem::take(&mut record));
            }
            (c, _) => field.push(c),
        }
    }
    if !field.is_empty() || !record.is_empty() {
        record.push(field);
        records.push(record);
    }
    records
}

/// A CSV as an HTML table ([`crate::report::table::html_rows`]), its first record the header.
fn csv_table(text: &str) -> String {
    let mut records = csv_records(text);
    let header = if records.is_empty() {
        Vec::new()
    } else {
        records.remove(0)
    };
    html_rows(&header, &records)
}

/// Copies `from` to `to` (atomically, as every output is written) if `from` exists; whether
/// it did.
fn copy_if_present(from: &Path, to: &Path) -> Result<bool> {
    match fs::read(from) {
        Ok(bytes) => {
            write_atomic(to, &bytes)?;
            Ok(true)
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(false),
        Err(e) => Err(io_err(from)(e)),
    }
}

/// The `.html` files directly in `dir`, sorted (none if it does not exist).
fn pages_in(dir: &Path) -> Vec<String> {
    let mut pages: Vec<String> = fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| e.file_name().into_string().ok())
        .filter(|name| name.ends_with(".html"))
        .collect();
    pages.sort();
    pages
}

/// What the site shows for an output the run did not write.
const MISSING: &str = "<p class=\"missing\">not generated in this run</p>";

const STYLE: &str = "body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}\
h1{font-size:1.6em}h2{margin-top:2em;border-bottom:1px solid #ccc}\
.gallery{display:grid;grid-template-columns:repeat(auto-fill,minmax(360px,1fr));gap:1.5em}\
figure{margin:0}figure img{width:100%;border:1px solid #ddd}figcaption{font-size:.9em;margin-top:.3em}\
table{border-collapse:collapse;font-size:.85em;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}\
th{background:#f3f3f3}details{margin:.6em 0}summary{cursor:pointer}code{background:#f3f3f3;padding:0 .2em}\
.missing{color:#a00}";

/// One output on the page, under its id and caption: a figure as a figure, a table folded
/// (`<details>`); `body` `None` if the run did not write it.
fn entry(o: &Output, body: Option<String>) -> String {
    let body = body.unwrap_or_else(|| MISSING.into());
    let caption = format!("<code>{}</code> — {}", o.id, escape(o.description));
    if o.is_figure() {
        format!(
            "<figure id=\"{}\">{body}<figcaption>{caption}</figcaption></figure>",
            o.id
        )
    } else {
        format!(
            "<details id=\"{}\"><summary>{caption}</summary>{body}</details>",
            o.id
        )
    }
}

/// Writes `out/site/` from the outputs under `out/` (module docs); returns the index page.
///
/// # Errors
/// [`crate::report::Error::Io`] if a file cannot be read or written.
pub fn write_site(out: &Path) -> Result<PathBuf> {
    let site = out.join("site");
    for dir in ["figures", "tables"] {
        fs::create_dir_all(site.join(dir)).map_err(io_err(&site.join(dir)))?;
    }
    let mut html = format!(
        "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>splinelab: notebooks, figures and tables</title><style>{STYLE}</style></head><body>\
<h1>splinelab — notebooks, figures and tables</h1>\
<p>Everything here was written by one run of <code>cargo run --release</code> (figures and tables) and \
<code>scripts/notebooks.sh --site</code> (notebooks and API documentation); the page opens from the file system.</p>"
    );
    let (figures, tables): (Vec<&Output>, Vec<&Output>) = outputs().partition(|o| o.is_figure());
    // a run's file copied into the site's folder of the same name, if the run wrote it
    let bring = |dir: &str, name: &str| {
        copy_if_present(&out.join(dir).join(name), &site.join(dir).join(name))
    };
    let notebooks = pages_in(&site.join("notebooks"));
    html.push_str("<h2 id=\"notebooks\">Notebooks</h2>");
    if notebooks.is_empty() {
        html.push_str("<p class=\"missing\">Not here yet: <code>scripts/notebooks.sh --site</code> executes the notebooks and copies their HTML pages in.</p>");
    } else {
        html.push_str("<ul>");
        for page in &notebooks {
            let name = page.trim_end_matches(".html");
            let _ = write!(
                html,
                "<li><a href=\"notebooks/{}\">{}</a></li>",
                escape(page),
                escape(name)
            );
        }
        html.push_str("</ul>");
    }
    let _ = write!(
        html,
        "<h2 id=\"figures\">Figures ({})</h2><div class=\"gallery\">",
        figures.len()
    );
    for o in &figures {
        let png = format!("{}.png", o.id);
        let picture = bring("figures", &png)?.then(|| {
            format!("<a href=\"figures/{png}\"><img src=\"figures/{png}\" alt=\"{}\" loading=\"lazy\"></a>", escape(o.description))
        });
        html.push_str(&entry(o, picture));
    }
    let _ = write!(
        html,
        "</div><h2 id=\"tables\">Tables ({})</h2>",
        tables.len()
    );
    for o in &tables {
        let (csv, md) = (format!("{}.csv", o.id), format!("{}.md", o.id));
        let here = bring("tables", &csv)?;
        bring("tables", &md)?;
        let body = if here {
            let path = site.join("tables").join(&csv);
            let text = fs::read_to_string(&path).map_err(io_err(&path))?;
            Some(format!(
                "{} <a href=\"tables/{csv}\">CSV</a> · <a href=\"tables/{md}\">Markdown</a>",
                csv_table(&text)
            ))
        } else {
            None
        };
        html.push_str(&entry(o, body));
    }
    html.push_str("<h2 id=\"api\">API documentation</h2>");
    if site.join("doc/splinelab/index.html").exists() {
        html.push_str("<p><a href=\"doc/splinelab/index.html\">splinelab's API documentation</a> (<code>cargo doc</code>).</p>");
    } else {
        html.push_str("<p class=\"missing\">Not here yet: <code>scripts/notebooks.sh --site</code> copies <code>cargo doc</code>'s pages in.</p>");
    }
    html.push_str("</body></html>\n");
    let index = site.join("index.html");
    write_atomic(&index, html.as_bytes())?;
    Ok(index)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_records_read_what_the_writer_quotes() {
        let text = "a,\"b, c\",\"say \"\"hi\"\"\"\n1,\"two\nlines\",3\n";
        assert_eq!(
            csv_records(text),
            vec![
                vec!["a".to_string(), "b, c".into(), "say \"hi\"".into()],
                vec!["1".to_string(), "two\nlines".into(), "3".into()],
            ]
        );
        assert!(csv_table("x,<y>\n1,2\n").contains("<th>&lt;y&gt;</th>"));
    }

    /// A site from an `out/` folder with one figure and one table: both copied and shown,
    /// the rest listed as not generated; the notebooks and the API documentation linked once
    /// present.
    #[test]
    fn a_site_shows_what_the_run_wrote() {
        let out = tempfile::tempdir().expect("temp dir");
        let (fig, table) = (
            outputs().find(|o| o.is_figure()).expect("a figure"),
            outputs().find(|o| !o.is_figure()).expect("a table"),
        );
        fs::create_dir_all(out.path().join("figures")).expect("dir");
        fs::create_dir_all(out.path().join("tables")).expect("dir");
        fs::write(out.path().join(format!("figures/{}.png", fig.id)), b"png").expect("write");
        fs::write(
            out.path().join(format!("tables/{}.csv", table.id)),
            "k,v\n1,2\n",
        )
        .expect("write");
        let index = write_site(out.path()).expect("site");
        let html = fs::read_to_string(&index).expect("index");
        assert!(html.contains(&format!("<img src=\"figures/{}.png\"", fig.id)));
        assert!(out
            .path()
            .join(format!("site/figures/{}.png", fig.id))
            .exists());
        assert!(html.contains("<th>k</th>") && html.contains("<td>2</td>"));
        assert!(html.contains("not generated in this run"));
        assert!(html.contains("Not here yet"));
        fs::create_dir_all(out.path().join("site/notebooks")).expect("dir");
        fs::write(out.path().join("site/notebooks/01-x.html"), "<html>").expect("write");
        fs::create_dir_all(out.path().join("site/doc/splinelab")).expect("dir");
        fs::write(out.path().join("site/doc/splinelab/index.html"), "<html>").expect("write");
        let html = fs::read_to_string(write_site(out.path()).expect("site")).expect("index");
        assert!(
            html.contains("href=\"notebooks/01-x.html\"")
                && html.contains("doc/splinelab/index.html")
        );
        assert!(!html.contains("Not here yet"));
        // an output folder that does not exist yet: a site listing everything as missing;
        // one that is a file: an I/O error naming it, nothing written
        let fresh = out.path().join("never-run");
        let html = fs::read_to_string(write_site(&fresh).expect("site")).expect("index");
        assert!(!html.contains("<img") && html.contains("not generated in this run"));
        let file = out.path().join("a-file");
        fs::write(&file, b"x").expect("write");
        assert!(matches!(
            write_site(&file),
            Err(crate::report::Error::Io { .. })
        ));
    }
}
