"""What the examples' plot scripts share: finding and reading a run's CSV results, the figure set-up,
panel labelling and saving, the energy-balance panel of the dynamic examples, and the
length-control panels of the sliding-mass examples (falling_beam, suspended_beam, semicircular_beam).

A plot script imports it relative to its own file, so it runs from any directory:

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
    from plotting import column, figure_grid, read_results_csv, results_folder, save_figure

Importing it selects matplotlib's file-only backend (Agg): the scripts run without a display; a
script that needs pyplot itself (3-D panels, colour maps) takes `plt` from here. No plot reads the
HDF5 results: every example also writes the CSV files these functions read.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def results_folder(default):
    """The results folder named by the script's first argument, else `default`."""
    return sys.argv[1] if len(sys.argv) > 1 else default


def results_folders(defaults):
    """The results folders named by the script's arguments (one per run), else `defaults`."""
    return sys.argv[1:] or defaults


def run_label(folder):
    """The legend label of a run: the last component of its results folder."""
    return os.path.basename(os.path.normpath(folder))


def read_results_csv(folder, name):
    """The rows of the CSV file `name` in `folder`, each a dict from column name to text."""
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


def load_results(default, *names):
    """The results folder (results_folder(default)) and the rows of each CSV file `names` in it."""
    folder = results_folder(default)
    return (folder, *(read_results_csv(folder, name) for name in names))


def column(rows, name):
    """The column `name` of CSV rows as floats."""
    return [float(r[name]) for r in rows]


def figure_grid(nrows, ncols, figsize, **kwargs):
    """A new figure with an nrows × ncols grid of panels (plt.subplots; kwargs such as sharex pass on)."""
    return plt.subplots(nrows, ncols, figsize=figsize, **kwargs)


def label_panel(ax, title, xlabel, ylabel=None, legend=True, legend_fontsize=8, **title_style):
    """Gives a panel its title (title_style such as fontsize passes on), axis labels and a light grid,
    and, with legend=True, a legend of the labelled lines."""
    ax.set_title(title, **title_style)
    ax.set_xlabel(xlabel)
    if ylabel is not None:
        ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    if legend:
        ax.legend(fontsize=legend_fontsize)


def save_figure(fig, path, dpi):
    """Lays out the panels, writes the figure to `path` and says so on stdout."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    print(f"wrote {path}")


def plot_energy_balance(ax, rows):
    """The energy-balance panel every dynamic example's plot shows (docs/dynamics.md D8): E - E(0)
    (E = kinetic + strain + gravity, whichever columns the CSV rows have), the work W of the
    external loads and drivers, and the numerical dissipation D = W - (E - E(0))."""
    t = column(rows, "t")
    parts = [c for c in ("kinetic_energy", "strain_energy", "gravity_potential") if c in rows[0]]
    energy = [sum(float(r[c]) for c in parts) for r in rows]
    ax.plot(t, [e - energy[0] for e in energy], label="E - E(0)")
    ax.plot(t, column(rows, "external_work"), "--", label="external work W")
    ax.plot(t, column(rows, "numerical_dissipation"), color="C3", label="numerical dissipation W - (E - E(0))")
    label_panel(ax, "energy balance", "t [s]", "energy [J]")


def plot_run_with_energy_balance(example, plot_panels):
    """The figure of a dynamic example's run (flexible_pendulum, heavy_top, four_bar): reads
    <example>.csv from the folder given on the command line (default results/<example>), lets
    plot_panels(axes, rows, t) draw three panels of a 2 × 2 grid, puts the energy balance in the fourth
    (bottom right) and writes <example>.png into the folder."""
    folder = results_folder(f"results/{example}")
    rows = read_results_csv(folder, f"{example}.csv")
    fig, axes = figure_grid(2, 2, (10, 8))
    plot_panels(axes, rows, column(rows, "t"))
    plot_energy_balance(axes[1][1], rows)
    save_figure(fig, os.path.join(folder, f"{example}.png"), 120)


def length_control_runs(folders, example):
    """Each sliding-mass run's (colour, legend label, rows of <example>.csv, rows of
    <example>_shapes.csv), one colour per results folder (C0, C1, ...)."""
    for i, folder in enumerate(folders):
        yield (f"C{i}", run_label(folder), read_results_csv(folder, f"{example}.csv"),
               read_results_csv(folder, f"{example}_shapes.csv"))


def length_control_events(shapes):
    """The length-control event numbers in the rows of an example's *_shapes.csv, in order."""
    return sorted({int(s["event"]) for s in shapes})


def centreline(shapes, event, phase):
    """The beam's centreline (xs, ys) at a length-control event: phase 0 just before, 1 just after."""
    pts = [(float(s["x"]), float(s["y"])) for s in shapes if int(s["event"]) == event and int(s["phase"]) == phase]
    return [p[0] for p in pts], [p[1] for p in pts]


def plot_centrelines_before_after(ax, shapes, colour, label):
    """One run's centrelines just before (—) and just after (--) every length-control event, in one
    colour, labelled once."""
    for event in length_control_events(shapes):
        for phase, style in ((0, "-"), (1, "--")):
            xs, ys = centreline(shapes, event, phase)
            first = event == 0 and phase == 0
            ax.plot(xs, ys, style, color=colour, label=f"{label}: before/after LC" if first else None)


def plot_total_and_kinetic_energy(ax, rows, colour, label, change=False):
    """One run's total energy (solid; with change=True its change E - E0) and kinetic energy (dotted)."""
    t = column(rows, "t")
    total = column(rows, "total_energy")
    if change:
        ax.plot(t, [e - total[0] for e in total], color=colour, label=f"{label}: E - E0")
    else:
        ax.plot(t, total, color=colour, label=f"{label}: total")
    ax.plot(t, column(rows, "kinetic_energy"), ":", color=colour, label=f"{label}: kinetic")


def decorate_panels(axes, titles):
    """Gives each panel of a grid its (title, x label, y label) in the sliding-mass examples' small
    type, a light grid and a legend."""
    for ax, (title, xlabel, ylabel) in zip(axes.flat, titles):
        label_panel(ax, title, xlabel, ylabel, legend_fontsize=7, fontsize=9)


def plot_before_after_figure(example, folders, plot_middle_panels, middle_titles):
    """The figure of falling_beam and suspended_beam (000 Figures 10-14), one colour per run:
    (a) the centrelines just before and after each length-control event, (b) and (c) drawn by
    plot_middle_panels(axes, rows, colour, label) with their (title, x label, y label) in
    middle_titles, (d) the total and kinetic energies; written to <example>.png in the first folder."""
    fig, axes = figure_grid(2, 2, (11, 8))
    for colour, label, rows, shapes in length_control_runs(folders, example):
        plot_centrelines_before_after(axes[0][0], shapes, colour, label)
        plot_middle_panels(axes, rows, colour, label)
        plot_total_and_kinetic_energy(axes[1][1], rows, colour, label)
    decorate_panels(axes, [("(a) configurations before (—) and after (--) length control", "x [m]", "y [m]"),
                           *middle_titles, ("(d) energies", "t [s]", "energy [J]")])
    axes[0][0].set_aspect("equal")
    save_figure(fig, os.path.join(folders[0], f"{example}.png"), 150)
