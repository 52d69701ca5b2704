// The flexible slider-crank of 003 §5.1 (examples/slider_crank): the constraints hold to 1e-10
// after every step. The strategies' agreement is strategies_test.cpp's; the comparison with the
// paper's figures and counts is the example's (examples/slider_crank/README.md and
// tests/examples), not asserted here.
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include "slider_crank_run.hpp"

using namespace spar;

TEST_CASE("slider-crank: constraints hold to 1e-10 after every step", "[dynamics][slider_crank]") {
  const auto run = test::run_slider_crank(solvers::IterationMatrix::update, 1e-4, 0.02, 1e-6);
  INFO("max constraint residual " << run.max_constraint_residual);
  CHECK(run.max_constraint_residual <= 1e-10);
  CHECK(run.counters.cutbacks == 0);
}
