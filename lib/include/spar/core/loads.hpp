#pragma once
/// \file
/// External loads on the nodes and beams of a model (003 eq. 33). A load contributes to the
/// generalized external force (local-increment components, core/configuration.hpp) and, where it
/// depends on the configuration, to the tangent.

#include <Eigen/Core>

#include <variant>

namespace spar::core {

/// The frame a moment's components are given in.
enum class MomentFrame {
  material,  ///< follower: fixed components in the cross-section's frame (003 eq. 33, P)
  inertial,  ///< dead: fixed components in the inertial frame
};

/// A concentrated force on a node, in the inertial frame (dead load).
struct NodalForce {
  int node = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
};

/// A concentrated moment on a node (a beam's end control point carries the end section's moment).
struct NodalMoment {
  int node = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  MomentFrame frame = MomentFrame::material;
};

/// A force per unit reference length on a whole beam, in the inertial frame (dead load); gravity
/// is force_per_length = ρA g.
struct DistributedForce {
  int beam = 0;
  Eigen::Vector3d force_per_length = Eigen::Vector3d::Zero();
};

/// A moment per unit reference length on a whole beam: material frame (follower, 003 eq. 33's
/// P) or inertial frame (dead). Its generalized force and tangent: core/distributed_moment.hpp.
struct DistributedMoment {
  int beam = 0;
  Eigen::Vector3d moment_per_length = Eigen::Vector3d::Zero();
  MomentFrame frame = MomentFrame::material;
};

using Load = std::variant<NodalForce, NodalMoment, DistributedForce, DistributedMoment>;

}  // namespace spar::core
