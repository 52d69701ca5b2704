// The installed derivative checker of constraints (joints/check_constraint.hpp), checked itself: it
// passes a correct joint with frames at large rotations and time dependence, and finds an error of
// 1e-4 put into one entry of B, K_λ, c or Φ_t — in that comparison alone, at that entry; it
// describes what it found and refuses a state or options it cannot use.
#include <spar/error.hpp>
#include <spar/joints/check_constraint.hpp>
#include <spar/joints/position_driver.hpp>
#include <spar/joints/revolute_joint.hpp>
#include <spar/joints/spherical_joint.hpp>

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "constraint_checks.hpp"

using namespace spar;

namespace {

enum class Output { jacobian, multiplier_tangent, acceleration_terms, time_derivative };

/// A joint that is `joint` with `error` added to one entry of one derivative.
class Tampered final : public joints::Constraint {
public:
  Tampered(const joints::Constraint& joint, Output output, Eigen::Index row, Eigen::Index column, double error)
      : joint_(joint), output_(output), row_(row), column_(column), error_(error) {}
  int equation_count() const override { return joint_.equation_count(); }
  const std::vector<int>& blocks() const override { return joint_.blocks(); }

private:
  void compute_value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const override {
    joint_.value(q, t, phi);
  }
  void compute_jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const override {
    joint_.jacobian(q, t, B);
    if (output_ == Output::jacobian) B(row_, column_) += error_;
  }
  void compute_multiplier_tangent(const core::Configuration& q, double t, const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override {
    joint_.multiplier_tangent(q, t, lambda, K);
    if (output_ == Output::multiplier_tangent) K(row_, column_) += error_;
  }
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override {
    joint_.acceleration_terms(q, velocity, t, c);
    if (output_ == Output::acceleration_terms) c(row_) += error_;
  }
  void compute_time_derivative(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi_t) const override {
    joint_.time_derivative(q, t, phi_t);
    if (output_ == Output::time_derivative) phi_t(row_) += error_;
  }

  const joints::Constraint& joint_;
  Output output_;
  Eigen::Index row_, column_;
  double error_;
};

/// A state with random velocities, accelerations (every block moving) and multipliers.
joints::ConstraintCheckState random_state(const joints::Constraint& joint, const core::Configuration& q, double t,
                                          test::RandomRotations& random) {
  const auto draw = [&](Eigen::Index size) {
    return Eigen::VectorXd(Eigen::VectorXd::NullaryExpr(size, [&] { return random.uniform(-1, 1); }));
  };
  return {.q = q, .time = t, .velocity = draw(q.dof_count()), .acceleration = draw(q.dof_count()),
          .multipliers = draw(joint.equation_count())};
}

}  // namespace

TEST_CASE("check_constraint finds a wrong entry of B, K_lambda, c or Phi_t, and only there", "[joints]") {
  test::RandomRotations random(621);
  const core::Configuration q = test::random_configuration(3, random);
  // A hinge between two frames (5 equations, 12 columns) and a driver with f(t) = 0.3 t + 0.2 t².
  const joints::RevoluteJoint hinge(joints::Attachment{.node = 0, .offset = Eigen::Vector3d(0.3, -0.1, 0.2)},
                                    joints::Attachment{.node = 2}, Eigen::Vector3d(0.2, 1.0, -0.4), q);
  const joints::PositionDriver driver(joints::Attachment{.node = 1, .offset = Eigen::Vector3d(0.5, 0.1, 0.0)},
                                      Eigen::Vector3d(1.0, 2.0, 0.5), joints::TimeFunction::polynomial({0.0, 0.3, 0.2}),
                                      q);
  const double t = 0.7;
  for (const joints::Constraint* joint : std::vector<const joints::Constraint*>{&hinge, &driver}) {
    const joints::ConstraintCheckState state = random_state(*joint, q, t, random);
    const core::DerivativeCheck correct = joints::check_constraint(*joint, state);
    INFO(correct.description());
    CHECK(correct.passed());
    REQUIRE(correct.comparisons.size() == 4);
    // An error of 1e-4 is 1e3 times the tolerance 1e-7 (and 50 times 2e-6 for c) for entries of
    // size ≲ 1, and 1e3 times the round-off of the differences. Without acceleration, so that the
    // comparison of B a + c does not see an error of B.
    joints::ConstraintCheckState still = state;
    still.acceleration.setZero();
    const Eigen::Index last_row = joint->equation_count() - 1, last_column = 5;
    struct Wrong {
      Output output;
      std::size_t comparison;  ///< B, K_λ, B a + c, Φ_t
      Eigen::Index row, column;
    };
    for (const Wrong& wrong : {Wrong{Output::jacobian, 0, last_row, last_column},
                               Wrong{Output::multiplier_tangent, 1, 4, last_column},
                               Wrong{Output::acceleration_terms, 2, last_row, 0},
                               Wrong{Output::time_derivative, 3, last_row, 0}}) {
      const Tampered tampered(*joint, wrong.output, wrong.row, wrong.column, 1e-4);
      const core::DerivativeCheck check = joints::check_constraint(tampered, still);
      INFO(check.description());
      CHECK_FALSE(check.passed());
      for (std::size_t k = 0; k < check.comparisons.size(); ++k) {
        const core::DerivativeComparison& c = check.comparisons[k];
        CHECK(c.passed() == (k != wrong.comparison));
        if (k != wrong.comparison) continue;
        CHECK(c.row == wrong.row);
        CHECK(c.column == wrong.column);
        CHECK(c.analytic - c.finite_difference == Approx(1e-4).epsilon(1e-3));
        CHECK(c.error == Approx(1e-4 / c.scale).epsilon(1e-3));
        CHECK(&check.worst() == &c);
      }
      CHECK_THAT(check.description(), Catch::Contains("Tampered") && Catch::Contains("FAILED") &&
                                          Catch::Contains(check.comparisons[wrong.comparison].name));
    }
  }
}

TEST_CASE("check_constraint refuses states and options it cannot use", "[joints][errors]") {
  test::RandomRotations random(622);
  const core::Configuration q = test::random_configuration(2, random);
  const joints::SphericalJoint joint(joints::Attachment{.node = 1}, joints::Attachment{.node = 0}, q);
  const joints::ConstraintCheckState state = random_state(joint, q, 0.0, random);
  joints::ConstraintCheckState short_velocity = state, long_multipliers = state;
  short_velocity.velocity.conservativeResize(6);
  long_multipliers.multipliers.conservativeResize(4);
  CHECK_THROWS_AS(joints::check_constraint(joint, short_velocity), InputError);
  CHECK_THROWS_WITH(joints::check_constraint(joint, short_velocity),
                    Catch::Contains("joints::check_constraint: the velocity has 6 and the acceleration 12 entries, "
                                    "the configuration 12 dofs"));
  CHECK_THROWS_WITH(joints::check_constraint(joint, long_multipliers),
                    Catch::Contains("the multipliers have 4 entries, the constraint 3 equations"));
  CHECK_THROWS_WITH(joints::check_constraint(joint, state, {.step = 0.0}), Catch::Contains("a step is 0"));
  CHECK_THROWS_WITH(joints::check_constraint(joint, state, {.tolerance = -1.0}),
                    Catch::Contains("a tolerance or the scale floor is -1"));
  // What the constraint itself refuses, it refuses here too: a configuration without its node 1.
  joints::ConstraintCheckState one_node = state;
  one_node.q = test::random_configuration(1, random);
  one_node.velocity.conservativeResize(6);
  one_node.acceleration.conservativeResize(6);
  CHECK_THROWS_WITH(joints::check_constraint(joint, one_node), Catch::Contains("acts on block 1"));
}
