#pragma once
/// \file
/// The reaction of a joint: the force and moment its constraint forces exert on one of its frame
/// blocks (docs/joints.md §5).

#include <spar/core/configuration.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

namespace spar::joints {

/// A force and a moment, inertial components, the moment about a stated point.
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< N
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< N m
};

/// What `constraint`, with its multipliers λ (equation_count() entries), exerts on the frame block
/// `node` (one of its blocks()): the equations of motion read M v̇ + … = f_ext − Bᵀλ, so the
/// constraint's generalized force on the node is g = −B_nodeᵀλ, its translation entries the force
/// F (inertial) and its rotation entries the moment about the node's origin x in the material
/// frame, m (virtual work F·δx + m·δφ, δφ material). Returned: F, and the moment about the
/// inertial point `point`, R m + (x − point) × F. The force on the other body of a two-body joint
/// is −F, its moment about the same point −M (the constraint forces are internal). spar::Error
/// when `node` is not a frame block of the constraint or λ has the wrong size.
Wrench reaction(const Constraint& constraint, const core::Configuration& q, double t,
                const Eigen::Ref<const Eigen::VectorXd>& lambda, int node, const Eigen::Vector3d& point);

}  // namespace spar::joints
