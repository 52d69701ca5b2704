#pragma once
/// \file
/// The chart about the last converged configuration (Cardona & Géradin 1988; 003 eq. 20):
/// R_k = R_k^n exp(φ_k) for every frame block. Newton iterates on φ, so increments of a step add
/// up in one vector space and the tangent of a conservative force is a Hessian — symmetric.
///
/// A contribution computed in local increments (force f, tangent K_loc = ∂f(q ⊕ Δ)/∂Δ) becomes,
/// per frame block with rotation chart φ (docs/beam.md eq. B13):
///   f_φ = T(φ)ᵀ f,   K_φ = T(φ)ᵀ K_loc T(φ) + blockdiag ∂(T(φ)ᵀ f)/∂φ,
/// T acting on the rotational entries only; vector blocks are unchanged.

#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::core {

/// Pulls a contribution over `blocks` (local order) back to the converged chart: `chart` is the
/// global increment vector since the converged state (φ at each frame's rotation entries).
/// `tangent` may be null (force only).
void pull_back_to_converged_chart(const Configuration& q, const std::vector<int>& blocks,
                                  const Eigen::VectorXd& chart, Eigen::Ref<Eigen::VectorXd> force,
                                  Eigen::MatrixXd* tangent);

}  // namespace spar::core
