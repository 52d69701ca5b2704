// Rational Bézier curves of the ALE-RANCF element (paper 000): de Casteljau splitting in
// homogeneous coordinates (eq. (21)) reproduces the curve on both halves (eqs. (23), (25)) and
// keeps the nodal slopes (eq. (27)); RANCF ↔ Bézier conversions (eqs. (5), (6)) round-trip; the
// shape functions of eq. (9) interpolate the curve and reduce to ANCF's for equal weights (eq. (10)).
#include <spar/error.hpp>
#include <spar/iga/nurbs_curve.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace spar::iga;
using Catch::Contains;

namespace {

RationalBezier<3> sample_cubic(unsigned seed) {
  std::mt19937 engine(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), weight(0.5, 2.0);
  RationalBezier<3> cubic{RationalBezier<3>::Points(3, 4), Eigen::VectorXd(4)};
  for (int i = 0; i < 4; ++i) {
    for (int d = 0; d < 3; ++d) cubic.points(d, i) = coordinate(engine);
    cubic.weights(i) = weight(engine);
  }
  return cubic;
}

double bernstein(int i, int n, double u) {
  return std::tgamma(n + 1.0) / (std::tgamma(i + 1.0) * std::tgamma(n - i + 1.0)) *
         std::pow(u, i) * std::pow(1 - u, n - i);
}

// The Bézier as a NURBS on {0^4, 1^4}: its derivatives give the RANCF slopes independently.
NurbsCurve<3> as_nurbs(const RationalBezier<3>& cubic) {
  return NurbsCurve<3>(KnotVector({0, 0, 0, 0, 1, 1, 1, 1}, 3), cubic.points, cubic.weights);
}

}  // namespace

TEST_CASE("de Casteljau splitting reproduces the curve on both halves (000 eq. (23))",
          "[iga][validation]") {
  for (unsigned seed = 1; seed <= 5; ++seed)
    for (double u_h : {0.1, 0.37, 0.5, 0.9}) {
      const RationalBezier<3> curve = sample_cubic(seed);
      const BezierSplit<3> halves = split(curve, u_h);
      // Eq. (21) written out with Bernstein polynomials: w̄_k = Σ_{i≤k} B_{i,k}(u_H) w_i.
      for (int k = 0; k <= 3; ++k) {
        double expected = 0.0;
        for (int i = 0; i <= k; ++i) expected += bernstein(i, k, u_h) * curve.weights(i);
        CHECK(halves.left.weights(k) == Approx(expected).epsilon(1e-14));
      }
      CHECK(halves.right.weights(1) ==
            Approx(bernstein(0, 2, u_h) * curve.weights(1) + bernstein(1, 2, u_h) * curve.weights(2) +
                   bernstein(2, 2, u_h) * curve.weights(3))
                .epsilon(1e-14));
      double worst = 0.0;
      for (int i = 0; i <= 1000; ++i) {
        const double u = i / 1000.0;
        const Eigen::Vector3d r = curve.point(u);
        const Eigen::Vector3d half = u <= u_h ? halves.left.point(u / u_h)
                                              : halves.right.point((u - u_h) / (1 - u_h));
        worst = std::max(worst, (half - r).norm());
      }
      // Convex combinations of points in [−1, 1]³; u/u_H adds one rounding: 1e-14 absolute.
      CHECK(worst <= 1e-14);
      // Eq. (27): the RANCF slopes of the halves (lengths u_H·l and (1 − u_H)·l, eq. (28)) equal
      // the original slopes at A, B and H; the slope at H is dr/du(u_H)/l.
      const double l = 2.0;
      const RancfElement<3> whole = rancf_from_bezier(curve, l);
      const RancfElement<3> ah = rancf_from_bezier(halves.left, u_h * l);
      const RancfElement<3> hb = rancf_from_bezier(halves.right, (1 - u_h) * l);
      const Eigen::Vector3d slope_h = as_nurbs(curve).derivatives(u_h, 1).col(1) / l;
      CHECK((ah.e.segment<3>(3) - whole.e.segment<3>(3)).norm() <= 1e-13);
      CHECK((hb.e.segment<3>(9) - whole.e.segment<3>(9)).norm() <= 1e-13);
      CHECK((ah.e.segment<3>(9) - slope_h).norm() <= 1e-13 * slope_h.norm());
      CHECK((hb.e.segment<3>(3) - slope_h).norm() <= 1e-13 * slope_h.norm());
      CHECK((ah.e.segment<3>(6) - curve.point(u_h)).norm() <= 1e-14);
    }
}

TEST_CASE("RANCF ↔ rational cubic Bézier conversions round-trip (000 eqs. (5), (6))",
          "[iga][validation]") {
  for (unsigned seed = 11; seed <= 15; ++seed) {
    const RationalBezier<3> cubic = sample_cubic(seed);
    const double l = 0.75;
    const RancfElement<3> element = rancf_from_bezier(cubic, l);
    // Eq. (5) against the curve's own derivatives: r_x = (dr/du)/l at both ends.
    const NurbsCurve<3> nurbs = as_nurbs(cubic);
    CHECK((element.e.segment<3>(3) - nurbs.derivatives(0.0, 1).col(1) / l).norm() <= 1e-13);
    CHECK((element.e.segment<3>(9) - nurbs.derivatives(1.0, 1).col(1) / l).norm() <= 1e-13);
    const RationalBezier<3> back = bezier_from_rancf(element);
    // Each way is one multiply-add per coordinate: a few ulps of values ≤ ~10.
    CHECK((back.points - cubic.points).cwiseAbs().maxCoeff() <= 1e-14);
    CHECK(back.weights == cubic.weights);
    const RancfElement<3> again = rancf_from_bezier(back, l);
    CHECK((again.e - element.e).cwiseAbs().maxCoeff() <= 1e-13);
    // Eq. (9): r(u) = Σ s_k(u) e_k is the Bézier curve.
    for (int i = 0; i <= 20; ++i) {
      const double u = i / 20.0;
      const Eigen::Vector4d s = rancf_shape_functions(u, element.weights, l);
      const Eigen::Vector3d r = s(0) * element.e.segment<3>(0) + s(1) * element.e.segment<3>(3) +
                                s(2) * element.e.segment<3>(6) + s(3) * element.e.segment<3>(9);
      CHECK((r - cubic.point(u)).norm() <= 1e-14);
    }
  }
}

TEST_CASE("equal weights give the ANCF cubic Hermite shape functions (000 eq. (10))",
          "[iga][validation]") {
  const double l = 1.3;
  for (double u : {0.0, 0.2, 0.5, 0.81, 1.0}) {
    const Eigen::Vector4d s = rancf_shape_functions(u, Eigen::Vector4d::Constant(0.7), l);
    const Eigen::Vector4d hermite(1 - 3 * u * u + 2 * u * u * u, l * (u - 2 * u * u + u * u * u),
                                  3 * u * u - 2 * u * u * u, l * (-u * u + u * u * u));
    CHECK((s - hermite).cwiseAbs().maxCoeff() <= 1e-15);
  }
}

TEST_CASE("invalid rational Béziers raise spar::Error naming the problem", "[iga]") {
  RationalBezier<3> cubic = sample_cubic(3);
  CHECK_THROWS_WITH(split(cubic, 1.0), Contains("not inside (0, 1)"));
  CHECK_THROWS_WITH(rancf_from_bezier(cubic, 0.0), Contains("length"));
  cubic.weights(2) = -1.0;
  CHECK_THROWS_WITH(split(cubic, 0.5), Contains("weight ≤ 0"));
  RationalBezier<3> one_point{RationalBezier<3>::Points::Zero(3, 1), Eigen::VectorXd::Ones(1)};
  CHECK_THROWS_WITH(split(one_point, 0.5), Contains("too few control points"));
  RationalBezier<3> quadratic{RationalBezier<3>::Points::Zero(3, 3), Eigen::VectorXd::Ones(3)};
  CHECK_THROWS_WITH(rancf_from_bezier(quadratic, 1.0), Contains("degree 2"));
  CHECK_THROWS_WITH(quadratic.point(1.5), Contains("outside"));
}

TEST_CASE("rancf_shape_function_derivatives: values and three derivatives", "[iga][rancf]") {
  // Column 0 is rancf_shape_functions with s_2, s_4 divided by l; columns 1 … 3 against central
  // differences of the previous column (h = 1e-5: truncation ~1e-10 on O(10) third derivatives,
  // round-off ~1e-11; 1e-7).
  const Eigen::Vector4d w(1.0, 0.7, 1.3, 0.9);
  const double l = 0.8, h = 1e-5;
  for (double u : {1e-3, 0.27, 0.5, 0.93}) {
    const Eigen::Matrix4d s = spar::iga::rancf_shape_function_derivatives(u, w);
    const Eigen::Vector4d plain = spar::iga::rancf_shape_functions(u, w, l);
    CHECK((s.col(0) - Eigen::Vector4d(plain(0), plain(1) / l, plain(2), plain(3) / l)).cwiseAbs().maxCoeff() <= 1e-15);
    const Eigen::Matrix4d plus = spar::iga::rancf_shape_function_derivatives(u + h, w);
    const Eigen::Matrix4d minus = spar::iga::rancf_shape_function_derivatives(u - h, w);
    for (int d = 1; d <= 3; ++d)
      CHECK((s.col(d) - (plus.col(d - 1) - minus.col(d - 1)) / (2 * h)).cwiseAbs().maxCoeff() <=
            1e-7 * std::max(1.0, s.col(d).cwiseAbs().maxCoeff()));
  }
}

TEST_CASE("degree elevation and Möbius reparameterization keep the curve", "[iga]") {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const RationalBezier<3> cubic = sample_cubic(seed);
    const RationalBezier<3> quartic = elevate(cubic);
    REQUIRE(quartic.degree() == 4);
    const double rho = 0.4 + 0.3 * seed;
    const RationalBezier<3> moved = reparameterize(cubic, rho);
    const NurbsCurve<3> original = as_nurbs(cubic), reparameterized = as_nurbs(moved);
    for (int j = 0; j <= 20; ++j) {
      const double u = j / 20.0, t = rho * u / (rho * u + 1.0 - u);  // r̃(u) = r(t(u))
      // Round-off of a few de Casteljau levels on O(1) coordinates.
      CHECK((quartic.point(u) - cubic.point(u)).norm() < 1e-14);
      CHECK((moved.point(u) - cubic.point(t)).norm() < 1e-14);
    }
    // The end derivatives scale by ρ at u = 0 and by 1/ρ at u = 1.
    const Eigen::Matrix<double, 3, 2> d0 = original.derivatives(0.0, 1), d1 = original.derivatives(1.0, 1);
    CHECK((reparameterized.derivatives(0.0, 1).col(1) - rho * d0.col(1)).norm() < 1e-13 * d0.col(1).norm());
    CHECK((reparameterized.derivatives(1.0, 1).col(1) - d1.col(1) / rho).norm() < 1e-13 * d1.col(1).norm());
  }
  // The rational quadratic arc of A7.1 elevated is 000 eq. (43)'s cubic: w1 = w2 = (1 + 2 cos(θ/2))/3.
  const double theta = 0.7;
  RationalBezier<2> arc{RationalBezier<2>::Points(2, 3), Eigen::Vector3d(1.0, std::cos(theta / 2), 1.0)};
  arc.points << 1.0, 1.0, std::cos(theta), 0.0, std::tan(theta / 2), std::sin(theta);
  const RationalBezier<2> cubic = elevate(arc);
  CHECK(cubic.weights(1) / cubic.weights(0) == Approx((1 + 2 * std::cos(theta / 2)) / 3).epsilon(1e-15));
  CHECK(cubic.weights(2) / cubic.weights(0) == Approx((1 + 2 * std::cos(theta / 2)) / 3).epsilon(1e-15));
  for (int j = 0; j <= 10; ++j) CHECK(std::abs(cubic.point(j / 10.0).norm() - 1.0) < 1e-15);
  CHECK_THROWS_WITH(reparameterize(cubic, 0.0), Contains("ρ = 0"));
}
