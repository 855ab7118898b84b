#!/usr/bin/env python3
"""The `symbolic-torus` workload beside sympy, in one run on one machine.

splinelab: `splinelab bench --only symbolic-torus` (release build): Torus::eval traced on
hyper-dual numbers of expressions, the 12 formulas X, X_s, X_t, X_st simplified and printed.
sympy: the same three functions of Codice 3 (f_x = (2 + cos t) cos s, f_y = (2 + cos t) sin s,
f_z = sin t), `diff` by s, t and s-and-t, each of the 12 printed with `str` (sympy's
`diff` already returns them simplified as it prints them). Timed with sympy's cache cleared
before each run (as a fresh session, the headline figure) and with it kept (repeated calls
then return memoised results).

Installs sympy into the notebooks' virtual environment ($SPLINELAB_STATE/venv, default
~/.cache/splinelab/venv) if it is missing, and prints one JSON line per side plus the ratio.

usage: python3 scripts/bench_symbolic.py [--millis N]
"""
import json
import pathlib
import statistics
import subprocess
import sys
import time

from sympy_venv import venv_python

ROOT = pathlib.Path(__file__).resolve().parent.parent


SYMPY_SIDE = r"""
import json, statistics, sys, time
import sympy as sp
millis = float(sys.argv[1])
def run():
    s, t = sp.symbols("s t")
    fs = [(2 + sp.cos(t)) * sp.cos(s), (2 + sp.cos(t)) * sp.sin(s), sp.sin(t)]
    out = []
    for f in fs:
        out += [str(f), str(sp.diff(f, s)), str(sp.diff(f, t)), str(sp.diff(f, s, t))]
    return out
formulas = run()
times, start = [], time.perf_counter()
while len(times) < 5 or time.perf_counter() - start < millis / 1000:
    sp.core.cache.clear_cache()  # each run from scratch, as a fresh session would
    t0 = time.perf_counter()
    run()
    times.append(time.perf_counter() - t0)
warm, start = [], time.perf_counter()
while len(warm) < 5 or time.perf_counter() - start < millis / 1000:
    t0 = time.perf_counter()  # sympy's cache kept: repeated calls return memoised results
    run()
    warm.append(time.perf_counter() - t0)
print(json.dumps({"workload": "sympy-torus", "points": len(formulas),
                  "seconds": statistics.median(times),
                  "seconds_cache_kept": statistics.median(warm), "sympy": sp.__version__,
                  "formulas": formulas}))
"""


def main():
    millis = "2000"
    if "--millis" in sys.argv:
        millis = sys.argv[sys.argv.index("--millis") + 1]
    python = venv_python()
    ours = subprocess.run(
        ["cargo", "run", "--release", "--quiet", "--", "bench", "--only", "symbolic-torus",
         "--millis", millis],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout.strip().splitlines()[-1]
    theirs = subprocess.run(
        [str(python), "-c", SYMPY_SIDE, millis], check=True, capture_output=True, text=True
    ).stdout.strip()
    a, b = json.loads(ours), json.loads(theirs)
    print(json.dumps(a))
    print(json.dumps({k: v for k, v in b.items() if k != "formulas"}))
    print("sympy's formulas:", "; ".join(b["formulas"]))
    print(json.dumps({"ratio_sympy_over_splinelab": b["seconds"] / a["seconds"],
                      "ratio_with_sympy_cache_kept": b["seconds_cache_kept"] / a["seconds"]}))


if __name__ == "__main__":
    main()
