#pragma once
// Private to spar_solvers: the energy balance the generalized-α integrator keeps (docs/dynamics.md
// D7–D8).

#include <spar/solvers/generalized_alpha.hpp>

#include "system_assembly.hpp"

#include <Eigen/Core>

#include <vector>

namespace spar::solvers::detail {

/// The kinetic, strain and gravity energy of the last residual-only evaluation.
double mechanical_energy(const SystemAssembly& assembly);

/// The forces whose work the balance books, at the last evaluation: the external loads without
/// a potential and the constraint forces −Bᵀλ (non-zero work for drivers only).
Eigen::VectorXd work_force(const SystemAssembly& assembly);

/// Σ Bᵀλ of the drivers at the last evaluation (global tangent layout): the constraints whose
/// equations depend on time, Φ_t(q, t) ≠ 0 now or at an earlier accepted state (`driven`, a flag
/// per constraint that this sets). A passive joint's forces do no work on the constraint manifold
/// (their power −λᵀBv = λᵀΦ_t is zero), so they are left out.
Eigen::VectorXd driver_force(const SystemAssembly& assembly, const core::Configuration& q, double t,
                             std::vector<bool>& driven);

/// The running balance of eq. D8: the energy at t = 0, the work done since, the work of the
/// elements' dissipative forces since (the physical dissipation), and the forces at the last
/// accepted state. A value type, saved and restored with the dynamic state.
///
/// Beside it, the energy the integrator created (eq. D8a, the alarm's measure): the same balance
/// with the drivers' forces alone doing work, so that a passive joint does none and the spurious
/// work of its forces in an unstable run counts as what it is, energy the method made.
struct EnergyBalance {
  double initial_energy = 0.0, external_work = 0.0, physical_dissipation = 0.0;
  Eigen::VectorXd last_work_force, last_dissipative_force;
  /// The loads' work alone and the drivers' (external_work without the passive joints' forces),
  /// booked along the increments like external_work (eq. D8a).
  double load_work = 0.0, driver_work = 0.0;
  /// The gravity potential at t = 0 and the energy scale of the accepted states so far (eq. D8a).
  double initial_gravity = 0.0, scale = 0.0;
  Eigen::VectorXd last_load_force, last_driver_force;
  std::vector<bool> driven;  ///< per constraint: its Φ_t was not zero at an accepted state

  /// The forces of the current evaluation (`driver_force` the drivers' part of the constraint
  /// forces) become the start of the next step's work (after initialize(), an event, a structure
  /// change).
  void restart(const SystemAssembly& assembly, Eigen::VectorXd driver_force) {
    last_work_force = work_force(assembly);
    last_dissipative_force = assembly.dissipative_force();
    last_load_force = assembly.external_force();
    last_driver_force = std::move(driver_force);
  }
  /// Forgets the forces of the last state (the auxiliary step of the perturbed starting values
  /// books against nothing).
  void clear_forces(int dofs) {
    last_work_force = last_dissipative_force = last_load_force = last_driver_force = Eigen::VectorXd::Zero(dofs);
  }
  /// Books the work of an accepted step whose increment was hΔq, and restarts there.
  void book_step(const SystemAssembly& assembly, const Eigen::VectorXd& increment, Eigen::VectorXd driver_force);
  /// The energies of the last residual-only evaluation and the balance since t = 0.
  Energies energies(const SystemAssembly& assembly) const;
  /// Takes the energies of an accepted state into the scale (eq. D8a).
  void widen_scale(const Energies& energies);
};

}  // namespace spar::solvers::detail
