#pragma once
/// \file
/// A finite-difference check of a constraint's derivatives, for a user writing a joint
/// (docs/model.md, "Adding a joint"): B, K_λ, the acceleration terms c and Φ_t against central
/// differences of Φ at a state the user gives, the worst entry of each with a pass or fail.

#include <spar/core/configuration.hpp>
#include <spar/core/derivative_check.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

namespace spar::joints {

/// Where check_constraint evaluates the constraint.
struct ConstraintCheckState {
  core::Configuration q;
  double time = 0.0;
  /// v and a in the global tangent layout (q.dof_count() entries each): the motion along which
  /// the acceleration terms are checked. Every block moves, the constraint's and the others (a
  /// joint that read another block's velocity would show).
  Eigen::VectorXd velocity;
  Eigen::VectorXd acceleration;
  /// λ (equation_count() entries): K_λ is checked as the derivative of Bᵀλ.
  Eigen::VectorXd multipliers;
};

/// Steps and tolerances of check_constraint. The defaults suit positions and offsets of size ≲ 10
/// and rates ≲ 2 (per second): the first differences of step ε = 1e-6 have the truncation error
/// ε²/6·|Φ‴| ≈ 1e-12·|Φ‴| and the round-off u·|Φ terms|/ε ≈ 1e-9, two orders below 1e-7; the
/// second difference of step h = 1e-4 has the truncation h²/12·|Φ⁗| ≈ 1e-9·|Φ⁗| and the round-off
/// 4u·|Φ terms|/h² ≈ 4e-7, below 2e-6.
struct ConstraintCheckOptions {
  /// Step ε on the increments Δ of the constraint's blocks, taken through q ⊕ Δ (B, K_λ).
  double step = 1e-6;
  /// Step in time of the first difference of Φ (Φ_t).
  double time_step = 1e-6;
  /// Step h of the second difference of Φ along the motion (c).
  double motion_step = 1e-4;
  /// The largest error that passes for B, K_λ and Φ_t (DerivativeComparison: relative to the
  /// derivative's scale).
  double tolerance = 1e-7;
  /// The largest error that passes for B a + c: a second difference loses more to round-off.
  double acceleration_tolerance = 2e-6;
  /// Each derivative's scale is max(scale_floor, max |FD entry|): with 1, errors of derivatives
  /// smaller than 1 are absolute; with 0, every error is relative to its derivative's size.
  double scale_floor = 1.0;
};

/// Checks the constraint at `state` against central differences, entry by entry over its local
/// increments (the columns of B):
///   "Jacobian B"                B = ∂Φ(q ⊕ Δ, t)/∂Δ against the differences of Φ;
///   "multiplier tangent K_lambda"  K_λ = ∂(B(q ⊕ Δ, t)ᵀλ)/∂Δ against the differences of Bᵀλ;
///   "acceleration terms B a + c"   B a + c against the second central difference at s = 0 of
///       Φ(q(s), t + s) along the motion q(s) = q ⊕ (s v + s²/2 a): its second derivative is
///       Φ̈ = B v̇ + c with v̇ = a (for a frame, R(s) = R exp(sΩ + s²/2 α) has the angular velocity
///       Ω and the angular acceleration α at s = 0; docs/model.md eq. M1);
///   "time derivative Phi_t"     Φ_t against the central difference of Φ(q, t ± δ).
/// The constraint is evaluated through its public interface, so bad input raises its errors;
/// velocities or multipliers of the wrong size and options that are not positive and finite
/// (steps) or negative (tolerances, scale floor) raise spar::InputError.
core::DerivativeCheck check_constraint(const Constraint& constraint, const ConstraintCheckState& state,
                                       const ConstraintCheckOptions& options = {});

}  // namespace spar::joints
