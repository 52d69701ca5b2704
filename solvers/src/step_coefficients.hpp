#pragma once
// Private to spar_solvers: the coefficients of one generalized-α step of size h.

#include <spar/solvers/generalized_alpha.hpp>

#include "system_assembly.hpp"

namespace spar::solvers::detail {

/// What one step of size h needs of the method (docs/dynamics.md D3): α_m, α_f, γ, β and the
/// derived β′ = (1 − α_m)/(h²β(1 − α_f)) and γ′ = γ/(hβ) — a Newton correction Δx of hΔq changes
/// v by γ′Δx and v̇ by β′Δx — and the iteration matrix's M + (γ′/β′) C + (1/β′)(K + K_λ) T, the
/// dynamic rows divided by β′ (Bottasso, Bauchau & Cardona 2007).
struct StepCoefficients {
  double h = 0.0;
  double alpha_m = 0.0, alpha_f = 0.0, gamma = 0.0, beta = 0.0;
  double beta_prime = 0.0, gamma_prime = 0.0;
  MatrixCoefficients matrix;

  static StepCoefficients of(double h, const GeneralizedAlphaParameters& method) {
    StepCoefficients c{.h = h, .alpha_m = method.alpha_m, .alpha_f = method.alpha_f, .gamma = method.gamma,
                       .beta = method.beta};
    c.beta_prime = (1 - c.alpha_m) / (h * h * c.beta * (1 - c.alpha_f));
    c.gamma_prime = c.gamma / (h * c.beta);
    c.matrix = {.mass = 1.0, .damping = c.gamma_prime / c.beta_prime, .stiffness = 1.0 / c.beta_prime};
    return c;
  }
};

}  // namespace spar::solvers::detail
