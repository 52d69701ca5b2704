#pragma once
/// \file
/// The configuration space of a model: nodes in R³ × SO(3) (beam control points, rigid bodies),
/// and the update rule q ⊕ Δ shared by every solver (docs/conventions.md eq. C9).
///
/// Increments and generalized forces are ordered node by node, six per node: three translations
/// (inertial frame) followed by three rotations (material frame, right-trivialized:
/// R ← R exp(Δφ)).

#include <Eigen/Core>

#include <vector>

namespace spar::core {

/// Degrees of freedom per node: 3 translations + 3 rotations.
inline constexpr int dofs_per_node = 6;

/// Positions and rotations of all nodes.
struct Configuration {
  std::vector<Eigen::Vector3d> position;
  std::vector<Eigen::Matrix3d> rotation;

  int node_count() const { return static_cast<int>(position.size()); }
  int dof_count() const { return dofs_per_node * node_count(); }

  /// Adds a node, returns its index.
  int add_node(const Eigen::Vector3d& x, const Eigen::Matrix3d& R);

  /// q ← q ⊕ Δ: x_k += Δx_k, R_k ← R_k exp(Δφ_k). Δ has dof_count() entries.
  void apply_increment(const Eigen::Ref<const Eigen::VectorXd>& delta);
};

}  // namespace spar::core
