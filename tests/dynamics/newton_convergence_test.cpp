// Newton's method with the `update` iteration matrix converges quadratically: seen through the
// cost of tightening the increment tolerance.
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <utility>

#include "flexible_pendulum.hpp"

using namespace spar;

namespace {

/// Newton iterations over 50 steps of the flexible pendulum (h = 1e-3, ρ∞ = 0.9) when the
/// increment test ‖Δ‖² ≤ tolerance alone decides convergence (the residual and constraint tests
/// set loose).
long iterations(solvers::IterationMatrix strategy, double tolerance) {
  test::FlexiblePendulum p = test::flexible_pendulum(4);
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints),
                                       {.time_step = 1e-3, .iteration_matrix = strategy, .tolerance = tolerance,
                                        .constraint_tolerance = 1.0, .residual_tolerance = 1.0,
                                        .max_iterations = 100});
  for (int n = 0; n < 50; ++n) integrator.step();
  REQUIRE(integrator.counters().cutbacks == 0);
  return integrator.counters().newton_iterations;
}

}  // namespace

TEST_CASE("Newton with the update strategy converges quadratically", "[dynamics]") {
  // Lowering the bound on the last increment from 1e-4 (‖Δ‖² ≤ 1e-8) to 1e-12 (‖Δ‖² ≤ 1e-24) —
  // eight decades — costs a quadratically convergent iteration at most two more corrections per
  // step (1e-4 → 1e-8 → 1e-16), a linearly convergent one with rate r at least log(1e-8)/log(r)
  // more (8 for r = 0.1). Bound: 2 per step for update. The modified strategy (a factorization
  // kept while it contracts by ½) is linear and must pay more — the check has teeth.
  const long update_loose = iterations(solvers::IterationMatrix::update, 1e-8);
  const long update_tight = iterations(solvers::IterationMatrix::update, 1e-24);
  const long modified_loose = iterations(solvers::IterationMatrix::modified, 1e-8);
  const long modified_tight = iterations(solvers::IterationMatrix::modified, 1e-24);
  INFO("update: " << update_loose << " -> " << update_tight << " iterations; modified: " << modified_loose << " -> "
                  << modified_tight << " (50 steps)");
  CHECK(update_tight - update_loose <= 2 * 50);
  CHECK(modified_tight - modified_loose > update_tight - update_loose);
}
