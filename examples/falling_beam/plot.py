#!/usr/bin/env python3
"""Plots falling_beam runs side by side like 000 Figures 10–12: (a) the beam just before and after
each length-control event, (b) the Y displacement of the right end, (c) the mass's path, (d) the energies.

Usage: plot.py [results/falling_beam_rancf results/falling_beam_ancf]
       (each folder from `falling_beam --element ... --out <folder>`; writes falling_beam.png
       into the first folder). Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import (column, decorate_panels, figure_grid, length_control_runs,  # noqa: E402
                      plot_centrelines_before_after, plot_total_and_kinetic_energy, results_folders, save_figure)

folders = results_folders(["results/falling_beam_rancf", "results/falling_beam_ancf"])
fig, axes = figure_grid(2, 2, (11, 8))
for colour, label, rows, shapes in length_control_runs(folders, "falling_beam"):
    t = column(rows, "t")
    plot_centrelines_before_after(axes[0][0], shapes, colour, label)
    axes[0][1].plot(t, column(rows, "right_end_y"), color=colour, label=label)
    axes[1][0].plot(column(rows, "mass_x"), column(rows, "mass_y"), color=colour, label=label)
    plot_total_and_kinetic_energy(axes[1][1], rows, colour, label)

titles = [("(a) configurations before (—) and after (--) length control", "x [m]", "y [m]"),
          ("(b) Y displacement of the right end (Figure 10)", "t [s]", "y [m]"),
          ("(c) path of the mass (Figure 11)", "x [m]", "y [m]"),
          ("(d) energies", "t [s]", "energy [J]")]
decorate_panels(axes, titles)
axes[0][0].set_aspect("equal")
save_figure(fig, os.path.join(folders[0], "falling_beam.png"), 150)
