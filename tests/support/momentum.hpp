#pragma once
// Linear and angular momentum of a model's discrete motion, from its elements' own mass matrices:
// the momenta conjugate to translations and rotations of the whole model (Noether), so they are
// what external forces and moments change, whatever the discretization. Per frame block I with
// momentum (p_I, π_I) = (M v)_I — p_I inertial, π_I material — the linear momentum is Σ p_I and
// the angular momentum about the origin is Σ x_I × p_I + R_I π_I (the rotation of every frame by
// an inertial δθ moves x_I by δθ × x_I and turns R_I by the material increment R_Iᵀ δθ).
#include <spar/core/model.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <utility>

namespace spar::test {

/// (linear momentum, angular momentum about the origin) of `model` at velocity v (global layout).
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> momentum(const core::Model& model, const core::Configuration& q,
                                                            const Eigen::VectorXd& v) {
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(v.size());
  const core::ElementInput in{.q = &q, .velocity = &v, .acceleration = &a};
  const core::ElementRequest request{.residual = false, .mass = true};
  Eigen::Vector3d linear = Eigen::Vector3d::Zero(), angular = Eigen::Vector3d::Zero();
  core::ElementOutput out;
  for (int e = 0; e < model.element_count(); ++e) {
    const core::Element& element = model.element(e);
    const int n = core::block_dof_count(q, element.blocks());
    out.reset(n, request);
    element.evaluate(in, request, out);
    Eigen::VectorXd local(n);
    core::gather(q, element.blocks(), v, local);
    const Eigen::VectorXd p = out.mass * local;
    int offset = 0;
    for (int b : element.blocks()) {
      if (q.is_frame(b)) {
        linear += p.segment<3>(offset);
        angular += q.position[b].cross(p.segment<3>(offset)) + q.rotation[b] * p.segment<3>(offset + 3);
      }
      offset += q.blocks[b].size;
    }
  }
  return {linear, angular};
}

}  // namespace spar::test
