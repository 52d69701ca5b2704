// An element that cannot be evaluated at a Newton iterate throws spar::Error: the iteration has
// failed, the step is cut back, and nothing escapes, with serial and parallel assembly alike.
// When no cut-back helps, step() and solve_static throw and leave the last converged state.
#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/static_solver.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <memory>

#include "coordinate_limit.hpp"
#include "linear_spring.hpp"
#include "point_mass.hpp"
#include "saturating_tether.hpp"

using namespace spar;

namespace {

// A mass m = 1 kg on a spring k = 100 N/m (ω = 10 rad/s) to a fixed anchor, passing through the
// rest length at 1 m/s: its stretch never exceeds v/ω = 0.1 m (ρ∞ = 1 keeps ½ m v² + ½ k u²
// exactly on a linear problem). A step h = 0.2 s starts Newton from a prediction 0.2 m out, past
// a limit at 0.15 m; half a step predicts 0.1 m.
struct Oscillator {
  core::Model model;
  int mass = 0;
  std::shared_ptr<std::atomic<int>> refusals = std::make_shared<std::atomic<int>>(0);
};

std::unique_ptr<Oscillator> make_oscillator(bool limited) {
  auto o = std::make_unique<Oscillator>();
  const int anchor = o->model.add_vector(Eigen::Vector3d::Zero());
  o->mass = o->model.add_vector(Eigen::Vector3d(1.0, 0, 0));
  o->model.fix(anchor);
  o->model.add_element(std::make_unique<test::PointMass>(anchor, 1.0));
  o->model.add_element(std::make_unique<test::PointMass>(o->mass, 1.0));
  o->model.add_element(std::make_unique<test::LinearSpring>(
      test::LinearSpringParameters{.block_a = anchor, .block_b = o->mass, .stiffness = 100.0, .rest_length = 1.0}));
  if (limited)
    o->model.add_element(std::make_unique<test::CoordinateLimit>(
        test::CoordinateLimitParameters{.block = o->mass, .coordinate = 0, .limit = 1.15}, o->refusals));
  return o;
}

solvers::DynamicOptions oscillator_options(double h, solvers::AssemblyExecution execution) {
  solvers::DynamicOptions options;
  options.time_step = h;
  options.spectral_radius = 1.0;
  options.tolerance = 1e-24;
  options.residual_tolerance = 1e-12;
  options.assembly = execution;
  return options;
}

}  // namespace

TEST_CASE("an element that throws at an overshooting iterate makes the step cut back",
          "[model][errors]") {
  const double h = 0.2;
  auto reference = make_oscillator(false);
  solvers::GeneralizedAlpha reference_integrator(reference->model, {},
                                                 oscillator_options(h / 2, solvers::AssemblyExecution::serial));
  reference_integrator.set_velocity(reference->mass, Eigen::VectorXd(Eigen::Vector3d(1, 0, 0)));
  reference_integrator.step();
  reference_integrator.step();

  for (const solvers::AssemblyExecution execution : {solvers::AssemblyExecution::serial, solvers::AssemblyExecution::parallel}) {
    CAPTURE(execution == solvers::AssemblyExecution::parallel);
    auto limited = make_oscillator(true);
    solvers::GeneralizedAlpha integrator(limited->model, {}, oscillator_options(h, execution));
    integrator.set_velocity(limited->mass, Eigen::VectorXd(Eigen::Vector3d(1, 0, 0)));
    REQUIRE_NOTHROW(integrator.step());
    // Both predictors of the full step reached the limit; the two halves did not.
    CHECK(*limited->refusals == 2);
    CHECK(integrator.counters().cutbacks == 1);
    CHECK(integrator.counters().steps == 2);
    CHECK(integrator.time() == Approx(h).epsilon(1e-15));
    // The halves are the reference's two steps of h/2: the same solution of the same linear
    // equations from another predictor, equal to the round-off of Newton's correction (1e-16 m).
    CHECK((integrator.configuration().values - reference_integrator.configuration().values).cwiseAbs().maxCoeff() < 1e-14);
    CHECK((integrator.velocity() - reference_integrator.velocity()).cwiseAbs().maxCoeff() < 1e-14);
    for (int n = 0; n < 20; ++n) REQUIRE_NOTHROW(integrator.step());
    CHECK(integrator.configuration().vector(limited->mass)(0) <= 1.15);
  }
}

TEST_CASE("a step that fails even after every cut-back leaves the state of the step's start",
          "[model][errors]") {
  for (const solvers::AssemblyExecution execution : {solvers::AssemblyExecution::serial, solvers::AssemblyExecution::parallel}) {
    CAPTURE(execution == solvers::AssemblyExecution::parallel);
    // A free mass at 1 m/s towards a limit at 0.37 m, steps of 0.1 s: the fourth step cannot
    // reach 0.4 m, and its halves get as close as 0.37 m before the last halving fails.
    core::Model model;
    const int mass = model.add_vector(Eigen::Vector3d::Zero());
    model.add_element(std::make_unique<test::PointMass>(mass, 1.0));
    auto refusals = std::make_shared<std::atomic<int>>(0);
    model.add_element(std::make_unique<test::CoordinateLimit>(
        test::CoordinateLimitParameters{.block = mass, .coordinate = 0, .limit = 0.37}, refusals));
    solvers::DynamicOptions options = oscillator_options(0.1, execution);
    options.max_cutbacks = 4;
    solvers::GeneralizedAlpha integrator(model, {}, options);
    integrator.set_velocity(mass, Eigen::VectorXd(Eigen::Vector3d(1, 0, 0)));
    for (int n = 0; n < 3; ++n) integrator.step();
    const core::Configuration q = integrator.configuration();
    const Eigen::VectorXd v = integrator.velocity(), vdot = integrator.acceleration();
    const double t = integrator.time();
    const double kinetic = integrator.energies().kinetic;
    const long steps = integrator.counters().steps;
    CHECK_THROWS_AS(integrator.step(), Error);
    CHECK(*refusals > 0);
    // Everything as before the failed step(): not some converged sub-step inside it.
    CHECK(integrator.time() == t);
    CHECK(integrator.configuration().values == q.values);
    CHECK(integrator.velocity() == v);
    CHECK(integrator.acceleration() == vdot);
    CHECK(integrator.energies().kinetic == kinetic);
    CHECK(integrator.counters().steps == steps);
    CHECK(integrator.configuration().vector(mass)(0) == Approx(0.3).epsilon(1e-14));
  }
}

TEST_CASE("solve_static that fails after every cut-back leaves the last converged load factor",
          "[model][errors]") {
  // A mass m = 1 kg hangs from a fixed anchor on a spring k = m g / 0.1 m, rest length 0.9 m,
  // under gravity scaled by the load factor λ: its equilibrium is z = −(0.9 + 0.1 λ), exact in
  // one Newton iteration (the spring is linear along its axis). Evaluation is refused below
  // z = −0.955, so λ > 0.55 cannot be reached.
  const double g = 9.81, k = g / 0.1;
  core::Model model;
  const int anchor = model.add_vector(Eigen::Vector3d::Zero());
  const int mass = model.add_vector(Eigen::Vector3d(0, 0, -0.95));  // stretched: transverse stiffness > 0
  model.fix(anchor);
  model.add_element(std::make_unique<test::PointMass>(mass, 1.0));
  model.add_element(std::make_unique<test::LinearSpring>(
      test::LinearSpringParameters{.block_a = anchor, .block_b = mass, .stiffness = k, .rest_length = 0.9}));
  auto refusals = std::make_shared<std::atomic<int>>(0);
  model.add_element(std::make_unique<test::CoordinateLimit>(
      test::CoordinateLimitParameters{.block = mass, .coordinate = 2, .limit = 0.955, .direction = -1.0}, refusals));
  model.set_gravity(Eigen::Vector3d(0, 0, -g));
  solvers::StaticOptions options;
  options.max_cutbacks = 6;
  double last = -1.0;
  try {
    solvers::solve_static(model, options);
    FAIL("solve_static passed the limit");
  } catch (const solvers::ConvergenceError& error) {
    last = error.last_converged_load_factor();
  }
  CHECK(*refusals > 0);
  CHECK(last > 0.5);
  CHECK(last < 0.55);
  // The positions are the equilibrium at that load factor (one linear solve from the previous
  // equilibrium: round-off of coordinates of size 1, well below 1e-14 m), not the refused iterate's.
  const Eigen::Vector3d x = model.state().vector(mass);
  CHECK(std::abs(x(0)) < 1e-14);
  CHECK(std::abs(x(1)) < 1e-14);
  CHECK(x(2) == Approx(-(0.9 + 0.1 * last)).epsilon(1e-14));
}

TEST_CASE("a singular tangent at a static Newton iterate is a failed iteration, not a crash",
          "[model][errors]") {
  // A tether of strength T_max = 1 N under a load of 2.2 N: equilibria exist up to λ = 1/2.2 only
  // (not a load factor the halvings of 0.1 reach, where tanh would round to 1 at a finite z).
  // Past it Newton's iterates run away until the tangent is exactly zero: the load step must be
  // cut back like any failed iteration, and the failure reported as a ConvergenceError with the
  // model at the last equilibrium.
  core::Model model;
  const int block = model.add_vector(Eigen::VectorXd::Zero(1));
  const test::SaturatingTetherParameters p{.block = block, .stiffness = 10.0, .max_tension = 1.0, .load = 2.2};
  model.add_element(std::make_unique<test::SaturatingTether>(p));
  solvers::StaticOptions options;
  options.max_cutbacks = 6;
  double last = -1.0;
  try {
    solvers::solve_static(model, options);
    FAIL("solve_static found an equilibrium past the tether's strength");
  } catch (const solvers::ConvergenceError& error) {
    last = error.last_converged_load_factor();
  }
  CHECK(last >= 0.4);
  CHECK(last < 1 / 2.2);
  // The state is that equilibrium, not the runaway iterate: z = (T_max/k) atanh(2.2 λ). Newton
  // stopped after an increment ≤ 1e-10 m, and its quadratic convergence leaves an error of the
  // order of that increment squared times |K′/K| ≈ 10/m: far below 1e-12 m (measured 6e-17 m).
  CHECK(std::abs(model.state().values(0) - test::SaturatingTether(p).equilibrium(last)) < 1e-12);
}
