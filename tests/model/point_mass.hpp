#pragma once
// A point mass on a 3-coordinate vector block, written outside the library against the public
// Element interface only (issue 10, "An open model"): r = m ẍ − λ m g, so M = m I, no stiffness,
// no damping; kinetic energy ½ m |ẋ|², gravity potential −m g · x (filled on every evaluation,
// as the assembly reads them after any evaluate).
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::test {

class PointMass final : public core::Element {
public:
  /// A mass `mass` (kg) whose position is vector block `block` (3 coordinates, inertial, m).
  PointMass(int block, double mass) : blocks_{block}, mass_(mass) {
    if (!(mass > 0.0))
      throw Error("non-positive mass", "test::PointMass", "give a mass > 0");
  }

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "point mass on block " + std::to_string(blocks_[0]); }

  void compute(const core::ElementInput& in, const core::ElementRequest& request,
               core::ElementOutput& out) const override {
    const core::Configuration& q = *in.q;
    if (q.is_frame(blocks_[0]) || q.blocks[blocks_[0]].size != 3)
      throw Error("block " + std::to_string(blocks_[0]) + " is not a 3-vector block",
                  "test::PointMass", "put the mass on a vector block of 3 coordinates");
    const Eigen::Vector3d x = q.vector(blocks_[0]);
    const Eigen::Vector3d g = in.load_factor * in.gravity;
    const int offset = q.blocks[blocks_[0]].offset;
    if (request.residual) out.residual = -mass_ * g;
    if (in.dynamic()) {
      const Eigen::Vector3d v = in.velocity->segment<3>(offset);
      if (request.residual) out.residual += mass_ * in.acceleration->segment<3>(offset);
      if (request.mass) out.mass = mass_ * Eigen::Matrix3d::Identity();
      out.energy.kinetic = 0.5 * mass_ * v.squaredNorm();
    }
    out.energy.gravity = -mass_ * g.dot(x);
  }

private:
  std::vector<int> blocks_;
  double mass_;
};

}  // namespace spar::test
