#pragma once
/// \file
/// Sliding joint: a point of a frame block slides along a curve that any element family offers
/// (a beam's or a cable's centerline, a rigid body's rail) at a coordinate ζ of its own, without
/// friction (003 §4, eqs. 50–53; docs/joints.md §2.5, eqs. J23–J29).

#include <spar/core/curve.hpp>
#include <spar/core/model.hpp>
#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/point_kinematics.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace spar::joints {

/// What a sliding joint is built from.
struct SlidingJointParameters {
  /// The sliding point: a point of a frame block (a rigid body, a beam control point).
  Attachment slider;
  /// The carrier: a curve of the model — core::beam_centerline(model, b),
  /// core::cable_centerline(model, elements), core::rigid_body_rail(model, body, curve), or a
  /// family's own core::Curve.
  std::shared_ptr<const core::Curve> carrier;
  /// The slider's initial carrier coordinate ζ ∈ [0, L₀] (see SlidingJoint): Φ(q₀) is
  /// p_A(q₀) − x_B(ζ₀), so put the slider on the carrier for an assembled start.
  double zeta = 0.0;
  /// End stops: when ζ reaches one after a step the joint locks there (ζ = stop from then on).
  /// Without a stop at an end, a slider that passes it is an error (it would leave the carrier).
  std::optional<double> lower_stop;
  std::optional<double> upper_stop;
  /// For messages and events ("sliding joint 'left diagonal' locked at ...").
  std::string name = "sliding joint";
};

/// Φ = p_A(q) − x_B(ζ) (3 equations, 003 eq. 50) with x_B the carrier curve (003 eq. 53 for a
/// beam) and ζ a 1-entry vector block of the model that the constructor adds, running over the
/// curve's [0, L₀] (eq. J23: a metre-sized coordinate, the reference arc length where the curve is
/// parameterized proportionally to it). The frictionless condition x_B,ζ · λ = 0 (003 eq. 51) is
/// not an equation of its own: it is the ζ row of Bᵀλ in the dynamic equations (eq. J25), which
/// is why ζ needs no mass. After the lock (an end stop reached), a 4th equation ζ − ζ_stop = 0
/// holds.
///
/// Blocks: the slider's node, ζ, then the carrier's blocks of the segment (element) holding ζ and
/// of its two neighbours (its "window"). The segment is found from ζ at every evaluation, so ζ
/// crosses element boundaries inside a step without restart; update_structure re-centres the
/// window on ζ's segment after a step (the integrator then rebuilds its pattern). A Newton
/// iterate that leaves the window (more than one element in a step) is an evaluation error, which
/// the integrator answers by cutting the step.
///
/// Beyond an end of the carrier (a step that overshoots an end stop, or a slider running off)
/// x_B continues as the end's tangent line (eq. J29) so that the iteration can be evaluated; a
/// converged step there is either locked onto the stop (the integrator then projects the state
/// back onto it) or, without a stop, reported as a spar::Error naming the joint and the time by
/// update_structure — never accepted.
///
/// The joint shares the carrier curve; a family's curve may refer to the model (a beam's
/// centerline does), which must then outlive the joint.
class SlidingJoint final : public Constraint {
public:
  /// Adds the ζ block to `model`. Raises spar::Error when the carrier is null or names a block
  /// the model does not have, the slider's node does not exist, the slider is on the ground or on
  /// the carrier itself, or ζ₀ or a stop is outside [0, L₀] (within 1e-9 L₀ of an end counts as
  /// the end) or ζ₀ is not strictly between the stops.
  SlidingJoint(const SlidingJointParameters& parameters, core::Model& model);

  int equation_count() const override { return locked_ ? 4 : 3; }
  const std::vector<int>& blocks() const override { return blocks_; }

  /// The distance in ζ to the nearer end stop ahead (+∞ when locked or without stops): the
  /// integrator ends a step on the lock rather than an overshoot past it.
  double event_distance(const core::Configuration& q) const override;
  /// After a converged step: locks at a stop that ζ has reached, raises spar::Error when ζ has
  /// left an end without a stop, and otherwise re-centres the window when ζ changed segment.
  bool update_structure(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                        std::string& description) override;

  /// The model block holding ζ.
  int zeta_block() const { return zeta_block_; }
  /// ζ in configuration q.
  double zeta(const core::Configuration& q) const;
  /// The carrier curve.
  const core::Curve& carrier() const { return *carrier_; }
  /// The carrier's reference length L₀: ζ runs over [0, L₀].
  double carrier_length() const { return length_; }
  /// x_B(ζ) in configuration q (the carrier point the slider is held to).
  Eigen::Vector3d carrier_point(const core::Configuration& q) const;
  bool locked() const { return locked_; }
  /// The time of the step after which the joint locked (meaningful when locked()): with the
  /// integrator's event location (DynamicOptions::locate_events) the time the slider reached
  /// the stop, to the location's tolerance.
  double lock_time() const { return lock_time_; }
  /// The stop the joint locked at (meaningful when locked()).
  double lock_position() const { return lock_position_; }
  /// ζ at the end of the step after which the joint locked, past the stop (meaningful when
  /// locked()): with the ζ of the step before, it places the arrival at the stop within the step.
  double zeta_at_lock() const { return zeta_at_lock_; }
  /// The carrier segment (element) at the centre of the current window.
  int window_element() const { return window_element_; }
  const std::string& name() const { return name_; }

private:
  /// Φ = p_A − x_B(ζ) (eq. J24), and ζ − ζ_stop when locked.
  void compute_value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// B = [∂p_A/∂Δ_A, −x_B,ζ, −∂x_B/∂Δ (the carrier's blocks)] (eq. J25); the lock row is e_ζᵀ.
  void compute_jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// ∂(Bᵀλ)/∂Δ: eq. J3 on the slider with f = λ, and the carrier's second derivatives of
  /// −x_B(ζ, q)·λ in (ζ, Δ) (003 eq. 52; eq. J26 for a beam).
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// c = R_A(Ω×(Ω×a)) − (ẍ_B less its terms in ζ̈ and the carrier's accelerations) (eq. J27);
  /// 0 for the lock row.
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  /// x_B at ζ with its ζ-derivatives up to `order`, and the joint's Jacobian column of the
  /// point's first carrier block. Throws when the point's blocks are not all in the window.
  struct Evaluation {
    core::CurvePoint point;
    int column = 0;
  };
  Evaluation evaluate(const core::Configuration& q, int order) const;
  void set_window(const core::Configuration& q, int segment);

  std::shared_ptr<const core::Curve> carrier_;
  std::string name_;
  std::string where_;  ///< "joints::SlidingJoint '<name>'", built once: evaluations allocate nothing
  AttachedPoint slider_;
  int zeta_block_ = -1;
  double length_ = 0.0;
  std::optional<double> lower_stop_, upper_stop_;
  bool locked_ = false;
  double lock_position_ = 0.0;
  double lock_time_ = 0.0;
  double zeta_at_lock_ = 0.0;
  int window_element_ = 0;
  int window_first_ = 0, window_last_ = 0;  ///< the carrier's blocks of the window
  std::vector<int> window_columns_;         ///< the Jacobian column of each of them
  std::vector<int> blocks_;
};

}  // namespace spar::joints
