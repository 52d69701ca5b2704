#!/usr/bin/python3
"""Where a dynamic run's instructions go, per Newton iteration (docs/performance.md).

    valgrind --tool=callgrind --callgrind-out-file=run.cg <program> ...
    scripts/iteration_breakdown.py run.cg NEWTON_ITERATIONS [LABEL]

Reads the inclusive costs of callgrind_annotate and prints one Markdown table row of
instructions per Newton iteration: element kernels (every Element::evaluate), constraints,
assembly and scatter (the rest of the system's evaluation), factorization, back-substitution,
the integrator's bookkeeping (the rest of its steps), output (the rest of main after the model is
built and the integrator has stepped) and the total.
"""
import re
import subprocess
import sys


def inclusive_costs(path):
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", path],
                          capture_output=True, text=True, check=True).stdout
    costs = {}
    for line in text.splitlines():
        match = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+(?:\S*?:)?(.*?)(?: \[.*\])?$", line)
        if match:
            name = match.group(2)
            costs[name] = costs.get(name, 0) + int(match.group(1).replace(",", ""))
    return costs


def total(costs, pattern):
    """The summed inclusive cost of the functions matching `pattern` (none nested in another)."""
    return sum(cost for name, cost in costs.items() if re.search(pattern, name))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    costs = inclusive_costs(sys.argv[1])
    iterations = int(sys.argv[2])
    label = sys.argv[3] if len(sys.argv) > 3 else sys.argv[1]
    program = total(costs, r"^main$")
    elements = total(costs, r"^spar::core::\w*Element::evaluate\(")
    constraints = total(costs, r"^spar::solvers::detail::SystemAssembly::compute_constraint\(")
    system = (total(costs, r"^spar::solvers::detail::SystemAssembly::evaluate\(")
              + total(costs, r"^spar::solvers::detail::SystemAssembly::evaluate_constraints_and_loads\(")
              + total(costs, r"^spar::solvers::detail::SystemAssembly::freeze\("))
    factorization = total(costs, r"^spar::solvers::GeneralizedAlpha::Implementation::factorize\(")
    solve = total(costs, r"^spar::solvers::LinearSolver::solve\(")
    integrator = (total(costs, r"^spar::solvers::GeneralizedAlpha::step\(\)")
                  + total(costs, r"^spar::solvers::GeneralizedAlpha::initialize\(\)")
                  + total(costs, r"^spar::solvers::GeneralizedAlpha::energies\(\) const"))
    # Building the model and the integrator (its symbolic analysis included), and tearing down.
    model = total(costs, r"build_slider_crank|^spar::solvers::GeneralizedAlpha::(~?GeneralizedAlpha)\(")
    rows = {
        "element kernels": elements,
        "constraints": constraints,
        "assembly, scatter": system - elements - constraints,
        "factorization": factorization,
        "back-substitution": solve,
        "bookkeeping": integrator - system - factorization - solve,
        "output": max(0, program - integrator - model),
        "total": max(program - model, integrator),
    }
    print("| run | " + " | ".join(rows) + " |")
    print("| --- |" + " --- |" * len(rows))
    print(f"| {label} | " + " | ".join(f"{cost / iterations / 1e3:.0f} k" for cost in rows.values()) + " |")


if __name__ == "__main__":
    main()
