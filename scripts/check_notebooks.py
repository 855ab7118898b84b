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
"""
import json
import sys

# The Debug text of splinelab values that have a display of their own.
DEBUG_DUMPS = ("Figure {", "Table {", "Html {", "SurfaceFormulas {", "CurveFormulas {",
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


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    sys.exit(main(sys.argv[1:]))
