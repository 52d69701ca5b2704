#include <spar/joints/sliding_joint.hpp>

#include <spar/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace spar::joints {

namespace {

// Jacobian columns: the slider's node (6), ζ (1), then the carrier's blocks of the window.
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
    : carrier_(parameters.carrier),
      name_(parameters.name),
      where_("joints::SlidingJoint '" + parameters.name + "'"),
      lower_stop_(parameters.lower_stop),
      upper_stop_(parameters.upper_stop) {
  if (!carrier_)
    throw Error("the joint has no carrier", where_,
                "give the curve to slide along (core::beam_centerline(model, b), core::cable_centerline, "
                "core::rigid_body_rail)");
  const core::Configuration& q0 = model.state();
  slider_ = AttachedPoint(single_node_frame(parameters.slider.node, q0, where_),
                          finite_point(parameters.slider.offset, "slider offset", where_));
  for (int i = 0; i < carrier_->block_count(); ++i) {
    const int block = carrier_->block(i);
    if (block < 0 || block >= q0.block_count())
      throw Error("the carrier's block " + std::to_string(i) + " is block " + std::to_string(block) +
                      ", which the model does not have",
                  where_, "give a carrier curve of this model");
    if (block == parameters.slider.node)
      throw Error("the slider is attached to node " + std::to_string(block) + ", block " + std::to_string(i) +
                      " of its own carrier",
                  where_, "attach the slider to another body or beam than the carrier");
  }
  length_ = carrier_->length();
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
  set_window(model.state(), carrier_->segment_at(zeta0));
}

// The window (eq. J28): the carrier's blocks of segments e − 1 … e + 1, clipped at the ends.
void SlidingJoint::set_window(const core::Configuration& q, int segment) {
  window_element_ = segment;
  const int last = carrier_->segment_count() - 1;
  const core::CurveBlocks window = carrier_->segment_blocks(std::max(segment - 1, 0), std::min(segment + 1, last));
  window_first_ = window.first;
  window_last_ = window.last;
  blocks_ = {slider_.frame().node, zeta_block_};
  window_columns_.clear();
  int column = first_carrier_column;
  for (int i = window_first_; i <= window_last_; ++i) {
    blocks_.push_back(carrier_->block(i));
    window_columns_.push_back(column);
    column += q.blocks[blocks_.back()].size;
  }
}

double SlidingJoint::zeta(const core::Configuration& q) const { return q.vector(zeta_block_)(0); }

SlidingJoint::Evaluation SlidingJoint::evaluate(const core::Configuration& q, int order) const {
  const double z = zeta(q);
  if (!std::isfinite(z))
    throw Error("zeta is not finite", where_, "check the model for NaN velocities or loads");
  Evaluation e;
  e.point = carrier_->point(q, z, order);
  const int first = e.point.first_block;
  if (first < window_first_ || first + e.point.block_count - 1 > window_last_)
    throw Error("zeta = " + number(z) + " lies in carrier element " + std::to_string(e.point.segment) +
                    ", beyond the neighbours of element " + std::to_string(window_element_) +
                    " that the joint covers in this step",
                where_, "reduce the time step: the slider crossed more than one element in a step");
  e.column = window_columns_[first - window_first_];
  return e;
}

Eigen::Vector3d SlidingJoint::carrier_point(const core::Configuration& q) const { return evaluate(q, 0).point.x[0]; }

void SlidingJoint::compute_value(const core::Configuration& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi) const {
  phi.head<3>() = slider_.position(q) - carrier_point(q);  // 003 eq. 50
  if (locked_) phi(3) = zeta(q) - lock_position_;
}

void SlidingJoint::compute_jacobian(const core::Configuration& q, double /*t*/, Eigen::Ref<Eigen::MatrixXd> B) const {
  const Evaluation e = evaluate(q, 1);
  slider_.add_jacobian<3>(q, Eigen::Matrix3d::Identity(), B, 0);
  B.block<3, 1>(0, zeta_column) = -e.point.x[1];
  carrier_->add_jacobian(q, e.point, Eigen::Matrix3d(-Eigen::Matrix3d::Identity()), B, 0, e.column);
  if (locked_) B(3, zeta_column) = 1.0;
}

void SlidingJoint::compute_multiplier_tangent(const core::Configuration& q, double /*t*/,
                                              const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                              Eigen::Ref<Eigen::MatrixXd> K) const {
  const Evaluation e = evaluate(q, 2);
  const Eigen::Vector3d force = lambda.head<3>();
  slider_.add_multiplier_tangent(q, force, K);
  // The ζ row of Bᵀλ is −x_B,ζ·λ (the frictionless condition, 003 eq. 51), the carrier's rows
  // −(∂x_B/∂Δ)ᵀλ: their derivatives (003 eq. 52) are the carrier's with f = −λ.
  carrier_->add_multiplier_tangent(q, e.point, -force, K, zeta_column, e.column);
}

void SlidingJoint::compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                              double /*t*/, Eigen::Ref<Eigen::VectorXd> c) const {
  const Evaluation e = evaluate(q, 2);
  const double zeta_rate = velocity(q.blocks[zeta_block_].offset);
  // ẍ_B = (∂x_B/∂Δ) v̇ + x_B,ζ ζ̈ + the carrier's terms (for a beam 2 ζ̇ Σ N_I,ζ ẋ_I + x_B,ζζ ζ̇²).
  Eigen::Vector3d carrier_terms = Eigen::Vector3d::Zero();
  carrier_->add_acceleration_terms(q, e.point, velocity, zeta_rate, carrier_terms);
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
  const int segment = carrier_->segment_at(z);
  if (segment == window_element_) return false;
  set_window(q, segment);
  description = "sliding joint '" + name_ + "' entered carrier element " + std::to_string(segment);
  return true;
}

}  // namespace spar::joints
