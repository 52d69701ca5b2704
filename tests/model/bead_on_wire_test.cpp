// Issue 10, proof 2: a joint defined in a test that owns a coordinate (a bead on a circular wire,
// its place on the wire a massless vector block s). Jacobian, multiplier tangent and acceleration
// terms against finite differences; the bead released at 60° under gravity against the exact
// period of the pendulum, and the energy error's order.
#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include "elliptic_integral.hpp"
#include "upward_crossings.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "circular_wire.hpp"
#include "point_mass.hpp"
#include "vector_block_checks.hpp"

using namespace spar;

TEST_CASE("a joint that owns its coordinate: Jacobian, multiplier tangent, acceleration terms",
          "[model][joints]") {
  std::mt19937 random(2002);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  const test::CircularWire wire({.bead = 0, .arc_length = 1, .centre = Eigen::Vector3d(0.1, 0.2, 0.3),
                                 .radius = 1.3});
  for (int sample = 0; sample < 20; ++sample) {
    core::Configuration q;
    q.add_vector(Eigen::Vector3d(uniform(random), uniform(random), uniform(random)));
    q.add_vector(Eigen::VectorXd::Constant(1, 3 * uniform(random)));  // s over ±6 m: θ over ±4.6 rad
    const double t = 0.0;
    CAPTURE(sample);
    const Eigen::Vector3d lambda(uniform(random), uniform(random), uniform(random));
    const Eigen::VectorXd velocity = Eigen::VectorXd::NullaryExpr(4, [&] { return uniform(random); });
    test::check_constraint_derivatives(wire, q, t, lambda, velocity);
  }
}

namespace {

using test::complete_elliptic_k;

constexpr double bead_mass = 0.7, radius = 1.0, gravity = 9.81;
const double release_angle = std::numbers::pi / 3;

struct WireRun {
  double period = 0.0;        ///< mean period from the upward crossings of the lowest point, s
  double energy_error = 0.0;  ///< max |E(t) − E(0)| over the run, J
  double dissipation = 0.0;   ///< the integrator's numerical_dissipation at the end, J
  double constraint = 0.0;    ///< largest ‖Φ‖∞ after a step, m
};

WireRun release_bead(double h, double periods) {
  core::Model model;
  const double s0 = radius * release_angle;
  const Eigen::Vector3d x0 = radius * Eigen::Vector3d(std::sin(release_angle), 0, -std::cos(release_angle));
  const int bead = model.add_vector(x0);
  const int arc = model.add_vector(Eigen::VectorXd::Constant(1, s0));
  model.add_element(std::make_unique<test::PointMass>(bead, bead_mass));
  model.set_gravity(Eigen::Vector3d(0, 0, -gravity));
  solvers::ConstraintList constraints;
  constraints.push_back(std::make_unique<test::CircularWire>(
      test::CircularWireParameters{.bead = bead, .arc_length = arc, .radius = radius}));
  solvers::DynamicOptions options;
  options.time_step = h;
  // Index 3 with ρ∞ = 1 is weakly unstable (Arnold & Brüls 2007): the multipliers' parasitic mode
  // is not damped. ρ∞ = 0.9 damps it and keeps the method second order.
  options.spectral_radius = 0.9;
  options.tolerance = 1e-24;
  options.residual_tolerance = 1e-12;
  solvers::GeneralizedAlpha integrator(model, std::move(constraints), options);
  integrator.initialize();
  const double energy0 = integrator.energies().total();

  WireRun run;
  const double exact_period = 4 * std::sqrt(radius / gravity) * complete_elliptic_k(std::sin(release_angle / 2));
  const int steps = static_cast<int>(std::lround(periods * exact_period / h)) + 1;
  test::UpwardCrossings crossings;
  const int s_dof = integrator.configuration().blocks[arc].offset;
  double s_prev = s0, v_prev = 0.0;
  for (int n = 0; n < steps; ++n) {
    const double t_prev = integrator.time();
    integrator.step();
    const double s = integrator.configuration().values(s_dof), v = integrator.velocity()(s_dof);
    run.energy_error = std::max(run.energy_error, std::abs(integrator.energies().total() - energy0));
    run.constraint = std::max(run.constraint, integrator.constraint_residual());
    crossings.add_step(t_prev, h, s_prev, v_prev, s, v);
    s_prev = s;
    v_prev = v;
  }
  REQUIRE(crossings.count() >= 2);
  run.period = crossings.period();
  run.dissipation = integrator.energies().numerical_dissipation;
  return run;
}

}  // namespace

TEST_CASE("a bead on a circular wire released at 60 degrees: exact period, O(h^2) energy error",
          "[model][validation]") {
  // The quadrature first: K(k = 1/2) = 1.685750354812596 (Abramowitz & Stegun, table 17.1, m = 1/4).
  CHECK(complete_elliptic_k(0.5) == Approx(1.685750354812596).epsilon(1e-15));
  const double exact_period = 4 * std::sqrt(radius / gravity) * complete_elliptic_k(std::sin(release_angle / 2));
  const double periods = 4.0;
  const WireRun r1 = release_bead(4e-3, periods);
  const WireRun r2 = release_bead(2e-3, periods);
  const WireRun r3 = release_bead(1e-3, periods);
  const double e1 = r1.period - exact_period, e2 = r2.period - exact_period, e3 = r3.period - exact_period;
  // Second order: halving h divides the period error by 4 (measured 6.579e-5, 1.645e-5,
  // 4.112e-6 s; ratios 3.9996, 4.0001), and the Richardson extrapolation (4 T_h/2 − T_h)/3 removes
  // the h² term: what is left (measured 1e-10 s) is the O(h⁴) remainder and the crossings' Hermite
  // interpolation (O(h⁴)); 1e-8 s is 400 times below the h² error it removes.
  CHECK(e1 / e2 == Approx(4.0).margin(0.1));
  CHECK(e2 / e3 == Approx(4.0).margin(0.1));
  CHECK(std::abs((4 * r3.period - r2.period) / 3 - exact_period) < 1e-8);
  // The energy error (largest |E(t) − E(0)| over four periods) is O(h²): measured 2.055e-4,
  // 5.135e-5, 1.284e-5 J (3.7e-6 of the drop energy m g R (1 − cos θ0) = 3.4 J at h = 1 ms);
  // ratios 4.001, 4.000.
  CHECK(r1.energy_error / r2.energy_error == Approx(4.0).margin(0.1));
  CHECK(r2.energy_error / r3.energy_error == Approx(4.0).margin(0.1));
  // The secular part, the energy ρ∞ = 0.9 removes, is positive and of higher order: generalized-α's
  // damping ratio is O((ωh)³) (Chung & Hulbert 1993), so the loss over a fixed time is O(h³)
  // (measured 8.28e-8, 1.07e-8, 1.43e-9 J: ratios 7.7, 7.5).
  for (const WireRun& r : {r1, r2, r3}) CHECK(r.dissipation > 0.0);
  CHECK(r1.dissipation / r2.dissipation > 6.0);
  CHECK(r2.dissipation / r3.dissipation > 6.0);
  // Index 3: the constraint holds at every step to Newton's constraint tolerance (measured 3e-16).
  for (const WireRun& r : {r1, r2, r3}) CHECK(r.constraint <= 1e-10);
}
