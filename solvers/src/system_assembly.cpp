#include "system_assembly.hpp"

#include <spar/core/converged_chart.hpp>
#include <spar/solvers/work_sharing.hpp>
#include <spar/solvers/linear_solver.hpp>
#include <spar/error.hpp>

#include <algorithm>
#include <chrono>

namespace spar::solvers::detail {

namespace {

/// Calls body(i) for i in [0, count): in order on this thread, or when `parallel` in chunks on
/// the shared team (solvers/work_sharing.hpp), whose first exception is rethrown here once every
/// running chunk has finished.
template <class Body>
void for_each_index(int count, bool parallel, const Body& body) {
  if (!parallel) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  solvers::WorkSharing& team = solvers::WorkSharing::shared();
  team.for_each_chunk(count, team.chunk_for(count, 64),
                      [&](int begin, int end, int) {
                        for (int i = begin; i < end; ++i) body(i);
                      });
}

/// global(dofs[i]) += local(i) for every entry of an element's local vector.
void add_local(Eigen::VectorXd& global, const std::vector<int>& dofs, const Eigen::VectorXd& local) {
  for (std::size_t i = 0; i < dofs.size(); ++i) global(dofs[i]) += local(static_cast<Eigen::Index>(i));
}

/// Calls f(row, col) with the local offsets of the rotation entries of every pair of frame blocks
/// among `blocks`.
template <class F>
void for_each_rotation_pair(const core::Configuration& q, const std::vector<int>& blocks, const F& f) {
  Eigen::Index row = 0;
  for (const int a : blocks) {
    if (q.is_frame(a)) {
      Eigen::Index col = 0;
      for (const int b : blocks) {
        if (q.is_frame(b)) f(row + 3, col + 3);
        col += q.blocks[b].size;
      }
    }
    row += q.blocks[a].size;
  }
}

}  // namespace

SystemAssembly::SystemAssembly(core::Model& model, std::vector<joints::Constraint*> constraints,
                               solvers::AssemblyExecution execution)
    : model_(model), constraints_(std::move(constraints)), execution_(execution) {
  for (const joints::Constraint* constraint : constraints_)
    if (!constraint)
      throw Error("null constraint", "solvers::SystemAssembly", "pass joint objects");
  rebuild();
}

void SystemAssembly::rebuild() {
  const core::Configuration& q = model_.state();
  dof_count_ = model_.dof_count();
  std::vector<solvers::PatternBlock> pattern_blocks;
  element_work_.resize(static_cast<std::size_t>(model_.element_count()));
  work_elements_.clear();
  for (int id = 0; id < model_.element_count(); ++id) {
    if (model_.element(id).has_external_force() || model_.element(id).has_dissipation())
      work_elements_.push_back(id);
    element_work_[id].dofs = core::block_dofs(q, model_.element(id).blocks());
    element_work_[id].frozen_mass.resize(0, 0);
    pattern_blocks.push_back(solvers::PatternBlock::element(element_work_[id].dofs));
  }
  multiplier_count_ = 0;
  constraint_work_.resize(constraints_.size());
  for (std::size_t ci = 0; ci < constraints_.size(); ++ci) {
    ConstraintWork& w = constraint_work_[ci];
    for (const int b : constraints_[ci]->blocks())
      if (b < 0 || b >= model_.block_count())
        throw Error("constraint " + std::to_string(ci) + " refers to block " + std::to_string(b) +
                        ", which the model does not have",
                    "solvers::SystemAssembly", "build joints on the model they constrain");
    w.dofs = core::block_dofs(q, constraints_[ci]->blocks());
    w.first_multiplier = multiplier_count_;
    const int m = constraints_[ci]->equation_count();
    multiplier_count_ += m;
    // One square block per constraint over its dofs and its multipliers.
    std::vector<int> dofs = w.dofs;
    for (int i = 0; i < m; ++i) dofs.push_back(dof_count_ + w.first_multiplier + i);
    pattern_blocks.push_back(solvers::PatternBlock::element(std::move(dofs)));
  }
  pattern_ = std::make_unique<solvers::SparsePattern>(size(), pattern_blocks);
  find_substructures();
  residual_ = scale_ = Eigen::VectorXd::Zero(size());
  external_force_ = dissipative_force_ = constraint_force_ = Eigen::VectorXd::Zero(dof_count_);
}

void SystemAssembly::find_substructures() {
  const core::Configuration& q = model_.state();
  // Union–find over blocks: the blocks of one element belong together.
  std::vector<int> root(static_cast<std::size_t>(model_.block_count()), -1);
  const auto find = [&](int b) {
    while (root[b] != b) b = root[b] = root[root[b]];
    return b;
  };
  for (int id = 0; id < model_.element_count(); ++id) {
    const std::vector<int>& blocks = model_.element(id).blocks();
    for (const int b : blocks)
      if (root[b] < 0) root[b] = b;
    for (const int b : blocks) root[find(b)] = find(blocks.front());
  }
  substructures_.assign(static_cast<std::size_t>(size()), interface_unknown);
  for (int b = 0; b < model_.block_count(); ++b)
    if (root[b] >= 0)
      std::fill_n(substructures_.begin() + q.blocks[b].offset, q.blocks[b].size, find(b));
  for (const int dof : model_.fixed_dofs()) substructures_[dof] = fixed_unknown;
}

void SystemAssembly::compute_element(int id, const core::ElementInput& in,
                                     const MatrixCoefficients* c, Chart chart,
                                     const Eigen::VectorXd& increment, bool use_frozen,
                                     Eigen::MatrixXd* K, bool with_energies) {
  const core::Element& element = model_.element(id);
  ElementWork& w = element_work_[id];
  const bool dynamic = in.dynamic();
  core::ElementRequest request;
  request.stiffness = c && c->stiffness != 0.0;
  request.mass = c && dynamic && c->mass != 0.0;
  request.damping = c && dynamic && c->damping != 0.0;
  request.skip_rotation_blocks = use_frozen;
  // A converged step ends on a residual-only evaluation (docs/dynamics.md D4): the energies of
  // the accepted state come from there.
  request.energy = (c == nullptr) && with_energies;
  const int n = static_cast<int>(w.dofs.size());
  w.output.reset(n, request);
  element.evaluate(in, request, w.output);
  const std::vector<int>& blocks = element.blocks();
  if (chart == Chart::converged)
    core::pull_back_to_converged_chart(*in.q, blocks, increment, w.output.residual,
                                       request.stiffness ? &w.output.stiffness : nullptr);
  else if (request.stiffness)
    core::apply_tangent_operator(*in.q, blocks, increment, w.output.stiffness);
  if (!K) return;
  // K arrives zeroed: the usual dynamic case is one fused pass over the three matrices.
  if (request.stiffness && request.mass && request.damping)
    K->noalias() = c->stiffness * w.output.stiffness + c->mass * w.output.mass + c->damping * w.output.damping;
  else {
    if (request.stiffness) *K += c->stiffness * w.output.stiffness;
    if (request.mass) *K += c->mass * w.output.mass;
    if (request.damping) *K += c->damping * w.output.damping;
  }
  if (use_frozen && w.frozen_mass.size() > 0)
    // 003 §5.1: the rotation–rotation blocks J_θ stay those of t = 0.
    for_each_rotation_pair(*in.q, blocks, [&](Eigen::Index r, Eigen::Index s) {
      K->block<3, 3>(r, s) = c->mass * w.frozen_mass.block<3, 3>(r, s) +
                             c->damping * w.frozen_damping.block<3, 3>(r, s) +
                             c->stiffness * w.frozen_stiffness.block<3, 3>(r, s);
    });
}

void SystemAssembly::compute_constraint(int ci, const core::ElementInput& in,
                                        const Eigen::VectorXd& lambda, const MatrixCoefficients* c,
                                        Chart chart, const Eigen::VectorXd& increment,
                                        Eigen::MatrixXd* K) {
  const joints::Constraint& constraint = *constraints_[ci];
  ConstraintWork& w = constraint_work_[ci];
  const int m = constraint.equation_count();
  const int n = static_cast<int>(w.dofs.size());
  const core::Configuration& q = *in.q;
  w.value.resize(m);
  w.jacobian.resize(m, n);
  constraint.value(q, in.time, w.value);
  constraint.jacobian(q, in.time, w.jacobian);
  const auto lambda_c = lambda.segment(w.first_multiplier, m);
  w.force.noalias() = w.jacobian.transpose() * lambda_c;
  const std::vector<int>& blocks = constraint.blocks();
  const bool with_tangent = K && c->stiffness != 0.0;
  if (with_tangent) {
    w.multiplier_tangent.resize(n, n);  // the constraint zeroes it (Constraint::multiplier_tangent)
    constraint.multiplier_tangent(q, in.time, lambda_c, w.multiplier_tangent);
  }
  if (chart == Chart::converged)
    core::pull_back_to_converged_chart(q, blocks, increment, w.force,
                                       with_tangent ? &w.multiplier_tangent : nullptr);
  else if (with_tangent)
    core::apply_tangent_operator(q, blocks, increment, w.multiplier_tangent);
  if (!K) return;
  K->setZero(n + m, n + m);
  if (with_tangent) K->topLeftCorner(n, n) = c->stiffness * w.multiplier_tangent;
  // B in the unknowns: B T(increment) on frame rotation columns, in both charts; the Bᵀλ rows
  // are pulled back in the converged chart only.
  w.mapped_jacobian = w.jacobian;
  core::apply_tangent_operator(q, blocks, increment, w.mapped_jacobian);
  K->bottomLeftCorner(m, n) = w.mapped_jacobian;
  if (chart == Chart::converged)
    K->topRightCorner(n, m) = w.mapped_jacobian.transpose();
  else
    K->topRightCorner(n, m) = w.jacobian.transpose();
}

void SystemAssembly::evaluate(const core::ElementInput& in, const Eigen::VectorXd& lambda,
                              const MatrixCoefficients* c, Chart chart,
                              const Eigen::VectorXd& increment, bool use_frozen,
                              bool with_energies) {
  const int element_count = static_cast<int>(element_work_.size());
  const int total = element_count + static_cast<int>(constraints_.size());
  // `automatic` on a model too small for the parallel evaluation to pay for certain: the faster
  // of the two as timed (execution_choice.hpp).
  const bool parallel_by_size = pattern_->runs_parallel(execution_);
  const bool timed = execution_ == solvers::AssemblyExecution::automatic && !parallel_by_size &&
                     solvers::WorkSharing::shared().thread_count() > 1;
  ExecutionChoice& choice = c ? matrix_execution_ : residual_execution_;
  const bool parallel = timed ? choice.parallel() : parallel_by_size;
  const auto start = std::chrono::steady_clock::now();
  if (c) {
    pattern_->assemble(
        [&](int id, Eigen::MatrixXd& K) {
          if (id < element_count)
            compute_element(id, in, c, chart, increment, use_frozen, &K);
          else
            compute_constraint(id - element_count, in, lambda, c, chart, increment, &K);
        },
        parallel ? solvers::AssemblyExecution::parallel : solvers::AssemblyExecution::serial);
  } else {
    for_each_index(total, parallel, [&](int id) {
      if (id < element_count)
        compute_element(id, in, nullptr, chart, increment, false, nullptr, with_energies);
      else
        compute_constraint(id - element_count, in, lambda, nullptr, chart, increment, nullptr);
    });
  }
  if (timed) choice.record(std::chrono::steady_clock::now() - start);
  // Gather: dynamic rows Σ r_e + Σ Bᵀλ and the size of their terms; constraint rows Φ.
  residual_.setZero();
  scale_.setZero();
  constraint_force_.setZero();
  const bool with_energy = (c == nullptr) && with_energies;
  if (with_energy) {
    external_force_.setZero();
    dissipative_force_.setZero();
  }
  for (const ElementWork& w : element_work_) {
    for (std::size_t i = 0; i < w.dofs.size(); ++i) {
      const double r = w.output.residual(static_cast<Eigen::Index>(i));
      residual_(w.dofs[i]) += r;
      scale_(w.dofs[i]) += std::abs(r);
    }
    if (with_energy) {
      add_local(external_force_, w.dofs, w.output.external_force);
      add_local(dissipative_force_, w.dofs, w.output.dissipative_force);
    }
  }
  for (const ConstraintWork& w : constraint_work_) gather_constraint(w, true);
}

void SystemAssembly::gather_constraint(const ConstraintWork& w, bool with_residual) {
  for (std::size_t i = 0; i < w.dofs.size(); ++i) {
    const double f = w.force(static_cast<Eigen::Index>(i));
    if (with_residual) {
      residual_(w.dofs[i]) += f;
      scale_(w.dofs[i]) += std::abs(f);
    }
    constraint_force_(w.dofs[i]) += f;
  }
  residual_.segment(dof_count_ + w.first_multiplier, w.value.size()) = w.value;
}

void SystemAssembly::evaluate_constraints_and_loads(const core::ElementInput& in,
                                                    const Eigen::VectorXd& lambda,
                                                    const Eigen::VectorXd& increment) {
  constraint_force_.setZero();
  for (int ci = 0; ci < static_cast<int>(constraint_work_.size()); ++ci) {
    compute_constraint(ci, in, lambda, nullptr, Chart::local_increment, increment, nullptr);
    gather_constraint(constraint_work_[ci], false);
  }
  external_force_.setZero();
  dissipative_force_.setZero();
  for (const int id : work_elements_) {
    compute_element(id, in, nullptr, Chart::local_increment, increment, false, nullptr);
    add_local(external_force_, element_work_[id].dofs, element_work_[id].output.external_force);
    add_local(dissipative_force_, element_work_[id].dofs, element_work_[id].output.dissipative_force);
  }
}

void SystemAssembly::evaluate_energies(const core::ElementInput& in) {
  core::ElementRequest request;
  request.residual = false;
  request.energy = true;
  external_force_.setZero();
  dissipative_force_.setZero();
  for (int id = 0; id < static_cast<int>(element_work_.size()); ++id) {
    ElementWork& w = element_work_[id];
    w.output.reset(static_cast<int>(w.dofs.size()), request);
    model_.element(id).evaluate(in, request, w.output);
    add_local(external_force_, w.dofs, w.output.external_force);
    add_local(dissipative_force_, w.dofs, w.output.dissipative_force);
  }
}

void SystemAssembly::freeze(const core::ElementInput& in) {
  const MatrixCoefficients all{.mass = 1.0, .damping = 1.0, .stiffness = 1.0};
  const Eigen::VectorXd no_increment = Eigen::VectorXd::Zero(dof_count_);
  for (int id = 0; id < static_cast<int>(element_work_.size()); ++id) {
    compute_element(id, in, &all, Chart::local_increment, no_increment, false, nullptr);
    ElementWork& w = element_work_[id];
    w.frozen_mass = w.output.mass;
    w.frozen_damping = w.output.damping;
    w.frozen_stiffness = w.output.stiffness;
  }
}

SummedEnergies SystemAssembly::energies() const {
  SummedEnergies sum;
  for (const ElementWork& w : element_work_) {
    sum.kinetic += w.output.energy.kinetic;
    sum.strain += w.output.energy.strain;
    sum.gravity += w.output.energy.gravity;
  }
  return sum;
}

}  // namespace spar::solvers::detail
