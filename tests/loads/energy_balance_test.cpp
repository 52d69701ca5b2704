// The energy balance kept by the integrator (docs/dynamics.md eq. D8): external_work =
// ∫ (f_ext · v − λᵀ B v) dt by the trapezoidal rule, numerical_dissipation = external_work − ΔE.
// A conservative model at ρ∞ = 1 dissipates nothing to the integrator's accuracy and receives no
// external work; a pushed rigid body receives exactly its kinetic energy.
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/loads/loads.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "flexible_pendulum.hpp"

using namespace spar;

TEST_CASE("energy balance: the pinned flexible pendulum at rho_infinity = 1 dissipates nothing",
          "[loads][dynamics][validation]") {
  // Gravity is a potential (in E), the pin is fixed (λᵀ B v is the power of a workless
  // constraint: zero for Bv = 0, which the index-3 method satisfies only through Φ(q_n) = 0, so
  // to O(h²)), and ρ∞ = 1 is the trapezoidal rule: the balance is |numerical_dissipation| = the
  // energy drift, O(h²) — tests/dynamics/flexible_pendulum_test.cpp measures 7.1e-7 of m g L/2 at
  // h = 2.5e-4 over the swing. Bounds here, at h = 5e-4 over 0.5 s: 1e-5 of the energy scale
  // m g L / 2 for both (measured: see INFO), far below anything visible in an energy plot.
  test::FlexiblePendulum p = test::flexible_pendulum(4);
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints),
                                       {.time_step = 5e-4, .spectral_radius = 1.0, .tolerance = 1e-20,
                                        .constraint_tolerance = 1e-12, .residual_tolerance = 1e-8});
  integrator.initialize();
  double worst_dissipation = 0.0, worst_work = 0.0;
  while (integrator.time() < 0.5 - 1e-12) {
    integrator.step();
    worst_dissipation = std::max(worst_dissipation, std::fabs(integrator.energies().numerical_dissipation));
    worst_work = std::max(worst_work, std::fabs(integrator.energies().external_work));
  }
  INFO("worst |numerical dissipation| " << worst_dissipation / p.energy_scale << ", worst |external work| "
                                        << worst_work / p.energy_scale << " of m g L/2 = " << p.energy_scale << " J");
  CHECK(worst_dissipation <= 1e-5 * p.energy_scale);
  CHECK(worst_work <= 1e-5 * p.energy_scale);
}

TEST_CASE("energy balance: a constant force on a free rigid body does work equal to its kinetic energy",
          "[loads][dynamics][validation]") {
  // From rest in translation under F: v(t) = F t/m exactly in the method (Σ M v̇ = F at every
  // evaluation; see dynamic_loads_test.cpp), so the trapezoidal ∫ F · v dt of a linear v is exact:
  // external_work = F² t²/(2m) to round-off and the Newton residual (1e-10 of F; bound 1e-9
  // relative). The body also tumbles torque-free (J = diag(1, 2, 3), Ω₀ = (0.3, 1, 0.2) rad/s,
  // rotational energy 1.1 J), which no external force works on but which the Lie-group
  // generalized-α keeps only to O(h²): ΔKE = external_work to (|Ω| h)²/12 of the rotational
  // energy, 1e-7 J at h = 1e-3 (measured 4.1e-9 J); so is numerical_dissipation.
  core::Model model;
  const int node = core::rigid_body(model, core::add_rigid_body(model,
      {.mass = 2.0, .inertia = Eigen::Vector3d(1, 2, 3).asDiagonal()})).node;
  const Eigen::Vector3d F(3.0, -1.0, 2.0), Omega(0.3, 1.0, 0.2);
  core::add_load(model, core::NodalForce{node, F});
  const double h = 1e-3;
  solvers::GeneralizedAlpha integrator(model, {},
                                       {.time_step = h, .spectral_radius = 0.8, .tolerance = 1e-20,
                                        .residual_tolerance = 1e-10});
  integrator.set_velocity(node, Eigen::Vector3d::Zero(), Omega);
  integrator.initialize();
  const double kinetic0 = integrator.energies().kinetic;
  for (int k = 0; k < 500; ++k) integrator.step();
  const solvers::Energies e = integrator.energies();
  const double t = integrator.time(), expected = F.squaredNorm() * t * t / (2 * 2.0);
  const double rotation_bound = std::pow(Omega.norm() * h, 2) / 12 * kinetic0;
  INFO("external work " << e.external_work << ", Delta KE " << e.kinetic - kinetic0 << ", F^2 t^2/2m "
                        << expected << ", numerical dissipation " << e.numerical_dissipation);
  CHECK(std::fabs(e.external_work - expected) <= 1e-9 * expected);
  CHECK(std::fabs(e.kinetic - kinetic0 - e.external_work) <= rotation_bound);
  CHECK(std::fabs(e.numerical_dissipation) <= rotation_bound);
}
