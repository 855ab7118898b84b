//! The `splinelab` binary: default outputs, --list, --only, bench, and readable failures.

use std::path::{Path, PathBuf};
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

const POINTS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/examples/points.csv");
const LEAF: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/examples/leaf.svg");

/// The files of `dir`, sorted (none if it does not exist).
fn files_in(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

#[test]
fn each_user_command_has_help_with_an_example() {
    for command in ["fit", "fewest", "surface"] {
        let help = stdout_of(&[command, "--help"]);
        assert!(help.contains("Example"), "{command}: {help}");
        assert!(help.contains(&format!("splinelab {command} ")), "{command}");
    }
}

#[test]
fn fit_writes_samples_figures_and_the_svg_path_and_prints_formulas() {
    let dir = tempfile::tempdir().unwrap();
    // a ring stored with its first point repeated (the shipped coastline): that ring, said so
    let ring = dir.path().join("ring");
    let printed = stdout_of(&[
        "fit",
        "--method",
        "linear",
        "--closed",
        "--out",
        ring.to_str().unwrap(),
        concat!(env!("CARGO_MANIFEST_DIR"), "/data/sicily-coastline.csv"),
    ]);
    assert!(
        printed.contains(
            "the last point repeats the first: the closed curve is the ring of the first"
        ),
        "{printed}"
    );
    let out = dir.path().join("fit");
    let printed = stdout_of(&[
        "fit",
        "--method",
        "cardinal",
        "--a",
        "0.4",
        "--closed",
        "--formulas",
        "latex",
        "--out",
        out.to_str().unwrap(),
        POINTS,
    ]);
    assert_eq!(
        files_in(&out),
        [
            "points-path.svg",
            "points-samples.csv",
            "points.png",
            "points.svg"
        ]
    );
    assert!(printed.contains("\\begin{align*}"), "{printed}");
    let csv = std::fs::read_to_string(out.join("points-samples.csv")).unwrap();
    assert!(csv.starts_with("t,x,y\n"));
    let svg = std::fs::read_to_string(out.join("points-path.svg")).unwrap();
    // a closed curve of cubic pieces: one M, a C a piece, closed by Z
    assert!(
        svg.contains("<path d=\"M 1.9 1.6 C ") && svg.contains(" Z\""),
        "{svg}"
    );
    assert_eq!(svg.matches(" C ").count(), 7, "{svg}");
}

#[test]
fn bad_input_files_fail_with_their_line_and_column_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let cases: [(&str, &[u8], &[&str], &str); 8] = [
        (
            "g.svg",
            b"<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 10 10'>\n  <rect width='4' height='4'/>\n  <text x='1' y='8'>A</text>\n</svg>",
            &["fewest"],
            "line 3, column 3: a <text> element: text is not read as an outline",
        ),
        (
            "h.csv",
            b"x;y\n0;0\n1,5;2\n",
            &["fit", "--method", "linear"],
            "line 3, column 1: not a number: \"1,5\" (a decimal comma",
        ),
        (
            "a.csv",
            b"x,y\n0,0\n1,oops\n",
            &["fit", "--method", "cubic"],
            "line 3, column 3",
        ),
        (
            "b.csv",
            b"0,0\n1,nan\n2,2\n",
            &["fit", "--method", "linear"],
            "line 2, column 3",
        ),
        ("c.csv", b"", &["fit", "--method", "linear"], "points"),
        (
            "d.svg",
            b"<svg xmlns='http://www.w3.org/2000/svg'>\n<path d='M 0 0 A 1 1 0 2 1 2 2'/></svg>",
            &["fewest"],
            "line 2, column 24: cannot read \"2\" here (a number, or an arc flag 0 or 1, is expected)",
        ),
        (
            "e.path",
            b"M 0 0 L 1 1 K 2 2",
            &["fewest"],
            "line 1, column 13",
        ),
        ("f.ttf", b"not a font", &["fewest", "--glyph", "a"], "'a'"),
    ];
    for (name, bytes, args, expected) in cases {
        let file = dir.path().join(name);
        std::fs::write(&file, bytes).unwrap();
        let result = splinelab()
            .args(args)
            .arg("--out")
            .arg(&out)
            .arg(&file)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&result.stderr);
        assert!(!result.status.success(), "{name}");
        assert!(err.contains(expected), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
        assert!(
            files_in(&out).is_empty(),
            "{name} wrote {:?}",
            files_in(&out)
        );
    }
}

#[test]
fn fewest_on_a_paper_shape_prints_table_i_counts_and_writes_a_table_and_figures() {
    let dir = tempfile::tempdir().unwrap();
    let printed = stdout_of(&[
        "fewest",
        "--shape",
        "parabola-1",
        "--method",
        "cubic,bspline",
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    // Table I's automatic counts for Parabola 2 (our parabola-1): cubic 4, B-spline 3
    assert!(printed.contains("| cubic | 4 |"), "{printed}");
    assert!(printed.contains("| bspline | 3 |"), "{printed}");
    assert_eq!(
        files_in(dir.path()),
        [
            "parabola-1-bspline-curve.svg",
            "parabola-1-bspline-parameters.csv",
            "parabola-1-bspline-points.csv",
            "parabola-1-bspline.png",
            "parabola-1-bspline.svg",
            "parabola-1-cubic-curve.svg",
            "parabola-1-cubic-parameters.csv",
            "parabola-1-cubic-points.csv",
            "parabola-1-cubic.png",
            "parabola-1-cubic.svg",
            "parabola-1-fewest.csv",
            "parabola-1-fewest.md",
            "parabola-1-outline.csv"
        ]
    );
}

/// The path data `d="…"` of the first path of an SVG document.
fn path_data(svg: &str) -> &str {
    let start = svg.find(" d=\"").expect("a path") + 4;
    let len = svg[start..].find('"').expect("its end");
    &svg[start..start + len]
}

/// Issue 46: every answer of `fewest` is written (points, parameters, curve) and `fit` on
/// those points with those parameters draws the same curve: for each method and contour,
/// the `redraw` command of the parameters file, run as written, writes a path that is the
/// contour's subpath of the answer's curve, number for number.
#[test]
fn fewest_writes_each_answer_and_fit_redraws_it() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("two.svg");
    std::fs::write(
        &svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 20"><circle cx="10" cy="10" r="8"/><path d="M24 4h12v12h-12z"/></svg>"#,
    )
    .unwrap();
    stdout_of(&[
        "fewest",
        "--method",
        "angular,cardinal,cubic,bspline,linear",
        "--out",
        dir.path().to_str().unwrap(),
        svg.to_str().unwrap(),
    ]);
    for method in ["angular", "cardinal", "cubic", "bspline", "linear"] {
        let read = |suffix: &str| {
            std::fs::read_to_string(dir.path().join(format!("two-{method}-{suffix}")))
                .unwrap_or_else(|e| panic!("two-{method}-{suffix}: {e}"))
        };
        let curve = read("curve.svg");
        let whole = path_data(&curve);
        let parameters = read("parameters.csv");
        let mut rows = csv::Reader::from_reader(parameters.as_bytes());
        let header = rows.headers().unwrap().clone();
        let redraw = header.iter().position(|h| h == "redraw").unwrap();
        let mut contours = 0;
        for row in rows.records() {
            let row = row.unwrap();
            let words: Vec<&str> = row[redraw].split(' ').collect();
            assert_eq!(words[..2], ["splinelab", "fit"], "{}", &row[redraw]);
            let out = dir.path().join(format!("redraw-{method}-{contours}"));
            let done = splinelab()
                .current_dir(dir.path())
                .args(&words[1..])
                .arg("--out")
                .arg(&out)
                .output()
                .unwrap();
            assert!(
                done.status.success(),
                "{method}: {}: {}",
                &row[redraw],
                String::from_utf8_lossy(&done.stderr)
            );
            let stem = format!("two-{method}-points");
            let again = std::fs::read_to_string(out.join(format!("{stem}-path.svg"))).unwrap();
            let part = path_data(&again);
            assert!(
                whole.contains(part),
                "{method}, contour {}: {part} is not in {whole}",
                contours + 1
            );
            contours += 1;
        }
        assert_eq!(contours, 2, "{method}: {parameters}");
        // the points file: one row a point, the contour first
        assert!(read("points.csv").starts_with("contour,x,y\n"));
    }
}

#[test]
fn fewest_on_an_svg_outline_reports_progress_on_stderr() {
    let dir = tempfile::tempdir().unwrap();
    let out = splinelab()
        .args(["fewest", "--method", "linear,cubic", "--out"])
        .arg(dir.path())
        .arg(LEAF)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let err = String::from_utf8_lossy(&out.stderr);
    // not a terminal: one line a finished search
    assert_eq!(err.matches("searches").count(), 2, "{err}");
    assert!(err.contains("2/2 searches"), "{err}");
    assert!(String::from_utf8_lossy(&out.stdout).contains("| linear |"));
}

#[test]
fn surface_exports_a_mesh_of_the_users_partition() {
    let dir = tempfile::tempdir().unwrap();
    for (name, extra) in [
        ("t.obj", &[][..]),
        ("t.ply", &["--ascii"][..]),
        ("t.stl", &[][..]),
    ] {
        let path = dir.path().join(name);
        let printed = stdout_of(
            &[
                &[
                    "surface",
                    "--torus",
                    "3,1",
                    "--partition",
                    "6x4",
                    "--samples",
                    "2",
                ][..],
                extra,
                &["--export", path.to_str().unwrap()],
            ]
            .concat(),
        );
        assert!(
            printed.contains("6 x 4 bicubic Hermite patches"),
            "{printed}"
        );
        assert!(
            printed.contains("13 x 9") || printed.contains("117 vertices"),
            "{printed}"
        );
        assert!(std::fs::metadata(&path).unwrap().len() > 0);
    }
    let obj = std::fs::read_to_string(dir.path().join("t.obj")).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), 13 * 9);
    let sphere = dir.path().join("s.stl");
    stdout_of(&[
        "surface",
        "--sphere",
        "--s-nodes",
        "0,3,6.283185307179586",
        "--t-nodes",
        "-1.5707963267948966,0,1.5707963267948966",
        "--export",
        sphere.to_str().unwrap(),
    ]);
    // no partition: the stated default, 8 x 8
    let default = dir.path().join("default.obj");
    let said = stdout_of(&["surface", "--torus", "--export", default.to_str().unwrap()]);
    assert!(said.contains("8 x 8 bicubic Hermite patches"), "{said}");
    // refusals, nothing written
    for args in [
        &["surface", "--torus", "--partition", "0x4"][..],
        &["surface", "--torus", "2", "--partition", "4x4"][..],
        &["surface", "--exp", "--partition", "4x4", "--samples", "0"][..],
        &[
            "surface",
            "--sphere",
            "--s-nodes",
            "0,0",
            "--t-nodes",
            "0,1",
        ][..],
    ] {
        let bad = dir.path().join("bad.obj");
        let out = splinelab()
            .args(args)
            .arg("--export")
            .arg(&bad)
            .output()
            .unwrap();
        assert!(!out.status.success(), "{args:?}");
        assert!(!bad.exists(), "{args:?}");
    }
    let out = splinelab()
        .args(["surface", "--exp", "--partition", "2x2", "--export"])
        .arg(dir.path().join("x.gltf"))
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains(".obj, .ply or .stl"));
}

/// Ctrl-C during a run leaves no temporary file: the default run, interrupted at a range of
/// moments while it renders figures into temporary files, leaves only whole outputs.
#[test]
fn an_interrupted_run_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let mut interrupted_with_outputs = 0;
    for k in 0..8u64 {
        let out = dir.path().join(format!("run{k}"));
        let mut child = splinelab()
            .args(["--out", out.to_str().unwrap()])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(300 + 250 * k));
        // SAFETY: sending a signal to our own child
        unsafe {
            libc::kill(child.id() as libc::pid_t, libc::SIGINT);
        }
        let status = child.wait().unwrap();
        let mut left = Vec::new();
        let mut outputs = 0;
        for entry in walk(&out) {
            let name = entry.file_name().unwrap().to_string_lossy().to_string();
            if name.contains(".tmp.") {
                left.push(entry.clone());
            } else {
                outputs += 1;
            }
        }
        assert!(left.is_empty(), "after {k}: {left:?} left ({status:?})");
        if !status.success() && outputs > 0 {
            interrupted_with_outputs += 1;
        }
    }
    assert!(
        interrupted_with_outputs > 0,
        "no run was interrupted while writing"
    );
}

/// Every file under `dir`.
fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Ok(entries) = std::fs::read_dir(dir) {
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                out.extend(walk(&p));
            } else {
                out.push(p);
            }
        }
    }
    out
}
