#!/usr/bin/env python3
"""Plots suspended_beam runs side by side like 000 Figure 14: (a) the beam just before and after
each length-control event, (b) the deformed beam length, (c) its rate of change, (d) the energies.

Usage: plot.py [results/suspended_beam_rancf results/suspended_beam_ancf]
       (each folder from `suspended_beam --element ... --out <folder>`; writes suspended_beam.png
       into the first folder). Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import (column, decorate_panels, figure_grid, length_control_runs,  # noqa: E402
                      plot_centrelines_before_after, plot_total_and_kinetic_energy, results_folders, save_figure)

folders = results_folders(["results/suspended_beam_rancf", "results/suspended_beam_ancf"])
fig, axes = figure_grid(2, 2, (11, 8))
for colour, label, rows, shapes in length_control_runs(folders, "suspended_beam"):
    t = column(rows, "t")
    length = column(rows, "beam_length")
    rate = [(length[k + 1] - length[k - 1]) / (t[k + 1] - t[k - 1]) for k in range(1, len(t) - 1)]
    plot_centrelines_before_after(axes[0][0], shapes, colour, label)
    axes[0][1].plot(t, length, color=colour, label=label)
    axes[1][0].plot(t[1:-1], rate, color=colour, label=label)
    plot_total_and_kinetic_energy(axes[1][1], rows, colour, label)

titles = [("(a) configurations before (—) and after (--) length control", "x [m]", "y [m]"),
          ("(b) deformed length of the beam", "t [s]", "length [m]"),
          ("(c) rate of change of the beam length", "t [s]", "d length/dt [m/s]"),
          ("(d) energies", "t [s]", "energy [J]")]
decorate_panels(axes, titles)
axes[0][0].set_aspect("equal")
save_figure(fig, os.path.join(folders[0], "suspended_beam.png"), 150)
