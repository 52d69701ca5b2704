#pragma once
// A point mass in plane polar coordinates (r, θ): an element with a configuration-dependent mass
// matrix and quadratic-velocity forces, written outside the library against the public Element
// interface only (issue 10). From the kinetic energy T = ½ m (ṙ² + r² θ̇²):
//     M(q) = diag(m, m r²),  f_qv = (−m r θ̇², 2 m r ṙ θ̇),  r = M(q) v̇ + f_qv (no other force),
//     K = ∂r/∂(r, θ) = [−m θ̇²  0 ; 2 m r θ̈ + 2 m ṙ θ̇  0],
//     C = ∂r/∂(ṙ, θ̇) = [0  −2 m r θ̇ ; 2 m r θ̇  2 m r ṙ].
// The coordinates (r, θ), in this order, are the element's local dofs: one 2-vector block, or two
// 1-vector blocks (the same element after a block split).
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::test {

class PolarPointMass final : public core::Element {
public:
  /// `blocks`: vector blocks holding (r, θ) between them, 2 coordinates in all.
  PolarPointMass(std::vector<int> blocks, double mass) : blocks_(std::move(blocks)), mass_(mass) {}

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "polar point mass"; }

  void compute(const core::ElementInput& in, const core::ElementRequest& request,
               core::ElementOutput& out) const override {
    const core::Configuration& q = *in.q;
    const std::vector<int> dofs = core::block_dofs(q, blocks_);
    if (dofs.size() != 2)
      throw Error("the blocks hold " + std::to_string(dofs.size()) + " coordinates", "test::PolarPointMass",
                  "give vector blocks holding (r, theta)");
    const double r = q.values(dofs[0]);
    if (!in.dynamic()) return;  // no force but inertia
    const double r_dot = (*in.velocity)(dofs[0]), theta_dot = (*in.velocity)(dofs[1]);
    const double r_ddot = (*in.acceleration)(dofs[0]), theta_ddot = (*in.acceleration)(dofs[1]);
    const double m = mass_;
    if (request.residual) {
      out.residual(0) = m * r_ddot - m * r * theta_dot * theta_dot;
      out.residual(1) = m * r * r * theta_ddot + 2 * m * r * r_dot * theta_dot;
    }
    if (request.mass) {
      out.mass(0, 0) = m;
      out.mass(1, 1) = m * r * r;
    }
    if (request.stiffness) {
      out.stiffness(0, 0) = -m * theta_dot * theta_dot;
      out.stiffness(1, 0) = 2 * m * r * theta_ddot + 2 * m * r_dot * theta_dot;
    }
    if (request.damping) {
      out.damping(0, 1) = -2 * m * r * theta_dot;
      out.damping(1, 0) = 2 * m * r * theta_dot;
      out.damping(1, 1) = 2 * m * r * r_dot;
    }
    out.energy.kinetic = 0.5 * m * (r_dot * r_dot + r * r * theta_dot * theta_dot);
  }

private:
  std::vector<int> blocks_;
  double mass_;
};

}  // namespace spar::test
