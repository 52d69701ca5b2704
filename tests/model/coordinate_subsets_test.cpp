// Part of a vector block fixed or driven (Model::fix_coordinates, joints::CoordinateDriver), on
// cables built by the cable family's mesh builder (core::add_cable).
#include <spar/spar.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace spar;

namespace {

// A steel-like cable of L = 1 m with EI = 1 N m², nearly inextensible (EA = 1e6 N) and a weight
// q = ρA g that deflects the simply supported span by w = 5qL⁴/(384 EI) = 1e-5 m: the membrane
// stiffening of a span whose ends cannot approach is then ~EA w²/EI ≈ 1e-4 of the bending, below
// the tests' 1e-3.
constexpr double length = 1.0, bending = 1.0, axial = 1e6, g = 9.81;
constexpr double load_per_length = 384.0 * bending * 1e-5 / (5.0 * length * length * length * length);

core::Cable make_cable(core::Model& model, int elements) {
  model.set_gravity(Eigen::Vector3d(0, 0, -g));
  return core::add_cable<3>(model, {.end = Eigen::Vector3d(length, 0, 0), .elements = elements,
                                    .section = {.axial_stiffness = axial, .bending_stiffness = bending,
                                                .mass_per_length = load_per_length / g}});
}

/// The vertical deflection of the middle node (an even element count puts a node there).
double midspan_deflection(const core::Model& model, const core::Cable& cable) {
  return -model.state().vector(cable.nodes[cable.nodes.size() / 2])(2);
}

}  // namespace

TEST_CASE("a cable pinned by fixing its end positions only deflects as the simply supported beam",
          "[model][rancf][validation]") {
  // Cubic Hermite elements give the Euler–Bernoulli beam's nodal deflections exactly under a
  // uniform load (the consistent nodal forces), so the difference is the geometric
  // nonlinearity alone (~1e-4, see above): a relative 1e-3.
  core::Model pinned;
  const core::Cable cable = make_cable(pinned, 8);
  for (const int end : {cable.nodes.front(), cable.nodes.back()}) pinned.fix_coordinates(end, {0, 1, 2});
  solvers::solve_static(pinned, {.load_steps = 1});
  const double simply_supported = 5.0 * load_per_length * std::pow(length, 4) / (384.0 * bending);
  CHECK(midspan_deflection(pinned, cable) == Approx(simply_supported).epsilon(1e-3));

  // Fixing the slopes too clamps the ends: a fifth of the deflection. The ratio tells that
  // fix_coordinates fixed the positions and left the slopes free.
  core::Model clamped;
  const core::Cable same = make_cable(clamped, 8);
  for (const int end : {same.nodes.front(), same.nodes.back()}) clamped.fix(end);
  solvers::solve_static(clamped, {.load_steps = 1});
  CHECK(midspan_deflection(clamped, same) == Approx(simply_supported / 5.0).epsilon(1e-3));
}

TEST_CASE("a cable's root slope driven by a CoordinateDriver turns the unloaded cable rigidly",
          "[model][rancf][joints][validation]") {
  // Root position fixed, root slope driven from (1, 0, 0) to (cos θ, sin θ, 0): the unloaded
  // cable's equilibrium is the rigid turn by θ with no strain, exact on any mesh.
  core::Model model;
  const core::Cable cable = core::add_cable<3>(
      model, {.end = Eigen::Vector3d(length, 0, 0), .elements = 4,
              .section = {.axial_stiffness = axial, .bending_stiffness = bending, .mass_per_length = 1.0}});
  model.fix_coordinates(cable.nodes.front(), {0, 1, 2});
  const double theta = 0.3;
  joints::CoordinateDriver slope(cable.nodes.front(), {3, 4},
                                 {joints::TimeFunction::constant(std::cos(theta) - 1.0),
                                  joints::TimeFunction::constant(std::sin(theta))},
                                 model.state());
  const solvers::StaticReport report = solvers::solve_static(model, {.load_steps = 4}, {&slope});
  INFO("Newton iterations: " << report.newton_iterations);
  const Eigen::VectorXd tip = model.state().vector(cable.nodes.back());
  CHECK((tip.head<3>() - length * Eigen::Vector3d(std::cos(theta), std::sin(theta), 0)).norm() < 1e-10);
  CHECK((tip.tail<3>() - Eigen::Vector3d(std::cos(theta), std::sin(theta), 0)).norm() < 1e-10);
}

TEST_CASE("the CoordinateDriver's derivatives agree with finite differences", "[joints][derivatives]") {
  core::Model model;
  const core::Cable cable = core::add_cable<2>(
      model, {.end = Eigen::Vector3d(2, 0, 0), .elements = 1,
              .section = {.axial_stiffness = 1, .bending_stiffness = 1, .mass_per_length = 1}});
  const joints::CoordinateDriver driver(cable.nodes.back(), {0, 3},
                                        {joints::TimeFunction::polynomial({0.1, -0.4, 0.7}),
                                         joints::TimeFunction::linear(0.5)},
                                        model.state());
  joints::ConstraintCheckState state{.q = model.state(), .time = 0.6};
  state.q.vector(cable.nodes.back()) += Eigen::Vector4d(0.02, -0.03, 0.01, 0.05);
  state.velocity = Eigen::VectorXd::LinSpaced(state.q.dof_count(), -0.8, 1.1);
  state.acceleration = Eigen::VectorXd::LinSpaced(state.q.dof_count(), 0.5, -1.5);
  state.multipliers = Eigen::Vector2d(0.7, -1.3);
  const core::DerivativeCheck check = joints::check_constraint(driver, state);
  INFO(check.description());
  CHECK(check.passed());
}

TEST_CASE("bad coordinate subsets and cables are refused and change nothing", "[model][input]") {
  core::Model model;
  const int frame = model.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  const int node = model.add_vector(Eigen::VectorXd::Zero(6));
  CHECK_THROWS_WITH(model.fix_coordinates(frame, {0}), Catch::Contains("is a frame"));
  CHECK_THROWS_WITH(model.fix_coordinates(node, {1, 6}), Catch::Contains("coordinate 6 is outside"));
  CHECK_THROWS_WITH(model.fix_coordinates(node, {2, 2}), Catch::Contains("given twice"));
  CHECK(model.fixed_dofs().empty());
  model.fix_coordinates(node, {5, 3});
  CHECK(model.fixed_dofs() == std::vector<int>{6 + 3, 6 + 5});

  const core::Configuration& q = model.state();
  const auto hold = joints::TimeFunction::constant(0);
  CHECK_THROWS_WITH(joints::CoordinateDriver(frame, {0}, {hold}, q), Catch::Contains("not a vector block"));
  CHECK_THROWS_WITH(joints::CoordinateDriver(node, {}, {hold}, q), Catch::Contains("no coordinate"));
  CHECK_THROWS_WITH(joints::CoordinateDriver(node, {0, 9}, {hold}, q), Catch::Contains("outside"));
  CHECK_THROWS_WITH(joints::CoordinateDriver(node, {0, 1, 2}, {hold, hold}, q),
                    Catch::Contains("2 time functions for 3 coordinates"));

  const int blocks = model.block_count(), elements = model.element_count();
  CHECK_THROWS_WITH(core::add_cable<3>(model, {.elements = 0}), Catch::Contains("0 elements"));
  CHECK_THROWS_WITH(core::add_cable<3>(model, {.end = Eigen::Vector3d::Zero()}), Catch::Contains("coincide"));
  CHECK_THROWS_WITH(core::add_cable<2>(model, {.end = Eigen::Vector3d(1, 0, 1)}), Catch::Contains("X-Y plane"));
  CHECK_THROWS_AS(core::add_cable<3>(model, {.section = {.axial_stiffness = -1}}), Error);
  CHECK(model.block_count() == blocks);
  CHECK(model.element_count() == elements);
}
