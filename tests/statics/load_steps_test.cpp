// The load steps of solve_static: StaticReport::steps has one entry per load step taken, the last
// at load factor 1 exactly (issue 14: ten steps of 0.1 sum to 0.9999999999999999 and took an
// eleventh step of 1e-16).
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>

#include <catch2/catch.hpp>

#include "cantilever.hpp"

using namespace spar;

TEST_CASE("statics: n load steps give n report entries, the last at load factor 1", "[statics]") {
  for (const int steps : {3, 7, 10}) {
    auto c = test::make_cantilever(4, 2);
    core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, 0, -10.0)});
    const solvers::StaticReport report = solvers::solve_static(c.model, {.load_steps = steps});
    INFO(steps << " load steps");
    REQUIRE(static_cast<int>(report.steps.size()) == steps);
    CHECK(report.steps.back().load_factor == 1.0);
    for (int k = 0; k < steps; ++k) CHECK(report.steps[k].load_factor == Approx((k + 1.0) / steps).epsilon(1e-14));
  }
}
