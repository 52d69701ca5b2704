// Exact circular arcs (A7.1): every sample on the circle, the length R·sweep, the curvature 1/R,
// and the arc-length parameterization and point inversion that the sliding joints rely on.
#include <spar/error.hpp>
#include <spar/iga/circular_arc.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace spar::iga;
using Catch::Contains;

namespace {

CircularArc<3> tilted_arc(double sweep) {
  CircularArc<3> arc;
  arc.center = Eigen::Vector3d(0.3, -1.2, 2.0);
  arc.x_axis = Eigen::Vector3d(1, 2, 2) / 3.0;
  arc.y_axis = Eigen::Vector3d(2, 1, -2) / 3.0;
  arc.radius = 2.5;
  arc.start_angle = 0.4;
  arc.sweep = sweep;
  return arc;
}

}  // namespace

TEST_CASE("arcs of 10°, 90°, 180°, 270°, 360° are exact circles of length R·sweep",
          "[iga][validation]") {
  constexpr double pi = std::numbers::pi;
  for (double degrees : {10.0, 90.0, 180.0, 270.0, 360.0}) {
    const CircularArc<3> spec = tilted_arc(degrees * pi / 180);
    const NurbsCurve<3> arc = circular_arc(spec);
    const Eigen::Vector3d normal = spec.x_axis.cross(spec.y_axis);
    double worst_radius = 0.0, worst_plane = 0.0, worst_curvature = 0.0;
    for (int i = 0; i < 1000; ++i) {
      const double u = i / 999.0;
      const Eigen::Vector3d r = arc.point(u) - spec.center;
      worst_radius = std::max(worst_radius, std::abs(r.norm() - spec.radius));
      worst_plane = std::max(worst_plane, std::abs(r.dot(normal)));
      worst_curvature = std::max(worst_curvature, std::abs(arc.curvature(u) * spec.radius - 1.0));
    }
    INFO("sweep = " << degrees << "°");
    // A rational combination of three points of size ~|center| + R: round-off only.
    CHECK(worst_radius <= 1e-14 * spec.radius);
    CHECK(worst_plane <= 1e-14 * spec.radius);
    // Curvature uses C′ and C″ and a difference of squares: a few hundred ulps.
    CHECK(worst_curvature <= 1e-12);
    // The ends: start and end angles.
    const auto at = [&](double angle) {
      return Eigen::Vector3d(spec.center + spec.radius * (std::cos(angle) * spec.x_axis +
                                                          std::sin(angle) * spec.y_axis));
    };
    CHECK((arc.point(0.0) - at(spec.start_angle)).norm() <= 1e-14 * spec.radius);
    CHECK((arc.point(1.0) - at(spec.start_angle + spec.sweep)).norm() <= 1e-14 * spec.radius);
    // Issue 3: the length is R·sweep to 1e-12 relative.
    const double length = arc.arc_length(0.0, 1.0);
    CHECK(std::abs(length - spec.radius * spec.sweep) <= 1e-12 * spec.radius * spec.sweep);
  }
}

TEST_CASE("the quarter circle, semicircle and full circle conveniences", "[iga][validation]") {
  constexpr double pi = std::numbers::pi;
  const NurbsCurve<2> quarter = quarter_circle<2>(2.0);
  CHECK(quarter.control_points().cols() == 3);
  CHECK(quarter.weights()(1) == Approx(std::sqrt(0.5)).epsilon(1e-15));
  CHECK((quarter.point(1.0) - Eigen::Vector2d(0, 2)).norm() <= 1e-15);
  CHECK(semicircle(1.0).arc_length(0.0, 1.0) == Approx(pi).epsilon(1e-13));
  const NurbsCurve<3> circle = full_circle(1.0);
  CHECK(circle.knots().element_count() == 4);
  CHECK((circle.point(0.0) - circle.point(1.0)).norm() <= 1e-15);
  CHECK(circle.arc_length(0.0, 1.0) == Approx(2 * pi).epsilon(1e-13));
}

TEST_CASE("arc length ↔ parameter map round-trips", "[iga]") {
  const NurbsCurve<3> arc = circular_arc(tilted_arc(5.0));
  const double length = arc.arc_length(0.0, 1.0);
  for (int i = 0; i <= 50; ++i) {
    const double s = length * i / 50.0;
    const double u = arc.parameter_at_arc_length(s);
    // On a circle the arc length to u is R·(angle between the radii): an independent check.
    const Eigen::Vector3d a = arc.point(0.0) - Eigen::Vector3d(0.3, -1.2, 2.0);
    const Eigen::Vector3d b = arc.point(u) - Eigen::Vector3d(0.3, -1.2, 2.0);
    double angle = std::atan2(a.cross(b).norm(), a.dot(b));
    if (s > std::numbers::pi * 2.5) angle = 2 * std::numbers::pi - angle;
    // The Newton iteration stops at |s(u) − s| ≤ 1e-14·L; the angle check carries atan2
    // round-off ~1e-15.
    CHECK(std::abs(2.5 * angle - s) <= 1e-13 * length);
    CHECK(std::abs(arc.arc_length(0.0, u) - s) <= 1e-13 * length);
  }
  CHECK(arc.arc_length(0.7, 0.2) == Approx(-arc.arc_length(0.2, 0.7)).epsilon(1e-15));
  CHECK_THROWS_WITH(arc.parameter_at_arc_length(length * 1.01), Contains("outside [0"));
  CHECK_THROWS_WITH(arc.arc_length(0.0, 1.5), Contains("outside the knot range"));
}

TEST_CASE("closest point: points off the circle project radially", "[iga][validation]") {
  const CircularArc<3> spec = tilted_arc(4.0);
  const NurbsCurve<3> arc = circular_arc(spec);
  const Eigen::Vector3d normal = spec.x_axis.cross(spec.y_axis);
  for (int i = 1; i < 20; ++i) {
    const double u_true = i / 20.0;
    const Eigen::Vector3d on = arc.point(u_true);
    // Move off the circle radially (by ±30 % of R) and out of plane: the closest point stays.
    const double offset = (i % 2 == 0 ? 0.3 : -0.3) * spec.radius;
    const Eigen::Vector3d x = on + offset * (on - spec.center).normalized() + 0.2 * normal;
    const double guess = std::clamp(u_true + 0.04, 0.0, 1.0);
    const double u = arc.closest_point(x, guess);
    // Newton converges quadratically; the stopping test is at 1e-15 relative, the
    // parameter is as good as ~1e-8 × (a distance of 1e-15 relative lies in a flat minimum).
    CHECK(std::abs(u - u_true) <= 1e-8);
    CHECK((arc.point(u) - on).norm() <= 1e-8 * spec.radius);
  }
  // A point beyond the end projects onto the end.
  const Eigen::Vector3d beyond = arc.point(1.0) + 0.5 * arc.unit_tangent(1.0);
  CHECK(arc.closest_point(beyond, 0.9) == 1.0);
  CHECK_THROWS_WITH(arc.closest_point(beyond, 2.0), Contains("outside the knot range"));
}

TEST_CASE("invalid arcs raise spar::Error naming the problem", "[iga]") {
  CircularArc<2> arc;
  arc.sweep = 7.0;
  CHECK_THROWS_WITH(circular_arc(arc), Contains("sweep"));
  arc.sweep = 1.0;
  arc.radius = 0.0;
  CHECK_THROWS_WITH(circular_arc(arc), Contains("radius"));
  arc.radius = 1.0;
  arc.y_axis = Eigen::Vector2d(1, 1);
  CHECK_THROWS_WITH(circular_arc(arc), Contains("orthonormal"));
}
