#include <spar/joints/spherical_joint.hpp>

namespace spar::joints {

namespace {
constexpr std::string_view name = "joints::SphericalJoint";
}

SphericalJoint::SphericalJoint(const Attachment& a, const Attachment& b,
                               const core::Configuration& q0)
    : SphericalJoint(a, b, joint_frames(a, b, q0, name)) {}

SphericalJoint::SphericalJoint(const Attachment& a, const Attachment& b, const JointFrames& frames)
    : nodes_(frames.nodes),
      points_(AttachedPoint(frames.a, a.offset), AttachedPoint(frames.b, b.offset)) {}

void SphericalJoint::compute_value(const core::Configuration& q, double /*t*/,
                                   Eigen::Ref<Eigen::VectorXd> phi) const {
  phi = points_.value(q);
}

void SphericalJoint::compute_jacobian(const core::Configuration& q, double /*t*/,
                                      Eigen::Ref<Eigen::MatrixXd> B) const {
  points_.add_jacobian(q, B, 0);
}

void SphericalJoint::compute_multiplier_tangent(const core::Configuration& q, double /*t*/,
                                                const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                                Eigen::Ref<Eigen::MatrixXd> K) const {
  points_.add_multiplier_tangent(q, lambda, K);
}

void SphericalJoint::compute_acceleration_terms(const core::Configuration& q,
                                                const Eigen::VectorXd& velocity, double /*t*/,
                                                Eigen::Ref<Eigen::VectorXd> c) const {
  c = points_.acceleration_terms(q, velocity);
}

}  // namespace spar::joints
