// Bad input to the model and the statics solver raises spar::Error with a useful message.
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include "cantilever.hpp"

using namespace spar;

TEST_CASE("a clamp on a node that does not exist is refused", "[statics][errors]") {
  auto c = test::make_cantilever(2, 2);
  CHECK_THROWS_WITH(c.model.fix(1000), Catch::Contains("block 1000 does not exist"));
  CHECK_THROWS_WITH(core::add_load(c.model, core::NodalForce{.node = -1}), Catch::Contains("does not exist"));
}

TEST_CASE("a beam with a zero stiffness is refused", "[statics][errors]") {
  core::SectionStiffness C = test::cantilever_stiffness();
  C.bending_2 = 0.0;
  core::Model model;
  CHECK_THROWS_WITH(core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 2), .stiffness = C}),
                    Catch::Contains("bending stiffness EI2"));
}

TEST_CASE("a beam with fewer control points than p + 1 is refused", "[statics][errors]") {
  // A beam's centerline is a NurbsCurve, so the refusal happens while its arguments are built:
  // a clamped knot vector of degree p with fewer than p + 1 basis functions, or a curve whose
  // control points do not match its basis functions. Either way no block reaches the model.
  core::Model model;
  const auto add_quadratic = [&model](std::vector<double> knots, int points) {
    core::add_beam(model, {.centerline = iga::NurbsCurve<3>(iga::KnotVector(std::move(knots), 2),
                                                     iga::NurbsCurve<3>::Points::Zero(3, points)),
                    .stiffness = test::cantilever_stiffness()});
  };
  CHECK_THROWS_WITH(add_quadratic({0, 0, 1, 1}, 2), Catch::Contains("too few control points"));
  CHECK_THROWS_WITH(add_quadratic({0, 0, 0, 1, 1, 1}, 2), Catch::Contains("control points"));
  CHECK(core::beam_count(model) == 0);
  CHECK(model.block_count() == 0);
}

TEST_CASE("a load step that cannot converge reports the last converged load factor", "[statics][errors]") {
  // Two Newton iterations per step cannot roll a cantilever into a circle in one step.
  auto c = test::make_cantilever(8, 2);
  core::add_load(c.model, core::NodalMoment{.node = c.tip, .moment = Eigen::Vector3d(0, 0, 2 * 3.14159 * 1e4)});
  const core::Configuration initial = c.model.state();
  try {
    solvers::solve_static(c.model, {.load_steps = 1, .max_iterations = 2, .max_cutbacks = 2});
    FAIL("expected a ConvergenceError");
  } catch (const solvers::ConvergenceError& error) {
    CHECK_THAT(error.what(), Catch::Contains("last converged load factor"));
    // Two iterations cannot turn the tip by a quarter circle either (the smallest increment,
    // after two halvings): no step converges, the last converged factor is 0 and the state left
    // behind must be that equilibrium — the straight reference, bit for bit, not a failed iterate.
    CHECK(error.last_converged_load_factor() == 0.0);
    for (int k = 0; k < c.model.block_count(); ++k) {
      CHECK(c.model.state().position[k] == initial.position[k]);
      CHECK(c.model.state().rotation[k] == initial.rotation[k]);
    }
  }
}

TEST_CASE("an unsupported beam gives a singular tangent error", "[statics][errors]") {
  core::Model model;
  const int b = core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 2), .stiffness = test::cantilever_stiffness()});
  core::add_load(model, core::NodalForce{.node = core::beam(model, b).node(2), .force = Eigen::Vector3d(0, 1, 0)});
  CHECK_THROWS_WITH(solvers::solve_static(model), Catch::Contains("singular"));
}
