#pragma once
/// \file
/// The kernel of the geometrically exact beam element: strain energy, internal force and the
/// exact, symmetric stiffness of one element in one configuration (docs/beam.md).
///
/// Unknowns of an element with k = p + 1 control points, in node order, six per node:
/// (Δx_I, Δφ_I), with x_I ← x_I + Δx_I and R_I ← R_I exp(Δφ_I) (local, right-trivialized).
/// With Π(Δ) the element's strain energy in the configuration q ⊕ Δ:
///   internal_force = ∂Π/∂Δ at Δ = 0,
///   stiffness      = ∂²Π/∂Δ² at Δ = 0 (the Hessian in the exponential chart centred at q:
///                    symmetric, exact, and equal to the Cardona–Géradin tangent of 003
///                    eqs. 24–28 taken about q).
/// The derivative of the internal force along q ⊕ Δ is stiffness + ½ blockdiag(hat(m_I)) with
/// m_I the rotational part of the internal force (see core::local_tangent).

#include <spar/elements/beam/beam.hpp>
#include <spar/core/configuration.hpp>

#include <Eigen/Core>

namespace spar::core {

inline constexpr int max_beam_element_dofs = frame_dofs * max_beam_element_nodes;

using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor,
                                    max_beam_element_dofs, 1>;
using ElementMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                    max_beam_element_dofs, max_beam_element_dofs>;

/// What to evaluate (deal.II-style update flags): the stiffness costs ~5× the force.
/// `force_and_translation_stiffness` leaves the rotation–rotation blocks of the stiffness zero
/// (003's frozen iteration matrix keeps them from t = 0) and skips the work only they need;
/// `energy` computes the strain energy alone (internal_force left empty).
enum class BeamEvaluation { energy, force, force_and_stiffness, force_and_translation_stiffness };

/// The result of one element evaluation. Fixed capacity: no heap allocation.
struct BeamElementResult {
  double strain_energy = 0.0;
  ElementVector internal_force;
  ElementMatrix stiffness;
};

/// Strain measures at one Gauss point of an element (003 eqs. 8, 41), and the section frame
/// they are measured in.
struct BeamStrains {
  Eigen::Vector3d translational;  ///< γ = Rᵀx′ − γ₀ (extension, two shears)
  Eigen::Vector3d curvature;      ///< κ = T(Θ)Θ′ − κ₀ (twist, two curvatures)
  Eigen::Matrix3d rotation;       ///< R = R_r exp(Θ) (003 eq. 42)
};

/// Evaluates element e of `beam` in configuration q. Throws spar::Error when two control points
/// of the element are rotated by π relative to each other (the Crisfield–Jelenić interpolation of
/// log(R_rᵀR_I) is undefined there: refine the mesh).
void evaluate_beam_element(const GeometricallyExactBeam& beam, int e, const Configuration& q,
                           BeamEvaluation what, BeamElementResult& result);

/// The strains at Gauss point g of element e in configuration q.
BeamStrains beam_strains(const GeometricallyExactBeam& beam, int e, int g, const Configuration& q);

/// The derivative of the internal force f along q ⊕ Δ, ∂f(q ⊕ Δ)/∂Δ at Δ = 0, from the
/// exponential-chart Hessian H: H + ½ blockdiag(hat(m_I)), m_I the rotational entries of f
/// (docs/beam.md eq. B12). Not symmetric away from equilibrium.
void add_local_tangent_correction(const Eigen::Ref<const Eigen::VectorXd>& force,
                                  Eigen::Ref<Eigen::MatrixXd> tangent);

}  // namespace spar::core
