// ActiveUntil (docs/joints.md §3.3): the wrapped constraint equation for equation while active;
// after the release no equations and no blocks, reported once as an event naming it.
#include <spar/error.hpp>
#include <spar/joints/active_until.hpp>
#include <spar/joints/angle_driver.hpp>

#include <catch2/catch.hpp>

#include <memory>

using namespace spar;

namespace {

core::Configuration one_frame() {
  core::Configuration q;
  q.add_frame(Eigen::Vector3d(1, 2, 3), Eigen::Matrix3d::Identity());
  return q;
}

}  // namespace

TEST_CASE("ActiveUntil: the wrapped driver until the condition, then nothing", "[joints][drivers]") {
  core::Configuration q = one_frame();
  const auto angle = joints::TimeFunction::polynomial({0.0, 0.7, -0.4});
  joints::AngleDriver reference(0, Eigen::Vector3d::UnitZ(), angle, q);
  bool release = false;
  joints::ActiveUntil driver(std::make_unique<joints::AngleDriver>(0, Eigen::Vector3d::UnitZ(), angle, q),
                             [&release](const core::Configuration&, double) { return release; }, "hold");
  q.apply_increment((Eigen::VectorXd(6) << 0.1, 0, 0, 0.2, -0.1, 0.3).finished());
  const Eigen::VectorXd v = (Eigen::VectorXd(6) << 0, 0, 0, 0.5, 0.1, -2.0).finished();
  const double t = 0.4;
  // Active: equal to the wrapped driver in every evaluation (the same code runs: bitwise).
  REQUIRE(driver.equation_count() == 1);
  CHECK(driver.blocks() == reference.blocks());
  Eigen::VectorXd phi(1), phi_ref(1), c(1), c_ref(1), phi_t(1), phi_t_ref(1);
  Eigen::MatrixXd B(1, 6), B_ref(1, 6), K(6, 6), K_ref(6, 6);
  driver.value(q, t, phi);
  reference.value(q, t, phi_ref);
  driver.jacobian(q, t, B);
  reference.jacobian(q, t, B_ref);
  driver.multiplier_tangent(q, t, Eigen::VectorXd::Constant(1, 3.0), K);
  reference.multiplier_tangent(q, t, Eigen::VectorXd::Constant(1, 3.0), K_ref);
  driver.acceleration_terms(q, v, t, c);
  reference.acceleration_terms(q, v, t, c_ref);
  driver.time_derivative(q, t, phi_t);
  reference.time_derivative(q, t, phi_t_ref);
  CHECK(phi == phi_ref);
  CHECK(B == B_ref);
  CHECK(K == K_ref);
  CHECK(c == c_ref);
  CHECK(phi_t == phi_t_ref);
  std::string description;
  CHECK_FALSE(driver.update_structure(q, v, t, description));
  CHECK(driver.active());
  // Released: an event, once, naming the constraint and the time; then no equations, no blocks.
  release = true;
  CHECK(driver.update_structure(q, v, 1.25, description));
  CHECK(description == "'hold' released at t = 1.25");
  CHECK_FALSE(driver.active());
  CHECK(driver.release_time() == 1.25);
  CHECK(driver.equation_count() == 0);
  CHECK(driver.blocks().empty());
  description.clear();
  CHECK_FALSE(driver.update_structure(q, v, 1.5, description));
  CHECK(description.empty());
}

TEST_CASE("ActiveUntil: an empty constraint or condition is refused", "[joints][drivers][errors]") {
  const core::Configuration q = one_frame();
  CHECK_THROWS_WITH(joints::ActiveUntil(nullptr, [](const core::Configuration&, double) { return true; }, "x"),
                    Catch::Contains("no constraint to wrap"));
  CHECK_THROWS_WITH(joints::ActiveUntil(std::make_unique<joints::AngleDriver>(0, Eigen::Vector3d::UnitZ(),
                                                                              joints::TimeFunction::constant(0.0), q),
                                        nullptr, "x"),
                    Catch::Contains("no release condition"));
}
