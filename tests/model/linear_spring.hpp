#pragma once
// A linear spring between two point masses (3-coordinate vector blocks a and b), written outside
// the library against the public Element interface only (issue 10). With d = x_b − x_a, l = |d|,
// e = d/l and the tension N = k (l − L0):
//     r = [−N e ; N e],
//     K = ∂r/∂(x_a, x_b) = [K_d −K_d ; −K_d K_d],  K_d = ∂(N e)/∂d = k e eᵀ + (N/l)(I − e eᵀ),
// strain energy ½ k (l − L0)². No inertia (the masses are separate elements).
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::test {

struct LinearSpringParameters {
  int block_a = 0, block_b = 1;  ///< 3-coordinate vector blocks (positions, m)
  double stiffness = 1.0;        ///< k, N/m
  double rest_length = 1.0;      ///< L0, m
};

class LinearSpring final : public core::Element {
public:
  explicit LinearSpring(const LinearSpringParameters& p)
      : blocks_{p.block_a, p.block_b}, k_(p.stiffness), rest_length_(p.rest_length) {}

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override {
    return "spring between blocks " + std::to_string(blocks_[0]) + " and " + std::to_string(blocks_[1]);
  }

  void compute(const core::ElementInput& in, const core::ElementRequest& request,
               core::ElementOutput& out) const override {
    const core::Configuration& q = *in.q;
    const Eigen::Vector3d d = q.vector(blocks_[1]) - q.vector(blocks_[0]);
    const double l = d.norm();
    if (!(l > 0.0))
      throw Error("the spring's ends coincide", "test::LinearSpring " + name(),
                  "start the masses apart");
    const Eigen::Vector3d e = d / l;
    const double tension = k_ * (l - rest_length_);
    if (request.residual) {
      out.residual.head<3>() = -tension * e;
      out.residual.tail<3>() = tension * e;
    }
    if (request.stiffness) {
      const Eigen::Matrix3d eet = e * e.transpose();
      const Eigen::Matrix3d K_d = k_ * eet + (tension / l) * (Eigen::Matrix3d::Identity() - eet);
      out.stiffness.topLeftCorner<3, 3>() = K_d;
      out.stiffness.topRightCorner<3, 3>() = -K_d;
      out.stiffness.bottomLeftCorner<3, 3>() = -K_d;
      out.stiffness.bottomRightCorner<3, 3>() = K_d;
    }
    out.energy.strain = 0.5 * k_ * (l - rest_length_) * (l - rest_length_);
  }

private:
  std::vector<int> blocks_;
  double k_, rest_length_;
};

}  // namespace spar::test
