// ClampJoint: zero at q0 and along rigid motions of the pair, violated by any relative motion,
// its derivatives against finite differences, and the errors it raises.
#include <spar/error.hpp>
#include <spar/joints/clamp_joint.hpp>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "constraint_checks.hpp"

using namespace spar;

namespace {
const std::vector<std::pair<int, int>> node_pairs = {{2, 0}, {1, -1}, {-1, 1}};
}  // namespace

TEST_CASE("clamp joint: zero at q0, derivatives against finite differences", "[joints][clamp]") {
  test::RandomRotations random(301);
  for (int sample = 0; sample < 15; ++sample) {
    const core::Configuration q0 = test::random_configuration(3, random);
    const Eigen::Vector3d point = test::random_vector(random, 2);
    for (const auto& [node_a, node_b] : node_pairs) {
      INFO("sample " << sample << ", nodes " << node_a << ", " << node_b);
      const joints::ClampJoint joint(joints::attach_at(node_a, point, q0),
                                     joints::attach_at(node_b, point, q0), q0);
      CHECK(test::value(joint, q0, 0).norm() <= 1e-14);
      test::check_derivatives(joint, q0, 0.3, random);
      test::check_derivatives(joint, test::random_configuration(3, random), 0.3, random);
    }
  }
}

TEST_CASE("clamp joint allows rigid motions of the pair and locks relative rotations",
          "[joints][clamp]") {
  test::RandomRotations random(302);
  const core::Configuration q0 = test::random_configuration(2, random);
  const Eigen::Vector3d point = test::random_vector(random, 2);
  const joints::ClampJoint joint(joints::attach_at(0, point, q0), joints::attach_at(1, point, q0),
                                 q0);
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector3d rotation = random.rotation_vector();
    const Eigen::Vector3d center = test::random_vector(random, 2);
    const core::Configuration rigid = test::rotate_node_about(
        test::rotate_node_about(q0, 0, center, rotation), 1, center, rotation);
    CHECK(test::value(joint, rigid, 0).norm() <= 1e-14);
    // Turning node 1 alone about the clamp point by Q = exp(0.1 a): the rotation rows are
    // (e₂·Q e₃, e₃·Q e₁, e₁·Q e₂) = (Q₂₃, Q₃₁, Q₁₂) (docs/joints.md J16, both frames carrying the
    // inertial basis at q0), Q from Eigen's angle-axis. Entries of rotations built from the same
    // angle by two routes: 1e-15 is a few roundings.
    const Eigen::Vector3d axis = random.axis();
    const Eigen::VectorXd phi = test::value(joint, test::rotate_node_about(q0, 1, point, 0.1 * axis), 0);
    const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.1, axis).toRotationMatrix();
    CHECK(phi.head<3>().norm() <= 1e-14);
    CHECK((phi.tail<3>() - Eigen::Vector3d(Q(1, 2), Q(2, 0), Q(0, 1))).norm() <= 1e-15);
  }
  // The Jacobian of the rotation rows at q0 is regular: a clamp has no free relative rotation.
  const Eigen::MatrixXd B = test::jacobian(joint, q0, 0);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(B);
  CHECK(lu.rank() == 6);
}

TEST_CASE("clamp joint rejects missing nodes, the same node twice and two ground attachments",
          "[joints][clamp][errors]") {
  test::RandomRotations random(303);
  const core::Configuration q0 = test::random_configuration(2, random);
  using joints::Attachment;
  CHECK_THROWS_WITH(
      joints::ClampJoint(Attachment{.node = 4}, Attachment{.node = 0}, q0),
      Catch::Contains("node 4 does not exist") && Catch::Contains("joints::ClampJoint"));
  CHECK_THROWS_WITH(joints::ClampJoint(Attachment{.node = 0}, Attachment{.node = 0}, q0),
                    Catch::Contains("same node 0"));
  CHECK_THROWS_WITH(joints::ClampJoint(Attachment{}, Attachment{}, q0),
                    Catch::Contains("both attachments are on the ground"));
}
