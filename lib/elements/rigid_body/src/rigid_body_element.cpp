#include <spar/elements/rigid_body/rigid_body_element.hpp>

namespace spar::core {

RigidBodyElement::RigidBodyElement(const RigidBody& body, int body_index)
    : body_(body), body_index_(body_index), blocks_{body.node} {}

void RigidBodyElement::compute(const ElementInput& in, const ElementRequest& request,
                               ElementOutput& out) const {
  const Configuration& q = *in.q;
  // Weight: a dead force λ m g at the centre of mass, potential −λ m g · x.
  const Eigen::Vector3d weight = in.load_factor * body_.mass * in.gravity;
  if (request.residual) out.residual.head<3>() -= weight;
  if (request.energy) out.energy.gravity = -weight.dot(q.position[body_.node]);

  if (!in.dynamic()) return;
  const Eigen::Index offset = q.blocks[body_.node].offset;
  const Eigen::Matrix<double, frame_dofs, 1> v = in.velocity->segment<frame_dofs>(offset);
  const Eigen::Matrix<double, frame_dofs, 1> a = in.acceleration->segment<frame_dofs>(offset);
  const FrameInertia inertia = rigid_body_inertia(body_);
  if (request.residual) inertia.add_force(v, a, out.residual);
  if (request.mass) inertia.add_mass(out.mass);
  if (request.damping) inertia.add_gyroscopic_tangent(v, out.damping);
  if (request.energy) out.energy.kinetic = inertia.kinetic_energy(v);
}

}  // namespace spar::core
