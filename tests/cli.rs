//! The `splinelab` binary: default outputs, --list, --only, bench, and readable failures.

use std::process::Command;

fn splinelab() -> Command {
    Command::new(env!("CARGO_BIN_EXE_splinelab"))
}

/// Runs `splinelab --only ID --out DIR` and asserts it succeeded.
fn regenerate_only(id: &str, dir: &std::path::Path) {
    let out = splinelab()
        .args(["--only", id, "--out"])
        .arg(dir)
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn list_names_every_output() {
    let out = splinelab().arg("--list").output().expect("runs");
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for id in [
        "torus-partials",
        "t3-error",
        "t4-equivalence",
        "t6-spline-error",
        "convergence",
    ] {
        assert!(text.contains(id), "--list lacks {id}: {text}");
    }
}

#[test]
fn only_writes_csv_and_markdown() {
    let dir = tempfile::tempdir().expect("tempdir");
    regenerate_only("t6-spline-error", dir.path());
    let csv = std::fs::read_to_string(dir.path().join("tables/t6-spline-error.csv")).expect("csv");
    assert_eq!(csv.lines().count(), 13, "header + 12 rows:\n{csv}");
    let md = std::fs::read_to_string(dir.path().join("tables/t6-spline-error.md")).expect("md");
    assert!(
        md.contains("| printed |") || md.contains("| printed"),
        "{md}"
    );
    assert!(md.contains("Codice 7 sign error"), "{md}");
}

#[test]
fn unwritable_output_folder_fails_readably() {
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("not-a-folder");
    std::fs::write(&file, "x").expect("write");
    let out = splinelab()
        .args(["--only", "t3-error", "--out"])
        .arg(&file)
        .output()
        .expect("runs");
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("splinelab: error:"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn unknown_id_fails_readably() {
    let out = splinelab().args(["--only", "nope"]).output().expect("runs");
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("unknown output id `nope`"), "{err}");
}

#[test]
fn bench_prints_json_lines() {
    let out = splinelab()
        .args(["bench", "--only", "patch-matrix", "--millis", "1"])
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line = String::from_utf8_lossy(&out.stdout);
    for key in [
        "\"workload\": \"patch-matrix\"",
        "\"points\": 225",
        "\"seconds\"",
        "\"throughput\"",
    ] {
        assert!(line.contains(key), "{line}");
    }
}

#[test]
fn only_draws_one_figure() {
    let dir = tempfile::tempdir().expect("tempdir");
    regenerate_only("fig2-torus", dir.path());
    let names: Vec<String> = std::fs::read_dir(dir.path().join("figures"))
        .expect("figures folder")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
    assert!(names.contains(&"fig2-torus.png".to_string()), "{names:?}");
}
