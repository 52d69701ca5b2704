// study::EnergyLedger (<spar/study/energy_ledger.hpp>) on a free rigid body falling under gravity,
// whose total energy the generalized-α method (ρ∞ = 1) conserves: the drifts stay at Newton's and
// round-off's level, and a restart that doubles the velocity (GeneralizedAlpha::remap with P = 2I)
// is booked as the jump ½m(2v)² − ½mv² = 3 × the kinetic energy, and the drift between restarts
// starts again from there.
#include <spar/study/energy_ledger.hpp>

#include <spar/elements/rigid_body/rigid_body.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace spar;

TEST_CASE("EnergyLedger: drifts between restarts and the jump at a restart", "[study]") {
  core::Model model;
  core::add_rigid_body(model, {.center_of_mass = Eigen::Vector3d(0, 0, 1), .mass = 2.0,
                               .inertia = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal()});
  model.set_gravity(Eigen::Vector3d(0, 0, -9.81));
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = 1e-2, .spectral_radius = 1.0, .residual_tolerance = 1e-12});
  integrator.initialize();
  study::EnergyLedger ledger(integrator);
  CHECK(ledger.max_kinetic() == 0.0);
  CHECK(ledger.max_jump() == 0.0);

  for (int n = 0; n < 10; ++n) {
    integrator.step();
    ledger.after_step();
  }
  const double kinetic = integrator.energies().kinetic;  // ½ m (g t)² at t = 0.1 s: 0.962 J
  CHECK(ledger.max_kinetic() == kinetic);                 // it grows as the body falls
  // The free fall is integrated to Newton's tolerance (1e-12 of the forces) and round-off: a
  // drift of 1e-9 of the kinetic energy would be a million times more.
  CHECK(ledger.max_drift() <= 1e-9 * kinetic);
  CHECK(ledger.max_drift_between_restarts() == ledger.max_drift());  // no restart yet

  const Eigen::Index dofs = integrator.velocity().size();
  const double jump = ledger.restart(2.0 * Eigen::MatrixXd::Identity(dofs, dofs));
  CHECK(jump == Approx(3.0 * kinetic).epsilon(1e-12));  // the same state's energies, a few roundings apart
  CHECK(ledger.max_jump() == std::fabs(jump));

  integrator.step();
  ledger.after_step();
  CHECK(ledger.max_kinetic() > 4.0 * kinetic);                        // twice as fast, and falling on
  CHECK(ledger.max_drift() == Approx(3.0 * kinetic).epsilon(1e-9));   // E(0) is before the jump
  CHECK(ledger.max_drift_between_restarts() <= 1e-9 * kinetic);      // measured from the restart
}
