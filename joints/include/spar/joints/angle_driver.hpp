#pragma once
/// \file
/// Driving constraint: a node's rotation about an inertial axis, relative to q0, follows a time
/// function (docs/joints.md §3.2).

#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/time_function.hpp>
#include <spar/joints/vector_kinematics.hpp>

#include <vector>

namespace spar::joints {

/// Φ = (R u)·w(t), w(t) = n × d(t), d(t) = cos f(t)·p₀ + sin f(t)·(n × p₀) (docs/joints.md
/// eq. J22), with n the unit axis, p₀ a unit inertial vector ⊥ n and u = R0ᵀ p₀: if R u has turned
/// by φ about n from p₀, Φ = sin(φ − f). Only the rotation about n is driven; the other two
/// rotations and the position are left to other joints. Φ has a second root at φ = f + π, far
/// from any step of a Newton iteration that starts from the previous time step.
class AngleDriver final : public Constraint {
 public:
  /// Raises spar::Error when the node is not in q0 (or is −1), the axis is zero or not finite, or
  /// the angle function lacks a derivative.
  AngleDriver(int node, const Eigen::Vector3d& axis, TimeFunction angle,
              const core::Configuration& q0);

  int equation_count() const override { return 1; }
  const std::vector<int>& blocks() const override { return nodes_; }

 private:
  /// Φ = (R u)·w(t).
  void compute_value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// B = (u × Rᵀw)ᵀ in the rotation columns (eq. J10).
  void compute_jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// K = λ ũ (Rᵀw)~ (eq. J11).
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// c = R(Ω×(Ω×u))·w + 2 R(Ω×u)·ẇ + (R u)·ẅ, ẇ = −f′ d, ẅ = −f″ d − f′² w (eq. J22).
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;
  /// Φ_t = (R u)·ẇ = −f′ (R u)·d.
  void compute_time_derivative(const core::Configuration& q, double t,
                               Eigen::Ref<Eigen::VectorXd> phi_t) const override;

  /// d(t) and w(t) = n × d(t) for the angle f.
  struct DrivenFrame {
    Eigen::Vector3d d;
    Eigen::Vector3d w;
  };
  DrivenFrame driven_frame(double f) const;

  std::vector<int> nodes_;
  AttachedVector vector_;
  Eigen::Vector3d axis_;
  Eigen::Vector3d reference_;  // p₀
  TimeFunction angle_;
};

}  // namespace spar::joints
