#pragma once
/// \file
/// External loads on the nodes and beams of a model (003 eq. 33). A load contributes to the
/// generalized external force (local-increment components, core/configuration.hpp) and, where it
/// depends on the configuration, to the tangent. The loads family's builder, core::add_load,
/// adds a load to a model as elements (elements/loads/load_elements.hpp).

#include <spar/core/model.hpp>

#include <Eigen/Core>

#include <functional>
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
/// P) or inertial frame (dead). Its generalized force and tangent: elements/beam/distributed_moment.hpp.
struct DistributedMoment {
  int beam = 0;
  Eigen::Vector3d moment_per_length = Eigen::Vector3d::Zero();
  MomentFrame frame = MomentFrame::material;
};

using Load = std::variant<NodalForce, NodalMoment, DistributedForce, DistributedMoment>;

/// Whether a load is a moment (nodal or distributed, material or inertial): such a moment does
/// no work that a potential gives for 3D rotations.
inline bool is_moment(const Load& load) {
  return std::holds_alternative<NodalMoment>(load) || std::holds_alternative<DistributedMoment>(load);
}

/// A factor multiplying a load in time (dynamics); an empty function means 1.
using LoadHistory = std::function<double(double)>;

/// Adds an external load to `model` as elements (a distributed load: one per element of its
/// beam), scaled in statics by the load factor and in dynamics by `history(t)`; returns the
/// load's index. Throws spar::Error for a node or beam that does not exist, a node that is not a
/// frame, or a non-finite load, and then leaves the model as it was. A history that is not finite
/// at an evaluation is a spar::InputError there, in statics at t = 0.
int add_load(Model& model, const Load& load, LoadHistory history = {});
/// The loads added to `model` so far.
int load_count(const Model& model);

}  // namespace spar::core
