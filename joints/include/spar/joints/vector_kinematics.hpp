#pragma once
/// \file
/// Building block of the joints: a vector fixed in a node's material frame (or in the ground), the
/// dot product of two such vectors, and the three dot products that lock a relative rotation,
/// each with its Jacobian, multiplier tangent and acceleration terms (docs/joints.md eqs. J9–J16).

#include <spar/core/configuration.hpp>
#include <spar/joints/attachment.hpp>

#include <Eigen/Core>

#include <array>

namespace spar::joints {

/// d = R v on a node (v material), d = v on the ground (v inertial), docs/joints.md eq. J9.
class AttachedVector {
 public:
  AttachedVector() = default;
  AttachedVector(JointFrame frame, const Eigen::Vector3d& material)
      : frame_(frame), vector_(material) {}

  /// The vector of `frame` that is the inertial vector w in configuration q0: v = R0ᵀ w on a node,
  /// v = w on the ground.
  static AttachedVector from_inertial(JointFrame frame, const Eigen::Vector3d& inertial,
                                      const core::Configuration& q0);

  const JointFrame& frame() const { return frame_; }
  /// v: material on a node, inertial on the ground.
  const Eigen::Vector3d& vector() const { return vector_; }

  /// d(q) = R v, or v on the ground (eq. J9).
  Eigen::Vector3d direction(const core::Configuration& q) const;

  /// Adds ∂(d·w)/∂Δ for a fixed inertial w to row `row` of B: (v × Rᵀw)ᵀ in the node's rotation
  /// columns (eq. J10); nothing on the ground.
  void add_jacobian_along(const core::Configuration& q, const Eigen::Vector3d& w,
                          Eigen::Ref<Eigen::MatrixXd> B, int row) const;

  /// Adds λ ∂(v × Rᵀw)/∂Δ for a fixed inertial w to K: λ ṽ (Rᵀw)~ in the node's rotation ×
  /// rotation block (eq. J11); nothing on the ground.
  void add_multiplier_tangent_along(const core::Configuration& q, const Eigen::Vector3d& w,
                                    double lambda, Eigen::Ref<Eigen::MatrixXd> K) const;

  /// ḋ = R (Ω × v) (eq. J12); zero on the ground.
  Eigen::Vector3d rate(const core::Configuration& q, const Eigen::VectorXd& velocity) const;

  /// The part of d̈ not proportional to the accelerations: R (Ω × (Ω × v)) (eq. J12); zero on the
  /// ground.
  Eigen::Vector3d acceleration_terms(const core::Configuration& q,
                                     const Eigen::VectorXd& velocity) const;

 private:
  JointFrame frame_;
  Eigen::Vector3d vector_ = Eigen::Vector3d::Zero();
};

/// s = d_a · d_b for two attached vectors (docs/joints.md eqs. J13–J15): one equation.
class DotProduct {
 public:
  DotProduct() = default;
  DotProduct(const AttachedVector& a, const AttachedVector& b) : a_(a), b_(b) {}

  /// d_a · d_b (eq. J13).
  double value(const core::Configuration& q) const;
  /// Adds ∂s/∂Δ to row `row` of B: (v_a × R_aᵀ d_b)ᵀ and (v_b × R_bᵀ d_a)ᵀ in the rotation columns
  /// of a and b (eq. J13).
  void add_jacobian(const core::Configuration& q, Eigen::Ref<Eigen::MatrixXd> B, int row) const;
  /// Adds λ ∂²s: the diagonal blocks λ ṽ_a (R_aᵀd_b)~, λ ṽ_b (R_bᵀd_a)~ and the coupling block
  /// −λ ṽ_a R_aᵀ R_b ṽ_b with its transpose (eq. J14).
  void add_multiplier_tangent(const core::Configuration& q, double lambda,
                              Eigen::Ref<Eigen::MatrixXd> K) const;
  /// c = R_a(Ω_a×(Ω_a×v_a))·d_b + 2 ḋ_a·ḋ_b + d_a·R_b(Ω_b×(Ω_b×v_b)) (eq. J15).
  double acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity) const;

 private:
  AttachedVector a_;
  AttachedVector b_;
};

/// Three dot products that keep the relative rotation of frames a and b at its value in q0
/// (docs/joints.md eq. J16): with the inertial basis e₁, e₂, e₃ carried by each frame from q0,
/// Φ = ((R_a e₂ᵃ)·(R_b e₃ᵇ), (R_a e₃ᵃ)·(R_b e₁ᵇ), (R_a e₁ᵃ)·(R_b e₂ᵇ)), zero at q0 and
/// with a regular Jacobian there.
class RelativeRotationLock {
 public:
  RelativeRotationLock(JointFrame a, JointFrame b, const core::Configuration& q0);

  Eigen::Vector3d value(const core::Configuration& q) const;
  void add_jacobian(const core::Configuration& q, Eigen::Ref<Eigen::MatrixXd> B,
                    int first_row) const;
  void add_multiplier_tangent(const core::Configuration& q, const Eigen::Vector3d& lambda,
                              Eigen::Ref<Eigen::MatrixXd> K) const;
  Eigen::Vector3d acceleration_terms(const core::Configuration& q,
                                     const Eigen::VectorXd& velocity) const;

 private:
  std::array<DotProduct, 3> products_;
};

}  // namespace spar::joints
