#include <spar/joints/angle_driver.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <utility>

namespace spar::joints {

namespace {
constexpr std::string_view name = "joints::AngleDriver";
}

AngleDriver::AngleDriver(int node, const Eigen::Vector3d& axis, TimeFunction angle,
                         const core::Configuration& q0)
    : axis_(unit_vector(axis, "rotation axis", name)),
      reference_(axis_.unitOrthogonal()),
      angle_(std::move(angle)) {
  const JointFrame frame = single_node_frame(node, q0, name);
  check_time_function(angle_, name);
  nodes_ = {node};
  vector_ = AttachedVector::from_inertial(frame, reference_, q0);
}

AngleDriver::DrivenFrame AngleDriver::driven_frame(double f) const {
  const Eigen::Vector3d normal = axis_.cross(reference_);
  const Eigen::Vector3d d = std::cos(f) * reference_ + std::sin(f) * normal;
  return {.d = d, .w = axis_.cross(d)};
}

void AngleDriver::compute_value(const core::Configuration& q, double t,
                                Eigen::Ref<Eigen::VectorXd> phi) const {
  phi(0) = vector_.direction(q).dot(driven_frame(angle_.value(t)).w);
}

void AngleDriver::compute_jacobian(const core::Configuration& q, double t,
                                   Eigen::Ref<Eigen::MatrixXd> B) const {
  vector_.add_jacobian_along(q, driven_frame(angle_.value(t)).w, B, 0);
}

void AngleDriver::compute_multiplier_tangent(const core::Configuration& q, double t,
                                             const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                             Eigen::Ref<Eigen::MatrixXd> K) const {
  vector_.add_multiplier_tangent_along(q, driven_frame(angle_.value(t)).w, lambda(0), K);
}

void AngleDriver::compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                             double t, Eigen::Ref<Eigen::VectorXd> c) const {
  const DrivenFrame frame = driven_frame(angle_.value(t));
  const double rate = angle_.first_derivative(t);
  // ḋ = f′ n × d = f′ w, so ẇ = n × ḋ = −f′ d (d ⊥ n) and ẅ = −f″ d − f′² w (eq. J22).
  const Eigen::Vector3d w_rate = -rate * frame.d;
  const Eigen::Vector3d w_acceleration =
      -angle_.second_derivative(t) * frame.d - rate * rate * frame.w;
  c(0) = vector_.acceleration_terms(q, velocity).dot(frame.w) +
         2 * vector_.rate(q, velocity).dot(w_rate) + vector_.direction(q).dot(w_acceleration);
}

void AngleDriver::compute_time_derivative(const core::Configuration& q, double t,
                                          Eigen::Ref<Eigen::VectorXd> phi_t) const {
  phi_t(0) =
      -angle_.first_derivative(t) * vector_.direction(q).dot(driven_frame(angle_.value(t)).d);
}

}  // namespace spar::joints
