// Structure changes during a generalized-α run (docs/model.md, "Structure changes"; docs/dynamics.md
// D6b): a new sparse pattern and symbolic factorization, the state carried across.
#include "integrator.hpp"

#include <string>
#include <vector>

namespace spar::solvers {

/// Blocks or elements the user changed since the last step (Model::replace_element,
/// add_element, replace_state with the same dofs) are taken in before the next step: an element
/// evaluated through a stale pattern would add its rows to another element's dofs. A new number
/// of dofs needs remap(P) first, which carries the state across.
void GeneralizedAlpha::Implementation::take_structure_changes() {
  if (model.structure_version() == structure_version) return;
  if (model.dof_count() != assembly.dof_count())
    throw Error("the model now has " + std::to_string(model.dof_count()) + " dofs, the integrator's state " +
                    std::to_string(assembly.dof_count()),
                "solvers::GeneralizedAlpha::step",
                "after Model::replace_state, call remap(P) with P of (new dofs) x (old dofs)");
  rebuild(nullptr);
}

/// Rebuilds the pattern and the symbolic factorization; carries v, v̇, a through P (if the dof
/// layout changed) and the multipliers of constraints whose equation count is unchanged.
void GeneralizedAlpha::Implementation::rebuild(const Eigen::MatrixXd* P) {
  std::vector<int> old_first, old_count;
  for (std::size_t ci = 0; ci < constraints.size(); ++ci) {
    old_first.push_back(assembly.first_multiplier(static_cast<int>(ci)));
    old_count.push_back(ci + 1 < constraints.size()
                            ? assembly.first_multiplier(static_cast<int>(ci + 1)) - old_first.back()
                            : assembly.multiplier_count() - old_first.back());
  }
  const Eigen::VectorXd old_lambda = state.multipliers;
  assembly.rebuild();
  matrix.analyze(assembly);
  ++counters.pattern_builds;
  structure_version = model.structure_version();
  matrix.invalidate();
  if (P) {
    state.velocity = *P * state.velocity;
    state.acceleration = *P * state.acceleration;
    state.algorithmic_acceleration = *P * state.algorithmic_acceleration;
  }
  state.multipliers = Eigen::VectorXd::Zero(assembly.multiplier_count());
  for (std::size_t ci = 0; ci < constraints.size(); ++ci)
    if (constraints[ci]->equation_count() == old_count[ci])
      state.multipliers.segment(assembly.first_multiplier(static_cast<int>(ci)), old_count[ci]) =
          old_lambda.segment(old_first[ci], old_count[ci]);
  increment = Eigen::VectorXd::Zero(assembly.dof_count());
  solution = Eigen::VectorXd::Zero(assembly.size());
  matrix.freeze(assembly, input(state.time));
  // The balance carries on across the change: a jump of the energy at the event shows in the
  // numerical dissipation, where a user sees it.
  evaluate(state.time, nullptr, 1.0);
  restart_balance();
}

}  // namespace spar::solvers
