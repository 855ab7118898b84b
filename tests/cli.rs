//! The `splinelab` binary: default outputs, --list, --only, bench, and readable failures.

use std::process::Command;

fn splinelab() -> Command {
    Command::new(env!("CARGO_BIN_EXE_splinelab"))
}

/// Runs `splinelab ARGS`, asserts it succeeded, and returns its standard output.
fn stdout_of(args: &[&str]) -> String {
    let out = splinelab().args(args).output().expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
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
    let line = stdout_of(&["bench", "--only", "patch-matrix", "--millis", "1"]);
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
fn bench_sweep_prints_sizes_and_draws_the_scaling_figure() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = splinelab()
        .args([
            "bench",
            "--sweep",
            "--only",
            "patch-matrix",
            "--millis",
            "1",
            "--out",
        ])
        .arg(dir.path())
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let json: Vec<&str> = text.lines().filter(|l| l.starts_with('{')).collect();
    assert_eq!(json.len(), 9, "{text}");
    for (line, size) in json.iter().zip([4, 8, 15, 32, 64, 128, 256, 512, 1024]) {
        assert!(line.contains(&format!("\"size\": {size},")), "{line}");
        assert!(
            line.contains(&format!("\"points\": {},", size * size)),
            "{line}"
        );
    }
    let jsonl =
        std::fs::read_to_string(dir.path().join("tables/bench-sweep.jsonl")).expect("jsonl");
    assert_eq!(jsonl.lines().count(), 9);
    for ext in ["png", "svg"] {
        let f = dir.path().join(format!("figures/fig-bench-scaling.{ext}"));
        assert!(std::fs::metadata(&f).expect("figure").len() > 1000, "{f:?}");
    }
}

/// Issue 26: one workload at a chosen size, the sweep sizes listed, and a peer CSV drawn as
/// the ratio panel (a malformed one refused with its line).
#[test]
fn bench_at_a_size_lists_sizes_and_draws_peers() {
    let text = stdout_of(&[
        "bench",
        "--only",
        "patch-matrix",
        "--size",
        "8",
        "--millis",
        "1",
    ]);
    assert!(
        text.contains("\"size\": 8,") && text.contains("\"points\": 64,"),
        "{text}"
    );
    let text = stdout_of(&["bench", "--sizes"]);
    assert!(
        text.lines()
            .any(|l| l == "patch-matrix 4 8 15 32 64 128 256 512 1024"),
        "{text}"
    );
    let dir = tempfile::tempdir().expect("tempdir");
    let peers = dir.path().join("peers.csv");
    std::fs::write(
        &peers,
        "workload,size,points,splinelab_seconds,peer_seconds,peer\npatch-matrix,4,16,1e-6,3e-6,scipy\npatch-matrix,8,64,2e-6,3e-6,scipy\n",
    )
    .expect("write");
    let sweep = || {
        splinelab()
            .args([
                "bench",
                "--sweep",
                "--only",
                "patch-matrix",
                "--millis",
                "1",
                "--peers",
            ])
            .arg(&peers)
            .arg("--out")
            .arg(dir.path())
            .output()
            .expect("runs")
    };
    let out = sweep();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg =
        std::fs::read_to_string(dir.path().join("figures/fig-bench-scaling.svg")).expect("svg");
    assert!(svg.contains("parity") && svg.contains("patch-matrix (scipy)"));
    std::fs::write(&peers, "workload,size\n").expect("write");
    let out = sweep();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 1"), "{err}");
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

/// Runs `splinelab ARGS` through `sh -c` with `shell` redirections, returning (status,
/// stderr). Used for a closed or full standard output.
fn through_shell(args: &str, shell: &str) -> (std::process::ExitStatus, String) {
    let bin = env!("CARGO_BIN_EXE_splinelab");
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!("'{bin}' {args} {shell}"))
        .output()
        .expect("sh runs");
    (
        out.status,
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_closed_or_full_stdout_is_a_readable_error_not_a_panic() {
    // a pipe whose reading end is closed before the program starts: every write is EPIPE
    // (what `splinelab --list | head -0` gives once head has exited)
    for args in [&["--list"][..], &["bench", "--list"][..]] {
        let (reader, writer) = std::io::pipe().expect("pipe");
        drop(reader);
        let out = splinelab()
            .args(args)
            .stdout(writer)
            .output()
            .expect("runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(
            out.status.code(),
            Some(1),
            "{args:?} into a closed pipe: {stderr}"
        );
        assert!(
            stderr.starts_with("splinelab: error:") && !stderr.contains("panicked"),
            "{args:?}: {stderr}"
        );
    }
    // a full device
    if std::path::Path::new("/dev/full").exists() {
        let (status, stderr) = through_shell("--list", "> /dev/full");
        assert_eq!(status.code(), Some(1), "--list > /dev/full: {stderr}");
        assert!(
            stderr.starts_with("splinelab: error:") && !stderr.contains("panicked"),
            "{stderr}"
        );
    }
}

#[test]
fn outputs_are_written_through_temporary_files_renamed_into_place() {
    let dir = tempfile::tempdir().expect("tempdir");
    regenerate_only("t3-error", dir.path());
    regenerate_only("fig-runge", dir.path());
    for sub in ["tables", "figures"] {
        for entry in std::fs::read_dir(dir.path().join(sub)).expect("folder") {
            let name = entry.expect("entry").file_name();
            let name = name.to_string_lossy();
            assert!(
                !name.starts_with('.') && !name.contains(".tmp"),
                "a temporary file was left behind: {name}"
            );
        }
    }
}

#[cfg(unix)]
#[test]
fn a_run_stopped_by_a_file_size_limit_leaves_no_truncated_output() {
    // `ulimit -f 8` (8 blocks of 512 bytes): the first figure (PNG, tens of kB) cannot be
    // written; the process is stopped by SIGXFSZ (or gets EFBIG) while writing it. Whatever
    // happens, every file under an output's name must be complete: here, each one present
    // must equal the same output from an unrestricted run.
    let full = tempfile::tempdir().expect("tempdir");
    regenerate_only("fig-runge", full.path());
    let limited = tempfile::tempdir().expect("tempdir");
    let bin = env!("CARGO_BIN_EXE_splinelab");
    let status = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -f 8; exec '{bin}' --only fig-runge --out '{}'",
            limited.path().display()
        ))
        .status()
        .expect("sh runs");
    assert!(!status.success(), "the limit must stop the run");
    let figures = limited.path().join("figures");
    for name in ["fig-runge.png", "fig-runge.svg"] {
        let path = figures.join(name);
        if path.exists() {
            let want = std::fs::read(full.path().join("figures").join(name)).expect("reference");
            let got = std::fs::read(&path).expect("output");
            assert_eq!(got, want, "{name} exists but differs from a complete run");
        }
    }
}
