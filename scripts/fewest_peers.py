#!/usr/bin/env python3
"""`splinelab fewest` beside three simplifiers, on the shipped outlines.

For each outline (the Sicily coast, the leaf, the nine `--shape` outlines and four icons of
tests/data/svg_corpus), `splinelab fewest --method angular,cardinal,cubic,bspline,linear`
finds the fewest points of each method within the tolerance (default 1 % of the outline's
size, the larger side of its bounding box). Then, on the same points (NAME-outline.csv, the
outline exactly as the search read it) and the same tolerance (a distance: the fraction of
the size taken over all contours), three peers run on each contour:

| peer    | library                                        | parameter bisected          |
|---------|------------------------------------------------|-----------------------------|
| RDP     | simplification.cutil.simplify_coords           | epsilon (a distance)        |
| VW      | simplification.cutil.simplify_coords_vw        | epsilon (an area)           |
| splprep | scipy.interpolate.splprep, cubic, per=1 closed | smoothing s                 |

Each parameter is bisected on a log scale (40 steps) for the largest value whose result lies
within the tolerance; the count is that result's points counted as splinelab counts them
(RDP, VW: the distinct vertices kept, + 1 for a closed contour, its first point repeated;
splprep: the B-spline's control points, the k coefficients scipy repeats at the end of a
periodic spline taken off and the closing one counted, as splinelab counts a closed
B-spline's control polygon), summed over the contours. "—": no parameter is within (or the
peer cannot fit the contour: splprep needs 4 distinct points).

The measure is splinelab's: the symmetric Hausdorff distance max(h(curve, outline),
h(outline, curve)), h(A, B) the largest distance from a point of A to the nearest segment of
B, the curve sampled at 256 points per piece (a polygon's side, a spline's knot span; at
least 20 000 points for a spline), the outline by its vertices. It is exact over these
points: a k-d tree of points along B at most `step` apart bounds each distance within
step / 2, and the points whose bound reaches the answer are measured against the segments
near them (a check on two squares runs at start-up).

Prints a Markdown table (one row per outline, the count columns totalled below, the wall time
of splinelab's whole run and of each peer's bisection, its fits and their measures, over all
contours) and notes (a simplifier below our exact polygon on a contour, which would be a bug on
one side; splprep below our bspline; a peer with no count), writes them to
out/tables/fewest-peers.md and as CSV (per-contour counts, errors, parameters) to
out/tables/fewest-peers.csv; splinelab's own outputs go to out/fewest-peers/. Runs in the
notebooks' virtual environment ($SPLINELAB_STATE/venv, default ~/.cache/splinelab/venv),
installing the pinned numpy, scipy and simplification into it if they are missing; builds
splinelab with `cargo build --release` only if target/release/splinelab is missing.

usage: python3 scripts/fewest_peers.py [--binary PATH] [--only NAME ...] [--tolerance 1%]
"""
import argparse
import collections
import csv
import importlib.metadata
import itertools
import math
import os
import pathlib
import re
import subprocess
import sys
import time
import warnings

try:
    import numpy as np
    from scipy.interpolate import splev, splprep
    from scipy.spatial import cKDTree
    from simplification.cutil import simplify_coords, simplify_coords_vw
except ImportError:  # outside the virtual environment: main() runs this script again in it
    np = None

NUMPY_VERSION = "2.4.6"
SCIPY_VERSION = "1.17.1"
SIMPLIFICATION_VERSION = "2.0.0"
PINS = {"numpy": NUMPY_VERSION, "scipy": SCIPY_VERSION, "simplification": SIMPLIFICATION_VERSION}
ROOT = pathlib.Path(__file__).resolve().parent.parent
METHODS = "angular,cardinal,cubic,bspline,linear"
SHAPES = ["circle", "ellipse-0.7", "ellipse-0.4", "parabola-2", "parabola-1", "hyperbola-2",
          "hyperbola-0.5", "sinusoid-1", "rectangle-2x1"]
# four icons of different kinds: filled with a hole (bootstrap), a stroke of straight open
# lines (tabler), a stroke of arcs (feather), a filled logo of several contours (simple-icons)
ICONS = ["bootstrap-gear-fill", "tabler-cube", "feather-umbrella", "simple-icons-markdown"]
# each outline: its name (the file stem) and the arguments naming it to `splinelab fewest`
OUTLINES = (
    [("sicily-coastline", ["data/sicily-coastline.csv", "--closed"]),
     ("leaf", ["data/examples/leaf.svg"])]
    + [(shape, ["--shape", shape]) for shape in SHAPES]
    + [(icon, [f"tests/data/svg_corpus/{icon}.svg"]) for icon in ICONS]
)
PEERS = ["RDP", "VW", "splprep"]
# the table's count columns: its header, and where the count comes from (ours or a peer)
COLUMNS = [("linear (ours, exact)", "linear"), ("RDP", "RDP"), ("VW", "VW"),
           ("bspline (ours)", "bspline"), ("splprep", "splprep"), ("cardinal", "cardinal"),
           ("cubic", "cubic"), ("angular", "angular")]
SAMPLES_PER_PIECE = 256  # splinelab's FINAL_SAMPLES
SPLINE_SAMPLES = 20_000  # the fewest samples of a splprep spline
BISECTION_STEPS = 40
# the lowest parameter tried, as a fraction of the tolerance (RDP; squared for VW and splprep)
LOWEST = 1e-6
# the spacing of the k-d tree's points along a polyline, as a fraction of the tolerance
STEP = 1 / 8
CHUNK = 4096  # points measured exactly at once
SPLPREP_DEGREE = 3
# a peer on one contour: its count at `parameter`, the largest within the tolerance, and that
# result's error; without a count (None), `error` is the error at the lowest parameter (None
# when the peer cannot fit the contour at all)
Fit = collections.namedtuple("Fit", "count parameter error")


def venv_python():
    """The virtual environment's Python, with the pinned numpy, scipy and simplification."""
    state = pathlib.Path(os.environ.get("SPLINELAB_STATE", pathlib.Path.home() / ".cache/splinelab"))
    python = state / "venv" / "bin" / "python"
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(state / "venv")], check=True)
    wanted = " ".join(f"{name}=={version}" for name, version in PINS.items())
    probe = subprocess.run(
        [str(python), "-c",
         "import importlib.metadata as m, sys; "
         f"sys.exit(any(m.version(n) != v for n, v in {PINS!r}.items()))"],
        capture_output=True)
    if probe.returncode != 0:
        print(f"installing {wanted} into {python.parent.parent}", file=sys.stderr, flush=True)
        subprocess.run(
            [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
             *(f"{name}=={version}" for name, version in PINS.items())],
            check=True,
        )
    return python


def in_venv(python):
    """Whether this process runs the virtual environment's Python with the pinned packages."""
    if np is None or pathlib.Path(sys.prefix).resolve() != python.parent.parent.resolve():
        return False
    return all(importlib.metadata.version(name) == version for name, version in PINS.items())


def splinelab_binary(path):
    """The splinelab binary: `path`, or target/release/splinelab, built if it is missing."""
    if path:
        return pathlib.Path(path).resolve()
    binary = ROOT / "target" / "release" / "splinelab"
    if not binary.exists():
        subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    return binary


def segment_distances(p, a, b):
    """The distance from each point p[i] to the segment a[i] b[i] (arrays of shape (n, 2))."""
    d = b - a
    dd = np.einsum("ij,ij->i", d, d)
    t = np.einsum("ij,ij->i", p - a, d) / np.where(dd > 0, dd, 1.0)
    t = np.clip(np.where(dd > 0, t, 0.0), 0.0, 1.0)
    return np.hypot(*(p - a - t[:, None] * d).T)


class Polyline:
    """A polyline's segments and a k-d tree of points along it at most `step` apart (both
    ends of every segment among them), each point knowing its segment."""

    def __init__(self, vertices, step):
        self.vertices = vertices
        self.a, self.b = vertices[:-1], vertices[1:]
        lengths = np.hypot(*(self.b - self.a).T)
        pieces = np.maximum(1, np.ceil(lengths / step).astype(np.int64))
        self.segment = np.repeat(np.arange(len(lengths)), pieces + 1)
        first = np.repeat(np.cumsum(pieces + 1) - (pieces + 1), pieces + 1)
        along = (np.arange(len(self.segment)) - first) / pieces[self.segment]
        dense = self.a[self.segment] + along[:, None] * (self.b - self.a)[self.segment]
        self.tree = cKDTree(dense)
        self.step = step

    def nearest(self, points, bounds):
        """The distance from each point to the nearest segment, given for each an upper bound
        (the segments within it lie within bound + step / 2 of a point of the tree)."""
        reach = bounds + self.step / 2
        lists = self.tree.query_ball_point(points, reach * (1 + 1e-9) + 1e-300,
                                           return_sorted=False)
        counts = np.fromiter(map(len, lists), dtype=np.int64, count=len(lists))
        near = np.fromiter(itertools.chain.from_iterable(lists), dtype=np.int64,
                           count=int(counts.sum()))
        owner = np.repeat(np.arange(len(points)), counts)
        seg = self.segment[near]
        d = segment_distances(points[owner], self.a[seg], self.b[seg])
        return np.minimum.reduceat(d, np.cumsum(counts) - counts)

    def farthest(self, points, limit=None):
        """h(points, polyline): the largest distance from a point to the nearest segment.
        Exact without `limit`; with one, it exceeds `limit` exactly when the exact value does
        (the search stops there, and skips the points that cannot exceed it)."""
        upper, _ = self.tree.query(points)  # within step / 2 above the exact distance
        if limit is not None and upper.max() - self.step / 2 > limit:
            return upper.max() - self.step / 2  # a lower bound, enough to compare
        order = np.argsort(-upper)
        best = 0.0
        for start in range(0, len(order), CHUNK):
            batch = order[start:start + CHUNK]
            batch = batch[upper[batch] > (best if limit is None else max(best, limit))]
            if len(batch) == 0:
                break
            best = max(best, float(self.nearest(points[batch], upper[batch]).max()))
            if limit is not None and best > limit:
                break
        return best


def hausdorff(samples, outline, limit=None):
    """The symmetric Hausdorff distance between a curve (its samples, in order) and an outline
    contour (a Polyline): max(h(samples, outline's segments), h(outline's vertices, the
    samples' segments)); exact without `limit`, with one only compared with it (as
    Polyline.farthest)."""
    there = outline.farthest(samples, limit)
    if limit is not None and there > limit:
        return there
    return max(there, Polyline(samples, outline.step).farthest(outline.vertices, limit))


def sample_polygon(vertices):
    """A polygon's sides at SAMPLES_PER_PIECE points each, its last vertex once at the end."""
    t = np.arange(SAMPLES_PER_PIECE)[None, :, None] / SAMPLES_PER_PIECE
    a, b = vertices[:-1, None, :], vertices[1:, None, :]
    return np.concatenate([(a + t * (b - a)).reshape(-1, 2), vertices[-1:]])


def sample_spline(tck):
    """A spline from splprep at SAMPLES_PER_PIECE parameters per knot span of its domain, more
    if needed for SPLINE_SAMPLES in all, the domain's end once at the end."""
    t, _, k = tck
    knots = np.unique(t[k:len(t) - k])
    per_span = max(SAMPLES_PER_PIECE, math.ceil(SPLINE_SAMPLES / (len(knots) - 1)))
    s = np.arange(per_span) / per_span
    u = np.concatenate([(knots[:-1, None] + s * np.diff(knots)[:, None]).ravel(), knots[-1:]])
    return np.column_stack(splev(u, tck))


def self_check():
    """The measure on a case with a known answer: the unit square against itself scaled by
    1.01 about its centre. Its sides are 0.005 apart, so each corner of the unit square is
    0.005 from the large square's sides, but each corner of the large square is 0.005·√2
    from the unit square's corner: h = 0.005 one way, 0.005·√2 the other."""
    unit = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]])
    large = 0.5 + 1.01 * (unit - 0.5)
    outline = Polyline(unit, 0.01)
    samples = sample_polygon(large)
    back = Polyline(samples, 0.01).farthest(unit)
    assert abs(back - 0.005) < 1e-12, back
    assert abs(hausdorff(samples, outline) - 0.005 * math.sqrt(2)) < 1e-12
    assert hausdorff(samples, outline, limit=0.007) > 0.007
    assert hausdorff(samples, outline, limit=0.0071) <= 0.0071


class Contour:
    """One contour of an outline, as the search read it (a closed one's last point repeats its
    first), measured within `tolerance`."""

    def __init__(self, points, closed, tolerance):
        self.points = points
        self.closed = closed
        self.tolerance = tolerance
        self.polyline = Polyline(points, STEP * tolerance)

    def within(self, samples):
        """Whether a curve's samples lie within the tolerance of this contour."""
        return hausdorff(samples, self.polyline, self.tolerance) <= self.tolerance

    def error(self, samples):
        """The exact symmetric Hausdorff distance between a curve's samples and this contour."""
        return hausdorff(samples, self.polyline)

    def polygon(self, kept):
        """A simplifier's kept vertices: their samples and their count as splinelab counts a
        polygon (the distinct vertices, + 1 for a closed one: its first point repeated)."""
        distinct = len(kept) - int(self.closed and np.array_equal(kept[0], kept[-1]))
        return sample_polygon(kept), distinct + int(self.closed)

    def rdp(self, epsilon):
        """Ramer–Douglas–Peucker with distance `epsilon`: (samples, count)."""
        return self.polygon(np.asarray(simplify_coords(self.points, epsilon)))

    def vw(self, area):
        """Visvalingam–Whyatt with area `area`: (samples, count)."""
        return self.polygon(np.asarray(simplify_coords_vw(self.points, area)))

    def splprep(self, s):
        """scipy's cubic smoothing spline with smoothing `s` (periodic for a closed contour):
        (samples, count), count the control points as splinelab counts a B-spline's (a
        periodic one's k repeated coefficients taken off, its closing one counted); None when
        scipy cannot fit the contour (fewer than k + 1 distinct points, or an input error)."""
        points = self.points[np.r_[True, np.any(np.diff(self.points, axis=0) != 0, axis=1)]]
        k = SPLPREP_DEGREE
        if len(points) - int(self.closed) <= k:
            return None
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                (tck, _), _, ier, _ = splprep(points.T, s=s, k=k, per=int(self.closed),
                                              full_output=1, quiet=1)
        except ValueError:
            return None
        if ier >= 10:
            return None
        coefficients = len(tck[1][0])
        count = coefficients - k + 1 if self.closed else coefficients
        return sample_spline(tck), count


def bisect_largest(attempt, lo, hi):
    """The largest parameter in [lo, hi] (bisected on a log scale, BISECTION_STEPS steps) for
    which `attempt` gives a result, and that result: (parameter, result), or None when even
    `lo` gives none."""
    result = attempt(hi)
    if result is not None:
        return hi, result
    best = None
    for _ in range(BISECTION_STEPS):
        mid = math.sqrt(lo * hi)
        result = attempt(mid)
        if result is not None:
            lo, best = mid, (mid, result)
        else:
            hi = mid
    if best is None:
        result = attempt(lo)
        best = None if result is None else (lo, result)
    return best


def peer_fit(contour, peer, size):
    """A peer's fewest points on one contour (a Fit)."""
    tol = contour.tolerance
    fit, lo, hi = {
        "RDP": (contour.rdp, LOWEST * tol, size),
        "VW": (contour.vw, (LOWEST * tol) ** 2, size ** 2),
        "splprep": (contour.splprep, len(contour.points) * (LOWEST * tol) ** 2,
                    len(contour.points) * size ** 2),
    }[peer]

    def attempt(parameter):
        result = fit(parameter)
        return result if result is not None and contour.within(result[0]) else None

    found = bisect_largest(attempt, lo, hi)
    if found is None:
        lowest = fit(lo)
        return Fit(None, lo, None if lowest is None else contour.error(lowest[0]))
    parameter, (samples, count) = found
    return Fit(count, parameter, contour.error(samples))


def read_outline(path, tolerance_arg):
    """The contours of NAME-outline.csv, the outline's size (the larger side of the bounding
    box of all contours) and the tolerance as a distance."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    groups = {}
    for row in rows:
        groups.setdefault(row["contour"], []).append(row)
    everything = np.array([[float(r["x"]), float(r["y"])] for r in rows])
    size = float(np.max(everything.max(axis=0) - everything.min(axis=0)))
    text = tolerance_arg.strip()
    tolerance = float(text[:-1]) / 100 * size if text.endswith("%") else float(text)
    contours = [Contour(np.array([[float(r["x"]), float(r["y"])] for r in group]),
                        group[0]["closed"] == "true", tolerance)
                for group in groups.values()]
    return contours, size, tolerance


def check_tolerance(markdown, size, tolerance):
    """Stops if splinelab's header (NAME-fewest.md: 'within T (P % of the size S)') states
    another size or tolerance than the ones computed here from the outline."""
    header = markdown.read_text(encoding="utf-8").splitlines()[0]
    match = re.search(r"within (\S+) \(.* of the size (\S+)\)", header)
    if match is None:
        sys.exit(f"{markdown}: no tolerance in its header: {header}")
    theirs = float(match.group(1)), float(match.group(2))
    for ours, stated in zip((tolerance, size), theirs):
        if abs(ours - stated) > 1e-5 * abs(stated):
            sys.exit(f"{markdown}: splinelab states tolerance {theirs[0]} of size {theirs[1]}, "
                     f"this script computed {tolerance} of {size}")


def run_ours(binary, name, args, tolerance_arg, out):
    """splinelab fewest on one outline: its rows by method and its wall time."""
    start = time.perf_counter()
    subprocess.run([str(binary), "fewest", *args, "--method", METHODS, "--tolerance",
                    tolerance_arg, "--out", str(out)],
                   cwd=ROOT, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    seconds = time.perf_counter() - start
    with open(out / f"{name}-fewest.csv", newline="", encoding="utf-8") as f:
        return {row["method"]: row for row in csv.DictReader(f)}, seconds


def compare(binary, name, args, tolerance_arg, out):
    """One outline: splinelab's counts, each peer's per contour, and the times."""
    ours, ours_seconds = run_ours(binary, name, args, tolerance_arg, out)
    contours, size, tolerance = read_outline(out / f"{name}-outline.csv", tolerance_arg)
    check_tolerance(out / f"{name}-fewest.md", size, tolerance)
    peers, seconds = {}, {}
    for peer in PEERS:
        start = time.perf_counter()
        peers[peer] = [peer_fit(contour, peer, size) for contour in contours]
        seconds[peer] = time.perf_counter() - start
    return {"outline": name, "contours": len(contours), "size": size, "tolerance": tolerance,
            "ours": ours, "ours_seconds": ours_seconds, "peers": peers, "peer_seconds": seconds}


def count_of(result, column):
    """A count column of one outline: (total or None, per-contour text, marker); ours marked
    † when splinelab states it is not within the tolerance."""
    if column in PEERS:
        fits = result["peers"][column]
        per = " + ".join("—" if fit.count is None else str(fit.count) for fit in fits)
        total = (None if any(fit.count is None for fit in fits)
                 else sum(fit.count for fit in fits))
        return total, per, ""
    row = result["ours"][column]
    return int(row["points"]), row["per_contour"], "" if row["within_tolerance"] == "true" else "†"


def per_contour_counts(result, column):
    """The per-contour counts of a column (None for a contour without one)."""
    if column in PEERS:
        return [fit.count for fit in result["peers"][column]]
    return [int(n) for n in result["ours"][column]["per_contour"].split(" + ")]


def notes_of(result):
    """What to look at in one outline: a simplifier's polygon with fewer points than our exact
    linear optimum on a contour (one side is wrong), splprep below our bspline (legitimate:
    other knots), a peer with no parameter within the tolerance."""
    notes = []
    linear = per_contour_counts(result, "linear")
    for peer in PEERS:
        for i, fit in enumerate(result["peers"][peer]):
            where = f"{result['outline']} contour {i + 1}"
            if fit.count is None and fit.error is None:
                notes.append(f"{where}: {peer} cannot fit it (a cubic needs 4 distinct "
                             "points; or scipy refused the input)")
            elif fit.count is None:
                notes.append(f"{where}: {peer} is not within the tolerance even at its lowest "
                             f"parameter {fit.parameter:.3g} (error "
                             f"{100 * fit.error / result['size']:.3g} % of the size)")
            elif peer != "splprep" and fit.count < linear[i]:
                notes.append(f"CHECK {where}: {peer} {fit.count} points (error "
                             f"{100 * fit.error / result['size']:.4g} % of the size, parameter "
                             f"{fit.parameter:.4g}) < linear (ours, exact) {linear[i]}")
    bspline = count_of(result, "bspline")[0]
    splprep = count_of(result, "splprep")[0]
    if splprep is not None and splprep < bspline:
        notes.append(f"{result['outline']}: splprep {splprep} < bspline (ours) {bspline} "
                     "(legitimate: other knots)")
    return notes


def markdown_table(results):
    """The Markdown table: one row per outline, a line of totals of the count columns."""
    header = (["outline", "contours", "tolerance (% of size)"] + [h for h, _ in COLUMNS]
              + ["ours (s)", "peers (s): RDP / VW / splprep"])
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    totals = {column: [0, 0] for _, column in COLUMNS}  # sum, outlines without a count
    for r in results:
        cells = [r["outline"], str(r["contours"]), f"{100 * r['tolerance'] / r['size']:.4g}"]
        for _, column in COLUMNS:
            total, _, mark = count_of(r, column)
            if total is None:
                cells.append("—")
                totals[column][1] += 1
            else:
                cells.append(f"{total}{mark}")
                totals[column][0] += total
        cells.append(f"{r['ours_seconds']:.2f}")
        cells.append(" / ".join(f"{r['peer_seconds'][p]:.2f}" for p in PEERS))
        lines.append("| " + " | ".join(cells) + " |")
    cells = ["**total**", str(sum(r["contours"] for r in results)), ""]
    for _, column in COLUMNS:
        total, missing = totals[column]
        cells.append(f"{total}" + (f" (+{missing} —)" if missing else ""))
    cells.append(f"{sum(r['ours_seconds'] for r in results):.2f}")
    cells.append(" / ".join(f"{sum(r['peer_seconds'][p] for r in results):.2f}" for p in PEERS))
    lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def csv_rows(results):
    """The CSV: per outline, each count with its per-contour parts, the peers' errors (% of
    the size, the largest over the contours) and parameters, and the times."""
    header = ["outline", "contours", "size", "tolerance", "tolerance_pct"]
    for _, column in COLUMNS:
        header += [column, f"{column}_per_contour"]
    for peer in PEERS:
        header += [f"{peer}_error_pct", f"{peer}_parameter"]
    header += ["ours_s"] + [f"{peer}_s" for peer in PEERS]
    rows = [header]
    for r in results:
        row = [r["outline"], r["contours"], repr(r["size"]), repr(r["tolerance"]),
               f"{100 * r['tolerance'] / r['size']:.6g}"]
        for _, column in COLUMNS:
            total, per, _ = count_of(r, column)
            row += ["—" if total is None else total, per]
        for peer in PEERS:
            fits = r["peers"][peer]
            errors = [fit.error for fit in fits if fit.count is not None]
            row += [f"{100 * max(errors) / r['size']:.6g}" if errors else "—",
                    " + ".join("—" if fit.count is None else f"{fit.parameter:.6g}"
                               for fit in fits)]
        row += [f"{r['ours_seconds']:.3f}"] + [f"{r['peer_seconds'][p]:.3f}" for p in PEERS]
        rows.append(row)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", help="the splinelab binary (default: target/release/splinelab)")
    parser.add_argument("--only", action="append", metavar="NAME",
                        help="run this outline only (repeatable): " + ", ".join(n for n, _ in OUTLINES))
    parser.add_argument("--tolerance", default="1%", help="splinelab's --tolerance (default 1%%)")
    options = parser.parse_args()
    unknown = set(options.only or []) - {name for name, _ in OUTLINES}
    if unknown:
        parser.error(f"unknown outline(s): {', '.join(sorted(unknown))}")
    python = venv_python()
    if not in_venv(python):
        os.execv(str(python), [str(python), str(pathlib.Path(__file__).resolve()), *sys.argv[1:]])
    self_check()
    binary = splinelab_binary(options.binary)
    out = ROOT / "out" / "fewest-peers"
    out.mkdir(parents=True, exist_ok=True)
    results = []
    for name, args in OUTLINES:
        if options.only and name not in options.only:
            continue
        r = compare(binary, name, args, options.tolerance, out)
        print(f"{name}: ours {r['ours_seconds']:.2f} s, peers "
              + " / ".join(f"{p} {r['peer_seconds'][p]:.2f} s" for p in PEERS),
              file=sys.stderr, flush=True)
        results.append(r)
    table = markdown_table(results)
    notes = [note for r in results for note in notes_of(r)]
    if any(row["within_tolerance"] != "true" for r in results for row in r["ours"].values()):
        table += "\n† splinelab states this count is not within the tolerance.\n"
    print(table + "".join(f"\n- {note}" for note in notes))
    tables = ROOT / "out" / "tables"
    tables.mkdir(parents=True, exist_ok=True)
    (tables / "fewest-peers.md").write_text(
        table + "".join(f"\n- {note}" for note in notes) + "\n", encoding="utf-8")
    with open(tables / "fewest-peers.csv", "w", newline="", encoding="utf-8") as f:
        csv.writer(f).writerows(csv_rows(results))
    print(f"wrote {tables / 'fewest-peers.md'} and {tables / 'fewest-peers.csv'}", file=sys.stderr)


if __name__ == "__main__":
    main()
