// The joints' evaluation functions allocate nothing: every global operator new in this test
// executable is counted, and a batch of value/jacobian/multiplier_tangent/acceleration_terms/
// time_derivative calls on every joint must leave the counter unchanged.
#include <spar/elements/beam/beam_centerline.hpp>
#include <spar/joints/joints.hpp>

#include <catch2/catch.hpp>

#include "allocation_counter.hpp"

#include <spar/core/model.hpp>
#include <spar/iga/straight_line.hpp>
#include <spar/elements/beam/beam.hpp>

#include <array>
#include <cmath>

#include "constraint_checks.hpp"

using namespace spar;

TEST_CASE("joint evaluations do not allocate", "[joints][allocation]") {
  test::RandomRotations random(701);
  const core::Configuration q0 = test::random_configuration(3, random);
  const Eigen::Vector3d point = test::random_vector(random, 2);
  const Eigen::Vector3d axis = random.axis();
  const joints::Attachment a = joints::attach_at(0, point, q0);
  const joints::Attachment b = joints::attach_at(2, point, q0);
  const joints::SphericalJoint spherical(a, b, q0);
  const joints::RevoluteJoint revolute(a, b, axis, q0);
  const joints::ClampJoint clamp(a, b, q0);
  const joints::PrismaticJoint prismatic(a, point, axis, true, q0);
  const joints::PositionDriver position(a, axis, joints::TimeFunction::polynomial({0.0, 1.0, 2.0}),
                                        q0);
  const joints::AngleDriver angle(1, axis, joints::TimeFunction::linear(2.0), q0);
  const std::array<const joints::Constraint*, 6> constraints = {&spherical, &revolute, &clamp,
                                                                &prismatic, &position, &angle};
  // The sliding joint, on a carrier of 4 quadratic elements, locked (4 equations).
  core::Model model;
  core::add_beam(model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 0, 0), 4, 2),
                  .stiffness = {.axial = 1, .shear_2 = 1, .shear_3 = 1, .torsion = 1, .bending_2 = 1, .bending_3 = 1}});
  const int slider = model.add_frame(Eigen::Vector3d(1.1, 0, 0), Eigen::Matrix3d::Identity());
  joints::SlidingJoint sliding({.slider = {.node = slider}, .carrier = core::beam_centerline(model, 0), .zeta = 1.1, .upper_stop = 1.5}, model);
  core::Configuration q_sliding = model.state();
  q_sliding.vector(sliding.zeta_block())(0) = 1.6;
  std::string description;
  sliding.update_structure(q_sliding, Eigen::VectorXd::Zero(q_sliding.dof_count()), 0.0, description);
  REQUIRE(sliding.locked());
  const Eigen::Index sliding_dofs = core::block_dof_count(q_sliding, sliding.blocks());
  const Eigen::VectorXd sliding_velocity = Eigen::VectorXd::Constant(q_sliding.dof_count(), 0.5);
  Eigen::MatrixXd B_sliding(4, sliding_dofs), K_sliding(sliding_dofs, sliding_dofs);

  const core::Configuration q = test::random_configuration(3, random);
  const Eigen::VectorXd velocity = Eigen::VectorXd::Constant(q.dof_count(), 0.5);
  const Eigen::VectorXd lambda = Eigen::VectorXd::Constant(6, 0.25);
  Eigen::VectorXd phi(6);
  Eigen::MatrixXd B(6, 12);
  Eigen::MatrixXd K(12, 12);
  double sink = 0;

  const long before = spar::test::allocation_count();
  for (const joints::Constraint* constraint : constraints) {
    const Eigen::Index m = constraint->equation_count();
    const Eigen::Index n = 6 * static_cast<Eigen::Index>(constraint->blocks().size());
    constraint->value(q, 0.3, phi.head(m));
    constraint->jacobian(q, 0.3, B.topLeftCorner(m, n));
    constraint->multiplier_tangent(q, 0.3, lambda.head(m), K.topLeftCorner(n, n));
    sink += phi.head(m).sum() + B.topLeftCorner(m, n).sum() + K.topLeftCorner(n, n).sum();
    constraint->acceleration_terms(q, velocity, 0.3, phi.head(m));
    sink += phi.head(m).sum();
    constraint->time_derivative(q, 0.3, phi.head(m));
    sink += phi.head(m).sum();
  }
  sliding.value(q_sliding, 0.3, phi.head(4));
  sliding.jacobian(q_sliding, 0.3, B_sliding);
  sliding.multiplier_tangent(q_sliding, 0.3, lambda.head(4), K_sliding);
  sliding.acceleration_terms(q_sliding, sliding_velocity, 0.3, phi.head(4));
  sink += phi.head(4).sum() + B_sliding.sum() + K_sliding.sum();
  const long after = spar::test::allocation_count();
  CHECK(after == before);
  CHECK(std::isfinite(sink));
}
