#include <spar/joints/spherical_joint.hpp>

#include "evaluation_checks.hpp"

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

void SphericalJoint::value(const core::Configuration& q, double /*t*/,
                           Eigen::Ref<Eigen::VectorXd> phi) const {
  detail::begin_vector_output(*this, q, phi, name);
  phi = points_.value(q);
}

void SphericalJoint::jacobian(const core::Configuration& q, double /*t*/,
                              Eigen::Ref<Eigen::MatrixXd> B) const {
  detail::begin_jacobian(*this, q, B, name);
  points_.add_jacobian(q, B, 0);
}

void SphericalJoint::multiplier_tangent(const core::Configuration& q, double /*t*/,
                                        const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                        Eigen::Ref<Eigen::MatrixXd> K) const {
  detail::begin_multiplier_tangent(*this, q, lambda, K, name);
  points_.add_multiplier_tangent(q, lambda, K);
}

void SphericalJoint::acceleration_terms(const core::Configuration& q,
                                        const Eigen::VectorXd& velocity, double /*t*/,
                                        Eigen::Ref<Eigen::VectorXd> c) const {
  detail::begin_acceleration_terms(*this, q, velocity, c, name);
  c = points_.acceleration_terms(q, velocity);
}

}  // namespace spar::joints
