#include <spar/core/inertia.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

namespace spar::core {

namespace {

/// The gyroscopic force and its velocity tangent for nodes with angular momenta Π_I:
/// f_I = Ω_I × Π_I, ∂f_I/∂Ω_K = −hat(Π_I) δ_IK + hat(Ω_I) ∂Π_I/∂Ω_K (docs/dynamics.md eq. D2).
void add_gyroscopic(const Eigen::VectorXd& velocity, InertiaContribution& c) {
  const int k = static_cast<int>(c.nodes.size());
  c.gyroscopic.setZero(dofs_per_node * k);
  c.gyroscopic_tangent.setZero(dofs_per_node * k, dofs_per_node * k);
  auto omega = [&](int I) { return velocity.segment<3>(dofs_per_node * c.nodes[I] + 3); };
  for (int I = 0; I < k; ++I) {
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    for (int J = 0; J < k; ++J) momentum += c.mass.block<3, 3>(6 * I + 3, 6 * J + 3) * omega(J);
    const Eigen::Vector3d omega_I = omega(I);
    c.gyroscopic.segment<3>(6 * I + 3) = omega_I.cross(momentum);
    const Eigen::Matrix3d hat_omega = lie::hat(omega_I);
    for (int K = 0; K < k; ++K)
      c.gyroscopic_tangent.block<3, 3>(6 * I + 3, 6 * K + 3) =
          hat_omega * c.mass.block<3, 3>(6 * I + 3, 6 * K + 3);
    c.gyroscopic_tangent.block<3, 3>(6 * I + 3, 6 * I + 3) -= lie::hat(momentum);
  }
}

}  // namespace

void beam_element_inertia(const GeometricallyExactBeam& beam, int e, const Eigen::VectorXd& velocity,
                          InertiaContribution& out) {
  const BeamElement& element = beam.element(e);
  const int k = beam.degree() + 1;
  out.nodes.resize(k);
  for (int I = 0; I < k; ++I) out.nodes[I] = beam.node(element.first_control_point + I);
  // M_IJ = m_IJ diag(ρA I, ρJ)  (003 eq. 32 with interpolated nodal velocities).
  out.mass.setZero(dofs_per_node * k, dofs_per_node * k);
  const SectionInertia& inertia = beam.inertia();
  for (int I = 0; I < k; ++I)
    for (int J = 0; J < k; ++J) {
      const double m = element.mass_coefficients(I, J);
      out.mass.block<3, 3>(6 * I, 6 * J).diagonal().setConstant(m * inertia.mass_per_length);
      out.mass.block<3, 3>(6 * I + 3, 6 * J + 3) = m * inertia.rotary;
    }
  add_gyroscopic(velocity, out);
}

void rigid_body_inertia(const RigidBody& body, const Eigen::VectorXd& velocity,
                        InertiaContribution& out) {
  out.nodes = {body.node};
  out.mass.setZero(dofs_per_node, dofs_per_node);
  out.mass.topLeftCorner<3, 3>().diagonal().setConstant(body.mass);
  out.mass.bottomRightCorner<3, 3>() = body.inertia;
  add_gyroscopic(velocity, out);
}

double kinetic_energy(const InertiaContribution& c, const Eigen::VectorXd& velocity) {
  Eigen::VectorXd v(dofs_per_node * c.nodes.size());
  for (std::size_t I = 0; I < c.nodes.size(); ++I)
    v.segment<dofs_per_node>(dofs_per_node * I) = velocity.segment<dofs_per_node>(dofs_per_node * c.nodes[I]);
  return 0.5 * v.dot(c.mass * v);
}

}  // namespace spar::core
