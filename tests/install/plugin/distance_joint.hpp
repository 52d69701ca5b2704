#pragma once
// A user's own joint, written against the installed spar package only: a frame block's position
// x_a held at the distance L from a ground point p, or from another frame block's position x_b
// (docs/model.md, "Adding a joint in your own project"). With d = x_a − x_b (or x_a − p), one
// equation
//     Φ = ½ (|d|² − L²),
// whose multiplier λ is the rod's tension over its length (the force on a is −Bᵀλ = −λ d).
// A frame's translation increment Δx is inertial, so B, K_λ and c involve only the translation
// columns: B = [dᵀ 0 −dᵀ 0], K_λ = λ [I 0 −I 0; 0; −I 0 I 0; 0] and Φ̈ = dᵀ(ẍ_a − ẍ_b) + |ẋ_a − ẋ_b|².
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <vector>

namespace plugin {

struct DistanceJointParameters {
  int block_a = 0;   ///< the frame block whose position is held
  int block_b = -1;  ///< the frame block at the other end; −1: the ground point
  Eigen::Vector3d ground_point = Eigen::Vector3d::Zero();  ///< the other end when block_b = −1, m
  double length = 1.0;                                     ///< L > 0, m
};

class DistanceJoint final : public spar::joints::Constraint {
public:
  /// Throws spar::Error for a negative block_a, equal blocks, or a length that is not positive
  /// and finite.
  explicit DistanceJoint(const DistanceJointParameters& parameters);

  int equation_count() const override { return 1; }
  const std::vector<int>& blocks() const override { return blocks_; }

private:
  // Constraint::value, jacobian, ... check their input and hand these their outputs sized and
  // zeroed: each writes its non-zero entries only.
  void compute_value(const spar::core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const override;
  void compute_jacobian(const spar::core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const override;
  void compute_multiplier_tangent(const spar::core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  void compute_acceleration_terms(const spar::core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  bool grounded() const { return blocks_.size() == 1; }
  /// d = x_a − x_b, or x_a − p at the ground.
  Eigen::Vector3d separation(const spar::core::Configuration& q) const;

  std::vector<int> blocks_;
  Eigen::Vector3d ground_point_;
  double length_;
};

}  // namespace plugin
