#!/usr/bin/env python3
"""Plots the tip trajectory and velocity of ancf_pendulum runs beside each other.

Usage: plot.py folder [folder ...]   (reads ancf_pendulum.csv from each, writes tip.png in the first)
Example: plot.py results/ancf_pendulum results/ancf_pendulum_gebt
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folders = sys.argv[1:] or ["results/ancf_pendulum"]
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
for folder in folders:
    with open(os.path.join(folder, "ancf_pendulum.csv")) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["t"]) for r in rows]
    label = os.path.basename(os.path.normpath(folder))
    ax1.plot([float(r["tip_x"]) for r in rows], [float(r["tip_z"]) for r in rows], label=label)
    speed = [(float(r["tip_vx"]) ** 2 + float(r["tip_vz"]) ** 2) ** 0.5 for r in rows]
    ax2.plot(t, speed, label=label)
ax1.set_xlabel("tip x [m]")
ax1.set_ylabel("tip z [m]")
ax1.set_aspect("equal")
ax1.legend()
ax2.set_xlabel("t [s]")
ax2.set_ylabel("tip speed [m/s]")
ax2.legend()
fig.tight_layout()
fig.savefig(os.path.join(folders[0], "tip.png"), dpi=150)
print("wrote", os.path.join(folders[0], "tip.png"))
