// The public API's boundaries refuse the input of issue 29's audit with a spar::Error naming it:
// out-of-range indices that read past an array (Model::element(99), ancf_node_position of block
// 999), an ElementOutput that was never sized, a replaced configuration that no longer holds the
// elements' blocks, a rotation block that is no rotation, a NaN velocity, a NaN load history in
// statics, an ANCF beam without a section. A static load too large for the model ends in an error
// that says so, and leaves the state of the last converged load factor.
#include <spar/core/core.hpp>
#include <spar/elements/elements.hpp>
#include <spar/iga/iga.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include "cantilever.hpp"
#include "error_cases.hpp"

#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace spar;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

/// A steel cantilever of 8 cubic elements along +X, clamped at the root, with inertia.
test::Cantilever steel_cantilever() { return test::make_steel_cantilever(8); }

/// An aluminium ANCF beam of 2 elements.
core::AncfBeamParameters ancf_parameters() {
  return {.elements = 2,
          .material = {.young_modulus = 7e10, .poisson_ratio = 0.3, .density = 2700},
          .section = core::SectionIntegrals::circle(0.01)};
}

/// Evaluates the cantilever's first element dynamically, at zero velocity and acceleration
/// except for what `change` writes into them.
void evaluate_dynamic(const std::function<void(Eigen::VectorXd& v, Eigen::VectorXd& a)>& change) {
  test::Cantilever c = steel_cantilever();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(c.model.dof_count()), a = v;
  change(v, a);
  const core::Element& element = c.model.element(0);
  const core::ElementInput in{.q = &c.model.state(), .velocity = &v, .acceleration = &a};
  const core::ElementRequest request{.residual = true, .mass = true};
  core::ElementOutput out;
  out.reset(core::frame_dofs * static_cast<int>(element.blocks().size()), request);
  element.evaluate(in, request, out);
}

}  // namespace

TEST_CASE("every bad API input of issue 29's audit ends in a spar::Error naming it", "[input]") {
  const std::vector<test::ErrorCase> cases = {
      {"Model::element(99) of an 8-element model, then evaluate (SIGSEGV)",
       [] {
         test::Cantilever c = steel_cantilever();
         core::ElementOutput out;
         c.model.element(99).evaluate({.q = &c.model.state()}, {}, out);
       },
       "element 99 does not exist (the model has 8 elements)"},
      {"Model::element(-1) (SIGSEGV)", [] { test::Cantilever c = steel_cantilever(); c.model.element(-1).name(); }, "element -1 does not exist"},
      {"Element::evaluate into a default ElementOutput (SIGSEGV)",
       [] {
         test::Cantilever c = steel_cantilever();
         core::ElementOutput out;
         c.model.element(0).evaluate({.q = &c.model.state()}, {.stiffness = true}, out);
       },
       "the output holds a residual of 0 entries for the element's 24 dofs"},
      {"Element::evaluate into an output without the requested stiffness",
       [] {
         test::Cantilever c = steel_cantilever();
         core::ElementOutput out;
         out.reset(24, {});
         c.model.element(0).evaluate({.q = &c.model.state()}, {.stiffness = true}, out);
       },
       "a stiffness of 0x0"},
      {"Element::evaluate with a NaN velocity (12 of 24 residual entries NaN)",
       [] { evaluate_dynamic([](Eigen::VectorXd& v, Eigen::VectorXd&) { v(7) = not_a_number; }); },
       "the velocity has a non-finite entry (nan) at dof 7"},
      {"Element::evaluate with an infinite acceleration",
       [] { evaluate_dynamic([](Eigen::VectorXd&, Eigen::VectorXd& a) { a(9) = std::numeric_limits<double>::infinity(); }); },
       "the acceleration has a non-finite entry (inf) at dof 9"},
      {"Model::replace_state with an empty state, then solve_static (SIGSEGV)",
       [] {
         test::Cantilever c = steel_cantilever();
         c.model.replace_state(core::Configuration{});
         solvers::solve_static(c.model);
       },
       "acts on block 0, which the configuration (0 blocks) does not have"},
      {"Model::replace_state with an empty state, then a GeneralizedAlpha",
       [] {
         test::Cantilever c = steel_cantilever();
         c.model.replace_state(core::Configuration{});
         solvers::GeneralizedAlpha(c.model, {}, {});
       },
       "solvers::GeneralizedAlpha: element 0 (beam 0, element 0) acts on block 0"},
      {"R = 2I written into model.state(), then solve_static (solved)",
       [] {
         test::Cantilever c = steel_cantilever();
         c.model.state().rotation[c.tip] = 2.0 * Eigen::Matrix3d::Identity();
         solvers::solve_static(c.model);
       },
       "the rotation of block 10 is not a rotation: |R^T R - I| = 5.19615"},
      {"a reflection written into model.state() during a run, then a step",
       [] {
         test::Cantilever c = steel_cantilever();
         solvers::GeneralizedAlpha integrator(c.model, {}, {});
         integrator.step();
         c.model.state().rotation[c.tip] = Eigen::Vector3d(1, 1, -1).asDiagonal();
         integrator.step();
       },
       "GeneralizedAlpha::step: the rotation of block 10 is a reflection (det R = -1)"},
      {"a NaN position written into model.state(), then initialize",
       [] {
         test::Cantilever c = steel_cantilever();
         solvers::GeneralizedAlpha integrator(c.model, {}, {});
         c.model.state().position[c.tip].y() = not_a_number;
         integrator.initialize();
       },
       "GeneralizedAlpha::initialize: the position of block 10 has a NaN or infinite entry"},
      {"a fixed dof outside a replaced configuration, then solve_static",
       [] {
         core::Model model;
         model.add_vector(Eigen::VectorXd::Zero(3));
         model.fix(0);
         core::Configuration smaller;
         smaller.add_vector(Eigen::VectorXd::Zero(1));
         model.replace_state(smaller);
         solvers::solve_static(model);
       },
       "fixed dof 1 is outside the configuration's 1 dofs"},
      {"ancf_node_position of block 999 (SIGSEGV)",
       [] {
         core::Model model;
         core::add_ancf_beam(model, ancf_parameters());
         core::ancf_node_position(model.state(), 999);
       },
       "block 999 is not an ANCF node"},
      {"ancf_node_position of a frame block (returned zeros)",
       [] {
         core::Model model;
         core::add_ancf_beam(model, ancf_parameters());
         core::ancf_node_position(model.state(), model.add_frame(Eigen::Vector3d::Ones(), Eigen::Matrix3d::Identity()));
       },
       "block 3 is not an ANCF node"},
      {"add_ancf_beam with a default (empty) section (accepted)",
       [] {
         core::Model model;
         auto p = ancf_parameters();
         p.section = {};
         core::add_ancf_beam(model, p);
       },
       "the section has an area of 0"},
      {"a NaN load history in statics (ignored)",
       [] {
         test::Cantilever c = steel_cantilever();
         core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, 10, 0)},
                          [](double) { return not_a_number; });
         solvers::solve_static(c.model);
       },
       "the load history gives nan at t = 0"},
  };
  test::check_error_cases(cases);
}

TEST_CASE("add_ancf_beam refuses a bad section or material before it adds a block", "[input]") {
  core::Model model;
  auto p = ancf_parameters();
  p.section = {};
  CHECK_THROWS_AS(core::add_ancf_beam(model, p), Error);
  p = ancf_parameters();
  p.material.young_modulus = -1.0;
  CHECK_THROWS_AS(core::add_ancf_beam(model, p), Error);
  CHECK(model.block_count() == 0);
  CHECK(model.element_count() == 0);
}

TEST_CASE("a static load too large for the model is refused in its words, the state restored", "[input]") {
  // Before: a tip force of 1e200 N ended in lie::exp's "the rotation vector has a NaN or infinite
  // entry" and left the tip near 1e291 m (the increment applied outside the solver's restore).
  for (const double force : {1e200, 1e250, 1e300}) {
    INFO("tip force " << force << " N");
    test::Cantilever c = steel_cantilever();
    core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, force, 0)});
    const core::Configuration initial = c.model.state();
    try {
      solvers::solve_static(c.model, {.max_cutbacks = 3});
      FAIL("the load was accepted");
    } catch (const solvers::ConvergenceError& error) {
      CHECK_THAT(error.what(), Catch::Contains("the load is too large for the model"));
      CHECK(error.last_converged_load_factor() == 0.0);
    }
    for (int b = 0; b < c.model.block_count(); ++b) {
      CHECK(c.model.state().position[b] == initial.position[b]);
      CHECK(c.model.state().rotation[b] == initial.rotation[b]);
    }
  }
}

TEST_CASE("a NaN load history in statics stops the solve at once, the state restored", "[input]") {
  // The dynamic path refuses it at its first evaluation (api_input_test.cpp); statics scales
  // the load by the load factor alone and never looked at the history.
  test::Cantilever c = steel_cantilever();
  core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, 10, 0)},
                   [](double t) { return t == 0.0 ? not_a_number : 1.0; });
  const core::Configuration initial = c.model.state();
  try {
    solvers::solve_static(c.model);
    FAIL("the NaN history was accepted");
  } catch (const InputError& error) {
    CHECK_THAT(error.what(), Catch::Contains("the load history gives nan at t = 0"));
    CHECK(error.fix() == "give a history that is finite at every time of the run");
  }
  for (int b = 0; b < c.model.block_count(); ++b) CHECK(c.model.state().position[b] == initial.position[b]);
}

TEST_CASE("a static solve accepts the round-off its own rotation updates leave", "[input]") {
  // The boundary's tolerance on |R^T R - I| is lie::rotation_tolerance = 1e-9, that of add_frame:
  // a thousand times the drift of 10^7 updates R exp(dphi) of 0.01 rad (9e-13, measured; it grows
  // as the square root of the count). R (1 + e) has |R^T R - I| = 2 sqrt(3) e to first order.
  const auto solve_with_scaled_tip = [](double e) {
    test::Cantilever c = steel_cantilever();
    core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, 10, 0)});
    c.model.state().rotation[c.tip] *= 1.0 + e;
    solvers::solve_static(c.model);
  };
  CHECK_NOTHROW(solve_with_scaled_tip(1e-10));  // 3.5e-10
  CHECK_THROWS_WITH(solve_with_scaled_tip(1e-9), Catch::Contains("|R^T R - I| = 3.4641e-09 > 1e-09"));
}

TEST_CASE("GeneralizedAlpha: step() before initialize() initializes; a second initialize() needs a step or remap",
          "[input]") {
  // step() without initialize() is the documented start (twenty test files and the examples'
  // runs rely on it): it must be the same run, bit for bit, as initialize() then step().
  const auto tip_after_steps = [](bool initialize_first) {
    test::Cantilever c = steel_cantilever();
    core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, 10, 0)});
    solvers::GeneralizedAlpha integrator(c.model, {}, {.time_step = 1e-3});
    if (initialize_first) integrator.initialize();
    for (int n = 0; n < 3; ++n) integrator.step();
    return c.model.state().position[c.tip];
  };
  CHECK(tip_after_steps(false) == tip_after_steps(true));

  // A second initialize() with no step or remap since the first restarted the method at the
  // same state, silently dropping DynamicOptions::perturbed_starting_values (a = v̇ again).
  test::Cantilever c = steel_cantilever();
  solvers::GeneralizedAlpha integrator(c.model, {}, {.time_step = 1e-3, .perturbed_starting_values = true});
  integrator.initialize();
  CHECK_THROWS_WITH(integrator.initialize(),
                    Catch::Contains("initialize() was already called at t = 0, and no step or remap followed"));
  integrator.step();
  CHECK_NOTHROW(integrator.initialize());  // a restart during a run (heavy_top_test.cpp)
}
