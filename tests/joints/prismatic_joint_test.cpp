// PrismaticJoint: zero at q0 and along the line, rotation locked or free, its derivatives against
// finite differences, and the errors it raises.
#include <spar/error.hpp>
#include <spar/joints/prismatic_joint.hpp>

#include <catch2/catch.hpp>

#include "constraint_checks.hpp"

using namespace spar;

TEST_CASE("prismatic joint: zero at q0, derivatives against finite differences",
          "[joints][prismatic]") {
  test::RandomRotations random(401);
  for (int sample = 0; sample < 20; ++sample) {
    const core::Configuration q0 = test::random_configuration(3, random);
    const Eigen::Vector3d point = test::random_vector(random, 2);
    const Eigen::Vector3d direction = test::random_vector(random, 1);
    // The line passes through the attached point at q0, the line point elsewhere on it.
    const Eigen::Vector3d line_point = point + random.uniform(-2, 2) * direction;
    for (const bool lock : {true, false}) {
      INFO("sample " << sample << ", lock rotation " << lock);
      const joints::PrismaticJoint joint(joints::attach_at(1, point, q0), line_point, direction,
                                         lock, q0);
      CHECK(joint.equation_count() == (lock ? 5 : 2));
      CHECK(test::value(joint, q0, 0).norm() <= 1e-14);
      test::check_derivatives(joint, q0, 0.3, random);
      test::check_derivatives(joint, test::random_configuration(3, random), 0.3, random);
    }
  }
}

TEST_CASE("prismatic joint allows sliding along the line and locks or frees the rotation",
          "[joints][prismatic]") {
  test::RandomRotations random(402);
  const core::Configuration q0 = test::random_configuration(1, random);
  const Eigen::Vector3d point = test::random_vector(random, 2);
  const Eigen::Vector3d direction = random.axis();
  const joints::PrismaticJoint locked(joints::attach_at(0, point, q0), point, 2 * direction, true,
                                      q0);
  const joints::PrismaticJoint free(joints::attach_at(0, point, q0), point, direction, false, q0);
  for (const double distance : {-1.5, 0.2, 3.0}) {
    core::Configuration slid = q0;
    slid.position[0] += distance * direction;
    CHECK(test::value(locked, slid, 0).norm() <= 1e-14);
    // A rotation about the attached point: free keeps Φ = 0, locked sees it.
    const core::Configuration turned =
        test::rotate_node_about(slid, 0, point + distance * direction, random.rotation_vector());
    CHECK(test::value(free, turned, 0).norm() <= 1e-14);
    CHECK(test::value(locked, turned, 0).head<2>().norm() <= 1e-14);
  }
  const core::Configuration turned = test::rotate_node_about(q0, 0, point, 0.5 * random.axis());
  CHECK(test::value(locked, turned, 0).tail<3>().norm() > 0.3);
}

TEST_CASE("prismatic joint rejects the ground, missing nodes and a zero direction",
          "[joints][prismatic][errors]") {
  test::RandomRotations random(403);
  const core::Configuration q0 = test::random_configuration(2, random);
  using joints::Attachment;
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  CHECK_THROWS_WITH(
      joints::PrismaticJoint(Attachment{.node = 2}, origin, x, true, q0),
      Catch::Contains("node 2 does not exist") && Catch::Contains("joints::PrismaticJoint"));
  CHECK_THROWS_WITH(joints::PrismaticJoint(Attachment{}, origin, x, false, q0),
                    Catch::Contains("attachment is on the ground"));
  CHECK_THROWS_WITH(joints::PrismaticJoint(Attachment{.node = 0}, origin, origin, false, q0),
                    Catch::Contains("line direction is zero"));
}
