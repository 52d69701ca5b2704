// Every joint checks what it is evaluated on (the Constraint interface does, for all of them: see
// also constraint_boundary_test.cpp): a configuration that lacks its nodes, outputs that are not
// sized m, m×n and n×n (n = 6 per frame node here), multipliers or velocities of the wrong size all
// raise spar::Error naming the joint and the mismatch.
#include <spar/error.hpp>
#include <spar/joints/spherical_joint.hpp>

#include <catch2/catch.hpp>

#include "constraint_checks.hpp"

using namespace spar;

TEST_CASE("joints reject a configuration without their nodes and mis-sized outputs",
          "[joints][errors]") {
  test::RandomRotations random(601);
  const core::Configuration q0 = test::random_configuration(3, random);
  const joints::SphericalJoint joint(joints::Attachment{.node = 2}, joints::Attachment{.node = 0},
                                     q0);
  const core::Configuration smaller = test::random_configuration(2, random);
  Eigen::VectorXd phi(3);
  CHECK_THROWS_WITH(joint.value(smaller, 0, phi),
                    Catch::Contains("has 2 blocks but the joint acts on block 2") &&
                        Catch::Contains("joints::SphericalJoint"));
  Eigen::VectorXd short_phi(2);
  CHECK_THROWS_WITH(joint.value(q0, 0, short_phi),
                    Catch::Contains("output vector has 2 entries, expected 3"));
  Eigen::MatrixXd B(3, 6);
  CHECK_THROWS_WITH(joint.jacobian(q0, 0, B), Catch::Contains("Jacobian B is 3×6, expected 3×12"));
  Eigen::MatrixXd K(12, 12);
  const Eigen::VectorXd lambda(2);
  CHECK_THROWS_WITH(joint.multiplier_tangent(q0, 0, lambda, K),
                    Catch::Contains("multiplier vector has 2 entries, expected 3"));
  const Eigen::VectorXd velocity = Eigen::VectorXd::Zero(12);
  CHECK_THROWS_WITH(joint.acceleration_terms(q0, velocity, 0, phi),
                    Catch::Contains("velocity vector has 12 entries, expected 18"));
  Eigen::VectorXd phi_t(3);
  joint.time_derivative(q0, 0, phi_t);
  CHECK(phi_t.isZero(0));
}
