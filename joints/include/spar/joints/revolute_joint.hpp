#pragma once
/// \file
/// Revolute joint (hinge): two attached points coincide and a hinge axis stays common to both
/// frames (docs/joints.md §2.2).

#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/point_kinematics.hpp>
#include <spar/joints/reaction.hpp>
#include <spar/joints/vector_kinematics.hpp>

#include <array>
#include <vector>

namespace spar::joints {

/// Φ₁…₃ = p_a − p_b, Φ₄ = (R_a u_a)·(R_b v_b1), Φ₅ = (R_a u_a)·(R_b v_b2) (docs/joints.md eq. J18):
/// the hinge axis n (inertial, at q0) is carried by a as u_a = R_a0ᵀ n and the two unit vectors
/// n₁, n₂ ⊥ n by b as v_bi = R_b0ᵀ nᵢ (on the ground: the inertial vectors themselves), so
/// Φ₄,₅ = 0 at q0 and the relative rotation about n is free.
class RevoluteJoint final : public Constraint {
 public:
  /// Raises spar::Error for a zero or non-finite axis, a node not in q0, two ground attachments
  /// or two attachments on the same node.
  RevoluteJoint(const Attachment& a, const Attachment& b, const Eigen::Vector3d& axis,
                const core::Configuration& q0);

  int equation_count() const override { return 5; }
  const std::vector<int>& blocks() const override { return nodes_; }

  // Joint-level outputs (docs/joints.md §5).

  /// The hinge point p_b (inertial; p_a = p_b when Φ holds).
  Eigen::Vector3d point(const core::Configuration& q) const;
  /// The joint's frame, carried by b: columns n₁, n₂ (⊥ the axis at q0) and n = n₁ × n₂ (the
  /// axis), inertial components.
  Eigen::Matrix3d frame(const core::Configuration& q) const;
  /// The rotation φ of a relative to b about the axis since q0, right-handed about n, in (−π, π]
  /// [rad]: a's copy of n₁ is at cos φ n₁ + sin φ n₂.
  double relative_angle(const core::Configuration& q) const;
  /// φ̇ = (ω_a − ω_b)·n with ω = R Ω the inertial angular velocities (zero on the ground) [rad/s].
  double relative_rate(const core::Configuration& q, const Eigen::VectorXd& velocity) const;
  /// The reaction the joint exerts on a (on b: the opposite), about the hinge point, in the
  /// joint's frame (n₁, n₂, n): force [N] and moment [N m] (the moment's n component is zero — the
  /// hinge is frictionless — up to the rotation of a relative to b out of the axis). λ are the
  /// joint's 5 multipliers. With a on the ground, still the reaction on a: minus that on b.
  Wrench reaction_in_frame(const core::Configuration& q, double t,
                           const Eigen::Ref<const Eigen::VectorXd>& lambda) const;

 private:
  /// Φ = (p_a − p_b, d_a·d_b1, d_a·d_b2).
  void compute_value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// Rows 1–3 as SphericalJoint (eq. J6), rows 4–5 the dot-product rows (eq. J13).
  void compute_jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// The sum of eq. J7 for λ₁…₃ and eq. J14 for λ₄, λ₅.
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// Rows 1–3 eq. J8, rows 4–5 eq. J15.
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  RevoluteJoint(const Attachment& a, const Attachment& b, const Eigen::Vector3d& axis,
                const JointFrames& frames, const core::Configuration& q0);

  std::vector<int> nodes_;
  PointCoincidence points_;
  std::array<DotProduct, 2> axis_products_;
  // The outputs' kinematics: b's point, a's copies of the axis and of n₁, b's copies of n₁, n₂.
  AttachedPoint point_b_;
  AttachedVector axis_a_, normal_a_;
  std::array<AttachedVector, 2> normals_b_;
};

}  // namespace spar::joints
