#pragma once
/// \file
/// The constraint interface: holonomic constraints Φ(q, t) = 0 between nodes of a model (and the
/// ground), imposed with Lagrange multipliers (003 eq. 48). Every joint is one class implementing
/// it; the solvers see only this interface.
///
/// Derivatives are taken in the local increments of core/configuration.hpp: for each node of the
/// constraint, six entries (Δx inertial, Δφ material) with R ← R exp(Δφ). Velocities are given the
/// same way: per node (ẋ inertial, Ω material), in the global dof order of the model.

#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::joints {

class Constraint {
public:
  virtual ~Constraint() = default;

  /// Number of scalar equations m.
  virtual int equation_count() const = 0;
  /// The nodes the constraint involves (global indices), in the order of the Jacobian's column
  /// blocks (six columns per node). The ground is not a node.
  virtual const std::vector<int>& nodes() const = 0;

  /// Φ(q, t), m entries.
  virtual void value(const core::Configuration& q, double t,
                     Eigen::Ref<Eigen::VectorXd> phi) const = 0;
  /// B = ∂Φ(q ⊕ Δ, t)/∂Δ at Δ = 0: m × 6k for the k nodes of nodes().
  virtual void jacobian(const core::Configuration& q, double t,
                        Eigen::Ref<Eigen::MatrixXd> B) const = 0;
  /// ∂(B(q ⊕ Δ, t)ᵀ λ)/∂Δ at Δ = 0: 6k × 6k, the constraint's part of the iteration matrix.
  virtual void multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const = 0;
  /// The terms c(q, v, t) of Φ̈ = B v̇ + c: everything in the second time derivative of Φ along a
  /// motion that is not proportional to the accelerations (velocity products, Φ_tt, 2 Φ_qt v).
  /// `velocity` is the model's global velocity vector (6 per node). m entries.
  virtual void acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                  double t, Eigen::Ref<Eigen::VectorXd> c) const = 0;
  /// ∂Φ/∂t at fixed q (non-zero for drivers only); the initial velocities must satisfy
  /// B v + Φ_t = 0. m entries.
  virtual void time_derivative(const core::Configuration& q, double t,
                               Eigen::Ref<Eigen::VectorXd> phi_t) const {
    (void)q;
    (void)t;
    phi_t.setZero();
  }
};

}  // namespace spar::joints
