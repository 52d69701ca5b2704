#include <spar/joints/revolute_joint.hpp>

#include <Eigen/Geometry>

#include <cmath>

namespace spar::joints {

namespace {
constexpr std::string_view name = "joints::RevoluteJoint";
}

RevoluteJoint::RevoluteJoint(const Attachment& a, const Attachment& b, const Eigen::Vector3d& axis,
                             const core::Configuration& q0)
    : RevoluteJoint(a, b, unit_vector(axis, "hinge axis", name), joint_frames(a, b, q0, name), q0) {
}

RevoluteJoint::RevoluteJoint(const Attachment& a, const Attachment& b, const Eigen::Vector3d& axis,
                             const JointFrames& frames, const core::Configuration& q0)
    : nodes_(frames.nodes),
      points_(AttachedPoint(frames.a, a.offset), AttachedPoint(frames.b, b.offset)),
      point_b_(frames.b, b.offset) {
  // `axis` is a unit vector here; n₁, n₂ complete it to an orthonormal basis.
  const Eigen::Vector3d normal_1 = axis.unitOrthogonal();
  const Eigen::Vector3d normal_2 = axis.cross(normal_1);
  axis_a_ = AttachedVector::from_inertial(frames.a, axis, q0);
  normal_a_ = AttachedVector::from_inertial(frames.a, normal_1, q0);
  normals_b_ = {AttachedVector::from_inertial(frames.b, normal_1, q0),
                AttachedVector::from_inertial(frames.b, normal_2, q0)};
  axis_products_ = {DotProduct(axis_a_, normals_b_[0]), DotProduct(axis_a_, normals_b_[1])};
}

void RevoluteJoint::compute_value(const core::Configuration& q, double /*t*/,
                                  Eigen::Ref<Eigen::VectorXd> phi) const {
  phi.head<3>() = points_.value(q);
  for (int i = 0; i < 2; ++i) phi(3 + i) = axis_products_[i].value(q);
}

void RevoluteJoint::compute_jacobian(const core::Configuration& q, double /*t*/,
                                     Eigen::Ref<Eigen::MatrixXd> B) const {
  points_.add_jacobian(q, B, 0);
  for (int i = 0; i < 2; ++i) axis_products_[i].add_jacobian(q, B, 3 + i);
}

void RevoluteJoint::compute_multiplier_tangent(const core::Configuration& q, double /*t*/,
                                               const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                               Eigen::Ref<Eigen::MatrixXd> K) const {
  points_.add_multiplier_tangent(q, lambda.head<3>(), K);
  for (int i = 0; i < 2; ++i) axis_products_[i].add_multiplier_tangent(q, lambda(3 + i), K);
}

void RevoluteJoint::compute_acceleration_terms(const core::Configuration& q,
                                               const Eigen::VectorXd& velocity, double /*t*/,
                                               Eigen::Ref<Eigen::VectorXd> c) const {
  c.head<3>() = points_.acceleration_terms(q, velocity);
  for (int i = 0; i < 2; ++i) c(3 + i) = axis_products_[i].acceleration_terms(q, velocity);
}

Eigen::Vector3d RevoluteJoint::point(const core::Configuration& q) const { return point_b_.position(q); }

Eigen::Matrix3d RevoluteJoint::frame(const core::Configuration& q) const {
  Eigen::Matrix3d frame;
  frame.col(0) = normals_b_[0].direction(q);
  frame.col(1) = normals_b_[1].direction(q);
  frame.col(2) = frame.col(0).cross(frame.col(1));
  return frame;
}

double RevoluteJoint::relative_angle(const core::Configuration& q) const {
  const Eigen::Vector3d d = normal_a_.direction(q);
  return std::atan2(d.dot(normals_b_[1].direction(q)), d.dot(normals_b_[0].direction(q)));
}

double RevoluteJoint::relative_rate(const core::Configuration& q, const Eigen::VectorXd& velocity) const {
  auto omega = [&](const JointFrame& f) -> Eigen::Vector3d {
    return f.on_ground() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(q.rotation[f.node] * f.angular_velocity(q, velocity));
  };
  return (omega(normal_a_.frame()) - omega(normals_b_[0].frame())).dot(frame(q).col(2));
}

Wrench RevoluteJoint::reaction_in_frame(const core::Configuration& q, double t,
                                        const Eigen::Ref<const Eigen::VectorXd>& lambda) const {
  const Eigen::Vector3d p = point(q);
  const JointFrame& a = normal_a_.frame();
  Wrench w;
  if (!a.on_ground()) {
    w = reaction(*this, q, t, lambda, a.node, p);
  } else {
    const Wrench on_b = reaction(*this, q, t, lambda, normals_b_[0].frame().node, p);
    w.force = -on_b.force;
    w.moment = -on_b.moment;
  }
  const Eigen::Matrix3d basis = frame(q);
  return {.force = basis.transpose() * w.force, .moment = basis.transpose() * w.moment};
}

}  // namespace spar::joints
