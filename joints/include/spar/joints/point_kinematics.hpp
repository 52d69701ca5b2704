#pragma once
/// \file
/// Building block of the joints: a point fixed in a node's material frame (or in the ground), with
/// its Jacobian, multiplier tangent and acceleration terms (docs/joints.md eqs. J1–J4), and the
/// coincidence of two such points (eqs. J5–J8). Joints compose these; they never differentiate a
/// point themselves.

#include <spar/core/configuration.hpp>
#include <spar/joints/attachment.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Core>

namespace spar::joints {

/// p = x + R a on a node (a material), p = a on the ground (a inertial), docs/joints.md eq. J1.
class AttachedPoint {
 public:
  AttachedPoint() = default;
  AttachedPoint(JointFrame frame, const Eigen::Vector3d& offset) : frame_(frame), offset_(offset) {}

  const JointFrame& frame() const { return frame_; }
  const Eigen::Vector3d& offset() const { return offset_; }

  /// p(q) = x + R a, or a on the ground (eq. J1).
  Eigen::Vector3d position(const core::Configuration& q) const;

  /// Adds W ∂p/∂Δ = W [I, −R ã] (eq. J2) to the rows first_row … first_row + Rows − 1 of B, in the
  /// column block of the point's node; nothing for a ground point. W is a Rows × 3 weight (±I for
  /// a coincidence, a row nᵀ for a projection).
  template <int Rows>
  void add_jacobian(const core::Configuration& q, const Eigen::Matrix<double, Rows, 3>& weight,
                    Eigen::Ref<Eigen::MatrixXd> B, int first_row) const {
    if (frame_.on_ground()) return;
    B.template block<Rows, 3>(first_row, frame_.translation_column()) += weight;
    B.template block<Rows, 3>(first_row, frame_.rotation_column()) -=
        weight * q.rotation[frame_.node] * lie::hat(offset_);
  }

  /// Adds ∂((∂p/∂Δ)ᵀ f)/∂Δ for a fixed inertial force f to K (eq. J3): the only non-zero block is
  /// rotation × rotation, ã (Rᵀf)~. Nothing for a ground point.
  void add_multiplier_tangent(const core::Configuration& q, const Eigen::Vector3d& force,
                              Eigen::Ref<Eigen::MatrixXd> K) const;

  /// The part of p̈ not proportional to the accelerations: R (Ω × (Ω × a)) (eq. J4), with Ω the
  /// node's material angular velocity read from the global `velocity`. Zero on the ground.
  Eigen::Vector3d acceleration_terms(const core::Configuration& q,
                                     const Eigen::VectorXd& velocity) const;

 private:
  JointFrame frame_;
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
};

/// Φ = p_a − p_b for two attached points (docs/joints.md eqs. J5–J8): three equations.
class PointCoincidence {
 public:
  PointCoincidence(const AttachedPoint& a, const AttachedPoint& b) : a_(a), b_(b) {}

  /// p_a − p_b (eq. J5).
  Eigen::Vector3d value(const core::Configuration& q) const;
  /// Adds ∂p_a/∂Δ − ∂p_b/∂Δ to the three rows of B starting at first_row (eq. J6).
  void add_jacobian(const core::Configuration& q, Eigen::Ref<Eigen::MatrixXd> B,
                    int first_row) const;
  /// Adds ∂(B_abᵀ λ)/∂Δ for the three multipliers λ (eq. J7).
  void add_multiplier_tangent(const core::Configuration& q, const Eigen::Vector3d& lambda,
                              Eigen::Ref<Eigen::MatrixXd> K) const;
  /// c = R_a(Ω_a × (Ω_a × a)) − R_b(Ω_b × (Ω_b × b)) (eq. J8).
  Eigen::Vector3d acceleration_terms(const core::Configuration& q,
                                     const Eigen::VectorXd& velocity) const;

 private:
  AttachedPoint a_;
  AttachedPoint b_;
};

}  // namespace spar::joints
