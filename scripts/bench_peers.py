#!/usr/bin/env python3
"""splinelab's workloads beside scipy's, in one run on one machine.

Each pair is timed in alternating rounds (splinelab, scipy, splinelab, scipy, …) so that both
sides meet the same state of the machine, and the median over the rounds of each side's
median is reported, with the ratio scipy / splinelab (above 1: splinelab is faster).

| splinelab workload   | scipy                                                          |
|----------------------|----------------------------------------------------------------|
| cubic-spline-build   | CubicSpline(x, y, bc_type="natural"), 1e6 points, y = sin x    |
| cubic-spline-refit   | the same (scipy has no in-place rebuild)                       |
| cubic-spline-eval    | that spline at 1e7 sorted points                               |
| bspline-curve        | BSpline(t, c, 3)(ts): 60 control points in 3-D, 1e6 parameters |
| bspline-curve-deg5   | the same at degree 5                                           |
| bspline-curve-deg7   | the same at degree 7                                           |
| bspline-curve-spans  | BSpline(t, c, 3)(ts): 10⁶ spans (10⁶ + 3 points in 3-D)        |
| corner-data          | sympy.lambdify of X, X_s, X_t, X_st of the torus (numpy), k × k nodes |

With `--sweep`, every pair is timed at every size of its workload's sweep (`splinelab bench
--sizes`: the evaluation points, the data points of a build), both sides alternating at each
size; the results go to out/tables/bench-peers-sweep.csv (`splinelab::report::bench::
PEER_HEADER`) and `splinelab bench --sweep --peers` then draws fig-bench-scaling with a panel
of scipy's time over ours against size.

The inputs are built the same way on both sides (see src/report/bench.rs). What each side
does differs as each library is used: splinelab's batch evaluations write into an output
buffer kept from the previous run and, from 65 536 points, use both cores (the two-thread
paths of issue 13); scipy allocates a new output array each call and runs on one core.
`cubic-spline-build` allocates a new spline on both sides. Installs numpy
and scipy into the notebooks' virtual environment ($SPLINELAB_STATE/venv, default
~/.cache/splinelab/venv) if they are missing; builds splinelab with `cargo build --release`.

usage: python3 scripts/bench_peers.py [--millis N] [--rounds R] [--only WORKLOAD ...] [--sweep]
"""
import json
import os
import pathlib
import statistics
import subprocess
import sys

NUMPY_VERSION = "2.4.6"
SCIPY_VERSION = "1.17.1"
ROOT = pathlib.Path(__file__).resolve().parent.parent
PAIRS = [
    "cubic-spline-build",
    "cubic-spline-refit",
    "cubic-spline-eval",
    "bspline-curve",
    "bspline-curve-deg5",
    "bspline-curve-deg7",
    "bspline-curve-spans",
    "corner-data",
]
# the peer of each workload (the CSV's `peer` column)
PEER = {"corner-data": "sympy-lambdify"}
SYMPY_VERSION = "1.14.0"
# the default size of each workload (src/report/bench.rs), for the runs without --sweep
DEFAULT_SIZE = {
    "cubic-spline-build": 1_000_000,
    "cubic-spline-refit": 1_000_000,
    "cubic-spline-eval": 10_000_000,
    "bspline-curve": 1_000_000,
    "bspline-curve-deg5": 1_000_000,
    "bspline-curve-deg7": 1_000_000,
    "bspline-curve-spans": 1_000_000,
    "corner-data": 257,
}


def venv_python():
    state = pathlib.Path(os.environ.get("SPLINELAB_STATE", pathlib.Path.home() / ".cache/splinelab"))
    python = state / "venv" / "bin" / "python"
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(state / "venv")], check=True)
    probe = subprocess.run([str(python), "-c", "import numpy, scipy, sympy"], capture_output=True)
    if probe.returncode != 0:
        subprocess.run(
            [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
             f"numpy=={NUMPY_VERSION}", f"scipy=={SCIPY_VERSION}", f"sympy=={SYMPY_VERSION}"],
            check=True,
        )
    return python


SCIPY_SIDE = r"""
import json, statistics, sys, time
import numpy as np, scipy
from scipy.interpolate import BSpline, CubicSpline
workload, millis, size = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])

def helix_curve(p, n):
    a = 0.4 * np.arange(n)
    c = np.stack([np.cos(a), np.sin(a), 0.05 * np.arange(n)], axis=1)
    interior = np.arange(1, n - p) / (n - p)
    t = np.concatenate([np.zeros(p + 1), interior, np.ones(p + 1)])
    return BSpline(t, c, p)

if workload in ("cubic-spline-build", "cubic-spline-refit"):
    x = np.linspace(0.0, 1000.0, size)
    y = np.sin(x)
    run = lambda: CubicSpline(x, y, bc_type="natural")
    points = x.size
elif workload == "cubic-spline-eval":
    x = np.linspace(0.0, 1000.0, 1_000_000)
    cs = CubicSpline(x, np.sin(x), bc_type="natural")
    xs = np.linspace(0.0, 1000.0, size)
    run = lambda: cs(xs)
    points = xs.size
elif workload == "corner-data":
    # the torus (R = 2, r = 1) and its partials by sympy, lambdified for numpy once (outside
    # the timing, as our trace is); each run evaluates the 12 functions on the k × k grid
    import sympy as sp
    s_, t_ = sp.symbols("s t")
    X = [(2 + sp.cos(t_)) * sp.cos(s_), (2 + sp.cos(t_)) * sp.sin(s_), sp.sin(t_)]
    exprs = X + [sp.diff(f, s_) for f in X] + [sp.diff(f, t_) for f in X] + [sp.diff(f, s_, t_) for f in X]
    f = sp.lambdify((s_, t_), exprs, "numpy")
    nodes = np.linspace(0.0, 2 * np.pi, size)
    S, T = np.meshgrid(nodes, nodes, indexing="ij")
    run = lambda: [np.broadcast_to(v, S.shape) for v in f(S, T)]
    points = S.size
elif workload == "bspline-curve-spans":
    curve = helix_curve(3, 1_000_003)
    ts = np.linspace(0.0, 1.0, size)
    run = lambda: curve(ts)
    points = ts.size
else:
    p = {"bspline-curve": 3, "bspline-curve-deg5": 5, "bspline-curve-deg7": 7}[workload]
    curve = helix_curve(p, 60)
    ts = np.linspace(0.0, 1.0, size)
    run = lambda: curve(ts)
    points = ts.size
run()
times, start = [], time.perf_counter()
while len(times) < 5 or time.perf_counter() - start < millis / 1000:
    t0 = time.perf_counter()
    run()
    times.append(time.perf_counter() - t0)
print(json.dumps({"workload": "scipy:" + workload, "points": points,
                  "seconds": statistics.median(times), "scipy": scipy.__version__,
                  "numpy": np.__version__}))
"""


def pair(binary, python, workload, size, millis, rounds):
    """Both sides at one size in alternating rounds: the medians and the rounds."""
    ours, theirs = [], []
    for _ in range(rounds):
        line = subprocess.run(
            [str(binary), "bench", "--only", workload, "--size", str(size), "--millis", millis],
            cwd=ROOT, check=True, capture_output=True, text=True,
        ).stdout.strip().splitlines()[-1]
        ours.append(json.loads(line))
        line = subprocess.run(
            [str(python), "-c", SCIPY_SIDE, workload, millis, str(size)],
            check=True, capture_output=True, text=True,
        ).stdout.strip()
        theirs.append(json.loads(line))
    a = statistics.median(r["seconds"] for r in ours)
    b = statistics.median(r["seconds"] for r in theirs)
    return {
        "workload": workload,
        "size": size,
        "points": ours[0]["points"],
        "splinelab_seconds": a,
        "peer": PEER.get(workload, "scipy"),
        "peer_seconds": b,
        "ratio_peer_over_splinelab": b / a,
        "rounds_splinelab": [r["seconds"] for r in ours],
        "rounds_peer": [r["seconds"] for r in theirs],
        "scipy": theirs[0]["scipy"],
        "numpy": theirs[0]["numpy"],
    }


def main():
    args = sys.argv[1:]
    millis = args[args.index("--millis") + 1] if "--millis" in args else "1000"
    rounds = int(args[args.index("--rounds") + 1]) if "--rounds" in args else 3
    only = [args[i + 1] for i, a in enumerate(args) if a == "--only"] or PAIRS
    sweep = "--sweep" in args
    python = venv_python()
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    binary = ROOT / "target" / "release" / "splinelab"
    if not sweep:
        for workload in only:
            print(json.dumps(pair(binary, python, workload, DEFAULT_SIZE[workload], millis, rounds)),
                  flush=True)
        return
    listed = subprocess.run([str(binary), "bench", "--sizes"], cwd=ROOT, check=True,
                            capture_output=True, text=True).stdout.splitlines()
    sizes = {line.split()[0]: [int(v) for v in line.split()[1:]] for line in listed if line.strip()}
    rows = []
    for workload in only:
        for size in sizes[workload]:
            r = pair(binary, python, workload, size, millis, rounds)
            print(json.dumps(r), flush=True)
            rows.append(r)
    tables = ROOT / "out" / "tables"
    tables.mkdir(parents=True, exist_ok=True)
    csv = tables / "bench-peers-sweep.csv"
    tmp = csv.with_suffix(".csv.tmp")
    tmp.write_text("workload,size,points,splinelab_seconds,peer_seconds,peer\n" + "".join(
        f"{r['workload']},{r['size']},{r['points']},{r['splinelab_seconds']!r},{r['peer_seconds']!r},{r['peer']}\n"
        for r in rows))
    tmp.replace(csv)
    print(f"wrote {csv}", flush=True)
    # the throughput sweep of every workload, with the ratio panel from these rows
    subprocess.run([str(binary), "bench", "--sweep", "--millis", str(max(200, int(millis) // 2)),
                    "--peers", str(csv), "--out", str(ROOT / "out")], cwd=ROOT, check=True)


if __name__ == "__main__":
    main()
