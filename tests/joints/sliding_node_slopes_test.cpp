// SlidingNodeSlopes (000 eq. (40)): both slope conditions against finite differences on random
// node blocks (with a frame block in the configuration, so the column layout is exercised), zero
// when the sides agree, a hinge that keeps the stretch, and the errors it raises.
#include <spar/error.hpp>
#include <spar/joints/sliding_node_slopes.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "constraint_checks.hpp"

using namespace spar;
using Catch::Contains;

TEST_CASE("sliding node slopes: derivatives against finite differences", "[joints][sliding]") {
  test::RandomRotations random(77);
  for (int dimension : {2, 3})
    for (joints::SlopeCondition condition : {joints::SlopeCondition::continuous, joints::SlopeCondition::discontinuous})
      for (int sample = 0; sample < 5; ++sample) {
        core::Configuration q = test::random_configuration(1, random);
        Eigen::VectorXd left(2 * dimension), right(2 * dimension);
        for (int i = 0; i < 2 * dimension; ++i) {
          left(i) = random.uniform(-1, 1);
          right(i) = random.uniform(-1, 1);
        }
        const int a = q.add_vector(left), b = q.add_vector(right);
        const joints::SlidingNodeSlopes joint(b, a, dimension, condition, q);  // right block first: columns swap
        INFO("dimension " << dimension << ", discontinuous " << (condition == joints::SlopeCondition::discontinuous));
        test::check_derivatives(joint, q, 0.0, random);
      }
}

TEST_CASE("sliding node slopes: zero on a smooth node; the discontinuous one allows a kink", "[joints][sliding]") {
  core::Configuration q;
  const int a = q.add_vector(Eigen::Vector4d(0.3, -0.2, 0.6, 0.8));
  const int b = q.add_vector(Eigen::Vector4d(0.3, -0.2, 0.6, 0.8));
  const joints::SlidingNodeSlopes smooth(a, b, 2, joints::SlopeCondition::continuous, q);
  const joints::SlidingNodeSlopes hinge(a, b, 2, joints::SlopeCondition::discontinuous, q);
  CHECK(smooth.equation_count() == 4);
  CHECK(hinge.equation_count() == 3);
  CHECK(test::value(smooth, q, 0.0).norm() == 0.0);
  CHECK(test::value(hinge, q, 0.0).norm() == 0.0);
  // Turn the right-hand slope by 40°, same magnitude: a kink the hinge accepts and the smooth
  // node does not; stretch it by 10 %: both refuse.
  const double angle = 0.7;
  q.vector(b).tail<2>() = Eigen::Rotation2Dd(angle) * Eigen::Vector2d(0.6, 0.8);
  CHECK(std::abs(test::value(hinge, q, 0.0)(2)) <= 1e-15);  // round-off of the rotation
  CHECK(test::value(smooth, q, 0.0).tail<2>().norm() > 0.6);
  q.vector(b).tail<2>() *= 1.1;
  CHECK(test::value(hinge, q, 0.0)(2) == Approx(0.5 * (1.0 - 1.21)));
}

TEST_CASE("sliding node slopes: invalid blocks are refused", "[joints][sliding]") {
  core::Configuration q;
  const int a = q.add_vector(Eigen::Vector4d::Zero());
  const int small = q.add_vector(Eigen::Vector2d::Zero());
  CHECK_THROWS_WITH(joints::SlidingNodeSlopes(a, a, 2, joints::SlopeCondition::discontinuous, q), Contains("same block"));
  CHECK_THROWS_WITH(joints::SlidingNodeSlopes(a, small, 2, joints::SlopeCondition::discontinuous, q), Contains("node block"));
  CHECK_THROWS_WITH(joints::SlidingNodeSlopes(a, 5, 2, joints::SlopeCondition::discontinuous, q), Contains("node block"));
  CHECK_THROWS_WITH(joints::SlidingNodeSlopes(a, small, 4, joints::SlopeCondition::continuous, q), Contains("dimension"));
}
