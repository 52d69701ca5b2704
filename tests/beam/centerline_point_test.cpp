// GeometricallyExactBeam::centerline_point: the centerline point and its parameter derivatives
// as weights of the control points (003 eq. 53, docs/beam.md eq. B15), at any parameter, across
// element boundaries, for rational carriers of every continuity.
#include <spar/elements/beam/beam.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <algorithm>

#include "beam_fixtures.hpp"
#include "random_rotations.hpp"
#include "sliding_carriers.hpp"

using namespace spar;

namespace {

core::BeamParameters carrier(const iga::NurbsCurve<3>& centerline) {
  core::BeamParameters p{.centerline = centerline, .stiffness = test::generic_stiffness()};
  return p;
}

/// Parameters covering every element: its ends (the knots), and interior points.
std::vector<double> sample_parameters(const iga::KnotVector& U) {
  std::vector<double> u;
  for (int e = 0; e < U.element_count(); ++e)
    for (const double s : {0.0, 0.013, 0.5, 0.97}) {
      const iga::Element el = U.element(e);
      u.push_back(el.first + s * (el.last - el.first));
    }
  u.push_back(U.last());
  return u;
}

}  // namespace

TEST_CASE("centerline point: reference geometry and its derivatives, any element, any continuity",
          "[gebt][centerline]") {
  for (const int degree : {2, 3})
    for (int continuity = 0; continuity < degree; ++continuity) {
      INFO("degree " << degree << ", C" << continuity);
      const iga::NurbsCurve<3> curve = test::quarter_circle_carrier(1.7, 5, degree, continuity);
      core::Configuration q;
      const core::GeometricallyExactBeam beam(carrier(curve), q);
      for (const double u : sample_parameters(curve.knots())) {
        const core::CenterlinePoint point = beam.centerline_point(u, 3);
        const auto reference = curve.derivatives(u, 3);
        // In the reference configuration the control points are the curve's: Σ R_I^(k) P_I is
        // the curve's k-th derivative (the same NURBS basis), to round-off of the sums
        // (|terms| ≤ 1e3 for the third derivative of this arc, 1e-12 relative).
        for (int k = 0; k <= 3; ++k)
          CHECK((beam.centerline_derivative(q, point, k) - reference.col(k)).norm() <=
                1e-12 * std::max(1.0, reference.col(k).norm()));
        // Partition of unity and its derivatives.
        CHECK(std::abs(point.shape.row(0).sum() - 1.0) <= 1e-14);
        for (int k = 1; k <= 3; ++k)
          CHECK(std::abs(point.shape.row(k).sum()) <= 1e-11 * point.shape.row(k).cwiseAbs().sum());
        // The element holds u and starts at the first control point of its span.
        const iga::Element element = curve.knots().element(point.element);
        CHECK(u >= element.first);
        CHECK(u <= element.last);
        CHECK(beam.element(point.element).first_control_point == point.first_control_point);
      }
    }
}

TEST_CASE("sample_centerline: points on the knots and between them, any continuity",
          "[gebt][centerline]") {
  // 5 elements and 21 samples: every 4th sample is a knot (simple, double or triple), where the
  // element found is the one starting there (the last one at the right end).
  for (int continuity = 0; continuity < 3; ++continuity) {
    INFO("C" << continuity);
    const iga::NurbsCurve<3> curve = test::quarter_circle_carrier(1.7, 5, 3, continuity);
    const iga::KnotVector& U = curve.knots();
    core::Configuration q;
    const core::GeometricallyExactBeam beam(carrier(curve), q);
    const Eigen::MatrixXd samples = beam.sample_centerline(q, 21);
    for (int i = 0; i < 21; ++i) {
      const double u = U.first() + (U.last() - U.first()) * i / 20;
      // The same NURBS sums as the curve's own evaluation: round-off of |x| = 1.7, 1e-14 relative.
      CHECK((samples.row(i).transpose() - curve.derivatives(u, 0).col(0)).norm() <= 1.7e-14);
      if (i % 4 == 0)
        CHECK(beam.centerline_point(u, 0).element == std::min(i / 4, U.element_count() - 1));
    }
  }
}

TEST_CASE("centerline point: derivatives in u against finite differences in a deformed state",
          "[gebt][centerline]") {
  test::RandomRotations random(1101);
  const iga::NurbsCurve<3> curve = test::quarter_circle_carrier(1.0, 4, 3, 2);
  core::Configuration q;
  const core::GeometricallyExactBeam beam(carrier(curve), q);
  for (Eigen::Vector3d& x : q.position)
    x += Eigen::Vector3d(random.uniform(-0.3, 0.3), random.uniform(-0.3, 0.3), random.uniform(-0.3, 0.3));
  // Central differences with step 1e-5 inside one element (C² cubic: the third derivative jumps at
  // knots, so the points stay 1e-3 away from them): truncation ε²/6·|x⁗| ≲ 1e-10·1e3 and round-off
  // 1e-16·|x|/ε ≈ 1e-11 — 1e-6 relative.
  const double eps = 1e-5;
  for (const double u : {0.05, 0.2, 0.4, 0.6, 0.93}) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d fd = (beam.centerline_derivative(q, beam.centerline_point(u + eps, 3), k) -
                                  beam.centerline_derivative(q, beam.centerline_point(u - eps, 3), k)) /
                                 (2 * eps);
      const Eigen::Vector3d analytic = beam.centerline_derivative(q, beam.centerline_point(u, 3), k + 1);
      CHECK((fd - analytic).norm() <= 1e-6 * std::max(1.0, analytic.norm()));
    }
    CHECK((beam.position_at(q, u) - beam.centerline_derivative(q, beam.centerline_point(u, 0), 0)).norm() == 0.0);
  }
}

TEST_CASE("centerline point: outside the knot range is an error", "[gebt][centerline][errors]") {
  core::Configuration q;
  const core::GeometricallyExactBeam beam(carrier(test::straight_centerline(2.0, 3, 2)), q);
  CHECK_THROWS_WITH(beam.centerline_point(1.0 + 1e-9, 1), Catch::Contains("outside the knot range"));
  CHECK_THROWS_WITH(beam.centerline_point(-0.1, 1), Catch::Contains("outside the knot range"));
  CHECK_THROWS_WITH(beam.centerline_point(0.5, iga::max_derivative_order + 1),
                    Catch::Contains("derivative order"));
}
