#pragma once
/// \file
/// Driving constraint on coordinates of a vector block: chosen coordinates of an ANCF node (its
/// slope r_x, a position entry) follow time functions from their values in q0 — an ANCF slope
/// driven, or held (f = 0) as the constraint counterpart of Model::fix_coordinates whose
/// reaction is wanted (docs/joints.md §3.4).

#include <spar/joints/constraint.hpp>
#include <spar/joints/time_function.hpp>

#include <vector>

namespace spar::joints {

/// Φ_k = p_{c_k} − p_{c_k}(q0) − f_k(t) for the coordinates c_k of one vector block p
/// (docs/joints.md eq. J30): B holds a 1 in column c_k of row k, K_λ = 0, c_k = −f_k″(t),
/// Φ_t,k = −f_k′(t).
class CoordinateDriver final : public Constraint {
 public:
  /// One time function per coordinate, or one for all of them. Raises spar::Error for a block
  /// that is not a vector block of q0, no coordinate, a coordinate outside the block or given
  /// twice, a count of functions that is neither 1 nor the coordinates', or a function that
  /// lacks a derivative.
  CoordinateDriver(int block, std::vector<int> coordinates, std::vector<TimeFunction> f,
                   const core::Configuration& q0);

  int equation_count() const override { return static_cast<int>(coordinates_.size()); }
  const std::vector<int>& blocks() const override { return blocks_; }

 private:
  void compute_value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const override;
  void compute_jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// B does not depend on q: K_λ = 0 (left as handed in, zeroed).
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;
  void compute_time_derivative(const core::Configuration& q, double t,
                               Eigen::Ref<Eigen::VectorXd> phi_t) const override;

  /// f_k: the function of coordinate k (the one shared function when a single one was given).
  const TimeFunction& function(int k) const { return f_[f_.size() == 1 ? 0 : k]; }

  std::vector<int> blocks_;
  std::vector<int> coordinates_;
  std::vector<double> reference_;  // p_{c_k}(q0)
  std::vector<TimeFunction> f_;
};

}  // namespace spar::joints
