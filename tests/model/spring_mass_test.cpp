// Issue 10, proof 1: an element kind defined entirely in a test (point masses on vector blocks,
// a linear spring between them) enters the model through add_element and is integrated by the
// library's generalized-α with no change to the solvers. Its stiffness is checked against finite
// differences; two free masses on one spring against the analytical motion, with the order of
// the error measured.
#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>

#include "linear_spring.hpp"
#include "point_mass.hpp"
#include "vector_block_checks.hpp"

using namespace spar;

TEST_CASE("a spring defined in a test has the exact stiffness and a point mass the mass m I",
          "[model]") {
  std::mt19937 random(1001);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int sample = 0; sample < 20; ++sample) {
    test::ElementState s;
    s.q.add_vector(Eigen::Vector3d(uniform(random), uniform(random), uniform(random)));
    s.q.add_vector(Eigen::Vector3d(uniform(random), uniform(random), uniform(random)) + Eigen::Vector3d(1.5, 0, 0));
    s.velocity = Eigen::VectorXd::NullaryExpr(6, [&] { return uniform(random); });
    s.acceleration = Eigen::VectorXd::NullaryExpr(6, [&] { return uniform(random); });
    s.gravity = Eigen::Vector3d(0, 0, -9.81);
    // Rest lengths below and above the current length: tension and compression.
    const test::LinearSpring spring({.block_a = 0, .block_b = 1, .stiffness = 50.0,
                                     .rest_length = 0.5 + 0.1 * sample});
    const core::ElementOutput out = test::evaluate(spring, s, {});
    CAPTURE(sample);
    test::check_element_derivatives(spring, s);
    // The spring is a conservative force: its residual is the gradient of its strain energy.
    const double energy_step = test::vector_element_options.step;
    for (int i = 0; i < 6; ++i) {
      test::ElementState plus = s, minus = s;
      plus.q.values(i) += energy_step;
      minus.q.values(i) -= energy_step;
      const double gradient = (test::evaluate(spring, plus, {}).energy.strain -
                               test::evaluate(spring, minus, {}).energy.strain) / (2 * energy_step);
      CHECK(std::abs(gradient - out.residual(i)) <
            test::vector_element_options.tolerance * std::max(1.0, std::abs(out.residual(i))));
    }

    test::check_element_derivatives(test::PointMass(1, 2.5), s);
  }
}

namespace {

// Two masses m = 1 kg on a spring k = 50 N/m, L0 = 1 m, stretched by u0 = 0.1 m along x, at rest
// relative to each other, their centre of mass moving at V. Along the spring's axis the spring
// is exactly linear, so the relative coordinate u = l − L0 obeys (m/2) ü = −k u exactly:
// u(t) = u0 cos ωt, ω = sqrt(2k/m) = 10 rad/s, and the centre of mass moves uniformly.
constexpr double mass = 1.0, stiffness = 50.0, rest_length = 1.0, stretch = 0.1;
const Eigen::Vector3d centre_velocity(0.3, -0.2, 0.1);

struct SpringErrors {
  double relative = 0.0;  ///< |u_h(T) − u(T)|, m
  double centre = 0.0;    ///< |c_h(T) − c(T)|, m
  double transverse = 0.0;  ///< largest distance of the two masses from the moving axis, m
};

SpringErrors integrate_two_masses(double h, double spectral_radius, double end_time) {
  core::Model model;
  const int a = model.add_vector(Eigen::Vector3d(0, 0, 0));
  const int b = model.add_vector(Eigen::Vector3d(rest_length + stretch, 0, 0));
  model.add_element(std::make_unique<test::PointMass>(a, mass));
  model.add_element(std::make_unique<test::PointMass>(b, mass));
  model.add_element(std::make_unique<test::LinearSpring>(test::LinearSpringParameters{
      .block_a = a, .block_b = b, .stiffness = stiffness, .rest_length = rest_length}));
  solvers::DynamicOptions options;
  options.time_step = h;
  options.spectral_radius = spectral_radius;
  // Newton to round-off, so that only the time discretization shows in the error: ‖Δ‖ ≤ 1e-12 m
  // (the squared test), residual 1e-12 of its terms.
  options.tolerance = 1e-24;
  options.residual_tolerance = 1e-12;
  solvers::GeneralizedAlpha integrator(model, {}, options);
  integrator.set_velocity(a, Eigen::VectorXd(centre_velocity));
  integrator.set_velocity(b, Eigen::VectorXd(centre_velocity));
  const int steps = static_cast<int>(std::lround(end_time / h));
  for (int n = 0; n < steps; ++n) integrator.step();

  const double t = integrator.time();
  const double omega = std::sqrt(2 * stiffness / mass);
  const Eigen::Vector3d xa = integrator.configuration().vector(a), xb = integrator.configuration().vector(b);
  const Eigen::Vector3d centre0(0.5 * (rest_length + stretch), 0, 0);
  SpringErrors e;
  e.relative = std::abs((xb - xa).norm() - rest_length - stretch * std::cos(omega * t));
  e.centre = (0.5 * (xa + xb) - centre0 - centre_velocity * t).norm();
  const Eigen::Vector3d c = centre0 + centre_velocity * t;
  e.transverse = std::max((xa - c).tail<2>().norm(), (xb - c).tail<2>().norm());
  return e;
}

}  // namespace

TEST_CASE("two masses on a spring defined in a test: uniform centre, harmonic stretch, O(h^2)",
          "[model][validation]") {
  // ρ∞ = 1: an unconstrained linear oscillator needs no numerical dissipation (the method is then
  // the energy-conserving trapezoidal rule, second order, error purely a phase lag ω³h²t/12), so
  // the measured error is the method's order and nothing else.
  const double end_time = 1.0;  // 1.6 periods
  const SpringErrors e1 = integrate_two_masses(4e-3, 1.0, end_time);
  const SpringErrors e2 = integrate_two_masses(2e-3, 1.0, end_time);
  const SpringErrors e3 = integrate_two_masses(1e-3, 1.0, end_time);
  // The trapezoidal rule's phase lag is ω³h²t/12 to leading order, so |u_h − u| ≈
  // u0 |sin ωt| ω³h²t/12: measured 7.244e-5, 1.813e-5, 4.533e-6 m against 7.25e-5, 1.81e-5,
  // 4.53e-6 predicted. Halving h divides the error by 4.00 ± 0.004; 3.9–4.1 allows the O(h⁴) rest.
  CHECK(e1.relative / e2.relative == Approx(4.0).margin(0.1));
  CHECK(e2.relative / e3.relative == Approx(4.0).margin(0.1));
  const double omega = std::sqrt(2 * stiffness / mass), h = 1e-3;
  const double predicted = stretch * std::abs(std::sin(omega * end_time)) * std::pow(omega, 3) * h * h * end_time / 12;
  CHECK(e3.relative == Approx(predicted).epsilon(0.01));
  // No net force: the centre of mass moves uniformly and the masses stay on the moving axis, to
  // round-off accumulated over 1000 steps of coordinates of size 1 (1000 · 2.2e-16 ≈ 2e-13;
  // measured ≤ 4.2e-15).
  for (const SpringErrors& e : {e1, e2, e3}) {
    CHECK(e.centre < 2e-13);
    CHECK(e.transverse < 2e-13);
  }
}
