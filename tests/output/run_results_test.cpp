// The results file of a real run, read back against the exact motion (issue 16: the other output
// tests write synthetic steps, whose velocities have nothing to do with their configurations). A
// symmetric body spinning about its symmetry axis under gravity feels no moment about its centre:
//     x(t) = x₀ + v₀ t + ½ g t²,   R(t) = R₀ exp(Ω t),   ẋ = v₀ + g t,   Ω constant,
// and generalized-α from consistent accelerations reproduces this motion (docs/dynamics.md D10;
// the time sampler's test). What the file holds is compared with these closed forms, the
// quaternion written out by hand, so the writer's conversion and the integrator's state are both
// checked from outside.
#include <spar/core/model.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/output/results_writer.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "output_fixtures.hpp"

using namespace spar;

TEST_CASE("a run's results file holds the exact motion of a falling, spinning body", "[output][validation]") {
  // R₀ = exp(0.7 e₁), Ω = 20 e₃ (material): R(t) has the quaternion q₀ ⊗ (cos 10t, 0, 0, sin 10t)
  // = (a c, s c, −s d, a d) with (a, s) = (cos 0.35, sin 0.35), (c, d) = (cos 10t, sin 10t),
  // stored with w ≥ 0: over 0.3 s, 10t passes π/2 and the sign flips.
  const double h = 3e-4, t_end = 0.3, omega = 20.0, half_tilt = 0.35, mass = 1.5;
  const Eigen::Vector3d x0(0.1, 0.2, 0.3), v0(1.0, 2.0, 0.5), g(0, -9.81, 0);
  const Eigen::Matrix3d J = Eigen::Vector3d(0.02, 0.02, 0.03).asDiagonal();
  core::Model model;
  const int body = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = x0, .rotation = Eigen::AngleAxisd(2 * half_tilt, Eigen::Vector3d::UnitX()).toRotationMatrix(),
       .mass = mass, .inertia = J})).node;
  model.set_gravity(g);
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = h, .tolerance = 1e-24});
  integrator.set_velocity(body, v0, Eigen::Vector3d(0, 0, omega));
  integrator.initialize();

  const spar::test::ScratchFolder folder("run_results");
  const std::string path = folder.file("body.h5");
  output::ResultsLayout layout;
  layout.node_count = 1;
  layout.scalars = {{.name = "kinetic_energy", .unit = "J", .description = "kinetic energy"}};
  {
    output::ResultsWriter writer(path, layout, 64);  // 1001 steps: 15 full blocks and a partial one
    const auto append = [&] {
      writer.append({.time = integrator.time(), .configuration = &model.state(), .velocity = &integrator.velocity(),
                     .scalars = {integrator.energies().kinetic}});
    };
    append();
    while (integrator.time() < t_end - 0.5 * h) {
      integrator.step();
      append();
    }
  }
  const spar::test::ReadOnlyFile file(path);
  const spar::test::DatasetContents time = file.read("/time"), positions = file.read("/positions"),
                                    quaternions = file.read("/quaternions"), velocities = file.read("/velocities"),
                                    kinetic = file.read("/scalars/kinetic_energy");
  const std::size_t steps = time.values.size();
  REQUIRE(steps == 1001);
  // Round-off of 1000 steps on O(1) to O(10) numbers: ≤ 1000 · 2.2e-16 · 10 = 2e-12 (measured
  // 6.5e-14). A velocity one step behind its configuration is off by g h = 3e-3, the quaternion of
  // R₀ᵀ or of −Ω by O(1).
  const double bound = 2e-12;
  double worst = 0.0;
  for (std::size_t k = 0; k < steps; ++k) {
    const double t = time.values[k];
    CHECK(std::abs(t - h * static_cast<double>(k)) <= 1e-15 * static_cast<double>(k));
    const Eigen::Vector3d x = x0 + v0 * t + 0.5 * g * t * t, v = v0 + g * t;
    const double a = std::cos(half_tilt), s = std::sin(half_tilt), c = std::cos(0.5 * omega * t),
                 d = std::sin(0.5 * omega * t);
    const Eigen::Vector4d q = (c >= 0 ? 1.0 : -1.0) * Eigen::Vector4d(a * c, s * c, -s * d, a * d);
    const double T = 0.5 * mass * v.squaredNorm() + 0.5 * J(2, 2) * omega * omega;
    Eigen::Matrix<double, 6, 1> expected_velocity;
    expected_velocity << v, 0, 0, omega;
    const double errors[] = {
        (Eigen::Vector3d(&positions.values[3 * k]) - x).norm(),
        (Eigen::Vector4d(&quaternions.values[4 * k]) - q).norm(),
        (Eigen::Matrix<double, 6, 1>(&velocities.values[6 * k]) - expected_velocity).norm(),
        std::abs(kinetic.values[k] - T) / T,
    };
    for (const double e : errors) worst = std::max(worst, e);
  }
  INFO("largest difference from the exact motion " << worst);
  CHECK(worst <= bound);
}
