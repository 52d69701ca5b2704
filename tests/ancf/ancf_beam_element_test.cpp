// The ANCF beam elements (docs/ancf.md): the section-integrated Piola–Kirchhoff force and its
// analytic Jacobian against finite differences and against a direct Gauss volume integration of
// the same energy; strain-free rigid motions; the mass matrix and the weight.
#include <spar/elements/ancf/ancf_beam.hpp>
#include <spar/elements/ancf/ancf_beam_element.hpp>
#include <spar/core/check_element.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <limits>
#include <random>

#include "ancf_reference.hpp"

using namespace spar;

namespace {

const core::Material material{.young_modulus = 1000.0, .poisson_ratio = 0.3, .density = 2.0};
const double length = 0.5;

// An L-angle a few times thinner than the element (fourth-order moments matter), off the
// reference line.
std::vector<Eigen::Vector2d> l_angle() {
  return {{-0.02, -0.01}, {0.06, -0.01}, {0.06, 0.01}, {0.0, 0.01}, {0.0, 0.05}, {-0.02, 0.05}};
}

template <int transverse>
struct OneElement {
  core::Model model;
  const core::AncfBeamElement<transverse>* element = nullptr;

  explicit OneElement(const core::SectionIntegrals& section,
                      core::AncfForceMethod method = core::AncfForceMethod::gerstmayr,
                      core::AncfLockingRemedy remedy = core::AncfLockingRemedy::none, double shear_factor = 1.0) {
    const core::AncfBeam beam = core::add_ancf_beam(
        model, {.start = Eigen::Vector3d(0.1, -0.2, 0.3),
                .end = Eigen::Vector3d(0.1, -0.2, 0.3) + length * Eigen::Vector3d(1, 2, 2) / 3.0,
                .y_direction = Eigen::Vector3d(0, 0, 1),
                .kind = transverse == 2 ? core::AncfElementKind::standard_24 : core::AncfElementKind::higher_order_30,
                .method = method,
                .remedy = remedy,
                .shear_factor = shear_factor,
                .material = material,
                .section = section});
    element = dynamic_cast<const core::AncfBeamElement<transverse>*>(&model.element(beam.elements[0]));
  }
};

/// A large deformation: e0 plus random changes of 10 % in positions (relative to l) and gradients.
template <int transverse>
typename core::AncfBeamElement<transverse>::Vector deformed(const OneElement<transverse>& one, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  auto e = one.element->coordinates(one.model.state());
  for (int k = 0; k < e.size(); ++k) e(k) += u(gen) * ((k % 12) < 3 ? length : 1.0);
  return e;
}

double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& reference) {
  return (a - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

template <int transverse>
void check_against_finite_differences(const core::SectionIntegrals& section, core::AncfForceMethod method,
                                      core::AncfLockingRemedy remedy = core::AncfLockingRemedy::none,
                                      double shear_factor = 1.0) {
  OneElement<transverse> one(section, method, remedy, shear_factor);
  using Vector = typename core::AncfBeamElement<transverse>::Vector;
  using Matrix = typename core::AncfBeamElement<transverse>::Matrix;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Vector e = deformed(one, seed);
    // The element at e, in statics without gravity: its residual is the elastic force Q, its
    // stiffness K = ∂Q/∂e, its potential the strain energy U.
    core::Configuration q = one.model.state();
    Eigen::Index k = 0;
    for (const int b : one.element->blocks()) {
      q.vector(b) = e.segment(k, q.blocks[b].size);
      k += q.blocks[b].size;
    }
    // Central differences with step 1e-6 on coordinates of size ≤ 1: truncation ε²|U'''|/6 ≈ 1e-12
    // relative, round-off u |U| / ε ≈ 1e-10 relative to |Q| (U ≈ |Q| · 0.1): 1e-7 relative to the
    // largest entry of each difference leaves margin.
    const core::DerivativeCheck check = core::check_element(
        *one.element, {.q = &q}, {.step = 1e-6, .tolerance = 1e-7, .scale_floor = 0.0, .potential = true});
    INFO("seed " << seed << ", " << e.size() << " coordinates\n" << check.description());
    CHECK(check.passed());
    Vector Q;
    Matrix K;
    one.element->elastic_force(e, Q, &K);
    CHECK(relative_error(K, K.transpose()) < 1e-14);
  }
}

template <int transverse>
void check_against_volume_integration(const core::SectionIntegrals& section, const test::SectionQuadrature& rule,
                                      double shear_factor = 1.0) {
  OneElement<transverse> one(section, core::AncfForceMethod::gerstmayr, core::AncfLockingRemedy::none, shear_factor);
  using Vector = typename core::AncfBeamElement<transverse>::Vector;
  using Matrix = typename core::AncfBeamElement<transverse>::Matrix;
  for (unsigned seed : {4u, 5u}) {
    const Vector e = deformed(one, seed);
    Vector Q;
    Matrix K;
    const double U = one.element->elastic_force(e, Q, &K);
    const auto reference = test::volume_reference(*one.element, rule, e);
    // Both routes are exact (polynomial integrands within both rules' degrees) and differ only in
    // the order of O(100) summations with cancellation between the terms of E (≈ 1 − 1): 1e-11.
    INFO("seed " << seed << ": U = " << U << ", reference " << reference.energy);
    CHECK(std::fabs(U - reference.energy) <= 1e-11 * reference.energy);
    CHECK(relative_error(Q, reference.force) < 1e-11);
    CHECK(relative_error(K, reference.stiffness) < 1e-11);
  }
  CHECK(relative_error(one.element->mass_matrix(), test::volume_reference(*one.element, rule, Vector::Zero()).mass) < 1e-13);
}

}  // namespace

TEST_CASE("ANCF force and Jacobian against finite differences", "[ancf][element]") {
  for (const auto method : {core::AncfForceMethod::gerstmayr, core::AncfForceMethod::invariant}) {
    INFO((method == core::AncfForceMethod::gerstmayr ? "method II" : "method I"));
    check_against_finite_differences<2>(core::SectionIntegrals::circle(0.03), method);
    check_against_finite_differences<2>(core::SectionIntegrals::polygon(l_angle()), method);
    check_against_finite_differences<3>(core::SectionIntegrals::circle(0.03), method);
    check_against_finite_differences<3>(core::SectionIntegrals::polygon(l_angle()), method);
  }
}

template <int transverse>
void check_methods_agree(const core::SectionIntegrals& section,
                         core::AncfLockingRemedy remedy = core::AncfLockingRemedy::none, double shear_factor = 1.0) {
  OneElement<transverse> one(section, core::AncfForceMethod::gerstmayr, remedy, shear_factor);
  OneElement<transverse> two(section, core::AncfForceMethod::invariant, remedy, shear_factor);
  using Vector = typename core::AncfBeamElement<transverse>::Vector;
  using Matrix = typename core::AncfBeamElement<transverse>::Matrix;
  for (unsigned seed : {6u, 7u}) {
    const Vector e = deformed(one, seed);
    Vector Q1, Q2;
    Matrix K1, K2;
    const double U1 = one.element->elastic_force(e, Q1, &K1), U2 = two.element->elastic_force(e, Q2, &K2);
    // Method I sums terms of size λ|e|⁴ that cancel down to the strain energy (E ≈ 0.1 here):
    // its round-off is ≈ 1e-16 · λ|e|⁴ / (E² λ) ≈ 1e-14 relative; 1e-12 leaves margin.
    CHECK(std::fabs(U1 - U2) <= 1e-12 * U1);
    CHECK(relative_error(Q2, Q1) < 1e-12);
    CHECK(relative_error(K2, K1) < 1e-12);
  }
}

TEST_CASE("ANCF methods I (invariant) and II (Gerstmayr) agree to round-off", "[ancf][element]") {
  check_methods_agree<2>(core::SectionIntegrals::polygon(l_angle()));
  check_methods_agree<3>(core::SectionIntegrals::polygon(l_angle()));
  check_methods_agree<2>(core::SectionIntegrals::circle(0.03).truncated_to_second_order());
}

TEST_CASE("ANCF section integrals reproduce a direct volume integration", "[ancf][element]") {
  SECTION("24 coordinates, L-angle") {
    check_against_volume_integration<2>(core::SectionIntegrals::polygon(l_angle()), test::polygon_quadrature(l_angle()));
  }
  SECTION("30 coordinates, L-angle") {
    check_against_volume_integration<3>(core::SectionIntegrals::polygon(l_angle()), test::polygon_quadrature(l_angle()));
  }
  SECTION("24 coordinates, off-centre circle") {
    check_against_volume_integration<2>(core::SectionIntegrals::circle(0.03, {0.01, -0.02}),
                                        test::circle_quadrature(0.03, {0.01, -0.02}));
  }
}

TEST_CASE("ANCF Poisson locking remedy: derivatives and both methods", "[ancf][element]") {
  const auto remedy = core::AncfLockingRemedy::uniaxial_bending;
  for (const auto method : {core::AncfForceMethod::gerstmayr, core::AncfForceMethod::invariant}) {
    check_against_finite_differences<2>(core::SectionIntegrals::polygon(l_angle()), method, remedy);
    check_against_finite_differences<3>(core::SectionIntegrals::circle(0.03), method, remedy);
  }
  check_methods_agree<2>(core::SectionIntegrals::polygon(l_angle()), remedy);
  check_methods_agree<3>(core::SectionIntegrals::polygon(l_angle()), remedy);
  // The remedy changes only the section-varying axial strain: a uniform stretch with free
  // lateral contraction and a rigid rotation give the same energy as without it.
  OneElement<2> with(core::SectionIntegrals::polygon(l_angle()), core::AncfForceMethod::gerstmayr, remedy);
  OneElement<2> without(core::SectionIntegrals::polygon(l_angle()));
  auto e = with.element->coordinates(with.model.state());
  for (int k = 0; k < 8; ++k) e.segment<3>(3 * k) *= (k % 4 == 0 || k % 4 == 1) ? 1.1 : 0.97;
  core::AncfBeam24Element::Vector Q1, Q2;
  const double U1 = with.element->elastic_force(e, Q1, nullptr), U2 = without.element->elastic_force(e, Q2, nullptr);
  CHECK(std::fabs(U1 - U2) <= 1e-13 * U2);
  CHECK(relative_error(Q1, Q2) < 1e-13);
}

TEST_CASE("ANCF shear factor: force and Jacobian against finite differences", "[ancf][element][shear]") {
  // k = 5/6 (a rectangle's Timoshenko factor); with the remedy k = 0.6, so that neither term hides
  // in the other. The excess (k − 1)μ is 17 % and 40 % of μ: a wrong term fails by O(1e-2).
  using core::AncfLockingRemedy;
  const double k = 5.0 / 6.0;
  const auto circle = core::SectionIntegrals::circle(0.03), angle = core::SectionIntegrals::polygon(l_angle());
  for (const auto method : {core::AncfForceMethod::gerstmayr, core::AncfForceMethod::invariant}) {
    INFO((method == core::AncfForceMethod::gerstmayr ? "method II" : "method I"));
    check_against_finite_differences<2>(circle, method, AncfLockingRemedy::none, k);
    check_against_finite_differences<2>(angle, method, AncfLockingRemedy::none, k);
    check_against_finite_differences<3>(circle, method, AncfLockingRemedy::none, k);
    check_against_finite_differences<3>(angle, method, AncfLockingRemedy::none, k);
    check_against_finite_differences<2>(angle, method, AncfLockingRemedy::uniaxial_bending, 0.6);
    check_against_finite_differences<3>(angle, method, AncfLockingRemedy::uniaxial_bending, 0.6);
  }
}

TEST_CASE("ANCF shear factor: methods I and II agree to round-off", "[ancf][element][shear]") {
  check_methods_agree<2>(core::SectionIntegrals::polygon(l_angle()), core::AncfLockingRemedy::none, 5.0 / 6.0);
  check_methods_agree<3>(core::SectionIntegrals::polygon(l_angle()), core::AncfLockingRemedy::none, 5.0 / 6.0);
  check_methods_agree<2>(core::SectionIntegrals::circle(0.03), core::AncfLockingRemedy::uniaxial_bending, 0.6);
  check_methods_agree<3>(core::SectionIntegrals::polygon(l_angle()), core::AncfLockingRemedy::uniaxial_bending, 0.6);
}

TEST_CASE("ANCF shear factor against a direct volume integration of S_xy = 2k mu E_xy", "[ancf][element][shear]") {
  // The reference evaluates the modified law point by point (tests/support/ancf_reference.hpp):
  // this proves the energy itself, which the finite differences only prove self-consistent.
  check_against_volume_integration<2>(core::SectionIntegrals::polygon(l_angle()), test::polygon_quadrature(l_angle()),
                                      5.0 / 6.0);
  check_against_volume_integration<3>(core::SectionIntegrals::circle(0.03, {0.01, -0.02}),
                                      test::circle_quadrature(0.03, {0.01, -0.02}), 5.0 / 6.0);
}

TEST_CASE("ANCF shear factor: the energy it scales, torsion, and the locking remedy beside it",
          "[ancf][element][shear]") {
  using core::AncfLockingRemedy;
  const auto section = core::SectionIntegrals::polygon(l_angle());
  for (const auto method : {core::AncfForceMethod::gerstmayr, core::AncfForceMethod::invariant}) {
    INFO((method == core::AncfForceMethod::gerstmayr ? "method II" : "method I"));
    const auto energy = [&](double k, AncfLockingRemedy remedy) {
      OneElement<3> one(section, method, remedy, k);
      core::AncfBeam30Element::Vector Q;
      return one.element->elastic_force(deformed(one, 8), Q, nullptr);
    };
    // W(k) = W(1) + (k − 1) 2μ (E_xy² + E_xz²) (eq. A22): U is affine in k, at a large strain:
    // U(5/6) − U(1) = (5/6 − 1)/(1/2 − 1) (U(1/2) − U(1)). Round-off ≈ 1e-14 of U (method I): 1e-12.
    const double U1 = energy(1.0, AncfLockingRemedy::none), U56 = energy(5.0 / 6.0, AncfLockingRemedy::none);
    const double U12 = energy(0.5, AncfLockingRemedy::none);
    CHECK(std::fabs((U56 - U1) - (U12 - U1) / 3) <= 1e-12 * U1);
    CHECK(U56 < U1);
    // The remedy (eq. A21) acts on E_xx only, k on E_xy, E_xz only: its correction does not
    // depend on k (docs/ancf.md §7).
    const double R1 = energy(1.0, AncfLockingRemedy::uniaxial_bending);
    const double R56 = energy(5.0 / 6.0, AncfLockingRemedy::uniaxial_bending);
    CHECK(std::fabs((R56 - U56) - (R1 - U1)) <= 1e-12 * U1);
    CHECK(R1 < U1);
  }
  // Torsion lives in E_xy, E_xz (E_xy = −½ z θ′, E_xz = ½ y θ′ for a twist rate θ′), so k scales
  // the torsional stiffness: a unit twist of node B about the axis has 2U = dᵀK d = k G I_p / l,
  // I_p = ∫ (y² + z²) dA about the reference line (the section does not warp).
  for (const double k : {1.0, 5.0 / 6.0}) {
    OneElement<2> one(section, core::AncfForceMethod::gerstmayr, AncfLockingRemedy::none, k);
    const auto e0 = one.element->coordinates(one.model.state());
    const Eigen::Vector3d t = e0.segment<3>(15);  // r_x,B: the axis
    core::AncfBeam24Element::Vector d = core::AncfBeam24Element::Vector::Zero();
    d.segment<3>(18) = t.cross(Eigen::Vector3d(e0.segment<3>(18)));  // δr_y,B
    d.segment<3>(21) = t.cross(Eigen::Vector3d(e0.segment<3>(21)));  // δr_z,B
    core::AncfBeam24Element::Vector Q;
    core::AncfBeam24Element::Matrix K;
    one.element->elastic_force(e0, Q, &K);
    const double Ip = section.moment(2, 0) + section.moment(0, 2);
    CHECK(d.dot(K * d) == Approx(k * material.shear_modulus() * Ip / length).epsilon(1e-12));
  }
}

TEST_CASE("ANCF shear factor input errors", "[ancf][element][shear]") {
  // 0 < k ≤ 1: k ≤ 0 leaves no shear stiffness, and above 1 is the reciprocal (form factor A/A_s).
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const double k : {0.0, -0.5, 1.2, nan, inf}) {
    INFO("k = " << k);
    core::Model model;
    const int blocks = model.state().block_count();
    CHECK_THROWS_WITH(core::add_ancf_beam(model, {.shear_factor = k, .material = material,
                                                  .section = core::SectionIntegrals::circle(0.01)}),
                      Catch::Contains("shear correction factor") && Catch::Contains("add_ancf_beam"));
    CHECK(model.state().block_count() == blocks);  // refused before anything is added
    CHECK_THROWS_WITH(core::AncfElementTables<3>(1.0, material, core::SectionIntegrals::circle(0.01),
                                                 core::AncfForceMethod::invariant, core::AncfLockingRemedy::none, k),
                      Catch::Contains("shear correction factor"));
  }
  for (const double k : {1.0, 1e-3}) {
    core::Model model;
    CHECK_NOTHROW(core::add_ancf_beam(model, {.shear_factor = k, .material = material,
                                              .section = core::SectionIntegrals::circle(0.01)}));
  }
}

TEST_CASE("ANCF rigid motions are strain free", "[ancf][element]") {
  OneElement<2> one(core::SectionIntegrals::polygon(l_angle()));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(2.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  auto e = one.element->coordinates(one.model.state());
  for (int k = 0; k < 8; ++k)
    e.segment<3>(3 * k) = R * e.segment<3>(3 * k) + ((k % 4) == 0 ? Eigen::Vector3d(1, 2, 3) : Eigen::Vector3d::Zero());
  core::AncfBeam24Element::Vector Q;
  const double U = one.element->elastic_force(e, Q, nullptr);
  // Round-off of E = ½(FᵀF − I) with O(1) entries is ≈ 1e-16: U ≈ E l A ε² and |Q| ≈ E A ε.
  const double EA = material.young_modulus * one.element->tables().moment[0][0][0][0];
  CHECK(std::fabs(U) < 1e-28 * EA * length);
  CHECK(Q.cwiseAbs().maxCoeff() < 1e-13 * EA);
}

TEST_CASE("ANCF uniform stretch against the closed form", "[ancf][element]") {
  // ν = 0, r = (1 + ε) x: E₁₁ = ((1 + ε)² − 1)/2, U = ½ E A l E₁₁², N = ∂U/∂(l ε)... at node B
  // the axial force is E A E₁₁ (1 + ε) (P₁₁ = F₁₁ S₁₁).
  const core::Material no_poisson{.young_modulus = 1000.0, .poisson_ratio = 0.0, .density = 2.0};
  core::Model model;
  const auto section = core::SectionIntegrals::rectangle(0.02, 0.01);
  const core::AncfBeam beam = core::add_ancf_beam(model, {.end = Eigen::Vector3d(length, 0, 0), .material = no_poisson,
                                                          .section = section});
  const auto& element = dynamic_cast<const core::AncfBeam24Element&>(model.element(beam.elements[0]));
  const double eps = 0.2;
  auto e = element.coordinates(model.state());
  e.segment<3>(12) *= 1 + eps;  // r_B
  e.segment<3>(3) *= 1 + eps;   // r_x,A
  e.segment<3>(15) *= 1 + eps;  // r_x,B
  core::AncfBeam24Element::Vector Q;
  const double U = element.elastic_force(e, Q, nullptr);
  const double E11 = ((1 + eps) * (1 + eps) - 1) / 2, A = section.area();
  CHECK(U == Approx(0.5 * 1000.0 * A * length * E11 * E11).epsilon(1e-13));
  CHECK(Q(12) == Approx(1000.0 * A * E11 * (1 + eps)).epsilon(1e-13));
}

TEST_CASE("ANCF mass and weight", "[ancf][element]") {
  core::Model model;
  const auto section = core::SectionIntegrals::circle(0.02);
  const core::AncfBeam beam = core::add_ancf_beam(model, {.end = Eigen::Vector3d(length, 0, 0), .kind = core::AncfElementKind::higher_order_30,
                                                          .material = material, .section = section});
  const auto& element = dynamic_cast<const core::AncfBeam30Element&>(model.element(beam.elements[0]));
  const double m = material.density * section.area() * length;
  // A rigid translation v: kinetic energy ½ m |v|²; the weight sums to m g on the positions.
  auto v = core::AncfBeam30Element::Vector::Zero().eval();
  v.segment<3>(0) = v.segment<3>(12) = Eigen::Vector3d(1, -2, 0.5);
  CHECK(0.5 * v.dot(element.mass_matrix() * v) == Approx(0.5 * m * 5.25).epsilon(1e-14));
  const auto& w = element.tables().gravity_weights;
  CHECK(w(0) + w(4) == Approx(m).epsilon(1e-14));
  CHECK(w(1) == Approx(m * length / 12).epsilon(1e-14));  // Hermite: ∫ S2 dx = l²/12
  CHECK(w(2) == 0.0);  // a centred section: no first moment
}

TEST_CASE("ANCF element input errors", "[ancf][element]") {
  core::Model model;
  CHECK_THROWS_AS(core::add_ancf_beam(model, {.elements = 0, .material = material,
                                              .section = core::SectionIntegrals::circle(0.01)}), Error);
  CHECK_THROWS_AS(core::add_ancf_beam(model, {.y_direction = Eigen::Vector3d::UnitX(), .material = material,
                                              .section = core::SectionIntegrals::circle(0.01)}), Error);
  const core::AncfBeam beam = core::add_ancf_beam(model, {.material = material, .section = core::SectionIntegrals::circle(0.01)});
  // A curved reference configuration is refused.
  core::Configuration bent = model.state();
  bent.vector(beam.nodes[1]).segment<3>(3) = Eigen::Vector3d(1, 1, 0).normalized();
  const auto tables = std::make_shared<const core::AncfElementTables<2>>(1.0, material, core::SectionIntegrals::circle(0.01));
  CHECK_THROWS_AS(core::AncfBeam24Element({beam.nodes[0], beam.nodes[1]}, tables, bent, 0), Error);
  CHECK_THROWS_AS(core::add_ancf_nodal_force(model, 99, Eigen::Vector3d::UnitZ()), Error);
}

TEST_CASE("ANCF beams of short elements far from the origin build (issue 29)", "[ancf][element]") {
  // Each element compares its nodes' distance with the tables' length. That distance is a
  // difference of two positions, each rounded to its own magnitude: 1e4 m from the origin a
  // 5 cm element's length is known only to ~2e-12 m, and a test of 1e-12 of the length alone
  // (5e-14 m) refused the beam; so did ancf_cantilever from ~10⁴ elements of its 1 m beam.
  for (const double distance : {0.0, 1e4}) {
    core::Model model;
    const Eigen::Vector3d start(distance, 0, 0);
    const core::AncfBeam beam = core::add_ancf_beam(
        model, {.start = start, .end = start + Eigen::Vector3d(1, 0, 0), .elements = 20, .material = material,
                .section = core::SectionIntegrals::circle(0.01)});
    CHECK(beam.elements.size() == 20);
  }
  core::Model model;
  const core::AncfBeam fine = core::add_ancf_beam(
      model, {.elements = 20000, .material = material, .section = core::SectionIntegrals::circle(0.01)});
  CHECK(fine.element_length == Approx(5e-5).epsilon(1e-12));
  // A length that is truly another is still refused: 1e-9 of a 1 m element.
  core::Model one;
  const core::AncfBeam beam = core::add_ancf_beam(one, {.material = material, .section = core::SectionIntegrals::circle(0.01)});
  core::Configuration stretched = one.state();
  stretched.vector(beam.nodes[1]).head<3>() += Eigen::Vector3d(1e-9, 0, 0);
  const auto tables = std::make_shared<const core::AncfElementTables<2>>(1.0, material, core::SectionIntegrals::circle(0.01));
  CHECK_THROWS_WITH(core::AncfBeam24Element({beam.nodes[0], beam.nodes[1]}, tables, stretched, 0),
                    Catch::Contains("apart"));
}
