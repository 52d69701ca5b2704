#!/usr/bin/env python3
"""Plots the path of the free end B, the energies and the constraint residual of ancf_double_pendulum.

Usage: plot.py [results/ancf_double_pendulum]   (reads ancf_double_pendulum.csv, writes double_pendulum.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else "results/ancf_double_pendulum"
with open(os.path.join(folder, "ancf_double_pendulum.csv")) as f:
    rows = list(csv.DictReader(f))
t = [float(r["t"]) for r in rows]
fig = plt.figure(figsize=(12, 4.5))
ax = fig.add_subplot(1, 3, 1, projection="3d")
ax.plot([float(r["B_x"]) for r in rows], [float(r["B_y"]) for r in rows], [float(r["B_z"]) for r in rows], label="B")
ax.plot([float(r["A_x"]) for r in rows], [float(r["A_y"]) for r in rows], [float(r["A_z"]) for r in rows], label="A")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_zlabel("z [m]")
ax.legend()
ax2 = fig.add_subplot(1, 3, 2)
for name in ("kinetic_energy", "strain_energy", "gravity_potential", "total_energy"):
    ax2.plot(t, [float(r[name]) for r in rows], label=name.replace("_", " "))
ax2.set_xlabel("t [s]")
ax2.set_ylabel("energy [J]")
ax2.legend()
ax3 = fig.add_subplot(1, 3, 3)
ax3.semilogy(t, [max(float(r["constraint_residual"]), 1e-20) for r in rows])
ax3.set_xlabel("t [s]")
ax3.set_ylabel("constraint residual [m]")
fig.tight_layout()
fig.savefig(os.path.join(folder, "double_pendulum.png"), dpi=150)
print("wrote", os.path.join(folder, "double_pendulum.png"))
