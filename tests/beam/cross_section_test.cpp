// Cross-section helpers against closed forms, and the stiffness matrix layout of 003 eq. (15).
#include <spar/core/cross_section.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace spar;

TEST_CASE("rectangle, circle and tube properties", "[gebt][section][validation]") {
  // The closed forms are a few products and one subtraction of doubles: 1e-15 relative is a few
  // roundings; 1e-14 where the tube's d⁴ − D⁴ or the circle's π r⁴ cancel or compound roundings
  // (a wrong factor or exponent is off by O(1)).
  const double pi = std::numbers::pi;
  const core::CrossSection square = core::CrossSection::rectangle(0.03, 0.03, 0.3);
  CHECK(square.area == Approx(9e-4).epsilon(1e-15));
  CHECK(square.second_moment_2 == Approx(std::pow(0.03, 4) / 12).epsilon(1e-15));
  // Saint-Venant: J = 0.140577 a⁴ for a square (Timoshenko & Goodier table, 6 digits: ±5e-7 /
  // 0.14 = 4e-6 relative).
  CHECK(square.torsion_constant / std::pow(0.03, 4) == Approx(0.140577).epsilon(4e-6));
  CHECK(square.shear_coefficient_2 == Approx(10 * 1.3 / (12 + 3.3)).epsilon(1e-15));

  const core::CrossSection tube = core::CrossSection::tube(0.060, 0.055, 0.3);
  CHECK(tube.area == Approx(pi * (0.03 * 0.03 - 0.0275 * 0.0275)).epsilon(1e-14));
  // A thin-walled-or-not circular tube's torsion constant is its polar moment π(D⁴ − d⁴)/32.
  CHECK(tube.torsion_constant == Approx(pi * (std::pow(0.060, 4) - std::pow(0.055, 4)) / 32).epsilon(1e-14));
  const core::CrossSection circle = core::CrossSection::circle(0.02, 0.3);
  CHECK(circle.second_moment_2 == Approx(pi * std::pow(0.01, 4) / 4).epsilon(1e-14));
  CHECK(circle.shear_coefficient_2 == Approx(6 * 1.3 / (7 + 1.8)).epsilon(1e-15));
}

TEST_CASE("section stiffness matrix follows 003 eq. 15", "[gebt][section]") {
  // Each entry is one or two products of doubles given here in closed form: 1e-15 relative is a
  // few roundings (an entry in the wrong place is off by O(1)).
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  core::CrossSection section = core::CrossSection::rectangle(0.03, 0.02, 0.3);
  section.product_moment = 1e-9;
  const Eigen::Matrix<double, 6, 6> C = core::SectionStiffness::from(steel, section).matrix();
  const double G = 2.1e11 / (2 * 1.3), kappa = 10 * 1.3 / (12 + 3.3);  // Cowper's rectangle
  CHECK(C(0, 0) == Approx(2.1e11 * 6e-4).epsilon(1e-15));
  CHECK(C(1, 1) == Approx(kappa * G * 6e-4).epsilon(1e-15));
  CHECK(C(2, 2) == Approx(kappa * G * 6e-4).epsilon(1e-15));
  CHECK(C(4, 4) == Approx(2.1e11 * 0.03 * std::pow(0.02, 3) / 12).epsilon(1e-15));  // about axis 2: ∫ξ₃²
  CHECK(C(5, 5) == Approx(2.1e11 * 0.02 * std::pow(0.03, 3) / 12).epsilon(1e-15));  // about axis 3: ∫ξ₂²
  CHECK(C(4, 5) == Approx(-2.1e11 * 1e-9).epsilon(1e-15));
  CHECK(C(5, 4) == C(4, 5));
  const Eigen::Matrix<double, 6, 6> off_diagonal = C - Eigen::Matrix<double, 6, 6>(C.diagonal().asDiagonal());
  CHECK(off_diagonal.cwiseAbs().sum() == Approx(2 * 2.1e11 * 1e-9).epsilon(1e-15));  // nothing but C₂₃
  // Torsion G J against Timoshenko & Goodier's tabulated J = 0.140577 a⁴ of a square (6 digits:
  // ±5e-7 / 0.14 = 4e-6 relative).
  const core::CrossSection square = core::CrossSection::rectangle(0.03, 0.03, 0.3);
  const Eigen::Matrix<double, 6, 6> Cs = core::SectionStiffness::from(steel, square).matrix();
  CHECK(Cs(3, 3) == Approx(G * 0.140577 * std::pow(0.03, 4)).epsilon(4e-6));
}

TEST_CASE("invalid sections and materials raise spar::Error", "[gebt][section][errors]") {
  CHECK_THROWS_WITH(core::CrossSection::rectangle(-1.0, 0.1, 0.3), Catch::Contains("width"));
  CHECK_THROWS_WITH(core::CrossSection::tube(0.05, 0.06, 0.3), Catch::Contains("inner diameter"));
  core::SectionStiffness C;
  C.axial = 1;
  CHECK_THROWS_WITH(C.validate(), Catch::Contains("shear stiffness"));
  const core::Material bad{.young_modulus = 1e9, .poisson_ratio = 0.7, .density = 1};
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("Poisson"));
}
