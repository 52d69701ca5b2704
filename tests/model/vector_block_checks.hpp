#pragma once
// Finite-difference checks of elements and constraints whose blocks are all vector blocks (so
// q ⊕ Δ is q + Δ): an element's stiffness, damping and mass against central differences of its
// own residual in q, v and v̇; a constraint's Jacobian, multiplier tangent and acceleration terms
// against differences of its value.
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace spar::test {

// Central differences with step ε = 1e-6 on coordinates, velocities and accelerations of size
// ≲ 10: the truncation error ε²/6·|f‴| ≈ 2e-12·|f‴| and the round-off u·|f|/ε ≈ 1e-16·100/1e-6 =
// 1e-8 for residual terms of size ≤ 100 (k ≤ 100 N/m times lengths ≤ 1), so 1e-7 relative to
// max(1, |reference|) leaves an order of magnitude over both.
inline constexpr double vector_fd_step = 1e-6;
inline constexpr double vector_fd_tolerance = 1e-7;
// Second central difference in time with τ = 1e-4 along q + v τ: truncation τ²/12·|Φ⁗| ≈ 1e-9
// for |Φ⁗| ≲ 10, round-off 4u·|Φ terms|/τ² ≈ 4e-16·10/1e-8 = 4e-7: tolerance 2e-6 relative.
inline constexpr double vector_acceleration_step = 1e-4;
inline constexpr double vector_acceleration_tolerance = 2e-6;

/// max |analytic − reference| / max(1, max |reference|).
inline double relative_difference(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& reference) {
  return (analytic - reference).cwiseAbs().maxCoeff() / std::max(1.0, reference.cwiseAbs().maxCoeff());
}

/// Everything an element is evaluated at, in the global layout of q.
struct ElementState {
  core::Configuration q;
  Eigen::VectorXd velocity, acceleration;
  double time = 0.0;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
};

/// The element's output at `s` for `request` (dynamic evaluation).
inline core::ElementOutput evaluate(const core::Element& element, const ElementState& s,
                                    const core::ElementRequest& request) {
  core::ElementInput in;
  in.q = &s.q;
  in.velocity = &s.velocity;
  in.acceleration = &s.acceleration;
  in.time = s.time;
  in.gravity = s.gravity;
  core::ElementOutput out;
  out.reset(core::block_dof_count(s.q, element.blocks()), request);
  element.evaluate(in, request, out);
  return out;
}

/// Which argument of the residual a difference is taken in.
enum class Argument { coordinates, velocity, acceleration };

/// Column i: (r(· + εeᵢ) − r(· − εeᵢ))/2ε over the element's local dofs, in `argument`.
inline Eigen::MatrixXd residual_difference(const core::Element& element, const ElementState& s,
                                           Argument argument) {
  const std::vector<int> dofs = core::block_dofs(s.q, element.blocks());
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd D(n, n);
  for (int i = 0; i < n; ++i) {
    ElementState plus = s, minus = s;
    auto entry = [&](ElementState& state) -> double& {
      switch (argument) {
        case Argument::coordinates: return state.q.values(dofs[i]);
        case Argument::velocity: return state.velocity(dofs[i]);
        case Argument::acceleration: break;
      }
      return state.acceleration(dofs[i]);
    };
    entry(plus) += vector_fd_step;
    entry(minus) -= vector_fd_step;
    D.col(i) = (evaluate(element, plus, {}).residual - evaluate(element, minus, {}).residual) /
               (2 * vector_fd_step);
  }
  return D;
}

inline Eigen::VectorXd constraint_value(const joints::Constraint& c, const core::Configuration& q, double t) {
  Eigen::VectorXd phi(c.equation_count());
  c.value(q, t, phi);
  return phi;
}

inline Eigen::MatrixXd constraint_jacobian(const joints::Constraint& c, const core::Configuration& q,
                                           double t) {
  Eigen::MatrixXd B(c.equation_count(), core::block_dof_count(q, c.blocks()));
  c.jacobian(q, t, B);
  return B;
}

/// Column i: (f(q + εeᵢ) − f(q − εeᵢ))/2ε over the constraint's local dofs.
template <class F>
Eigen::MatrixXd constraint_difference(const joints::Constraint& c, const core::Configuration& q, F&& f) {
  const std::vector<int> dofs = core::block_dofs(q, c.blocks());
  Eigen::MatrixXd D;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    core::Configuration plus = q, minus = q;
    plus.values(dofs[i]) += vector_fd_step;
    minus.values(dofs[i]) -= vector_fd_step;
    const Eigen::VectorXd column = (f(plus) - f(minus)) / (2 * vector_fd_step);
    if (i == 0) D.resize(column.size(), static_cast<Eigen::Index>(dofs.size()));
    D.col(static_cast<Eigen::Index>(i)) = column;
  }
  return D;
}

/// Φ̈ along q(τ) = q + v τ (no acceleration, so Φ̈ = c) by the second central difference.
inline Eigen::VectorXd acceleration_terms_difference(const joints::Constraint& c,
                                                     const core::Configuration& q,
                                                     const Eigen::VectorXd& velocity, double t) {
  const double tau = vector_acceleration_step;
  core::Configuration plus = q, minus = q;
  plus.values += tau * velocity;
  minus.values -= tau * velocity;
  return (constraint_value(c, plus, t) - 2 * constraint_value(c, q, t) + constraint_value(c, minus, t)) /
         (tau * tau);
}

}  // namespace spar::test
