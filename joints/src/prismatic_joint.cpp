#include <spar/joints/prismatic_joint.hpp>

#include <Eigen/Geometry>

namespace spar::joints {

namespace {

constexpr std::string_view name = "joints::PrismaticJoint";

/// Rows n₁ᵀ, n₂ᵀ: an orthonormal pair ⊥ the unit direction.
Eigen::Matrix<double, 2, 3> line_normals(const Eigen::Vector3d& direction) {
  Eigen::Matrix<double, 2, 3> normals;
  normals.row(0) = direction.unitOrthogonal().transpose();
  normals.row(1) = direction.cross(normals.row(0).transpose()).transpose();
  return normals;
}

}  // namespace

PrismaticJoint::PrismaticJoint(const Attachment& a, const Eigen::Vector3d& line_point,
                               const Eigen::Vector3d& direction, bool lock_rotation,
                               const core::Configuration& q0)
    : point_(single_node_frame(a.node, q0, name), finite_point(a.offset, "attachment offset", name)),
      line_point_(finite_point(line_point, "line point", name)),
      normals_(line_normals(unit_vector(direction, "line direction", name))) {
  nodes_ = {a.node};
  if (lock_rotation) rotation_lock_.emplace(point_.frame(), JointFrame{}, q0);
}

void PrismaticJoint::compute_value(const core::Configuration& q, double /*t*/,
                                   Eigen::Ref<Eigen::VectorXd> phi) const {
  phi.head<2>() = normals_ * (point_.position(q) - line_point_);
  if (rotation_lock_) phi.segment<3>(2) = rotation_lock_->value(q);
}

void PrismaticJoint::compute_jacobian(const core::Configuration& q, double /*t*/,
                                      Eigen::Ref<Eigen::MatrixXd> B) const {
  point_.add_jacobian<2>(q, normals_, B, 0);
  if (rotation_lock_) rotation_lock_->add_jacobian(q, B, 2);
}

void PrismaticJoint::compute_multiplier_tangent(const core::Configuration& q, double /*t*/,
                                                const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                                Eigen::Ref<Eigen::MatrixXd> K) const {
  point_.add_multiplier_tangent(q, normals_.transpose() * lambda.head<2>(), K);
  if (rotation_lock_) rotation_lock_->add_multiplier_tangent(q, lambda.segment<3>(2), K);
}

void PrismaticJoint::compute_acceleration_terms(const core::Configuration& q,
                                                const Eigen::VectorXd& velocity, double /*t*/,
                                                Eigen::Ref<Eigen::VectorXd> c) const {
  c.head<2>() = normals_ * point_.acceleration_terms(q, velocity);
  if (rotation_lock_) c.segment<3>(2) = rotation_lock_->acceleration_terms(q, velocity);
}

double PrismaticJoint::stroke(const core::Configuration& q) const {
  // d = n₁ × n₂, since n₂ = d × n₁ (line_normals).
  const Eigen::Vector3d direction = normals_.row(0).transpose().cross(normals_.row(1).transpose());
  return (point_.position(q) - line_point_).dot(direction);
}

double PrismaticJoint::stroke_rate(const core::Configuration& q, const Eigen::VectorXd& velocity) const {
  const Eigen::Vector3d direction = normals_.row(0).transpose().cross(normals_.row(1).transpose());
  const JointFrame& f = point_.frame();
  const Eigen::Vector3d rate = velocity.segment<3>(q.blocks[f.node].offset) +
                               q.rotation[f.node] * f.angular_velocity(q, velocity).cross(point_.offset());
  return rate.dot(direction);
}

}  // namespace spar::joints
