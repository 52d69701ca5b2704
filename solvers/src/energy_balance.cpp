// The energy balance of the generalized-α integrator (docs/dynamics.md D7–D8).
#include "energy_balance.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace spar::solvers::detail {

double mechanical_energy(const SystemAssembly& assembly) {
  const SummedEnergies e = assembly.energies();
  return e.kinetic + e.strain + e.gravity;
}

Eigen::VectorXd work_force(const SystemAssembly& assembly) {
  return assembly.external_force() - assembly.constraint_force();
}

Eigen::VectorXd driver_force(const SystemAssembly& assembly, const core::Configuration& q, double t,
                             std::vector<bool>& driven) {
  const std::vector<joints::Constraint*>& constraints = assembly.constraints();
  driven.resize(constraints.size(), false);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(assembly.dof_count());
  Eigen::VectorXd phi_t;
  for (std::size_t ci = 0; ci < constraints.size(); ++ci) {
    if (!driven[ci]) {
      phi_t.resize(constraints[ci]->equation_count());
      constraints[ci]->time_derivative(q, t, phi_t);
      driven[ci] = !phi_t.isZero(0.0);
    }
    if (driven[ci]) assembly.add_constraint_force(static_cast<int>(ci), force);
  }
  return force;
}

void EnergyBalance::book_step(const SystemAssembly& assembly, const Eigen::VectorXd& increment,
                              Eigen::VectorXd driver_force) {
  // Trapezoidal work along the step's increment, W += ½ (f_n + f_{n+1}) · hΔq (eq. D8): the
  // increment is what the configuration did, so an unresolved velocity oscillation of a
  // stiff mode (ωh ≫ 1) books no spurious work.
  Eigen::VectorXd force_next = work_force(assembly);
  external_work += 0.5 * (last_work_force + force_next).dot(increment);
  last_work_force = std::move(force_next);
  // The dissipative forces' work, booked the same way: D += ½ (f_d,n + f_d,n+1) · hΔq.
  const Eigen::VectorXd& dissipative_next = assembly.dissipative_force();
  physical_dissipation += 0.5 * (last_dissipative_force + dissipative_next).dot(increment);
  last_dissipative_force = dissipative_next;
  // eq. D8a: the loads' and the drivers' work, booked the same way (a driver's force is −Bᵀλ).
  const Eigen::VectorXd& load_next = assembly.external_force();
  load_work += 0.5 * (last_load_force + load_next).dot(increment);
  last_load_force = load_next;
  driver_work -= 0.5 * (last_driver_force + driver_force).dot(increment);
  last_driver_force = std::move(driver_force);
}

// eq. D8: what the integrator dissipated is the work done minus the change of the energy and
// minus what the elements' dissipative forces took.
Energies EnergyBalance::energies(const SystemAssembly& assembly) const {
  const SummedEnergies e = assembly.energies();
  Energies energies{.kinetic = e.kinetic, .strain = e.strain, .gravity = e.gravity, .external_work = external_work,
                    .physical_dissipation = physical_dissipation};
  energies.numerical_dissipation =
      energies.external_work - (energies.total() - initial_energy) - energies.physical_dissipation;
  // eq. D8a: the energy created, the balance in which of the constraints only the drivers work.
  energies.created = (energies.total() - initial_energy) + energies.physical_dissipation - load_work - driver_work;
  energies.scale = scale;
  return energies;
}

void EnergyBalance::widen_scale(const Energies& e) {
  scale = std::max(scale, e.kinetic + std::abs(e.strain) + std::abs(e.gravity - initial_gravity) + std::abs(load_work) +
                              std::abs(driver_work) + e.physical_dissipation);
}

}  // namespace spar::solvers::detail
