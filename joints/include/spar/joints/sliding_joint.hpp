#pragma once
/// \file
/// Sliding joint: a point of a frame block slides along the centerline of a flexible carrier beam
/// at a coordinate ζ of its own, without friction (003 §4, eqs. 50–53; docs/joints.md §2.5,
/// eqs. J23–J29).

#include <spar/core/beam.hpp>
#include <spar/core/model.hpp>
#include <spar/joints/attachment.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/joints/point_kinematics.hpp>

#include <optional>
#include <string>
#include <vector>

namespace spar::joints {

/// What a sliding joint is built from.
struct SlidingJointParameters {
  /// The sliding point: a point of a frame block (a rigid body, a beam control point).
  Attachment slider;
  /// The carrier: index of a beam of the model (Model::beam).
  int carrier = 0;
  /// The slider's initial carrier coordinate ζ ∈ [0, L₀] (see SlidingJoint): Φ(q₀) is
  /// p_A(q₀) − x_B(ζ₀), so put the slider on the carrier's centerline for an assembled start.
  double zeta = 0.0;
  /// End stops: when ζ reaches one after a step the joint locks there (ζ = stop from then on).
  /// Without a stop at an end, a slider that passes it is an error (it would leave the carrier).
  std::optional<double> lower_stop;
  std::optional<double> upper_stop;
  /// For messages and events ("sliding joint 'left diagonal' locked at ...").
  std::string name = "sliding joint";
};

/// Φ = p_A(q) − x_B(ζ) (3 equations, 003 eq. 50) with x_B(ζ) = Σ_I N_I(u(ζ)) x_I the carrier's
/// centerline (003 eq. 53) and ζ a 1-entry vector block of the model that the constructor adds.
/// ζ is the carrier's curve parameter u rescaled linearly to [0, L₀], L₀ the reference length of
/// the carrier (eq. J23): it equals the reference arc length when the reference centerline is
/// parameterized proportionally to arc length (a straight line of iga::straight_line), and is
/// metre-sized everywhere. The frictionless condition x_B,ζ · λ = 0 (003 eq. 51) is not an
/// equation of its own: it is the ζ row of Bᵀλ in the dynamic equations (eq. J25), which is why
/// ζ needs no mass. After the lock (an end stop reached), a 4th equation ζ − ζ_stop = 0 holds.
///
/// Blocks: the slider's node, ζ, then the carrier's control points of the element holding ζ and
/// of its two neighbours (its "window"). The carrier's element is found from ζ at every
/// evaluation, so ζ crosses element boundaries inside a step without restart; update_structure
/// re-centres the window on ζ's element after a step (the integrator then rebuilds its pattern).
/// A Newton iterate that leaves the window (more than one element in a step) is an evaluation
/// error, which the integrator answers by cutting the step.
///
/// Beyond an end of the carrier (a step that overshoots an end stop, or a slider running off)
/// x_B continues as the end's tangent line (eq. J29) so that the iteration can be evaluated; a
/// converged step there is either locked onto the stop (the integrator then projects the state
/// back onto it) or, without a stop, reported as a spar::Error naming the joint and the time by
/// update_structure — never accepted.
///
/// The joint keeps a reference to the carrier beam: the model must outlive it.
class SlidingJoint final : public Constraint {
 public:
  /// Adds the ζ block to `model`. Raises spar::Error when the carrier or the slider's node does
  /// not exist, the slider is on the ground or on the carrier itself, or ζ₀ or a stop is outside
  /// [0, L₀] (within 1e-9 L₀ of an end counts as the end) or ζ₀ is not strictly between the
  /// stops.
  SlidingJoint(const SlidingJointParameters& parameters, core::Model& model);

  int equation_count() const override { return locked_ ? 4 : 3; }
  const std::vector<int>& blocks() const override { return blocks_; }

  /// Φ = p_A − x_B(ζ) (eq. J24), and ζ − ζ_stop when locked.
  void value(const core::Configuration& q, double t,
             Eigen::Ref<Eigen::VectorXd> phi) const override;
  /// B = [∂p_A/∂Δ_A, −x_B,ζ, −N_I I₃ (translations of control point I), 0 (their rotations)]
  /// (eq. J25); the lock row is e_ζᵀ.
  void jacobian(const core::Configuration& q, double t,
                Eigen::Ref<Eigen::MatrixXd> B) const override;
  /// ∂(Bᵀλ)/∂Δ: eq. J3 on the slider with f = λ, −x_B,ζζ·λ on (ζ, ζ), −N_I,ζ λ on (x_I, ζ) and
  /// its transpose (eq. J26).
  void multiplier_tangent(const core::Configuration& q, double t,
                          const Eigen::Ref<const Eigen::VectorXd>& lambda,
                          Eigen::Ref<Eigen::MatrixXd> K) const override;
  /// c = R_A(Ω×(Ω×a)) − 2ζ̇ Σ N_I,ζ ẋ_I − x_B,ζζ ζ̇² (eq. J27); 0 for the lock row.
  void acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                          Eigen::Ref<Eigen::VectorXd> c) const override;
  /// The distance in ζ to the nearer end stop ahead (+∞ when locked or without stops): the
  /// integrator ends a step on the lock rather than an overshoot past it.
  double event_distance(const core::Configuration& q) const override;
  /// After a converged step: locks at a stop that ζ has reached, raises spar::Error when ζ has
  /// left an end without a stop, and otherwise re-centres the window when ζ changed element.
  bool update_structure(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                        std::string& description) override;

  /// The model block holding ζ.
  int zeta_block() const { return zeta_block_; }
  /// ζ in configuration q.
  double zeta(const core::Configuration& q) const;
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
  /// The carrier element at the centre of the current window.
  int window_element() const { return window_element_; }
  const std::string& name() const { return name_; }

 private:
  /// x_B at ζ: the carrier's centerline point with its weights converted to derivatives in ζ
  /// (up to `order`), continued by the end's tangent line beyond an end (eq. J29), and the
  /// joint's Jacobian column of its first control point.
  struct Evaluation {
    core::CenterlinePoint point;
    int column = 0;
  };
  Evaluation evaluate(const core::Configuration& q, int order) const;
  void set_window(int element);
  int element_at(double zeta) const;

  const core::GeometricallyExactBeam* carrier_;
  std::string name_;
  std::string where_;  ///< "joints::SlidingJoint '<name>'", built once: evaluations allocate nothing
  AttachedPoint slider_;
  int zeta_block_ = -1;
  double length_ = 0.0;
  double parameter_per_zeta_ = 0.0;  ///< du/dζ = (u₁ − u₀)/L₀
  std::optional<double> lower_stop_, upper_stop_;
  bool locked_ = false;
  double lock_position_ = 0.0;
  double lock_time_ = 0.0;
  double zeta_at_lock_ = 0.0;
  int window_element_ = 0;
  int window_first_ = 0, window_last_ = 0;  ///< control points of the window
  std::vector<int> blocks_;
};

}  // namespace spar::joints
