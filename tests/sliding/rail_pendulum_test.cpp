// A bead on a circular rail of a clamped rigid body under gravity (issue 30): the sliding joint
// on a rigid body's rail (core::rigid_body_rail) is a pendulum of the rail's radius. Its period
// against 2π√(R/g) for small oscillations and against the exact 4√(R/g) K(sin(θ₀/2)) released
// at 90°, K the complete elliptic integral of the first kind computed here by the
// arithmetic–geometric mean.
#include <spar/core/model.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/rigid_body/rigid_rail.hpp>
#include <spar/iga/circular_arc.hpp>
#include <spar/joints/sliding_joint.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <catch2/catch.hpp>

#include "elliptic_integral.hpp"
#include "upward_crossings.hpp"

#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <vector>

using namespace spar;

namespace {

using test::complete_elliptic_k;

constexpr double radius = 1.0, gravity = 9.81, bead_mass = 0.7;

/// The period of generalized-α (spar's parameters from ρ∞; Arnold & Brüls 2007) on the linear
/// oscillator ẍ = −ω²x with step h: 2πh over the phase of the principal eigenvalue of its
/// amplification matrix over (q, v, v̇, a):
///   q₁ = q₀ + h v₀ + h²(½ − β) a₀ + h²β a₁,   v₁ = v₀ + h(1 − γ) a₀ + hγ a₁,   v̇₁ = −ω² q₁,
///   (1 − α_m) a₁ + α_m a₀ = (1 − α_f) v̇₁ + α_f v̇₀.
double discrete_period(double rho, double omega, double h) {
  const solvers::GeneralizedAlphaParameters p = solvers::GeneralizedAlphaParameters::from_spectral_radius(rho);
  Eigen::Matrix4d next, now;  // next · (q₁, v₁, v̇₁, a₁) = now · (q₀, v₀, v̇₀, a₀)
  next << 1, 0, 0, -h * h * p.beta,
          0, 1, 0, -h * p.gamma,
          omega * omega, 0, 1, 0,
          0, 0, -(1 - p.alpha_f), 1 - p.alpha_m;
  now << 1, h, 0, h * h * (0.5 - p.beta),
         0, 1, 0, h * (1 - p.gamma),
         0, 0, 0, 0,
         0, 0, p.alpha_f, -p.alpha_m;
  const Eigen::Matrix4d amplification = next.partialPivLu().solve(now);
  double phase = 0.0;  // the principal pair e^{±iω̄h}: the eigenvalues of largest modulus
  const Eigen::EigenSolver<Eigen::Matrix4d> eigen(amplification);
  double largest = 0.0;
  for (int k = 0; k < 4; ++k)
    if (std::abs(eigen.eigenvalues()(k)) > largest) {
      largest = std::abs(eigen.eigenvalues()(k));
      phase = std::abs(std::arg(eigen.eigenvalues()(k)));
    }
  return 2 * std::numbers::pi * h / phase;
}


struct RailRun {
  double amplitude = 0.0;  ///< θ₀, the bead's angle from the lowest point at release (rad)
  double period = 0.0;     ///< mean period from the upward crossings of the lowest point (s)
  double constraint = 0.0; ///< largest ‖Φ‖ after a step (m)
};

/// The bead released at rest at the rail point nearest to the angle `angle` from the lowest point,
/// integrated over `periods` periods of the small oscillations with step h.
RailRun release_bead(double angle, double h, double periods) {
  core::Model model;
  // The rail: the circle of radius R about the body's centre of mass in its X–Z plane, angles
  // measured from the lowest point (−Z) towards +X, from −135° to +135° (three exact rational
  // quarter pieces; the lowest point is the middle of the middle one). The body is clamped.
  const int body = core::add_rigid_body(model, {.mass = 1.0, .inertia = Eigen::Matrix3d::Identity()});
  model.fix(core::rigid_body(model, body).node);
  const iga::NurbsCurve<3> circle = iga::circular_arc<3>({.x_axis = -Eigen::Vector3d::UnitZ(),
                                                          .y_axis = Eigen::Vector3d::UnitX(), .radius = radius,
                                                          .start_angle = -0.75 * std::numbers::pi,
                                                          .sweep = 1.5 * std::numbers::pi});
  const std::shared_ptr<const core::Curve> rail = core::rigid_body_rail(model, body, circle);
  const int bead = core::rigid_body(model, core::add_rigid_body(model, {.mass = bead_mass,
                                                                        .inertia = 1e-3 * Eigen::Matrix3d::Identity()}))
                       .node;
  model.set_gravity(Eigen::Vector3d(0, 0, -gravity));
  // ζ₀ from the curve parameter of the point at `angle` (the knot range is [0, 1], ζ = u L₀).
  const double u0 = circle.closest_point(radius * Eigen::Vector3d(std::sin(angle), 0, -std::cos(angle)), 0.5);
  auto joint = std::make_unique<joints::SlidingJoint>(
      joints::SlidingJointParameters{.slider = {.node = bead}, .carrier = rail, .zeta = u0 * rail->length(),
                                     .name = "bead"},
      model);
  model.state().position[bead] = joint->carrier_point(model.state());
  RailRun run;
  const Eigen::Vector3d x0 = model.state().position[bead];
  run.amplitude = std::atan2(x0.x(), -x0.z());
  solvers::ConstraintList constraints;
  constraints.push_back(std::move(joint));
  // ρ∞ = 0.9: index 3 with ρ∞ = 1 leaves the multipliers' parasitic mode undamped (Arnold & Brüls
  // 2007); 0.9 damps it and keeps the method second order. Newton to round-off, so that the
  // errors measured are the integrator's.
  solvers::GeneralizedAlpha integrator(model, std::move(constraints),
                                       {.time_step = h, .spectral_radius = 0.9, .tolerance = 1e-24,
                                        .constraint_tolerance = 1e-13, .residual_tolerance = 1e-12});
  integrator.initialize();
  const int offset = model.state().blocks[bead].offset;
  const int steps = static_cast<int>(std::lround(periods * 2 * std::numbers::pi * std::sqrt(radius / gravity) / h)) + 1;
  test::UpwardCrossings crossings;
  double x_prev = x0.x(), v_prev = 0.0;
  for (int n = 0; n < steps; ++n) {
    const double t_prev = integrator.time();
    integrator.step();
    const double x = integrator.configuration().position[bead].x(), v = integrator.velocity()(offset);
    run.constraint = std::max(run.constraint, integrator.constraint_residual());
    crossings.add_step(t_prev, h, x_prev, v_prev, x, v);
    x_prev = x;
    v_prev = v;
  }
  REQUIRE(crossings.count() >= 2);
  run.period = crossings.period();
  return run;
}

}  // namespace

TEST_CASE("a bead on a clamped body's circular rail: the small oscillations' period 2 pi sqrt(R/g)",
          "[sliding][validation]") {
  const double omega = std::sqrt(gravity / radius), linear_period = 2 * std::numbers::pi / omega;
  // θ₀ = 1e-4: the exact period exceeds 2π√(R/g) by θ₀²/16 of it, 1.3e-9 s.
  const double angle = 1e-4;
  for (const double h : {4e-3, 2e-3, 1e-3}) {
    const RailRun run = release_bead(angle, h, 4.0);
    REQUIRE(std::abs(run.amplitude - angle) <= 1e-12);
    // The tolerance from the time step: generalized-α's period on ẍ = −ω²x is the discrete one of
    // its amplification matrix, T₀(1 + c (ωh)² + O(h⁴)), c = 0.0844 at ρ∞ = 0.9 (discrete_period).
    // What may remain is the amplitude's θ₀²/16 T₀ (1.3e-9 s), the crossings' Hermite
    // interpolation, O(h⁴) ≈ (ωh)⁴ T₀ ≲ 5e-9 s at h = 4 ms, and Newton's 1e-13 m over the bead's
    // speed ωRθ₀ = 3e-4 m/s (3e-10 s): 1e-8 s, against period errors c (ωh)² T₀ = 2.7e-5 …
    // 1.7e-6 s that it must reproduce.
    INFO("h = " << h << ": period " << run.period << " s, 2 pi sqrt(R/g) " << linear_period << " s");
    CHECK(std::abs(run.period - discrete_period(0.9, omega, h)) <= 1e-8);
    CHECK(std::abs(run.period - linear_period) <= 0.1 * (omega * h) * (omega * h) * linear_period);
    // Index 3: the constraint holds at every step to Newton's tolerance.
    CHECK(run.constraint <= 1e-10);
  }
}

TEST_CASE("a bead on a clamped body's circular rail released at 90 degrees: the exact pendulum period",
          "[sliding][validation]") {
  // The quadrature first: K(1/√2) = 1.854074677301372 (Abramowitz & Stegun, table 17.1, m = 1/2).
  CHECK(complete_elliptic_k(std::sqrt(0.5)) == Approx(1.854074677301372).epsilon(1e-15));
  const double angle = std::numbers::pi / 2;
  const RailRun r1 = release_bead(angle, 4e-3, 4.0);
  const RailRun r2 = release_bead(angle, 2e-3, 4.0);
  const RailRun r3 = release_bead(angle, 1e-3, 4.0);
  // The release point is on the rail to the closest-point search's 1e-12 rad.
  REQUIRE(std::abs(r1.amplitude - angle) <= 1e-9);
  const double exact = 4 * std::sqrt(radius / gravity) * complete_elliptic_k(std::sin(r1.amplitude / 2));
  const double e1 = r1.period - exact, e2 = r2.period - exact, e3 = r3.period - exact;
  // The integrator's phase error is O(h²) as above (ratios 4 ± 0.1), and the Richardson
  // extrapolation meets the exact period to its O(h⁴) remainder and the interpolation's: 1e-8 s,
  // 400 times below the h² error it removes. The bead crosses the rail's knots at ±45° on every
  // swing: the rational pieces meet with C¹ parameterization, x_ζζ jumps there, which the joint
  // evaluates in the element holding ζ without loss of order.
  CHECK(e1 / e2 == Approx(4.0).margin(0.1));
  CHECK(e2 / e3 == Approx(4.0).margin(0.1));
  CHECK(std::abs((4 * r3.period - r2.period) / 3 - exact) <= 1e-8);
  for (const RailRun& r : {r1, r2, r3}) CHECK(r.constraint <= 1e-10);
}
