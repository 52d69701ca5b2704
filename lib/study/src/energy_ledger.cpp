#include <spar/study/energy_ledger.hpp>

#include <algorithm>
#include <cmath>

namespace spar::study {

EnergyLedger::EnergyLedger(solvers::GeneralizedAlpha& integrator)
    : integrator_(integrator), initial_(integrator.energies().total()), current_(initial_), restarted_at_(initial_) {}

void EnergyLedger::after_step() {
  const solvers::Energies energy = integrator_.energies();
  current_ = energy.total();
  max_kinetic_ = std::max(max_kinetic_, energy.kinetic);
  max_drift_ = std::max(max_drift_, std::fabs(current_ - initial_));
  max_drift_between_restarts_ = std::max(max_drift_between_restarts_, std::fabs(current_ - restarted_at_));
}

double EnergyLedger::restart(const Eigen::MatrixXd& P) {
  const double before = current_;
  integrator_.remap(P);
  integrator_.initialize();
  current_ = restarted_at_ = integrator_.energies().total();
  max_jump_ = std::max(max_jump_, std::fabs(current_ - before));
  return current_ - before;
}

}  // namespace spar::study
