#!/usr/bin/env python3
"""Plots the truss_deployment runs beside 003's Figures 7-12.

Usage: plot.py [results/truss_deployment]
Reads, where present, the run folders case1, case2_<law> (the four laws) and case2_linear_10
(--elements 10) and writes into the results folder:
  truss_geometry.png   the folded, half-deployed and deployed unit (case2_cosine's snapshots),
                       members by kind, joints marked (README, "Geometry")
  truss_case1.png      X of D in case 1 (003 Figure 8)
  truss_laws.png       X and Z of D for the four laws, Z after t_f magnified (003 Figures 10-12)
  truss_convergence.png  X of D with 4 and 10 elements per member, linear law (003 Figure 9)
Needs Debian's python3-matplotlib (installed by scripts/setup.sh).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from plotting import column, plt, read_results_csv, results_folder  # noqa: E402

root = results_folder("results/truss_deployment")
laws = ["linear", "polynomial", "cycloid", "cosine"]
kinds = {0: ("frame rod", "tab:gray"), 1: ("cross-bar", "tab:blue"),
         2: ("side diagonal (slides)", "tab:red"), 3: ("top/bottom diagonal", "tab:green")}


def history(folder):
    run = os.path.join(root, folder)
    if not os.path.exists(os.path.join(run, "truss_deployment.csv")):
        return None
    rows = read_results_csv(run, "truss_deployment.csv")
    return {name: column(rows, name) for name in rows[0]}


def snapshots(folder):
    run = os.path.join(root, folder)
    if not os.path.exists(os.path.join(run, "truss_snapshots.csv")):
        return {}
    shapes = {}
    for r in read_results_csv(run, "truss_snapshots.csv"):
        member = shapes.setdefault(float(r["t"]), {}).setdefault(int(r["member"]), [int(r["kind"]), [], [], []])
        for k, axis in enumerate("xyz"):
            member[k + 1].append(float(r[axis]))
    return shapes


def d_at(run, t):
    """D's position in `run` at the recorded time nearest t."""
    i = min(range(len(run["t"])), key=lambda k: abs(run["t"][k] - t))
    return run["d_x"][i], run["d_y"][i], run["d_z"][i]


# The geometry: three states of the cosine run, members coloured by kind.
shapes, cosine = snapshots("case2_cosine"), history("case2_cosine")
if shapes:
    times = sorted(shapes)
    picked = [times[0], times[len(times) // 2 - 1] if len(times) > 2 else times[0], times[-1]]
    titles = ["folded (t = 0, beta = 5 deg)", "half-deployed (t = t_f/2)", "deployed and locked (t = 30 s)"]
    fig = plt.figure(figsize=(16, 5.5))
    for i, (t, title) in enumerate(zip(picked, titles)):
        ax = fig.add_subplot(1, 3, i + 1, projection="3d")
        seen = set()
        for member, (kind, xs, ys, zs) in sorted(shapes[t].items()):
            label, colour = kinds[kind]
            ax.plot(xs, ys, zs, color=colour, lw=2, label=None if kind in seen else label)
            seen.add(kind)
            if kind == 2:  # the sliding end of a side diagonal
                ax.scatter([xs[-1]], [ys[-1]], [zs[-1]], color="tab:red", marker="s", s=30)
        d = d_at(cosine, t)
        ax.scatter(*[[c] for c in d], color="k", marker="*", s=120, label="D" if i == 0 else None)
        ax.set_title(f"{title}")
        ax.set_xlabel("X [m]")
        ax.set_ylabel("Y [m]")
        ax.set_zlabel("Z [m]")
        ax.set_xlim(-0.5, 8.5)  # one scale for the three states: metres look alike
        ax.set_ylim(-0.5, 2.5)
        ax.set_zlim(-0.5, 6.5)
        ax.set_box_aspect((9, 3, 7))
        ax.view_init(elev=18, azim=-60)
        if i == 0:
            ax.legend(loc="upper left", fontsize=8)
    fig.suptitle("deployable truss unit (003 section 5.3): frame 0 fixed; squares = sliders on the next frame's rods")
    fig.tight_layout()
    fig.savefig(os.path.join(root, "truss_geometry.png"), dpi=110)

# Case 1: X of D under gravity 0.005 g (003 Figure 8).
case1 = history("case1")
if case1:
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(case1["t"], case1["d_x"], label="spar, 1 element per member, h = 0.1 s")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("X of D [m]")
    ax.set_title("case 1: deployment under 0.005 g along X (003 Figure 8)")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(root, "truss_case1.png"), dpi=110)

# Case 2: the four laws (003 Figures 10-12).
runs = {law: history("case2_" + law) for law in laws}
runs = {law: run for law, run in runs.items() if run}
if runs:
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.8))
    for law, run in runs.items():
        axes[0].plot(run["t"], run["d_x"], label=law)
        axes[1].plot(run["t"], run["d_z"], label=law)
        after = [i for i, t in enumerate(run["t"]) if t >= 19.0]
        axes[2].plot([run["t"][i] for i in after], [1e3 * (run["d_z"][i] - 2.0) for i in after], label=law)
    axes[0].set_ylabel("X of D [m]")
    axes[1].set_ylabel("Z of D [m]")
    axes[2].set_ylabel("Z of D - 2 m [mm]")
    axes[2].set_ylim(-0.2, 0.2)
    for ax, title in zip(axes, ["X of D (003 Figure 10)", "Z of D (003 Figure 11)",
                                "Z of D after deployment, magnified (003 Figure 12)"]):
        ax.set_xlabel("t [s]")
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(root, "truss_laws.png"), dpi=110)

# Convergence: 4 against 10 elements per member, linear law (003 Figure 9).
coarse, fine = history("case2_linear"), history("case2_linear_10")
if coarse and fine:
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    axes[0].plot(coarse["t"], coarse["d_x"], label="4 elements per member")
    axes[0].plot(fine["t"], fine["d_x"], "--", label="10 elements per member")
    axes[0].set_ylabel("X of D [m]")
    n = min(len(coarse["t"]), len(fine["t"]))
    axes[1].plot(coarse["t"][:n], [1e3 * (fine["d_x"][i] - coarse["d_x"][i]) for i in range(n)])
    axes[1].set_ylabel("X of D, 10 minus 4 elements [mm]")
    for ax in axes:
        ax.set_xlabel("t [s]")
        ax.grid(alpha=0.3)
    axes[0].legend()
    axes[0].set_title("linear law: X of D (003 Figure 9)")
    fig.tight_layout()
    fig.savefig(os.path.join(root, "truss_convergence.png"), dpi=110)
print("plots written to", root)
