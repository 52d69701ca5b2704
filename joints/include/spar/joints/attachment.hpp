#pragma once
/// \file
/// Where a joint grips the model: a point fixed in a node's material frame, or a fixed point of
/// the ground (docs/joints.md §1), and the bookkeeping that maps a joint's nodes to the column
/// blocks of its Jacobian.

#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <string_view>
#include <vector>

namespace spar::joints {

/// A 3-vector that starts at zero: `Offset{}` is (0, 0, 0), where Eigen's default constructor
/// leaves a Vector3d's entries uninitialized (so `Attachment{node, {}}` once gave a garbage offset).
/// Converts from any Eigen 3-vector expression and is used as an Eigen::Vector3d.
struct Offset : Eigen::Vector3d {
  Offset() : Eigen::Vector3d(Eigen::Vector3d::Zero()) {}
  template <class Derived>
  Offset(const Eigen::MatrixBase<Derived>& v) : Eigen::Vector3d(v) {}  // NOLINT: implicit by design
};

/// A point fixed in a frame block's material frame (node ≥ 0: p = x + R·offset, offset material),
/// or a fixed inertial point of the ground (node = −1: p = offset, offset inertial).
/// `Attachment{node}` and `Attachment{node, {}}` are the node itself (offset zero).
struct Attachment {
  int node = -1;
  Offset offset;

  bool on_ground() const { return node < 0; }
};

/// The attachment of node `node` at the inertial point `point` of configuration q0: its material
/// offset is R0ᵀ(point − x0). With node = −1, the ground point `point`. Raises spar::Error when
/// the node does not exist in q0.
Attachment attach_at(int node, const Eigen::Vector3d& point, const core::Configuration& q0);

/// A frame block as a joint sees it: its global block index (−1: the ground) and the first of its
/// six columns in the joint's Jacobian (−1: the ground).
struct JointFrame {
  int node = -1;
  int column = -1;

  bool on_ground() const { return node < 0; }
  /// The first of the frame's three translation columns in the joint's Jacobian.
  int translation_column() const { return column; }
  /// The first of the frame's three rotation columns in the joint's Jacobian.
  int rotation_column() const { return column + 3; }
  /// The frame's material angular velocity Ω in the model's global velocity vector.
  Eigen::Vector3d angular_velocity(const core::Configuration& q,
                                   const Eigen::VectorXd& velocity) const {
    return velocity.segment<3>(q.blocks[node].offset + 3);
  }
};

/// The frames of a joint between two attachments and the node list of the joint (a's node first).
struct JointFrames {
  JointFrame a;
  JointFrame b;
  std::vector<int> nodes;
};

/// Checks that `node` is −1 (ground) or a frame block of q0; raises spar::Error naming `where`
/// otherwise.
void check_node(int node, const core::Configuration& q0, std::string_view where);

/// The frames of a joint between attachments a and b, after checking that both nodes exist in
/// q0, that at least one attachment is on a node, and that the two are not on the same node.
/// Raises spar::Error naming `where` otherwise.
JointFrames joint_frames(const Attachment& a, const Attachment& b, const core::Configuration& q0,
                         std::string_view where);

/// The frame of a joint acting on a single node (which must exist in q0 and not be the ground):
/// block 0. Raises spar::Error naming `where` otherwise.
JointFrame single_node_frame(int node, const core::Configuration& q0, std::string_view where);

/// `point` itself, or a spar::Error naming `where` and the argument `name` when it has a NaN or
/// infinite coordinate (an attachment offset, a point on a line, a ground point).
const Eigen::Vector3d& finite_point(const Eigen::Vector3d& point, std::string_view name, std::string_view where);

/// `direction` / ‖direction‖, or a spar::Error naming `where` and the argument `name` when it is
/// zero or not finite.
Eigen::Vector3d unit_vector(const Eigen::Vector3d& direction, std::string_view name,
                            std::string_view where);

}  // namespace spar::joints
