#!/usr/bin/env python3
"""Plots the path of the free end B, the energies and the constraint residual of ancf_double_pendulum.

Usage: plot.py [results/ancf_double_pendulum]   (reads ancf_double_pendulum.csv, writes double_pendulum.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, load_results, plt, save_figure  # noqa: E402

folder, rows = load_results("results/ancf_double_pendulum", "ancf_double_pendulum.csv")
t = column(rows, "t")
fig = plt.figure(figsize=(12, 4.5))
ax = fig.add_subplot(1, 3, 1, projection="3d")
ax.plot(column(rows, "B_x"), column(rows, "B_y"), column(rows, "B_z"), label="B")
ax.plot(column(rows, "A_x"), column(rows, "A_y"), column(rows, "A_z"), label="A")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_zlabel("z [m]")
ax.legend()
ax2 = fig.add_subplot(1, 3, 2)
for name in ("kinetic_energy", "strain_energy", "gravity_potential", "total_energy"):
    ax2.plot(t, column(rows, name), label=name.replace("_", " "))
ax2.set_xlabel("t [s]")
ax2.set_ylabel("energy [J]")
ax2.legend()
ax3 = fig.add_subplot(1, 3, 3)
ax3.semilogy(t, [max(v, 1e-20) for v in column(rows, "constraint_residual")])
ax3.set_xlabel("t [s]")
ax3.set_ylabel("constraint residual [m]")
save_figure(fig, os.path.join(folder, "double_pendulum.png"), 150)
