#pragma once
// 003's Newton test as the examples read it from the command line (docs/dynamics.md D4).
#include <cli.hpp>

#include <cmath>

namespace spar::examples {

/// The three tests of a Newton iteration (solvers::DynamicOptions).
struct NewtonTest {
  double tolerance;             ///< ‖[Δq, h²βΔλ]‖² (003 §5.1: 1e-6)
  double constraint_tolerance;  ///< ‖Φ‖∞ [m]
  double residual_tolerance;    ///< the dynamic residual relative to its terms; +∞: untested
};

/// --tolerance, --constraint-tolerance and --residual-tolerance; by default 003's test: the
/// increment at 1e-6, Φ at 1e-10 m, the residual untested (or tested at `residual_tolerance`).
inline NewtonTest newton_test_options(CommandLine& cli, double residual_tolerance = INFINITY) {
  return {.tolerance = cli.number("--tolerance", 1e-6, "Newton: |[dq, h^2 beta dlambda]|^2 (003: 1e-6)",
                                  newton_tolerances),
          .constraint_tolerance = cli.number("--constraint-tolerance", 1e-10, "Newton: |Phi|_inf [m]",
                                             newton_tolerances),
          .residual_tolerance = cli.number("--residual-tolerance", residual_tolerance,
                                           "Newton: relative dynamic residual (inf: off, 003's test)",
                                           Range::positive(1))};
}

}  // namespace spar::examples
