#!/usr/bin/env python3
"""Plots a flexible_pendulum run: the tip's path, the rod's bending and the energies.

Usage: plot.py [results/flexible_pendulum]   (reads flexible_pendulum.csv, writes flexible_pendulum.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, label_panel, plot_run_with_energy_balance  # noqa: E402


def plot_panels(axes, rows, t):
    """The tip's path, the rod's bending and the energies."""
    ax = axes[0][0]
    ax.plot(column(rows, "tip_x"), column(rows, "tip_z"), "-", color="C0", label="tip")
    ax.plot([0], [0], "k+", label="pin")
    ax.set_aspect("equal")
    label_panel(ax, "tip trajectory", "x [m]", "z [m]")

    ax = axes[0][1]
    ax.plot(t, [100 * d for d in column(rows, "chord_deflection")], color="C1")  # stored as a fraction, shown in %
    label_panel(ax, "bending of the rod", "t [s]", "max distance from the chord / L [%]", legend=False)

    ax = axes[1][0]
    ax.plot(t, column(rows, "kinetic_energy"), label="kinetic")
    ax.plot(t, column(rows, "gravity_potential"), label="gravity potential")
    ax.plot(t, column(rows, "strain_energy"), label="strain")
    ax.plot(t, column(rows, "total_energy"), "k", label="total")
    label_panel(ax, "energies", "t [s]", "energy [J]")


plot_run_with_energy_balance("flexible_pendulum", plot_panels)
