// RevoluteJoint: zero at q0, free relative rotation about the hinge axis only, its derivatives
// against finite differences, and the errors it raises.
#include <spar/error.hpp>
#include <spar/joints/revolute_joint.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>
#include <utility>
#include <vector>

#include "constraint_checks.hpp"

using namespace spar;

namespace {
const std::vector<std::pair<int, int>> node_pairs = {{2, 0}, {1, -1}, {-1, 1}};
}  // namespace

TEST_CASE("revolute joint: zero at q0, derivatives against finite differences",
          "[joints][revolute]") {
  test::RandomRotations random(201);
  for (int sample = 0; sample < 15; ++sample) {
    const core::Configuration q0 = test::random_configuration(3, random);
    const Eigen::Vector3d point = test::random_vector(random, 2);
    const Eigen::Vector3d axis = test::random_vector(random, 1);
    for (const auto& [node_a, node_b] : node_pairs) {
      INFO("sample " << sample << ", nodes " << node_a << ", " << node_b);
      const joints::RevoluteJoint joint(joints::attach_at(node_a, point, q0),
                                        joints::attach_at(node_b, point, q0), axis, q0);
      CHECK(test::value(joint, q0, 0).norm() <= 1e-14);
      test::check_derivatives(joint, q0, 0.3, random);
      test::check_derivatives(joint, test::random_configuration(3, random), 0.3, random);
    }
  }
}

TEST_CASE("revolute joint frees the relative rotation about the hinge axis and no other",
          "[joints][revolute]") {
  test::RandomRotations random(202);
  const core::Configuration q0 = test::random_configuration(2, random);
  const Eigen::Vector3d point = test::random_vector(random, 2);
  const Eigen::Vector3d axis = random.axis();
  for (const int node_b : {1, -1}) {
    INFO("node b = " << node_b);
    const joints::RevoluteJoint joint(joints::attach_at(0, point, q0),
                                      joints::attach_at(node_b, point, q0), 3 * axis, q0);
    for (const double angle : {0.3, 2.0, -3.0}) {
      // Node 0 turned about the hinge: assembled.
      CHECK(test::value(joint, test::rotate_node_about(q0, 0, point, angle * axis), 0).norm() <=
            1e-14);
      // Node 0 turned about an axis ⊥ the hinge: the axis rows see sin(angle).
      const Eigen::Vector3d across = axis.unitOrthogonal();
      const Eigen::VectorXd phi =
          test::value(joint, test::rotate_node_about(q0, 0, point, angle * across), 0);
      CHECK(phi.head<3>().norm() <= 1e-14);
      CHECK(phi.tail<2>().norm() == Approx(std::abs(std::sin(angle))).epsilon(1e-12));
    }
  }
}

TEST_CASE("revolute joint rejects a zero axis, missing nodes and two ground attachments",
          "[joints][revolute][errors]") {
  test::RandomRotations random(203);
  const core::Configuration q0 = test::random_configuration(2, random);
  using joints::Attachment;
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  CHECK_THROWS_WITH(joints::RevoluteJoint(Attachment{.node = 0}, Attachment{.node = 1},
                                          Eigen::Vector3d::Zero(), q0),
                    Catch::Contains("hinge axis is zero"));
  CHECK_THROWS_WITH(joints::RevoluteJoint(Attachment{.node = 0}, Attachment{.node = 1},
                                          Eigen::Vector3d(NAN, 0, 1), q0),
                    Catch::Contains("hinge axis is zero or not finite"));
  CHECK_THROWS_WITH(
      joints::RevoluteJoint(Attachment{.node = 0}, Attachment{.node = 7}, axis, q0),
      Catch::Contains("node 7 does not exist") && Catch::Contains("joints::RevoluteJoint"));
  CHECK_THROWS_WITH(joints::RevoluteJoint(Attachment{}, Attachment{}, axis, q0),
                    Catch::Contains("both attachments are on the ground"));
}
