#include <spar/joints/position_driver.hpp>

#include "evaluation_checks.hpp"

#include <utility>

namespace spar::joints {

namespace {
constexpr std::string_view name = "joints::PositionDriver";
}

PositionDriver::PositionDriver(const Attachment& a, const Eigen::Vector3d& direction,
                               TimeFunction f, const core::Configuration& q0)
    : point_(single_node_frame(a.node, q0, name), finite_point(a.offset, "attachment offset", name)),
      direction_(unit_vector(direction, "driving direction", name)),
      reference_(direction_.dot(point_.position(q0))),
      f_(std::move(f)) {
  check_time_function(f_, name);
  nodes_ = {a.node};
}

void PositionDriver::value(const core::Configuration& q, double t,
                           Eigen::Ref<Eigen::VectorXd> phi) const {
  detail::begin_vector_output(*this, q, phi, name);
  phi(0) = direction_.dot(point_.position(q)) - reference_ - f_.value(t);
}

void PositionDriver::jacobian(const core::Configuration& q, double /*t*/,
                              Eigen::Ref<Eigen::MatrixXd> B) const {
  detail::begin_jacobian(*this, q, B, name);
  point_.add_jacobian<1>(q, direction_.transpose(), B, 0);
}

void PositionDriver::multiplier_tangent(const core::Configuration& q, double /*t*/,
                                        const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                        Eigen::Ref<Eigen::MatrixXd> K) const {
  detail::begin_multiplier_tangent(*this, q, lambda, K, name);
  point_.add_multiplier_tangent(q, lambda(0) * direction_, K);
}

void PositionDriver::acceleration_terms(const core::Configuration& q,
                                        const Eigen::VectorXd& velocity, double t,
                                        Eigen::Ref<Eigen::VectorXd> c) const {
  detail::begin_acceleration_terms(*this, q, velocity, c, name);
  c(0) = direction_.dot(point_.acceleration_terms(q, velocity)) - f_.second_derivative(t);
}

void PositionDriver::time_derivative(const core::Configuration& q, double t,
                                     Eigen::Ref<Eigen::VectorXd> phi_t) const {
  detail::begin_vector_output(*this, q, phi_t, name);
  phi_t(0) = -f_.first_derivative(t);
}

}  // namespace spar::joints
