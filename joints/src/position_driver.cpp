#include <spar/joints/position_driver.hpp>

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

void PositionDriver::compute_value(const core::Configuration& q, double t,
                                   Eigen::Ref<Eigen::VectorXd> phi) const {
  phi(0) = direction_.dot(point_.position(q)) - reference_ - f_.value(t);
}

void PositionDriver::compute_jacobian(const core::Configuration& q, double /*t*/,
                                      Eigen::Ref<Eigen::MatrixXd> B) const {
  point_.add_jacobian<1>(q, direction_.transpose(), B, 0);
}

void PositionDriver::compute_multiplier_tangent(const core::Configuration& q, double /*t*/,
                                                const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                                Eigen::Ref<Eigen::MatrixXd> K) const {
  point_.add_multiplier_tangent(q, lambda(0) * direction_, K);
}

void PositionDriver::compute_acceleration_terms(const core::Configuration& q,
                                                const Eigen::VectorXd& velocity, double t,
                                                Eigen::Ref<Eigen::VectorXd> c) const {
  c(0) = direction_.dot(point_.acceleration_terms(q, velocity)) - f_.second_derivative(t);
}

void PositionDriver::compute_time_derivative(const core::Configuration& /*q*/, double t,
                                             Eigen::Ref<Eigen::VectorXd> phi_t) const {
  phi_t(0) = -f_.first_derivative(t);
}

}  // namespace spar::joints
