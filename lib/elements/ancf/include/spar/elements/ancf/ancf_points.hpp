#pragma once
/// \file
/// The material points the ANCF beam family offers to joints (docs/ancf.md §8): an ANCF node's
/// position r and a point r(ξ, y, z) = S(ξ, y, z) e inside an element (001 eqs. 5, 55), both
/// linear in the blocks' coordinates (core::LinearPoint). Hold them with joints::PointJoint.

#include <spar/core/configuration.hpp>
#include <spar/core/linear_point.hpp>
#include <spar/elements/ancf/ancf_beam.hpp>

#include <Eigen/Core>

namespace spar::core {

/// The position r of an ANCF node: C = [I₃ 0 0 0]. Throws spar::Error unless `node` is a vector
/// block of 12 in q.
LinearPoint ancf_node_point(const Configuration& q, int node);

/// The material point (ξ l, y, z) of element `element` of `beam` (ξ ∈ [0, 1]): C = S(ξ, y, z) on
/// the element's blocks. Throws spar::Error for an element or ξ out of range.
LinearPoint ancf_element_point(const AncfBeam& beam, int element, double xi,
                               const Eigen::Vector2d& section_point = Eigen::Vector2d::Zero());

}  // namespace spar::core
