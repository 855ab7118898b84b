"""Fails (exit 1) if an executed notebook holds an error output or a panic/error on stderr.

`jupyter execute` already fails on a cell error, but evcxr reports some failures only as
text: a top-level `?` on an `Err` prints the error's text to stderr and the cell "succeeds"
(measured with evcxr_jupyter 0.22.0). That text has no fixed form, so any stderr output in a
code cell is a failure; the notebooks print nothing to stderr when healthy (compiler warnings
included, deliberately). Names the notebook and the cell.

It also fails when a figure, table or HTML view of splinelab shows up as its `Debug` text
instead of its display (evcxr does that to the value of the first cell of a session that
uses `?`; the notebooks settle it with one `?` in their `use` cell), and when mathematics
(text/latex) comes without its MathML twin in text/html, which is what the HTML copy shows
and browsers render without a script.

Two more uses keep the stored notebooks (notebooks/*.ipynb, kept with their outputs) true:

  check_notebooks.py --store FRESH DEST      writes the executed notebook FRESH to DEST in
                                             its stored form (`stored`: run metadata dropped)
  check_notebooks.py --stale STORED FRESH …  fails when a stored notebook's outputs differ from
                                             a fresh execution's (`stale`), naming the cell and
                                             the first difference

The outputs are deterministic, so text is compared exactly and figures by their PNG bytes;
the one exception is a benchmark run in the kernel (`<div class="timing">`), whose numbers
are a timing by design and are not compared.
"""
import json
import sys

# The Debug text of splinelab values that have a display of their own.
DEBUG_DUMPS = ("Figure {", "Animation {", "Table {", "Html {", "SurfaceFormulas {", "CurveFormulas {",
               "BasisFormulas {", "PatchFormulas {", "MathTable {", "Formula {")


def problems(path):
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    number = 0
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "code":
            continue
        number += 1
        for out in cell.get("outputs", []):
            kind = out.get("output_type")
            if kind == "error":
                yield number, f"{out.get('ename', '')}: {out.get('evalue', '')}".strip()
            elif kind == "stream" and out.get("name") == "stderr":
                text = "".join(out.get("text", [])).strip()
                if text:
                    yield number, "stderr: " + text.splitlines()[0]
            elif kind in ("execute_result", "display_data"):
                plain = "".join(out.get("data", {}).get("text/plain", []))
                if plain.startswith("Error") or "panicked" in plain:
                    yield number, plain.strip().splitlines()[0]
                elif len(out.get("data", {})) == 1 and plain.startswith(DEBUG_DUMPS):
                    yield number, "shown as Debug text, not displayed: " + plain[:60]
                data = out.get("data", {})
                if "text/latex" in data and "<math" not in "".join(data.get("text/html", [])):
                    # the HTML copy shows text/html when there is one; without MathML beside
                    # the LaTeX it would need MathJax (a script from the network) to render
                    yield number, "mathematics without its MathML (text/html) twin"


# Cell metadata that a run writes and that is not the notebook's content: nbclient's
# timestamps of each execution.
RUN_METADATA = ("execution",)


def stored(nb):
    """The notebook `nb` as it is kept: each cell's run metadata dropped, streams of one kind
    that follow each other merged (the kernel may split a print at any byte), and the sources
    and texts as lists of lines (Jupyter's own on-disk form)."""
    def lines(text):
        text = "".join(text) if isinstance(text, list) else text
        return text.splitlines(keepends=True)

    for cell in nb.get("cells", []):
        meta = cell.get("metadata", {})
        for key in RUN_METADATA:
            meta.pop(key, None)
        cell["source"] = lines(cell.get("source", ""))
        if cell.get("cell_type") != "code":
            continue
        merged = []
        for out in cell.get("outputs", []):
            if out.get("output_type") == "stream":
                out["text"] = lines(out.get("text", ""))
                if merged and merged[-1].get("output_type") == "stream" and \
                        merged[-1].get("name") == out.get("name"):
                    merged[-1]["text"] = lines("".join(merged[-1]["text"]) + "".join(out["text"]))
                    continue
            for mime, value in out.get("data", {}).items():
                if isinstance(value, (str, list)) and not mime.startswith("image/"):
                    out["data"][mime] = lines(value)
            merged.append(out)
        cell["outputs"] = merged
    return nb


# An output that is a timing by design (a benchmark run in the kernel: `BenchResult`'s display
# wraps it in this class) differs from run to run; its text is not compared, only its place.
TIMING = '<div class="timing">'


def timing_free(out):
    """`out`, or a placeholder if it is a timing by design."""
    html = "".join(out.get("data", {}).get("text/html", []))
    return {"timing": True} if html.startswith(TIMING) else out


def outputs_of(nb):
    """Each code cell's place (its number among all cells, from 1), source and outputs in
    their stored form, in order."""
    return [(k, "".join(c.get("source", [])), [timing_free(o) for o in c.get("outputs", [])])
            for k, c in enumerate(stored(nb).get("cells", []), start=1)
            if c.get("cell_type") == "code"]


def first_difference(a, b):
    """Where two outputs' JSON texts first differ, with a little of each."""
    x, y = json.dumps(a, sort_keys=True), json.dumps(b, sort_keys=True)
    i = next((k for k in range(min(len(x), len(y))) if x[k] != y[k]), min(len(x), len(y)))
    return f"stored …{x[max(0, i - 40):i + 60]!r}… fresh …{y[max(0, i - 40):i + 60]!r}…"


def stale(stored_path, fresh_path):
    """The code cells whose stored outputs differ from a fresh execution's (or whose source
    does: the fresh run is of another text), as (cell number among all cells, from 1, what)."""
    with open(stored_path, encoding="utf-8") as f:
        kept = outputs_of(json.load(f))
    with open(fresh_path, encoding="utf-8") as f:
        fresh = outputs_of(json.load(f))
    if len(kept) != len(fresh):
        yield 0, f"{len(kept)} code cells stored, {len(fresh)} executed"
        return
    for (number, src_a, out_a), (_, src_b, out_b) in zip(kept, fresh):
        if src_a != src_b:
            yield number, "the executed source is not the stored one"
        elif not out_a and out_b:
            yield number, "stored without its outputs"
        elif out_a != out_b:
            yield number, "stored outputs differ from a fresh run: " + first_difference(out_a, out_b)


def store(fresh_path, dest_path):
    """Writes the executed notebook at `fresh_path` to `dest_path` in its stored form."""
    with open(fresh_path, encoding="utf-8") as f:
        nb = stored(json.load(f))
    with open(dest_path, "w", encoding="utf-8") as f:
        json.dump(nb, f, indent=1, ensure_ascii=False)
        f.write("\n")


def self_test():
    """Checks the scanner on synthetic notebooks: each failure kind is caught, a clean one passes."""
    import os
    import tempfile

    def notebook(outputs):
        return {"cells": [{"cell_type": "code", "outputs": outputs, "source": ""}], "nbformat": 4}

    cases = {
        "error output": (notebook([{"output_type": "error", "ename": "E", "evalue": "x"}]), True),
        "panic on stderr": (notebook([{"output_type": "stream", "name": "stderr",
                                       "text": ["thread '<unnamed>' panicked at src/lib.rs:1:1:\n"]}]), True),
        "compile error": (notebook([{"output_type": "stream", "name": "stderr",
                                     "text": ["error[E0308]: mismatched types\n"]}]), True),
        "Err value": (notebook([{"output_type": "execute_result", "data": {"text/plain": ["Error: boom"]}}]), True),
        "top-level ? on Err (evcxr prints the error text)": (
            notebook([{"output_type": "stream", "name": "stderr", "text": ["deliberate error\n"]}]), True),
        "warning on stderr": (notebook([{"output_type": "stream", "name": "stderr",
                                         "text": ["warning: unused variable\n"]}]), True),
        "a figure shown as its Debug text": (
            notebook([{"output_type": "execute_result",
                       "data": {"text/plain": ["Figure { drawing: Scene(Figure3d { title: \"x\" }) }"]}}]), True),
        "LaTeX without MathML": (
            notebook([{"output_type": "display_data",
                       "data": {"text/latex": ["$$x^2$$"], "text/plain": [""]}}]), True),
        "clean": (notebook([{"output_type": "stream", "name": "stdout", "text": ["table\n"]},
                            {"output_type": "execute_result", "data": {"text/plain": ["42"]}},
                            {"output_type": "display_data",
                             "data": {"text/latex": ["$$x^2$$"],
                                      "text/html": ["<math display=\"block\"><msup><mi>x</mi><mn>2</mn></msup></math>"]}}]),
                  False),
    }
    wrong = []
    with tempfile.TemporaryDirectory() as d:
        for name, (nb, should_fail) in cases.items():
            path = os.path.join(d, "case.ipynb")
            with open(path, "w", encoding="utf-8") as f:
                json.dump(nb, f)
            if any(True for _ in problems(path)) != should_fail:
                wrong.append(name)
        # staleness: a stored copy of a run is fresh; a changed number, a missing output, a
        # changed figure or an edited source is stale
        def code(source, outputs):
            return {"cells": [{"cell_type": "code", "source": source, "outputs": outputs,
                               "metadata": {"execution": {"shell.execute_reply": "now"}}}],
                    "nbformat": 4}
        text = {"output_type": "stream", "name": "stdout", "text": ["x = 0.5\n"]}
        split = [{"output_type": "stream", "name": "stdout", "text": ["x = 0."]},
                 {"output_type": "stream", "name": "stdout", "text": ["5\n"]}]
        png = {"output_type": "display_data", "data": {"image/png": "iVBORw0KGgo="}}

        def timing(t):
            return {"output_type": "display_data",
                    "data": {"text/html": [TIMING + "<table>" + t + "</table></div>"]}}
        run = code("let x = 0.5;", [text, png])
        stale_cases = {
            "a stored copy of the run": (run, code("let x = 0.5;", split + [png]), False),
            "a changed number": (run, code("let x = 0.5;", [dict(text, text=["x = 0.6\n"]), png]), True),
            "stored without outputs": (code("let x = 0.5;", []), run, True),
            "a changed figure": (run, code("let x = 0.5;", [text, {"output_type": "display_data",
                                                                   "data": {"image/png": "iVBORw0KGgp="}}]), True),
            "an edited source": (code("let x = 0.6;", [text, png]), run, True),
            "another timing": (code("b", [timing("1 s")]), code("b", [timing("2 s")]), False),
            "a timing lost": (code("b", [timing("1 s")]), code("b", [text]), True),
        }
        for name, (kept, fresh, should_fail) in stale_cases.items():
            kept_path, fresh_path = os.path.join(d, "kept.ipynb"), os.path.join(d, "fresh.ipynb")
            stored_path = os.path.join(d, "stored.ipynb")
            with open(fresh_path, "w", encoding="utf-8") as f:
                json.dump(fresh, f)
            with open(kept_path, "w", encoding="utf-8") as f:
                json.dump(kept, f)
            # what --store writes is what --stale compares
            store(kept_path, stored_path)
            if any(True for _ in stale(stored_path, fresh_path)) != should_fail:
                wrong.append("stale: " + name)
        cases.update({"stale: " + k: v for k, v in stale_cases.items()})
    if wrong:
        print(f"check_notebooks self-test: wrong verdict for {wrong}", file=sys.stderr)
        return 1
    print(f"check_notebooks self-test: {len(cases)} passed, 0 failed")
    return 0


def main(paths):
    failed = False
    for path in paths:
        for cell, what in problems(path):
            print(f"{path}: code cell {cell}: {what}", file=sys.stderr)
            failed = True
    return 1 if failed else 0


def main_stale(paths):
    if len(paths) % 2:
        print("usage: check_notebooks.py --stale STORED FRESH [STORED FRESH ...]", file=sys.stderr)
        return 2
    failed = False
    for kept, fresh in zip(paths[::2], paths[1::2]):
        for cell, what in stale(kept, fresh):
            print(f"{kept}: cell {cell}: {what}", file=sys.stderr)
            failed = True
    if failed:
        print("the stored notebooks are stale: regenerate them with `scripts/notebooks.sh --store`",
              file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    if sys.argv[1:2] == ["--stale"]:
        sys.exit(main_stale(sys.argv[2:]))
    if sys.argv[1:2] == ["--store"] and len(sys.argv) == 4:
        store(sys.argv[2], sys.argv[3])
        sys.exit(0)
    sys.exit(main(sys.argv[1:]))
