// The energy balance of the generalized-α integrator (docs/dynamics.md D7–D8).
#include "energy_balance.hpp"

#include <utility>

namespace spar::solvers::detail {

double mechanical_energy(const SystemAssembly& assembly) {
  const SummedEnergies e = assembly.energies();
  return e.kinetic + e.strain + e.gravity;
}

Eigen::VectorXd work_force(const SystemAssembly& assembly) {
  return assembly.external_force() - assembly.constraint_force();
}

void EnergyBalance::book_step(const SystemAssembly& assembly, const Eigen::VectorXd& increment) {
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
}

// eq. D8: what the integrator dissipated is the work done minus the change of the energy and
// minus what the elements' dissipative forces took.
Energies EnergyBalance::energies(const SystemAssembly& assembly) const {
  const SummedEnergies e = assembly.energies();
  Energies energies{.kinetic = e.kinetic, .strain = e.strain, .gravity = e.gravity, .external_work = external_work,
                    .physical_dissipation = physical_dissipation};
  energies.numerical_dissipation =
      energies.external_work - (energies.total() - initial_energy) - energies.physical_dissipation;
  return energies;
}

}  // namespace spar::solvers::detail
