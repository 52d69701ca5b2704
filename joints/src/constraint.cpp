#include <spar/joints/constraint.hpp>

#include "evaluation_checks.hpp"

namespace spar::joints {

// Every evaluation: the boundary checks of evaluation_checks.hpp, the output zeroed (a joint writes
// only its non-zeros), then the joint's own computation.

void Constraint::value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const {
  detail::check_configuration(*this, q, t, "value");
  detail::check_size(*this, phi.size(), equation_count(), "the output vector", "value");
  phi.setZero();
  compute_value(q, t, phi);
}

void Constraint::jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const {
  const Eigen::Index n = detail::check_configuration(*this, q, t, "jacobian");
  detail::check_shape(*this, B, equation_count(), n, "the Jacobian B", "jacobian");
  B.setZero();
  compute_jacobian(q, t, B);
}

void Constraint::multiplier_tangent(const core::Configuration& q, double t,
                                    const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                    Eigen::Ref<Eigen::MatrixXd> K) const {
  const Eigen::Index n = detail::check_configuration(*this, q, t, "multiplier_tangent");
  detail::check_multipliers(*this, lambda, "multiplier_tangent");
  detail::check_shape(*this, K, n, n, "the multiplier tangent K", "multiplier_tangent");
  K.setZero();
  compute_multiplier_tangent(q, t, lambda, K);
}

void Constraint::acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                    Eigen::Ref<Eigen::VectorXd> c) const {
  detail::check_configuration(*this, q, t, "acceleration_terms");
  detail::check_velocity(*this, q, velocity, "acceleration_terms");
  detail::check_size(*this, c.size(), equation_count(), "the output vector", "acceleration_terms");
  c.setZero();
  compute_acceleration_terms(q, velocity, t, c);
}

void Constraint::time_derivative(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi_t) const {
  detail::check_configuration(*this, q, t, "time_derivative");
  detail::check_size(*this, phi_t.size(), equation_count(), "the output vector", "time_derivative");
  phi_t.setZero();
  compute_time_derivative(q, t, phi_t);
}

}  // namespace spar::joints
