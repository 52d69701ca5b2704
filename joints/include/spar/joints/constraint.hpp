#pragma once
/// \file
/// The constraint interface: holonomic constraints Φ(q, t) = 0 between blocks of a model (and the
/// ground), imposed with Lagrange multipliers (003 eq. 48; docs/model.md, "Constraints"). Every
/// joint is one class implementing it — equation_count(), blocks() and the private compute_*
/// functions; the public evaluations check their input and zero the outputs before calling them.
/// The solvers see only this interface.
///
/// Derivatives are taken in the local increments of core/configuration.hpp: the Jacobian's
/// columns are the increments of blocks(), block after block (six for a frame: Δx inertial, Δφ
/// material with R ← R exp(Δφ); n for a vector block). Velocities are the model's global
/// tangent-layout vector. A joint may own a coordinate of its own (a sliding joint's ζ): it is a
/// vector block of the model like any other, listed in blocks().

#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace spar::joints {

class Constraint {
public:
  virtual ~Constraint() = default;

  /// Number of scalar equations m (may change at an event, see update_structure).
  virtual int equation_count() const = 0;
  /// The blocks the constraint involves (global indices), in the order of the Jacobian's column
  /// groups. The ground is not a block.
  virtual const std::vector<int>& blocks() const = 0;

  // The evaluations (the non-virtual-interface idiom of core::Element::evaluate). Each checks its
  // input once, here, and then calls the joint's own computation (the private compute_* below)
  // with every output sized and ZEROED, so a joint writes only its non-zero entries. The checks
  // throw spar::InputError naming the constraint's type, the function and the field, for: a
  // configuration that lacks one of blocks(), a non-finite time, an output not sized m, m × n or
  // n × n (n = the tangent size of blocks() in q), a velocity not of q.dof_count() entries, and
  // multipliers not of m entries. A non-finite velocity entry at the constraint's blocks or a
  // non-finite multiplier is a plain spar::Error (inside a solver they come from an iteration
  // that a shorter step may avoid). Cost: a pass over the constraint's blocks (and its m
  // multipliers), no allocation.

  /// Φ(q, t), m entries.
  void value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const;
  /// B = ∂Φ(q ⊕ Δ, t)/∂Δ at Δ = 0: m × n for the n increments of blocks().
  void jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const;
  /// K_λ = ∂(B(q ⊕ Δ, t)ᵀ λ)/∂Δ at Δ = 0: n × n, the constraint's part of the iteration matrix.
  void multiplier_tangent(const core::Configuration& q, double t,
                          const Eigen::Ref<const Eigen::VectorXd>& lambda,
                          Eigen::Ref<Eigen::MatrixXd> K) const;
  /// The terms c(q, v, t) of Φ̈ = B v̇ + c: everything in the second time derivative of Φ along a
  /// motion that is not proportional to the accelerations (velocity products, Φ_tt, 2 Φ_qt v).
  /// `velocity` is the model's global velocity vector. m entries.
  void acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                          Eigen::Ref<Eigen::VectorXd> c) const;
  /// ∂Φ/∂t at fixed q (non-zero for drivers only); the initial velocities must satisfy
  /// B v + Φ_t = 0. m entries.
  void time_derivative(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi_t) const;

  /// How far the state is from this constraint's next event (an end stop that a slider
  /// approaches), in the constraint's own unit: positive before it, ≤ 0 at or past it; +∞ when
  /// no event lies ahead. The integrator shortens a step that crosses an event so that it ends on
  /// it (DynamicOptions::locate_events) before update_structure switches the equations.
  virtual double event_distance(const core::Configuration& q) const {
    (void)q;
    return std::numeric_limits<double>::infinity();
  }
  /// Called by the integrator after every converged step: a constraint with events (an end stop
  /// that locks a slider, a joint released when a mass leaves a beam) switches its equations here
  /// and returns true when equation_count() or blocks() changed, so the integrator rebuilds its
  /// sparse pattern. `description` then says what happened (for the results file and the log).
  virtual bool update_structure(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                double t, std::string& description) {
    (void)q;
    (void)velocity;
    (void)t;
    (void)description;
    return false;
  }

private:
  // What a joint implements: the evaluation of the same name above, called after its checks with
  // the output sized and zeroed. Write only the non-zero entries (or overwrite the whole output);
  // never resize it. joints::check_constraint compares the derivatives with central differences.

  /// Φ(q, t) into `phi` (m entries, zeroed).
  virtual void compute_value(const core::Configuration& q, double t,
                             Eigen::Ref<Eigen::VectorXd> phi) const = 0;
  /// B into `B` (m × n, zeroed).
  virtual void compute_jacobian(const core::Configuration& q, double t,
                                Eigen::Ref<Eigen::MatrixXd> B) const = 0;
  /// K_λ into `K` (n × n, zeroed); λ has m finite entries.
  virtual void compute_multiplier_tangent(const core::Configuration& q, double t,
                                          const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                          Eigen::Ref<Eigen::MatrixXd> K) const = 0;
  /// c into `c` (m entries, zeroed); `velocity` has q.dof_count() entries, finite at blocks().
  virtual void compute_acceleration_terms(const core::Configuration& q,
                                          const Eigen::VectorXd& velocity, double t,
                                          Eigen::Ref<Eigen::VectorXd> c) const = 0;
  /// Φ_t into `phi_t` (m entries, zeroed). The default leaves it zero: a constraint without
  /// explicit time dependence overrides nothing here.
  virtual void compute_time_derivative(const core::Configuration& q, double t,
                                       Eigen::Ref<Eigen::VectorXd> phi_t) const {
    (void)q;
    (void)t;
    (void)phi_t;
  }
};

}  // namespace spar::joints
