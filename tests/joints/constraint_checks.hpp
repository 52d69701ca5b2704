#pragma once
// Property checks run for every joint: its Jacobian, multiplier tangent, acceleration terms and
// time derivative against finite differences of its value along the configuration space's own
// update rule q ⊕ Δ (the installed joints::check_constraint), on random configurations with large
// rotations; and the small evaluation helpers the joint tests share.
#include <spar/core/configuration.hpp>
#include <spar/joints/check_constraint.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/lie/exp.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "random_rotations.hpp"

namespace spar::test {

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

// joints::check_constraint's steps and tolerances, as its defaults. Central differences of
// Φ(q ⊕ εeᵢ) with ε = 1e-6: the truncation error is ε²/6·|Φ‴| ≈ 1e-12·|Φ‴| and the round-off
// u·|terms of Φ|/ε ≈ 1e-16·10/1e-6 = 1e-9 for positions and offsets of size ≤ 10, so 1e-7 relative
// (to max(1, |reference|)) leaves two orders of margin over both; the same for Φ_t with a step 1e-6
// in time. Second central difference along the motion with step 1e-4: truncation h²/12·|Φ⁗| ≈
// 1e-9·|Φ⁗| (|Φ⁗| ≲ 100 for angular velocities ≤ 2 rad/s and offsets ≤ 2), round-off
// 4u·|terms of Φ|/h² ≈ 4e-7 for terms of size ≤ 10: tolerance 2e-6 relative.
inline constexpr joints::ConstraintCheckOptions joint_check_options{
    .step = 1e-6, .time_step = 1e-6, .motion_step = 1e-4, .tolerance = 1e-7,
    .acceleration_tolerance = 2e-6, .scale_floor = 1.0};

/// CHECKs every derivative of `c` at (q, t) with joints::check_constraint and the options above,
/// with random multipliers in [−2, 2], velocities and accelerations in [−1, 1] drawn from `random`.
/// Every block moves along the motion, the joint's and the others (so reading another block's
/// velocity would show).
inline void check_derivatives(const joints::Constraint& c, const core::Configuration& q, double t,
                              RandomRotations& random) {
  const auto draw = [&](Eigen::Index size, double bound) {
    return Eigen::VectorXd(Eigen::VectorXd::NullaryExpr(size, [&] { return random.uniform(-bound, bound); }));
  };
  joints::ConstraintCheckState state{.q = q, .time = t};
  state.multipliers = draw(c.equation_count(), 2);
  state.velocity = draw(q.dof_count(), 1);
  state.acceleration = draw(q.dof_count(), 1);
  const core::DerivativeCheck check = joints::check_constraint(c, state, joint_check_options);
  INFO(check.description());
  CHECK(check.passed());
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
