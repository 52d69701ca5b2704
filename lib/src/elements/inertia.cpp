#include <spar/core/inertia.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

namespace spar::core {

namespace {

/// Both parts of InertiaContribution from its mass matrix.
void add_gyroscopic(const Eigen::Ref<const Eigen::VectorXd>& velocity, InertiaContribution& c) {
  c.gyroscopic.setZero(c.mass.rows());
  c.gyroscopic_tangent.setZero(c.mass.rows(), c.mass.cols());
  add_gyroscopic_force(c.mass, velocity, c.gyroscopic);
  add_gyroscopic_tangent(c.mass, velocity, c.gyroscopic_tangent);
}

/// Π_I = Σ_J M_IJ^ΩΩ Ω_J, the angular momentum carried by frame I.
Eigen::Vector3d angular_momentum(const ElementMatrix& mass, const Eigen::Ref<const Eigen::VectorXd>& velocity,
                                 int I) {
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (int J = 0; J < mass.rows() / frame_dofs; ++J)
    momentum += mass.block<3, 3>(6 * I + 3, 6 * J + 3) * velocity.segment<3>(6 * J + 3);
  return momentum;
}

}  // namespace

// docs/dynamics.md eq. D2.
void add_gyroscopic_force(const ElementMatrix& mass, const Eigen::Ref<const Eigen::VectorXd>& velocity,
                          Eigen::Ref<Eigen::VectorXd> force) {
  for (int I = 0; I < mass.rows() / frame_dofs; ++I)
    force.segment<3>(6 * I + 3) +=
        Eigen::Vector3d(velocity.segment<3>(6 * I + 3)).cross(angular_momentum(mass, velocity, I));
}

// docs/dynamics.md eq. D2.
void add_gyroscopic_tangent(const ElementMatrix& mass, const Eigen::Ref<const Eigen::VectorXd>& velocity,
                            Eigen::Ref<Eigen::MatrixXd> tangent) {
  const int k = static_cast<int>(mass.rows() / frame_dofs);
  for (int I = 0; I < k; ++I) {
    const Eigen::Matrix3d hat_omega = lie::hat(Eigen::Vector3d(velocity.segment<3>(6 * I + 3)));
    for (int K = 0; K < k; ++K)
      tangent.block<3, 3>(6 * I + 3, 6 * K + 3) += hat_omega * mass.block<3, 3>(6 * I + 3, 6 * K + 3);
    tangent.block<3, 3>(6 * I + 3, 6 * I + 3) -= lie::hat(angular_momentum(mass, velocity, I));
  }
}

// M_IJ = m_IJ diag(ρA I, ρJ)  (003 eq. 32 with interpolated nodal velocities).
void beam_element_mass(const GeometricallyExactBeam& beam, int e, ElementMatrix& mass) {
  const BeamElement& element = beam.element(e);
  const int k = beam.degree() + 1;
  mass.setZero(frame_dofs * k, frame_dofs * k);
  const SectionInertia& inertia = beam.inertia();
  for (int I = 0; I < k; ++I)
    for (int J = 0; J < k; ++J) {
      const double m = element.mass_coefficients(I, J);
      mass.block<3, 3>(6 * I, 6 * J).diagonal().setConstant(m * inertia.mass_per_length);
      mass.block<3, 3>(6 * I + 3, 6 * J + 3) = m * inertia.rotary;
    }
}

void beam_element_inertia(const GeometricallyExactBeam& beam, int e,
                          const Eigen::Ref<const Eigen::VectorXd>& velocity,
                          InertiaContribution& out) {
  beam_element_mass(beam, e, out.mass);
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
