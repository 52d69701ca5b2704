#pragma once
/// \file
/// Forward-mode dual numbers a + Σ_i d_i ε_i (ε_i ε_j = 0) with a fixed number N of derivative
/// directions, usable as the scalar of fixed-size Eigen matrices (NumTraits below).
///
/// Why here: the ALE-RANCF element's residual (docs/rancf.md eqs. R11–R13) is a rational function
/// of the nodal coordinates, the two material coordinates and the velocities whose derivatives
/// (∂(M(q)q̈)/∂q, the quadratic-velocity terms, the bending Hessian through (x_A, x_B)) would take
/// hundreds of hand-written terms. Evaluating the hand-written residual once with duals seeded on
/// q (and v) gives K (and C) exact to round-off at about (N + 1)× the residual's cost, with no
/// heap allocation; the finite-difference tests check the result.

#include <Eigen/Core>

#include <cmath>

namespace spar::core {

template <int N>
struct Dual {
  using Gradient = Eigen::Matrix<double, N, 1>;
  double value = 0.0;
  Gradient grad = Gradient::Zero();

  Dual() = default;
  Dual(double v) : value(v) {}  // NOLINT(google-explicit-constructor): constants mix freely
  Dual(double v, const Gradient& g) : value(v), grad(g) {}

  /// The variable with value v and derivative 1 in direction i.
  static Dual variable(double v, int i) {
    Dual d(v);
    d.grad(i) = 1.0;
    return d;
  }

  Dual& operator+=(const Dual& b) { value += b.value; grad += b.grad; return *this; }
  Dual& operator-=(const Dual& b) { value -= b.value; grad -= b.grad; return *this; }
  Dual& operator*=(const Dual& b) { grad = b.value * grad + value * b.grad; value *= b.value; return *this; }
  Dual& operator/=(const Dual& b) {
    const double inv = 1.0 / b.value;
    value *= inv;
    grad = (grad - value * b.grad) * inv;
    return *this;
  }
};

template <int N> Dual<N> operator-(const Dual<N>& a) { return {-a.value, -a.grad}; }
template <int N> Dual<N> operator+(Dual<N> a, const Dual<N>& b) { return a += b; }
template <int N> Dual<N> operator-(Dual<N> a, const Dual<N>& b) { return a -= b; }
template <int N> Dual<N> operator*(Dual<N> a, const Dual<N>& b) { return a *= b; }
template <int N> Dual<N> operator/(Dual<N> a, const Dual<N>& b) { return a /= b; }
template <int N> Dual<N> operator+(Dual<N> a, double b) { a.value += b; return a; }
template <int N> Dual<N> operator+(double b, Dual<N> a) { a.value += b; return a; }
template <int N> Dual<N> operator-(Dual<N> a, double b) { a.value -= b; return a; }
template <int N> Dual<N> operator-(double b, const Dual<N>& a) { return {b - a.value, -a.grad}; }
template <int N> Dual<N> operator*(const Dual<N>& a, double b) { return {a.value * b, a.grad * b}; }
template <int N> Dual<N> operator*(double b, const Dual<N>& a) { return {a.value * b, a.grad * b}; }
template <int N> Dual<N> operator/(const Dual<N>& a, double b) { return {a.value / b, a.grad / b}; }
template <int N> Dual<N> operator/(double b, const Dual<N>& a) {
  const double v = b / a.value;
  return {v, (-v / a.value) * a.grad};
}
template <int N> bool operator<(const Dual<N>& a, const Dual<N>& b) { return a.value < b.value; }
template <int N> bool operator>(const Dual<N>& a, const Dual<N>& b) { return a.value > b.value; }
template <int N> bool operator==(const Dual<N>& a, const Dual<N>& b) { return a.value == b.value; }
template <int N> bool operator!=(const Dual<N>& a, const Dual<N>& b) { return a.value != b.value; }
template <int N> Dual<N> sqrt(const Dual<N>& a) {
  const double s = std::sqrt(a.value);
  return {s, (0.5 / s) * a.grad};
}

/// The value of a double or a dual (kernels templated on the scalar report energies with it).
inline double value_of(double x) { return x; }
template <int N> double value_of(const Dual<N>& x) { return x.value; }

}  // namespace spar::core

namespace Eigen {

template <int N>
struct NumTraits<spar::core::Dual<N>> : NumTraits<double> {
  using Real = spar::core::Dual<N>;
  using NonInteger = spar::core::Dual<N>;
  using Nested = spar::core::Dual<N>;
  using Literal = double;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = N + 1,
    MulCost = 2 * N + 1
  };
};

template <int N, typename Op>
struct ScalarBinaryOpTraits<spar::core::Dual<N>, double, Op> {
  using ReturnType = spar::core::Dual<N>;
};
template <int N, typename Op>
struct ScalarBinaryOpTraits<double, spar::core::Dual<N>, Op> {
  using ReturnType = spar::core::Dual<N>;
};

}  // namespace Eigen
