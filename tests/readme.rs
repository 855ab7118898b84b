//! The README's table of outputs names exactly the outputs the program writes: every id in
//! the table is in the registry (`splinelab --list`) and every registered id is in the table.
//! Rows may shorten a family of ids: `fig-seed004-circle`, `-ellipse-0.7` (the first id's
//! `fig-seed004` stem, then the rest) and `fig-seed004-letter-a-1` … `-letter-a-4` (a range of
//! the trailing number).
#![cfg(feature = "report")]

use std::collections::BTreeSet;

/// The ids of the README's `| id | content |` table, families expanded.
fn readme_ids() -> BTreeSet<String> {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md");
    let mut lines = text.lines().skip_while(|l| l.trim() != "| id | content |");
    assert!(
        lines.next().is_some(),
        "the README has a `| id | content |` table"
    );
    let mut ids = BTreeSet::new();
    for row in lines.skip(1).take_while(|l| l.starts_with("| `")) {
        let first_cell = row[2..].split(" | ").next().expect("a first cell");
        // the backticked tokens and whether "…" (a range) came before each
        let mut tokens: Vec<(bool, &str)> = Vec::new();
        let mut rest = first_cell;
        while let Some(open) = rest.find('`') {
            let before = &rest[..open];
            let close = rest[open + 1..].find('`').expect("closing backtick") + open + 1;
            tokens.push((before.contains('…'), &rest[open + 1..close]));
            rest = &rest[close + 1..];
        }
        let first = tokens[0].1.to_string();
        let stem: String = first.splitn(3, '-').take(2).collect::<Vec<_>>().join("-");
        let mut previous = first.clone();
        ids.insert(first);
        for &(range, token) in &tokens[1..] {
            let id = if token.starts_with('-') {
                format!("{stem}{token}")
            } else {
                token.to_string()
            };
            if range {
                let number = |s: &str| -> (String, u32) {
                    let digits = s.len() - s.trim_end_matches(|c: char| c.is_ascii_digit()).len();
                    let (head, tail) = s.split_at(s.len() - digits);
                    (head.to_string(), tail.parse().expect("a trailing number"))
                };
                let ((head, from), (_, to)) = (number(&previous), number(&id));
                for k in from + 1..to {
                    ids.insert(format!("{head}{k}"));
                }
            }
            previous = id.clone();
            ids.insert(id);
        }
    }
    ids
}

#[test]
fn the_readme_lists_every_output_and_no_other() {
    let registered: BTreeSet<String> = splinelab::report::outputs()
        .map(|o| o.id.to_string())
        .collect();
    let readme = readme_ids();
    let missing: Vec<_> = registered.difference(&readme).collect();
    let unknown: Vec<_> = readme.difference(&registered).collect();
    assert!(
        missing.is_empty() && unknown.is_empty(),
        "registered but not in the README: {missing:?}; in the README but not registered: {unknown:?}"
    );
    assert!(readme.len() > 40, "{} ids parsed", readme.len());
}

/// The README's own-crate example is the crate CI builds and tests (`tests/own-crate`): every
/// line of the README's block is a line of that crate's `src/lib.rs`, in order.
#[test]
fn the_readme_own_crate_example_is_the_crate_ci_builds() {
    let root = env!("CARGO_MANIFEST_DIR");
    let readme = std::fs::read_to_string(format!("{root}/README.md")).expect("README.md");
    let lib = std::fs::read_to_string(format!("{root}/tests/own-crate/src/lib.rs"))
        .expect("tests/own-crate/src/lib.rs");
    let start = readme
        .find("```rust,ignore\nuse splinelab::prelude::*;")
        .expect("the README shows the own crate's lib.rs");
    let block: Vec<&str> = readme[start..]
        .lines()
        .skip(1)
        .take_while(|l| !l.starts_with("```"))
        .collect();
    assert!(block.len() >= 10, "{block:?}");
    let text = block.join("\n");
    assert!(
        lib.contains(&text),
        "the README's block is not tests/own-crate/src/lib.rs:\n{text}"
    );
}
