// NURBS arc length far from the origin (issue 29): the adaptive quadrature must converge relative to
// the curve, however far the curve lies from the origin, and end where its integrand |C′| stops
// being resolvable above round-off. Before the fix each of these never returned.
#include <spar/iga/circular_arc.hpp>
#include <spar/iga/knot_operations.hpp>
#include <spar/iga/nurbs_curve.hpp>
#include <spar/iga/straight_line.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

using namespace spar::iga;

namespace {

constexpr double u_round = std::numeric_limits<double>::epsilon() / 2;

/// The spacing of the doubles at |x|: the finest a coordinate near x can be given.
double ulp(double x) { return std::nextafter(std::abs(x), INFINITY) - std::abs(x); }

}  // namespace

TEST_CASE("arc length of a straight line 1e3 m and 1e6 m from the origin", "[iga][validation]") {
  // A 2 m segment in a general direction, 200 quadratic (and cubic) elements as a fine beam mesh.
  const Eigen::Vector3d direction = Eigen::Vector3d(1, 2, -2) / 3;
  for (const double offset : {0.0, 1e3, 1e6})
    for (const int degree : {1, 2, 3}) {
      const Eigen::Vector3d a = offset * Eigen::Vector3d(0.6, -0.8, 0.0) + Eigen::Vector3d(0.1, 0.2, 0.3);
      const NurbsCurve<3> line = straight_line<3>(a, a + 2.0 * direction, 200, degree);
      // The interior control points are rounded to the doubles near the offset, off the line by
      // at most δ = √3/2 ulp: that lengthens each element by O(δ²/h) ≤ 1e-18 m, and moves none
      // back, so the length is the distance between the end control points as stored. The
      // quadrature's target is 1e-14 per element; summing 200 elements adds ≤ 200 u: 1e-13.
      const double exact =
          (line.control_points().rightCols<1>() - line.control_points().col(0)).norm();
      INFO("offset " << offset << " m, degree " << degree);
      CHECK(std::abs(line.arc_length(0.0, 1.0) - exact) <= 1e-13 * exact);
      // Inside, the rounding moves the points C(¼) and C(¾) along the line by up to δ too.
      const double delta = std::sqrt(3.0) / 2 * ulp(a.cwiseAbs().maxCoeff() + 2.0);
      CHECK(std::abs(line.arc_length(0.25, 0.75) - 0.5 * exact) <= 1e-13 * exact + 2 * delta);
    }
}

TEST_CASE("arc length of an exact circular arc 1e3 m and 1e6 m from the origin", "[iga][validation]") {
  for (const double offset : {1e3, 1e6})
    for (const int refinement : {1, 20}) {
      CircularArc<3> arc;
      arc.center = offset * Eigen::Vector3d(0.48, 0.6, 0.64);
      arc.x_axis = Eigen::Vector3d(0, 0.8, -0.6);
      arc.y_axis = Eigen::Vector3d(1, 0, 0);
      arc.radius = 1.5;
      arc.sweep = 3 * std::numbers::pi / 2;
      NurbsCurve<3> curve = circular_arc(arc);
      std::vector<double> knots;
      for (int k = 1; k < refinement; ++k) knots.push_back(static_cast<double>(k) / refinement);
      if (!knots.empty()) curve = refine_knots(curve, knots).curve;
      // The control points are stored to within √3 (ulp(|center|∞)/2 + 4u r/cos 45°) of the
      // exact ones (the sum center + r(cos x + sin y) rounded to the doubles near the center),
      // and knot refinement (A5.4) chains one convex combination, one more such rounding, per
      // inserted knot: δ = (knots + 1) times that. The curve moves by ≤ δ (convex hull), and its
      // length by ≤ (θ + 2) δ (the first variation ∫κ d ds plus the two ends).
      const double delta =
          std::sqrt(3.0) * (refinement + 1) * (ulp(arc.center.cwiseAbs().maxCoeff()) / 2 +
                                               4 * u_round * arc.radius / std::cos(std::numbers::pi / 4));
      const double exact = arc.radius * arc.sweep;
      INFO("offset " << offset << " m, " << refinement << " elements per piece");
      CHECK(std::abs(curve.arc_length(0.0, 1.0) - exact) <= (arc.sweep + 2) * delta + 1e-13 * exact);
    }
}

TEST_CASE("arc length ends where the integrand's round-off hides its error", "[iga][validation]") {
  // A degree-7 Bézier on the x axis whose control points zigzag ±1 while they advance 1e-3:
  // x(u) = Σ B_{i,7}(u) ((−1)^i + 1e-3 i) = t⁷ + 0.0035 (1 − t) with t = 1 − 2u, so
  // x′ = −14 t⁶ + 7e-3 cancels to 7e-3 near u = ½ out of terms of size ~10: |C′| is known there
  // to ~1e-13 relative only, at the origin too. The quadrature must stop at that floor (it
  // bisected towards 2^40 pieces). The curve turns back where t⁶ = 5e-4 (two cusps, kinks of
  // |C′|), and its length is the total variation of x.
  const KnotVector U({0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1}, 7);
  NurbsCurve<2>::Points P(2, 8);
  for (int i = 0; i < 8; ++i) P.col(i) = Eigen::Vector2d((i % 2 == 0 ? 1.0 : -1.0) + 1e-3 * i, 0.0);
  const NurbsCurve<2> zigzag(U, P);
  const auto x = [](double t) { return std::pow(t, 7) + 0.0035 * (1 - t); };
  const double t0 = std::pow(5e-4, 1.0 / 6);
  const double exact = (x(1) - x(t0)) + (x(-t0) - x(t0)) + (x(-t0) - x(-1));
  // Round-off of |C′|: u Σ|R′_j||P_j − P_0| ≲ 1e-16 · 20 · 8 terms ≈ 2e-14 absolute on [0, 1],
  // beside a length of ~2.1: 1e-13 relative covers it and the stored control points (1e-16).
  CHECK(std::abs(zigzag.arc_length(0.0, 1.0) - exact) <= 1e-13 * exact);
}
