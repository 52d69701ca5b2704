#pragma once
// Property checks run for every joint: its Jacobian, multiplier tangent, acceleration terms and
// time derivative against finite differences of its value along the configuration space's own
// update rule q ⊕ Δ, on random configurations with large rotations.
#include <spar/core/configuration.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/lie/exp.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "random_rotations.hpp"

namespace spar::test {

// Central differences of Φ(q ⊕ εeᵢ) with ε = 1e-6: the truncation error is ε²/6·|Φ‴| ≈ 1e-12·|Φ‴|
// and the round-off u·|terms of Φ|/ε ≈ 1e-16·10/1e-6 = 1e-9 for positions and offsets of size ≤ 10,
// so 1e-7 relative (to max(1, |reference|)) leaves two orders of margin over both.
inline constexpr double fd_step = 1e-6;
inline constexpr double fd_tolerance = 1e-7;
// Second central difference in time with step 1e-4: truncation h²/12·|Φ⁗| ≈ 1e-9·|Φ⁗| (|Φ⁗| ≲ 100
// for angular velocities ≤ 2 rad/s and offsets ≤ 2), round-off 4u·|terms of Φ|/h² ≈ 4e-7 for terms
// of size ≤ 10: tolerance 2e-6 relative.
inline constexpr double acceleration_step = 1e-4;
inline constexpr double acceleration_tolerance = 2e-6;
// First central difference in time with step 1e-6, as fd_tolerance.
inline constexpr double time_step = 1e-6;

/// max |analytic − reference| / max(1, max |reference|).
inline double relative_error(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& reference) {
  const double scale = std::max(1.0, reference.cwiseAbs().maxCoeff());
  return (analytic - reference).cwiseAbs().maxCoeff() / scale;
}

/// `count` nodes with positions in [−2, 2]³ and random rotations (angles over [0, π], some within
/// 1e-10 of 0 or π).
inline core::Configuration random_configuration(int count, RandomRotations& random) {
  core::Configuration q;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d x(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
    q.add_frame(x, lie::exp(random.rotation_vector()));
  }
  return q;
}

inline Eigen::Vector3d random_vector(RandomRotations& random, double size) {
  return {random.uniform(-size, size), random.uniform(-size, size), random.uniform(-size, size)};
}

/// q ⊕ Δ for the increment Δ of the constraint's local dofs (the increments of its blocks, block
/// after block: 6 for a frame, n for a vector block).
inline core::Configuration plus(const core::Configuration& q, const std::vector<int>& blocks,
                                const Eigen::VectorXd& local) {
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(q.dof_count());
  Eigen::Index column = 0;
  for (const int b : blocks) {
    delta.segment(q.blocks[b].offset, q.blocks[b].size) = local.segment(column, q.blocks[b].size);
    column += q.blocks[b].size;
  }
  core::Configuration result = q;
  result.apply_increment(delta);
  return result;
}

/// The number of local dofs of a constraint in q.
inline Eigen::Index local_dofs(const joints::Constraint& c, const core::Configuration& q) {
  return core::block_dof_count(q, c.blocks());
}

inline Eigen::VectorXd value(const joints::Constraint& c, const core::Configuration& q, double t) {
  Eigen::VectorXd phi(c.equation_count());
  c.value(q, t, phi);
  return phi;
}

inline Eigen::MatrixXd jacobian(const joints::Constraint& c, const core::Configuration& q,
                                double t) {
  Eigen::MatrixXd B(c.equation_count(), local_dofs(c, q));
  c.jacobian(q, t, B);
  return B;
}

/// Column i: (f(q ⊕ εeᵢ) − f(q ⊕ −εeᵢ)) / 2ε over the constraint's local dofs.
template <class F>
Eigen::MatrixXd central_difference(const joints::Constraint& c, const core::Configuration& q,
                                   F&& f) {
  const Eigen::Index n = local_dofs(c, q);
  Eigen::MatrixXd D;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::VectorXd step = fd_step * Eigen::VectorXd::Unit(n, i);
    const Eigen::VectorXd column =
        (f(plus(q, c.blocks(), step)) - f(plus(q, c.blocks(), -step))) / (2 * fd_step);
    if (i == 0) D.resize(column.size(), n);
    D.col(i) = column;
  }
  return D;
}

/// The errors of one constraint's derivatives at (q, t) against finite differences.
struct DerivativeErrors {
  double jacobian = 0;
  double multiplier_tangent = 0;
  double acceleration_terms = 0;
  double time_derivative = 0;
};

/// B, K, c and Φ_t of `c` at (q, t) against central differences, with random multipliers,
/// velocities and accelerations drawn from `random`.
inline DerivativeErrors derivative_errors(const joints::Constraint& c, const core::Configuration& q,
                                          double t, RandomRotations& random) {
  DerivativeErrors errors;
  const int m = c.equation_count();
  const Eigen::Index n = local_dofs(c, q);

  // B = ∂Φ(q ⊕ Δ)/∂Δ.
  const Eigen::MatrixXd B = jacobian(c, q, t);
  errors.jacobian = relative_error(
      B, central_difference(c, q, [&](const core::Configuration& p) { return value(c, p, t); }));

  // K = ∂(B(q ⊕ Δ)ᵀλ)/∂Δ.
  const Eigen::VectorXd lambda =
      Eigen::VectorXd::NullaryExpr(m, [&] { return random.uniform(-2, 2); });
  Eigen::MatrixXd K(n, n);
  c.multiplier_tangent(q, t, lambda, K);
  errors.multiplier_tangent =
      relative_error(K, central_difference(c, q, [&](const core::Configuration& p) {
                       return Eigen::VectorXd(jacobian(c, p, t).transpose() * lambda);
                     }));

  // Φ̈ = B v̇ + c along x(s) = x + v s + ½ a s², R(s) = R exp(Ω s + ½ α s²), p(s) = p + v s + ½ a s²
  // for vector blocks, every block moving (blocks outside the joint too, so reading another
  // block's velocity would show).
  const Eigen::VectorXd velocity =
      Eigen::VectorXd::NullaryExpr(q.dof_count(), [&] { return random.uniform(-1, 1); });
  const Eigen::VectorXd acceleration =
      Eigen::VectorXd::NullaryExpr(q.dof_count(), [&] { return random.uniform(-1, 1); });
  const auto moved = [&](double s) {
    core::Configuration p = q;
    const Eigen::VectorXd d = velocity * s + 0.5 * acceleration * s * s;
    for (int k = 0; k < q.block_count(); ++k) {
      const core::Block& b = q.blocks[k];
      if (q.is_frame(k)) {
        p.position[k] += d.segment<3>(b.offset);
        p.rotation[k] = q.rotation[k] * lie::exp(Eigen::Vector3d(d.segment<3>(b.offset + 3)));
      } else {
        p.vector(k) += d.segment(b.offset, b.size);
      }
    }
    return value(c, p, t + s);
  };
  const double h = acceleration_step;
  const Eigen::VectorXd second_difference = (moved(h) - 2 * moved(0) + moved(-h)) / (h * h);
  Eigen::VectorXd local_acceleration(n);
  core::gather(q, c.blocks(), acceleration, local_acceleration);
  Eigen::VectorXd terms(m);
  c.acceleration_terms(q, velocity, t, terms);
  errors.acceleration_terms = relative_error(B * local_acceleration + terms, second_difference);

  // Φ_t at fixed q.
  Eigen::VectorXd phi_t(m);
  c.time_derivative(q, t, phi_t);
  errors.time_derivative = relative_error(
      phi_t, (value(c, q, t + time_step) - value(c, q, t - time_step)) / (2 * time_step));
  return errors;
}

/// CHECKs every derivative of `c` at (q, t) against its finite-difference tolerance.
inline void check_derivatives(const joints::Constraint& c, const core::Configuration& q, double t,
                              RandomRotations& random) {
  const DerivativeErrors errors = derivative_errors(c, q, t, random);
  CHECK(errors.jacobian <= fd_tolerance);
  CHECK(errors.multiplier_tangent <= fd_tolerance);
  CHECK(errors.acceleration_terms <= acceleration_tolerance);
  CHECK(errors.time_derivative <= fd_tolerance);
}

}  // namespace spar::test

namespace spar::test {

/// q with node `node` turned rigidly by exp(rotation_vector) (inertial) about the inertial point
/// `center`: x ← c + Q(x − c), R ← Q R.
inline core::Configuration rotate_node_about(const core::Configuration& q, int node,
                                             const Eigen::Vector3d& center,
                                             const Eigen::Vector3d& rotation_vector) {
  const Eigen::Matrix3d Q = lie::exp(rotation_vector);
  core::Configuration result = q;
  result.position[node] = center + Q * (q.position[node] - center);
  result.rotation[node] = Q * q.rotation[node];
  return result;
}

}  // namespace spar::test
