#!/usr/bin/env python3
"""Plots semicircular_beam runs like 000 Figure 16, one colour per run (e.g. per element count):
(a) the beam at each length-control event (first run), (b) its deformed length, (c) the
trajectory of the sliding mass, (d) the change of the total energy and the kinetic energy.

Usage: plot.py results/semicircular_beam_8 results/semicircular_beam_16 ...
       (each folder from `semicircular_beam --elements N --out <folder>`; writes
       semicircular_beam.png into the first folder). Needs Debian's python3-matplotlib.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folders = sys.argv[1:] or ["results/semicircular_beam"]


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


fig, axes = plt.subplots(2, 2, figsize=(11, 8))
for i, folder in enumerate(folders):
    label = os.path.basename(os.path.normpath(folder))
    rows = read(os.path.join(folder, "semicircular_beam.csv"))
    t = [float(r["t"]) for r in rows]
    if i == 0:
        shapes = read(os.path.join(folder, "semicircular_beam_shapes.csv"))
        for event in sorted({int(s["event"]) for s in shapes}):
            pts = [(float(s["x"]), float(s["y"])) for s in shapes if int(s["event"]) == event and int(s["phase"]) == 1]
            axes[0][0].plot([p[0] for p in pts], [p[1] for p in pts], color=f"C{event % 10}", lw=0.8)
        axes[0][0].plot([float(r["slider_x"]) for r in rows], [float(r["slider_y"]) for r in rows], "k:", lw=0.6,
                        label=f"{label}: the mass")
    axes[0][1].plot(t, [float(r["beam_length"]) for r in rows], color=f"C{i}", label=label)
    axes[1][0].plot([float(r["slider_x"]) for r in rows], [float(r["slider_y"]) for r in rows], color=f"C{i}",
                    label=label)
    e0 = float(rows[0]["total_energy"])
    axes[1][1].plot(t, [float(r["total_energy"]) - e0 for r in rows], color=f"C{i}", label=f"{label}: E - E0")
    axes[1][1].plot(t, [float(r["kinetic_energy"]) for r in rows], ":", color=f"C{i}", label=f"{label}: kinetic")

titles = [("(a) configurations at the length-control events", "x [m]", "y [m]"),
          ("(b) deformed length of the beam", "t [s]", "length [m]"),
          ("(c) trajectory of the sliding mass", "x [m]", "y [m]"),
          ("(d) total energy change and kinetic energy", "t [s]", "energy [J]")]
for ax, (title, xlabel, ylabel) in zip(axes.flat, titles):
    ax.set_title(title, fontsize=9)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
axes[0][0].set_aspect("equal")
axes[1][0].set_aspect("equal")
fig.tight_layout()
out = os.path.join(folders[0], "semicircular_beam.png")
fig.savefig(out, dpi=150)
print(out)
