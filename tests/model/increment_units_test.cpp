// DynamicOptions::increment_units: the convergence test measures each increment entry in its own
// unit, ‖Δq ⊘ u‖² ≤ tolerance (003 §5.1 with units), and a units vector that does not fit the
// layout is refused — at construction, and at a remap to another layout.
#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <memory>

#include "point_mass.hpp"
#include "linear_spring.hpp"
#include "polar_point_mass.hpp"

using namespace spar;

namespace {

struct UnitsRun {
  Eigen::VectorXd coordinates, velocity;
  long newton_iterations = 0;
};

/// Two masses on a spring (spring_mass_test.cpp) spinning about their centre while the spring
/// stretches: a nonlinear motion, 20 steps of 0.05 s (ωh = 0.5). Every dof carries a mass and the
/// spring, so the residual test is relative to the size of both forces and the increment test
/// decides when Newton stops.
UnitsRun spinning_spring_run(double tolerance, const Eigen::VectorXd& units) {
  core::Model model;
  const int a = model.add_vector(Eigen::Vector3d(0, 0, 0));
  const int b = model.add_vector(Eigen::Vector3d(1.1, 0, 0));
  model.add_element(std::make_unique<test::PointMass>(a, 1.0));
  model.add_element(std::make_unique<test::PointMass>(b, 1.0));
  model.add_element(std::make_unique<test::LinearSpring>(
      test::LinearSpringParameters{.block_a = a, .block_b = b, .stiffness = 50.0, .rest_length = 1.0}));
  solvers::DynamicOptions options;
  options.time_step = 0.05;
  options.spectral_radius = 1.0;
  options.tolerance = tolerance;
  options.residual_tolerance = 1e-6;
  options.increment_units = units;
  solvers::GeneralizedAlpha integrator(model, {}, options);
  integrator.set_velocity(a, Eigen::VectorXd(Eigen::Vector3d(0, -2, 0)));
  integrator.set_velocity(b, Eigen::VectorXd(Eigen::Vector3d(0, 2, 0)));
  for (int n = 0; n < 20; ++n) integrator.step();
  return {integrator.configuration().values, integrator.velocity(), integrator.counters().newton_iterations};
}

}  // namespace

TEST_CASE("increment_units divide the increments in the convergence test", "[model]") {
  // τ = 1e-4: one Newton correction per step suffices (20 solves in 20 steps); τ ≤ 1e-8 takes two.
  const double tolerance = 1e-4;
  // Units u = 2⁻¹⁰ make ‖Δ/u‖² = 2²⁰ ‖Δ‖²: with powers of two every operation is exact, so the
  // run is bitwise the run without units at tolerance 2⁻²⁰ τ.
  const double unit = std::ldexp(1.0, -10);
  const UnitsRun plain = spinning_spring_run(tolerance, {});
  const UnitsRun with_units = spinning_spring_run(tolerance, Eigen::VectorXd::Constant(6, unit));
  const UnitsRun equivalent = spinning_spring_run(tolerance * unit * unit, {});
  CHECK(with_units.newton_iterations == equivalent.newton_iterations);
  CHECK(with_units.coordinates == equivalent.coordinates);
  CHECK(with_units.velocity == equivalent.velocity);
  // …and not the run without units at τ: the units changed the test.
  CHECK(with_units.newton_iterations > plain.newton_iterations);
  // Units of 1 are the test without units.
  const UnitsRun ones = spinning_spring_run(tolerance, Eigen::VectorXd::Ones(6));
  CHECK(ones.newton_iterations == plain.newton_iterations);
  CHECK(ones.coordinates == plain.coordinates);
}

TEST_CASE("increment_units that do not fit the layout are refused", "[model][errors]") {
  core::Model model;
  const int block = model.add_vector(Eigen::Vector2d(1.0, 0.0));
  model.add_element(std::make_unique<test::PolarPointMass>(std::vector<int>{block}, 1.3));
  solvers::DynamicOptions options;
  for (const Eigen::VectorXd& units : {Eigen::VectorXd(Eigen::VectorXd::Ones(3)), Eigen::VectorXd(Eigen::VectorXd::Ones(1)),
                                       Eigen::VectorXd(Eigen::Vector2d(1.0, 0.0)), Eigen::VectorXd(Eigen::Vector2d(1.0, -1.0)),
                                       Eigen::VectorXd(Eigen::Vector2d(1.0, std::numeric_limits<double>::quiet_NaN()))}) {
    options.increment_units = units;
    CHECK_THROWS_WITH(solvers::GeneralizedAlpha(model, {}, options), Catch::Contains("increment_units"));
  }
}
