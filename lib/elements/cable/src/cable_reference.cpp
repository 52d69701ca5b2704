#include <spar/elements/cable/cable_reference.hpp>

#include <spar/error.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace spar::core {

CableReference::CableReference(const std::vector<iga::RationalBezier<2>>& pieces,
                               std::vector<double> breakpoints)
    : breakpoints_(std::move(breakpoints)) {
  constexpr const char* where = "core::CableReference";
  if (pieces.empty() || breakpoints_.size() != pieces.size() + 1)
    throw Error(std::to_string(pieces.size()) + " pieces for " + std::to_string(breakpoints_.size()) +
                    " breakpoints",
                where, "give one piece per span: N pieces and N + 1 breakpoints");
  for (std::size_t i = 0; i + 1 < breakpoints_.size(); ++i)
    if (!(breakpoints_[i + 1] > breakpoints_[i]) || !std::isfinite(breakpoints_[i + 1] - breakpoints_[i]))
      throw Error("breakpoints " + std::to_string(i) + " and " + std::to_string(i + 1) + " (" +
                      std::to_string(breakpoints_[i]) + ", " + std::to_string(breakpoints_[i + 1]) +
                      ") do not increase",
                  where, "give finite, strictly increasing material coordinates");
  // Bernstein → power basis of a cubic: row i holds B_{i,3}(u) = Σ_j M(i, j) u^j.
  Eigen::Matrix4d to_power;
  to_power << 1, -3, 3, -1, 0, 3, -6, 3, 0, 0, 3, -3, 0, 0, 0, 1;
  // The pieces as cubics, and their end speeds |r_x| (000 eq. (5)) in logarithms a_k, b_k.
  const int N = static_cast<int>(pieces.size());
  std::vector<iga::RationalBezier<2>> cubics;
  Eigen::VectorXd a(N), b(N);
  for (int k = 0; k < N; ++k) {
    pieces[k].validate(where);
    if (pieces[k].degree() > 3)
      throw Error("piece " + std::to_string(k) + " has degree " + std::to_string(pieces[k].degree()), where,
                  "give pieces of degree 1, 2 or 3 (a RANCF element is a rational cubic)");
    iga::RationalBezier<2> cubic = pieces[k];
    while (cubic.degree() < 3) cubic = iga::elevate(cubic);
    const Eigen::Matrix<double, 8, 1> e = iga::rancf_from_bezier(cubic, breakpoints_[k + 1] - breakpoints_[k]).e;
    a(k) = std::log(e.segment<2>(2).norm());
    b(k) = std::log(e.segment<2>(6).norm());
    cubics.push_back(cubic);
  }
  // One slope per node: piece k reparameterized by ρ_k has the end speeds ρ_k e^{a_k} and
  // e^{b_k}/ρ_k, so log ρ_{k+1} = −log ρ_k + b_k − a_{k+1}: one free parameter, log ρ_0. It is
  // chosen closest, in least squares, to each piece's own symmetric choice (b_k − a_k)/2 (equal
  // end speeds; 000 eq. (43) for an arc): log ρ_k = (−1)^k log ρ_0 + c_k, c_0 = 0.
  Eigen::VectorXd c = Eigen::VectorXd::Zero(N), symmetric = 0.5 * (b - a);
  for (int k = 0; k + 1 < N; ++k) c(k + 1) = -c(k) + b(k) - a(k + 1);
  double log_rho0 = 0.0;
  for (int k = 0; k < N; ++k) log_rho0 -= (k % 2 == 0 ? 1.0 : -1.0) * (c(k) - symmetric(k)) / N;
  Eigen::Vector2d incoming_end = Eigen::Vector2d::Zero(), incoming_tangent = Eigen::Vector2d::UnitX();
  for (int k = 0; k < N; ++k) {
    const double L = breakpoints_[k + 1] - breakpoints_[k];
    iga::RationalBezier<2> cubic = iga::reparameterize(cubics[k], std::exp((k % 2 == 0 ? 1.0 : -1.0) * log_rho0 + c(k)));
    cubic.weights /= cubic.weights(0);
    const iga::RancfElement<2> element = iga::rancf_from_bezier(cubic, L);
    const Eigen::Vector2d start = element.e.segment<2>(0), tangent = element.e.segment<2>(2).normalized();
    if (k > 0) {
      const double gap = (start - incoming_end).norm();
      const double kink = std::atan2(std::abs(incoming_tangent.x() * tangent.y() - incoming_tangent.y() * tangent.x()),
                                     incoming_tangent.dot(tangent));
      if (gap > 1e-9 * L || kink > 1e-9)
        throw Error("pieces " + std::to_string(k - 1) + " and " + std::to_string(k) + " meet with a gap of " +
                        std::to_string(gap) + " m and a kink of " + std::to_string(kink) + " rad",
                    where, "give a continuous shape with a continuous tangent (a cable node has one slope)");
    }
    nodes_.push_back(element.e.head<4>());
    weights_.push_back(element.weights);
    lengths_.push_back(L);
    polynomials_.push_back(cubic.homogeneous() * to_power);
    incoming_end = element.e.segment<2>(4);
    incoming_tangent = element.e.segment<2>(6).normalized();
    if (k + 1 == N) nodes_.push_back(element.e.tail<4>());
  }
}

CableReference CableReference::circular_arc(const iga::CircularArc<2>& arc, std::vector<double> breakpoints) {
  constexpr const char* where = "core::CableReference::circular_arc";
  const double R = arc.radius, length = R * arc.sweep;
  if (!(R > 0.0) || !(arc.sweep > 0.0) || !std::isfinite(length))
    throw Error("radius " + std::to_string(R) + " and sweep " + std::to_string(arc.sweep), where,
                "give a radius > 0 and a sweep > 0");
  if (breakpoints.size() < 2 || std::abs(breakpoints.front()) > 1e-12 * length ||
      std::abs(breakpoints.back() - length) > 1e-12 * length)
    throw Error("the breakpoints do not run from 0 to the arc length " + std::to_string(length) + " m", where,
                "give material coordinates from 0 to radius · sweep");
  std::vector<iga::RationalBezier<2>> pieces;
  const auto on_circle = [&](double angle, double radius) -> Eigen::Vector2d {
    return arc.center + radius * (std::cos(angle) * arc.x_axis + std::sin(angle) * arc.y_axis);
  };
  for (std::size_t k = 0; k + 1 < breakpoints.size(); ++k) {
    // A7.1's rational quadratic of one piece: the end points, the tangents' intersection at
    // R/cos(θ/2) on the bisector, middle weight cos(θ/2).
    const double a0 = arc.start_angle + breakpoints[k] / R, a1 = arc.start_angle + breakpoints[k + 1] / R;
    const double theta = a1 - a0;
    if (!(theta > 0.0 && theta < std::numbers::pi))
      throw Error("span " + std::to_string(k) + " sweeps " + std::to_string(theta) + " rad", where,
                  "cut the arc into spans of less than π");
    iga::RationalBezier<2> piece{iga::RationalBezier<2>::Points(2, 3),
                                 Eigen::Vector3d(1.0, std::cos(theta / 2), 1.0)};
    piece.points << on_circle(a0, R), on_circle(0.5 * (a0 + a1), R / std::cos(theta / 2)), on_circle(a1, R);
    pieces.push_back(piece);
  }
  return CableReference(pieces, std::move(breakpoints));
}

CableReference CableReference::polynomial_interpolant() const {
  std::vector<iga::RationalBezier<2>> pieces;
  for (int k = 0; k < elements(); ++k) {
    const Eigen::Vector4d a = node(k), b = node(k + 1);
    const double third = (breakpoints_[k + 1] - breakpoints_[k]) / 3;
    iga::RationalBezier<2> piece{iga::RationalBezier<2>::Points(2, 4), Eigen::Vector4d::Ones()};
    piece.points << a.head<2>(), a.head<2>() + third * a.tail<2>().normalized(),
        b.head<2>() - third * b.tail<2>().normalized(), b.head<2>();
    pieces.push_back(piece);
  }
  return CableReference(pieces, breakpoints_);
}

}  // namespace spar::core
