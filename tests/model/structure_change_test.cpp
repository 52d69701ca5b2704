// Structure changes made by the user between steps (Model::replace_element, replace_state) are
// taken in before the next step, and a change of the dof layout is refused until remap(P) has
// carried the state across — with the new layout's increment units when the run uses units.
#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <memory>

#include "linear_spring.hpp"
#include "point_mass.hpp"
#include "polar_point_mass.hpp"

using namespace spar;

namespace {

/// Two masses on a spring spinning about their centre, 10 steps of 0.01 s; with `reverse`, the
/// spring is then replaced by the same spring with its ends listed the other way round (blocks
/// {b, a}: the same forces, in other local rows), and 10 more steps follow.
Eigen::VectorXd spinning_spring(bool reverse, long& pattern_builds) {
  core::Model model;
  const int a = model.add_vector(Eigen::Vector3d(0, 0, 0));
  const int b = model.add_vector(Eigen::Vector3d(1.1, 0, 0));
  model.add_element(std::make_unique<test::PointMass>(a, 1.0));
  model.add_element(std::make_unique<test::PointMass>(b, 2.0));
  const int spring = model.add_element(std::make_unique<test::LinearSpring>(
      test::LinearSpringParameters{.block_a = a, .block_b = b, .stiffness = 50.0, .rest_length = 1.0}));
  solvers::DynamicOptions options;
  options.time_step = 0.01;
  options.tolerance = 1e-24;
  options.residual_tolerance = 1e-12;
  solvers::GeneralizedAlpha integrator(model, {}, options);
  integrator.set_velocity(a, Eigen::VectorXd(Eigen::Vector3d(0, -2, 0.5)));
  integrator.set_velocity(b, Eigen::VectorXd(Eigen::Vector3d(0, 1, 0)));
  for (int n = 0; n < 10; ++n) integrator.step();
  if (reverse)
    model.replace_element(spring, std::make_unique<test::LinearSpring>(test::LinearSpringParameters{
                                      .block_a = b, .block_b = a, .stiffness = 50.0, .rest_length = 1.0}));
  for (int n = 0; n < 10; ++n) integrator.step();
  pattern_builds = integrator.counters().pattern_builds;
  return integrator.configuration().values;
}

}  // namespace

TEST_CASE("an element replaced between steps acts from the next step on", "[model]") {
  long builds = 0, reversed_builds = 0;
  const Eigen::VectorXd whole = spinning_spring(false, builds);
  const Eigen::VectorXd reversed = spinning_spring(true, reversed_builds);
  CHECK(builds == 1);
  CHECK(reversed_builds == 2);
  // The reversed spring computes d = x_a − x_b = −(x_b − x_a) exactly, so the same numbers reach
  // the same global rows: the runs agree bitwise. Stale local-to-global maps would apply the
  // spring's force on b to a for a step (an O(1) error).
  CHECK(reversed == whole);
}

namespace {

/// The polar point mass on one 2-vector block, with a point mass on a new 3-vector block added to
/// the layout (5 dofs) by replace_state after 5 steps; P = [I₂; 0] carries the state.
struct GrownModel {
  core::Model model;
  std::unique_ptr<solvers::GeneralizedAlpha> integrator;
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(5, 2);

  explicit GrownModel(const Eigen::VectorXd& units) {
    const int block = model.add_vector(Eigen::Vector2d(1.0, 0.0));
    model.add_element(std::make_unique<test::PolarPointMass>(std::vector<int>{block}, 1.3));
    solvers::DynamicOptions options;
    options.time_step = 0.01;
    options.increment_units = units;
    integrator = std::make_unique<solvers::GeneralizedAlpha>(model, solvers::ConstraintList{}, options);
    integrator->set_velocity(block, Eigen::VectorXd(Eigen::Vector2d(0.3, 1.0)));
    for (int n = 0; n < 5; ++n) integrator->step();
    core::Configuration grown;
    grown.add_vector(model.state().values);
    const int mass = grown.add_vector(Eigen::Vector3d(0, 0, 0));
    model.replace_state(std::move(grown));
    model.add_element(std::make_unique<test::PointMass>(mass, 1.0));
    P.topRows(2).setIdentity();
  }
};

}  // namespace

TEST_CASE("a new dof layout without remap is refused at the next step", "[model][errors]") {
  GrownModel grown({});
  const double t = grown.integrator->time();
  CHECK_THROWS_WITH(grown.integrator->step(), Catch::Contains("remap"));
  CHECK(grown.integrator->time() == t);
  grown.integrator->remap(grown.P);
  REQUIRE_NOTHROW(grown.integrator->step());
  CHECK(grown.integrator->velocity().size() == 5);
}

TEST_CASE("a remap of a run with increment units needs the new layout's units", "[model][errors]") {
  GrownModel grown(Eigen::Vector2d(1.0, 0.5));
  CHECK_THROWS_WITH(grown.integrator->remap(grown.P), Catch::Contains("increment_units"));
  CHECK_THROWS_WITH(grown.integrator->remap(grown.P, Eigen::VectorXd::Ones(4)), Catch::Contains("increment_units"));
  CHECK_THROWS_WITH(grown.integrator->remap(grown.P, Eigen::VectorXd::Zero(5)), Catch::Contains("increment_units"));
  // A refused remap changes nothing: the integrator still has the old layout.
  CHECK(grown.integrator->velocity().size() == 2);
  Eigen::VectorXd units(5);
  units << 1.0, 0.5, 1.0, 1.0, 1.0;
  grown.integrator->remap(grown.P, units);
  REQUIRE_NOTHROW(grown.integrator->step());
  CHECK(grown.integrator->velocity().size() == 5);
}
