#pragma once
/// \file
/// Spherical joint: two attached points coincide (docs/joints.md §2.1).

#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/point_kinematics.hpp>

#include <vector>

namespace spar::joints {

/// Φ = p_a − p_b = 0 (3 equations), p = x + R·offset on a node, p = offset on the ground
/// (docs/joints.md eq. J17). B, K and c are those of PointCoincidence (eqs. J6–J8).
class SphericalJoint final : public Constraint {
 public:
  /// Raises spar::Error when a node is not in q0, both attachments are on the ground, or both
  /// are on the same node. Φ(q0) is p_a(q0) − p_b(q0): place the attachments at one point (e.g.
  /// with attach_at) for an assembled initial configuration.
  SphericalJoint(const Attachment& a, const Attachment& b, const core::Configuration& q0);

  int equation_count() const override { return 3; }
  const std::vector<int>& blocks() const override { return nodes_; }

 private:
  /// Φ = p_a − p_b.
  void compute_value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// B = [∂p_a/∂Δ_a, −∂p_b/∂Δ_b] (eq. J6).
  void compute_jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// K = ∂(Bᵀλ)/∂Δ: ã (R_aᵀλ)~ and −b̃ (R_bᵀλ)~ in the rotation blocks (eq. J7).
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// c = R_a(Ω_a×(Ω_a×a)) − R_b(Ω_b×(Ω_b×b)) (eq. J8).
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  SphericalJoint(const Attachment& a, const Attachment& b, const JointFrames& frames);

  std::vector<int> nodes_;
  PointCoincidence points_;
};

}  // namespace spar::joints
