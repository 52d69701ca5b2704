#pragma once
/// \file
/// Clamp: a rigid connection of two frames, positions and rotations (docs/joints.md §2.3).

#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/point_kinematics.hpp>
#include <spar/joints/vector_kinematics.hpp>

#include <vector>

namespace spar::joints {

/// Φ₁…₃ = p_a − p_b, Φ₄…₆ = RelativeRotationLock of a and b (docs/joints.md eq. J19): the
/// relative rotation R_aᵀR_b keeps its value of q0 (to first order around it, and exactly on the
/// branch that contains q0).
class ClampJoint final : public Constraint {
 public:
  /// Raises spar::Error for a node not in q0, two ground attachments or two attachments on the
  /// same node.
  ClampJoint(const Attachment& a, const Attachment& b, const core::Configuration& q0);

  int equation_count() const override { return 6; }
  const std::vector<int>& blocks() const override { return nodes_; }

 private:
  /// Φ = (p_a − p_b, (R_a e₂ᵃ)·(R_b e₃ᵇ), (R_a e₃ᵃ)·(R_b e₁ᵇ), (R_a e₁ᵃ)·(R_b e₂ᵇ)).
  void compute_value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// Rows 1–3 eq. J6, rows 4–6 eq. J13 for each product.
  void compute_jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// Eq. J7 for λ₁…₃ plus eq. J14 for λ₄…₆.
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// Rows 1–3 eq. J8, rows 4–6 eq. J15.
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  ClampJoint(const Attachment& a, const Attachment& b, const JointFrames& frames,
             const core::Configuration& q0);

  std::vector<int> nodes_;
  PointCoincidence points_;
  RelativeRotationLock rotation_lock_;
};

}  // namespace spar::joints
