// The Newton test with the dynamic residual off (003's test) evaluates only the constraints and
// the loaded elements at an iterate it may accept, and the elements' energies when asked for
// (docs/dynamics.md D4). Proven here against the same run with the residual test on but
// unable to fail (residual_tolerance = 1e300, which evaluates every element at every check):
// the iterates, multipliers, energies and the work booked by the balance are bitwise the same,
// for every iteration-matrix strategy, with loads of every kind and a time history among them.
#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "flexible_pendulum.hpp"

using namespace spar;

namespace {

/// The flexible pendulum of tests/support with a tip force that follows a history, a distributed
/// force and an inertial moment at its tip, and `steps` steps of 1e-3 s.
struct Run {
  std::vector<Eigen::VectorXd> positions, multipliers;
  std::vector<solvers::Energies> energies;
  long iterations = 0, residual_evaluations = 0;
};

Run run(solvers::IterationMatrix strategy, double residual_tolerance, int steps) {
  test::FlexiblePendulum pendulum = test::flexible_pendulum(6);
  core::Model& model = pendulum.model;
  const int tip = core::beam(model, 0).node(core::beam(model, 0).control_point_count() - 1);
  core::add_load(model, core::NodalForce{tip, Eigen::Vector3d(0.0, 0.02, 0.05)},
                 [](double t) { return std::sin(40.0 * t); });
  core::add_load(model, core::DistributedForce{0, Eigen::Vector3d(0.0, -0.01, 0.0)});
  core::add_load(model, core::NodalMoment{tip, Eigen::Vector3d(0.0, 0.0, 2e-3), core::MomentFrame::inertial});
  solvers::GeneralizedAlpha integrator(model, std::move(pendulum.joints),
                                       {.time_step = 1e-3, .iteration_matrix = strategy,
                                        .residual_tolerance = residual_tolerance});
  integrator.initialize();
  Run r;
  for (int i = 0; i < steps; ++i) {
    integrator.step();
    Eigen::VectorXd x(3 * model.block_count());
    for (int b = 0; b < model.block_count(); ++b) x.segment<3>(3 * b) = model.state().position[b];
    r.positions.push_back(x);
    r.multipliers.push_back(integrator.multipliers());
    // Energies read every other step: the balance must not depend on when they are read.
    if (i % 2 == 1) r.energies.push_back(integrator.energies());
  }
  r.iterations = integrator.counters().newton_iterations;
  r.residual_evaluations = integrator.counters().residual_evaluations;
  return r;
}

}  // namespace

TEST_CASE("the residual-free Newton test gives bitwise the run that evaluates every element", "[dynamics]") {
  for (const auto strategy : {solvers::IterationMatrix::update, solvers::IterationMatrix::frozen,
                              solvers::IterationMatrix::modified}) {
    INFO("strategy " << static_cast<int>(strategy));
    const Run light = run(strategy, INFINITY, 40), full = run(strategy, 1e300, 40);
    CHECK(light.iterations == full.iterations);
    // Each check at an accepted iterate saves one evaluation of the elements.
    CHECK(light.residual_evaluations < full.residual_evaluations);
    for (std::size_t i = 0; i < light.positions.size(); ++i) {
      REQUIRE(light.positions[i] == full.positions[i]);
      REQUIRE(light.multipliers[i] == full.multipliers[i]);
    }
    for (std::size_t i = 0; i < light.energies.size(); ++i) {
      CHECK(light.energies[i].kinetic == full.energies[i].kinetic);
      CHECK(light.energies[i].strain == full.energies[i].strain);
      CHECK(light.energies[i].gravity == full.energies[i].gravity);
      CHECK(light.energies[i].external_work == full.energies[i].external_work);
      CHECK(light.energies[i].numerical_dissipation == full.energies[i].numerical_dissipation);
    }
    // The loads did work: the comparison of external_work is not one of zeros.
    CHECK(std::abs(full.energies.back().external_work) > 1e-6);
  }
}
