// Section integrals (docs/ancf.md §3) against direct area integration: a circle, a rectangle and
// an L-angle (non-symmetric: every odd and mixed moment non-zero) as a polygon, as the union of
// two rectangles, and by a triangle quadrature.
#include <spar/core/section_integrals.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "ancf_reference.hpp"

using namespace spar;

namespace {

// Every route sums O(10) terms of size ≤ the largest moment of the same order: a few ulps each,
// so 1e-13 relative to the largest moment of that order.
constexpr double round_off = 1e-13;

/// The size of the moments of one order: the largest of them, or A·(√A)^order when they all
/// vanish by symmetry.
double largest_of_order(const core::SectionIntegrals& s, int order) {
  double m = s.area() * std::pow(std::sqrt(s.area()), order) * 1e-3;
  for (int a = 0; a <= order; ++a) m = std::max(m, std::fabs(s.moment(a, order - a)));
  return m;
}

void check_moments(const core::SectionIntegrals& s, const test::SectionQuadrature& q) {
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; a + b <= 4; ++b) {
      INFO("moment (" << a << ", " << b << "): " << s.moment(a, b) << " vs " << test::quadrature_moment(q, a, b));
      CHECK(std::fabs(s.moment(a, b) - test::quadrature_moment(q, a, b)) <=
            round_off * largest_of_order(s, a + b));
    }
}

// An L-angle 60 × 40 mm, 8 mm thick, corner at (−5, −3) mm from the reference line.
const double W = 0.06, H = 0.04, t = 0.008;
const Eigen::Vector2d corner(-0.005, -0.003);
std::vector<Eigen::Vector2d> l_angle() {
  const std::vector<Eigen::Vector2d> v{{0, 0}, {W, 0}, {W, t}, {t, t}, {t, H}, {0, H}};
  std::vector<Eigen::Vector2d> shifted;
  for (const auto& p : v) shifted.push_back(p + corner);
  return shifted;
}

}  // namespace

TEST_CASE("circle and rectangle integrals match direct quadrature", "[ancf][section]") {
  check_moments(core::SectionIntegrals::circle(0.01), test::circle_quadrature(0.01));
  check_moments(core::SectionIntegrals::circle(0.02, {0.003, -0.01}), test::circle_quadrature(0.02, {0.003, -0.01}));
  check_moments(core::SectionIntegrals::rectangle(0.03, 0.01, {0.01, 0.002}),
                test::rectangle_quadrature(0.03, 0.01, {0.01, 0.002}));
  const auto circle = core::SectionIntegrals::circle(0.01);
  CHECK(circle.area() == Approx(std::numbers::pi * 1e-4).epsilon(1e-15));
  CHECK(circle.second_moment_y() == Approx(std::numbers::pi * 1e-8 / 4).epsilon(1e-15));
  CHECK(circle.moment(4, 0) == Approx(std::numbers::pi * 1e-12 / 8).epsilon(1e-14));
  CHECK(circle.moment(2, 2) == Approx(std::numbers::pi * 1e-12 / 24).epsilon(1e-14));
}

TEST_CASE("an L-angle: polygon, union of rectangles and triangle quadrature agree", "[ancf][section]") {
  const auto polygon = core::SectionIntegrals::polygon(l_angle());
  const auto rectangles = core::SectionIntegrals::rectangle(t, H, corner + Eigen::Vector2d(t / 2, H / 2)) +
                          core::SectionIntegrals::rectangle(W - t, t, corner + Eigen::Vector2d((W + t) / 2, t / 2));
  check_moments(polygon, test::polygon_quadrature(l_angle()));
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; a + b <= 4; ++b)
      CHECK(std::fabs(polygon.moment(a, b) - rectangles.moment(a, b)) <= round_off * largest_of_order(polygon, a + b));
  // Non-symmetric: the product moment and the odd moments do not vanish.
  const double A = polygon.area(), yc = polygon.moment(1, 0) / A, zc = polygon.moment(0, 1) / A;
  const double Iyz = polygon.product_moment() - A * yc * zc, Iy = polygon.second_moment_y() - A * zc * zc,
               Iz = polygon.second_moment_z() - A * yc * yc;
  CHECK(std::fabs(Iyz) > 0.1 * std::sqrt(Iy * Iz));
  CHECK(std::fabs(polygon.moment(3, 0)) > 0.0);
  CHECK(polygon.area() == Approx((W + H - t) * t).epsilon(1e-14));
}

TEST_CASE("the paper's second-order section and input errors", "[ancf][section]") {
  const auto s = core::SectionIntegrals::second_order(2.0, 3.0, 4.0, 1.0);
  CHECK(s.area() == 2.0);
  CHECK(s.second_moment_y() == 3.0);
  CHECK(s.second_moment_z() == 4.0);
  CHECK(s.product_moment() == 1.0);
  CHECK(s.moment(4, 0) == 0.0);
  CHECK(s.moment(1, 0) == 0.0);
  CHECK_THROWS_AS(s.moment(3, 2), Error);
  // A section given by all fifteen integrals.
  core::SectionIntegrals::Moments m{};
  const auto circle = core::SectionIntegrals::circle(0.02, {0.01, 0.0});
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; a + b <= 4; ++b) m[a][b] = circle.moment(a, b);
  const auto given = core::SectionIntegrals::from_moments(m);
  CHECK(given.moment(3, 0) == circle.moment(3, 0));
  m[2][3] = 1.0;
  CHECK_THROWS_AS(core::SectionIntegrals::from_moments(m), Error);
  CHECK_THROWS_AS(core::SectionIntegrals::circle(-1.0), Error);
  CHECK_THROWS_AS(core::SectionIntegrals::second_order(1.0, 1.0, 1.0, 2.0), Error);
  // Clockwise vertices give a negative area.
  std::vector<Eigen::Vector2d> cw = l_angle();
  std::reverse(cw.begin(), cw.end());
  CHECK_THROWS_AS(core::SectionIntegrals::polygon(cw), Error);
}
