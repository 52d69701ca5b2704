#pragma once
/// \file
/// A constraint that holds until a condition is met after a step and then lets go: the hand-over
/// of a driver to a lock (a deployment's angle drivers retiring when its sliders lock), a support
/// removed at a chosen instant (docs/joints.md §3.3).
#include <spar/joints/constraint.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spar::joints {

/// Wraps a constraint: while active it is the wrapped constraint, equation for equation; after
/// the first converged step at whose end `release(q, t)` is true it has no equations and no
/// blocks. The release is an event (update_structure returns true, the integrator rebuilds and
/// restarts consistently); it is final.
///
/// Order in the constraint list matters when the condition reads another constraint's state (a
/// sliding joint's lock): the integrator asks the constraints in list order after a step, so put
/// this one after the constraint it watches and both switch at the same step.
class ActiveUntil final : public Constraint {
 public:
  using Condition = std::function<bool(const core::Configuration& q, double t)>;
  /// Raises spar::Error for an empty constraint or condition.
  ActiveUntil(std::unique_ptr<Constraint> constraint, Condition release, std::string name);

  int equation_count() const override { return active_ ? constraint_->equation_count() : 0; }
  const std::vector<int>& blocks() const override { return active_ ? constraint_->blocks() : none_; }
  /// While active, the wrapped constraint's; the release condition is not an event distance
  /// (it is tested at the end of each step).
  double event_distance(const core::Configuration& q) const override {
    return active_ ? constraint_->event_distance(q) : Constraint::event_distance(q);
  }
  /// While active: the wrapped constraint's own events first, then the release condition.
  bool update_structure(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                        std::string& description) override;

  bool active() const { return active_; }
  /// The time of the step after which the constraint let go (meaningful when !active()).
  double release_time() const { return release_time_; }
  const std::string& name() const { return name_; }

 private:
  void compute_value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const override;
  void compute_jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const override;
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;
  void compute_time_derivative(const core::Configuration& q, double t,
                               Eigen::Ref<Eigen::VectorXd> phi_t) const override;

  std::unique_ptr<Constraint> constraint_;
  Condition release_;
  std::string name_;
  bool active_ = true;
  double release_time_ = 0.0;
  std::vector<int> none_;
};

}  // namespace spar::joints
