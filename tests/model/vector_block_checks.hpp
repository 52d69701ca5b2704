#pragma once
// Finite-difference checks of elements and constraints whose blocks are all vector blocks (so
// q ⊕ Δ is q + Δ), through the installed core::check_element and joints::check_constraint: an
// element's stiffness, damping and mass against central differences of its own residual in q, v
// and v̇; a constraint's Jacobian, multiplier tangent and acceleration terms against differences of
// its value.
#include <spar/core/check_element.hpp>
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/joints/check_constraint.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <catch2/catch.hpp>

namespace spar::test {

// Central differences with step ε = 1e-6 on coordinates, velocities and accelerations of size
// ≲ 10: the truncation error ε²/6·|f‴| ≈ 2e-12·|f‴| and the round-off u·|f|/ε ≈ 1e-16·100/1e-6 =
// 1e-8 for residual terms of size ≤ 100 (k ≤ 100 N/m times lengths ≤ 1), so 1e-7 relative to
// max(1, |reference|) leaves an order of magnitude over both.
inline constexpr core::ElementCheckOptions vector_element_options{
    .step = 1e-6, .rate_step = 1e-6, .tolerance = 1e-7, .scale_floor = 1.0};
// The same for the constraints' B, K_λ and Φ_t; the second central difference along q + v τ with
// τ = 1e-4: truncation τ²/12·|Φ⁗| ≈ 1e-9 for |Φ⁗| ≲ 10, round-off 4u·|Φ terms|/τ² ≈
// 4e-16·10/1e-8 = 4e-7: tolerance 2e-6 relative.
inline constexpr joints::ConstraintCheckOptions vector_constraint_options{
    .step = 1e-6, .time_step = 1e-6, .motion_step = 1e-4, .tolerance = 1e-7,
    .acceleration_tolerance = 2e-6, .scale_floor = 1.0};

/// Everything an element is evaluated at, in the global layout of q.
struct ElementState {
  core::Configuration q;
  Eigen::VectorXd velocity, acceleration;
  double time = 0.0;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();

  /// The dynamic evaluation at this state.
  core::ElementInput input() const {
    return {.q = &q, .velocity = &velocity, .acceleration = &acceleration, .time = time, .gravity = gravity};
  }
};

/// The element's output at `s` for `request` (dynamic evaluation).
inline core::ElementOutput evaluate(const core::Element& element, const ElementState& s,
                                    const core::ElementRequest& request) {
  core::ElementOutput out;
  out.reset(core::block_dof_count(s.q, element.blocks()), request);
  element.evaluate(s.input(), request, out);
  return out;
}

/// CHECKs the element's stiffness, damping and mass at `s` with core::check_element.
inline void check_element_derivatives(const core::Element& element, const ElementState& s) {
  const core::DerivativeCheck check = core::check_element(element, s.input(), vector_element_options);
  INFO(check.description());
  CHECK(check.passed());
}

/// CHECKs the constraint's Jacobian, multiplier tangent (with multipliers λ), acceleration terms
/// (along q + v τ, no acceleration, so Φ̈ = c) and time derivative at (q, t) with
/// joints::check_constraint.
inline void check_constraint_derivatives(const joints::Constraint& c, const core::Configuration& q, double t,
                                         const Eigen::VectorXd& lambda, const Eigen::VectorXd& velocity) {
  const core::DerivativeCheck check = joints::check_constraint(
      c,
      {.q = q, .time = t, .velocity = velocity, .acceleration = Eigen::VectorXd::Zero(q.dof_count()),
       .multipliers = lambda},
      vector_constraint_options);
  INFO(check.description());
  CHECK(check.passed());
}

}  // namespace spar::test
