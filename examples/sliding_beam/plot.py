#!/usr/bin/env python3
"""Plots a sliding_beam run: the mass's X-Z and Y-Z trajectories (003 Figure 6), both beams every
0.1 s (003 Figure 5) and the slider's coordinate along the carrier.

Usage: plot.py [results/sliding_beam]   (reads sliding_beam.csv and sliding_beam_snapshots.csv,
writes sliding_beam.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, load_results, plt, save_figure  # noqa: E402

folder, rows, snapshot_rows = load_results("results/sliding_beam", "sliding_beam.csv", "sliding_beam_snapshots.csv")

fig = plt.figure(figsize=(13, 9))

for panel, (axis, color, figure) in enumerate((("X", "C0", "6a"), ("Y", "C1", "6b")), start=1):
    ax = fig.add_subplot(2, 2, panel)
    ax.plot(column(rows, "mass_" + axis.lower()), column(rows, "mass_z"), color=color)
    ax.set_xlabel(f"{axis} [m]")
    ax.set_ylabel("Z [m]")
    ax.set_title(f"mass M: {axis}-Z trajectory (003 Figure {figure})")
    ax.set_aspect("equal")

ax = fig.add_subplot(2, 2, 3, projection="3d")
times = sorted({float(r["t"]) for r in snapshot_rows})
colors = plt.cm.viridis([i / max(1, len(times) - 1) for i in range(len(times))])
for t, color in zip(times, colors):
    for beam in ("0", "1"):
        pts = [r for r in snapshot_rows if float(r["t"]) == t and r["beam"] == beam]
        ax.plot([float(p["x"]) for p in pts], [float(p["y"]) for p in pts], [float(p["z"]) for p in pts],
                color=color, lw=1.5 if beam == "0" else 1.0)
ax.set_xlabel("X [m]")
ax.set_ylabel("Y [m]")
ax.set_zlabel("Z [m]")
ax.set_title("carrier and sliding beam every 0.1 s (003 Figure 5)")
ax.view_init(elev=20, azim=-60)

ax = fig.add_subplot(2, 2, 4)
ax.plot(column(rows, "t"), column(rows, "zeta"), color="C2", label="zeta [m]")
ax.plot(column(rows, "t"), column(rows, "zeta_rate"), color="C3", label="zeta rate [m/s]")
ax.axhline(10 ** 0.5, color="k", lw=0.5, ls="--", label="B (zeta = L)")
ax.axvline(1.306, color="gray", lw=0.5, ls=":", label="003: arrival 1.306 s")
ax.set_xlabel("t [s]")
ax.set_title("slider along the carrier")
ax.legend(fontsize=8)

save_figure(fig, os.path.join(folder, "sliding_beam.png"), 110)
