#pragma once
/// \file
/// Spherical joints on ANCF beams (docs/ancf.md §8): points whose position is linear in the
/// coordinates of vector blocks — an ANCF node's r (its first three coordinates) or a point
/// r(ξ, y, z) = S(ξ, y, z) e inside an element (001 eq. 5) — held at a ground point or at another
/// such point. Φ is linear in q, so B is constant, the multiplier tangent is zero and Φ̈ = B v̇.

#include <spar/core/ancf_beam.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::joints {

/// p(q) = Σ_k C_k q_k over vector blocks k (C_k: 3 × the block's size).
struct LinearPoint {
  std::vector<int> blocks;
  std::vector<Eigen::MatrixXd> maps;

  Eigen::Vector3d position(const core::Configuration& q) const;
};

/// The position r of an ANCF node: C = [I₃ 0 0 0]. Throws spar::Error unless `node` is a vector
/// block of 12 in q.
LinearPoint ancf_node_point(const core::Configuration& q, int node);

/// The material point (ξ l, y, z) of element `element` of `beam` (ξ ∈ [0, 1]): C = S(ξ, y, z) on
/// the element's blocks. Throws for an element or ξ out of range.
LinearPoint ancf_element_point(const core::AncfBeam& beam, int element, double xi,
                               const Eigen::Vector2d& section_point = Eigen::Vector2d::Zero());

/// Φ = p_a(q) − p_b(q) or Φ = p_a(q) − ground (3 equations).
class AncfSphericalJoint final : public Constraint {
 public:
  /// p_a held at a fixed ground point. Throws for a point without blocks or with a map of the
  /// wrong shape for q.
  AncfSphericalJoint(const LinearPoint& a, const Eigen::Vector3d& ground, const core::Configuration& q);
  /// Two points held together; a block shared by both enters once.
  AncfSphericalJoint(const LinearPoint& a, const LinearPoint& b, const core::Configuration& q);

  int equation_count() const override { return 3; }
  const std::vector<int>& blocks() const override { return blocks_; }

  void value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// B = [C_a, −C_b] on the blocks (constant).
  void jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// Zero: B does not depend on q.
  void multiplier_tangent(const core::Configuration& q, double t,
                          const Eigen::Ref<const Eigen::VectorXd>& lambda,
                          Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// Zero: Φ̈ = B v̇.
  void acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                          Eigen::Ref<Eigen::VectorXd> c) const override;

 private:
  void add(const LinearPoint& p, double sign, const core::Configuration& q);

  std::vector<int> blocks_;
  std::vector<int> columns_;  ///< first column of each block in B
  Eigen::MatrixXd jacobian_;  ///< 3 × n
  Eigen::Vector3d ground_ = Eigen::Vector3d::Zero();
};

}  // namespace spar::joints
