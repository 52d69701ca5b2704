#!/usr/bin/env python3
"""Plots the deflection line written by ancf_cantilever beside Euler-Bernoulli theory.

Usage: plot.py [results/ancf_cantilever]   (reads centerline.csv, writes deflection.png)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else "results/ancf_cantilever"
with open(os.path.join(folder, "centerline.csv")) as f:
    rows = list(csv.DictReader(f))
x = [float(r["x"]) for r in rows]
y = [1e3 * float(r["y"]) for r in rows]
s = [float(r["s"]) for r in rows]
theory = [1e3 * float(r["euler_bernoulli_y"]) for r in rows]

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(s, theory, "--", color="grey", label="Euler-Bernoulli F L^3/(3EI)")
ax.plot(x, y, "-", color="C0", label="ANCF")
ax.set_xlabel("x [m]")
ax.set_ylabel("deflection [mm]")
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(folder, "deflection.png"), dpi=150)
print("wrote", os.path.join(folder, "deflection.png"))
