#include <spar/solvers/static_solver.hpp>

#include "round_off.hpp"
#include "system_assembly.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace spar::solvers {

namespace {

double free_norm(const Eigen::VectorXd& v, const std::vector<char>& fixed, int count) {
  double norm = 0.0;
  for (int i = 0; i < count; ++i)
    if (!fixed[i]) norm = std::max(norm, std::abs(v(i)));
  return norm;
}

/// Whether an element's static forces derive from no potential (Element::has_potential, e.g. a
/// moment load): then the energy criterion of stability does not apply (docs/errors.md).
bool has_non_potential_force(const core::Model& model) {
  for (int i = 0; i < model.element_count(); ++i)
    if (!model.element(i).has_potential()) return true;
  return false;
}

/// Newton's method for one load factor, in the chart q = q_n ⊕ φ about the converged state
/// (core/converged_chart.hpp), with the constraints' multipliers as further unknowns.
class NewtonStep {
public:
  NewtonStep(core::Model& model, const std::vector<joints::Constraint*>& constraints,
             const StaticOptions& options)
      : model_(model),
        options_(options),
        assembly_(model, constraints, options.assembly),
        solver_(make_linear_solver(options.linear_solver)),
        fixed_(static_cast<std::size_t>(assembly_.size()), 0),
        lambda_(Eigen::VectorXd::Zero(assembly_.multiplier_count())) {
    for (int dof : model.fixed_dofs()) fixed_[dof] = 1;
    solver_->analyze(assembly_.pattern().matrix());
  }

  const Eigen::VectorXd& multipliers() const { return lambda_; }

  /// The number of negative eigenvalues of the tangent K on the null space of the constraints'
  /// Jacobian B at the converged state, or -1 (see StaticReport::unstable_directions).
  ///
  /// Unconstrained: the negative pivots of K's LDLᵀ (Sylvester's law of inertia). Constrained: by
  /// Finsler's lemma (Debreu 1952), for ρ above a threshold K + ρBᵀB is positive on the range of
  /// Bᵀ and has on null(B) the inertia of K there, so its negative pivots are the count. ρ starts
  /// at 100 max|K_ii| / max (BᵀB)_ii and grows tenfold until two counts agree (the count can only
  /// fall as ρ grows). The saddle-point matrix [K Bᵀ; B 0] in natural order gave the same count
  /// only while K itself was regular: a structure held by a joint alone has rigid modes in K, and
  /// their pivots were zero or round-off (found when an exact zero appeared, issue 17).
  int unstable_directions() {
    if (has_non_potential_force(model_)) return -1;
    Eigen::VectorXd unused = Eigen::VectorXd::Zero(assembly_.size());
    assembly_.pattern().apply_dirichlet(model_.fixed_dofs(), unused);
    const SparseMatrix& A = assembly_.pattern().matrix();
    const SparseMatrix At = A.transpose();
    // The converged chart makes K symmetric at equilibrium up to the residual; a load whose
    // tangent leaves a larger non-symmetric part has no energy whose minimum could be assessed.
    if ((A - At).norm() > 1e-6 * A.norm()) return -1;
    const int n = assembly_.dof_count(), m = assembly_.multiplier_count();
    const SparseMatrix K = (0.5 * (A + At)).topLeftCorner(n, n);
    const auto negative_pivots = [](const SparseMatrix& S) {
      const Eigen::SimplicialLDLT<SparseMatrix> ldlt(S);
      if (ldlt.info() != Eigen::Success) return -1;
      const Eigen::VectorXd& D = ldlt.vectorD();
      if (!D.allFinite() || (D.array() == 0.0).any()) return -1;  // singular: a critical state
      return static_cast<int>((D.array() < 0.0).count());
    };
    if (m == 0) return negative_pivots(K);
    const SparseMatrix B = A.bottomLeftCorner(m, n);
    const SparseMatrix BtB = SparseMatrix(B.transpose()) * B;
    const double b_scale = BtB.diagonal().cwiseAbs().maxCoeff();
    if (!(b_scale > 0.0)) return negative_pivots(K);
    double rho = 100.0 * K.diagonal().cwiseAbs().maxCoeff() / b_scale;
    int previous = negative_pivots(K + rho * BtB);
    for (int attempt = 0; attempt < 8; ++attempt) {
      rho *= 10.0;
      const int count = negative_pivots(K + rho * BtB);
      if (count == previous && count >= 0) return count;
      previous = count;
    }
    return -1;
  }
  void set_multipliers(const Eigen::VectorXd& lambda) { lambda_ = lambda; }

  /// Why the last solve() returned false, for the final error.
  const std::string& failure() const { return failure_; }
  /// Whether it failed because its iterate left the range of double: finite increments summing
  /// to a rotation whose norm overflows (exp cannot take it) or to a non-finite position. At
  /// finite input (Model::check_consistent, the loads' own checks) that is a load no state of
  /// the model balances: a tip force of 1e200 to 1e300 N on a steel cantilever ends here. A
  /// non-finite increment or residual is not counted: a nearly singular tangent gives those too.
  bool overflowed() const { return overflowed_; }

  /// Iterates from the converged state to equilibrium at `load_factor`; false if it does not
  /// converge in max_iterations, an element cannot be evaluated, the tangent is singular at an
  /// iterate or the iterates overflow (the state is then whatever the last iterate was; the
  /// caller restores it). A spar::InputError (a NaN load history) is passed on.
  bool solve(double load_factor, StaticStep& step, StaticReport& report) {
    overflowed_ = false;
    const core::Configuration converged = model_.state();
    const int n = assembly_.dof_count();
    Eigen::VectorXd chart = Eigen::VectorXd::Zero(n), delta(assembly_.size());
    const detail::MatrixCoefficients stiffness_only{.mass = 0.0, .damping = 0.0, .stiffness = 1.0};
    core::ElementInput in;
    in.q = &model_.state();
    in.load_factor = load_factor;
    in.gravity = model_.gravity();
    double increment_norm = INFINITY;
    const bool start_multipliers = assembly_.multiplier_count() > 0 && lambda_.isZero(0.0);
    for (int iteration = 0; iteration <= options_.max_iterations; ++iteration) {
      try {
        assembly_.evaluate(in, lambda_, &stiffness_only, detail::Chart::converged, chart, false);
        if (iteration == 0 && start_multipliers && balancing_multipliers())
          assembly_.evaluate(in, lambda_, &stiffness_only, detail::Chart::converged, chart, false);
      } catch (const InputError&) {
        throw;  // bad input, which a smaller load step cannot help
      } catch (const Error& error) {
        return fail(error.what());  // an element that cannot be evaluated here: cut the load step back
      }
      const Eigen::VectorXd& residual = assembly_.residual();
      const double residual_norm = free_norm(residual, fixed_, n);
      if (!std::isfinite(residual_norm)) return fail("the residual is not finite");
      const double constraint_norm =
          assembly_.multiplier_count() ? residual.tail(assembly_.multiplier_count()).lpNorm<Eigen::Infinity>() : 0.0;
      const double allowed = std::max(options_.residual_tolerance * free_norm(assembly_.scale(), fixed_, n),
                                      detail::residual_round_off_floor(assembly_.pattern().matrix(), model_.state()));
      if (iteration > 0 && residual_norm <= allowed && increment_norm <= options_.increment_tolerance &&
          constraint_norm <= options_.constraint_tolerance) {
        step = {load_factor, iteration, residual_norm, increment_norm};
        return true;
      }
      if (iteration == options_.max_iterations) break;
      delta = -residual;
      assembly_.pattern().apply_dirichlet(model_.fixed_dofs(), delta);
      try {
        solver_->factorize(assembly_.pattern().matrix());
      } catch (const Error& error) {
        return fail(error.what());  // a singular tangent at this iterate: cut the load step back
      }
      ++report.factorizations;
      solver_->solve(delta);
      ++report.newton_iterations;
      if (!delta.allFinite()) return fail("the increment is not finite");
      increment_norm = delta.head(n).lpNorm<Eigen::Infinity>();
      chart += delta.head(n);
      lambda_ += delta.tail(assembly_.multiplier_count());
      // exp of a rotation whose norm overflows (a tip force of 1e200 N) throws: before, out of the
      // solver and past its restore, leaving positions near 1e291 m.
      if (!chart.allFinite() || !std::isfinite(model_.state().largest_rotation(chart))) {
        overflowed_ = true;
        return fail("the iterate left the range of double");
      }
      model_.state().assign_increment(converged, chart);
    }
    return fail("no convergence in " + std::to_string(options_.max_iterations) + " iterations");
  }

private:
  bool fail(std::string why) {
    failure_ = std::move(why);
    return false;
  }

  /// The first load step starts from the multipliers that best balance its load,
  /// λ₀ = argmin ‖Bᵀλ + r‖ over the free dofs (r the residual at λ = 0), from the normal
  /// equations B Bᵀ λ₀ = −B r; false (λ left at 0) when B Bᵀ is singular (redundant
  /// constraints). At λ = 0 the tangent of a constraint that owns a coordinate with neither
  /// stiffness nor mass — a sliding joint's ζ, whose only entry is −x_B,ζζ·λ (docs/joints.md
  /// eq. J26) — is singular, so Newton could not take its first step.
  bool balancing_multipliers() {
    const int n = assembly_.dof_count(), m = assembly_.multiplier_count();
    const Eigen::SparseMatrix<double> A = assembly_.pattern().matrix();
    Eigen::SparseMatrix<double> Bt = A.middleCols(n, m).topRows(n);
    Eigen::VectorXd r = assembly_.residual().head(n);
    for (int dof = 0; dof < n; ++dof)
      if (fixed_[dof]) r(dof) = 0.0;
    for (int k = 0; k < Bt.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(Bt, k); it; ++it)
        if (fixed_[it.row()]) it.valueRef() = 0.0;
    const Eigen::SparseMatrix<double> normal = Bt.transpose() * Bt;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (ldlt.info() != Eigen::Success) return false;
    const Eigen::VectorXd lambda = ldlt.solve(-(Bt.transpose() * r));
    if (ldlt.info() != Eigen::Success || !lambda.allFinite()) return false;
    lambda_ = lambda;
    return true;
  }

  core::Model& model_;
  const StaticOptions& options_;
  detail::SystemAssembly assembly_;
  std::unique_ptr<LinearSolver> solver_;
  std::vector<char> fixed_;
  Eigen::VectorXd lambda_;
  std::string failure_;
  bool overflowed_ = false;
};

void check_options(const StaticOptions& o) {
  if (o.load_steps < 1 || o.max_iterations < 1 || o.max_cutbacks < 0)
    throw Error("load_steps and max_iterations must be at least 1, max_cutbacks at least 0",
                "solvers::solve_static", "fix the StaticOptions");
  if (!(o.residual_tolerance > 0.0) || !(o.increment_tolerance > 0.0) || !(o.constraint_tolerance > 0.0))
    throw Error("the tolerances must be positive numbers", "solvers::solve_static",
                "fix the StaticOptions' tolerances (NaN and values <= 0 are refused)");
}

}  // namespace

StaticReport solve_static(core::Model& model, const StaticOptions& options,
                          const std::vector<joints::Constraint*>& constraints) {
  check_options(options);
  model.check_consistent("solvers::solve_static");
  const auto start = std::chrono::steady_clock::now();
  StaticReport report;
  NewtonStep newton(model, constraints, options);
  double converged_factor = 0.0;
  double increment = 1.0 / options.load_steps;
  // Halvings of the load increment so far. The increment never grows back, so this counts every
  // halving, not only those since the last converged step: near a limit load the steps would
  // otherwise alternate "converged, halved" for ever, the increment shrinking below the load
  // factor's ulp and the loop never ending.
  int halvings = 0;
  while (converged_factor < 1.0) {
    // The last increment lands on 1 exactly: ten steps of 0.1 sum to 0.9999999999999999, which
    // took an eleventh step of 1e-16 (issue 14: StaticReport::steps had one entry too many).
    const double target = 1.0 - converged_factor <= increment * (1 + 1e-9) ? 1.0 : converged_factor + increment;
    const core::Configuration converged = model.state();
    const Eigen::VectorXd converged_lambda = newton.multipliers();
    StaticStep step;
    const auto restore = [&] {
      model.state() = converged;
      newton.set_multipliers(converged_lambda);
    };
    bool solved = false;
    try {
      solved = newton.solve(target, step, report);
    } catch (...) {
      restore();  // every failure leaves the state of the last converged load factor
      throw;
    }
    if (solved) {
      report.steps.push_back(step);
      converged_factor = target;
      continue;
    }
    restore();
    ++report.cutbacks;
    if (++halvings > options.max_cutbacks) {
      std::ostringstream what;
      if (newton.overflowed()) what << "the load is too large for the model: ";
      what << "Newton did not converge from load factor " << converged_factor << " to " << target
           << " with the load increment halved " << options.max_cutbacks << " times; the model keeps the state at the "
           << "last converged load factor " << converged_factor << " (the last attempt: " << newton.failure() << ")";
      throw ConvergenceError(what.str(), "solvers::solve_static",
                             newton.overflowed()
                                 ? "reduce the loads to what the model can carry (check their units)"
                                 : "use more load steps, check supports (an unsupported rigid-body mode "
                                   "makes the tangent singular) and loads",
                             converged_factor);
    }
    increment /= 2;
  }
  report.multipliers = newton.multipliers();
  report.unstable_directions = newton.unstable_directions();
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace spar::solvers
