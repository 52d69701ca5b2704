// exp and log of SO(3): round trips to 1e-14, including angles within 1e-10 of 0 and π, agreement
// with Eigen's AngleAxis, and a clear spar::Error for matrices that are not rotations.
#include <spar/lie/exp.hpp>
#include <spar/lie/hat.hpp>
#include <spar/lie/log.hpp>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>

#include "random_rotations.hpp"
#include "tolerances.hpp"

using namespace spar;

TEST_CASE("hat and vee are inverse and hat is the cross product", "[lie]") {
  const Eigen::Vector3d v(0.3, -1.2, 2.5), w(-0.7, 0.1, 0.4);
  CHECK((lie::hat(v) * w - v.cross(w)).norm() == 0.0);
  CHECK((lie::vee(lie::hat(v)) - v).norm() == 0.0);
}

TEST_CASE("exp agrees with Eigen's AngleAxis", "[lie][exp]") {
  test::RandomRotations random(1);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d theta = random.rotation_vector();
    const double angle = theta.norm();
    const Eigen::Matrix3d reference =
        angle > 0 ? Eigen::AngleAxisd(angle, theta / angle).toRotationMatrix()
                  : Eigen::Matrix3d::Identity();
    CHECK((lie::exp(theta) - reference).norm() <= test::round_off_3x3);
  }
}

TEST_CASE("exp is orthogonal to round-off", "[lie][exp]") {
  test::RandomRotations random(2);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Matrix3d R = lie::exp(random.rotation_vector());
    CHECK((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() <= test::round_off_3x3);
    CHECK(std::fabs(R.determinant() - 1.0) <= test::round_off_3x3);
  }
}

TEST_CASE("log(exp(theta)) = theta to 1e-14 for |theta| < pi - 1e-6", "[lie][log]") {
  // Absolute error relative to |θ| + 1: the requirement.
  test::RandomRotations random(3);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    Eigen::Vector3d theta = random.rotation_vector();
    if (theta.norm() >= std::numbers::pi - 1e-6) theta *= (std::numbers::pi - 1e-6) / theta.norm();
    const double error = (lie::log(lie::exp(theta)) - theta).norm() / (theta.norm() + 1.0);
    worst = std::max(worst, error);
  }
  INFO("worst error " << worst);
  CHECK(worst <= 1e-14);
}

TEST_CASE("exp(log(R)) = R to 1e-14 for 1e5 random rotations", "[lie][log]") {
  // Includes angles within 1e-10 of 0 and of π, where acos-based logs lose half their digits.
  test::RandomRotations random(4);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const Eigen::Matrix3d R = lie::exp(random.rotation_vector());
    worst = std::max(worst, (lie::exp(lie::log(R)) - R).norm());
  }
  INFO("worst error " << worst);
  CHECK(worst <= 1e-14);
}

TEST_CASE("log returns angles in [0, pi], the right axis at pi, and 0 at identity", "[lie][log]") {
  CHECK(lie::log(Eigen::Matrix3d::Identity()).norm() == 0.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -2) / 3.0;
  const Eigen::Vector3d at_pi = lie::log(lie::exp(std::numbers::pi * axis));
  CHECK(std::fabs(at_pi.norm() - std::numbers::pi) <= 1e-15);
  CHECK(std::fabs(std::fabs(at_pi.normalized().dot(axis)) - 1.0) <= 1e-15);
  // An angle beyond π comes back as the equivalent vector of angle 2π − θ.
  const Eigen::Vector3d beyond = lie::log(lie::exp(4.0 * axis));
  CHECK((beyond - (4.0 - 2 * std::numbers::pi) * axis).norm() <= 1e-14);
}

TEST_CASE("relative_rotation is log(Rr^T R)", "[lie][log]") {
  const Eigen::Matrix3d R_r = lie::exp(Eigen::Vector3d(0.3, 1.1, -0.4));
  const Eigen::Vector3d psi(-0.2, 0.5, 0.9);
  CHECK((lie::relative_rotation(R_r, lie::right_plus(R_r, psi)) - psi).norm() <= 1e-15);
}

TEST_CASE("log refuses matrices that are not rotations", "[lie][log][errors]") {
  Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity();
  reflection(2, 2) = -1.0;
  CHECK_THROWS_AS(lie::log(reflection), Error);
  CHECK_THROWS_WITH(lie::log(reflection), Catch::Contains("reflection"));

  Eigen::Matrix3d sheared = lie::exp(Eigen::Vector3d(0.1, 0.2, 0.3));
  sheared(0, 1) += 1e-8;
  CHECK_THROWS_WITH(lie::log(sheared), Catch::Contains("not orthogonal"));

  Eigen::Matrix3d with_nan = Eigen::Matrix3d::Identity();
  with_nan(1, 2) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(lie::log(with_nan), Catch::Contains("NaN"));

  CHECK_THROWS_AS(lie::log(Eigen::Matrix3d::Zero()), Error);
  // Within the tolerance of 1e-9 a nearly orthogonal matrix is accepted.
  Eigen::Matrix3d nearly = lie::exp(Eigen::Vector3d(0.1, 0.2, 0.3));
  nearly(0, 1) += 1e-11;
  CHECK_NOTHROW(lie::log(nearly));
}

TEST_CASE("exp refuses a NaN rotation vector", "[lie][exp][errors]") {
  const Eigen::Vector3d bad(0.0, std::numeric_limits<double>::quiet_NaN(), 1.0);
  CHECK_THROWS_AS(lie::exp(bad), Error);
  CHECK_THROWS_WITH(lie::exp(bad), Catch::Contains("lie::exp"));
}
