#!/usr/bin/env python3
"""Plots semicircular_beam runs like 000 Figure 16, one colour per run (e.g. per element count):
(a) the beam at each length-control event (first run), (b) its deformed length, (c) the
trajectory of the sliding mass, (d) the change of the total energy and the kinetic energy.

Usage: plot.py results/semicircular_beam_8 results/semicircular_beam_16 ...
       (each folder from `semicircular_beam --elements N --out <folder>`; writes
       semicircular_beam.png into the first folder). Needs Debian's python3-matplotlib.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import (centreline, column, decorate_panels, figure_grid, length_control_events,  # noqa: E402
                      length_control_runs, plot_total_and_kinetic_energy, results_folders, save_figure)

folders = results_folders(["results/semicircular_beam"])
fig, axes = figure_grid(2, 2, (11, 8))
for i, (colour, label, rows, shapes) in enumerate(length_control_runs(folders, "semicircular_beam")):
    slider_x, slider_y = column(rows, "slider_x"), column(rows, "slider_y")
    if i == 0:
        for event in length_control_events(shapes):
            axes[0][0].plot(*centreline(shapes, event, 1), color=f"C{event % 10}", lw=0.8)
        axes[0][0].plot(slider_x, slider_y, "k:", lw=0.6, label=f"{label}: the mass")
    axes[0][1].plot(column(rows, "t"), column(rows, "beam_length"), color=colour, label=label)
    axes[1][0].plot(slider_x, slider_y, color=colour, label=label)
    plot_total_and_kinetic_energy(axes[1][1], rows, colour, label, change=True)

titles = [("(a) configurations at the length-control events", "x [m]", "y [m]"),
          ("(b) deformed length of the beam", "t [s]", "length [m]"),
          ("(c) trajectory of the sliding mass", "x [m]", "y [m]"),
          ("(d) total energy change and kinetic energy", "t [s]", "energy [J]")]
decorate_panels(axes, titles)
axes[0][0].set_aspect("equal")
axes[1][0].set_aspect("equal")
save_figure(fig, os.path.join(folders[0], "semicircular_beam.png"), 150)
