#pragma once
/// \file
/// The energy account of a run whose layout changes on the way: a cable's length-control events
/// and a released mass (paper 000 §5–6), or any remeshing carried across by
/// GeneralizedAlpha::remap. Between changes a conservative run (ρ∞ = 1) holds its total energy to
/// Newton's tolerance; a change moves it by what the new discretization stores differently (000
/// Table 2's energy jumps). The ledger keeps the two apart: the drift since the start, the drift
/// since the last change, and the jump at each change.
///
///     study::EnergyLedger ledger(integrator);  // after the first initialize()
///     // after each step:
///     ledger.after_step();
///     if (cable.control_length(model, integrator.time(), P)) ledger.restart(P);

#include <spar/solvers/generalized_alpha.hpp>

#include <Eigen/Core>

namespace spar::study {

class EnergyLedger {
public:
  /// Starts the account at the integrator's present total energy E(0).
  explicit EnergyLedger(solvers::GeneralizedAlpha& integrator);

  /// After a step: the largest kinetic energy, |E − E(0)| and |E − E(last restart)| so far.
  void after_step();
  /// Carries the run to the new layout (GeneralizedAlpha::remap with P, new dofs × old dofs) and
  /// restarts the accelerations on the new system (initialize()); returns the total energy's
  /// change across it, E after − E before (before: at the last after_step() or restart()). The
  /// drift between restarts is measured from the energy after it.
  double restart(const Eigen::MatrixXd& P);

  double max_kinetic() const { return max_kinetic_; }
  /// max |E − E(0)| over the steps.
  double max_drift() const { return max_drift_; }
  /// max |E − E(last restart)| over the steps (E(0) before the first restart).
  double max_drift_between_restarts() const { return max_drift_between_restarts_; }
  /// max |E after − E before| over the restarts (0 without one).
  double max_jump() const { return max_jump_; }

private:
  solvers::GeneralizedAlpha& integrator_;
  double initial_ = 0.0, current_ = 0.0, restarted_at_ = 0.0;
  double max_kinetic_ = 0.0, max_drift_ = 0.0, max_drift_between_restarts_ = 0.0, max_jump_ = 0.0;
};

}  // namespace spar::study
