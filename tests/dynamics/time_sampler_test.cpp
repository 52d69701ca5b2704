// Output at chosen times (solvers::TimeSampler, docs/dynamics.md D10): samples every 1 ms from a
// run at h = 3e-4 s, whose steps never land on them. Exact for a body falling and spinning
// steadily (the method and the cubic Hermite interpolation both are); of the method's order 2
// for a pendulum.
#include <spar/joints/revolute_joint.hpp>
#include <spar/lie/exp.hpp>
#include <spar/lie/log.hpp>
#include <spar/solvers/time_sampler.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace spar;

namespace {

/// The positions of a body's node at the samples of a run.
struct SampledRun {
  std::vector<double> times;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Matrix3d> rotations;
};

}  // namespace

TEST_CASE("time sampler: every 1 ms from h = 3e-4 s, exact for a falling body spinning steadily",
          "[dynamics][validation]") {
  // A symmetric body spinning about its symmetry axis feels no gyroscopic moment: R = R₀ exp(Ω t),
  // x = x₀ + v₀ t + ½ g t². Generalized-α from consistent accelerations reproduces both, and the
  // cubic Hermite interpolation is exact for them: round-off of ~170 steps, bound 1e-12.
  core::Model model;
  const Eigen::Vector3d x0(0.1, 0.2, 0.3), v0(1.0, 2.0, 0.5), omega(0, 0, 20.0), g(0, -9.81, 0);
  const int body = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = x0, .mass = 1.0, .inertia = Eigen::Vector3d(0.02, 0.02, 0.03).asDiagonal()})).node;
  model.set_gravity(g);
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = 3e-4, .tolerance = 1e-24});
  integrator.set_velocity(body, v0, omega);
  integrator.initialize();
  solvers::TimeSampler sampler = solvers::TimeSampler::every(1e-3);
  std::vector<solvers::Sample> samples;
  auto collect = [&] { for (const auto& s : sampler.update(integrator)) samples.push_back(s); };
  collect();
  while (integrator.time() < 0.05 - 1e-12) {
    integrator.step();
    collect();
  }
  REQUIRE(samples.size() == 51);  // 0, 1, …, 50 ms: 0.05 s is a step's end within round-off
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double t = samples[k].time;
    CHECK(t == Approx(1e-3 * static_cast<double>(k)).margin(1e-15));
    const Eigen::Vector3d x = x0 + v0 * t + 0.5 * g * t * t;
    const Eigen::Matrix3d R = lie::exp(Eigen::Vector3d(omega * t));
    CHECK((samples[k].q.position[body] - x).norm() <= 1e-12);
    CHECK(lie::log(R.transpose() * samples[k].q.rotation[body]).norm() <= 1e-12);
    CHECK((samples[k].velocity.head<3>() - (v0 + g * t)).norm() <= 1e-12);
    CHECK((samples[k].velocity.tail<3>() - omega).norm() <= 1e-12);
  }
}

namespace {

/// A rigid pendulum (hinged about Z at the origin, centre 0.5 m off, released horizontal),
/// sampled at the given times.
SampledRun pendulum(double h, std::vector<double> times, double t_end) {
  core::Model model;
  const int body = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = Eigen::Vector3d(0.5, 0, 0), .mass = 1.0,
       .inertia = Eigen::Vector3d(0.01, 0.01, 0.02).asDiagonal()})).node;
  model.set_gravity(Eigen::Vector3d(0, -9.81, 0));
  solvers::ConstraintList joints;
  joints.push_back(std::make_unique<joints::RevoluteJoint>(joints::attach_at(body, Eigen::Vector3d::Zero(), model.state()),
                                                           joints::Attachment{-1}, Eigen::Vector3d::UnitZ(), model.state()));
  solvers::GeneralizedAlpha integrator(model, std::move(joints),
                                       {.time_step = h, .tolerance = 1e-24, .constraint_tolerance = 1e-13});
  integrator.initialize();
  solvers::TimeSampler sampler(std::move(times));
  SampledRun run;
  auto collect = [&] {
    for (const auto& s : sampler.update(integrator)) {
      run.times.push_back(s.time);
      run.positions.push_back(s.q.position[body]);
    }
  };
  collect();
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    collect();
  }
  return run;
}

double largest_distance(const SampledRun& a, const SampledRun& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.positions.size(); ++k) worst = std::max(worst, (a.positions[k] - b.positions[k]).norm());
  return worst;
}

}  // namespace

TEST_CASE("time sampler: samples between steps converge with the method's order 2", "[dynamics]") {
  // Every 1 ms over 0.3 s (a listed set), from h = 3e-4 and 1.5e-4 s,
  // against h = 1e-5 s. The errors at the samples shrink by 4 per halving like the method's own
  // (the interpolation's O(h³) is below it).
  std::vector<double> times;
  for (int k = 0; k <= 300; ++k) times.push_back(1e-3 * k);
  const SampledRun reference = pendulum(1e-5, times, 0.3);
  const SampledRun coarse = pendulum(3e-4, times, 0.3);
  const SampledRun fine = pendulum(1.5e-4, times, 0.3);
  REQUIRE(reference.positions.size() == 301);
  REQUIRE(coarse.positions.size() == 301);
  REQUIRE(fine.positions.size() == 301);
  CHECK(coarse.times.front() == 0.0);
  const double e_coarse = largest_distance(coarse, reference), e_fine = largest_distance(fine, reference);
  INFO("largest error at the samples: " << e_coarse << " m (h = 3e-4), " << e_fine << " m (h = 1.5e-4), ratio "
                                        << e_coarse / e_fine);
  CHECK(e_coarse / e_fine > 3.5);
  CHECK(e_coarse / e_fine < 4.5);
}

TEST_CASE("time sampler: an interval that is not positive is refused", "[dynamics]") {
  CHECK_THROWS_AS(solvers::TimeSampler::every(0.0), Error);
  CHECK_THROWS_AS(solvers::TimeSampler::every(-1e-3), Error);
}

TEST_CASE("time sampler: listed times that do not increase are refused", "[dynamics]") {
  // Issue 29: decreasing times were sorted silently; a repeated time would give two samples at
  // one time, which the results file refuses later, mid-run.
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(solvers::TimeSampler({0.0, 2e-3, 1e-3}),
                    Contains("output time 2 (0.001 s)") && Contains("not after output time 1 (0.002 s)") &&
                        Contains("solvers::TimeSampler"));
  CHECK_THROWS_WITH(solvers::TimeSampler({0.0, 1e-3, 1e-3}), Contains("output time 2"));
  CHECK_THROWS_WITH(solvers::TimeSampler({0.0, NAN}), Contains("output time 1") && Contains("not finite"));
  CHECK_NOTHROW(solvers::TimeSampler({-1.0, 0.0, 1e-3}));
}
