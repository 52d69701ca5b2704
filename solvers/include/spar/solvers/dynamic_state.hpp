#pragma once
/// \file
/// The state the Lie-group generalized-α integrator advances (docs/dynamics.md, eqs. D1–D3; 003
/// eq. 49): the configuration and the four vectors of the update relations.

#include <spar/core/configuration.hpp>

#include <Eigen/Core>

namespace spar::solvers {

/// The dynamic state at one time. A value type: a copy is a snapshot of everything a step changes
/// in the motion, an assignment restores it. Velocities, accelerations and the algorithmic
/// acceleration live in the global tangent layout of `q` (frames: ẋ inertial, Ω material; vector
/// blocks: ṗ); the multipliers constraint by constraint.
struct DynamicState {
  double time = 0.0;
  core::Configuration q;
  Eigen::VectorXd velocity;                  ///< v
  Eigen::VectorXd acceleration;              ///< v̇
  /// a of the update relations (eq. D3): a_{n+1} follows (1 − α_m) a_{n+1} + α_m a_n =
  /// (1 − α_f) v̇_{n+1} + α_f v̇_n, an O(h)-shifted mean of v̇ (a = v̇ at a consistent start).
  Eigen::VectorXd algorithmic_acceleration;
  Eigen::VectorXd multipliers;               ///< λ
};

}  // namespace spar::solvers
