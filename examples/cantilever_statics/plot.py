#!/usr/bin/env python3
"""Plots the deformed and undeformed centerline written by cantilever_statics.

Usage: plot.py [results/cantilever_statics]   (reads centerline.csv, writes centerline.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, figure_grid, load_results, save_figure  # noqa: E402

folder, rows = load_results("results/cantilever_statics", "centerline.csv")
x = column(rows, "x")
y = column(rows, "y")
x0 = [float(r["x0"]) for r in rows]
y0 = [float(r["y0"]) for r in rows]

fig, ax = figure_grid(1, 1, (5, 5))
ax.plot(x0, y0, "--", color="grey", label="reference")
ax.plot(x, y, "-", color="C0", label="deformed")
ax.plot([x[-1]], [y[-1]], "o", color="C3", label="tip")
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.legend()
ax.grid(True, alpha=0.3)
save_figure(fig, os.path.join(folder, "centerline.png"), 120)
