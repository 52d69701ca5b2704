#!/usr/bin/env python3
"""Plots a heavy_top run: the centre of mass against the RK4 reference, the errors and the energy.

Usage: plot.py [results/heavy_top]   (reads heavy_top.csv, writes heavy_top.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, label_panel, plot_run_with_energy_balance  # noqa: E402


def plot_panels(axes, rows, t):
    """The centre of mass against the RK4 reference (from above and its height), the errors."""
    reference = {"color": "grey", "lw": 3, "alpha": 0.5, "label": "RK4 reference"}

    ax = axes[0][0]
    ax.plot(column(rows, "x_ref"), column(rows, "y_ref"), "-", **reference)
    ax.plot(column(rows, "x"), column(rows, "y"), "-", color="C0", lw=1, label="spar")
    ax.plot([0], [0], "k+", label="fixed point")
    ax.set_aspect("equal")
    label_panel(ax, "centre of mass, seen from above", "x [m]", "y [m]")

    ax = axes[0][1]
    ax.plot(t, column(rows, "z_ref"), "-", **reference)
    ax.plot(t, column(rows, "z"), "-", color="C0", lw=1, label="spar")
    label_panel(ax, "height of the centre of mass (nutation)", "t [s]", "z [m]")

    ax = axes[1][0]
    ax.semilogy(t[1:], column(rows, "rotation_error")[1:], label="rotation |log(R_ref^T R)| [rad]")
    ax.semilogy(t[1:], column(rows, "position_error")[1:], label="centre of mass [m]")
    ax.semilogy(t[1:], column(rows, "omega_error")[1:], label="angular velocity [rad/s]")
    label_panel(ax, "error against the reference", "t [s]")


plot_run_with_energy_balance("heavy_top", plot_panels)
