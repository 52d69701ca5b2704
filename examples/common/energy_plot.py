"""The energy-balance panel every dynamic example's plot shows (docs/dynamics.md D8).

    from energy_plot import plot_energy_balance
    plot_energy_balance(ax, rows)   # rows: csv.DictReader rows with t and the balance columns

Plots E - E(0) (E = kinetic + strain + gravity, whichever columns the CSV has), the work of the
external loads and drivers, and the numerical dissipation D = W - (E - E(0)).
"""


def plot_energy_balance(ax, rows):
    t = [float(r["t"]) for r in rows]
    parts = [c for c in ("kinetic_energy", "strain_energy", "gravity_potential") if c in rows[0]]
    energy = [sum(float(r[c]) for c in parts) for r in rows]
    ax.plot(t, [e - energy[0] for e in energy], label="E - E(0)")
    ax.plot(t, [float(r["external_work"]) for r in rows], "--", label="external work W")
    ax.plot(t, [float(r["numerical_dissipation"]) for r in rows], color="C3",
            label="numerical dissipation W - (E - E(0))")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("energy [J]")
    ax.set_title("energy balance")
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
