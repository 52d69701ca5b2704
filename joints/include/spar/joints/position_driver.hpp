#pragma once
/// \file
/// Driving constraint: the displacement of an attached point along a direction follows a time
/// function (docs/joints.md §3.1).

#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/point_kinematics.hpp>
#include <spar/joints/time_function.hpp>

#include <vector>

namespace spar::joints {

/// Φ = n·(p_a − p_a(q0)) − f(t) with n the unit direction (docs/joints.md eq. J21): f is the
/// displacement in metres along n from the point's position in q0.
class PositionDriver final : public Constraint {
 public:
  /// Raises spar::Error when a is on the ground or on a node not in q0, the direction is zero or
  /// not finite, or f lacks a derivative.
  PositionDriver(const Attachment& a, const Eigen::Vector3d& direction, TimeFunction f,
                 const core::Configuration& q0);

  int equation_count() const override { return 1; }
  const std::vector<int>& blocks() const override { return nodes_; }

 private:
  /// Φ = n·(p_a − p_a(q0)) − f(t).
  void compute_value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// B = nᵀ ∂p_a/∂Δ (eq. J2).
  void compute_jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// Eq. J3 with f = λn.
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// c = n·R(Ω×(Ω×a)) − f″(t) (eqs. J4, J21).
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;
  /// Φ_t = −f′(t).
  void compute_time_derivative(const core::Configuration& q, double t,
                               Eigen::Ref<Eigen::VectorXd> phi_t) const override;

  std::vector<int> nodes_;
  AttachedPoint point_;
  Eigen::Vector3d direction_;
  double reference_ = 0.0;  // n·p_a(q0)
  TimeFunction f_;
};

}  // namespace spar::joints
