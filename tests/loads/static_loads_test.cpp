// Every load kind in statics, on the cantilever of tests/support/cantilever.hpp (L = 1 m,
// EI = 1e4 N m², EA = 1e8 N, GA = 4e7 N, clamped at the root), against an independent reference:
// Reissner's planar rod solved by shooting with RK4 (tests/support/planar_rod.hpp) for forces,
// the closed form of a pure bending moment for moments, and the distributed force ρA g for
// gravity.
#include <spar/lie/lie.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <utility>
#include <vector>

#include "cantilever.hpp"
#include "planar_rod.hpp"

using namespace spar;

namespace {

constexpr double L = 1.0, EI = 1e4;

/// The cantilever with 32 cubic elements, loaded by `add`, solved in `steps` load steps.
template <class AddLoads>
test::Cantilever solved_cantilever(AddLoads add, int steps = 10) {
  test::Cantilever c = test::make_cantilever(32, 3, L);
  add(c);
  solvers::solve_static(c.model, {.load_steps = steps});
  return c;
}

Eigen::Vector2d tip_xy(const test::Cantilever& c) { return c.model.state().position[c.tip].head<2>(); }

double tip_angle(const test::Cantilever& c) {
  const Eigen::Vector3d axis = c.model.state().rotation[c.tip].col(0);
  return std::atan2(axis.y(), axis.x());
}

// Discretization error of 32 cubic elements on these smooth large-deflection solutions: the
// interpolation error of the positions reaches the rotations through the shear strain (see
// tests/beam/distributed_moment_test.cpp); measured at the tip: 2e-10 (tip moment, an exact arc
// apart from that), 1.6e-8 (tip force), 5.6e-8 (distributed moment), 6.2e-8 (distributed force).
// 2e-7 L is three times the worst of them, for the Newton tolerance (residual 1e-9 relative).
constexpr double mesh_tolerance = 2e-7;

}  // namespace

TEST_CASE("the shooting reference reproduces the inextensible elastica", "[loads][validation]") {
  // The inextensible elastica under a transverse tip force F L²/EI = 3 (Mattiasson 1981, Table 1:
  // horizontal displacement 0.2544 L, vertical 0.6033 L) ends at x/L = 0.7456, y/L = 0.6033;
  // 5e-5 is half the last tabulated digit. Axial and shear stiffnesses 1e8 times EI make the rod
  // inextensible and unshearable to ~1e-8.
  const test::PlanarRodTip tip = test::solve_planar_rod(
      {.length = L, .EA = 1e12, .GA = 1e12, .EI = EI, .tip_force = Eigen::Vector2d(0, 3 * EI)});
  INFO("elastica tip " << tip.position.transpose());
  REQUIRE(tip.moment_mismatch <= 1e-9 * EI / L);
  CHECK(std::fabs(tip.position.x() - 0.7456) <= 5e-5);
  CHECK(std::fabs(tip.position.y() - 0.6033) <= 5e-5);
}

TEST_CASE("statics: a dead tip force 3EI/L^2 bends the cantilever as Reissner's rod",
          "[loads][validation]") {
  const Eigen::Vector2d F(0.0, 3 * EI / (L * L));
  const test::Cantilever c = solved_cantilever([&](test::Cantilever& c) {
    core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(F.x(), F.y(), 0.0)});
  });
  const test::PlanarRodTip reference = test::solve_planar_rod({.length = L, .tip_force = F});
  INFO("tip " << tip_xy(c).transpose() << ", reference " << reference.position.transpose());
  CHECK((tip_xy(c) - reference.position).norm() <= mesh_tolerance * L);
  CHECK(std::fabs(tip_angle(c) - reference.angle) <= mesh_tolerance);
}

TEST_CASE("statics: a dead distributed force 8EI/L^3 bends the cantilever as Reissner's rod",
          "[loads][validation]") {
  const Eigen::Vector2d f(0.0, 8 * EI / (L * L * L));
  const test::Cantilever c = solved_cantilever([&](test::Cantilever& c) {
    core::add_load(c.model, core::DistributedForce{.beam = c.beam, .force_per_length = Eigen::Vector3d(f.x(), f.y(), 0.0)});
  });
  const test::PlanarRodTip reference = test::solve_planar_rod({.length = L, .force_per_length = f});
  INFO("tip " << tip_xy(c).transpose() << ", reference " << reference.position.transpose());
  CHECK((tip_xy(c) - reference.position).norm() <= mesh_tolerance * L);
  CHECK(std::fabs(tip_angle(c) - reference.angle) <= mesh_tolerance);
}

TEST_CASE("statics: a tip moment EI/L, material or inertial, bends the cantilever into an arc",
          "[loads][validation]") {
  // Pure bending: n = 0, so no stretch or shear, κ = M/EI = 1/L everywhere; the tip reaches
  // (sin 1, 1 − cos 1) L turned by 1 rad — for a follower and a dead moment alike in the plane.
  // The shooting reference agrees to its RK4 error (1e-13).
  const test::PlanarRodTip shot = test::solve_planar_rod({.length = L, .tip_moment = EI / L});
  REQUIRE((shot.position - Eigen::Vector2d(std::sin(1.0), 1.0 - std::cos(1.0)) * L).norm() <= 1e-12);
  for (core::MomentFrame frame : {core::MomentFrame::material, core::MomentFrame::inertial}) {
    const test::Cantilever c = solved_cantilever([&](test::Cantilever& c) {
      core::add_load(c.model, core::NodalMoment{.node = c.tip, .moment = Eigen::Vector3d(0, 0, EI / L), .frame = frame});
    });
    const Eigen::Vector2d exact(std::sin(1.0) * L, (1.0 - std::cos(1.0)) * L);
    INFO((frame == core::MomentFrame::material ? "material" : "inertial") << ": tip " << tip_xy(c).transpose());
    CHECK((tip_xy(c) - exact).norm() <= mesh_tolerance * L);
    CHECK(std::fabs(tip_angle(c) - 1.0) <= mesh_tolerance);
  }
}

TEST_CASE("statics: a distributed moment 3EI/L^2 bends the cantilever as M(s) = m (L - s)",
          "[loads][validation]") {
  // n = 0 again: θ(s) = m (L s − s²/2)/EI, tip angle m L²/(2EI) = 1.5 rad; the tip position
  // ∫(cos θ, sin θ) ds comes from the shooting reference (no force: the same integral by RK4).
  const double m = 3 * EI / (L * L);
  const test::PlanarRodTip reference = test::solve_planar_rod({.length = L, .moment_per_length = m});
  REQUIRE(std::fabs(reference.angle - 1.5) <= 1e-12);
  for (core::MomentFrame frame : {core::MomentFrame::material, core::MomentFrame::inertial}) {
    const test::Cantilever c = solved_cantilever([&](test::Cantilever& c) {
      core::add_load(c.model, core::DistributedMoment{.beam = c.beam, .moment_per_length = Eigen::Vector3d(0, 0, m),
                                               .frame = frame});
    });
    INFO((frame == core::MomentFrame::material ? "material" : "inertial") << ": tip " << tip_xy(c).transpose()
                                                                          << ", reference " << reference.position.transpose());
    CHECK((tip_xy(c) - reference.position).norm() <= mesh_tolerance * L);
    CHECK(std::fabs(tip_angle(c) - 1.5) <= mesh_tolerance);
  }
}

TEST_CASE("statics: gravity sags the cantilever exactly as the distributed force rho A g",
          "[loads][validation]") {
  // g = (0, −100 · 9.81, 0) on ρA = 8EI/(L³ |g|): the weight per length is 8EI/L³ downwards. The
  // gravity element and the distributed-force element integrate the same ∫ N_I q dS, so the two
  // solutions agree to round-off (1e-14 m on O(1) coordinates after a few hundred operations).
  const Eigen::Vector3d g(0.0, -100 * 9.81, 0.0);
  const double rhoA = 8 * EI / (L * L * L * g.norm());
  const auto weighed = [&](bool by_gravity) {
    test::Cantilever c;
    core::SectionInertia inertia;
    inertia.mass_per_length = rhoA;
    inertia.rotary = Eigen::Vector3d(2e-4, 1e-4, 1e-4).asDiagonal();
    c.beam = core::add_beam(c.model, {.centerline = test::straight_centerline(L, 32, 3),
                               .stiffness = test::cantilever_stiffness(), .inertia = inertia});
    c.root = core::beam(c.model, c.beam).node(0);
    c.tip = core::beam(c.model, c.beam).node(core::beam(c.model, c.beam).control_point_count() - 1);
    c.model.fix(c.root);
    if (by_gravity)
      c.model.set_gravity(g);
    else
      core::add_load(c.model, core::DistributedForce{.beam = c.beam, .force_per_length = rhoA * g});
    solvers::solve_static(c.model, {.load_steps = 10});
    return c;
  };
  const test::Cantilever by_gravity = weighed(true), by_force = weighed(false);
  const test::PlanarRodTip reference =
      test::solve_planar_rod({.length = L, .force_per_length = rhoA * g.head<2>()});
  INFO("gravity: tip " << tip_xy(by_gravity).transpose() << ", distributed force: tip "
                       << tip_xy(by_force).transpose() << ", reference " << reference.position.transpose());
  CHECK(tip_xy(by_gravity).y() < -0.5 * L);
  CHECK((tip_xy(by_gravity) - tip_xy(by_force)).norm() <= 1e-14);
  CHECK((tip_xy(by_gravity) - reference.position).norm() <= mesh_tolerance * L);
}

TEST_CASE("statics: the tip-force cantilever converges to Reissner's rod as h^2, h^4, h^6 for p = 1, 2, 3",
          "[loads][validation]") {
  // docs/validation.md's observed h-orders 2 / 4 / 6 (the nodal superconvergence 2p), here against
  // the independent shooting reference (accurate to ~1e-13) instead of a fine mesh, on meshes
  // where the error stays far above the reference's and Newton's (1e-10 m) accuracy. The
  // observed order must be within 0.3 of 2p (a lost superconvergence gives p + 1). Measured:
  // 3.8e-4 → 9.5e-5 m (p = 1, 16 → 32 elements, order 2.00), 8.6e-3 → 5.6e-4 (p = 2, 8 → 16,
  // 3.95), 5.8e-5 → 9.8e-7 (p = 3, 8 → 16, 5.89).
  const Eigen::Vector2d F(0.0, 3 * EI / (L * L));
  const test::PlanarRodTip reference = test::solve_planar_rod({.length = L, .tip_force = F});
  for (auto [degree, coarse] : {std::pair{1, 16}, std::pair{2, 8}, std::pair{3, 8}}) {
    std::vector<double> errors;
    for (const int elements : {coarse, 2 * coarse}) {
      test::Cantilever c = test::make_cantilever(elements, degree, L);
      core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(F.x(), F.y(), 0.0)});
      solvers::solve_static(c.model, {.load_steps = 10});
      errors.push_back((tip_xy(c) - reference.position).norm());
    }
    const double order = std::log2(errors[0] / errors[1]);
    INFO("p = " << degree << ": tip error " << errors[0] << " -> " << errors[1] << " m from " << coarse << " to "
                << 2 * coarse << " elements, observed order " << order);
    CHECK(std::fabs(order - 2 * degree) <= 0.3);
  }
}

TEST_CASE("nodal moments: the load tangent is the derivative of the residual along q + Delta",
          "[loads]") {
  // r = −Rᵀ M for an inertial (dead) moment, whose material components turn with the node: its
  // stiffness K = ∂r(R exp(Δφ))/∂Δφ = −[RᵀM]× is not zero; a material (follower) moment has
  // r = −M and K = 0. Central differences of step 1e-6 on O(1) data: round-off ~1e-10, bound 1e-8
  // relative to |M| (a dropped or transposed tangent is off by O(1)).
  const Eigen::Vector3d M(0.7, -1.1, 0.4);
  for (const core::MomentFrame frame : {core::MomentFrame::inertial, core::MomentFrame::material}) {
    core::Model model;
    const Eigen::Matrix3d R = lie::exp(Eigen::Vector3d(0.4, -1.3, 2.2));
    const int node = model.add_frame(Eigen::Vector3d(0.1, 0.2, 0.3), R);
    core::add_load(model, core::NodalMoment{.node = node, .moment = M, .frame = frame});
    const core::Element& load = model.element(model.element_count() - 1);
    const core::ElementRequest request{.residual = true, .stiffness = true};
    const core::ElementInput in{.q = &model.state()};
    core::ElementOutput out;
    out.reset(6, request);
    load.evaluate(in, request, out);
    Eigen::MatrixXd fd(6, 6);
    for (int i = 0; i < 6; ++i) {
      Eigen::VectorXd column = Eigen::VectorXd::Zero(6);
      for (const double sign : {1.0, -1.0}) {
        Eigen::VectorXd delta = Eigen::VectorXd::Zero(6);
        delta(i) = sign * 1e-6;
        core::Configuration q = model.state();
        q.assign_increment(model.state(), delta);
        const core::ElementInput perturbed{.q = &q};
        core::ElementOutput o;
        o.reset(6, {.residual = true});
        load.evaluate(perturbed, {.residual = true}, o);
        column += sign * o.residual / 2e-6;
      }
      fd.col(i) = column;
    }
    INFO((frame == core::MomentFrame::inertial ? "inertial" : "material") << " moment: K\n"
         << out.stiffness << "\nfinite differences\n" << fd);
    CHECK((out.stiffness - fd).norm() <= 1e-8 * M.norm());
    if (frame == core::MomentFrame::inertial) CHECK(out.stiffness.norm() >= 0.5 * M.norm());
  }
}
