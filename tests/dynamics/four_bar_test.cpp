// The flexible four-bar of examples/four_bar (issue 14): the initial assembly closes a perturbed
// rocker back onto its joint and reports the move; from rest, the crank's drive gets consistent
// velocities, and the rocker then follows the rigid four-bar from the first step, converging in h
// (observed order 1.5–1.7 at these steps: the rods' unresolved stiff modes, not the start). Short
// runs (0.02 s) keep the suite fast.
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "four_bar_model.hpp"

using namespace spar;

namespace {

struct FourBarRun {
  double rocker_angle = 0.0;      ///< at t_end [rad]
  double max_error = 0.0;         ///< max |ψ − ψ_rigid| over the run [rad]
  double max_residual = 0.0;      ///< max ‖Φ‖∞ after a step
  solvers::InitialAssembly assembly;
};

FourBarRun run_four_bar(double h, double t_end, double stiffness_time, bool perturbed_start = false,
                        const examples::FourBarGeometry& geometry = {}) {
  examples::FourBar f = examples::build_four_bar(4, geometry);
  solvers::GeneralizedAlpha integrator(f.model, std::move(f.joints),
                                       {.time_step = h, .tolerance = 1e-20, .constraint_tolerance = 1e-12,
                                        .residual_tolerance = 1e-8,
                                        .initial_velocity_stiffness_time = stiffness_time,
                                        .perturbed_starting_values = perturbed_start});
  integrator.initialize();
  FourBarRun run{.assembly = integrator.initial_assembly()};
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    const double error = f.rocker_angle(f.model.state()) - f.rigid.rocker_angle(f.rigid.crank_angle(integrator.time()));
    run.max_error = std::max(run.max_error, std::abs(error));
    run.max_residual = std::max(run.max_residual, integrator.constraint_residual());
  }
  run.rocker_angle = f.rocker_angle(f.model.state());
  return run;
}

}  // namespace

TEST_CASE("four-bar: the assembly closes a rocker placed 2 mm off its joint and reports the move", "[dynamics]") {
  examples::FourBar f = examples::build_four_bar(4);
  // Move the whole rocker by 2 mm along Y (its tip leaves the coupler's pin C, its root the pin D).
  for (int node = f.rocker_root; node <= f.rocker_tip; ++node) f.model.state().position[node].y() += 2e-3;
  solvers::GeneralizedAlpha integrator(f.model, std::move(f.joints),
                                       {.time_step = 1e-4, .constraint_tolerance = 1e-12,
                                        .initial_assembly_tolerance = 1e-2});
  integrator.initialize();
  const solvers::InitialAssembly& report = integrator.initial_assembly();
  INFO("moved by " << report.largest_position_change << " in " << report.position_iterations << " iterations");
  CHECK(report.constraint_residual == Approx(2e-3).epsilon(1e-12));
  CHECK(report.position_iterations >= 1);
  CHECK(integrator.constraint_residual() <= 1e-12);
  // The rocker's nodes move back by about the gap (the least change in the metric of M shares it
  // with the coupler and the crank, which move by less): between half of it and all of it.
  CHECK(report.largest_position_change > 1e-3);
  CHECK(report.largest_position_change <= 2e-3 * (1 + 1e-6));
  CHECK(report.largest_position_change_block >= f.rocker_root);
  CHECK(report.largest_position_change_block <= f.rocker_tip);
}

TEST_CASE("four-bar: started from rest, the rocker follows the rigid four-bar from the first step",
          "[dynamics][validation]") {
  // With the velocities projected in the metric M + τ²K (τ = 1 s) the rods start with the rigid
  // motion of the drive; what is left against the rigid four-bar is the rods' elastic response to
  // the mechanism's inertia and gravity, 7.8e-5 rad over 1 s whatever h (measured at h = 1e-4 and
  // 5e-5): bound 1e-4 rad over 0.02 s. In the mass metric (τ = 0) the drive spins the crank's root
  // section alone; the rest of the crank lags and rings, and the rocker is off by 1.3e-3 rad
  // within 2 ms (bound: above 5e-4).
  const double t_end = 0.02;
  const FourBarRun coarse = run_four_bar(2e-4, t_end, 1.0);
  const FourBarRun medium = run_four_bar(1e-4, t_end, 1.0);
  const FourBarRun fine = run_four_bar(5e-5, t_end, 1.0);
  const FourBarRun impulsive = run_four_bar(1e-4, t_end, 0.0);
  INFO("max error against the rigid four-bar: " << medium.max_error << " rad (tau = 1 s), "
                                                << impulsive.max_error << " rad (mass metric)");
  CHECK(medium.assembly.largest_position_change == 0.0);
  // At rest the velocity constraints are violated by the drive's rate alone, 10 rad/s (a product
  // or two of O(1) numbers: 1e-15 relative).
  CHECK(medium.assembly.velocity_constraint_residual == Approx(10.0).epsilon(1e-15));
  CHECK(medium.max_residual <= 1e-12);
  CHECK(medium.max_error <= 1e-4);
  CHECK(impulsive.max_error > 5e-4);
  // Convergence in h: the rocker angle at 0.02 s changes by 9.3e-7, 3.1e-7, 9.3e-8, 3.2e-8 rad
  // from h = 4e-4 to 2.5e-5 (halvings; Newton to 1e-20): ratios 3.06, 3.27, 2.87, an observed
  // order of 1.5–1.7, not yet 2 — the rods' stiff modes (ωh ≈ 1 and above), excited by the drive's
  // start, are not resolved at these steps (the next test proves it). The bound 2.5 (order 1.3)
  // separates it from a first-order start (ratio 2), which an inconsistent initial velocity would give.
  const double ratio = std::abs(coarse.rocker_angle - medium.rocker_angle) / std::abs(medium.rocker_angle - fine.rocker_angle);
  INFO("rocker angle at 0.02 s: " << coarse.rocker_angle << ", " << medium.rocker_angle << ", " << fine.rocker_angle
                                  << " rad; ratio of differences " << ratio);
  CHECK(ratio > 2.5);
}

TEST_CASE("four-bar: the rocker's order below 2 comes from the rods' unresolved stiff modes, not the start",
          "[dynamics]") {
  // Two hypotheses for the ratios 3.06, 3.27 of the test above (order 1.6–1.7, not 2):
  //  - the index-3 start-up (a₀ = v̇₀, v₀ consistent; docs/dynamics.md D6d): perturbed starting
  //    values move the rocker angle at 0.02 s by 1.1e-8 rad at h = 4e-4 and 2.8e-9 at 1e-4 (the
  //    differences between steps are 9.3e-7 and 3.1e-7), and the ratios from 3.06, 3.27, 2.88 to
  //    3.01, 3.39, 2.80 (h = 4e-4 ... 2.5e-5): the order stays 1.5–1.75, not the cause;
  //  - the rods' stiff modes: the axial ones (27 000 rad/s and up; ωh ≈ 3 at h = 1e-4) and the
  //    high bending ones of 4 cubic elements lie where the method's damping of a mode still
  //    changes with h. Rods 100 times softer (every frequency 10 times lower, resolved at these
  //    steps) converge as the method should: ratios 4.29, 5.23 from h = 2e-4 (measured; order
  //    2.1–2.4), and rods 100 times stiffer give differences that change sign (not asymptotic).
  // Checked: with and without the perturbed start the steel rods' ratios stay below 3.6 (order
  // 1.85), and the soft rods' are both above it.
  const double t_end = 0.02;
  auto ratio = [&](bool perturbed, const examples::FourBarGeometry& geometry) {
    const double a = run_four_bar(4e-4, t_end, 1.0, perturbed, geometry).rocker_angle;
    const double b = run_four_bar(2e-4, t_end, 1.0, perturbed, geometry).rocker_angle;
    const double c = run_four_bar(1e-4, t_end, 1.0, perturbed, geometry).rocker_angle;
    const double d = run_four_bar(5e-5, t_end, 1.0, perturbed, geometry).rocker_angle;
    return std::array<double, 2>{(a - b) / (b - c), (b - c) / (c - d)};
  };
  const std::array<double, 2> plain = ratio(false, {}), perturbed = ratio(true, {});
  const std::array<double, 2> soft = ratio(false, {.young_modulus = 210e9 / 100});
  INFO("ratios of successive differences, h = 4e-4 ... 5e-5: steel " << plain[0] << ", " << plain[1]
                                                                       << "; perturbed start " << perturbed[0] << ", "
                                                                       << perturbed[1] << "; soft rods " << soft[0]
                                                                       << ", " << soft[1]);
  for (int k = 0; k < 2; ++k) {
    CHECK(plain[k] < 3.6);
    CHECK(perturbed[k] < 3.6);
    CHECK(soft[k] > 3.6);
  }
}
