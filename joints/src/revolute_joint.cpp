#include <spar/joints/revolute_joint.hpp>

#include "evaluation_checks.hpp"

#include <Eigen/Geometry>

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
      points_(AttachedPoint(frames.a, a.offset), AttachedPoint(frames.b, b.offset)) {
  // `axis` is a unit vector here; n₁, n₂ complete it to an orthonormal basis.
  const Eigen::Vector3d normal_1 = axis.unitOrthogonal();
  const Eigen::Vector3d normal_2 = axis.cross(normal_1);
  const AttachedVector hinge = AttachedVector::from_inertial(frames.a, axis, q0);
  axis_products_ = {DotProduct(hinge, AttachedVector::from_inertial(frames.b, normal_1, q0)),
                    DotProduct(hinge, AttachedVector::from_inertial(frames.b, normal_2, q0))};
}

void RevoluteJoint::value(const core::Configuration& q, double /*t*/,
                          Eigen::Ref<Eigen::VectorXd> phi) const {
  detail::begin_vector_output(*this, q, phi, name);
  phi.head<3>() = points_.value(q);
  for (int i = 0; i < 2; ++i) phi(3 + i) = axis_products_[i].value(q);
}

void RevoluteJoint::jacobian(const core::Configuration& q, double /*t*/,
                             Eigen::Ref<Eigen::MatrixXd> B) const {
  detail::begin_jacobian(*this, q, B, name);
  points_.add_jacobian(q, B, 0);
  for (int i = 0; i < 2; ++i) axis_products_[i].add_jacobian(q, B, 3 + i);
}

void RevoluteJoint::multiplier_tangent(const core::Configuration& q, double /*t*/,
                                       const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                       Eigen::Ref<Eigen::MatrixXd> K) const {
  detail::begin_multiplier_tangent(*this, q, lambda, K, name);
  points_.add_multiplier_tangent(q, lambda.head<3>(), K);
  for (int i = 0; i < 2; ++i) axis_products_[i].add_multiplier_tangent(q, lambda(3 + i), K);
}

void RevoluteJoint::acceleration_terms(const core::Configuration& q,
                                       const Eigen::VectorXd& velocity, double /*t*/,
                                       Eigen::Ref<Eigen::VectorXd> c) const {
  detail::begin_acceleration_terms(*this, q, velocity, c, name);
  c.head<3>() = points_.acceleration_terms(q, velocity);
  for (int i = 0; i < 2; ++i) c(3 + i) = axis_products_[i].acceleration_terms(q, velocity);
}

}  // namespace spar::joints
