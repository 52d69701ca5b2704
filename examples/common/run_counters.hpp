#pragma once
// The counters every dynamic example stores with its results, so a results file says how it was
// computed: the end time, steps, Newton iterations, factorizations, J_θ evaluations and cut-backs.
#include <spar/spar.hpp>

namespace spar::examples {

/// Writes the integrator's counters as root attributes of `results` (docs/output.md).
inline void write_run_counters(core::ResultsWriter& results, const solvers::GeneralizedAlpha& integrator) {
  const solvers::DynamicCounters& counters = integrator.counters();
  results.write_attribute("t_end", integrator.time());
  results.write_attribute("steps", counters.steps);
  results.write_attribute("newton_iterations", counters.newton_iterations);
  results.write_attribute("factorizations", counters.factorizations);
  results.write_attribute("substructured_factorizations", counters.substructured_factorizations);
  results.write_attribute("jtheta_updates", counters.jtheta_evaluations);
  results.write_attribute("cutbacks", counters.cutbacks);
}

}  // namespace spar::examples
