#pragma once
// The warning a static example prints when its converged state is not stable
// (StaticReport::unstable_directions, docs/errors.md).
#include <spar/solvers/static_solver.hpp>

#include <cstdio>

namespace spar::examples {

/// Prints a warning on stderr when the static state is an unstable equilibrium (the straight
/// branch of a column above its Euler load, say), or when its stability was not assessed.
inline void warn_if_unstable(const solvers::StaticReport& report) {
  if (report.unstable_directions > 0)
    std::fprintf(stderr,
                 "warning: the static state is unstable: the tangent stiffness has %d negative "
                 "eigenvalue(s) on the constraints' null space; a real structure leaves this "
                 "equilibrium (buckles). Perturb the load or the geometry to follow a stable branch.\n",
                 report.unstable_directions);
  else if (report.unstable_directions < 0)
    std::fprintf(stderr, "note: the stability of the static state was not assessed (a non-symmetric "
                         "or singular tangent)\n");
}

}  // namespace spar::examples
