// The initial assembly of GeneralizedAlpha (docs/dynamics.md D6a) on a rigid pendulum: a body of
// mass m and inertia J about its centre of mass C, hinged about Z to the ground at a distance L
// from C. Perturbed positions move back onto the joint by the least change in the metric of M
// (checked against the closed-form least change), a perturbation beyond the tolerance is refused
// with the state left as given, and a driver started from rest gets the rigid velocities.
#include <spar/error.hpp>
#include <spar/joints/angle_driver.hpp>
#include <spar/joints/revolute_joint.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace spar;

namespace {

constexpr double mass = 2.0, inertia_z = 0.05, arm = 0.5;  // kg, kg m², m (C at (L, 0, 0))

struct Pendulum {
  core::Model model;
  solvers::ConstraintList joints;
  int body = 0;
};

/// The pendulum at rest along X, hinged at the origin; with `drive_rate` ≠ 0 an angle driver turns
/// the body about Z at that rate (rad/s) from its angle at t = 0.
Pendulum pendulum(double drive_rate = 0.0) {
  Pendulum p;
  p.body = core::rigid_body(p.model, core::add_rigid_body(p.model,
      {.center_of_mass = Eigen::Vector3d(arm, 0, 0), .mass = mass,
       .inertia = Eigen::Vector3d(0.04, 0.03, inertia_z).asDiagonal()})).node;
  p.model.set_gravity(Eigen::Vector3d(0, -9.81, 0));
  p.joints.push_back(std::make_unique<joints::RevoluteJoint>(
      joints::attach_at(p.body, Eigen::Vector3d::Zero(), p.model.state()), joints::Attachment{-1},
      Eigen::Vector3d::UnitZ(), p.model.state()));
  if (drive_rate != 0.0)
    p.joints.push_back(std::make_unique<joints::AngleDriver>(
        p.body, Eigen::Vector3d::UnitZ(), joints::TimeFunction::linear(drive_rate), p.model.state()));
  return p;
}

solvers::DynamicOptions options(double assembly_tolerance = 1e-3) {
  return {.time_step = 1e-3, .constraint_tolerance = 1e-12, .initial_assembly_tolerance = assembly_tolerance};
}

}  // namespace

TEST_CASE("initial assembly: a body off its hinge along the axis moves back by exactly that", "[dynamics]") {
  // The hinge's axis rows lock the rotations about X and Y, so only a translation along Z closes
  // a gap along Z: the constraint is linear in it and one Gauss–Newton iteration lands exactly.
  Pendulum p = pendulum();
  const double gap = 2e-3;  // m
  p.model.state().position[p.body].z() += gap;
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), options(1e-2));
  integrator.initialize();
  const solvers::InitialAssembly& report = integrator.initial_assembly();
  CHECK(report.performed);
  CHECK(report.constraint_residual == Approx(gap).epsilon(1e-14));
  CHECK(report.position_iterations == 1);
  CHECK(report.largest_position_change_block == p.body);
  CHECK(report.largest_position_change == Approx(gap).epsilon(1e-12));
  CHECK(report.position_change(6 * p.body + 2) == Approx(-gap).epsilon(1e-12));
  CHECK(integrator.constraint_residual() <= 1e-15);
  CHECK(p.model.state().position[p.body].z() == Approx(0.0).margin(1e-15));
}

TEST_CASE("initial assembly: an in-plane gap is closed by the least change in the metric of M",
          "[dynamics][validation]") {
  // The body's hinge point is δ off along Y. Closing it by a translation a (along Y) and a turn θ
  // about Z with a − Lθ = −δ, the least m a² + J θ² is a = −δ J/(J + m L²), θ = δ m L/(J + m L²).
  // The hinge is nonlinear in θ (its point moves by L(1 − cos θ) along X, and the turn changes
  // the arm), which moves the exact least change off the linear one by O(L θ²) = 2e-10 m for
  // δ = 1e-5 m: hence the margin 1e-9 (1e-4 of δ). The Euclidean metric would give
  // a = −δ/(1 + L²) = −0.8 δ against −0.091 δ here.
  Pendulum p = pendulum();
  const double delta = 1e-5;
  p.model.state().position[p.body].y() += delta;
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), options());
  integrator.initialize();
  const solvers::InitialAssembly& report = integrator.initial_assembly();
  const double denominator = inertia_z + mass * arm * arm;
  INFO("translation " << report.position_change(1) << " m, turn " << report.position_change(5) << " rad");
  CHECK(report.position_change(1) == Approx(-delta * inertia_z / denominator).margin(1e-9));
  CHECK(report.position_change(5) == Approx(delta * mass * arm / denominator).margin(1e-9 / arm));
  CHECK(integrator.constraint_residual() <= 1e-12);
}

TEST_CASE("initial assembly: a gap beyond the tolerance is an error that leaves the state as given", "[dynamics]") {
  Pendulum p = pendulum();
  p.model.state().position[p.body].z() += 2e-3;  // 2 mm against the default 1 mm
  const core::Configuration given = p.model.state();
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), options());
  CHECK_THROWS_AS(integrator.initialize(), Error);
  CHECK(p.model.state().position[p.body] == given.position[p.body]);
  CHECK(p.model.state().rotation[p.body] == given.rotation[p.body]);
}

TEST_CASE("initial assembly: switched off, the state is taken as given", "[dynamics]") {
  Pendulum p = pendulum();
  p.model.state().position[p.body].z() += 2e-3;
  solvers::DynamicOptions off = options();
  off.initial_assembly = false;
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), off);
  integrator.initialize();
  CHECK_FALSE(integrator.initial_assembly().performed);
  CHECK(p.model.state().position[p.body].z() == 2e-3);
}

TEST_CASE("initial assembly: a consistent start is left bit for bit", "[dynamics]") {
  Pendulum p = pendulum();
  const core::Configuration given = p.model.state();
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), options());
  integrator.initialize();
  const solvers::InitialAssembly& report = integrator.initial_assembly();
  CHECK(report.position_iterations == 0);
  CHECK(report.largest_position_change == 0.0);
  CHECK(report.largest_velocity_change == 0.0);
  CHECK(p.model.state().position[p.body] == given.position[p.body]);
  CHECK(p.model.state().rotation[p.body] == given.rotation[p.body]);
  CHECK(integrator.velocity().isZero(0.0));
}

TEST_CASE("initial assembly: a driver started from rest gets the rigid velocities",
          "[dynamics][validation]") {
  // Hinged at the origin and driven at ω = 10 rad/s about Z, the only consistent velocity is the
  // rigid one: Ω = ω e_z (material = inertial at R = I), ẋ_C = ω e_z × (L, 0, 0) = (0, ω L, 0).
  // Round-off of the 11 × 11 solve: 1e-13 of the velocities' size.
  const double omega = 10.0;
  Pendulum p = pendulum(omega);
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), options());
  integrator.initialize();
  const Eigen::VectorXd& v = integrator.velocity();
  const double round_off = 1e-13 * omega;
  CHECK((v.segment<3>(0) - Eigen::Vector3d(0, omega * arm, 0)).norm() <= round_off);
  CHECK((v.segment<3>(3) - Eigen::Vector3d(0, 0, omega)).norm() <= round_off);
  // The velocity constraints at rest are violated by the drive's rate ω alone (a product or two of
  // O(1) numbers: 1e-15 relative), and the largest change is Ω's ω, from the solve (round-off as
  // above).
  CHECK(integrator.initial_assembly().velocity_constraint_residual == Approx(omega).epsilon(1e-15));
  CHECK(integrator.initial_assembly().largest_velocity_change == Approx(omega).epsilon(1e-13));
  CHECK(integrator.initial_assembly().position_iterations == 0);
  // The first step then follows the rigid rotation θ = ω t: the driver holds it, and the hinge
  // point stays put.
  integrator.step();
  CHECK(integrator.constraint_residual() <= 1e-12);
  CHECK((integrator.velocity().segment<3>(3) - Eigen::Vector3d(0, 0, omega)).norm() <= 1e-9);
}

TEST_CASE("initial assembly: on a rigid mechanism the metric M + tau^2 K is the mass metric", "[dynamics]") {
  // A rigid body has no elastic stiffness, and the joints' ∂(Bᵀλ)/∂Δ vanishes at the assembly's
  // λ = 0: K = 0 and τ changes nothing. The driven pendulum gets the same rigid velocities with
  // τ = 0 and τ = 1 s, to the round-off of the solve (1e-13 of the velocities' size).
  const double omega = 10.0;
  Eigen::VectorXd velocities[2];
  for (int k = 0; k < 2; ++k) {
    Pendulum p = pendulum(omega);
    solvers::DynamicOptions weighted = options();
    weighted.initial_velocity_stiffness_time = k;
    solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), weighted);
    integrator.initialize();
    velocities[k] = integrator.velocity();
  }
  CHECK((velocities[1] - velocities[0]).lpNorm<Eigen::Infinity>() <= 1e-13 * omega);
}

TEST_CASE("perturbed starting values: an auxiliary step that fails is an error naming the option", "[dynamics]") {
  // One Newton iteration does not converge the pendulum's first step under gravity (the test
  // needs an iteration after the increment): the auxiliary step of the perturbed start fails,
  // and initialize() says so.
  Pendulum p = pendulum();
  solvers::DynamicOptions perturbed = options();
  perturbed.max_iterations = 1;
  perturbed.perturbed_starting_values = true;
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), perturbed);
  CHECK_THROWS_WITH(integrator.initialize(),
                    Catch::Matchers::Contains("auxiliary step of the perturbed starting values did not converge") &&
                        Catch::Matchers::Contains("perturbed_starting_values off"));
}
