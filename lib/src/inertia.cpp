#include <spar/core/inertia.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

namespace spar::core {

namespace {

/// The gyroscopic force and its velocity tangent for frames with angular momenta Π_I:
/// f_I = Ω_I × Π_I, ∂f_I/∂Ω_K = −hat(Π_I) δ_IK + hat(Ω_I) ∂Π_I/∂Ω_K (docs/dynamics.md eq. D2).
void add_gyroscopic(const Eigen::Ref<const Eigen::VectorXd>& velocity, InertiaContribution& c) {
  const Eigen::Index n = c.mass.rows();
  const int k = static_cast<int>(n / frame_dofs);
  c.gyroscopic.setZero(n);
  c.gyroscopic_tangent.setZero(n, n);
  for (int I = 0; I < k; ++I) {
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    for (int J = 0; J < k; ++J)
      momentum += c.mass.block<3, 3>(6 * I + 3, 6 * J + 3) * velocity.segment<3>(6 * J + 3);
    const Eigen::Vector3d omega_I = velocity.segment<3>(6 * I + 3);
    c.gyroscopic.segment<3>(6 * I + 3) = omega_I.cross(momentum);
    const Eigen::Matrix3d hat_omega = lie::hat(omega_I);
    for (int K = 0; K < k; ++K)
      c.gyroscopic_tangent.block<3, 3>(6 * I + 3, 6 * K + 3) =
          hat_omega * c.mass.block<3, 3>(6 * I + 3, 6 * K + 3);
    c.gyroscopic_tangent.block<3, 3>(6 * I + 3, 6 * I + 3) -= lie::hat(momentum);
  }
}

}  // namespace

void beam_element_inertia(const GeometricallyExactBeam& beam, int e,
                          const Eigen::Ref<const Eigen::VectorXd>& velocity,
                          InertiaContribution& out) {
  const BeamElement& element = beam.element(e);
  const int k = beam.degree() + 1;
  // M_IJ = m_IJ diag(ρA I, ρJ)  (003 eq. 32 with interpolated nodal velocities).
  out.mass.setZero(frame_dofs * k, frame_dofs * k);
  const SectionInertia& inertia = beam.inertia();
  for (int I = 0; I < k; ++I)
    for (int J = 0; J < k; ++J) {
      const double m = element.mass_coefficients(I, J);
      out.mass.block<3, 3>(6 * I, 6 * J).diagonal().setConstant(m * inertia.mass_per_length);
      out.mass.block<3, 3>(6 * I + 3, 6 * J + 3) = m * inertia.rotary;
    }
  add_gyroscopic(velocity, out);
}

void rigid_body_inertia(const RigidBody& body, const Eigen::Ref<const Eigen::VectorXd>& velocity,
                        InertiaContribution& out) {
  out.mass.setZero(frame_dofs, frame_dofs);
  out.mass.topLeftCorner<3, 3>().diagonal().setConstant(body.mass);
  out.mass.bottomRightCorner<3, 3>() = body.inertia;
  add_gyroscopic(velocity, out);
}

double kinetic_energy(const InertiaContribution& c, const Eigen::Ref<const Eigen::VectorXd>& velocity) {
  return 0.5 * velocity.dot(c.mass * velocity);
}

}  // namespace spar::core
