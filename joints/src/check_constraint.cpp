#include <spar/joints/check_constraint.hpp>

#include <spar/error.hpp>

#include "evaluation_checks.hpp"

#include <cmath>
#include <string>

namespace spar::joints {

namespace {

constexpr const char* where = "joints::check_constraint";

void check_input(const Constraint& constraint, const ConstraintCheckState& state,
                 const ConstraintCheckOptions& options) {
  const auto refuse = [](const std::string& what, const char* fix) { throw InputError(what, where, fix); };
  for (const double step : {options.step, options.time_step, options.motion_step})
    if (!(step > 0.0 && std::isfinite(step)))
      refuse("a step is " + significant(step), "give positive, finite steps (ConstraintCheckOptions)");
  for (const double bound : {options.tolerance, options.acceleration_tolerance, options.scale_floor})
    if (!(bound >= 0.0))
      refuse("a tolerance or the scale floor is " + significant(bound), "give tolerances and a scale floor ≥ 0");
  const auto dofs = static_cast<Eigen::Index>(state.q.dof_count());
  if (state.velocity.size() != dofs || state.acceleration.size() != dofs)
    refuse("the velocity has " + std::to_string(state.velocity.size()) + " and the acceleration " +
               std::to_string(state.acceleration.size()) + " entries, the configuration " + std::to_string(dofs) +
               " dofs",
           "give both in the configuration's global tangent layout");
  if (state.multipliers.size() != constraint.equation_count())
    refuse("the multipliers have " + std::to_string(state.multipliers.size()) + " entries, the constraint " +
               std::to_string(constraint.equation_count()) + " equations",
           "give one multiplier per equation");
}

}  // namespace

core::DerivativeCheck check_constraint(const Constraint& constraint, const ConstraintCheckState& state,
                                       const ConstraintCheckOptions& options) {
  check_input(constraint, state, options);
  const core::Configuration& q = state.q;
  const double t = state.time;
  const int m = constraint.equation_count();
  // The local size, counting only the blocks q has: the evaluations report a block it lacks.
  Eigen::Index n = 0;
  for (const int b : constraint.blocks())
    if (b >= 0 && b < q.block_count()) n += q.blocks[b].size;
  const Eigen::VectorXd& lambda = state.multipliers;

  Eigen::MatrixXd B(m, n), K(n, n);
  Eigen::VectorXd terms(m), phi_t(m);
  constraint.jacobian(q, t, B);
  constraint.multiplier_tangent(q, t, lambda, K);
  constraint.acceleration_terms(q, state.velocity, t, terms);
  constraint.time_derivative(q, t, phi_t);

  Eigen::VectorXd phi(m), plus(m), minus(m);
  Eigen::MatrixXd B_moved(m, n);
  const auto value = [&](const core::Configuration& p, double time) -> const Eigen::VectorXd& {
    constraint.value(p, time, phi);
    return phi;
  };
  const auto force = [&](const core::Configuration& p) -> Eigen::VectorXd {  // B(p)ᵀλ
    constraint.jacobian(p, t, B_moved);
    return B_moved.transpose() * lambda;
  };

  // Columns i of B and K_λ: central differences along q ⊕ ±ε eᵢ (docs/model.md eq. M1).
  const std::vector<int> dofs = core::block_dofs(q, constraint.blocks());
  Eigen::MatrixXd B_difference(m, n), K_difference(n, n);
  core::Configuration moved = q;
  Eigen::VectorXd increment = Eigen::VectorXd::Zero(q.dof_count());
  Eigen::VectorXd force_plus(n);
  const double e = options.step;
  for (Eigen::Index i = 0; i < n; ++i) {
    const int dof = dofs[static_cast<std::size_t>(i)];
    increment(dof) = e;
    moved.assign_increment(q, increment);
    plus = value(moved, t);
    force_plus = force(moved);
    increment(dof) = -e;
    moved.assign_increment(q, increment);
    minus = value(moved, t);
    increment(dof) = 0.0;
    B_difference.col(i) = (plus - minus) / (2 * e);
    K_difference.col(i) = (force_plus - force(moved)) / (2 * e);
  }

  // Φ̈ at s = 0 along q(s) = q ⊕ (s v + s²/2 a), t + s: (Φ(h) − 2 Φ(0) + Φ(−h)) / h².
  const double h = options.motion_step;
  const auto along = [&](double s) -> const Eigen::VectorXd& {
    moved.assign_increment(q, state.velocity * s + 0.5 * state.acceleration * s * s);
    return value(moved, t + s);
  };
  plus = along(h);
  minus = along(-h);
  const Eigen::VectorXd second_difference = (plus - 2 * value(q, t) + minus) / (h * h);
  Eigen::VectorXd local_acceleration(n);
  core::gather(q, constraint.blocks(), state.acceleration, local_acceleration);
  const Eigen::VectorXd acceleration = B * local_acceleration + terms;

  // Φ_t: (Φ(q, t + δ) − Φ(q, t − δ)) / 2δ.
  const double d = options.time_step;
  plus = value(q, t + d);
  const Eigen::VectorXd time_difference = (plus - value(q, t - d)) / (2 * d);

  core::DerivativeCheck check{.subject = std::string(where) + ", " + detail::type_name(constraint)};
  const auto compare = [&](const char* name, const Eigen::MatrixXd& derivative, const Eigen::MatrixXd& reference,
                           double tolerance) {
    check.comparisons.push_back(core::compare_derivative(name, derivative, reference, tolerance, options.scale_floor));
  };
  compare("Jacobian B", B, B_difference, options.tolerance);
  compare("multiplier tangent K_lambda", K, K_difference, options.tolerance);
  compare("acceleration terms B a + c", acceleration, second_difference, options.acceleration_tolerance);
  compare("time derivative Phi_t", phi_t, time_difference, options.tolerance);
  return check;
}

}  // namespace spar::joints
