// The iteration-matrix strategies of 003 §4 (update, frozen, modified Newton) solve the same
// discrete equations: on the flexible slider-crank (examples/slider_crank) they give the same
// motion to a bound derived from the Newton tolerance, at three step sizes and two tolerances, and
// their counts are ordered as the strategies promise.
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "slider_crank_run.hpp"

using namespace spar;

TEST_CASE("slider-crank: update, frozen and modified Newton give the same motion at every h and tolerance",
          "[dynamics][slider_crank]") {
  // A step stops when its last increment D = [Δq, h²βΔλ] has ‖D‖² ≤ tol (and Φ, r pass). Newton
  // contracts by c ≤ ½ per iteration there (modified Newton refactorizes above ½), so the remaining
  // error of the step is ≤ c/(1 − c)‖D‖ ≤ √tol in m and rad, and Rod II's midpoint, an affine
  // combination of node positions, is off the exact discrete step by ≤ √tol. Two strategies
  // therefore differ by ≤ 2√tol per step; over the N steps of the run (0.02 s, half a crank turn)
  // these differences add at most linearly: bound 2 N √tol.
  const double t_end = 0.02;
  for (const double h : {2e-4, 1e-4, 5e-5}) {
    for (const double tolerance : {1e-22, 1e-16}) {
      CAPTURE(h, tolerance);
      const auto update = test::run_slider_crank(solvers::IterationMatrix::update, h, t_end, tolerance);
      const auto frozen = test::run_slider_crank(solvers::IterationMatrix::frozen, h, t_end, tolerance);
      const auto modified = test::run_slider_crank(solvers::IterationMatrix::modified, h, t_end, tolerance);
      const std::size_t steps = update.midpoints.size();
      REQUIRE(steps == static_cast<std::size_t>(std::lround(t_end / h)));
      REQUIRE(frozen.midpoints.size() == steps);
      REQUIRE(modified.midpoints.size() == steps);
      const double bound = 2.0 * static_cast<double>(steps) * std::sqrt(tolerance);
      INFO("frozen vs update " << test::max_distance(frozen, update) << " m, modified vs update "
                               << test::max_distance(modified, update) << " m (bound " << bound << " m); "
                               << "iterations update " << update.counters.newton_iterations << ", frozen "
                               << frozen.counters.newton_iterations << ", modified "
                               << modified.counters.newton_iterations << "; factorizations update "
                               << update.counters.factorizations << ", frozen " << frozen.counters.factorizations
                               << ", modified " << modified.counters.factorizations);
      CHECK(test::max_distance(frozen, update) <= bound);
      CHECK(test::max_distance(modified, update) <= bound);
      for (const auto* run : {&update, &frozen, &modified}) CHECK(run->counters.cutbacks == 0);
      // update: a fresh matrix, evaluated and factorized, for every iteration (and [M Bᵀ; B 0]
      // once at the start).
      CHECK(update.counters.factorizations == update.counters.newton_iterations + 1);
      CHECK(update.counters.jtheta_evaluations == update.counters.newton_iterations);
      // frozen: 003's matrix is factorized at every iteration but never evaluates J_θ. (Its
      // iteration count is not ordered against update's: 826 against 681 at h = 1e-4, tol 1e-22,
      // but 334 against 353 at h = 2e-4, tol 1e-16.)
      CHECK(frozen.counters.jtheta_evaluations == 0);
      CHECK(frozen.counters.factorizations == frozen.counters.newton_iterations + 1);
      // modified: fewer factorizations than iterations, and more iterations than update.
      CHECK(modified.counters.factorizations < update.counters.factorizations);
      CHECK(modified.counters.factorizations < modified.counters.newton_iterations);
      CHECK(modified.counters.newton_iterations > update.counters.newton_iterations);
    }
  }
}
