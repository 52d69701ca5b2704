// What a dynamic run says when a model cannot move: a beam without section inertia (issue 14: the
// message was "iteration matrix is singular" without naming the beam).
#include <spar/error.hpp>
#include <spar/iga/straight_line.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <string>

using namespace spar;

TEST_CASE("dynamics: a beam without section inertia is named", "[dynamics]") {
  core::Model model;
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection section = core::CrossSection::rectangle(0.01, 0.01, steel.poisson_ratio);
  core::add_beam(model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 2, 2),
                  .stiffness = core::SectionStiffness::from(steel, section)});  // no .inertia
  model.fix(core::beam(model, 0).node(0), core::Fix::all);
  model.set_gravity(Eigen::Vector3d(0, 0, -9.81));
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = 1e-3});
  std::string message;
  try {
    integrator.step();
  } catch (const Error& error) {
    message = error.what();
  }
  INFO(message);
  CHECK(message.find("beam 0 has no section inertia") != std::string::npos);
  CHECK(message.find("SectionInertia::from") != std::string::npos);
}
