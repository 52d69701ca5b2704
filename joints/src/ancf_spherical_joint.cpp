#include <spar/joints/ancf_spherical_joint.hpp>

#include <spar/core/elements/ancf_beam_element.hpp>
#include <spar/error.hpp>
#include <spar/joints/attachment.hpp>

#include "evaluation_checks.hpp"

#include <algorithm>
#include <string>

namespace spar::joints {

namespace {
constexpr std::string_view name = "joints::AncfSphericalJoint";

/// The map S(ξ, y, z) of one element kind on its blocks (node A, node B[, extra]).
template <int transverse>
LinearPoint element_point(const core::AncfBeam& beam, int element, double xi, const Eigen::Vector2d& yz) {
  using Shape = core::AncfShapeFunctions<transverse>;
  const auto ax = Shape::axial(xi, beam.element_length);
  const auto tr = Shape::transverse_values(xi, beam.element_length);
  Eigen::Matrix<double, 3, Shape::dofs> S = Eigen::Matrix<double, 3, Shape::dofs>::Zero();
  for (int k = 0; k < 4; ++k) S.template block<3, 3>(0, 3 * Shape::axial_vectors[k]).diagonal().setConstant(ax[k]);
  for (int k = 0; k < transverse; ++k) {
    S.template block<3, 3>(0, 3 * Shape::y_vectors[k]).diagonal().setConstant(yz.x() * tr[k]);
    S.template block<3, 3>(0, 3 * Shape::z_vectors[k]).diagonal().setConstant(yz.y() * tr[k]);
  }
  LinearPoint p;
  p.blocks = {beam.nodes[element], beam.nodes[element + 1]};
  p.maps = {S.leftCols(12), S.middleCols(12, 12)};
  if constexpr (transverse == 3) {
    p.blocks.push_back(beam.element_blocks[element]);
    p.maps.push_back(S.rightCols(6));
  }
  return p;
}

}  // namespace

Eigen::Vector3d LinearPoint::position(const core::Configuration& q) const {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < blocks.size(); ++k) p += maps[k] * q.vector(blocks[k]);
  return p;
}

LinearPoint ancf_node_point(const core::Configuration& q, int node) {
  if (node < 0 || node >= q.block_count() || q.is_frame(node) || q.blocks[node].size != 12)
    throw Error("block " + std::to_string(node) + " is not an ANCF node", "joints::ancf_node_point",
                "give a node of core::add_ancf_beam");
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(3, 12);
  C.leftCols<3>().setIdentity();
  return {{node}, {C}};
}

LinearPoint ancf_element_point(const core::AncfBeam& beam, int element, double xi, const Eigen::Vector2d& yz) {
  if (element < 0 || element + 1 >= static_cast<int>(beam.nodes.size()) || !(xi >= 0.0 && xi <= 1.0))
    throw Error("element " + std::to_string(element) + " at xi = " + std::to_string(xi) + " is not on the beam",
                "joints::ancf_element_point", "give an element of the beam and xi in [0, 1]");
  return beam.kind == core::AncfElementKind::standard_24 ? element_point<2>(beam, element, xi, yz)
                                                         : element_point<3>(beam, element, xi, yz);
}

AncfSphericalJoint::AncfSphericalJoint(const LinearPoint& a, const Eigen::Vector3d& ground,
                                       const core::Configuration& q)
    : ground_(finite_point(ground, "ground point", "joints::AncfSphericalJoint")) {
  add(a, 1.0, q);
}

AncfSphericalJoint::AncfSphericalJoint(const LinearPoint& a, const LinearPoint& b, const core::Configuration& q) {
  add(a, 1.0, q);
  add(b, -1.0, q);
}

void AncfSphericalJoint::add(const LinearPoint& p, double sign, const core::Configuration& q) {
  if (p.blocks.empty() || p.blocks.size() != p.maps.size())
    throw Error("the point has " + std::to_string(p.blocks.size()) + " blocks and " +
                    std::to_string(p.maps.size()) + " maps", name, "give one 3 x size map per block");
  for (std::size_t k = 0; k < p.blocks.size(); ++k) {
    const int b = p.blocks[k];
    if (b < 0 || b >= q.block_count() || q.is_frame(b) || p.maps[k].rows() != 3 || p.maps[k].cols() != q.blocks[b].size)
      throw Error("block " + std::to_string(b) + " is not a vector block matching its 3 x " +
                      std::to_string(p.maps[k].cols()) + " map", name, "use ancf_node_point or ancf_element_point");
    const auto it = std::find(blocks_.begin(), blocks_.end(), b);
    if (it == blocks_.end()) {
      blocks_.push_back(b);
      columns_.push_back(static_cast<int>(jacobian_.cols()));
      jacobian_.conservativeResize(3, jacobian_.cols() + q.blocks[b].size);
      jacobian_.rightCols(q.blocks[b].size) = sign * p.maps[k];
    } else {
      jacobian_.middleCols(columns_[it - blocks_.begin()], q.blocks[b].size) += sign * p.maps[k];
    }
  }
}

void AncfSphericalJoint::value(const core::Configuration& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi) const {
  detail::begin_vector_output(*this, q, phi, name);
  for (std::size_t k = 0; k < blocks_.size(); ++k) {
    const core::Block& b = q.blocks[blocks_[k]];
    phi.noalias() += jacobian_.middleCols(columns_[k], b.size) * q.values.segment(b.offset, b.size);
  }
  phi -= ground_;
}

void AncfSphericalJoint::jacobian(const core::Configuration& q, double /*t*/, Eigen::Ref<Eigen::MatrixXd> B) const {
  detail::begin_jacobian(*this, q, B, name);
  B = jacobian_;
}

void AncfSphericalJoint::multiplier_tangent(const core::Configuration& q, double /*t*/,
                                            const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                            Eigen::Ref<Eigen::MatrixXd> K) const {
  detail::begin_multiplier_tangent(*this, q, lambda, K, name);
}

void AncfSphericalJoint::acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                            double /*t*/, Eigen::Ref<Eigen::VectorXd> c) const {
  detail::begin_acceleration_terms(*this, q, velocity, c, name);
}

}  // namespace spar::joints
