#pragma once
/// \file
/// The generalized force of a moment per unit length on a beam element and its local tangent
/// (docs/beam.md eq. B14).
///
/// The virtual work ∫ δϑ(S)ᵀ m dS with δϑ the material virtual rotation of the section at S,
/// δϑ = Eᵀ δa + T(Θ) δΘ for R(S) = R_r exp(a) exp(Θ(S)), gives in the element's variables
/// (a, ψ_1 … ψ_p): f_a = ∫ E m dS, f_ψI = ∫ N_I T(Θ)ᵀ m dS, with m the material components of
/// the moment (given for a follower moment; Rᵀ m_inertial for a dead one). These are mapped to the
/// nodes' increments like the internal force (B11); the local tangent adds the derivative of that
/// map, ∂(T⁻ᵀ(ψ) f)/∂ψ and ∂(T⁻¹(ψ) f)/∂ψ, to the chain rule through Θ.

#include <spar/elements/beam/beam.hpp>
#include <spar/core/configuration.hpp>
#include <spar/elements/loads/loads.hpp>

#include <Eigen/Core>

namespace spar::core {

/// The external generalized force `force` (6 per control point of the element) of
/// `moment_per_length` (already scaled by its load factor) on element e, and if `tangent` is given
/// its derivative along q ⊕ Δ.
void distributed_moment_contribution(const GeometricallyExactBeam& beam, int e,
                                     const Configuration& q,
                                     const Eigen::Vector3d& moment_per_length, MomentFrame frame,
                                     Eigen::VectorXd& force, Eigen::MatrixXd* tangent);

}  // namespace spar::core
