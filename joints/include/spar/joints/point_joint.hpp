#pragma once
/// \file
/// A spherical joint between material points that any element family offers (core::MaterialPoint:
/// an ANCF node's r, a point S(ξ, y, z) e inside an ANCF element, …): two points held together,
/// or one held at a fixed ground point (docs/joints.md §2.6; docs/ancf.md §8).

#include <spar/core/configuration.hpp>
#include <spar/core/material_point.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace spar::joints {

/// Φ = p_a(q) − p_b(q) or Φ = p_a(q) − ground (3 equations); B = [∂p_a/∂Δ, −∂p_b/∂Δ] with a
/// block shared by both points entering once, K = ∂((∂p_a/∂Δ)ᵀλ)/∂Δ − ∂((∂p_b/∂Δ)ᵀλ)/∂Δ, and
/// c = c_a − c_b (eqs. J5–J8 for any points). For points linear in q (ANCF points) B is constant
/// and K and c vanish.
class PointJoint final : public Constraint {
public:
  /// p_a held at the fixed ground point `ground`. Throws spar::Error when q does not hold the
  /// point's blocks as it expects, or for a non-finite ground point.
  PointJoint(const core::MaterialPoint& a, const Eigen::Vector3d& ground, const core::Configuration& q);
  /// Two points held together. Throws as above.
  PointJoint(const core::MaterialPoint& a, const core::MaterialPoint& b, const core::Configuration& q);

  int equation_count() const override { return 3; }
  const std::vector<int>& blocks() const override { return blocks_; }

private:
  /// The point's columns in B, adding its blocks not yet in blocks_.
  std::vector<int> place(const core::MaterialPoint& p, const core::Configuration& q);

  void compute_value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const override;
  void compute_jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const override;
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  std::unique_ptr<core::MaterialPoint> a_, b_;  ///< b_ null: held at ground_
  Eigen::Vector3d ground_ = Eigen::Vector3d::Zero();
  std::vector<int> blocks_;
  int columns_ = 0;  ///< the columns of blocks_ so far
  std::vector<int> columns_a_, columns_b_;
};

}  // namespace spar::joints
