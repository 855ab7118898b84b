//! The crate's layers depend one way (issue 28): the numeric core never names the formula
//! layer (`symbolic`) or the report layer (`report`); the formula layer never names the report
//! layer. The crate root (`lib.rs`, `prelude.rs`) re-exports them and the program (`main.rs`)
//! uses them, so those three files are the exceptions.
//!
//! Only code is read: comments (`//`, `///`, `//!`) may name any layer.
//!
//! Within the library, no file but the root's names an item through a root re-export
//! (`crate::Result`: the defining module is `crate::error`), and the modules import one
//! another without cycles at every level: the top-level files and folders of `src/`, and the
//! files of each folder ([`imports`]).

mod imports;

use imports::{code_lines, module_cycles, room_edges, root_reexport_offenders, sources, src_root};
use std::path::{Path, PathBuf};

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

#[test]
fn no_file_but_the_root_names_a_root_reexport() {
    let found = root_reexport_offenders(&src_root());
    assert!(
        found.is_empty(),
        "name the defining module (`crate::error::Result`), not the root re-export:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_modules_import_one_another_without_cycles() {
    let found = module_cycles(&src_root(), false);
    assert!(
        found.is_empty(),
        "modules that import one another:\n{}",
        found.join("\n")
    );
}

#[test]
fn no_module_and_its_own_file_import_one_another() {
    let found = module_cycles(&src_root(), true);
    assert!(
        found.is_empty(),
        "cycles through a `mod.rs`:\n{}",
        found.join("\n")
    );
}

/// Writes `files` (path under `src`, text) into a fresh temporary `src` folder.
fn fake_src(tag: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("splinelab-{tag}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    for (path, text) in files {
        let file = dir.join(path);
        std::fs::create_dir_all(file.parent().expect("a folder")).expect("a temporary folder");
        std::fs::write(&file, text).expect("a fake source file");
    }
    dir
}

#[test]
fn the_checks_see_cycles_and_root_reexports_named_in_code() {
    let src = fake_src(
        "cycles",
        &[
            ("lib.rs", "pub mod a;\npub mod b;\npub mod c;\npub mod d;\npub use a::{Thing, Other as O};\n"),
            ("a.rs", "use crate::b::{self, B};\npub struct Thing;\npub struct Other;\n"),
            ("b.rs", "pub fn f() {\n    crate::Thing::new(); // a, through the root's re-export\n}\n"),
            (
                "c.rs",
                "use crate::a::Thing; // crate::b\n/* crate::b::B */\nconst S: &str = \"crate::O\";\n\
                 #[cfg(test)]\nmod tests {\n    use crate::b::B;\n    fn t() { crate::O; }\n}\n",
            ),
            ("d/mod.rs", "mod x;\nmod y;\npub use x::X;\npub fn go() { x::run(); y::make(); }\nfn helper() {}\n"),
            ("d/x.rs", "use super::y::Y;\npub fn run() { super::helper(); super::super::c::f(); }\n"),
            (
                "d/y.rs",
                "use crate::error::Result;\npub fn make() {}\nconst R: &str = r#\"super::super::b\"#;\n\
                 mod inner {\n    fn f() { super::make(); }\n}\n",
            ),
            ("main.rs", "use splinelab::a::Thing;\nmod cli;\n"),
            ("cli/mod.rs", "use crate::Thing;\n"),
        ],
    );
    let reexports = root_reexport_offenders(&src);
    let plain = module_cycles(&src, false);
    let through_mod = module_cycles(&src, true);
    std::fs::remove_dir_all(&src).ok();
    assert_eq!(reexports.len(), 2, "{reexports:#?}");
    assert!(
        reexports[0].starts_with("b.rs:2: crate::Thing::new();"),
        "{reexports:#?}"
    );
    assert!(
        reexports[1].starts_with("c.rs:7: fn t() { crate::O; }"),
        "{reexports:#?}"
    );
    assert_eq!(plain.len(), 1, "{plain:#?}");
    assert_eq!(
        plain[0].lines().next(),
        Some("cycle in `crate`: a ⇄ b"),
        "{plain:#?}"
    );
    assert!(plain[0].contains("b → a: b.rs:2:"), "{plain:#?}");
    assert_eq!(through_mod.len(), 1, "{through_mod:#?}");
    assert_eq!(
        through_mod[0].lines().next(),
        Some("cycle in `d`: mod ⇄ x"),
        "{through_mod:#?}"
    );
}

/// The longest a function of the library may be: a longer one is split into named steps.
const MAX_FUNCTION_LINES: usize = 120;

/// Each function of `code` (comments and strings blanked) with its first line and its length
/// in lines, from its `fn` line to its closing brace (a function's nested closures and items
/// count as its lines).
fn function_lengths(code: &[String]) -> Vec<(String, usize, usize)> {
    let mut out = Vec::new();
    for (i, line) in code.iter().enumerate() {
        let Some(at) = line.find("fn ") else { continue };
        let before = &line[..at];
        let starts_item = before.trim().is_empty()
            || before.trim_end().ends_with("pub")
            || before.trim_end().ends_with(')')
            || before.trim_end().ends_with("const")
            || before.trim_end().ends_with("unsafe");
        if !starts_item || line.trim_end().ends_with(';') {
            continue;
        }
        let name: String = line[at + 3..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let (mut depth, mut opened) = (0i64, false);
        for (j, l) in code.iter().enumerate().skip(i) {
            for ch in l.chars() {
                match ch {
                    '{' => {
                        depth += 1;
                        opened = true;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if opened && depth <= 0 {
                out.push((name.clone(), i + 1, j - i + 1));
                break;
            }
            if !opened && l.trim_end().ends_with(';') {
                break;
            }
        }
    }
    out
}

#[test]
fn no_function_of_the_library_is_longer_than_120_lines() {
    let src = src_root();
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    let mut long = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).expect("a source file");
        for (name, line, len) in function_lengths(&code_lines(&text)) {
            if len > MAX_FUNCTION_LINES {
                long.push(format!("{}:{line}: fn {name}: {len} lines", f.display()));
            }
        }
    }
    assert!(
        long.is_empty(),
        "functions over {MAX_FUNCTION_LINES} lines:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_length_check_counts_a_function_from_its_line_to_its_brace() {
    let text = "/// doc { not counted\npub(crate) fn a(x: u8) -> u8 {\n    let s = \"}\";\n    x\n}\nfn b();\nfn c() {}\n";
    let found = function_lengths(&code_lines(text));
    assert_eq!(
        found,
        vec![("a".to_string(), 2, 4), ("c".to_string(), 7, 1)]
    );
}

/// The floors of the README's Layout (`| floor | rooms |`), top first: each floor's rooms,
/// named as modules (`interp/` and `nurbs.rs` are `interp` and `nurbs`).
fn readme_floors(readme: &str) -> Vec<Vec<String>> {
    let Some(start) = readme.find("| floor | rooms |") else {
        return Vec::new();
    };
    readme[start..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            let rooms = l.splitn(3, '|').nth(2).unwrap_or("");
            rooms
                .split('`')
                .skip(1)
                .step_by(2)
                .map(|r| r.trim_end_matches('/').trim_end_matches(".rs").to_string())
                .collect()
        })
        .collect()
}

/// The README's Layout gives the floors of the rooms; every room of `src/` is on one, and
/// each imports only rooms on the floors below its own.
#[test]
fn every_room_imports_only_the_floors_below_it() {
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md"))
        .expect("the README");
    let floors = readme_floors(&readme);
    assert!(
        floors.len() > 5,
        "the README's floor table is missing: {floors:?}"
    );
    let floor_of = |room: &str| floors.iter().position(|f| f.iter().any(|r| r == room));
    let mut wrong = Vec::new();
    for (from, to, witness) in room_edges(&src_root()) {
        match (floor_of(&from), floor_of(&to)) {
            (Some(a), Some(b)) if a < b => {}
            (Some(_), Some(_)) => {
                wrong.push(format!("{from} → {to} (not a lower floor): {witness}"))
            }
            _ => wrong.push(format!(
                "{from} → {to}: a room on no floor of the README: {witness}"
            )),
        }
    }
    assert!(
        wrong.is_empty(),
        "imports against the README's floors:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_floor_table_is_read_from_the_readme() {
    let text =
        "x\n| floor | rooms |\n|---|---|\n| top | `a/`, `b.rs` (note) |\n| low | `c.rs` |\n\nmore";
    assert_eq!(
        readme_floors(text),
        vec![
            vec!["a".to_string(), "b".to_string()],
            vec!["c".to_string()]
        ]
    );
}
