// Inertia of beams and rigid bodies: the gyroscopic tangent against finite differences, the mass
// matrix against the kinetic energy of rigid motions, and the Chung–Hulbert parameters.
#include <spar/core/inertia.hpp>
#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "beam_fixtures.hpp"
#include "random_rotations.hpp"

using namespace spar;

namespace {

core::SectionInertia generic_inertia() {
  core::SectionInertia inertia;
  inertia.mass_per_length = 2.0;
  inertia.rotary << 0.3, 0.0, 0.0, 0.0, 0.2, -0.05, 0.0, -0.05, 0.1;
  return inertia;
}

}  // namespace

TEST_CASE("the gyroscopic tangent is the derivative of the gyroscopic force", "[dynamics]") {
  core::Model model;
  model.add_beam({.centerline = test::straight_centerline(1.0, 2, 3),
                  .stiffness = test::generic_stiffness(), .inertia = generic_inertia()});
  const int body = model.add_rigid_body({.mass = 3.0, .inertia = Eigen::Vector3d(0.4, 0.5, 0.7).asDiagonal()});
  test::RandomRotations random(31);
  // Local velocities: the element's frames one after the other.
  auto check = [&](int n, auto evaluate) {
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v(i) = random.uniform(-3, 3);
    core::InertiaContribution c;
    evaluate(v, c);
    Eigen::MatrixXd fd(n, n);
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd plus = v, minus = v;
      plus(j) += 1e-6;
      minus(j) -= 1e-6;
      core::InertiaContribution cp, cm;
      evaluate(plus, cp);
      evaluate(minus, cm);
      fd.col(j) = (cp.gyroscopic - cm.gyroscopic) / 2e-6;
    }
    // The gyroscopic force is quadratic in v: central differences are exact up to round-off.
    CHECK((c.gyroscopic_tangent - fd).norm() <= 1e-8 * c.gyroscopic_tangent.norm());
  };
  check(6 * (model.beam(0).degree() + 1), [&](const Eigen::VectorXd& vel, core::InertiaContribution& c) {
    core::beam_element_inertia(model.beam(0), 1, vel, c);
  });
  check(6, [&](const Eigen::VectorXd& vel, core::InertiaContribution& c) {
    core::rigid_body_inertia(model.rigid_body(body), vel, c);
  });
}

TEST_CASE("the beam mass matrix gives the kinetic energy of a translating, spinning beam",
          "[dynamics]") {
  // A straight beam of length 1.5 translating with u and spinning about its axis with ω:
  // T = ½ ρA L |u|² + ½ ρJ₁₁ L ω².
  core::Model model;
  const int b = model.add_beam({.centerline = test::straight_centerline(1.5, 4, 2),
                                .stiffness = test::generic_stiffness(), .inertia = generic_inertia()});
  const Eigen::Vector3d u(0.3, -1.2, 0.4);
  const double omega = 2.5;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.dof_count());
  for (int k = 0; k < model.block_count(); ++k) {
    v.segment<3>(6 * k) = u;
    v(6 * k + 3) = omega;
  }
  double kinetic = 0.0;
  for (int e = 0; e < model.beam(b).element_count(); ++e) {
    core::InertiaContribution c;
    const int first = model.beam(b).node(model.beam(b).element(e).first_control_point);
    const Eigen::VectorXd local = v.segment(6 * first, 6 * (model.beam(b).degree() + 1));
    core::beam_element_inertia(model.beam(b), e, local, c);
    kinetic += core::kinetic_energy(c, local);
  }
  const double expected = 0.5 * 2.0 * 1.5 * u.squaredNorm() + 0.5 * 0.3 * 1.5 * omega * omega;
  CHECK(std::fabs(kinetic - expected) <= 1e-14 * expected);
}

TEST_CASE("generalized-alpha parameters follow Chung and Hulbert", "[dynamics]") {
  const auto p = solvers::GeneralizedAlphaParameters::from_spectral_radius(1.0);
  CHECK(p.alpha_m == Approx(0.5));
  CHECK(p.alpha_f == Approx(0.5));
  CHECK(p.gamma == Approx(0.5));
  CHECK(p.beta == Approx(0.25));
  const auto q = solvers::GeneralizedAlphaParameters::from_spectral_radius(0.0);
  CHECK(q.alpha_m == Approx(-1.0));
  CHECK(q.alpha_f == Approx(0.0));
  CHECK(q.gamma == Approx(1.5));
  CHECK(q.beta == Approx(1.0));
  CHECK_THROWS_AS(solvers::GeneralizedAlphaParameters::from_spectral_radius(1.5), Error);
}
