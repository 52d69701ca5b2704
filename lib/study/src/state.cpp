#include <spar/study/state.hpp>

#include <spar/error.hpp>

#include <algorithm>

namespace spar::study {

State::State(const solvers::GeneralizedAlpha& integrator)
    : time(integrator.time()),
      q(integrator.configuration()),
      velocity(integrator.velocity()),
      multipliers(integrator.multipliers()),
      integrator(integrator) {}

State::State(const solvers::GeneralizedAlpha& integrator, const solvers::Sample& sample)
    : time(sample.time),
      q(sample.q),
      velocity(sample.velocity),
      multipliers(sample.multipliers),
      integrator(integrator),
      energies_(sample.energies) {}

const solvers::Energies& State::energies() const {
  if (!energies_) energies_ = integrator.energies();
  return *energies_;
}

Eigen::VectorXd State::multipliers_of(int c) const {
  if (c < 0 || c >= integrator.constraint_count())
    throw Error("constraint " + std::to_string(c) + " does not exist (the integrator has " +
                    std::to_string(integrator.constraint_count()) + ")",
                "study::State::multipliers_of", "give an index of the integrator's constraint list");
  int first = 0;
  for (int i = 0; i < c; ++i) first += integrator.constraint(i).equation_count();
  return multipliers.segment(first, integrator.constraint(c).equation_count());
}

double State::constraint_residual() const {
  double norm = 0.0;
  for (int c = 0; c < integrator.constraint_count(); ++c) {
    Eigen::VectorXd phi(integrator.constraint(c).equation_count());
    integrator.constraint(c).value(q, time, phi);
    norm = std::max(norm, phi.lpNorm<Eigen::Infinity>());
  }
  return norm;
}

}  // namespace spar::study
