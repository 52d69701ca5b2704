#!/usr/bin/env python3
"""Plots the deformed and undeformed centerline written by cantilever_statics.

Usage: plot.py [results/cantilever_statics]   (reads centerline.csv, writes centerline.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else "results/cantilever_statics"
with open(os.path.join(folder, "centerline.csv")) as f:
    rows = list(csv.DictReader(f))
x = [float(r["x"]) for r in rows]
y = [float(r["y"]) for r in rows]
x0 = [float(r["x0"]) for r in rows]
y0 = [float(r["y0"]) for r in rows]

fig, ax = plt.subplots(figsize=(5, 5))
ax.plot(x0, y0, "--", color="grey", label="reference")
ax.plot(x, y, "-", color="C0", label="deformed")
ax.plot([x[-1]], [y[-1]], "o", color="C3", label="tip")
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.legend()
ax.grid(True, alpha=0.3)
fig.tight_layout()
out = os.path.join(folder, "centerline.png")
fig.savefig(out, dpi=120)
print(f"wrote {out}")
