// Quaternion ↔ rotation matrix ↔ rotation vector round trips, with Shepperd's rule exercised on
// every one of its four branches.
#include <spar/lie/exp.hpp>
#include <spar/lie/quaternion.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "random_rotations.hpp"
#include "tolerances.hpp"

using namespace spar;

TEST_CASE("quaternion_from_rotation inverts rotation_from_quaternion on all four branches",
          "[lie][quaternion]") {
  // Angles near π about each coordinate axis force the x, y and z pivots; small angles force w.
  const Eigen::Vector3d axes[] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                  Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, 1, 1).normalized()};
  for (const Eigen::Vector3d& axis : axes) {
    for (double angle : {0.0, 1e-9, 0.7, 2.9, std::numbers::pi - 1e-10, std::numbers::pi}) {
      const Eigen::Vector3d tilted = (axis + Eigen::Vector3d(0.01, -0.02, 0.015)).normalized();
      const Eigen::Matrix3d R = lie::exp(angle * tilted);
      const lie::Quaternion<double> q = lie::quaternion_from_rotation(R);
      INFO("angle " << angle);
      CHECK(q.w() >= 0.0);
      CHECK(std::fabs(q.norm() - 1.0) <= 1e-15);
      CHECK((lie::rotation_from_quaternion(q) - R).norm() <= test::round_off_3x3);
    }
  }
}

TEST_CASE("quaternion_from_rotation_vector matches exp and inverts back", "[lie][quaternion]") {
  test::RandomRotations random(5);
  for (int i = 0; i < 10000; ++i) {
    Eigen::Vector3d theta = random.rotation_vector();
    if (theta.norm() > std::numbers::pi - 1e-6) continue;
    const lie::Quaternion<double> q = lie::quaternion_from_rotation_vector(theta);
    CHECK((lie::rotation_from_quaternion(q) - lie::exp(theta)).norm() <= test::round_off_3x3);
    CHECK((lie::rotation_vector_from_quaternion(q) - theta).norm() <= 1e-15 * (1 + theta.norm()));
  }
}

TEST_CASE("rotation_vector_from_quaternion treats q and -q as the same rotation",
          "[lie][quaternion]") {
  const Eigen::Vector3d theta(0.4, -0.3, 1.0);
  const lie::Quaternion<double> q = lie::quaternion_from_rotation_vector(theta);
  const lie::Quaternion<double> minus_q(-q.w(), -q.x(), -q.y(), -q.z());
  CHECK((lie::rotation_vector_from_quaternion(minus_q) - theta).norm() <= 1e-15);
}
