#!/usr/bin/env python3
"""Plots the tip trajectory and velocity of ancf_pendulum runs beside each other.

Usage: plot.py folder [folder ...]   (reads ancf_pendulum.csv from each, writes tip.png in the first)
Example: plot.py results/ancf_pendulum results/ancf_pendulum_gebt
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, figure_grid, read_results_csv, results_folders, run_label, save_figure  # noqa: E402

folders = results_folders(["results/ancf_pendulum"])
fig, (ax1, ax2) = figure_grid(1, 2, (11, 4.5))
for folder in folders:
    rows = read_results_csv(folder, "ancf_pendulum.csv")
    t = column(rows, "t")
    label = run_label(folder)
    ax1.plot(column(rows, "tip_x"), column(rows, "tip_z"), label=label)
    speed = [(float(r["tip_vx"]) ** 2 + float(r["tip_vz"]) ** 2) ** 0.5 for r in rows]
    ax2.plot(t, speed, label=label)
ax1.set_xlabel("tip x [m]")
ax1.set_ylabel("tip z [m]")
ax1.set_aspect("equal")
ax1.legend()
ax2.set_xlabel("t [s]")
ax2.set_ylabel("tip speed [m/s]")
ax2.legend()
save_figure(fig, os.path.join(folders[0], "tip.png"), 150)
