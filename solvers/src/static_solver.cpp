#include <spar/solvers/static_solver.hpp>

#include <spar/core/converged_chart.hpp>
#include <spar/lie/exp.hpp>

#include "round_off.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace spar::solvers {

namespace {

using core::dofs_per_node;

void scatter(const core::NodalContribution& c, double sign, Eigen::VectorXd& global) {
  for (std::size_t I = 0; I < c.nodes.size(); ++I)
    global.segment<dofs_per_node>(dofs_per_node * c.nodes[I]) +=
        sign * c.force.segment<dofs_per_node>(dofs_per_node * I);
}

double free_norm(const Eigen::VectorXd& v, const std::vector<char>& fixed) {
  double norm = 0.0;
  for (int i = 0; i < v.size(); ++i)
    if (!fixed[i]) norm = std::max(norm, std::abs(v(i)));
  return norm;
}

/// Newton's method for one load factor, in the chart q = q_n ⊕ φ about the converged state.
class NewtonStep {
public:
  NewtonStep(core::Model& model, const StaticOptions& options)
      : model_(model),
        options_(options),
        blocks_(model.blocks()),
        pattern_(model.dof_count(), model.pattern_blocks()),
        solver_(make_linear_solver(options.linear_solver)),
        contributions_(blocks_.size()),
        fixed_(model.dof_count(), 0) {
    for (int dof : model.fixed_dofs()) fixed_[dof] = 1;
    solver_->analyze(pattern_.matrix());
  }

  /// Iterates from the converged state to equilibrium at `load_factor`; false if it does not
  /// converge in max_iterations (the state is then whatever the last iterate was).
  bool solve(double load_factor, StaticStep& step, StaticReport& report) {
    const core::Configuration converged = model_.state();
    std::vector<Eigen::Vector3d> phi(model_.node_count(), Eigen::Vector3d::Zero());
    const int n = model_.dof_count();
    Eigen::VectorXd residual(n), internal(n), external(n), delta(n);
    double increment_norm = INFINITY;
    for (int iteration = 0; iteration <= options_.max_iterations; ++iteration) {
      assemble(load_factor, phi, internal, external);
      residual = internal - external;
      const double scale = std::max(free_norm(internal, fixed_), free_norm(external, fixed_));
      const double residual_norm = free_norm(residual, fixed_);
      if (!std::isfinite(residual_norm)) return false;
      const double allowed = std::max(options_.residual_tolerance * scale, detail::residual_round_off_floor(pattern_.matrix(), model_.state()));
      if (iteration > 0 && residual_norm <= allowed &&
          increment_norm <= options_.increment_tolerance) {
        step = {load_factor, iteration, residual_norm, increment_norm};
        return true;
      }
      if (iteration == options_.max_iterations) break;
      delta = -residual;
      pattern_.apply_dirichlet(model_.fixed_dofs(), delta);
      solver_->factorize(pattern_.matrix());
      ++report.factorizations;
      solver_->solve(delta);
      ++report.newton_iterations;
      increment_norm = delta.lpNorm<Eigen::Infinity>();
      for (int k = 0; k < model_.node_count(); ++k) {
        model_.state().position[k] += delta.segment<3>(dofs_per_node * k);
        phi[k] += delta.segment<3>(dofs_per_node * k + 3);
        model_.state().rotation[k] = lie::right_plus(converged.rotation[k], phi[k]);
      }
    }
    return false;
  }

private:
  /// The chart's residual pieces f_int, λ f_ext and the tangent K_φ into the pattern.
  void assemble(double load_factor, const std::vector<Eigen::Vector3d>& phi,
                Eigen::VectorXd& internal, Eigen::VectorXd& external) {
    const core::Configuration& q = model_.state();
    pattern_.assemble(
        [&](int id, Eigen::MatrixXd& K) {
          const core::ModelBlock& block = blocks_[id];
          core::NodalContribution& c = contributions_[id];
          switch (block.kind) {
            case core::ModelBlock::Kind::beam_element:
              core::beam_element_contribution(model_, block.index, block.element, q, true, c);
              break;
            case core::ModelBlock::Kind::rigid_body:  // no stiffness, no force in statics
              c.nodes = {model_.rigid_body(block.index).node};
              c.force = Eigen::VectorXd::Zero(dofs_per_node);
              c.tangent = Eigen::MatrixXd::Zero(dofs_per_node, dofs_per_node);
              break;
            case core::ModelBlock::Kind::load:  // an external force: it enters with a minus sign
              core::load_contribution(model_, model_.loads()[block.index], q, load_factor, true, c,
                                      block.element);
              c.force = -c.force;
              c.tangent = -c.tangent;
              break;
          }
          core::pull_back_to_converged_chart(phi, c);
          K = c.tangent;
        },
        options_.assembly);
    internal.setZero();
    external.setZero();
    for (std::size_t id = 0; id < blocks_.size(); ++id) {
      const bool is_load = blocks_[id].kind == core::ModelBlock::Kind::load;
      scatter(contributions_[id], is_load ? -1.0 : 1.0, is_load ? external : internal);
    }
    core::NodalContribution load_force;
    for (const core::Load& load : model_.loads()) {
      if (core::load_has_tangent(load)) continue;
      core::load_contribution(model_, load, q, load_factor, false, load_force);
      core::pull_back_to_converged_chart(phi, load_force);
      scatter(load_force, 1.0, external);
    }
  }

  core::Model& model_;
  const StaticOptions& options_;
  std::vector<core::ModelBlock> blocks_;
  core::SparsePattern pattern_;
  std::unique_ptr<LinearSolver> solver_;
  std::vector<core::NodalContribution> contributions_;
  std::vector<char> fixed_;
};

}  // namespace

StaticReport solve_static(core::Model& model, const StaticOptions& options) {
  if (options.load_steps < 1 || options.max_iterations < 1 || options.max_cutbacks < 0)
    throw Error("load_steps and max_iterations must be at least 1, max_cutbacks at least 0",
                "solvers::solve_static", "fix the StaticOptions");
  const auto start = std::chrono::steady_clock::now();
  StaticReport report;
  NewtonStep newton(model, options);
  double converged_factor = 0.0;
  double increment = 1.0 / options.load_steps;
  int cutbacks_in_step = 0;
  while (converged_factor < 1.0) {
    const double target = std::min(1.0, converged_factor + increment);
    const core::Configuration converged = model.state();
    StaticStep step;
    if (newton.solve(target, step, report)) {
      report.steps.push_back(step);
      converged_factor = target;
      cutbacks_in_step = 0;
      continue;
    }
    model.state() = converged;
    ++report.cutbacks;
    if (++cutbacks_in_step > options.max_cutbacks) {
      std::ostringstream what;
      what << "Newton did not converge from load factor " << converged_factor << " to " << target
           << " after " << options.max_cutbacks << " cut-backs; the model keeps the state at the "
           << "last converged load factor " << converged_factor;
      throw ConvergenceError(what.str(), "solvers::solve_static",
                             "use more load steps, check supports (an unsupported rigid-body mode "
                             "makes the tangent singular) and loads",
                             converged_factor);
    }
    increment /= 2;
  }
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace spar::solvers
