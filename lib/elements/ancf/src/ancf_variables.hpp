#pragma once
/// \file
/// The section variables of the ANCF beam's invariant-matrix method, shared by the element's tables
/// and its section kernel.

namespace spar::core::detail {

/// The variables u = (a, b, c, g, h) of docs/ancf.md eq. A7 as (φ index p, column α of F):
/// F = Σ_p φ_p F_p with φ = (1, y, z), F₀ = [a g h], F₁ = [b 0 0], F₂ = [c 0 0].
inline constexpr int variable_phi[5] = {0, 1, 2, 0, 0};
inline constexpr int variable_column[5] = {0, 0, 0, 1, 2};

}  // namespace spar::core::detail
