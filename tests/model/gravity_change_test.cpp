// Model::set_gravity between steps takes effect at the next step: the integrator reads the
// model's gravity at every evaluation, for the library's rigid body and for an element defined
// outside it alike.
#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>

#include <catch2/catch.hpp>

#include <memory>

#include "point_mass.hpp"

using namespace spar;

TEST_CASE("set_gravity after the integrator is built is honoured at the next step", "[model]") {
  core::Model model;
  const int body = core::add_rigid_body(model, {.center_of_mass = Eigen::Vector3d(0, 0, 1), .mass = 2.0,
                                         .inertia = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal()});
  const int bead = model.add_vector(Eigen::Vector3d(1, 0, 0));
  model.add_element(std::make_unique<test::PointMass>(bead, 0.5));
  const Eigen::Vector3d g1(0, 0, -9.81), g2(1.5, -0.5, -3.0);
  model.set_gravity(g1);
  solvers::DynamicOptions options;
  options.time_step = 1e-2;
  options.residual_tolerance = 1e-12;
  solvers::GeneralizedAlpha integrator(model, {}, options);
  const int body_dofs = integrator.configuration().blocks[core::rigid_body(model, body).node].offset;
  const int bead_dofs = integrator.configuration().blocks[bead].offset;
  // A free body's (and a free point mass's) acceleration is gravity, which the step's equations
  // M v̇ = m g at t_{n+1} give to Newton's residual tolerance (1e-12 of m g, so 1e-11 m/s²) and
  // round-off (measured 1.8e-15 m/s²); 1e-10 m/s² is far below the 7 m/s² change it detects.
  for (int n = 0; n < 5; ++n) integrator.step();
  CHECK((integrator.acceleration().segment<3>(body_dofs) - g1).norm() < 1e-10);
  CHECK((integrator.acceleration().segment<3>(bead_dofs) - g1).norm() < 1e-10);
  model.set_gravity(g2);
  integrator.step();
  CHECK((integrator.acceleration().segment<3>(body_dofs) - g2).norm() < 1e-10);
  CHECK((integrator.acceleration().segment<3>(bead_dofs) - g2).norm() < 1e-10);
  CHECK(integrator.acceleration().segment<3>(body_dofs + 3).norm() < 1e-10);  // no spin
}
