// The lie kernels allocate nothing: every global operator new in this test executable is counted,
// and a batch of exp/log/tangent calls must leave the counter unchanged.
#include <spar/lie/lie.hpp>

#include <catch2/catch.hpp>

#include "allocation_counter.hpp"

TEST_CASE("exp, log, tangent, tangent_inverse and their derivatives do not allocate",
          "[lie][allocation]") {
  const Eigen::Vector3d theta(0.3, -0.8, 1.4), a(1.0, 2.0, 3.0), b(-1.0, 0.5, 0.25);
  Eigen::Matrix3d sink = Eigen::Matrix3d::Zero();
  const long before = spar::test::allocation_count();
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix3d R = spar::lie::exp(theta);
    sink += R + spar::lie::hat(spar::lie::log(R));
    sink += spar::lie::tangent(theta) + spar::lie::tangent_inverse(theta);
    sink += spar::lie::tangent_derivative(theta, a) + spar::lie::tangent_transpose_derivative(theta, a);
    sink += spar::lie::tangent_transpose_second_derivative(theta, a, b);
    sink += spar::lie::tangent_inverse_derivative(theta, a);
    sink += spar::lie::exp_and_tangent(theta).tangent;
  }
  const long after = spar::test::allocation_count();
  CHECK(after == before);
  CHECK(sink.allFinite());
}
