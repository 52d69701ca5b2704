// Error paths of the model's building blocks: each refusal names the problem and leaves the
// model as it was.
#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <memory>

#include "beam_fixtures.hpp"
#include "point_mass.hpp"

using namespace spar;

TEST_CASE("replace_element refuses a missing index and a null element, leaving the model as it was",
          "[model][errors]") {
  core::Model model;
  const int block = model.add_vector(Eigen::Vector3d(0.1, 0.2, 0.3));
  model.add_element(std::make_unique<test::PointMass>(block, 1.0));
  const long version = model.structure_version();
  CHECK_THROWS_WITH(model.replace_element(1, std::make_unique<test::PointMass>(block, 2.0)),
                    Catch::Contains("element 1 does not exist"));
  CHECK_THROWS_WITH(model.replace_element(-1, std::make_unique<test::PointMass>(block, 2.0)),
                    Catch::Contains("does not exist"));
  CHECK_THROWS_WITH(model.replace_element(0, nullptr), Catch::Contains("null element"));
  CHECK_THROWS_WITH(model.replace_element(0, std::make_unique<test::PointMass>(block + 1, 2.0)),
                    Catch::Contains("block 1 does not exist"));
  CHECK(model.element_count() == 1);
  CHECK(model.structure_version() == version);
}

TEST_CASE("a configuration refuses an increment of the wrong size", "[model][errors]") {
  core::Configuration q;
  q.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  const core::Configuration start = q;
  CHECK_THROWS_WITH(q.apply_increment(Eigen::VectorXd::Zero(5)), Catch::Contains("increment has 5 entries for 6"));
  CHECK_THROWS_WITH(q.assign_increment(start, Eigen::VectorXd::Zero(7)), Catch::Contains("increment has 7 entries"));
  CHECK(q.position[0] == start.position[0]);
  CHECK(q.rotation[0] == start.rotation[0]);
}

TEST_CASE("a beam refuses a section axis along its centerline and a wrong number of reference rotations",
          "[model][errors]") {
  core::Model model;
  CHECK_THROWS_WITH(core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 2),
                                    .stiffness = test::generic_stiffness(),
                                    .section_axis_hint = Eigen::Vector3d(2.0, 0.0, 0.0)}),
                    Catch::Contains("parallel to the centerline"));
  CHECK_THROWS_WITH(core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 2),
                                    .stiffness = test::generic_stiffness(),
                                    .reference_rotations = {Eigen::Matrix3d::Identity()}}),
                    Catch::Contains("got 1 reference rotations for 4 control points"));
  CHECK(core::beam_count(model) == 0);
  CHECK(model.block_count() == 0);
}

TEST_CASE("a rigid body without mass and a beam of degree 0 or of zero speed are refused, naming the fix",
          "[model][errors]") {
  core::Model model;
  try {
    core::add_rigid_body(model, {.mass = 0.0, .inertia = Eigen::Matrix3d::Identity()});
    FAIL("a massless rigid body was accepted");
  } catch (const Error& error) {
    CHECK_THAT(error.what(), Catch::Contains("rigid body mass must be positive and finite, got 0"));
    CHECK(error.where() == "core::add_rigid_body");
    CHECK(error.fix() == "give the mass in kg");
  }
  // Degree 0: a piecewise-constant "centerline" (two points, knots {0, 0.5, 1}).
  const iga::NurbsCurve<3> constant(iga::KnotVector({0, 0.5, 1}, 0), iga::NurbsCurve<3>::Points::Zero(3, 2));
  try {
    core::add_beam(model, {.centerline = constant, .stiffness = test::generic_stiffness()});
    FAIL("a beam of degree 0 was accepted");
  } catch (const Error& error) {
    CHECK_THAT(error.what(), Catch::Contains("a beam needs degree p >= 1, got 0"));
    CHECK(error.where() == "core::GeometricallyExactBeam");
    CHECK(error.fix() == "use a linear or higher-degree centerline");
  }
  // Three coincident control points: no tangent anywhere (the reference rotations are given, so
  // the frames' construction from the tangent does not refuse it first).
  const iga::NurbsCurve<3> point(iga::KnotVector({0, 0, 0, 1, 1, 1}, 2), iga::NurbsCurve<3>::Points::Zero(3, 3));
  try {
    core::add_beam(model, {.centerline = point, .stiffness = test::generic_stiffness(),
                    .reference_rotations = std::vector<Eigen::Matrix3d>(3, Eigen::Matrix3d::Identity())});
    FAIL("a beam of zero length was accepted");
  } catch (const Error& error) {
    CHECK_THAT(error.what(), Catch::Contains("the centerline has zero speed at u = "));
    CHECK(error.where() == "core::GeometricallyExactBeam");
    CHECK_THAT(error.fix(), Catch::Contains("no coincident control points"));
  }
  // Each refusal leaves no node behind (the beam's frames were added before its elements were
  // built, and a refused Gauss rule or zero speed left them in the model).
  CHECK_THROWS_WITH(core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 2),
                                    .stiffness = test::generic_stiffness(), .quadrature_points = 65}),
                    Catch::Contains("quadrature_points = 65"));
  CHECK(model.block_count() == 0);
  CHECK(model.dof_count() == 0);
}
