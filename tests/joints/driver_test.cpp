// Driving constraints and their time functions: PositionDriver and AngleDriver are zero along the
// motion they prescribe, their derivatives (including Φ_t and the Φ_tt part of the acceleration
// terms) agree with finite differences, and bad input raises spar::Error.
#include <spar/error.hpp>
#include <spar/joints/angle_driver.hpp>
#include <spar/joints/position_driver.hpp>
#include <spar/joints/time_function.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "constraint_checks.hpp"

using namespace spar;
using joints::TimeFunction;

namespace {
// f(0) = 0, with non-zero f′, f″ and f‴ so that every time term is exercised.
TimeFunction driving_function() { return TimeFunction::polynomial({0.0, 0.7, -0.4, 0.3}); }
}  // namespace

TEST_CASE("time functions: constant, linear and polynomial with their derivatives",
          "[joints][drivers]") {
  const TimeFunction constant = TimeFunction::constant(2.5);
  CHECK(constant.value(7.0) == 2.5);
  CHECK(constant.first_derivative(7.0) == 0.0);
  CHECK(constant.second_derivative(7.0) == 0.0);
  const TimeFunction linear = TimeFunction::linear(3.0, 1.0);
  CHECK(linear.value(0.5) == 2.5);
  CHECK(linear.first_derivative(0.5) == 3.0);
  CHECK(linear.second_derivative(0.5) == 0.0);
  // 1 + 2t + 3t² + 4t³ at t = 0.5: 3.25, f′ = 2 + 6t + 12t² = 8, f″ = 6 + 24t = 18 (exact in
  // binary).
  const TimeFunction cubic = TimeFunction::polynomial({1.0, 2.0, 3.0, 4.0});
  CHECK(cubic.value(0.5) == 3.25);
  CHECK(cubic.first_derivative(0.5) == 8.0);
  CHECK(cubic.second_derivative(0.5) == 18.0);
  const TimeFunction zero = TimeFunction::polynomial({});
  CHECK(zero.value(1.0) == 0.0);
  CHECK(zero.second_derivative(1.0) == 0.0);
}

TEST_CASE("position driver: zero along its motion, derivatives against finite differences",
          "[joints][drivers]") {
  test::RandomRotations random(501);
  for (int sample = 0; sample < 20; ++sample) {
    INFO("sample " << sample);
    const core::Configuration q0 = test::random_configuration(3, random);
    const Eigen::Vector3d direction = test::random_vector(random, 1);
    const joints::PositionDriver driver(
        joints::Attachment{.node = 2, .offset = test::random_vector(random, 1)}, direction,
        driving_function(), q0);
    CHECK(test::value(driver, q0, 0).norm() <= 1e-14);
    // The node translated by f(t) along the unit direction satisfies Φ(·, t) = 0.
    const double t = random.uniform(0, 2);
    core::Configuration moved = q0;
    moved.position[2] += driving_function().value(t) * direction.normalized();
    CHECK(std::abs(test::value(driver, moved, t)(0)) <= 1e-14);
    test::check_derivatives(driver, q0, t, random);
    test::check_derivatives(driver, test::random_configuration(3, random), t, random);
  }
}

TEST_CASE("angle driver: Phi = sin(phi - f), derivatives against finite differences",
          "[joints][drivers]") {
  test::RandomRotations random(502);
  for (int sample = 0; sample < 20; ++sample) {
    INFO("sample " << sample);
    const core::Configuration q0 = test::random_configuration(3, random);
    const Eigen::Vector3d axis = random.axis();
    const joints::AngleDriver driver(1, 2 * axis, driving_function(), q0);
    CHECK(std::abs(test::value(driver, q0, 0)(0)) <= 1e-15);
    // The node turned by f(t) + δ about the axis: Φ(·, t) = sin δ.
    const double t = random.uniform(0, 2);
    for (const double offset : {0.0, 0.4, -2.0}) {
      const double angle = driving_function().value(t) + offset;
      const core::Configuration turned =
          test::rotate_node_about(q0, 1, test::random_vector(random, 2), angle * axis);
      CHECK(test::value(driver, turned, t)(0) == Approx(std::sin(offset)).margin(1e-14));
    }
    test::check_derivatives(driver, q0, t, random);
    test::check_derivatives(driver, test::random_configuration(3, random), t, random);
  }
}

TEST_CASE("drivers reject the ground, missing nodes, zero directions and incomplete functions",
          "[joints][drivers][errors]") {
  test::RandomRotations random(503);
  const core::Configuration q0 = test::random_configuration(2, random);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  using joints::Attachment;
  CHECK_THROWS_WITH(
      joints::PositionDriver(Attachment{.node = 3}, z, driving_function(), q0),
      Catch::Contains("node 3 does not exist") && Catch::Contains("joints::PositionDriver"));
  CHECK_THROWS_WITH(joints::PositionDriver(Attachment{}, z, driving_function(), q0),
                    Catch::Contains("attachment is on the ground"));
  CHECK_THROWS_WITH(joints::PositionDriver(Attachment{.node = 0}, Eigen::Vector3d::Zero(),
                                           driving_function(), q0),
                    Catch::Contains("driving direction is zero"));
  CHECK_THROWS_WITH(joints::PositionDriver(Attachment{.node = 0}, z,
                                           TimeFunction{.value = [](double) { return 0.0; }}, q0),
                    Catch::Contains("lacks its value, first or second derivative"));
  CHECK_THROWS_WITH(
      joints::AngleDriver(2, z, driving_function(), q0),
      Catch::Contains("node 2 does not exist") && Catch::Contains("joints::AngleDriver"));
  CHECK_THROWS_WITH(joints::AngleDriver(-1, z, driving_function(), q0),
                    Catch::Contains("attachment is on the ground"));
  CHECK_THROWS_WITH(joints::AngleDriver(0, Eigen::Vector3d::Zero(), driving_function(), q0),
                    Catch::Contains("rotation axis is zero"));
  CHECK_THROWS_WITH(joints::AngleDriver(0, z, TimeFunction{}, q0),
                    Catch::Contains("lacks its value"));
}
