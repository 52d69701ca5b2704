#!/usr/bin/env python3
"""Plots a heavy_top run: the centre of mass against the RK4 reference, the errors and the energy.

Usage: plot.py [results/heavy_top]   (reads heavy_top.csv, writes heavy_top.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from energy_plot import plot_energy_balance  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else "results/heavy_top"
with open(os.path.join(folder, "heavy_top.csv")) as f:
    rows = list(csv.DictReader(f))


def column(name):
    return [float(r[name]) for r in rows]


t = column("t")
fig, axes = plt.subplots(2, 2, figsize=(10, 8))

ax = axes[0][0]
ax.plot(column("x_ref"), column("y_ref"), "-", color="grey", lw=3, alpha=0.5, label="RK4 reference")
ax.plot(column("x"), column("y"), "-", color="C0", lw=1, label="spar")
ax.plot([0], [0], "k+", label="fixed point")
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_title("centre of mass, seen from above")
ax.legend(fontsize=8)

ax = axes[0][1]
ax.plot(t, column("z_ref"), "-", color="grey", lw=3, alpha=0.5, label="RK4 reference")
ax.plot(t, column("z"), "-", color="C0", lw=1, label="spar")
ax.set_xlabel("t [s]")
ax.set_ylabel("z [m]")
ax.set_title("height of the centre of mass (nutation)")
ax.legend(fontsize=8)

ax = axes[1][0]
ax.semilogy(t[1:], column("rotation_error")[1:], label="rotation |log(R_ref^T R)| [rad]")
ax.semilogy(t[1:], column("position_error")[1:], label="centre of mass [m]")
ax.semilogy(t[1:], column("omega_error")[1:], label="angular velocity [rad/s]")
ax.set_xlabel("t [s]")
ax.set_title("error against the reference")
ax.legend(fontsize=8)

plot_energy_balance(axes[1][1], rows)

for a in axes.flat:
    a.grid(True, alpha=0.3)
fig.tight_layout()
out = os.path.join(folder, "heavy_top.png")
fig.savefig(out, dpi=120)
print(f"wrote {out}")
