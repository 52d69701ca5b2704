#pragma once
/// \file
/// Exact circular arcs as rational quadratic NURBS (The NURBS Book A7.1): the sweep is split into
/// 1–4 equal pieces of at most 90°, each a rational quadratic Bézier with middle weight
/// cos(Δθ/2), joined with double interior knots (C^0 in the control net, G^∞ on the circle).

#include <spar/error.hpp>
#include <spar/iga/detail/text.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <Eigen/Core>

#include <cmath>
#include <numbers>
#include <vector>

namespace spar::iga {

/// An arc of a circle: the plane is spanned by the orthonormal axes x_axis, y_axis through
/// center; the arc runs from start_angle (measured from x_axis towards y_axis) over sweep
/// radians, 0 < sweep ≤ 2π.
template <int Dim>
struct CircularArc {
  using Point = Eigen::Matrix<double, Dim, 1>;
  Point center = Point::Zero();
  Point x_axis = Point::Unit(0);
  Point y_axis = Point::Unit(1);
  double radius = 1.0;
  double start_angle = 0.0;
  double sweep = std::numbers::pi / 2;
};

/// The NURBS of `arc` on the parameter range [0, 1] (A7.1). The middle control point of each
/// piece is placed at the intersection of the end tangents in closed form,
/// center + r/cos(Δθ/2)·(cos θ_mid x + sin θ_mid y), instead of intersecting two lines.
template <int Dim>
NurbsCurve<Dim> circular_arc(const CircularArc<Dim>& arc) {
  constexpr const char* where = "iga::circular_arc";
  if (!(arc.radius > 0.0) || !std::isfinite(arc.radius))
    throw Error("radius " + detail::number(arc.radius) + " is not positive", where,
                "give a radius > 0");
  if (!(arc.sweep > 0.0 && arc.sweep <= 2 * std::numbers::pi))
    throw Error("sweep " + detail::number(arc.sweep) + " rad is outside (0, 2π]", where,
                "give 0 < sweep ≤ 2π");
  if (std::abs(arc.x_axis.norm() - 1.0) > 1e-12 || std::abs(arc.y_axis.norm() - 1.0) > 1e-12 ||
      std::abs(arc.x_axis.dot(arc.y_axis)) > 1e-12)
    throw Error("the axes are not orthonormal", where,
                "give two orthogonal unit vectors spanning the plane of the arc");
  // A7.1: the number of pieces.
  const int pieces = arc.sweep <= std::numbers::pi / 2       ? 1
                     : arc.sweep <= std::numbers::pi         ? 2
                     : arc.sweep <= 3 * std::numbers::pi / 2 ? 3
                                                             : 4;
  const double step = arc.sweep / pieces;
  const double middle_weight = std::cos(step / 2);
  const auto on_circle = [&](double angle, double radius) -> typename CircularArc<Dim>::Point {
    return arc.center + radius * (std::cos(angle) * arc.x_axis + std::sin(angle) * arc.y_axis);
  };
  typename NurbsCurve<Dim>::Points points(Dim, 2 * pieces + 1);
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(2 * pieces + 1);
  std::vector<double> knots(3, 0.0);
  points.col(0) = on_circle(arc.start_angle, arc.radius);
  for (int i = 0; i < pieces; ++i) {
    const double begin = arc.start_angle + i * step;
    points.col(2 * i + 1) = on_circle(begin + step / 2, arc.radius / middle_weight);
    weights(2 * i + 1) = middle_weight;
    points.col(2 * i + 2) = on_circle(begin + step, arc.radius);
    if (i + 1 < pieces) knots.insert(knots.end(), 2, static_cast<double>(i + 1) / pieces);
  }
  knots.insert(knots.end(), 3, 1.0);
  return NurbsCurve<Dim>(KnotVector(std::move(knots), 2), std::move(points), std::move(weights));
}

/// The quarter circle of radius r about the origin in the plane of the first two axes, from
/// angle 0 to π/2.
template <int Dim = 3>
NurbsCurve<Dim> quarter_circle(double radius) {
  CircularArc<Dim> arc;
  arc.radius = radius;
  arc.sweep = std::numbers::pi / 2;
  return circular_arc(arc);
}

/// The semicircle of radius r about the origin in the plane of the first two axes, from angle 0
/// to π.
template <int Dim = 3>
NurbsCurve<Dim> semicircle(double radius) {
  CircularArc<Dim> arc;
  arc.radius = radius;
  arc.sweep = std::numbers::pi;
  return circular_arc(arc);
}

/// The full circle of radius r about the origin in the plane of the first two axes, starting
/// and ending at angle 0 (four 90° pieces).
template <int Dim = 3>
NurbsCurve<Dim> full_circle(double radius) {
  CircularArc<Dim> arc;
  arc.radius = radius;
  arc.sweep = 2 * std::numbers::pi;
  return circular_arc(arc);
}

}  // namespace spar::iga
