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
from plotting import column, plot_before_after_figure, results_folders  # noqa: E402


def plot_length_and_rate(axes, rows, colour, label):
    """(b) the deformed length of the beam, (c) its rate of change (central differences)."""
    t = column(rows, "t")
    length = column(rows, "beam_length")
    rate = [(length[k + 1] - length[k - 1]) / (t[k + 1] - t[k - 1]) for k in range(1, len(t) - 1)]
    axes[0][1].plot(t, length, color=colour, label=label)
    axes[1][0].plot(t[1:-1], rate, color=colour, label=label)


plot_before_after_figure("suspended_beam",
                         results_folders(["results/suspended_beam_rancf", "results/suspended_beam_ancf"]),
                         plot_length_and_rate,
                         [("(b) deformed length of the beam", "t [s]", "length [m]"),
                          ("(c) rate of change of the beam length", "t [s]", "d length/dt [m/s]")])
