"""Prints, for executed notebooks, the time to first output (from the start of the first code
cell to the end of the first cell that displays a figure or table) and the total time, from
the cell timestamps nbclient records.

usage: python3 scripts/notebook_times.py out/notebooks/*.ipynb
"""
import json
import sys
from datetime import datetime


def stamp(text):
    return datetime.fromisoformat(text.replace("Z", "+00:00"))


def times(path):
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    cells = [c for c in nb["cells"] if c["cell_type"] == "code" and c["metadata"].get("execution")]
    if not cells:
        return None, None
    start = stamp(cells[0]["metadata"]["execution"]["iopub.execute_input"])
    end = stamp(cells[-1]["metadata"]["execution"]["shell.execute_reply"])
    first = None
    for c in cells:
        shown = any(
            "text/html" in o.get("data", {}) or o.get("output_type") == "stream"
            for o in c.get("outputs", [])
        )
        if shown:
            first = stamp(c["metadata"]["execution"]["shell.execute_reply"]) - start
            break
    return (first.total_seconds() if first else None), (end - start).total_seconds()


if __name__ == "__main__":
    for path in sys.argv[1:]:
        first, total = times(path)
        if total is None:
            print(f"{path}: no code cells")
        else:
            f = f"{first:.1f} s" if first is not None else "—"
            print(f"{path}: first output {f}, all cells {total:.1f} s")
