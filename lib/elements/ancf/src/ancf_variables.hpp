#pragma once
/// \file
/// The section variables of the ANCF beam's invariant-matrix method and the strain components the
/// shear factor scales, shared by the element's tables and its section kernel.

namespace spar::core::detail {

/// The variables u = (a, b, c, g, h) of docs/ancf.md eq. A7 as (φ index p, column α of F):
/// F = Σ_p φ_p F_p with φ = (1, y, z), F₀ = [a g h], F₁ = [b 0 0], F₂ = [c 0 0].
inline constexpr int variable_phi[5] = {0, 1, 2, 0, 0};
inline constexpr int variable_column[5] = {0, 0, 0, 1, 2};

/// Whether the strain E_αβ between columns α and β of F is a transverse shear strain (E_xy, E_xz,
/// either order), whose modulus the shear correction factor scales to kμ (docs/ancf.md eq. A22).
inline constexpr bool transverse_shear(int alpha, int beta) { return alpha != beta && (alpha == 0 || beta == 0); }

}  // namespace spar::core::detail
