// Every way a Newton iteration of the integrator and of the static solver can fail, and what
// follows: the step (load step) is cut back — halved — and succeeds, or, after the last halving,
// the solver gives up with a message that names the last failure and leaves the state of the
// step's start. The failures: a non-finite residual, iteration matrix or increment
// (non_finite_iterate.hpp), an element that cannot be evaluated (coordinate_limit.hpp), too many
// iterations, and a frame predicted to turn by π or more within a step.
#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/lie/exp.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/loads/loads.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <climits>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "coordinate_limit.hpp"
#include "non_finite_iterate.hpp"

using namespace spar;

namespace {

constexpr double anchor = 0.1;  // m: the spring's anchor, so x(t) = s (1 − cos ωt) from rest at 0

struct BreakingSpring {
  core::Model model;
  int block = 0;
  std::shared_ptr<std::atomic<int>> evaluations = std::make_shared<std::atomic<int>>(0);
};

/// A mass of 1 kg on a spring of 100 N/m (ω = 10 rad/s) anchored at 0.1 m, at rest at x = 0, whose
/// first `failures` stiffness evaluations break `part`.
std::unique_ptr<BreakingSpring> breaking_spring(test::BrokenPart part, int failures) {
  auto s = std::make_unique<BreakingSpring>();
  s->block = s->model.add_vector(Eigen::VectorXd::Zero(1));
  s->model.add_element(std::make_unique<test::NonFiniteIterate>(
      test::NonFiniteIterateParameters{.block = s->block, .anchor = anchor, .broken = part, .failures = failures},
      s->evaluations));
  return s;
}

/// Tight tolerances, so that the same step reached from two predictors agrees to round-off.
solvers::DynamicOptions options(double h, int max_cutbacks = 8) {
  return {.time_step = h, .tolerance = 1e-24, .residual_tolerance = 1e-12, .max_cutbacks = max_cutbacks};
}

/// The message of the spar::Error that `run` throws ("" if none).
template <class Run>
std::string error_message(const Run& run, std::string* where = nullptr, std::string* fix = nullptr) {
  try {
    run();
  } catch (const Error& error) {
    if (where) *where = error.where();
    if (fix) *fix = error.fix();
    return error.what();
  }
  return "";
}

const char* part_name(test::BrokenPart part) {
  switch (part) {
    case test::BrokenPart::residual: return "residual";
    case test::BrokenPart::matrix: return "iteration matrix";
    case test::BrokenPart::increment: return "increment";
  }
  return "";
}

constexpr test::BrokenPart all_parts[] = {test::BrokenPart::residual, test::BrokenPart::matrix,
                                          test::BrokenPart::increment};

}  // namespace

TEST_CASE("a step whose residual, iteration matrix or Newton increment is not finite is halved and then succeeds",
          "[model][errors]") {
  const double h = 0.05;
  auto reference = breaking_spring(test::BrokenPart::increment, 0);
  solvers::GeneralizedAlpha reference_integrator(reference->model, {}, options(h / 2));
  reference_integrator.step();
  reference_integrator.step();
  for (const test::BrokenPart part : all_parts) {
    INFO(part_name(part));
    // Two failures: the full step's first iteration from each of the two predictors.
    auto s = breaking_spring(part, 2);
    solvers::GeneralizedAlpha integrator(s->model, {}, options(h));
    REQUIRE_NOTHROW(integrator.step());
    CHECK(*s->evaluations > 2);  // the halves evaluated the sound element
    CHECK(integrator.counters().cutbacks == 1);
    CHECK(integrator.counters().steps == 2);
    CHECK(integrator.time() == h);
    // The halves are the reference's two steps of h/2: the same linear equations solved from
    // another predictor, equal to the round-off of one Newton correction of x ≈ 1e-2 m.
    const double x = integrator.configuration().vector(s->block)(0);
    CHECK(std::abs(x - reference_integrator.configuration().vector(reference->block)(0)) < 1e-15);
    CHECK(std::abs(integrator.velocity()(0) - reference_integrator.velocity()(0)) < 1e-14);
  }
}

TEST_CASE("after the last halving the integrator gives up, names the last failure and keeps the step's start",
          "[model][errors]") {
  const double h = 0.05;
  struct Case {
    std::string last_failure;
    std::function<std::unique_ptr<BreakingSpring>()> build;
    solvers::DynamicOptions options;
  };
  const auto always = [](test::BrokenPart part) {
    return [part] { return breaking_spring(part, INT_MAX); };
  };
  const auto sound = [] { return breaking_spring(test::BrokenPart::increment, 0); };
  solvers::DynamicOptions one_iteration = options(h, 3);
  one_iteration.max_iterations = 1;  // one correction cannot also confirm convergence
  const std::vector<Case> cases = {
      {"the residual is not finite", always(test::BrokenPart::residual), options(h, 3)},
      {"the iteration matrix has a NaN or infinite entry", always(test::BrokenPart::matrix), options(h, 3)},
      {"the Newton increment is not finite", always(test::BrokenPart::increment), options(h, 3)},
      {"spar: test::CoordinateLimit: coordinate 0",  // every step moves the mass towards the anchor, past 1e-9 m
       [&sound] {
         auto s = sound();
         s->model.add_element(std::make_unique<test::CoordinateLimit>(
             test::CoordinateLimitParameters{.block = s->block, .coordinate = 0, .limit = 1e-9},
             std::make_shared<std::atomic<int>>(0)));
         return s;
       },
       options(h, 3)},
      {"Newton did not converge in max_iterations", sound, one_iteration},
  };
  for (const Case& c : cases) {
    INFO(c.last_failure);
    auto s = c.build();
    solvers::GeneralizedAlpha integrator(s->model, {}, c.options);
    std::string where, fix;
    const std::string message = error_message([&] { integrator.step(); }, &where, &fix);
    CHECK_THAT(message, Catch::Contains("Newton did not converge at t = 0.00625 (step 1, h = 0.00625) after 3 "
                                        "halvings of the time step; last failure: " + c.last_failure));
    CHECK(where == "solvers::GeneralizedAlpha");
    CHECK_THAT(fix, Catch::Contains("reduce the time step, raise max_iterations"));
    // The broken element: both predictors at h, h/2, h/4 and h/8, each failing in its first
    // evaluation (the sound element counts more: the iteration limit's second evaluations, the
    // coordinate limit's first iterations from rest).
    CHECK(*s->evaluations >= 8);
    if (c.last_failure.find("finite") != std::string::npos) CHECK(*s->evaluations == 8);
    CHECK(integrator.time() == 0.0);
    CHECK(integrator.configuration().vector(s->block)(0) == 0.0);
    CHECK(integrator.counters().steps == 0);
  }
}

namespace {

/// A free rigid body, J = diag(0.04, 0.03, 0.05) kg m², turning about its principal axis Z: at a
/// steady 40 rad/s, or from rest under a moment of 40 N m (θ = ½ 800 rad/s² t²). Both motions are
/// exact in the Lie-group method: constant velocity, or constant acceleration about a fixed axis.
struct Spinner {
  core::Model model;
  int node = 0;
  Spinner() {
    node = core::rigid_body(model, core::add_rigid_body(model,
        {.mass = 2.0, .inertia = Eigen::Vector3d(0.04, 0.03, 0.05).asDiagonal()})).node;
  }
};

}  // namespace

TEST_CASE("a step that would turn a frame by pi or more is halved; with no halving left the integrator gives up",
          "[model][errors]") {
  const double h = 0.1;  // 4 rad per step: beyond the chart of exp (docs/model.md eq. M2); 2 rad per half
  {
    Spinner s;
    solvers::GeneralizedAlpha integrator(s.model, {}, options(h));
    integrator.set_velocity(s.node, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 40));
    REQUIRE_NOTHROW(integrator.step());
    CHECK(integrator.counters().rejected_rotations == 2);  // both predictors of the full step
    CHECK(integrator.counters().cutbacks == 1);
    CHECK(integrator.counters().steps == 2);
    // The steady spin is exact in the Lie-group method: R = exp(4 e_z), to the round-off of two
    // exponentials and a product (1e-15).
    const Eigen::Matrix3d exact = lie::exp(Eigen::Vector3d(0, 0, 4.0));
    CHECK((integrator.configuration().rotation[s.node] - exact).cwiseAbs().maxCoeff() < 1e-14);
  }
  {
    // From rest under 40 N m: the predictors turn the body by 2.0 rad (ρ∞ = 0.9) and 0 rad, both
    // inside the chart; Newton's first correction turns it by the step's 4 rad, which is refused.
    // The halves turn it by 1 and 3 rad.
    Spinner s;
    core::add_load(s.model, core::NodalMoment{.node = s.node, .moment = Eigen::Vector3d(0, 0, 40.0)});
    solvers::GeneralizedAlpha integrator(s.model, {}, options(h));
    REQUIRE_NOTHROW(integrator.step());
    CHECK(integrator.counters().rejected_rotations == 2);  // the first Newton iterate from each predictor
    CHECK(integrator.counters().cutbacks == 1);
    CHECK(integrator.counters().steps == 2);
    const Eigen::Matrix3d exact = lie::exp(Eigen::Vector3d(0, 0, 4.0));
    CHECK((integrator.configuration().rotation[s.node] - exact).cwiseAbs().maxCoeff() < 1e-14);
  }
  Spinner s;
  solvers::GeneralizedAlpha integrator(s.model, {}, options(h, 0));
  integrator.set_velocity(s.node, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 40));
  std::string where;
  CHECK_THAT(error_message([&] { integrator.step(); }, &where),
             Catch::Contains("Newton did not converge at t = 0.1 (step 1, h = 0.1) after 0 halvings of the time step; "
                             "last failure: a frame turned by pi or more within the step"));
  CHECK(where == "solvers::GeneralizedAlpha");
  CHECK(integrator.configuration().rotation[s.node] == Eigen::Matrix3d::Identity());
}

TEST_CASE("solve_static halves a load step whose residual, tangent or increment is not finite, then gives up",
          "[model][errors]") {
  for (const test::BrokenPart part : all_parts) {
    INFO(part_name(part));
    {
      // Two failures: the load steps to 1 and to 0.5; then 0.25, 0.5, 0.75, 1 (the increment never
      // grows back), each exact in one Newton iteration: x = λ s.
      auto s = breaking_spring(part, 2);
      const solvers::StaticReport report = solvers::solve_static(s->model, {.load_steps = 1});
      CHECK(report.cutbacks == 2);
      REQUIRE(report.steps.size() == 4);
      CHECK(report.steps.front().load_factor == 0.25);
      CHECK(s->model.state().vector(s->block)(0) == Approx(anchor).epsilon(1e-15));
    }
    auto s = breaking_spring(part, INT_MAX);
    try {
      solvers::solve_static(s->model, {.load_steps = 1, .max_cutbacks = 2});
      FAIL("solve_static converged with a broken element");
    } catch (const solvers::ConvergenceError& error) {
      CHECK_THAT(error.what(), Catch::Contains("Newton did not converge from load factor 0 to 0.25 with the load "
                                               "increment halved 2 times; the model keeps the state at the last "
                                               "converged load factor 0"));
      CHECK(error.where() == "solvers::solve_static");
      CHECK_THAT(error.fix(), Catch::Contains("use more load steps"));
      CHECK(error.last_converged_load_factor() == 0.0);
    }
    CHECK(*s->evaluations == 3);  // load factors 1, 0.5, 0.25: one broken iteration each
    CHECK(s->model.state().vector(s->block)(0) == 0.0);
  }
}
