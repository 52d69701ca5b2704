#include <spar/joints/clamp_joint.hpp>

namespace spar::joints {

namespace {
constexpr std::string_view name = "joints::ClampJoint";
}

ClampJoint::ClampJoint(const Attachment& a, const Attachment& b, const core::Configuration& q0)
    : ClampJoint(a, b, joint_frames(a, b, q0, name), q0) {}

ClampJoint::ClampJoint(const Attachment& a, const Attachment& b, const JointFrames& frames,
                       const core::Configuration& q0)
    : nodes_(frames.nodes),
      points_(AttachedPoint(frames.a, a.offset), AttachedPoint(frames.b, b.offset)),
      rotation_lock_(frames.a, frames.b, q0) {}

void ClampJoint::compute_value(const core::Configuration& q, double /*t*/,
                               Eigen::Ref<Eigen::VectorXd> phi) const {
  phi.head<3>() = points_.value(q);
  phi.tail<3>() = rotation_lock_.value(q);
}

void ClampJoint::compute_jacobian(const core::Configuration& q, double /*t*/,
                                  Eigen::Ref<Eigen::MatrixXd> B) const {
  points_.add_jacobian(q, B, 0);
  rotation_lock_.add_jacobian(q, B, 3);
}

void ClampJoint::compute_multiplier_tangent(const core::Configuration& q, double /*t*/,
                                            const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                            Eigen::Ref<Eigen::MatrixXd> K) const {
  points_.add_multiplier_tangent(q, lambda.head<3>(), K);
  rotation_lock_.add_multiplier_tangent(q, lambda.tail<3>(), K);
}

void ClampJoint::compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                            double /*t*/, Eigen::Ref<Eigen::VectorXd> c) const {
  c.head<3>() = points_.acceleration_terms(q, velocity);
  c.tail<3>() = rotation_lock_.acceleration_terms(q, velocity);
}

}  // namespace spar::joints
