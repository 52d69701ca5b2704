#!/usr/bin/env python3
"""Plots Rod II's deformation rate, Rod I's angular speed and the energy balance from slider_crank's CSV.

Usage: plot.py [results/slider_crank]   (reads slider_crank.csv, writes slider_crank.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from energy_plot import plot_energy_balance  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else "results/slider_crank"
with open(os.path.join(folder, "slider_crank.csv")) as f:
    rows = list(csv.DictReader(f))
t = [float(r["t"]) for r in rows]
rate = [100 * float(r["rod2_deformation_rate"]) for r in rows]  # stored as a fraction (unit 1), shown in %
speed = [float(r["rod1_angular_speed"]) for r in rows]

fig, (top, bottom, balance) = plt.subplots(3, 1, figsize=(6, 8.5), sharex=True)
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
fig.tight_layout()
out = os.path.join(folder, "slider_crank.png")
fig.savefig(out, dpi=120)
print(f"wrote {out}")
