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
from plotting import column, plot_before_after_figure, results_folders  # noqa: E402


def plot_right_end_and_mass(axes, rows, colour, label):
    """(b) the Y displacement of the right end, (c) the path of the mass."""
    axes[0][1].plot(column(rows, "t"), column(rows, "right_end_y"), color=colour, label=label)
    axes[1][0].plot(column(rows, "mass_x"), column(rows, "mass_y"), color=colour, label=label)


plot_before_after_figure("falling_beam", results_folders(["results/falling_beam_rancf", "results/falling_beam_ancf"]),
                         plot_right_end_and_mass,
                         [("(b) Y displacement of the right end (Figure 10)", "t [s]", "y [m]"),
                          ("(c) path of the mass (Figure 11)", "x [m]", "y [m]")])
