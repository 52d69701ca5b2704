// Fix::translations and Fix::rotations: the linear Timoshenko beam under a tip force with a guided
// end (rotations fixed, translations free) and with a pinned root (translations fixed, rotations
// free), against their closed forms.
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "cantilever.hpp"

using namespace spar;

namespace {

constexpr double F = 10.0, L = 1.0, EI = 1e4, GA = 4e7;

/// The angle about Z by which a node's frame has turned from the reference (the beam along X
/// starts with R = I).
double turned(const core::Configuration& q, int node) {
  return std::atan2(q.rotation[node](1, 0), q.rotation[node](0, 0));
}

}  // namespace

TEST_CASE("Fix::rotations and Fix::translations: guided and pinned ends against beam theory",
          "[statics][validation]") {
  // As for the linear cantilever: cubic elements represent the linear solution exactly (cubic
  // deflection, quadratic rotation), so the only error is geometric nonlinearity, ~0.1 (F L²/EI)²
  // = 1e-7 relative for this load: bound 1e-6. The fixed increments must not move at all.
  SECTION("clamped root, guided tip (Fix::rotations): F L^3/(12 EI) + F L/(GA)") {
    auto c = test::make_cantilever(4, 3);
    c.model.fix(c.tip, core::Fix::rotations);
    core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0.0, F, 0.0)});
    solvers::solve_static(c.model, {.load_steps = 1});
    const double reference = F * L * L * L / (12 * EI) + F * L / GA;
    const double deflection = c.model.state().position[c.tip].y();
    INFO("deflection " << deflection << ", reference " << reference);
    CHECK(std::fabs(deflection - reference) <= 1e-6 * reference);
    CHECK(c.model.state().rotation[c.tip] == Eigen::Matrix3d::Identity());
  }
  SECTION("pinned root (Fix::translations), guided tip: F L^3/(3 EI) + F L/(GA), root turned F L^2/(2 EI)") {
    // M(s) = −F s from the root, where no moment acts; the tip's reaction moment keeps it level.
    core::Model model;
    const int b = core::add_beam(model,
        {.centerline = test::straight_centerline(L, 4, 3), .stiffness = test::cantilever_stiffness()});
    const int root = core::beam(model, b).node(0), tip = core::beam(model, b).node(core::beam(model, b).control_point_count() - 1);
    model.fix(root, core::Fix::translations);
    model.fix(tip, core::Fix::rotations);
    core::add_load(model, core::NodalForce{.node = tip, .force = Eigen::Vector3d(0.0, F, 0.0)});
    solvers::solve_static(model, {.load_steps = 1});
    const double reference = F * L * L * L / (3 * EI) + F * L / GA, root_angle = F * L * L / (2 * EI);
    const double deflection = model.state().position[tip].y();
    INFO("deflection " << deflection << ", reference " << reference << "; root turned " << turned(model.state(), root)
                       << ", reference " << root_angle);
    CHECK(std::fabs(deflection - reference) <= 1e-6 * reference);
    CHECK(std::fabs(turned(model.state(), root) - root_angle) <= 1e-6 * root_angle);
    CHECK(model.state().position[root] == Eigen::Vector3d::Zero());
    CHECK(model.state().rotation[tip] == Eigen::Matrix3d::Identity());
  }
}
