#!/usr/bin/env python3
"""Plots a flexible_pendulum run: the tip's path, the rod's bending and the energies.

Usage: plot.py [results/flexible_pendulum]   (reads flexible_pendulum.csv, writes flexible_pendulum.png)
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

folder = sys.argv[1] if len(sys.argv) > 1 else "results/flexible_pendulum"
with open(os.path.join(folder, "flexible_pendulum.csv")) as f:
    rows = list(csv.DictReader(f))


def column(name):
    return [float(r[name]) for r in rows]


t = column("t")
fig, axes = plt.subplots(2, 2, figsize=(10, 8))

ax = axes[0][0]
ax.plot(column("tip_x"), column("tip_z"), "-", color="C0", label="tip")
ax.plot([0], [0], "k+", label="pin")
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("z [m]")
ax.set_title("tip trajectory")
ax.legend(fontsize=8)

ax = axes[0][1]
ax.plot(t, [100 * d for d in column("chord_deflection")], color="C1")  # stored as a fraction, shown in %
ax.set_xlabel("t [s]")
ax.set_ylabel("max distance from the chord / L [%]")
ax.set_title("bending of the rod")

ax = axes[1][0]
ax.plot(t, column("kinetic_energy"), label="kinetic")
ax.plot(t, column("gravity_potential"), label="gravity potential")
ax.plot(t, column("strain_energy"), label="strain")
ax.plot(t, column("total_energy"), "k", label="total")
ax.set_xlabel("t [s]")
ax.set_ylabel("energy [J]")
ax.set_title("energies")
ax.legend(fontsize=8)

plot_energy_balance(axes[1][1], rows)

for a in axes.flat:
    a.grid(True, alpha=0.3)
fig.tight_layout()
out = os.path.join(folder, "flexible_pendulum.png")
fig.savefig(out, dpi=120)
print(f"wrote {out}")
