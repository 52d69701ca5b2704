// SphericalJoint: zero at its assembled configuration, free rotations about the common point, its
// derivatives against finite differences, and the errors it raises.
#include <spar/error.hpp>
#include <spar/joints/spherical_joint.hpp>

#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "constraint_checks.hpp"

using namespace spar;

namespace {
// Node pairs: two nodes (in reverse order, so column blocks differ from node order), a node and
// the ground, the ground and a node.
const std::vector<std::pair<int, int>> node_pairs = {{2, 0}, {1, -1}, {-1, 1}};
}  // namespace

TEST_CASE("spherical joint: zero at q0, derivatives against finite differences",
          "[joints][spherical]") {
  test::RandomRotations random(101);
  for (int sample = 0; sample < 15; ++sample) {
    const core::Configuration q0 = test::random_configuration(3, random);
    const Eigen::Vector3d point = test::random_vector(random, 2);
    for (const auto& [node_a, node_b] : node_pairs) {
      INFO("sample " << sample << ", nodes " << node_a << ", " << node_b);
      const joints::SphericalJoint joint(joints::attach_at(node_a, point, q0),
                                         joints::attach_at(node_b, point, q0), q0);
      // Round-off of x + R R0ᵀ(point − x) for |x|, |point| ≤ 4: a few ulps of 4.
      CHECK(test::value(joint, q0, 0).norm() <= 1e-14);
      test::check_derivatives(joint, q0, 0.3, random);
      test::check_derivatives(joint, test::random_configuration(3, random), 0.3, random);
    }
  }
}

TEST_CASE("spherical joint leaves the rotations about the common point free",
          "[joints][spherical]") {
  test::RandomRotations random(102);
  const core::Configuration q0 = test::random_configuration(2, random);
  const Eigen::Vector3d point = test::random_vector(random, 2);
  const joints::SphericalJoint joint(joints::attach_at(0, point, q0),
                                     joints::attach_at(1, point, q0), q0);
  for (int k = 0; k < 10; ++k) {
    const core::Configuration q =
        test::rotate_node_about(test::rotate_node_about(q0, 0, point, random.rotation_vector()), 1,
                                point, random.rotation_vector());
    CHECK(test::value(joint, q, 0).norm() <= 1e-14);
  }
  CHECK(joint.blocks() == std::vector<int>{0, 1});
}

TEST_CASE("spherical joint rejects missing nodes and two ground attachments",
          "[joints][spherical][errors]") {
  test::RandomRotations random(103);
  const core::Configuration q0 = test::random_configuration(2, random);
  using joints::Attachment;
  CHECK_THROWS_WITH(
      joints::SphericalJoint(Attachment{.node = 2}, Attachment{.node = 0}, q0),
      Catch::Contains("node 2 does not exist") && Catch::Contains("joints::SphericalJoint"));
  CHECK_THROWS_WITH(joints::SphericalJoint(Attachment{.node = 0}, Attachment{.node = -3}, q0),
                    Catch::Contains("node -3 does not exist"));
  CHECK_THROWS_WITH(joints::SphericalJoint(Attachment{}, Attachment{}, q0),
                    Catch::Contains("both attachments are on the ground"));
  CHECK_THROWS_WITH(joints::SphericalJoint(Attachment{.node = 1}, Attachment{.node = 1}, q0),
                    Catch::Contains("same node 1"));
  CHECK_THROWS_AS(joints::attach_at(5, Eigen::Vector3d::Zero(), q0), Error);
}
