#include "distance_joint.hpp"

#include <spar/core/configuration.hpp>
#include <spar/error.hpp>

#include <cmath>
#include <string>

namespace plugin {

using namespace spar;

DistanceJoint::DistanceJoint(const DistanceJointParameters& p)
    : blocks_{p.block_a}, ground_point_(p.ground_point), length_(p.length) {
  if (p.block_a < 0 || p.block_b == p.block_a)
    throw Error("blocks " + std::to_string(p.block_a) + " and " + std::to_string(p.block_b), "plugin::DistanceJoint",
                "hold a frame block (block_a ≥ 0) at a distance from the ground (block_b = -1) or another block");
  if (!(std::isfinite(p.length) && p.length > 0.0) || !p.ground_point.allFinite())
    throw Error("length " + std::to_string(p.length) + " or a ground point that is not finite", "plugin::DistanceJoint",
                "give a positive, finite length and a finite ground point");
  if (p.block_b >= 0) blocks_.push_back(p.block_b);
}

Eigen::Vector3d DistanceJoint::separation(const core::Configuration& q) const {
  for (int block : blocks_)
    if (!q.is_frame(block))
      throw Error("block " + std::to_string(block) + " is not a frame", "plugin::DistanceJoint",
                  "hold the positions of frame blocks");
  return q.position[blocks_[0]] - (grounded() ? ground_point_ : q.position[blocks_[1]]);
}

// Φ = ½ (|d|² − L²).
void DistanceJoint::compute_value(const core::Configuration& q, double, Eigen::Ref<Eigen::VectorXd> phi) const {
  phi(0) = 0.5 * (separation(q).squaredNorm() - length_ * length_);
}

// B = ∂Φ(q ⊕ Δ)/∂Δ: x_a ← x_a + Δx_a moves d by Δx_a, x_b ← x_b + Δx_b by −Δx_b, and the
// rotations do not enter (columns 3–5 and 9–11 stay zero).
void DistanceJoint::compute_jacobian(const core::Configuration& q, double, Eigen::Ref<Eigen::MatrixXd> B) const {
  const Eigen::Vector3d d = separation(q);
  B.block<1, 3>(0, 0) = d.transpose();
  if (!grounded()) B.block<1, 3>(0, 6) = -d.transpose();
}

// K_λ = ∂(Bᵀλ)/∂Δ: Bᵀλ = λ [d; 0; −d; 0] and ∂d/∂(Δx_a, Δx_b) = [I, −I].
void DistanceJoint::compute_multiplier_tangent(const core::Configuration&, double,
                                               const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                               Eigen::Ref<Eigen::MatrixXd> K) const {
  const Eigen::Matrix3d block = lambda(0) * Eigen::Matrix3d::Identity();
  K.block<3, 3>(0, 0) = block;
  if (grounded()) return;
  K.block<3, 3>(0, 6) = -block;
  K.block<3, 3>(6, 0) = -block;
  K.block<3, 3>(6, 6) = block;
}

// Φ̇ = dᵀḋ, Φ̈ = dᵀd̈ + |ḋ|² = B v̇ + c with c = |ḋ|², ḋ = ẋ_a − ẋ_b (a frame's velocity starts with
// its inertial ẋ at the block's offset).
void DistanceJoint::compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double,
                                               Eigen::Ref<Eigen::VectorXd> c) const {
  Eigen::Vector3d d_rate = velocity.segment<3>(q.blocks[blocks_[0]].offset);
  if (!grounded()) d_rate -= velocity.segment<3>(q.blocks[blocks_[1]].offset);
  c(0) = d_rate.squaredNorm();
}

}  // namespace plugin
