#pragma once
/// \file
/// Rational Bézier curves for the RANCF and ALE-RANCF elements (paper 000, Machines 2022, 10, 174):
/// evaluation (000 eqs. (1)–(3)), splitting at u_H by the de Casteljau algorithm in homogeneous
/// coordinates (000 eq. (21); The NURBS Book §1.4 and A5.1 at full multiplicity), and the linear
/// maps between a rational cubic Bézier and the RANCF nodal coordinates
/// e = [r_A, r_x^A, r_B, r_x^B] (000 eqs. (4)–(6)) with the shape functions of 000 eq. (9).

#include <spar/error.hpp>
#include <spar/iga/detail/text.hpp>

#include <Eigen/Core>

#include <cmath>
#include <string>

namespace spar::iga {

/// r(u) = Σ w_i B_{i,n}(u) P_i / Σ w_i B_{i,n}(u), 0 ≤ u ≤ 1 (000 eqs. (1)–(3)).
template <int Dim>
struct RationalBezier {
  using Point = Eigen::Matrix<double, Dim, 1>;
  using Points = Eigen::Matrix<double, Dim, Eigen::Dynamic>;
  Points points;
  Eigen::VectorXd weights;

  int degree() const { return static_cast<int>(points.cols()) - 1; }

  /// Throws spar::Error unless there are ≥ 2 control points, one weight each, all weights > 0.
  void validate(const char* where) const {
    if (points.cols() < 2)
      throw Error("a Bézier curve needs at least 2 control points, got " +
                      std::to_string(points.cols()) + " (too few control points)",
                  where, "give degree + 1 ≥ 2 control points");
    if (weights.size() != points.cols())
      throw Error(std::to_string(weights.size()) + " weights for " +
                      std::to_string(points.cols()) + " control points",
                  where, "give one weight per control point");
    for (Eigen::Index i = 0; i < weights.size(); ++i)
      if (!(weights(i) > 0.0) || !std::isfinite(weights(i)))
        throw Error("weight " + std::to_string(i) + " = " + detail::number(weights(i)) +
                        " is not a finite number > 0 (weight ≤ 0)",
                    where, "give finite positive weights");
  }

  /// The homogeneous control points (w_i P_i, w_i) as columns.
  Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> homogeneous() const {
    Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> Pw(Dim + 1, points.cols());
    Pw.template topRows<Dim>() = points * weights.asDiagonal();
    Pw.row(Dim) = weights.transpose();
    return Pw;
  }

  /// r(u) by the de Casteljau algorithm in homogeneous coordinates, 0 ≤ u ≤ 1.
  Point point(double u) const {
    if (!(u >= 0.0 && u <= 1.0))
      throw Error("parameter u = " + detail::number(u) + " is outside the knot range [0, 1]",
                  "iga::RationalBezier::point", "evaluate at 0 ≤ u ≤ 1");
    Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> Pw = homogeneous();
    for (int level = 1; level <= degree(); ++level)
      for (int i = 0; i <= degree() - level; ++i)
        Pw.col(i) = (1.0 - u) * Pw.col(i) + u * Pw.col(i + 1);
    return Pw.col(0).template head<Dim>() / Pw(Dim, 0);
  }
};

/// The two halves of a rational Bézier curve split at u_H.
template <int Dim>
struct BezierSplit {
  RationalBezier<Dim> left;   // parameter ū = u/u_H (000 eq. (22))
  RationalBezier<Dim> right;  // parameter ū = (u − u_H)/(1 − u_H) (000 eq. (24))
};

/// Splits `curve` at 0 < u_H < 1 (000 eq. (21)): with the homogeneous de Casteljau triangle
/// Q^k_i = (1 − u_H) Q^{k−1}_i + u_H Q^{k−1}_{i+1}, Q^0 = (w P, w), the left half has the
/// control points Q^k_0 and the right half Q^{n−k}_k, k = 0 … n; expanded, Q^k_0 has weight
/// w̄_k = Σ_{i≤k} B_{i,k}(u_H) w_i and point Σ B_{i,k}(u_H) w_i P_i / w̄_k, as in eq. (21). Both
/// halves reproduce the curve (000 eqs. (23), (25)).
template <int Dim>
BezierSplit<Dim> split(const RationalBezier<Dim>& curve, double u_h) {
  constexpr const char* where = "iga::split";
  curve.validate(where);
  if (!(u_h > 0.0 && u_h < 1.0))
    throw Error("split parameter u_H = " + detail::number(u_h) + " is not inside (0, 1)", where,
                "split strictly inside the curve");
  const int n = curve.degree();
  Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> Q = curve.homogeneous();
  Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> left(Dim + 1, n + 1), right(Dim + 1, n + 1);
  left.col(0) = Q.col(0);
  right.col(n) = Q.col(n);
  for (int k = 1; k <= n; ++k) {
    for (int i = 0; i <= n - k; ++i) Q.col(i) = (1.0 - u_h) * Q.col(i) + u_h * Q.col(i + 1);
    left.col(k) = Q.col(0);
    right.col(n - k) = Q.col(n - k);
  }
  const auto from_homogeneous = [](const Eigen::Matrix<double, Dim + 1, Eigen::Dynamic>& Pw) {
    RationalBezier<Dim> half;
    half.weights = Pw.row(Dim).transpose();
    half.points = Pw.template topRows<Dim>() * half.weights.cwiseInverse().asDiagonal();
    return half;
  };
  return {from_homogeneous(left), from_homogeneous(right)};
}

/// The same curve one degree higher (The NURBS Book eq. (5.36) on one Bézier segment), in
/// homogeneous coordinates: Q_i = (i/(n+1)) P^w_{i−1} + (1 − i/(n+1)) P^w_i, i = 0 … n+1.
/// A rational quadratic arc becomes the rational cubic a RANCF element holds (000 eq. (43)).
template <int Dim>
RationalBezier<Dim> elevate(const RationalBezier<Dim>& curve) {
  curve.validate("iga::elevate");
  const int n = curve.degree();
  const Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> P = curve.homogeneous();
  Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> Q(Dim + 1, n + 2);
  Q.col(0) = P.col(0);
  Q.col(n + 1) = P.col(n);
  for (int i = 1; i <= n; ++i) {
    const double a = static_cast<double>(i) / (n + 1);
    Q.col(i) = a * P.col(i - 1) + (1.0 - a) * P.col(i);
  }
  RationalBezier<Dim> elevated;
  elevated.weights = Q.row(Dim).transpose();
  elevated.points = Q.template topRows<Dim>() * elevated.weights.cwiseInverse().asDiagonal();
  return elevated;
}

/// The same curve under the Möbius reparameterization u ↦ ρu/(ρu + 1 − u) (The NURBS Book §6.4):
/// the weights become w_i ρ^i, the control points stay. The end derivatives scale by ρ at u = 0
/// and by 1/ρ at u = 1 (r'(0) = n w1/w0 (P1 − P0)), so a chain of pieces can be given continuous
/// slopes without changing its shape.
template <int Dim>
RationalBezier<Dim> reparameterize(const RationalBezier<Dim>& curve, double rho) {
  constexpr const char* where = "iga::reparameterize";
  curve.validate(where);
  if (!(rho > 0.0) || !std::isfinite(rho))
    throw Error("Möbius factor ρ = " + detail::number(rho) + " is not a finite number > 0", where,
                "give ρ > 0 (ρ = 1 keeps the parameterization)");
  RationalBezier<Dim> result = curve;
  double factor = 1.0;
  for (Eigen::Index i = 0; i < result.weights.size(); ++i, factor *= rho) result.weights(i) *= factor;
  return result;
}

/// A RANCF element: nodal coordinates e = [r_A; r_x^A; r_B; r_x^B] (000 eq. (4)), the weights of
/// its rational cubic Bézier and its reference length l (material coordinate x = u·l).
template <int Dim>
struct RancfElement {
  Eigen::Matrix<double, 4 * Dim, 1> e;
  Eigen::Vector4d weights;
  double length;
};

/// 000 eq. (5): r_A = P0, r_x^A = 3w1/(l w0) (P1 − P0), r_B = P3, r_x^B = 3w2/(l w3) (P3 − P2).
template <int Dim>
RancfElement<Dim> rancf_from_bezier(const RationalBezier<Dim>& cubic, double length) {
  constexpr const char* where = "iga::rancf_from_bezier";
  cubic.validate(where);
  if (cubic.degree() != 3)
    throw Error("RANCF elements are rational cubics; got degree " +
                    std::to_string(cubic.degree()),
                where, "give 4 control points (elevate or split the curve first)");
  if (!(length > 0.0) || !std::isfinite(length))
    throw Error("element length " + detail::number(length) + " is not positive", where,
                "give a reference length l > 0");
  const auto& P = cubic.points;
  const auto& w = cubic.weights;
  RancfElement<Dim> element{{}, w, length};
  element.e.template segment<Dim>(0) = P.col(0);
  element.e.template segment<Dim>(Dim) = 3 * w(1) / (length * w(0)) * (P.col(1) - P.col(0));
  element.e.template segment<Dim>(2 * Dim) = P.col(3);
  element.e.template segment<Dim>(3 * Dim) = 3 * w(2) / (length * w(3)) * (P.col(3) - P.col(2));
  return element;
}

/// 000 eq. (6), the inverse of eq. (5): P0 = r_A, P1 = r_A + l w0/(3w1) r_x^A,
/// P2 = r_B − l w3/(3w2) r_x^B, P3 = r_B.
template <int Dim>
RationalBezier<Dim> bezier_from_rancf(const RancfElement<Dim>& element) {
  constexpr const char* where = "iga::bezier_from_rancf";
  if (!(element.length > 0.0) || !std::isfinite(element.length))
    throw Error("element length " + detail::number(element.length) + " is not positive", where,
                "give a reference length l > 0");
  const double l = element.length;
  const Eigen::Vector4d& w = element.weights;
  RationalBezier<Dim> cubic{typename RationalBezier<Dim>::Points(Dim, 4), w};
  cubic.validate(where);
  const auto r_a = element.e.template segment<Dim>(0);
  const auto r_b = element.e.template segment<Dim>(2 * Dim);
  cubic.points.col(0) = r_a;
  cubic.points.col(1) = r_a + l * w(0) / (3 * w(1)) * element.e.template segment<Dim>(Dim);
  cubic.points.col(2) = r_b - l * w(3) / (3 * w(2)) * element.e.template segment<Dim>(3 * Dim);
  cubic.points.col(3) = r_b;
  return cubic;
}

/// The RANCF shape functions s_1 … s_4 of 000 eq. (9), r(u) = Σ s_k(u) e_k (eqs. (7)–(8)):
///   s = [3w1 u(1−u)² + w0(1−u)³, l w0 u(1−u)², w3 u³ + 3w2 u²(1−u), −l w3 u²(1−u)] / W(u),
///   W(u) = w3 u³ + 3w2 u²(1−u) + 3w1 u(1−u)² + w0(1−u)³.
/// Weights are not checked here (hot path); RancfElement weights come through bezier_from_rancf
/// or rancf_from_bezier, which validate them.
inline Eigen::Vector4d rancf_shape_functions(double u, const Eigen::Vector4d& w, double length) {
  const double v = 1.0 - u;
  const double W = w(3) * u * u * u + 3 * w(2) * u * u * v + 3 * w(1) * u * v * v + w(0) * v * v * v;
  return Eigen::Vector4d(3 * w(1) * u * v * v + w(0) * v * v * v, length * w(0) * u * v * v,
                         w(3) * u * u * u + 3 * w(2) * u * u * v, -length * w(3) * u * u * v) /
         W;
}

/// The RANCF shape functions of 000 eq. (9) and their first three derivatives in u, with the
/// length factor taken out of s_2 and s_4: column d (= 0 … 3) holds d^d/du^d of
/// [s_1, s_2/l, s_3, s_4/l], so that r^(d)(u) = s_1^(d) r_A + l (s_2/l)^(d) r_x^A + s_3^(d) r_B
/// + l (s_4/l)^(d) r_x^B. With the cubic Bernstein-like monomials b = [u³, u²v, uv², v³],
/// v = 1 − u, each numerator n_k and W are combinations of b, and the quotient rule gives
/// s' = (n' − s W')/W, s'' = (n'' − 2 s' W' − s W'')/W and
/// s''' = (n''' − 3 s'' W' − 3 s' W'' − s W''')/W. Weights are not checked (hot path).
inline Eigen::Matrix<double, 4, 4> rancf_shape_function_derivatives(double u,
                                                                    const Eigen::Vector4d& w) {
  const double v = 1.0 - u;
  Eigen::Matrix<double, 4, 4> b;  // rows: u³, u²v, uv², v³; columns: value and d/du … d³/du³
  b << u * u * u, 3 * u * u, 6 * u, 6,
      u * u * v, 2 * u * v - u * u, 2 * v - 4 * u, -6,
      u * v * v, v * v - 2 * u * v, 2 * u - 4 * v, 6,
      v * v * v, -3 * v * v, 6 * v, -6;
  Eigen::Matrix<double, 4, 4> numerators;  // rows: n_1, n_2/l, n_3, n_4/l over b
  numerators << 0, 0, 3 * w(1), w(0),
      0, 0, w(0), 0,
      w(3), 3 * w(2), 0, 0,
      0, -w(3), 0, 0;
  const Eigen::RowVector4d denominator(w(3), 3 * w(2), 3 * w(1), w(0));
  const Eigen::Matrix<double, 4, 4> n = numerators * b;
  const Eigen::RowVector4d W = denominator * b;
  Eigen::Matrix<double, 4, 4> s;
  s.col(0) = n.col(0) / W(0);
  s.col(1) = (n.col(1) - s.col(0) * W(1)) / W(0);
  s.col(2) = (n.col(2) - 2 * s.col(1) * W(1) - s.col(0) * W(2)) / W(0);
  s.col(3) = (n.col(3) - 3 * s.col(2) * W(1) - 3 * s.col(1) * W(2) - s.col(0) * W(3)) / W(0);
  return s;
}

}  // namespace spar::iga
