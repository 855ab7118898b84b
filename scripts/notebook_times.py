"""Prints, for executed notebooks, where the time goes, from the cell timestamps nbclient
records: the setup cell, the time to first output (from the start of the first code cell to
the end of the first cell that displays something), the median and the slowest of the later
cells, and the total; with --cells, every code cell's time too.

usage: python3 scripts/notebook_times.py [--cells] [--markdown] out/notebooks/*.ipynb
       scripts/notebooks.sh --try-it notebooks/02-torus-and-partials.ipynb
           (runs this script's --try-it in the kernel's environment: the notebook's code cells
           in a live kernel, then its Try-it edit — the marked cell changed, as a user's edit
           changes it, and run with the next cell that draws a figure — three times, each
           time printed: edit cell, figure cell, edit → new figure)
"""
import json
import os
import statistics
import sys
from datetime import datetime


def stamp(text):
    return datetime.fromisoformat(text.replace("Z", "+00:00"))


def shows_something(cell):
    return any(
        any(m == "text/html" or m.startswith("image/") for m in o.get("data", {}))
        or o.get("output_type") == "stream"
        for o in cell.get("outputs", [])
    )


def cell_times(path):
    """[(first source line, seconds, shows output)] for each executed code cell."""
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    rows = []
    for c in nb["cells"]:
        run = c.get("metadata", {}).get("execution")
        if c["cell_type"] != "code" or not run:
            continue
        seconds = (stamp(run["shell.execute_reply"]) - stamp(run["iopub.execute_input"])).total_seconds()
        source = "".join(c["source"]).strip().splitlines()
        rows.append((source[0] if source else "", seconds, shows_something(c), run))
    return rows


def summary(path):
    """Setup, first output, later median, later max, total (seconds); None where absent."""
    rows = cell_times(path)
    if not rows:
        return None
    start = stamp(rows[0][3]["iopub.execute_input"])
    end = stamp(rows[-1][3]["shell.execute_reply"])
    first = next((k for k, r in enumerate(rows) if r[2]), None)
    first_s = (stamp(rows[first][3]["shell.execute_reply"]) - start).total_seconds() if first is not None else None
    later = [r[1] for r in rows[first + 1:]] if first is not None else []
    return {
        "setup": rows[0][1],
        "first": first_s,
        "median": statistics.median(later) if later else None,
        "max": max(later) if later else None,
        "total": (end - start).total_seconds(),
        "cells": len(rows),
    }


def fmt(x):
    return "—" if x is None else f"{x:.1f}"


def run_cell(kc, source):
    """Executes `source` in the kernel; (seconds, shows a figure, error text or None)."""
    import time
    start = time.time()
    msg_id = kc.execute(source)
    figure, error = False, None
    while True:
        m = kc.get_iopub_msg(timeout=1800)
        if m["parent_header"].get("msg_id") != msg_id:
            continue
        kind = m["msg_type"]
        if kind in ("execute_result", "display_data"):
            data = m["content"]["data"]
            html = data.get("text/html", "")
            figure = figure or "image/png" in data or "<svg" in html or "<img" in html
        elif kind == "error":
            error = m["content"].get("evalue", "error")
        elif kind == "status" and m["content"]["execution_state"] == "idle":
            return time.time() - start, figure, error


def try_it(path, rounds=3):
    """Times a notebook's Try-it edit in a live kernel (see the module docs)."""
    from jupyter_client.manager import start_new_kernel
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    code = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]
    edit = next(k for k, c in enumerate(code) if "✎ EDIT" in c)
    km, kc = start_new_kernel(kernel_name="rust", startup_timeout=300)
    try:
        shown = {}
        for k, source in enumerate(code):
            seconds, figure, error = run_cell(kc, source)
            if error:
                sys.exit(f"{path}: cell {k + 1} failed: {error}")
            shown[k] = figure
        draw = next(k for k in range(edit + 1, len(code)) if shown[k])
        print(f"{path}: Try-it edit cell {edit + 1}, figure cell {draw + 1}")
        for r in range(rounds):
            # a change to the cell's code, as any edit is: the kernel compiles it anew
            a, _, error = run_cell(kc, code[edit] + f"\n// edit {r + 1}")
            b, figure, error_b = run_cell(kc, code[draw])
            if error or error_b or not figure:
                sys.exit(f"{path}: the edit did not give a figure: {error or error_b}")
            print(f"  edit {r + 1}: edit cell {a:.2f} s, figure cell {b:.2f} s, "
                  f"edit → new figure {a + b:.2f} s")
    finally:
        km.shutdown_kernel(now=True)


if __name__ == "__main__":
    args = sys.argv[1:]
    if args[:1] == ["--try-it"]:
        for path in args[1:]:
            try_it(path)
        sys.exit(0)
    cells = "--cells" in args
    markdown = "--markdown" in args
    paths = [a for a in args if not a.startswith("--")]
    if markdown:
        print("| notebook | code cells | setup cell | first output | later cells: median | slowest | all |")
        print("|---|---|---|---|---|---|---|")
    for path in paths:
        s = summary(path)
        name = os.path.basename(path).removesuffix(".ipynb")
        if s is None:
            print(f"{path}: no code cells" if not markdown else f"| `{name}` | 0 | — | — | — | — | — |")
            continue
        if markdown:
            print(f"| `{name}` | {s['cells']} | {fmt(s['setup'])} s | {fmt(s['first'])} s | "
                  f"{fmt(s['median'])} s | {fmt(s['max'])} s | {fmt(s['total'])} s |")
        else:
            print(f"{path}: setup {fmt(s['setup'])} s, first output {fmt(s['first'])} s, later cells "
                  f"median {fmt(s['median'])} s, slowest {fmt(s['max'])} s, all cells {fmt(s['total'])} s")
        if cells:
            for k, (line, seconds, shown, _) in enumerate(cell_times(path), 1):
                print(f"  {k:3d} {seconds:7.2f} s {'*' if shown else ' '} {line[:70]}")
