"""Writes matplotlib-shapes.svg and matplotlib-plot.svg for the SVG corpus.

Run: python3 matplotlib-corpus.py OUTDIR   (matplotlib 3.11.2, numpy 2.4.6, Agg backend)
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib import patches
from matplotlib.path import Path

out = sys.argv[1] if len(sys.argv) > 1 else "."
plt.rcParams["svg.hashsalt"] = "splinelab"  # fixed ids, so a rerun gives the same file
plt.rcParams["svg.fonttype"] = "path"  # glyphs as paths, no <text>
meta = {"Date": None}

# 1. Patches only, no text: circle, rotated ellipse, rect, polygon, wedge, arc,
#    rounded box, and a path with a hole (even-odd by matplotlib's own rule).
fig, ax = plt.subplots(figsize=(3, 2))
ax.set_xlim(0, 12)
ax.set_ylim(0, 8)
ax.set_aspect("equal")
ax.axis("off")
ax.add_patch(patches.Circle((2, 6), 1.5, fc="tab:blue", ec="black", lw=1.5))
ax.add_patch(patches.Ellipse((6, 6), 4, 1.6, angle=30, fc="tab:orange", ec="none"))
ax.add_patch(patches.Rectangle((8.5, 4.8), 3, 2.4, angle=15, fc="none", ec="tab:green", lw=2))
ax.add_patch(patches.Polygon([(0.5, 0.5), (3, 0.8), (2.2, 3), (1, 2.4)], closed=True, fc="tab:red"))
ax.add_patch(patches.Wedge((5, 2), 1.8, 30, 300, width=0.7, fc="tab:purple"))
ax.add_patch(patches.Arc((8, 2), 2.5, 1.5, angle=0, theta1=0, theta2=220, lw=2, color="black"))
ax.add_patch(patches.FancyBboxPatch((9.6, 0.6), 1.8, 1.4, boxstyle="round,pad=0.2", fc="tab:cyan", ec="black"))
square = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)]
hole = [(0.3, 0.3), (0.3, 0.7), (0.7, 0.7), (0.7, 0.3), (0.3, 0.3)]
codes = [Path.MOVETO, Path.LINETO, Path.LINETO, Path.LINETO, Path.CLOSEPOLY]
verts = [(x * 1.6 + 6.6, y * 1.6 + 3.2) for x, y in square + hole]
ax.add_patch(patches.PathPatch(Path(verts, codes * 2), fc="gray", ec="black"))
fig.savefig(f"{out}/matplotlib-shapes.svg", format="svg", metadata=meta)
plt.close(fig)

# 2. A small line plot: clipped lines, markers written once in <defs> and placed with
#    <use>, tick labels as glyph paths (<defs> + <use>), a filled area.
x = np.linspace(0, 2 * np.pi, 40)
fig, ax = plt.subplots(figsize=(3, 2))
ax.plot(x, np.sin(x), color="tab:blue", lw=1.5)
ax.plot(x[::5], np.cos(x[::5]), "o--", color="tab:red", ms=4)
ax.fill_between(x, np.sin(x) * 0.5, 0, color="tab:green", alpha=0.3)
ax.set_xlim(-0.3, 6.6)  # the first marker stays inside the axes clip
ax.set_ylim(-1.2, 1.2)
ax.set_xticks([0, 2, 4, 6])
ax.set_yticks([-1, 0, 1])
fig.tight_layout()
fig.savefig(f"{out}/matplotlib-plot.svg", format="svg", metadata=meta)
plt.close(fig)
