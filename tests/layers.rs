//! The crate's layers depend one way (issue 28): the numeric core never names the formula
//! layer (`symbolic`) or the report layer (`report`); the formula layer never names the report
//! layer. The crate root (`lib.rs`, `prelude.rs`) re-exports them and the program (`main.rs`)
//! uses them, so those three files are the exceptions.
//!
//! Only code is read: comments (`//`, `///`, `//!`) may name any layer.

use std::path::{Path, PathBuf};

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("a source folder") {
        let path = entry.expect("a folder entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The lines of code (comments cut) of `path` that name one of `layers` as a path.
fn naming(path: &Path, layers: &[&str]) -> Vec<String> {
    let text = std::fs::read_to_string(path).expect("a source file");
    text.lines()
        .enumerate()
        .filter_map(|(i, line)| {
            let code = line.split("//").next().unwrap_or("");
            layers
                .iter()
                .any(|layer| {
                    [
                        format!("crate::{layer}"),
                        format!("super::{layer}"),
                        format!("splinelab::{layer}"),
                    ]
                    .iter()
                    .any(|p| code.contains(p.as_str()))
                })
                .then(|| format!("{}:{}: {}", path.display(), i + 1, line.trim()))
        })
        .collect()
}

/// What `layers` are named where they must not be: every source file under `src/` whose path
/// (relative to `src/`) starts with none of `allowed`.
fn offenders(layers: &[&str], allowed: &[&str]) -> Vec<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    files
        .iter()
        .filter(|f| {
            let rel = f.strip_prefix(&src).expect("under src").to_string_lossy();
            let rel = rel.replace('\\', "/");
            !allowed.iter().any(|a| rel.starts_with(a))
        })
        .flat_map(|f| naming(f, layers))
        .collect()
}

#[test]
fn the_core_names_neither_the_formula_nor_the_report_layer() {
    let found = offenders(
        &["symbolic", "report"],
        &[
            "symbolic/",
            "report/",
            "cli/",
            "lib.rs",
            "prelude.rs",
            "main.rs",
        ],
    );
    assert!(
        found.is_empty(),
        "the core names a layer above it:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_formula_layer_does_not_name_the_report_layer() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/symbolic");
    let mut files = Vec::new();
    sources(&src, &mut files);
    let found: Vec<String> = files.iter().flat_map(|f| naming(f, &["report"])).collect();
    assert!(
        found.is_empty(),
        "the formula layer names the report layer:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_check_sees_a_layer_named_in_code_and_not_in_a_comment() {
    let dir = std::env::temp_dir().join(format!("splinelab-layers-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let file = dir.join("probe.rs");
    std::fs::write(
        &file,
        "/// see [`crate::symbolic`]\nlet k = crate::symbolic::claim::piece(&x, &t); // crate::report\n",
    )
    .expect("a probe file");
    let found = naming(&file, &["symbolic", "report"]);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].ends_with("let k = crate::symbolic::claim::piece(&x, &t); // crate::report"));
}
