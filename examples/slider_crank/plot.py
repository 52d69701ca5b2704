#!/usr/bin/env python3
"""Plots Rod II's deformation rate, Rod I's angular speed and the energy balance from slider_crank's CSV.

Usage: plot.py [results/slider_crank]   (reads slider_crank.csv, writes slider_crank.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, figure_grid, load_results, plot_energy_balance, save_figure  # noqa: E402

folder, rows = load_results("results/slider_crank", "slider_crank.csv")
t = column(rows, "t")
rate = [100 * r for r in column(rows, "rod2_deformation_rate")]  # stored as a fraction (unit 1), shown in %
speed = column(rows, "rod1_angular_speed")

fig, (top, bottom, balance) = figure_grid(3, 1, (6, 8.5), sharex=True)
top.plot(t, rate, color="C0")
top.axhline(5.0, color="grey", ls="--", lw=0.8, label="5 % (003, Fig. 3)")
top.set_ylabel("Rod II deformation rate [%]")
top.legend(loc="upper left")
top.grid(True, alpha=0.3)
bottom.plot(t, speed, color="C1")
bottom.axhline(320.0, color="grey", ls="--", lw=0.8, label="320 rad/s (003)")
bottom.set_ylabel("Rod I angular speed [rad/s]")
bottom.legend(loc="upper left")
bottom.grid(True, alpha=0.3)
plot_energy_balance(balance, rows)
save_figure(fig, os.path.join(folder, "slider_crank.png"), 120)
