#pragma once
/// \file
/// NURBS curves in R^Dim (The NURBS Book ch. 4): points and derivatives (A4.2 through the rational
/// basis), unit tangent, curvature, arc length and its inverse, closest point (point inversion,
/// The NURBS Book §6.1).

#include <spar/error.hpp>
#include <spar/iga/basis.hpp>
#include <spar/iga/detail/text.hpp>
#include <spar/iga/knot_vector.hpp>
#include <spar/iga/quadrature.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace spar::iga {

/// C(u) = Σ R_{i,p}(u) P_i with the NURBS basis R of the knot vector and the weights w_i > 0.
/// Unit weights give a polynomial B-spline curve. Constant after construction.
template <int Dim>
class NurbsCurve {
  static_assert(Dim >= 2, "NurbsCurve is for plane and space curves");

public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  using Points = Eigen::Matrix<double, Dim, Eigen::Dynamic>;
  /// Homogeneous control points (w_i P_i, w_i) as columns.
  using HomogeneousPoints = Eigen::Matrix<double, Dim + 1, Eigen::Dynamic>;
  /// C, C′, C″, C‴ as columns (only the first order+1 are present); no heap storage.
  using Derivatives =
      Eigen::Matrix<double, Dim, Eigen::Dynamic, Eigen::ColMajor, Dim, max_derivative_order + 1>;

  /// Validates that there is one control point and one weight per basis function and that every
  /// weight is finite, > 0 and at least machine epsilon times the largest; throws spar::Error
  /// otherwise.
  NurbsCurve(KnotVector knots, Points control_points, Eigen::VectorXd weights)
      : knots_(std::move(knots)),
        control_points_(std::move(control_points)),
        weights_(std::move(weights)) {
    constexpr const char* where = "iga::NurbsCurve";
    const int n = knots_.basis_count();
    if (control_points_.cols() != n)
      throw Error(std::string(control_points_.cols() < n ? "too few" : "too many") +
                      " control points: " + std::to_string(control_points_.cols()) +
                      " for the " + std::to_string(n) + " basis functions of the knot vector",
                  where, "give exactly number of knots − p − 1 control points");
    if (weights_.size() != n)
      throw Error(std::to_string(weights_.size()) + " weights for " + std::to_string(n) +
                      " control points",
                  where, "give one weight per control point");
    for (int i = 0; i < n; ++i)
      if (!(weights_(i) > 0.0) || !std::isfinite(weights_(i)))
        throw Error("weight " + std::to_string(i) + " = " + detail::number(weights_(i)) +
                        " is not a finite number > 0 (weight ≤ 0)",
                    where, "give finite positive weights");
    // A weight below ε·max_j w_j (ε = 2.2e-16, machine epsilon) is lost to round-off in
    // W = Σ w_j N_j wherever a basis function of the largest weight is active: its control point
    // cannot be felt, the curve passes it within a parameter interval narrower than the doubles
    // resolve, and its derivatives overflow (a weight of 1e-300 beside 1, issue 29). The bound is
    // relative because the curve is unchanged when all weights are scaled alike; every curve of
    // meaning is far inside it (arcs: cos(Δθ/2) ≥ 0.7 of 1; refinement and elevation stay within
    // the range of the weights they start from).
    const double largest = weights_.maxCoeff();
    for (int i = 0; i < n; ++i)
      if (weights_(i) < std::numeric_limits<double>::epsilon() * largest)
        throw Error("weight " + std::to_string(i) + " = " + detail::number(weights_(i)) +
                        " is below machine epsilon times the largest weight (" + detail::number(largest) +
                        "): its control point is lost to round-off",
                    where, "give weights within a factor 4.5e15 of each other (scaling them all alike leaves the curve unchanged)");
    if (!control_points_.allFinite())
      throw Error("a control point has a NaN or infinite coordinate", where,
                  "give finite control points");
  }

  /// A polynomial B-spline curve (all weights 1).
  NurbsCurve(KnotVector knots, Points control_points)
      : NurbsCurve(knots, std::move(control_points),
                   Eigen::VectorXd::Ones(knots.basis_count())) {}

  /// The curve with homogeneous control points Pw (columns (w P, w)).
  static NurbsCurve from_homogeneous(KnotVector knots, const HomogeneousPoints& Pw) {
    Eigen::VectorXd weights = Pw.row(Dim).transpose();
    Points points = Pw.template topRows<Dim>();
    for (Eigen::Index i = 0; i < Pw.cols(); ++i)
      if (weights(i) != 0.0) points.col(i) /= weights(i);
    return NurbsCurve(std::move(knots), std::move(points), std::move(weights));
  }

  const KnotVector& knots() const { return knots_; }
  int degree() const { return knots_.degree(); }
  const Points& control_points() const { return control_points_; }
  const Eigen::VectorXd& weights() const { return weights_; }
  /// The homogeneous control points (w_i P_i, w_i) as columns.
  HomogeneousPoints homogeneous_points() const {
    HomogeneousPoints Pw(Dim + 1, control_points_.cols());
    Pw.template topRows<Dim>() = control_points_ * weights_.asDiagonal();
    Pw.row(Dim) = weights_.transpose();
    return Pw;
  }

  /// C(u); throws spar::Error for u outside the knot range.
  Point point(double u) const { return derivatives(u, 0).col(0); }

  /// [C, C′, …, C^(order)](u), derivatives with respect to u, 0 ≤ order ≤ max_derivative_order.
  /// Throws spar::Error when they overflow (weights or knot spans so extreme, e.g. a weight of
  /// 1e-300 next to 1, that the rational basis leaves the doubles).
  Derivatives derivatives(double u, int order) const {
    detail::check_derivative_order(order, "iga::NurbsCurve::derivatives");
    const int span = knots_.find_span(u);
    const int p = degree();
    BasisTable R;
    rational_basis_derivatives(knots_, span, u, order, weights_, R);
    Derivatives D(Dim, order + 1);
    for (int k = 0; k <= order; ++k)
      D.col(k) = control_points_.middleCols(span - p, p + 1) * R.row(k).head(p + 1).transpose();
    if (!D.allFinite()) throw overflow(order, u);
    return D;
  }

  /// C′(u)/|C′(u)|; throws spar::Error where C′ = 0 (a degenerate parameterization).
  Point unit_tangent(double u) const {
    const Point d = derivatives(u, 1).col(1);
    const double norm = d.norm();
    if (!(norm > 0.0))
      throw Error("the tangent vanishes at u = " + detail::number(u), "iga::NurbsCurve::unit_tangent",
                  "check for coincident control points");
    return d / norm;
  }

  /// κ = |C′ × C″| / |C′|³, with |C′ × C″|² = |C′|²|C″|² − (C′·C″)² in any dimension.
  double curvature(double u) const {
    const Derivatives D = derivatives(u, 2);
    const double speed2 = D.col(1).squaredNorm();
    if (!(speed2 > 0.0))
      throw Error("the tangent vanishes at u = " + detail::number(u), "iga::NurbsCurve::curvature",
                  "check for coincident control points");
    const double dot = D.col(1).dot(D.col(2));
    const double cross2 = std::max(0.0, speed2 * D.col(2).squaredNorm() - dot * dot);
    return std::sqrt(cross2) / (speed2 * std::sqrt(speed2));
  }

  /// ∫_{u0}^{u1} |C′(u)| du (negative when u1 < u0): Gauss–Legendre on every element piece,
  /// bisected until two successive estimates agree to 1e-14 relative, or to within their own
  /// round-off where |C′| is not known to 1e-14 (a speed that cancels out of much larger terms:
  /// see speed()). Translation-invariant: the cost and the accuracy are those of the same curve
  /// at the origin, however far from it the curve lies.
  double arc_length(double u0, double u1) const {
    knots_.find_span(u0);
    knots_.find_span(u1);
    if (u1 < u0) return -arc_length(u1, u0);
    double total = 0.0;
    for (int e = 0; e < knots_.element_count(); ++e) {
      const Element element = knots_.element(e);
      const double a = std::max(element.first, u0), b = std::min(element.last, u1);
      if (a < b) total += adaptive_length(a, b, gauss_length(a, b), 0);
    }
    return total;
  }

  /// The parameter u with arc_length(first, u) = s, 0 ≤ s ≤ total length: Newton's method on
  /// s(u) − s with s′ = |C′|, safeguarded by bisection inside a shrinking bracket.
  double parameter_at_arc_length(double s) const {
    constexpr const char* where = "iga::NurbsCurve::parameter_at_arc_length";
    const double first = knots_.first(), last = knots_.last();
    const double length = arc_length(first, last);
    if (!(s >= 0.0 && s <= length))
      throw Error("arc length s = " + detail::number(s) + " is outside [0, " +
                      detail::number(length) + "]",
                  where, "ask for 0 ≤ s ≤ arc_length(first, last)");
    double lower = first, upper = last;
    double u = first + (last - first) * (s / length);
    double residual = arc_length(first, u) - s;
    for (int iteration = 0; iteration < 100; ++iteration) {
      if (std::abs(residual) <= 1e-14 * length) return u;
      (residual < 0.0 ? lower : upper) = u;
      const double speed = derivatives(u, 1).col(1).norm();
      double next = speed > 0.0 ? u - residual / speed : lower;
      if (!(next > lower && next < upper)) next = 0.5 * (lower + upper);
      if (std::abs(next - u) <= 1e-15 * (last - first)) return next;
      residual += arc_length(u, next);
      u = next;
    }
    throw Error("Newton's method did not converge for s = " + detail::number(s), where,
                "check the curve for a vanishing tangent");
  }

  /// Point inversion (The NURBS Book §6.1): the parameter of the point of the curve closest to
  /// x, found from u_guess by Newton's method on f(u) = C′·(C − x), f′ = C″·(C − x) + |C′|².
  /// Safeguards: a Gauss–Newton step −f/|C′|² where f′ ≤ 0, backtracking until the distance
  /// decreases, and clamping to the knot range. It finds the local minimum near u_guess.
  double closest_point(const Point& x, double u_guess) const {
    constexpr const char* where = "iga::NurbsCurve::closest_point";
    knots_.find_span(u_guess);
    if (!x.allFinite())
      throw Error("the point has a NaN or infinite coordinate", where, "give a finite point");
    const double first = knots_.first(), last = knots_.last();
    double u = u_guess;
    for (int iteration = 0; iteration < 100; ++iteration) {
      const Derivatives D = derivatives(u, 2);
      const Point r = D.col(0) - x;
      const double distance = r.norm();
      const double scale = std::max({x.norm(), D.col(0).norm(), 1e-300});
      const double speed = D.col(1).norm();
      const double f = D.col(1).dot(r);
      // The NURBS Book §6.1 convergence tests: point coincidence and zero cosine.
      if (distance <= 1e-15 * scale || std::abs(f) <= 1e-15 * speed * distance) return u;
      const double curvature_term = D.col(2).dot(r) + speed * speed;
      double step = curvature_term > 0.0 ? -f / curvature_term : -f / (speed * speed);
      double next = std::clamp(u + step, first, last);
      for (int halving = 0; halving < 60 && (point(next) - x).norm() > distance; ++halving) {
        step *= 0.5;
        next = std::clamp(u + step, first, last);
      }
      // §6.1: the parameter step no longer moves the point.
      if (std::abs(next - u) * speed <= 1e-15 * scale) return next;
      u = next;
    }
    throw Error("point inversion did not converge", where,
                "give a better initial guess u_guess");
  }

private:
  static Error overflow(int order, double u) {
    return Error("the curve's derivatives up to order " + std::to_string(order) + " overflow at u = " +
                     detail::number(u),
                 "iga::NurbsCurve::derivatives",
                 "give weights of comparable size and knot spans that are not vanishingly small");
  }

  /// |C′(u)| and a bound on its round-off.
  struct Speed {
    double value = 0.0;
    double roundoff = 0.0;
  };

  /// C′ = Σ_j R′_j (P_j − P_0) over the p + 1 control points of u's span, relative to the first
  /// of them: the same vector as Σ_j R′_j P_j (derivatives()), since the R_j sum to 1 and so the
  /// R′_j to 0, but its round-off is of the size of the curve's own extent, u Σ|R′_j||P_j − P_0|,
  /// not u Σ|R′_j||P_j|, which grows with the distance from the origin: 1e3 m away, a 200-element
  /// line had |C′| only to 3e-11 relative (1e6 m away, 3e-8), and arc_length's 1e-14 test
  /// bisected towards 2^40 pieces (issue 29). The bound: an inner product of p + 1 terms rounds
  /// by at most γ_{p+1} ≈ (p + 1) u times the sum of their magnitudes (Higham, Accuracy and
  /// Stability of Numerical Algorithms, 2nd ed. 2002, §3.1), doubled for the round-off of the
  /// computed R′_j themselves.
  Speed speed(double u) const {
    const int span = knots_.find_span(u), p = degree();
    BasisTable R;
    rational_basis_derivatives(knots_, span, u, 1, weights_, R);
    const auto P = control_points_.middleCols(span - p, p + 1);
    Point tangent = Point::Zero();
    double magnitude = 0.0;
    for (int j = 1; j <= p; ++j) {
      const Point relative = P.col(j) - P.col(0);
      tangent += R(1, j) * relative;
      magnitude += std::abs(R(1, j)) * relative.norm();
    }
    if (!tangent.allFinite()) throw overflow(1, u);
    constexpr double unit_roundoff = std::numeric_limits<double>::epsilon() / 2;
    return {tangent.norm(), 2 * (p + 1) * unit_roundoff * magnitude};
  }

  /// The 12-point Gauss–Legendre estimate of ∫_a^b |C′| and the round-off it carries from |C′|.
  Speed gauss_length(double a, double b) const {
    static const GaussRule rule = gauss_legendre(12);
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    Speed sum;
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const Speed s = speed(mid + half * rule.points[q]);
      sum.value += rule.weights[q] * s.value;
      sum.roundoff += rule.weights[q] * s.roundoff;
    }
    return {half * sum.value, half * sum.roundoff};
  }

  /// Bisection until the halves' sum agrees with the whole's estimate to 1e-14 relative, or to
  /// within the three estimates' round-off, below which their difference says nothing more. The
  /// test is relative to the piece's own length, so the pieces' errors sum to 1e-14 of the total;
  /// depth 40 bounds the one path that bisects towards a cusp (a kink of |C′|).
  double adaptive_length(double a, double b, const Speed& whole, int depth) const {
    const double mid = 0.5 * (a + b);
    const Speed left = gauss_length(a, mid), right = gauss_length(mid, b);
    const double sum = left.value + right.value;
    const double roundoff = whole.roundoff + left.roundoff + right.roundoff;
    if (std::abs(sum - whole.value) <= std::max(1e-14 * sum, roundoff) || depth >= 40) return sum;
    return adaptive_length(a, mid, left, depth + 1) + adaptive_length(mid, b, right, depth + 1);
  }

  KnotVector knots_;
  Points control_points_;
  Eigen::VectorXd weights_;
};

}  // namespace spar::iga
