#pragma once
/// \file
/// Prismatic joint: a point of a node slides on a fixed inertial line, with the node's rotation
/// locked or free (docs/joints.md §2.4).

#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/point_kinematics.hpp>
#include <spar/joints/vector_kinematics.hpp>

#include <optional>
#include <vector>

namespace spar::joints {

/// Φ₁,₂ = (p_a − c)·n₁, (p_a − c)·n₂ with c the line point and n₁, n₂ unit vectors ⊥ the line's
/// direction; with lock_rotation, Φ₃…₅ = RelativeRotationLock of the node and the ground (its
/// rotation stays that of q0) (docs/joints.md eq. J20).
class PrismaticJoint final : public Constraint {
 public:
  /// Raises spar::Error when a is on the ground or on a node not in q0, or the direction is zero
  /// or not finite.
  PrismaticJoint(const Attachment& a, const Eigen::Vector3d& line_point,
                 const Eigen::Vector3d& direction, bool lock_rotation,
                 const core::Configuration& q0);

  int equation_count() const override { return rotation_lock_ ? 5 : 2; }
  const std::vector<int>& blocks() const override { return nodes_; }

  /// The stroke s = (p_a − c)·d along the unit line direction d from the line point c [m]
  /// (docs/joints.md §5).
  double stroke(const core::Configuration& q) const;
  /// ṡ = ṗ_a·d, ṗ_a = ẋ + R(Ω × a) [m/s].
  double stroke_rate(const core::Configuration& q, const Eigen::VectorXd& velocity) const;

 private:
  /// Φ = ((p_a − c)·n₁, (p_a − c)·n₂[, rotation lock]).
  void compute_value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// Rows 1–2: nᵢᵀ ∂p_a/∂Δ (eq. J2); rows 3–5 eq. J13.
  void compute_jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// Eq. J3 with f = λ₁n₁ + λ₂n₂, plus eq. J14 for λ₃…₅.
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// Rows 1–2: nᵢ·R(Ω×(Ω×a)) (eq. J4); rows 3–5 eq. J15.
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  std::vector<int> nodes_;
  AttachedPoint point_;
  Eigen::Vector3d line_point_;
  Eigen::Matrix<double, 2, 3> normals_;  // rows n₁ᵀ, n₂ᵀ
  std::optional<RelativeRotationLock> rotation_lock_;
};

}  // namespace spar::joints
