#pragma once
/// \file
/// The chart about the last converged configuration (Cardona & Géradin 1988; 003 eq. 20):
/// R_k = R_k^n exp(φ_k). Newton iterates on φ, so increments of a step add up in one vector space
/// and the tangent of a conservative force is a Hessian — symmetric.
///
/// A contribution computed in local increments (force f, tangent K_loc = ∂f(q ⊕ Δ)/∂Δ) becomes,
/// per node with rotation chart φ (docs/beam.md eq. B13):
///   f_φ = T(φ)ᵀ f,   K_φ = T(φ)ᵀ K_loc T(φ) + blockdiag ∂(T(φ)ᵀ f)/∂φ,
/// T acting on the rotational entries only.

#include <spar/core/model.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::core {

/// Pulls a contribution (force and, if present, tangent) back to the converged chart; `phi[k]`
/// is node k's rotation chart coordinate.
void pull_back_to_converged_chart(const std::vector<Eigen::Vector3d>& phi, NodalContribution& c);

}  // namespace spar::core
