#pragma once
/// \file
/// The rigid-body family's builder: a rigid body is one frame block at its centre of mass and one
/// RigidBodyElement (M = diag(m I, J), f_gyr = (0, Ω × JΩ), its weight m g).

#include <spar/core/frame_inertia.hpp>
#include <spar/core/model.hpp>

#include <Eigen/Core>

namespace spar::core {

/// A rigid body to add: its centre of mass and orientation at t = 0, mass, and inertia tensor
/// about the centre of mass in the body frame. Joints attach to points given relative to the
/// centre of mass (the node), so a body whose reference point is not its centre of mass is
/// described by offsetting its attachment points.
struct RigidBodyParameters {
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// A rigid body of a model: its frame block at the centre of mass, mass and inertia tensor about
/// the centre of mass in the body frame.
struct RigidBody {
  int node = 0;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// Adds a rigid body (one frame block at its centre of mass, one RigidBodyElement) to `model`;
/// returns the body's index. Throws spar::Error for a non-positive or non-finite mass, an inertia
/// that is not symmetric positive definite, or a centre of mass that is not finite.
int add_rigid_body(Model& model, const RigidBodyParameters& parameters);
/// The rigid bodies added to `model` so far.
int rigid_body_count(const Model& model);
/// Rigid body b of `model`; throws spar::Error for an index that does not exist.
const RigidBody& rigid_body(const Model& model, int b);

/// The inertia of a rigid body: one frame, M = diag(m I, J), f_gyr = (0, Ω × JΩ).
FrameInertia rigid_body_inertia(const RigidBody& body);

}  // namespace spar::core
