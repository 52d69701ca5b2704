#!/usr/bin/env python3
"""Plots suspended_beam runs side by side like 000 Figure 14: (a) the beam just before and after
each length-control event, (b) the deformed beam length, (c) its rate of change, (d) the energies.

Usage: plot.py [results/suspended_beam_rancf results/suspended_beam_ancf]
       (each folder from `suspended_beam --element ... --out <folder>`; writes suspended_beam.png
       into the first folder). Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folders = sys.argv[1:] or ["results/suspended_beam_rancf", "results/suspended_beam_ancf"]


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


fig, axes = plt.subplots(2, 2, figsize=(11, 8))
for i, folder in enumerate(folders):
    label = os.path.basename(os.path.normpath(folder))
    rows = read(os.path.join(folder, "suspended_beam.csv"))
    t = [float(r["t"]) for r in rows]
    length = [float(r["beam_length"]) for r in rows]
    rate = [(length[k + 1] - length[k - 1]) / (t[k + 1] - t[k - 1]) for k in range(1, len(t) - 1)]
    shapes = read(os.path.join(folder, "suspended_beam_shapes.csv"))
    for event in sorted({int(s["event"]) for s in shapes}):
        for phase, style in ((0, "-"), (1, "--")):
            pts = [(float(s["x"]), float(s["y"])) for s in shapes if int(s["event"]) == event and int(s["phase"]) == phase]
            axes[0][0].plot([p[0] for p in pts], [p[1] for p in pts], style, color=f"C{i}",
                            label=f"{label}: before/after LC" if event == 0 and phase == 0 else None)
    axes[0][1].plot(t, length, color=f"C{i}", label=label)
    axes[1][0].plot(t[1:-1], rate, color=f"C{i}", label=label)
    axes[1][1].plot(t, [float(r["total_energy"]) for r in rows], color=f"C{i}", label=f"{label}: total")
    axes[1][1].plot(t, [float(r["kinetic_energy"]) for r in rows], ":", color=f"C{i}", label=f"{label}: kinetic")

titles = [("(a) configurations before (—) and after (--) length control", "x [m]", "y [m]"),
          ("(b) deformed length of the beam", "t [s]", "length [m]"),
          ("(c) rate of change of the beam length", "t [s]", "d length/dt [m/s]"),
          ("(d) energies", "t [s]", "energy [J]")]
for ax, (title, xlabel, ylabel) in zip(axes.flat, titles):
    ax.set_title(title, fontsize=9)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
axes[0][0].set_aspect("equal")
fig.tight_layout()
out = os.path.join(folders[0], "suspended_beam.png")
fig.savefig(out, dpi=150)
print(out)
