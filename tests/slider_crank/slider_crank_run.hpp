#pragma once
// A short run of the flexible slider-crank of 003 §5.1 (examples/slider_crank, 6 elements per
// rod, ρ∞ = 0.9): Rod II's midpoint after every step, the largest constraint residual and the
// integrator's counters.
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/beam/beam.hpp>

#include <algorithm>
#include <vector>

#include "slider_crank_model.hpp"

namespace spar::test {

struct SliderCrankRun {
  std::vector<Eigen::Vector3d> midpoints;  ///< Rod II's midpoint after every step
  double max_constraint_residual = 0.0;
  solvers::DynamicCounters counters;
};

/// `strategy` with the increment tolerance `tolerance` on ‖[Δq, h²βΔλ]‖², constraints and dynamic
/// residual to 1e-10, from t = 0 to t_end in steps of h.
inline SliderCrankRun run_slider_crank(solvers::IterationMatrix strategy, double h, double t_end, double tolerance) {
  examples::SliderCrank mechanism = examples::build_slider_crank(6);
  const core::GeometricallyExactBeam& coupler = core::beam(mechanism.model, mechanism.coupler);
  solvers::GeneralizedAlpha integrator(
      mechanism.model, std::move(mechanism.joints),
      {.time_step = h, .spectral_radius = 0.9, .iteration_matrix = strategy,
       .tolerance = tolerance, .constraint_tolerance = 1e-10, .residual_tolerance = 1e-10,
       .max_iterations = 100});
  SliderCrankRun run;
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    run.midpoints.push_back(coupler.position_at(mechanism.model.state(), 0.5));
    run.max_constraint_residual = std::max(run.max_constraint_residual, integrator.constraint_residual());
  }
  run.counters = integrator.counters();
  return run;
}

/// The largest distance between the two runs' midpoints at the same step (m).
inline double max_distance(const SliderCrankRun& a, const SliderCrankRun& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.midpoints.size(), b.midpoints.size()); ++i)
    worst = std::max(worst, (a.midpoints[i] - b.midpoints[i]).norm());
  return worst;
}

}  // namespace spar::test
