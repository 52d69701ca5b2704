#pragma once
/// \file
/// spar::joints — the constraint interface, its kinematic building blocks, the joints and the
/// drivers. Equations: docs/joints.md.

#include <spar/joints/active_until.hpp>
#include <spar/joints/sliding_node_slopes.hpp>
#include <spar/joints/angle_driver.hpp>
#include <spar/joints/attachment.hpp>
#include <spar/joints/check_constraint.hpp>
#include <spar/joints/clamp_joint.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/coordinate_driver.hpp>
#include <spar/joints/point_joint.hpp>
#include <spar/joints/point_kinematics.hpp>
#include <spar/joints/position_driver.hpp>
#include <spar/joints/prismatic_joint.hpp>
#include <spar/joints/reaction.hpp>
#include <spar/joints/sliding_joint.hpp>
#include <spar/joints/revolute_joint.hpp>
#include <spar/joints/spherical_joint.hpp>
#include <spar/joints/motion_law.hpp>
#include <spar/joints/time_function.hpp>
#include <spar/joints/vector_kinematics.hpp>
