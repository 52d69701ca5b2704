#!/usr/bin/env python3
"""Plots the deflection line written by ancf_cantilever beside Euler-Bernoulli theory.

Usage: plot.py [results/ancf_cantilever]   (reads centerline.csv, writes deflection.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, figure_grid, load_results, save_figure  # noqa: E402

folder, rows = load_results("results/ancf_cantilever", "centerline.csv")
x = column(rows, "x")
y = [1e3 * v for v in column(rows, "y")]
s = column(rows, "s")
theory = [1e3 * v for v in column(rows, "euler_bernoulli_y")]

fig, ax = figure_grid(1, 1, (6, 4))
ax.plot(s, theory, "--", color="grey", label="Euler-Bernoulli F L^3/(3EI)")
ax.plot(x, y, "-", color="C0", label="ANCF")
ax.set_xlabel("x [m]")
ax.set_ylabel("deflection [mm]")
ax.legend()
save_figure(fig, os.path.join(folder, "deflection.png"), 150)
