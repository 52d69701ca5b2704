#include <spar/joints/active_until.hpp>

#include <spar/error.hpp>

#include <sstream>

namespace spar::joints {

ActiveUntil::ActiveUntil(std::unique_ptr<Constraint> constraint, Condition release, std::string name)
    : constraint_(std::move(constraint)), release_(std::move(release)), name_(std::move(name)) {
  const char* where = "joints::ActiveUntil";
  if (!constraint_) throw Error("no constraint to wrap", where, "pass the constraint that holds until the release");
  if (!release_) throw Error("no release condition", where, "pass a callable (q, t) -> bool");
}

// While active, the wrapped constraint's own evaluations, through its public interface (whose
// checks repeat ours: a second pass over the same few blocks). While released the constraint has
// no equations: the evaluations below receive empty outputs and have nothing to write.

void ActiveUntil::compute_value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const {
  if (active_) constraint_->value(q, t, phi);
}

void ActiveUntil::compute_jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const {
  if (active_) constraint_->jacobian(q, t, B);
}

void ActiveUntil::compute_multiplier_tangent(const core::Configuration& q, double t,
                                             const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                             Eigen::Ref<Eigen::MatrixXd> K) const {
  if (active_) constraint_->multiplier_tangent(q, t, lambda, K);
}

void ActiveUntil::compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                             double t, Eigen::Ref<Eigen::VectorXd> c) const {
  if (active_) constraint_->acceleration_terms(q, velocity, t, c);
}

void ActiveUntil::compute_time_derivative(const core::Configuration& q, double t,
                                          Eigen::Ref<Eigen::VectorXd> phi_t) const {
  if (active_) constraint_->time_derivative(q, t, phi_t);
}

bool ActiveUntil::update_structure(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                   double t, std::string& description) {
  if (!active_) return false;
  const bool changed = constraint_->update_structure(q, velocity, t, description);
  if (!release_(q, t)) return changed;
  active_ = false;
  release_time_ = t;
  std::ostringstream text;
  text << "'" << name_ << "' released at t = " << t;
  description = description.empty() ? text.str() : description + "; " + text.str();
  return true;
}

}  // namespace spar::joints
