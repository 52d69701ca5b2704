#pragma once
/// \file
/// The warning a static study prints when its converged state is not stable
/// (solvers::StaticReport::unstable_directions, docs/errors.md).

#include <spar/solvers/static_solver.hpp>

namespace spar::study {

/// Prints a warning on stderr when the static state is an unstable equilibrium (the straight
/// branch of a column above its Euler load, say), or when its stability was not assessed.
void warn_if_unstable(const solvers::StaticReport& report);

}  // namespace spar::study
