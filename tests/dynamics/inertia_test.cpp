// Inertia of beams and rigid bodies: the gyroscopic tangent against finite differences, the mass
// matrix against the kinetic energy of rigid motions, and the Chung–Hulbert parameters.
#include <spar/elements/beam/beam_inertia.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/beam/beam.hpp>

#include <Eigen/Geometry>
#include <Eigen/LU>
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
  core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 3),
                  .stiffness = test::generic_stiffness(), .inertia = generic_inertia()});
  const int body = core::add_rigid_body(model, {.mass = 3.0, .inertia = Eigen::Vector3d(0.4, 0.5, 0.7).asDiagonal()});
  test::RandomRotations random(31);
  // Local velocities: the element's frames one after the other.
  auto check = [&](const core::FrameInertia& inertia) {
    const int n = 6 * inertia.frame_count();
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v(i) = random.uniform(-3, 3);
    const Eigen::VectorXd no_acceleration = Eigen::VectorXd::Zero(n);
    auto gyroscopic = [&](const Eigen::VectorXd& velocity) {
      Eigen::VectorXd force = Eigen::VectorXd::Zero(n);
      inertia.add_force(velocity, no_acceleration, force);
      return force;
    };
    Eigen::MatrixXd tangent = Eigen::MatrixXd::Zero(n, n);
    inertia.add_gyroscopic_tangent(v, tangent);
    Eigen::MatrixXd fd(n, n);
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd plus = v, minus = v;
      plus(j) += 1e-6;
      minus(j) -= 1e-6;
      fd.col(j) = (gyroscopic(plus) - gyroscopic(minus)) / 2e-6;
    }
    // The gyroscopic force is quadratic in v: central differences are exact up to round-off.
    CHECK((tangent - fd).norm() <= 1e-8 * tangent.norm());
  };
  check(core::beam_element_inertia(core::beam(model, 0), 1));
  check(core::rigid_body_inertia(core::rigid_body(model, body)));
}

TEST_CASE("the factored inertia products are those of the dense mass matrix", "[dynamics]") {
  // M v̇ and ½ vᵀMv computed from the factors m_IJ, ρA, ρJ against the assembled 6k × 6k M: the
  // same sums in another order, equal to round-off. With v = 0 the force is M v̇ alone; with
  // v̇ = 0 it is the gyroscopic force Ω_I × (Σ_J M_IJ^ΩΩ Ω_J), written out here from M's blocks.
  core::Model model;
  core::add_beam(model, {.centerline = test::straight_centerline(1.0, 3, 3),
                  .stiffness = test::generic_stiffness(), .inertia = generic_inertia()});
  const core::FrameInertia inertia = core::beam_element_inertia(core::beam(model, 0), 1);
  const int k = inertia.frame_count(), n = 6 * k;
  REQUIRE(k == 4);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  inertia.add_mass(M);
  // m_IJ = Σ w N_I N_J is symmetric up to the order of its products.
  CHECK((M - M.transpose()).norm() <= 1e-15 * M.norm());
  test::RandomRotations random(7);
  Eigen::VectorXd v(n), a(n);
  for (int i = 0; i < n; ++i) {
    v(i) = random.uniform(-3, 3);
    a(i) = random.uniform(-3, 3);
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd inertial = Eigen::VectorXd::Zero(n);
  inertia.add_force(zero, a, inertial);
  CHECK((inertial - M * a).norm() <= 1e-14 * (M * a).norm());
  Eigen::VectorXd gyroscopic = Eigen::VectorXd::Zero(n), expected = Eigen::VectorXd::Zero(n);
  inertia.add_force(v, zero, gyroscopic);
  for (int I = 0; I < k; ++I) {
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    for (int J = 0; J < k; ++J) momentum += M.block<3, 3>(6 * I + 3, 6 * J + 3) * v.segment<3>(6 * J + 3);
    expected.segment<3>(6 * I + 3) = Eigen::Vector3d(v.segment<3>(6 * I + 3)).cross(momentum);
  }
  CHECK((gyroscopic - expected).norm() <= 1e-14 * expected.norm());
  CHECK(std::fabs(inertia.kinetic_energy(v) - 0.5 * v.dot(M * v)) <= 1e-14 * v.dot(M * v));
}

TEST_CASE("the beam mass matrix gives the kinetic energy of a translating, spinning beam",
          "[dynamics][validation]") {
  // A straight beam of length 1.5 translating with u and spinning about its axis with ω:
  // T = ½ ρA L |u|² + ½ ρJ₁₁ L ω².
  core::Model model;
  const int b = core::add_beam(model, {.centerline = test::straight_centerline(1.5, 4, 2),
                                .stiffness = test::generic_stiffness(), .inertia = generic_inertia()});
  const Eigen::Vector3d u(0.3, -1.2, 0.4);
  const double omega = 2.5;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.dof_count());
  for (int k = 0; k < model.block_count(); ++k) {
    v.segment<3>(6 * k) = u;
    v(6 * k + 3) = omega;
  }
  double kinetic = 0.0;
  for (int e = 0; e < core::beam(model, b).element_count(); ++e) {
    const int first = core::beam(model, b).node(core::beam(model, b).element(e).first_control_point);
    const Eigen::VectorXd local = v.segment(6 * first, 6 * (core::beam(model, b).degree() + 1));
    kinetic += core::beam_element_inertia(core::beam(model, b), e).kinetic_energy(local);
  }
  const double expected = 0.5 * 2.0 * 1.5 * u.squaredNorm() + 0.5 * 0.3 * 1.5 * omega * omega;
  CHECK(std::fabs(kinetic - expected) <= 1e-14 * expected);
}

TEST_CASE("the beam mass matrix gives the kinetic energy of a tumbling beam, any orientation",
          "[dynamics][validation]") {
  // A straight beam of length L along a unit a, its section turned about a (R₀ = [a, A₂, A₃] from a
  // section-axis hint), moving rigidly: its midpoint c at u, turning with inertial ω. Control
  // point velocities ẋ = u + ω × (x − c) and Ω = R₀ᵀω give the rigid field exactly (the spline is
  // affine-invariant), and T = ½ ρA L |u|² + ½ ρA L³/12 (|ω|² − (ω·a)²) + ½ L (R₀ᵀω)ᵀ ρJ (R₀ᵀω):
  // every entry of ρJ, the 2–3 coupling included, and the coupling of translation and rotation
  // through the arm x − c enter. Gauss quadrature integrates these polynomials exactly: 1e-14.
  const Eigen::Vector3d start(0.2, -0.1, 0.4), a = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  const double L = 1.5;
  core::Model model;
  const int b = core::add_beam(model, {.centerline = iga::straight_line<3>(start, start + L * a, 4, 2),
                                .stiffness = test::generic_stiffness(), .inertia = generic_inertia(),
                                .section_axis_hint = Eigen::Vector3d(0.3, 0.4, 1.0)});
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  const Eigen::Matrix3d R0 = model.state().rotation[beam.node(0)];
  REQUIRE((R0.col(0) - a).norm() <= 1e-15);
  const Eigen::Vector3d c = start + 0.5 * L * a, u(0.3, -1.2, 0.4), omega(1.1, 2.5, -0.7);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.dof_count());
  for (int k = 0; k < model.block_count(); ++k) {
    v.segment<3>(6 * k) = u + omega.cross(model.state().position[k] - c);
    v.segment<3>(6 * k + 3) = model.state().rotation[k].transpose() * omega;
  }
  double kinetic = 0.0;
  for (int e = 0; e < beam.element_count(); ++e) {
    const int first = beam.node(beam.element(e).first_control_point);
    const Eigen::VectorXd local = v.segment(6 * first, 6 * (beam.degree() + 1));
    kinetic += core::beam_element_inertia(beam, e).kinetic_energy(local);
  }
  const Eigen::Vector3d Omega = R0.transpose() * omega;
  const double expected = 0.5 * 2.0 * L * u.squaredNorm() +
                          0.5 * 2.0 * L * L * L / 12 * (omega.squaredNorm() - omega.dot(a) * omega.dot(a)) +
                          0.5 * L * Omega.dot(generic_inertia().rotary * Omega);
  INFO("kinetic energy " << kinetic << ", expected " << expected);
  CHECK(std::fabs(kinetic - expected) <= 1e-14 * expected);
}

TEST_CASE("generalized-alpha parameters follow Chung and Hulbert", "[dynamics][validation]") {
  // The property the parameters exist for, checked independently of their formulas: one step of
  // the method on x″ = −ω²x, with Ω = ωh and state (x, h v, h² a),
  //   (1 − α_m) a₁ + α_m a₀ + ω²((1 − α_f) x₁ + α_f x₀) = 0,
  //   x₁ = x₀ + h v₀ + h²((½ − β) a₀ + β a₁),  v₁ = v₀ + h((1 − γ) a₀ + γ a₁),
  // is y₁ = L⁻¹R y₀. As Ω → ∞ (the first row divided by Ω²) L⁻¹R tends to a matrix whose three
  // eigenvalues are all −ρ∞ (Chung & Hulbert 1993 §3: the principal roots meet at −ρ∞, the
  // spurious one is −α_f/(1 − α_f) = −ρ∞): its characteristic polynomial is (λ + ρ∞)³, so its
  // trace, sum of principal 2 × 2 minors and determinant are −3ρ∞, 3ρ∞², −ρ∞³. (The eigenvalues
  // themselves are a defective triple root, computable only to ~ε^⅓.) O(1) entries: 1e-14.
  for (const double rho : {1.0, 0.9, 0.5, 0.0}) {
    const auto p = solvers::GeneralizedAlphaParameters::from_spectral_radius(rho);
    Eigen::Matrix3d L, R;
    L << 1 - p.alpha_f, 0, 0, 1, 0, -p.beta, 0, 1, -p.gamma;
    R << -p.alpha_f, 0, 0, 1, 1, 0.5 - p.beta, 0, 1, 1 - p.gamma;
    const Eigen::Matrix3d A = L.fullPivLu().solve(R);
    const double minors = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0) + A(0, 0) * A(2, 2) - A(0, 2) * A(2, 0) +
                          A(1, 1) * A(2, 2) - A(1, 2) * A(2, 1);
    INFO("rho_infinity = " << rho << ": trace " << A.trace() << ", minors " << minors << ", det " << A.determinant());
    CHECK(std::abs(A.trace() + 3 * rho) <= 1e-14);
    CHECK(std::abs(minors - 3 * rho * rho) <= 1e-14);
    CHECK(std::abs(A.determinant() + rho * rho * rho) <= 1e-14);
  }
  // The published end points (Chung & Hulbert 1993 eq. (25) with second order and maximal
  // high-frequency dissipation), as numbers: ρ∞ = 1 is the trapezoidal rule, ρ∞ = 0 annihilates.
  const auto trapezoidal = solvers::GeneralizedAlphaParameters::from_spectral_radius(1.0);
  CHECK(trapezoidal.alpha_m == 0.5);
  CHECK(trapezoidal.alpha_f == 0.5);
  CHECK(trapezoidal.gamma == 0.5);
  CHECK(trapezoidal.beta == 0.25);
  const auto annihilating = solvers::GeneralizedAlphaParameters::from_spectral_radius(0.0);
  CHECK(annihilating.alpha_m == -1.0);
  CHECK(annihilating.alpha_f == 0.0);
  CHECK(annihilating.gamma == 1.5);
  CHECK(annihilating.beta == 1.0);
  CHECK_THROWS_AS(solvers::GeneralizedAlphaParameters::from_spectral_radius(1.5), Error);
}
