// A user's own project: an element kind (SpringDamper) and a joint (DistanceJoint) written
// outside spar, in files of their own, built against the installed package (find_package(spar),
// spar::spar), checked with spar's installed derivative checkers and run in two motions whose
// answers are known. docs/model.md, "Adding an element in your own project" and "Adding a joint
// in your own project", walks through these files; tests/install builds and runs them.
//
// Sample run: ./plugin (no options). Exit 0 when every check passes, 1 otherwise.
//
// 1. The derivatives at a generic state (two frames apart, turned, moving): the spring–damper's
//    K, C and M with core::check_element, and its static residual against the gradient of its
//    strain energy; the distance joint's B, K_λ, c and Φ_t with joints::check_constraint, to a
//    ground point and between two frames.
// 2. A pendulum: a rigid body held by the distance joint at L from a ground pivot, under gravity,
//    released from rest at θ0, against the small-angle period lengthened by the amplitude.
// 3. An oscillator: a rigid body tied by the spring–damper to a fixed frame, released from rest,
//    against the damped oscillator's decay per period exp(−ζ ω_n T_d).
#include "distance_joint.hpp"
#include "spring_damper.hpp"

#include <spar/core/check_element.hpp>
#include <spar/core/model.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/joints/check_constraint.hpp>
#include <spar/lie/exp.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

using namespace spar;

namespace {

constexpr double pi = std::numbers::pi;
/// Steps per period of both motions: generalized-α's error then stays below 1e-5 (see 2 and 3).
constexpr int steps_per_period = 1000;
constexpr int periods = 3;

bool report(const core::DerivativeCheck& check) {
  std::printf("%s\n", check.description().c_str());
  return check.passed();
}

/// Prints `what` measured against `reference` and whether their relative difference is within
/// `tolerance`.
bool compare(const char* what, double measured, double reference, double tolerance) {
  const double error = std::abs(measured / reference - 1.0);
  const bool passed = error <= tolerance;
  std::printf("%s: %.9g against %.9g, relative error %.2e, tolerance %.0e: %s\n", what, measured, reference, error,
              tolerance, passed ? "passed" : "FAILED");
  return passed;
}

solvers::DynamicOptions options(double time_step) {
  // ρ∞ = 0.9 damps the index-3 multiplier's parasitic mode; the squared increment norm 1e-20
  // runs Newton to increments of 1e-10 m.
  return {.time_step = time_step, .spectral_radius = 0.9, .tolerance = 1e-20};
}

// 1. The derivatives.
bool check_derivatives() {
  core::Configuration q;
  q.add_frame(Eigen::Vector3d(0.3, -0.2, 0.4), lie::exp(Eigen::Vector3d(0.3, -0.5, 0.2)));
  q.add_frame(Eigen::Vector3d(-0.5, 0.6, 1.1), lie::exp(Eigen::Vector3d(-1.2, 0.4, 0.9)));
  Eigen::VectorXd v(12), a(12);
  v << 0.7, -1.1, 0.4, 0.9, 0.2, -0.6, -0.3, 0.5, 1.2, -0.4, 0.8, 0.1;
  a << -0.2, 0.6, 1.3, -0.8, 0.3, 0.5, 0.9, -0.7, 0.2, 0.4, -1.0, 0.6;

  const plugin::SpringDamper spring({.block_a = 0, .block_b = 1, .stiffness = 40, .damping = 3, .rest_length = 0.8});
  bool passed = report(core::check_element(spring, {.q = &q, .velocity = &v, .acceleration = &a}));
  passed &= report(core::check_element(spring, {.q = &q}, {.potential = true}));

  const plugin::DistanceJoint to_ground({.block_a = 0, .ground_point = Eigen::Vector3d(0.1, 0.2, -0.3), .length = 0.9});
  const plugin::DistanceJoint between({.block_a = 0, .block_b = 1, .length = 1.4});
  const joints::ConstraintCheckState state{
      .q = q, .velocity = v, .acceleration = a, .multipliers = Eigen::VectorXd::Constant(1, 2.5)};
  passed &= report(joints::check_constraint(to_ground, state));
  passed &= report(joints::check_constraint(between, state));
  return passed;
}

// 2. The pendulum. The joint holds the body's centre of mass (its frame block's position) and
// exerts no moment about it, so the body keeps its attitude and swings as a point mass: the
// compound pendulum's small-angle period 2π√((I/m + L²)/(g L)) with I = 0, T0 = 2π√(L/g)
// (the body's inertia does not enter). The amplitude lengthens it to T0 (1 + θ0²/16 + 11 θ0⁴/3072
// + …); against T0 (1 + θ0²/16) what is left is the θ0⁴ term, 3.6e-7, and generalized-α's
// period lengthening (ωh)²/12 ≈ 3.3e-6 at 1000 steps per period (its amplification matrix at
// ρ∞ = 0.9: 1/12 to 1.3 %): tolerance 1e-5. The amplitude's own 6.2e-4 is 60 times that.
bool pendulum() {
  constexpr double g = 9.81, length = 0.5, theta0 = 0.1;
  const double T0 = 2 * pi * std::sqrt(length / g), h = T0 / steps_per_period;
  const Eigen::Vector3d pivot(0, 0, 1);

  core::Model model;
  const int body = core::rigid_body(model, core::add_rigid_body(
      model, {.center_of_mass = pivot + length * Eigen::Vector3d(std::sin(theta0), 0, -std::cos(theta0)),
              .mass = 2.0, .inertia = Eigen::Vector3d(0.02, 0.03, 0.04).asDiagonal().toDenseMatrix()})).node;
  model.set_gravity(Eigen::Vector3d(0, 0, -g));
  solvers::ConstraintList joints;
  joints.push_back(std::make_unique<plugin::DistanceJoint>(
      plugin::DistanceJointParameters{.block_a = body, .ground_point = pivot, .length = length}));
  solvers::GeneralizedAlpha integrator(model, std::move(joints), options(h));

  // The swing angle's zero crossings, at T/4, 3T/4, …, by linear interpolation between steps.
  std::vector<double> crossings;
  double previous = theta0;
  while (crossings.size() < 2 * periods + 1 && integrator.time() < (periods + 1) * T0) {
    integrator.step();
    const Eigen::Vector3d arm = model.state().position[body] - pivot;
    const double theta = std::atan2(arm.x(), -arm.z());
    if ((theta < 0) != (previous < 0)) crossings.push_back(integrator.time() - h * theta / (theta - previous));
    previous = theta;
  }
  if (crossings.size() < 2 * periods + 1) {
    std::printf("pendulum: %zu zero crossings in %.3f s, expected %d: FAILED\n", crossings.size(), integrator.time(),
                2 * periods + 1);
    return false;
  }
  const double period = (crossings.back() - crossings.front()) / periods;
  std::printf("pendulum: period %.9g s, %.2e above the small-angle 2 pi sqrt(L/g) = %.9g s\n", period,
              period / T0 - 1, T0);
  return compare("pendulum period against T0 (1 + theta0^2/16)", period, T0 * (1 + theta0 * theta0 / 16), 1e-5);
}

// 3. The oscillator: m ü + c u̇ + k u = 0 along the spring, u = l − L0, from rest at u0. Then
// u(t) = u0 e^{−ζ ω_n t} (cos ω_d t + ζ/√(1 − ζ²) sin ω_d t), so u(n T_d)/u0 = exp(−ζ ω_n T_d)ⁿ
// exactly, at the maxima (u̇ = 0 there). Generalized-α shortens the log decrement ζ ω_n T_d
// (0.315) by (ωh)²/6 of itself (its amplification matrix at ρ∞ = 0.9), 6.6e-6 at 1000 steps per
// period, so the decay per period is off by 2.1e-6 of itself; its period error, 3.3e-6, moves
// the samples at n T_d off the maxima by 6e-5 rad of phase after three periods, which costs 2e-9:
// tolerance 1e-5. An undamped run (ζ = 0) or a damping off by 1e-4 of itself (3e-5 on the decay)
// fails it.
bool oscillator() {
  constexpr double mass = 2.0, k = 200.0, zeta = 0.05, rest_length = 0.5, u0 = 0.05;
  const double omega_n = std::sqrt(k / mass), damping = 2 * zeta * std::sqrt(k * mass);
  const double T_d = 2 * pi / (omega_n * std::sqrt(1 - zeta * zeta));

  core::Model model;
  const int anchor = model.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  model.fix(anchor);
  const int body = core::rigid_body(model, core::add_rigid_body(
      model, {.center_of_mass = Eigen::Vector3d(rest_length + u0, 0, 0), .mass = mass,
              .inertia = Eigen::Vector3d(0.02, 0.03, 0.04).asDiagonal().toDenseMatrix()})).node;
  model.add_element(std::make_unique<plugin::SpringDamper>(plugin::SpringDamperParameters{
      .block_a = body, .block_b = anchor, .stiffness = k, .damping = damping, .rest_length = rest_length}));
  solvers::GeneralizedAlpha integrator(model, {}, options(T_d / steps_per_period));

  for (int n = 0; n < periods * steps_per_period; ++n) integrator.step();
  const double u = model.state().position[body].x() - rest_length;
  const bool decay = compare("oscillator decay per period against exp(-zeta omega_n T_d)",
                             std::pow(u / u0, 1.0 / periods), std::exp(-zeta * omega_n * T_d), 1e-5);
  // The energy lost, ½ k u0² − E, is the damper's heat (it says has_dissipation): the balance books
  // it as physical dissipation, and the integrator's own share stays at its round-off-sized level.
  const solvers::Energies e = integrator.energies();
  const bool heat = compare("damper heat (physical dissipation) against the energy lost", e.physical_dissipation,
                            0.5 * k * u0 * u0 - e.total(), 1e-4);
  return decay && heat;
}

}  // namespace

int main() {
  bool passed = check_derivatives();
  passed &= pendulum();
  passed &= oscillator();
  std::printf("plugin: %s\n", passed ? "every check passed" : "a check FAILED");
  return passed ? 0 : 1;
}
