#!/usr/bin/env python3
"""Plots a four_bar run: the rocker against the rigid four-bar, the error, the energy balance.

Usage: plot.py [results/four_bar]   (reads four_bar.csv, writes four_bar.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, label_panel, plot_run_with_energy_balance  # noqa: E402


def plot_panels(axes, rows, t):
    """The rocker angle against the rigid four-bar, their difference and the energies."""
    ax = axes[0][0]
    ax.plot(t, [math.degrees(a) for a in column(rows, "rocker_angle")], color="C0", label="flexible rocker (chord)")
    ax.plot(t, [math.degrees(a) for a in column(rows, "rigid_rocker_angle")], "k--", lw=0.8, label="rigid four-bar")
    label_panel(ax, "rocker angle", "t [s]", "rocker angle [deg]")

    ax = axes[0][1]
    ax.plot(t, [1e6 * e for e in column(rows, "rocker_angle_error")], color="C1")  # stored in rad, shown in µrad
    label_panel(ax, "rocker angle against the rigid four-bar", "t [s]", "flexible - rigid [µrad]", legend=False)

    ax = axes[1][0]
    ax.plot(t, column(rows, "kinetic_energy"), label="kinetic")
    ax.plot(t, column(rows, "gravity_potential"), label="gravity potential")
    ax.plot(t, [1e3 * s for s in column(rows, "strain_energy")], label="strain × 1000")
    label_panel(ax, "energies", "t [s]", "energy [J]")


plot_run_with_energy_balance("four_bar", plot_panels)
