// The eccentric sliding beam of 003 §5.2 (examples/sliding_beam) on the paper's mesh (16 + 2
// quadratic elements, h = 1e-3 s): the slider reaches B close to the paper's 1.306 s, crossing
// every carrier element on the way, with the constraints held after every step.
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "sliding_beam_model.hpp"

using namespace spar;

TEST_CASE("sliding beam (003 5.2): arrival at B, element crossings and constraints",
          "[sliding][validation]") {
  examples::SlidingBeam setup = examples::build_sliding_beam(16, 2);
  const joints::SlidingJoint& slide = *setup.slide;
  const int zeta_block = slide.zeta_block();
  const double h = 1e-3;
  solvers::GeneralizedAlpha integrator(setup.model, std::move(setup.joints),
                                       {.time_step = h, .spectral_radius = 0.9, .tolerance = 1e-12,
                                        .constraint_tolerance = 1e-10, .residual_tolerance = 1e-8});
  double arrival = NAN, max_residual = 0.0;
  while (integrator.time() < 2.0) {
    integrator.step();
    if (slide.locked()) {
      arrival = slide.lock_time();
      CHECK(std::abs(setup.model.state().vector(zeta_block)(0) - slide.lock_position()) <= 1e-10);
      break;
    }
    max_residual = std::max(max_residual, integrator.constraint_residual());
  }
  // Measured 1.3131 s on this mesh (converged in elements and h: 1.314 s, examples/sliding_beam/
  // README.md); 003 reports 1.306 s. 1 % covers the difference, which the README discusses.
  CHECK(std::abs(arrival - 1.306) <= 0.01 * 1.306);
  CHECK(arrival == Approx(1.31314).margin(1e-4));
  // Every step converged to the constraint tolerance.
  CHECK(max_residual <= 1e-10);
  // Events: carrier elements 1 … 15 entered in order, then the lock at B.
  const auto& events = integrator.events();
  REQUIRE(events.size() == 16);
  for (int e = 1; e <= 15; ++e)
    CHECK(events[e - 1].second == "sliding joint 'slider at A' entered carrier element " + std::to_string(e));
  CHECK(events.back().second.find("locked at its upper stop") != std::string::npos);
  CHECK(integrator.counters().cutbacks == 0);
}
