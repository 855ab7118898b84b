#!/usr/bin/env python3
"""Every printed formula of the corpus checked by sympy, an independent computer algebra system.

The corpus is `splinelab formulas` (src/symbolic/corpus.rs): surfaces of every supported
function, B-spline/NURBS/Bézier curves and the interpolating splines (in the global and the
piece's local variable), the bases and a patch, each with its formulas as printed, which is the
derivative of which, a box where they hold and reference values from the numeric path. For each
formula:

- value: the printed formula, parsed by sympy, at the reference points equals the numeric
  (hyper-dual) value to 1e-12 of the evaluation's scale (the larger of 1, the value and the sum
  of the magnitudes of its top-level terms: a power form evaluates to that accuracy);
- derivative: a printed derivative equals sympy's `diff` of the printed primary formula:
  proved (`simplify` of the difference is 0 within a few seconds) or at 50 random points of the
  box to 1e-12 of the scale; otherwise a disagreement;
- length: its length (characters, spaces dropped, `**` as `^`) against sympy's simplified form
  of the same function (`simplify` of sympy's derivative, or of the primary formula).

Prints a table per kind and a summary; exits 1 on any disagreement. Installs sympy into the
notebooks' virtual environment ($SPLINELAB_STATE/venv, default ~/.cache/splinelab/venv) the way
scripts/bench_symbolic.py does.

usage: python3 scripts/check_formulas.py [--corpus FILE] [--seconds N]
"""
import json
import pathlib
import subprocess
import sys

from sympy_venv import venv_python

ROOT = pathlib.Path(__file__).resolve().parent.parent


CHECKER = r'''
import json, random, signal, sys
import sympy as sp

corpus_path, seconds = sys.argv[1], float(sys.argv[2])
RTOL = 1e-12

class Slow(Exception):
    pass

def alarm(signum, frame):
    raise Slow()

signal.signal(signal.SIGALRM, alarm)

def within(seconds_, f):
    """f() or None if it takes longer than `seconds_`."""
    signal.setitimer(signal.ITIMER_REAL, seconds_)
    try:
        return f()
    except Slow:
        return None
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)

def names(vars_):
    syms = {v: sp.Symbol(v, real=True) for v in vars_}
    local = dict(syms)
    local.update({
        "ln": sp.log, "abs": sp.Abs, "cbrt": lambda x: sp.real_root(x, 3), "atan2": sp.atan2,
        "j0": lambda x: sp.jn(0, x), "j1": lambda x: sp.jn(1, x), "j2": lambda x: sp.jn(2, x),
        "asinh": sp.asinh, "acosh": sp.acosh, "atanh": sp.atanh,
    })
    return syms, local

def parse(text, local):
    from sympy.parsing.sympy_parser import parse_expr, standard_transformations
    return parse_expr(text.replace("^", "**"), local_dict=local,
                      transformations=standard_transformations, evaluate=True)

def scale(expr, subs):
    """max(1, |value|, Σ |top-level terms|) at `subs`, evaluated at 30 digits."""
    terms = expr.args if isinstance(expr, sp.Add) else (expr,)
    total = sum(abs(complex(t.evalf(30, subs=subs))) for t in terms)
    return max(1.0, abs(complex(expr.evalf(30, subs=subs))), total)

def length(text):
    return len(text.replace(" ", "").replace("**", "^"))

entries = [json.loads(l) for l in open(corpus_path) if l.strip()]
rows, bad = [], []
random.seed(20261204)
for e in entries:
    syms, local = names(e["vars"])
    parsed = {f["label"]: parse(f["plain"], local) for f in e["formulas"]}
    vs = [syms[v] for v in e["vars"]]
    # values at the numeric path's points
    for k, f in enumerate(e["formulas"]):
        expr = parsed[f["label"]]
        worst = 0.0
        for sample in e["samples"]:
            subs = dict(zip(vs, sample["at"]))
            want = sample["values"][k]
            got = complex(expr.evalf(30, subs=subs))
            err = abs(got - want) / max(scale(expr, subs), abs(want))
            worst = max(worst, err)
        row = {"entry": e["name"], "kind": e["kind"], "label": f["label"], "value_err": worst,
               "derivative": "—", "ours": length(f["plain"]), "sympy": None}
        if worst > RTOL:
            bad.append(f"{e['name']} {f['label']}: value off by {worst:.2e} of its scale")
        # derivative against sympy's diff of the printed primary formula
        reference = expr
        if f["derivative_of"] is not None:
            base = parsed[f["derivative_of"]["base"]]
            wrt = [syms[w] for w in f["derivative_of"]["wrt"]]
            reference = sp.diff(base, *wrt)
            diff = sp.expand(reference - expr)
            proved = within(seconds, lambda: sp.simplify(diff) == 0)
            if proved:
                row["derivative"] = "proved"
            else:
                ok = True
                for _ in range(50):
                    subs = {v: random.uniform(a, b) for v, (a, b) in zip(vs, e["region"])}
                    d = complex(reference.evalf(30, subs=subs))
                    p = complex(expr.evalf(30, subs=subs))
                    if abs(d - p) > RTOL * max(scale(expr, subs), abs(d)):
                        ok = False
                        bad.append(f"{e['name']} {f['label']}: {f['plain']} vs sympy {reference}")
                        break
                row["derivative"] = "numeric" if ok else "DISAGREES"
        simple = within(seconds, lambda: sp.simplify(reference))
        if simple is not None:
            row["sympy"] = length(sp.sstr(simple))
        rows.append(row)
print(json.dumps({"rows": rows, "bad": bad}))
'''


def main():
    corpus = None
    seconds = "4"
    args = sys.argv[1:]
    if "--corpus" in args:
        corpus = args[args.index("--corpus") + 1]
    if "--seconds" in args:
        seconds = args[args.index("--seconds") + 1]
    if corpus is None:
        # the test profile's build (optimised, Cargo.toml), which `cargo test` has made already
        subprocess.run(["cargo", "build", "--locked", "--quiet", "--bin", "splinelab"], cwd=ROOT,
                       check=True)
        out = subprocess.run([str(ROOT / "target/debug/splinelab"), "formulas"], cwd=ROOT,
                             check=True, capture_output=True, text=True).stdout
        corpus = ROOT / "out" / "tables" / "formula-corpus.jsonl"
        corpus.parent.mkdir(parents=True, exist_ok=True)
        corpus.write_text(out)
    python = venv_python()
    result = subprocess.run([str(python), "-c", CHECKER, str(corpus), seconds], check=True,
                            capture_output=True, text=True)
    report = json.loads(result.stdout)
    rows, bad = report["rows"], report["bad"]
    kinds = sorted({r["kind"] for r in rows})
    lines = []
    emit = lambda line="": (print(line), lines.append(line))
    emit("| kind | entries | formulas | values ok | derivatives proved | numeric | disagree | "
          "max length ÷ sympy | within 1.2× | within 2× |")
    emit("|---|---|---|---|---|---|---|---|---|---|")
    summary = []
    for kind in kinds + ["all"]:
        of = [r for r in rows if kind == "all" or r["kind"] == kind]
        ratios = [r["ours"] / r["sympy"] for r in of if r["sympy"]]
        values_ok = sum(r["value_err"] <= 1e-12 for r in of)
        line = (kind, len({r["entry"] for r in of}), len(of), values_ok,
                sum(r["derivative"] == "proved" for r in of),
                sum(r["derivative"] == "numeric" for r in of),
                sum(r["derivative"] == "DISAGREES" for r in of),
                max(ratios) if ratios else float("nan"),
                sum(x <= 1.2 for x in ratios) / max(1, len(ratios)),
                sum(x <= 2.0 for x in ratios) / max(1, len(ratios)))
        summary.append(line)
        emit("| {} | {} | {} | {} | {} | {} | {} | {:.2f} | {:.0%} | {:.0%} |".format(*line))
    longest = sorted((r for r in rows if r["sympy"]), key=lambda r: -r["ours"] / r["sympy"])[:5]
    emit()
    emit("longest against sympy: " + "; ".join(
        f"{r['entry']} {r['label']} {r['ours']}/{r['sympy']}" for r in longest))
    for b in bad:
        emit("DISAGREES: " + b)
    total = summary[-1]
    table = ROOT / "out" / "tables" / "formula-check.md"
    table.parent.mkdir(parents=True, exist_ok=True)
    table.write_text("# Printed formulas against sympy (scripts/check_formulas.py)\n\n"
                     + "\n".join(lines) + "\n")
    print(f"check_formulas: {total[2]} formulas of {total[1]} objects, {len(bad)} disagreements, "
          f"{total[8]:.0%} within 1.2x of sympy's length, longest {total[7]:.2f}x")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
