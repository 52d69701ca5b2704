#include "spring_damper.hpp"

#include <spar/core/configuration.hpp>
#include <spar/error.hpp>

#include <Eigen/Core>

#include <cmath>

namespace plugin {

using namespace spar;

SpringDamper::SpringDamper(const SpringDamperParameters& p)
    : blocks_{p.block_a, p.block_b}, stiffness_(p.stiffness), damping_(p.damping), rest_length_(p.rest_length) {
  if (p.block_a == p.block_b)
    throw Error("both ends on block " + std::to_string(p.block_a), "plugin::SpringDamper",
                "tie two different frame blocks");
  const auto usable = [](double x) { return std::isfinite(x) && x >= 0.0; };
  if (!usable(p.stiffness) || !usable(p.damping) || !usable(p.rest_length))
    throw Error("k = " + std::to_string(p.stiffness) + ", c = " + std::to_string(p.damping) +
                    ", L0 = " + std::to_string(p.rest_length),
                "plugin::SpringDamper", "give a finite, non-negative stiffness, damping and rest length");
}

std::string SpringDamper::name() const {
  return "spring-damper between blocks " + std::to_string(blocks_[0]) + " and " + std::to_string(blocks_[1]);
}

void SpringDamper::compute(const core::ElementInput& in, const core::ElementRequest& request,
                           core::ElementOutput& out) const {
  // Element::evaluate has checked `in` and sized and zeroed `out` (12 local dofs: x_a, φ_a, x_b,
  // φ_b); we write the translation entries only.
  const core::Configuration& q = *in.q;
  const int a = blocks_[0], b = blocks_[1];
  if (!q.is_frame(a) || !q.is_frame(b))
    throw Error("block " + std::to_string(q.is_frame(a) ? b : a) + " is not a frame", name(),
                "tie the positions of two frame blocks");
  const Eigen::Vector3d d = q.position[a] - q.position[b];
  const double l = d.norm();
  if (!(l > 0.0)) throw Error("the two ends coincide: no direction", name(), "start the blocks apart");
  const Eigen::Vector3d e = d / l;
  // w = ẋ_a − ẋ_b: a frame's velocity is (ẋ inertial, Ω material) at its offset; zero in statics.
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  if (in.dynamic())
    w = in.velocity->segment<3>(q.blocks[a].offset) - in.velocity->segment<3>(q.blocks[b].offset);
  const double tension = stiffness_ * (l - rest_length_) + damping_ * e.dot(w);

  if (request.residual) {
    out.residual.segment<3>(0) = tension * e;
    out.residual.segment<3>(6) = -tension * e;
  }
  if (request.stiffness) {
    // G = ∂(N e)/∂x_a with ∂e/∂x_a = P/l, P = I − e eᵀ, ∂l/∂x_a = eᵀ and ∂l̇/∂x_a = wᵀP/l:
    //   G = e (k e + (c/l) P w)ᵀ + (N/l) P.
    // The term in c is the damping force's configuration derivative (the direction e turns
    // under a transverse relative velocity); it makes K unsymmetric. Δx is inertial, so
    // ∂/∂x_b = −G and the rotation columns stay zero.
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - e * e.transpose();
    const Eigen::Matrix3d G = e * (stiffness_ * e + (damping_ / l) * P * w).transpose() + (tension / l) * P;
    out.stiffness.block<3, 3>(0, 0) = G;
    out.stiffness.block<3, 3>(0, 6) = -G;
    out.stiffness.block<3, 3>(6, 0) = -G;
    out.stiffness.block<3, 3>(6, 6) = G;
  }
  if (request.damping) {
    // C = ∂r/∂v: ∂(N e)/∂ẋ_a = c e eᵀ.
    const Eigen::Matrix3d D = damping_ * e * e.transpose();
    out.damping.block<3, 3>(0, 0) = D;
    out.damping.block<3, 3>(0, 6) = -D;
    out.damping.block<3, 3>(6, 0) = -D;
    out.damping.block<3, 3>(6, 6) = D;
  }
  if (request.energy) {
    // The dissipative part of the force, c l̇ e: its power c l̇² ≥ 0 leaves the motion as heat.
    out.dissipative_force.segment<3>(0) = damping_ * e.dot(w) * e;
    out.dissipative_force.segment<3>(6) = -damping_ * e.dot(w) * e;
  }
  // No mass (M stays zero): the bodies at the ends carry it.
  out.energy.strain = 0.5 * stiffness_ * (l - rest_length_) * (l - rest_length_);
}

}  // namespace plugin
