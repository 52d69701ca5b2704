#!/usr/bin/env python3
"""Plots a four_bar run: the rocker against the rigid four-bar, the error, the energy balance.

Usage: plot.py [results/four_bar]   (reads four_bar.csv, writes four_bar.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from energy_plot import plot_energy_balance  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else "results/four_bar"
with open(os.path.join(folder, "four_bar.csv")) as f:
    rows = list(csv.DictReader(f))


def column(name):
    return [float(r[name]) for r in rows]


t = column("t")
fig, axes = plt.subplots(2, 2, figsize=(10, 8))

ax = axes[0][0]
ax.plot(t, [math.degrees(a) for a in column("rocker_angle")], color="C0", label="flexible rocker (chord)")
ax.plot(t, [math.degrees(a) for a in column("rigid_rocker_angle")], "k--", lw=0.8, label="rigid four-bar")
ax.set_xlabel("t [s]")
ax.set_ylabel("rocker angle [deg]")
ax.set_title("rocker angle")
ax.legend(fontsize=8)

ax = axes[0][1]
ax.plot(t, [1e6 * e for e in column("rocker_angle_error")], color="C1")  # stored in rad, shown in µrad
ax.set_xlabel("t [s]")
ax.set_ylabel("flexible - rigid [µrad]")
ax.set_title("rocker angle against the rigid four-bar")

ax = axes[1][0]
ax.plot(t, column("kinetic_energy"), label="kinetic")
ax.plot(t, column("gravity_potential"), label="gravity potential")
ax.plot(t, [1e3 * s for s in column("strain_energy")], label="strain × 1000")
ax.set_xlabel("t [s]")
ax.set_ylabel("energy [J]")
ax.set_title("energies")
ax.legend(fontsize=8)

plot_energy_balance(axes[1][1], rows)

for a in axes.flat:
    a.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(folder, "four_bar.png"), dpi=120)
print("wrote", os.path.join(folder, "four_bar.png"))
