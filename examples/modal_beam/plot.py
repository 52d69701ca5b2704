#!/usr/bin/env python3
"""Plots a modal_beam run: the lowest bending mode shapes and the frequencies against Timoshenko's.

Usage: plot.py [results/modal_beam]   (reads modal_beam.csv and modal_beam_shapes.csv, writes modal_beam.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, figure_grid, load_results, save_figure  # noqa: E402

folder, modes, shapes = load_results("results/modal_beam", "modal_beam.csv", "modal_beam_shapes.csv")

fig, axes = figure_grid(1, 2, (11, 4.5))
ax = axes[0]
bending = [m for m in modes if m["timoshenko_hz"] not in ("nan", "")][:6]
for m in bending:
    rows = [r for r in shapes if r["mode"] == m["mode"]]
    x = [float(r["x0"]) for r in rows]
    # The transverse displacement (the larger of y and z), control points as markers.
    dy = column(rows, "dy")
    dz = column(rows, "dz")
    d = dy if max(map(abs, dy)) > max(map(abs, dz)) else dz
    ax.plot(x, d, ".-", ms=3, label=f"mode {m['mode']}: {float(m['frequency_hz']):.1f} Hz")
ax.set_xlabel("x [m]")
ax.set_ylabel("transverse displacement (mass-normalized)")
ax.set_title("bending mode shapes (control points)")
ax.legend(fontsize=7)

ax = axes[1]
xs = [int(m["mode"]) for m in modes if m["relative_difference"] not in ("nan", "")]
ys = [float(m["relative_difference"]) for m in modes if m["relative_difference"] not in ("nan", "")]
ax.semilogy(xs, [max(y, 1e-16) for y in ys], "o")
ax.set_xlabel("mode")
ax.set_ylabel("|f - f_Timoshenko| / f_Timoshenko")
ax.set_title("against the exact Timoshenko beam")

for a in axes:
    a.grid(True, alpha=0.3)
save_figure(fig, os.path.join(folder, "modal_beam.png"), 120)
