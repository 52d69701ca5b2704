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

/// The inertia of k frames in factored form, M_IJ = m_IJ diag(ρA I, ρJ) (003 eq. 32): a beam
/// element's consistent mass with m_IJ = ∫ N_I N_J dS, or a rigid body as one frame with m_11 = 1,
/// ρA = m, ρJ = J. The factored products cost k²·6 + k·9 multiplications where the dense 6k × 6k
/// matrix would cost 36 k². Fixed capacity: no heap allocation.
class FrameInertia {
public:
  using Coefficients = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                     max_beam_element_nodes, max_beam_element_nodes>;

  FrameInertia() = default;
  /// k frames with coefficients m_IJ (k × k, symmetric), translational factor ρA (or m) and
  /// rotational factor ρJ (or J, body frame).
  FrameInertia(const Coefficients& coefficients, double translational, const Eigen::Matrix3d& rotational);

  /// The number of frames k.
  int frame_count() const { return static_cast<int>(coefficients_.rows()); }
  /// Adds M v̇ + f_gyr(v), f_gyr,I = (0, Ω_I × Π_I), Π_I = Σ_J m_IJ ρJ Ω_J (docs/dynamics.md eq.
  /// D2), at local velocity v and acceleration v̇ (6k each), to `force`.
  void add_force(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                 const Eigen::Ref<const Eigen::VectorXd>& acceleration,
                 Eigen::Ref<Eigen::VectorXd> force) const;
  /// Adds the mass matrix M (6k × 6k) to `mass`.
  void add_mass(Eigen::Ref<Eigen::MatrixXd> mass) const;
  /// Adds ∂f_gyr/∂v: ∂f_I/∂Ω_K = −hat(Π_I) δ_IK + hat(Ω_I) m_IK ρJ, to `tangent`.
  void add_gyroscopic_tangent(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                              Eigen::Ref<Eigen::MatrixXd> tangent) const;
  /// ½ vᵀ M v.
  double kinetic_energy(const Eigen::Ref<const Eigen::VectorXd>& velocity) const;

private:
  /// Σ_J m_IJ Ω_J for every frame I (3 × k).
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, max_beam_element_nodes> weighted_angular_velocities(
      const Eigen::Ref<const Eigen::VectorXd>& velocity) const;

  Coefficients coefficients_;
  double translational_ = 0.0;
  Eigen::Matrix3d rotational_ = Eigen::Matrix3d::Zero();
};

/// The inertia of element e of a beam (k = p + 1 frames, 003 eqs. 30–32).
FrameInertia beam_element_inertia(const GeometricallyExactBeam& beam, int e);
/// The inertia of a rigid body: one frame, M = diag(m I, J), f_gyr = (0, Ω × JΩ).
FrameInertia rigid_body_inertia(const RigidBody& body);

}  // namespace spar::core
