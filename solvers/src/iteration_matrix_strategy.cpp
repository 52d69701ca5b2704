// The iteration-matrix strategies of the generalized-α integrator (docs/dynamics.md D5, D12).
#include "iteration_matrix_strategy.hpp"

#include <spar/error.hpp>

#include "finite_values.hpp"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace spar::solvers::detail {

namespace {

/// The backward error to which a substructured solve refines a Newton increment (docs/dynamics.md
/// D12): not round-off. The refinement gains in the increment's relative error what it shows in
/// ω, so at 1e-9 an increment of a millimetre is within ~1e-12 m of the exact one, below every
/// test of the iteration, and as accurate as KLU's LU of the whole saddle-point matrix
/// (2e-9…6e-9, tests/solvers/linear_solver_test.cpp). On the truss unit's linear law the first
/// solve leaves 1e-3…1e-5 (the couplings of kN multipliers that P leaves out) and each sweep gains
/// ~1e-4: round-off took three sweeps, 1e-9 takes one or two.
constexpr double newton_refinement_target = 1e-9;

/// What the model's elements say of freedoms they leave without mass (Element::mass_defect),
/// each distinct message once, joined by "; "; empty when there are none.
std::string mass_defects(const core::Model& model) {
  std::vector<std::string> defects;
  for (int i = 0; i < model.element_count(); ++i) {
    std::string defect = model.element(i).mass_defect();
    if (!defect.empty() && std::find(defects.begin(), defects.end(), defect) == defects.end())
      defects.push_back(std::move(defect));
  }
  std::string joined;
  for (const std::string& defect : defects) joined += (joined.empty() ? "" : "; ") + defect;
  return joined;
}

}  // namespace

IterationMatrixStrategy::IterationMatrixStrategy(const DynamicOptions& options, DynamicCounters& counters)
    : options_(options), counters_(counters), solver_(make_linear_solver(options.linear_solver)) {}

void IterationMatrixStrategy::analyze(const SystemAssembly& assembly) {
  const bool substructure = options_.substructuring && options_.iteration_matrix != IterationMatrix::modified;
  solver_->set_substructures(substructure ? assembly.substructures() : std::vector<int>{});
  solver_->set_refinement_target(newton_refinement_target);
  solver_->analyze(assembly.pattern().matrix());
}

bool IterationMatrixStrategy::factorize_step_matrix(SystemAssembly& assembly, const core::Model& model, double time,
                                                    double h) {
  if (options_.iteration_matrix != IterationMatrix::frozen) ++counters_.jtheta_evaluations;
  const auto& matrix = assembly.pattern().matrix();
  if (!all_finite(matrix.valuePtr(), matrix.nonZeros())) return false;
  factorize(assembly, model, time);
  factorized_step_ = h;
  refactor_requested_ = false;
  return true;
}

void IterationMatrixStrategy::factorize(SystemAssembly& assembly, const core::Model& model, double time) {
  if (!model.fixed_dofs().empty()) {
    Eigen::VectorXd unused = Eigen::VectorXd::Zero(assembly.size());
    assembly.pattern().apply_dirichlet(model.fixed_dofs(), unused);
  }
  try {
    solver_->factorize(assembly.pattern().matrix());
  } catch (const Error& error) {
    std::ostringstream what;
    what << "the iteration matrix is singular at t = " << time << " (step " << counters_.steps + 1
         << "): " << error.what();
    const std::string defects = mass_defects(model);
    if (!defects.empty())
      throw Error(what.str() + "; " + defects, "solvers::GeneralizedAlpha",
                  "give the parts named above mass (each says how)");
    throw Error(what.str(), "solvers::GeneralizedAlpha",
                "check for a redundant constraint (e.g. two joints fixing the same freedom) or a "
                "freedom with neither mass nor constraint (e.g. a beam without section inertia, "
                "a massless body's rotation, a coordinate that no constraint involves)");
  }
  ++counters_.factorizations;
  if (solver_->substructured()) ++counters_.substructured_factorizations;
  have_factorization_ = true;
}

}  // namespace spar::solvers::detail
