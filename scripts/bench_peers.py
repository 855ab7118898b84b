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

The inputs are built the same way on both sides (see src/report/bench.rs). What each side
does differs as each library is used: splinelab's batch evaluations write into an output
buffer kept from the previous run and, from 65 536 points, use both cores (the two-thread
paths of issue 13); scipy allocates a new output array each call and runs on one core.
`cubic-spline-build` allocates a new spline on both sides. Installs numpy
and scipy into the notebooks' virtual environment ($SPLINELAB_STATE/venv, default
~/.cache/splinelab/venv) if they are missing; builds splinelab with `cargo build --release`.

usage: python3 scripts/bench_peers.py [--millis N] [--rounds R] [--only WORKLOAD ...]
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
]


def venv_python():
    state = pathlib.Path(os.environ.get("SPLINELAB_STATE", pathlib.Path.home() / ".cache/splinelab"))
    python = state / "venv" / "bin" / "python"
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(state / "venv")], check=True)
    probe = subprocess.run([str(python), "-c", "import numpy, scipy"], capture_output=True)
    if probe.returncode != 0:
        subprocess.run(
            [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
             f"numpy=={NUMPY_VERSION}", f"scipy=={SCIPY_VERSION}"],
            check=True,
        )
    return python


SCIPY_SIDE = r"""
import json, statistics, sys, time
import numpy as np, scipy
from scipy.interpolate import BSpline, CubicSpline
workload, millis = sys.argv[1], float(sys.argv[2])

def helix_curve(p):
    n = 60
    a = 0.4 * np.arange(n)
    c = np.stack([np.cos(a), np.sin(a), 0.05 * np.arange(n)], axis=1)
    interior = np.arange(1, n - p) / (n - p)
    t = np.concatenate([np.zeros(p + 1), interior, np.ones(p + 1)])
    return BSpline(t, c, p), np.linspace(0.0, 1.0, 1_000_000)

x = np.linspace(0.0, 1000.0, 1_000_000)
y = np.sin(x)
if workload in ("cubic-spline-build", "cubic-spline-refit"):
    run = lambda: CubicSpline(x, y, bc_type="natural")
    points = x.size
elif workload == "cubic-spline-eval":
    cs = CubicSpline(x, y, bc_type="natural")
    xs = np.linspace(0.0, 1000.0, 10_000_000)
    run = lambda: cs(xs)
    points = xs.size
else:
    p = {"bspline-curve": 3, "bspline-curve-deg5": 5, "bspline-curve-deg7": 7}[workload]
    curve, ts = helix_curve(p)
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


def main():
    args = sys.argv[1:]
    millis = args[args.index("--millis") + 1] if "--millis" in args else "1000"
    rounds = int(args[args.index("--rounds") + 1]) if "--rounds" in args else 3
    only = [args[i + 1] for i, a in enumerate(args) if a == "--only"] or PAIRS
    python = venv_python()
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    binary = ROOT / "target" / "release" / "splinelab"
    for workload in only:
        ours, theirs = [], []
        for _ in range(rounds):
            line = subprocess.run(
                [str(binary), "bench", "--only", workload, "--millis", millis],
                cwd=ROOT, check=True, capture_output=True, text=True,
            ).stdout.strip().splitlines()[-1]
            ours.append(json.loads(line))
            line = subprocess.run(
                [str(python), "-c", SCIPY_SIDE, workload, millis],
                check=True, capture_output=True, text=True,
            ).stdout.strip()
            theirs.append(json.loads(line))
        a = statistics.median(r["seconds"] for r in ours)
        b = statistics.median(r["seconds"] for r in theirs)
        print(json.dumps({
            "workload": workload,
            "points": ours[0]["points"],
            "splinelab_seconds": a,
            "scipy_seconds": b,
            "ratio_scipy_over_splinelab": b / a,
            "rounds_splinelab": [r["seconds"] for r in ours],
            "rounds_scipy": [r["seconds"] for r in theirs],
            "scipy": theirs[0]["scipy"],
            "numpy": theirs[0]["numpy"],
        }), flush=True)


if __name__ == "__main__":
    main()
