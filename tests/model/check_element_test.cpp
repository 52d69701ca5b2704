// The installed derivative checker of elements (core/check_element.hpp), checked itself: it passes
// the GEBT beam's and the rigid body's elements — frame blocks at large rotations, dynamic, under
// gravity — and the beam's static residual as the gradient of its potential; it finds an error of
// 1e-4 put into one entry of K, C or M, in that comparison alone and at that entry; and it
// refuses options it cannot use.
#include <spar/core/check_element.hpp>
#include <spar/core/model.hpp>
#include <spar/elements/beam/beam.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/error.hpp>
#include <spar/lie/exp.hpp>

#include <catch2/catch.hpp>

#include <string>

#include "beam_fixtures.hpp"
#include "random_rotations.hpp"

using namespace spar;

namespace {

/// A beam of two quadratic elements with section inertia and a rigid body, turned and bent by up to
/// 2.5 rad, with random velocities and accelerations of size ≲ 1.
struct Bodies {
  core::Model model;
  Eigen::VectorXd velocity, acceleration;
};

Bodies bodies() {
  Bodies b;
  core::SectionInertia inertia;
  inertia.mass_per_length = 2.0;
  inertia.rotary << 0.3, 0.0, 0.0, 0.0, 0.2, -0.05, 0.0, -0.05, 0.1;
  core::add_beam(b.model, {.centerline = test::straight_centerline(1.2, 2, 2), .stiffness = test::generic_stiffness(),
                           .inertia = inertia});
  core::add_rigid_body(b.model, {.center_of_mass = Eigen::Vector3d(0.3, 0.5, -0.2), .mass = 1.5,
                                 .inertia = Eigen::Vector3d(0.4, 0.5, 0.7).asDiagonal()});
  test::RandomRotations random(631);
  core::Configuration& q = b.model.state();
  const Eigen::Matrix3d turn = lie::exp(Eigen::Vector3d(2.5 * random.axis()));
  for (int k = 0; k < q.block_count(); ++k) {
    q.position[k] = turn * q.position[k] + 0.1 * Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1),
                                                                  random.uniform(-1, 1));
    q.rotation[k] = turn * q.rotation[k] * lie::exp(Eigen::Vector3d(random.uniform(0, 0.6) * random.axis()));
  }
  const auto draw = [&] {
    return Eigen::VectorXd(Eigen::VectorXd::NullaryExpr(q.dof_count(), [&] { return random.uniform(-1, 1); }));
  };
  b.velocity = draw();
  b.acceleration = draw();
  return b;
}

enum class Matrix { stiffness, damping, mass };

/// An element that is `element` with `error` added to one entry of one matrix.
class Tampered final : public core::Element {
public:
  Tampered(const core::Element& element, Matrix matrix, Eigen::Index row, Eigen::Index column, double error)
      : element_(element), matrix_(matrix), row_(row), column_(column), error_(error) {}
  const std::vector<int>& blocks() const override { return element_.blocks(); }
  std::string name() const override { return "tampered " + element_.name(); }

private:
  void compute(const core::ElementInput& in, const core::ElementRequest& request,
               core::ElementOutput& out) const override {
    element_.evaluate(in, request, out);
    if (matrix_ == Matrix::stiffness && request.stiffness) out.stiffness(row_, column_) += error_;
    if (matrix_ == Matrix::damping && request.damping) out.damping(row_, column_) += error_;
    if (matrix_ == Matrix::mass && request.mass) out.mass(row_, column_) += error_;
  }

  const core::Element& element_;
  Matrix matrix_;
  Eigen::Index row_, column_;
  double error_;
};

const Eigen::Vector3d gravity(0.3, -9.81, 0.7);

}  // namespace

TEST_CASE("check_element passes beam and rigid-body elements with frames, dynamic and static", "[model]") {
  const Bodies b = bodies();
  const core::ElementInput dynamic{.q = &b.model.state(), .velocity = &b.velocity, .acceleration = &b.acceleration,
                                   .time = 0.0, .gravity = gravity};
  const core::ElementInput statics{.q = &b.model.state(), .gravity = gravity};
  REQUIRE(b.model.element_count() == 3);
  for (int e = 0; e < b.model.element_count(); ++e) {
    const core::Element& element = b.model.element(e);
    // The defaults: steps 1e-6, errors ≤ 1e-7 relative to max(1, |FD|) — the entries are O(1).
    const core::DerivativeCheck moving = core::check_element(element, dynamic);
    INFO(moving.description());
    CHECK(moving.passed());
    CHECK(moving.comparisons.size() == 3);
    // In statics the residual is the gradient of the strain energy and the gravity potential
    // along q ⊕ Δ (the internal force of the GEBT beam is exactly that gradient: tests/beam).
    const core::DerivativeCheck still = core::check_element(element, statics, {.potential = true});
    INFO(still.description());
    CHECK(still.passed());
    CHECK(still.comparisons.size() == 2);
  }
}

TEST_CASE("check_element finds a wrong entry of K, C or M, and only there", "[model]") {
  const Bodies b = bodies();
  const core::ElementInput in{.q = &b.model.state(), .velocity = &b.velocity, .acceleration = &b.acceleration,
                              .time = 0.0, .gravity = gravity};
  const core::Element& element = b.model.element(1);  // the beam's second element: 18 dofs
  struct Wrong {
    Matrix matrix;
    Eigen::Index row, column;
  };
  // 1e-4 is 1e3 times the tolerance for entries of size ≲ 1.
  for (const Wrong& wrong : {Wrong{Matrix::stiffness, 4, 17}, Wrong{Matrix::damping, 9, 3},
                             Wrong{Matrix::mass, 0, 11}}) {
    const Tampered tampered(element, wrong.matrix, wrong.row, wrong.column, 1e-4);
    const core::DerivativeCheck check = core::check_element(tampered, in);
    INFO(check.description());
    CHECK_FALSE(check.passed());
    const auto k = static_cast<std::size_t>(wrong.matrix);
    for (std::size_t i = 0; i < check.comparisons.size(); ++i) {
      const core::DerivativeComparison& c = check.comparisons[i];
      CHECK(c.passed() == (i != k));
      if (i != k) continue;
      CHECK(c.row == wrong.row);
      CHECK(c.column == wrong.column);
      CHECK(c.analytic - c.finite_difference == Approx(1e-4).epsilon(1e-3));
      CHECK(&check.worst() == &c);
    }
    CHECK_THAT(check.description(), Catch::Contains("tampered") && Catch::Contains("FAILED"));
  }
}

TEST_CASE("check_element refuses options it cannot use", "[model][errors]") {
  const Bodies b = bodies();
  const core::Element& element = b.model.element(0);
  const core::ElementInput dynamic{.q = &b.model.state(), .velocity = &b.velocity, .acceleration = &b.acceleration};
  CHECK_THROWS_AS(core::check_element(element, dynamic, {.potential = true}), InputError);
  CHECK_THROWS_WITH(core::check_element(element, dynamic, {.potential = true}),
                    Catch::Contains("core::check_element: a potential check of a dynamic evaluation"));
  CHECK_THROWS_WITH(core::check_element(element, dynamic, {.rate_step = -1e-6}),
                    Catch::Contains("the steps are 1e-06 and -1e-06"));
  CHECK_THROWS_WITH(core::check_element(element, dynamic, {.scale_floor = -1.0}),
                    Catch::Contains("the tolerance is 1e-07, the scale floor -1"));
  CHECK_THROWS_WITH(core::check_element(element, {}), Catch::Contains("ElementInput::q is null"));
  // What the element refuses, it refuses here too: a configuration without its blocks.
  const core::Configuration empty;
  CHECK_THROWS_WITH(core::check_element(element, {.q = &empty}), Catch::Contains("is not in the configuration"));
}
