"""Fails (exit 1) if an executed notebook holds an error output or a panic/error on stderr.

`jupyter execute` already fails on a cell error, but evcxr reports some failures as plain
output (a panic with preserved variables, a top-level `?` on an `Err`), so every executed
notebook is scanned as well. Names the notebook and the cell.
"""
import json
import re
import sys

BAD_STDERR = re.compile(r"panicked|^error(\[E\d+\])?:|^Error:", re.MULTILINE)


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
                text = "".join(out.get("text", []))
                if BAD_STDERR.search(text):
                    yield number, text.strip().splitlines()[0]
            elif kind in ("execute_result", "display_data"):
                plain = "".join(out.get("data", {}).get("text/plain", []))
                if plain.startswith("Error") or "panicked" in plain:
                    yield number, plain.strip().splitlines()[0]


def main(paths):
    failed = False
    for path in paths:
        for cell, what in problems(path):
            print(f"{path}: code cell {cell}: {what}", file=sys.stderr)
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
