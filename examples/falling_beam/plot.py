#!/usr/bin/env python3
"""Plots falling_beam runs side by side like 000 Figures 10–12: (a) the beam just before and after
each length-control event, (b) the Y displacement of the right end, (c) the mass's path, (d) the energies.

Usage: plot.py [results/falling_beam_rancf results/falling_beam_ancf]
       (each folder from `falling_beam --element ... --out <folder>`; writes falling_beam.png
       into the first folder). Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folders = sys.argv[1:] or ["results/falling_beam_rancf", "results/falling_beam_ancf"]


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


fig, axes = plt.subplots(2, 2, figsize=(11, 8))
for i, folder in enumerate(folders):
    label = os.path.basename(os.path.normpath(folder))
    rows = read(os.path.join(folder, "falling_beam.csv"))
    t = [float(r["t"]) for r in rows]
    shapes = read(os.path.join(folder, "falling_beam_shapes.csv"))
    for event in sorted({int(s["event"]) for s in shapes}):
        for phase, style in ((0, "-"), (1, "--")):
            pts = [(float(s["x"]), float(s["y"])) for s in shapes if int(s["event"]) == event and int(s["phase"]) == phase]
            axes[0][0].plot([p[0] for p in pts], [p[1] for p in pts], style, color=f"C{i}",
                            label=f"{label}: before/after LC" if event == 0 and phase == 0 else None)
    axes[0][1].plot(t, [float(r["right_end_y"]) for r in rows], color=f"C{i}", label=label)
    axes[1][0].plot([float(r["mass_x"]) for r in rows], [float(r["mass_y"]) for r in rows], color=f"C{i}", label=label)
    axes[1][1].plot(t, [float(r["total_energy"]) for r in rows], color=f"C{i}", label=f"{label}: total")
    axes[1][1].plot(t, [float(r["kinetic_energy"]) for r in rows], ":", color=f"C{i}", label=f"{label}: kinetic")

titles = [("(a) configurations before (—) and after (--) length control", "x [m]", "y [m]"),
          ("(b) Y displacement of the right end (Figure 10)", "t [s]", "y [m]"),
          ("(c) path of the mass (Figure 11)", "x [m]", "y [m]"),
          ("(d) energies", "t [s]", "energy [J]")]
for ax, (title, xlabel, ylabel) in zip(axes.flat, titles):
    ax.set_title(title, fontsize=9)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
axes[0][0].set_aspect("equal")
fig.tight_layout()
out = os.path.join(folders[0], "falling_beam.png")
fig.savefig(out, dpi=150)
print(out)
