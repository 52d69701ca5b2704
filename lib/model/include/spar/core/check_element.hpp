#pragma once
/// \file
/// A finite-difference check of an element's derivatives, for a user writing an element kind
/// (docs/model.md, "Adding an element"): the stiffness K, damping C and mass M that Element::evaluate
/// returns against central differences of its own residual, at a state the user gives.

#include <spar/core/derivative_check.hpp>
#include <spar/core/element.hpp>

namespace spar::core {

/// Steps and tolerance of check_element. The defaults suit data of size O(1) (coordinates,
/// velocities, forces): a central difference of step ε has the truncation error ε²/6·|r‴| ≈
/// 2e-13·|r‴| and the round-off u·|r|/ε ≈ 1e-10·|r|, far below the tolerance 1e-7, while a wrong
/// term is off by O(1).
struct ElementCheckOptions {
  /// Step ε on the increments Δ of the element's blocks, taken through q ⊕ Δ (a frame block's
  /// inertial translations and material rotations R exp(Δφ), a vector block's coordinates).
  double step = 1e-6;
  /// Step on the velocities (for C) and accelerations (for M). A residual polynomial in them
  /// (inertia: quadratic in v, linear in v̇) has no truncation error: a larger step, e.g. 1e-2,
  /// lowers the round-off.
  double rate_step = 1e-6;
  /// The largest error that passes (DerivativeComparison: relative to the derivative's scale).
  double tolerance = 1e-7;
  /// Each derivative's scale is max(scale_floor, max |FD entry|): with 1, errors of derivatives
  /// smaller than 1 are absolute; with 0, every error is relative to its derivative's size.
  double scale_floor = 1.0;
  /// Also compare the residual with the gradient of the element's potential (strain + gravity
  /// energy, ElementOutput::energy) along q ⊕ Δ: a conservative element's static residual is that
  /// gradient. Only for a static evaluation.
  bool potential = false;
};

/// Checks the element at `in` (as Element::evaluate takes it) against central differences of its
/// residual r over the element's local increments, entry by entry:
///   "stiffness K"  K = ∂r(q ⊕ Δ, v, v̇)/∂Δ at Δ = 0 (docs/model.md eq. M5), always;
///   "damping C"    C = ∂r/∂v and "mass M" M = ∂r/∂v̇, in a dynamic evaluation (`in` with a
///                  velocity and an acceleration);
///   "residual r"   against the gradient of the potential, with `options.potential`.
/// Every other block of the configuration stays where `in` has it. The element is evaluated
/// through Element::evaluate (2 evaluations per local increment and derivative), so bad input
/// raises its errors; options that are not positive and finite (steps), negative (tolerance,
/// scale floor), or a potential check in dynamics raise spar::InputError.
DerivativeCheck check_element(const Element& element, const ElementInput& in, const ElementCheckOptions& options = {});

}  // namespace spar::core
