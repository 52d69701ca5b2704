#include <spar/joints/sliding_joint.hpp>

#include <spar/error.hpp>

#include "evaluation_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace spar::joints {

namespace {

// Jacobian columns: the slider's node (6), ζ (1), then 6 per control point of the window.
constexpr int zeta_column = core::frame_dofs;
constexpr int first_carrier_column = zeta_column + 1;

std::string number(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

}  // namespace

SlidingJoint::SlidingJoint(const SlidingJointParameters& parameters, core::Model& model)
    : carrier_(&model.beam(parameters.carrier)),
      name_(parameters.name),
      where_("joints::SlidingJoint '" + parameters.name + "'"),
      lower_stop_(parameters.lower_stop),
      upper_stop_(parameters.upper_stop) {
  const core::Configuration& q0 = model.state();
  slider_ = AttachedPoint(single_node_frame(parameters.slider.node, q0, where_),
                          finite_point(parameters.slider.offset, "slider offset", where_));
  const int node = parameters.slider.node;
  if (node >= carrier_->first_node() &&
      node < carrier_->first_node() + carrier_->control_point_count())
    throw Error("the slider is attached to control point " +
                    std::to_string(node - carrier_->first_node()) + " of its own carrier",
                where_, "attach the slider to another body or beam than the carrier");
  const iga::KnotVector& U = carrier_->reference_centerline().knots();
  length_ = carrier_->reference_centerline().arc_length(U.first(), U.last());
  parameter_per_zeta_ = (U.last() - U.first()) / length_;
  // Coordinates within 1e-9 L₀ of an end (a stop at the carrier's end given as the distance
  // between its end points, say) are snapped to it: L₀ is a computed arc length.
  const auto inside = [&](double zeta, const std::string& what) {
    if (!(zeta >= -1e-9 * length_ && zeta <= (1 + 1e-9) * length_))
      throw Error(what + " = " + number(zeta) + " is outside the carrier's [0, L0 = " +
                      number(length_) + "]",
                  where_, "give carrier coordinates between 0 and the carrier's reference length");
    return std::clamp(zeta, 0.0, length_);
  };
  const double zeta0 = inside(parameters.zeta, "the initial zeta");
  if (lower_stop_) lower_stop_ = inside(*lower_stop_, "the lower stop");
  if (upper_stop_) upper_stop_ = inside(*upper_stop_, "the upper stop");
  if ((lower_stop_ && !(zeta0 > *lower_stop_)) || (upper_stop_ && !(zeta0 < *upper_stop_)))
    throw Error("the initial zeta = " + number(parameters.zeta) +
                    " is not strictly between the stops",
                where_, "start the slider between its end stops");
  zeta_block_ = model.add_vector(Eigen::VectorXd::Constant(1, zeta0));
  set_window(element_at(zeta0));
}

int SlidingJoint::element_at(double zeta) const {
  const double u = carrier_->reference_centerline().knots().first() + parameter_per_zeta_ * zeta;
  const iga::KnotVector& U = carrier_->reference_centerline().knots();
  return carrier_->centerline_point(std::clamp(u, U.first(), U.last()), 0).element;
}

void SlidingJoint::set_window(int element) {
  window_element_ = element;
  const int last = carrier_->element_count() - 1;
  window_first_ = carrier_->element(std::max(element - 1, 0)).first_control_point;
  window_last_ = carrier_->element(std::min(element + 1, last)).first_control_point +
                 carrier_->degree();
  blocks_ = {slider_.frame().node, zeta_block_};
  for (int I = window_first_; I <= window_last_; ++I) blocks_.push_back(carrier_->node(I));
}

double SlidingJoint::zeta(const core::Configuration& q) const { return q.vector(zeta_block_)(0); }

// 003 eq. 53 with u = u₀ + (du/dζ) ζ (eq. J23): d^k x_B/dζ^k = (du/dζ)^k Σ N_I^(k)(u) x_I. Beyond
// an end the tangent line x_B(ζ_e) + x_B,ζ(ζ_e)(ζ − ζ_e) (eq. J29).
SlidingJoint::Evaluation SlidingJoint::evaluate(const core::Configuration& q, int order) const {
  const double z = zeta(q);
  if (!std::isfinite(z))
    throw Error("zeta is not finite", where_, "check the model for NaN velocities or loads");
  const iga::KnotVector& U = carrier_->reference_centerline().knots();
  const double end = z <= 0.0 ? 0.0 : (z >= length_ ? length_ : z);
  const double u = std::clamp(U.first() + parameter_per_zeta_ * end, U.first(), U.last());
  Evaluation e;
  e.point = carrier_->centerline_point(u, std::max(order, 1));
  double scale = 1.0;
  for (int k = 1; k <= e.point.order; ++k) {
    scale *= parameter_per_zeta_;
    e.point.shape.row(k) *= scale;
  }
  if (z != end) {  // eq. J29: x_B = Σ (N_I + N_I,ζ (ζ − ζ_e)) x_I, x_B,ζ constant, x_B,ζζ = 0
    e.point.shape.row(0) += (z - end) * e.point.shape.row(1);
    e.point.shape.bottomRows(iga::max_derivative_order - 1).setZero();
  }
  const int first = e.point.first_control_point;
  if (first < window_first_ || first + carrier_->degree() > window_last_)
    throw Error("zeta = " + number(z) + " lies in carrier element " +
                    std::to_string(e.point.element) + ", beyond the neighbours of element " +
                    std::to_string(window_element_) + " that the joint covers in this step",
                where_, "reduce the time step: the slider crossed more than one element in a step");
  e.column = first_carrier_column + core::frame_dofs * (first - window_first_);
  return e;
}

Eigen::Vector3d SlidingJoint::carrier_point(const core::Configuration& q) const {
  return carrier_->centerline_derivative(q, evaluate(q, 0).point, 0);
}

void SlidingJoint::value(const core::Configuration& q, double /*t*/,
                         Eigen::Ref<Eigen::VectorXd> phi) const {
  detail::begin_vector_output(*this, q, phi, where_);
  phi.head<3>() = slider_.position(q) - carrier_point(q);  // 003 eq. 50
  if (locked_) phi(3) = zeta(q) - lock_position_;
}

void SlidingJoint::jacobian(const core::Configuration& q, double /*t*/,
                            Eigen::Ref<Eigen::MatrixXd> B) const {
  detail::begin_jacobian(*this, q, B, where_);
  const Evaluation e = evaluate(q, 1);
  slider_.add_jacobian<3>(q, Eigen::Matrix3d::Identity(), B, 0);
  B.block<3, 1>(0, zeta_column) = -carrier_->centerline_derivative(q, e.point, 1);
  for (int I = 0; I <= carrier_->degree(); ++I)
    B.block<3, 3>(0, e.column + core::frame_dofs * I).diagonal().setConstant(-e.point.shape(0, I));
  if (locked_) B(3, zeta_column) = 1.0;
}

void SlidingJoint::multiplier_tangent(const core::Configuration& q, double /*t*/,
                                      const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                      Eigen::Ref<Eigen::MatrixXd> K) const {
  detail::begin_multiplier_tangent(*this, q, lambda, K, where_);
  const Evaluation e = evaluate(q, 2);
  const Eigen::Vector3d force = lambda.head<3>();
  slider_.add_multiplier_tangent(q, force, K);
  // The ζ row of Bᵀλ is −x_B,ζ·λ (the frictionless condition, 003 eq. 51); the rows of x_I are
  // −N_I λ. Their derivatives (003 eq. 52): −x_B,ζζ·λ, −N_I,ζ λ and its transpose.
  K(zeta_column, zeta_column) = -carrier_->centerline_derivative(q, e.point, 2).dot(force);
  for (int I = 0; I <= carrier_->degree(); ++I) {
    const int column = e.column + core::frame_dofs * I;
    K.block<1, 3>(zeta_column, column) = -e.point.shape(1, I) * force.transpose();
    K.block<3, 1>(column, zeta_column) = -e.point.shape(1, I) * force;
  }
}

void SlidingJoint::acceleration_terms(const core::Configuration& q,
                                      const Eigen::VectorXd& velocity, double /*t*/,
                                      Eigen::Ref<Eigen::VectorXd> c) const {
  detail::begin_acceleration_terms(*this, q, velocity, c, where_);
  const Evaluation e = evaluate(q, 2);
  const double zeta_rate = velocity(q.blocks[zeta_block_].offset);
  // ẍ_B = Σ N_I ẍ_I + x_B,ζ ζ̈ + 2 ζ̇ Σ N_I,ζ ẋ_I + x_B,ζζ ζ̇².
  Eigen::Vector3d carrier_terms = carrier_->centerline_derivative(q, e.point, 2) * zeta_rate * zeta_rate;
  const int first = carrier_->node(e.point.first_control_point);
  for (int I = 0; I <= carrier_->degree(); ++I)
    carrier_terms += 2 * zeta_rate * e.point.shape(1, I) *
                     velocity.segment<3>(q.blocks[first + I].offset);
  c.head<3>() = slider_.acceleration_terms(q, velocity) - carrier_terms;
}

double SlidingJoint::event_distance(const core::Configuration& q) const {
  double distance = std::numeric_limits<double>::infinity();
  if (locked_) return distance;
  const double z = zeta(q);
  if (upper_stop_) distance = std::min(distance, *upper_stop_ - z);
  if (lower_stop_) distance = std::min(distance, z - *lower_stop_);
  return distance;
}

bool SlidingJoint::update_structure(const core::Configuration& q, const Eigen::VectorXd& /*velocity*/,
                                    double t, std::string& description) {
  if (locked_) return false;
  const double z = zeta(q);
  const auto lock = [&](double stop, const char* which) {
    locked_ = true;
    lock_position_ = stop;
    lock_time_ = t;
    zeta_at_lock_ = z;
    description = "sliding joint '" + name_ + "' locked at its " + which + " stop zeta = " +
                  number(stop) + " (zeta = " + number(z) + " after the step)";
  };
  if (upper_stop_ && z >= *upper_stop_) {
    lock(*upper_stop_, "upper");
    return true;
  }
  if (lower_stop_ && z <= *lower_stop_) {
    lock(*lower_stop_, "lower");
    return true;
  }
  if (!(z >= 0.0 && z <= length_))
    throw Error("the slider ran off the " + std::string(z < 0.0 ? "start" : "end") +
                    " of its carrier at t = " + number(t) + " (zeta = " + number(z) +
                    ", carrier coordinates 0 … " + number(length_) + ")",
                where_, "give the joint an end stop there (lower_stop / upper_stop), or end the "
                         "run before the slider reaches the carrier's end");
  const int element = element_at(z);
  if (element == window_element_) return false;
  set_window(element);
  description = "sliding joint '" + name_ + "' entered carrier element " + std::to_string(element);
  return true;
}

}  // namespace spar::joints
