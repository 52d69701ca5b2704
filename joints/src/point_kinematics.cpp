#include <spar/joints/point_kinematics.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

namespace spar::joints {

Eigen::Vector3d AttachedPoint::position(const core::Configuration& q) const {
  if (frame_.on_ground()) return offset_;
  return q.position[frame_.node] + q.rotation[frame_.node] * offset_;
}

void AttachedPoint::add_multiplier_tangent(const core::Configuration& q,
                                           const Eigen::Vector3d& force,
                                           Eigen::Ref<Eigen::MatrixXd> K) const {
  if (frame_.on_ground()) return;
  // (∂p/∂Δ)ᵀ f = (f, ã Rᵀ f); with R ← R exp(δ), Rᵀf ← Rᵀf + (Rᵀf)~ δ + O(δ²) (eq. J3).
  const int rotation = frame_.rotation_column();
  K.block<3, 3>(rotation, rotation) +=
      lie::hat(offset_) * lie::hat(q.rotation[frame_.node].transpose() * force);
}

Eigen::Vector3d AttachedPoint::acceleration_terms(const core::Configuration& q,
                                                  const Eigen::VectorXd& velocity) const {
  if (frame_.on_ground()) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d omega = frame_.angular_velocity(q, velocity);
  return q.rotation[frame_.node] * omega.cross(omega.cross(offset_));
}

Eigen::Vector3d PointCoincidence::value(const core::Configuration& q) const {
  return a_.position(q) - b_.position(q);
}

void PointCoincidence::add_jacobian(const core::Configuration& q, Eigen::Ref<Eigen::MatrixXd> B,
                                    int first_row) const {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  a_.add_jacobian<3>(q, identity, B, first_row);
  b_.add_jacobian<3>(q, Eigen::Matrix3d(-identity), B, first_row);
}

void PointCoincidence::add_multiplier_tangent(const core::Configuration& q,
                                              const Eigen::Vector3d& lambda,
                                              Eigen::Ref<Eigen::MatrixXd> K) const {
  a_.add_multiplier_tangent(q, lambda, K);
  b_.add_multiplier_tangent(q, -lambda, K);
}

Eigen::Vector3d PointCoincidence::acceleration_terms(const core::Configuration& q,
                                                     const Eigen::VectorXd& velocity) const {
  return a_.acceleration_terms(q, velocity) - b_.acceleration_terms(q, velocity);
}

}  // namespace spar::joints
