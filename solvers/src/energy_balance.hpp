#pragma once
// Private to spar_solvers: the energy balance the generalized-α integrator keeps (docs/dynamics.md
// D7–D8).

#include <spar/solvers/generalized_alpha.hpp>

#include "system_assembly.hpp"

#include <Eigen/Core>

namespace spar::solvers::detail {

/// The kinetic, strain and gravity energy of the last residual-only evaluation.
double mechanical_energy(const SystemAssembly& assembly);

/// The forces whose work the balance books, at the last evaluation: the external loads without
/// a potential and the constraint forces −Bᵀλ (non-zero work for drivers only).
Eigen::VectorXd work_force(const SystemAssembly& assembly);

/// The running balance of eq. D8: the energy at t = 0, the work done since, the work of the
/// elements' dissipative forces since (the physical dissipation), and the forces at the last
/// accepted state. A value type, saved and restored with the dynamic state.
struct EnergyBalance {
  double initial_energy = 0.0, external_work = 0.0, physical_dissipation = 0.0;
  Eigen::VectorXd last_work_force, last_dissipative_force;

  /// The forces of the current evaluation become the start of the next step's work (after
  /// initialize(), an event, a structure change).
  void restart(const SystemAssembly& assembly) {
    last_work_force = work_force(assembly);
    last_dissipative_force = assembly.dissipative_force();
  }
  /// Books the work of an accepted step whose increment was hΔq, and restarts there.
  void book_step(const SystemAssembly& assembly, const Eigen::VectorXd& increment);
  /// The energies of the last residual-only evaluation and the balance since t = 0.
  Energies energies(const SystemAssembly& assembly) const;
};

}  // namespace spar::solvers::detail
