// NURBS curves: points against the defining sum, derivatives against finite differences,
// curvature, arc length and its inverse, point inversion, and input validation.
#include <spar/error.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "spline_samples.hpp"

using namespace spar::iga;
using Catch::Contains;

TEST_CASE("curve points equal Σ R_i P_i with R_i = w_i N_i / Σ w_j N_j", "[iga]") {
  spar::test::SplineSamples samples(17);
  const KnotVector U = samples.knot_vector(3, 4, 2);
  const NurbsCurve<3> curve = samples.curve<3>(U);
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    BasisTable N;
    const int span = U.find_span(u);
    basis_derivatives(U, span, u, 0, N);
    Eigen::Vector3d numerator = Eigen::Vector3d::Zero();
    double denominator = 0.0;
    for (int j = 0; j <= 3; ++j) {
      const int index = span - 3 + j;
      numerator += N(0, j) * curve.weights()(index) * curve.control_points().col(index);
      denominator += N(0, j) * curve.weights()(index);
    }
    // Two evaluation orders of the same sum of ≤ 4 terms of size ≤ 2: round-off only.
    CHECK((curve.point(u) - numerator / denominator).norm() <= 1e-14);
  }
  CHECK((curve.point(0.0) - curve.control_points().col(0)).norm() <= 1e-15);
  CHECK((curve.point(1.0) - curve.control_points().rightCols<1>()).norm() <= 1e-15);
}

TEST_CASE("curve derivatives match finite differences", "[iga]") {
  spar::test::SplineSamples samples(19);
  for (int p = 1; p <= 5; ++p) {
    const KnotVector U = samples.knot_vector(p, 4, p);
    const NurbsCurve<3> curve = samples.curve<3>(U);
    // Step and tolerance as for the basis functions (basis_test.cpp): h = 1e-5, 1e-6 relative.
    constexpr double h = 1e-5;
    for (int e = 0; e < U.element_count(); ++e)
      for (int sample = 0; sample < 4; ++sample) {
        const double u = samples.inside(U, e, 10 * h);
        const auto D = curve.derivatives(u, 3);
        const auto plus = curve.derivatives(u + h, 3), minus = curve.derivatives(u - h, 3);
        REQUIRE(D.cols() == 4);
        for (int k = 1; k <= 3; ++k) {
          const Eigen::Vector3d fd = (plus.col(k - 1) - minus.col(k - 1)) / (2 * h);
          INFO("p = " << p << ", k = " << k << ", u = " << u);
          CHECK((D.col(k) - fd).norm() <= 1e-6 * std::max(1.0, D.col(k).norm()));
        }
      }
  }
}

TEST_CASE("plane curves: the unit tangent and the curvature of a parabola", "[iga][validation]") {
  // The quadratic Bézier with control points (−1, 1), (0, −1), (1, 1) is y = x²: C(u) = (2u−1,
  // (2u−1)²), κ = 2 / (1 + 4x²)^{3/2}.
  const KnotVector U({0, 0, 0, 1, 1, 1}, 2);
  NurbsCurve<2>::Points P(2, 3);
  P << -1, 0, 1, 1, -1, 1;
  const NurbsCurve<2> parabola(U, P);
  for (double u : {0.0, 0.1, 0.5, 0.77, 1.0}) {
    const double x = 2 * u - 1;
    CHECK((parabola.point(u) - Eigen::Vector2d(x, x * x)).norm() <= 1e-15);
    CHECK(parabola.curvature(u) == Approx(2.0 / std::pow(1 + 4 * x * x, 1.5)).epsilon(1e-14));
    CHECK((parabola.unit_tangent(u) - Eigen::Vector2d(1, 2 * x).normalized()).norm() <= 1e-15);
  }
}

TEST_CASE("invalid curves raise spar::Error naming the problem", "[iga]") {
  const KnotVector U = KnotVector::open_uniform(2, 2, 1);
  const NurbsCurve<3>::Points four = NurbsCurve<3>::Points::Random(3, 4);
  const NurbsCurve<3>::Points three = NurbsCurve<3>::Points::Random(3, 3);
  CHECK_THROWS_WITH(NurbsCurve<3>(U, three), Contains("too few control points"));
  CHECK_THROWS_WITH(NurbsCurve<3>(U, four, Eigen::Vector4d(1, 1, 0, 1)), Contains("weight ≤ 0"));
  CHECK_THROWS_WITH(NurbsCurve<3>(U, four, Eigen::Vector4d(1, -2, 1, 1)), Contains("weight ≤ 0"));
  CHECK_THROWS_WITH(NurbsCurve<3>(U, four, Eigen::Vector3d(1, 1, 1)), Contains("3 weights"));
  const NurbsCurve<3> curve(U, four);
  CHECK_THROWS_WITH(curve.point(1.5), Contains("outside the knot range"));
  CHECK_THROWS_WITH(curve.derivatives(0.5, max_derivative_order + 1), Contains("order 8"));
}

TEST_CASE("a weight lost to round-off beside the largest is refused, any common scale passes", "[iga]") {
  // Issue 29: a weight of 1e-300 beside 1 was accepted (its derivatives overflowed only later).
  const KnotVector U = KnotVector::open_uniform(2, 2, 1);
  const NurbsCurve<3>::Points P = NurbsCurve<3>::Points::Random(3, 4);
  for (const double tiny : {1e-300, 1e-17, 1e-16})
    CHECK_THROWS_WITH(NurbsCurve<3>(U, P, Eigen::Vector4d(1, tiny, 1, 1)),
                      Contains("weight 1 = ") && Contains("below machine epsilon times the largest weight"));
  CHECK_THROWS_WITH(NurbsCurve<3>(U, P, Eigen::Vector4d(1e300, 1, 1, 1)), Contains("largest weight"));
  // At the bound and above, and any common scale (the curve does not change under w -> c w).
  CHECK_NOTHROW(NurbsCurve<3>(U, P, Eigen::Vector4d(1, 1e-15, 1, 1)));
  CHECK_NOTHROW(NurbsCurve<3>(U, P, Eigen::Vector4d(1e-300, 2e-300, 1e-300, 1e-300)));
  CHECK_NOTHROW(NurbsCurve<3>(U, P, Eigen::Vector4d(1e300, 2e300, 1e300, 1e300)));
  const NurbsCurve<3> scaled(U, P, 1e-200 * Eigen::Vector4d(1, 0.5, 2, 1));
  const NurbsCurve<3> unscaled(U, P, Eigen::Vector4d(1, 0.5, 2, 1));
  for (const double u : {0.0, 0.3, 0.5, 0.8, 1.0})
    CHECK((scaled.derivatives(u, 2) - unscaled.derivatives(u, 2)).norm() <= 1e-13 * unscaled.derivatives(u, 2).norm());
}
