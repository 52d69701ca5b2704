#pragma once
// A rigid massless rod from a fixed pivot p to a point mass (3-vector block), released at a given
// time: a constraint with an event, written outside the library against the public Constraint
// interface only (issue 10). While held, with d = x − p and the rod's length L,
//     Φ = (|d|² − L²)/(2L),  B = dᵀ/L,  ∂(Bᵀλ)/∂x = λ I/L,  Φ̈ = dᵀẍ/L + |ẋ|²/L,
// so λ is the rod's compression (N) and the acceleration term is |ẋ|²/L. After the first converged
// step that ends at or after the release time, update_structure drops the equation (m = 0) and
// returns true.
#include <spar/core/configuration.hpp>
#include <spar/error.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::test {

struct ReleasableRodParameters {
  int mass = 0;  ///< 3-vector block
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  double length = 1.0;        ///< L, m
  double release_time = 0.0;  ///< s; a step end within 1e-9 s of it counts as reaching it
};

class ReleasableRod final : public joints::Constraint {
public:
  explicit ReleasableRod(const ReleasableRodParameters& p)
      : blocks_{p.mass}, pivot_(p.pivot), length_(p.length), release_time_(p.release_time) {}

  int equation_count() const override { return held_ ? 1 : 0; }
  const std::vector<int>& blocks() const override { return blocks_; }

  bool update_structure(const core::Configuration&, const Eigen::VectorXd&, double t,
                        std::string& description) override {
    if (!held_ || t < release_time_ - 1e-9) return false;
    held_ = false;
    description = "rod released at t = " + std::to_string(t);
    return true;
  }

private:
  void compute_value(const core::Configuration& q, double, Eigen::Ref<Eigen::VectorXd> phi) const override {
    if (held_) phi(0) = ((q.vector(blocks_[0]) - pivot_).squaredNorm() - length_ * length_) / (2 * length_);
  }
  void compute_jacobian(const core::Configuration& q, double, Eigen::Ref<Eigen::MatrixXd> B) const override {
    if (held_) B.row(0) = (q.vector(blocks_[0]) - pivot_).transpose() / length_;
  }
  void compute_multiplier_tangent(const core::Configuration&, double,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override {
    if (held_) K.diagonal().setConstant(lambda(0) / length_);
  }
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double,
                                  Eigen::Ref<Eigen::VectorXd> c) const override {
    if (held_) c(0) = velocity.segment<3>(q.blocks[blocks_[0]].offset).squaredNorm() / length_;
  }

  std::vector<int> blocks_;
  Eigen::Vector3d pivot_;
  double length_, release_time_;
  bool held_ = true;
};

}  // namespace spar::test
