#pragma once
/// \file
/// Inertial forces of beam elements and rigid bodies in the local-frame formulation (003 eqs.
/// 30–32, 47): f_ine = M v̇ + f_gyr(v), with v = (ẋ, Ω) per frame (ẋ inertial, Ω material).
///
/// Beams interpolate the nodal velocities, ẋ(S) = Σ N_I ẋ_I and Ω(S) = Σ N_I Ω_I, so the kinetic
/// energy is T = ½ Σ m_IJ (ρA ẋ_I·ẋ_J + Ω_Iᵀ ρJ Ω_J) with m_IJ = ∫ N_I N_J dS: the mass matrix is
/// constant, whatever the motion. The gyroscopic moment on node I is the Euler–Poincaré term of
/// this kinetic energy, Ω_I × Σ_J m_IJ ρJ Ω_J (docs/dynamics.md eq. D2); 003 eq. 47 instead
/// evaluates Ω × ρJΩ at the Gauss points, which does not derive from T and lets the energy of a
/// free beam drift. Neither depends on the configuration, so inertia adds nothing to the stiffness.
///
/// Velocities here are local: the element's frames one after the other, six entries each.

#include <spar/core/beam.hpp>
#include <spar/core/beam_element.hpp>

#include <Eigen/Core>

namespace spar::core {

/// A rigid body: one frame block at its centre of mass, mass and inertia tensor about the centre
/// of mass in the body frame.
struct RigidBody {
  int node = 0;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// Inertia of k frames with local velocity v (6k). Fixed capacity: no heap allocation.
struct InertiaContribution {
  ElementMatrix mass;                ///< M (6k × 6k), constant
  ElementVector gyroscopic;          ///< f_gyr(v) (6k)
  ElementMatrix gyroscopic_tangent;  ///< ∂f_gyr/∂v (6k × 6k)
};

/// The constant mass matrix of element e of a beam, M_IJ = m_IJ diag(ρA I, ρJ) (6(p + 1) square).
void beam_element_mass(const GeometricallyExactBeam& beam, int e, ElementMatrix& mass);

/// Adds the gyroscopic force f_I = Ω_I × Π_I, Π_I = Σ_J M_IJ^ΩΩ Ω_J, of frames with mass matrix
/// `mass` at local velocity v to `force` (docs/dynamics.md eq. D2).
void add_gyroscopic_force(const ElementMatrix& mass, const Eigen::Ref<const Eigen::VectorXd>& velocity,
                          Eigen::Ref<Eigen::VectorXd> force);
/// Adds its velocity tangent ∂f_I/∂Ω_K = −hat(Π_I) δ_IK + hat(Ω_I) M_IK^ΩΩ to `tangent`.
void add_gyroscopic_tangent(const ElementMatrix& mass, const Eigen::Ref<const Eigen::VectorXd>& velocity,
                            Eigen::Ref<Eigen::MatrixXd> tangent);

/// Inertia of element e of a beam at the element's local velocity v (6(p + 1) entries).
void beam_element_inertia(const GeometricallyExactBeam& beam, int e,
                          const Eigen::Ref<const Eigen::VectorXd>& velocity,
                          InertiaContribution& out);

/// Inertia of a rigid body at its local velocity v (6): M = diag(m I, J), f_gyr = (0, Ω × JΩ).
void rigid_body_inertia(const RigidBody& body, const Eigen::Ref<const Eigen::VectorXd>& velocity,
                        InertiaContribution& out);

/// ½ vᵀ M v of a contribution at its local velocity v.
double kinetic_energy(const InertiaContribution& c, const Eigen::Ref<const Eigen::VectorXd>& velocity);

}  // namespace spar::core
