#pragma once
/// \file
/// Unit quaternions q = (w, v) ↔ rotation matrices ↔ rotation vectors
/// (docs/conventions.md eqs. C10–C12). Quaternions are returned in the hemisphere w ≥ 0.

#include <spar/error.hpp>
#include <spar/lie/coefficients.hpp>
#include <spar/lie/exp.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>
#include <cmath>

namespace spar::lie {

template <class Scalar>
using Quaternion = Eigen::Quaternion<Scalar>;

/// The unit quaternion of a rotation matrix by Shepperd's largest-pivot rule: the component with
/// the largest magnitude is taken from a square root, the other three from sums or differences of
/// off-diagonal entries divided by it, so no branch divides by a small number (eq. C10).
template <class Derived>
Quaternion<typename Derived::Scalar> quaternion_from_rotation(const Eigen::MatrixBase<Derived>& R) {
  using Scalar = typename Derived::Scalar;
  using std::sqrt;
  const Scalar trace = R.trace();
  Scalar w, x, y, z;
  if (trace >= R(0, 0) && trace >= R(1, 1) && trace >= R(2, 2)) {
    w = sqrt(Scalar(1) + trace) / 2;
    const Scalar f = Scalar(1) / (4 * w);
    x = (R(2, 1) - R(1, 2)) * f;
    y = (R(0, 2) - R(2, 0)) * f;
    z = (R(1, 0) - R(0, 1)) * f;
  } else if (R(0, 0) >= R(1, 1) && R(0, 0) >= R(2, 2)) {
    x = sqrt(Scalar(1) + R(0, 0) - R(1, 1) - R(2, 2)) / 2;
    const Scalar f = Scalar(1) / (4 * x);
    w = (R(2, 1) - R(1, 2)) * f;
    y = (R(0, 1) + R(1, 0)) * f;
    z = (R(0, 2) + R(2, 0)) * f;
  } else if (R(1, 1) >= R(2, 2)) {
    y = sqrt(Scalar(1) - R(0, 0) + R(1, 1) - R(2, 2)) / 2;
    const Scalar f = Scalar(1) / (4 * y);
    w = (R(0, 2) - R(2, 0)) * f;
    x = (R(0, 1) + R(1, 0)) * f;
    z = (R(1, 2) + R(2, 1)) * f;
  } else {
    z = sqrt(Scalar(1) - R(0, 0) - R(1, 1) + R(2, 2)) / 2;
    const Scalar f = Scalar(1) / (4 * z);
    w = (R(1, 0) - R(0, 1)) * f;
    x = (R(0, 2) + R(2, 0)) * f;
    y = (R(1, 2) + R(2, 1)) * f;
  }
  const Scalar sign = (w < 0) ? Scalar(-1) : Scalar(1);
  return Quaternion<Scalar>(sign * w, sign * x, sign * y, sign * z);
}

/// The rotation matrix of a unit quaternion (eq. C11).
template <class Scalar>
Matrix3<Scalar> rotation_from_quaternion(const Quaternion<Scalar>& q) {
  return q.toRotationMatrix();
}

/// q = (cos(θ/2), sin(θ/2)/θ · Θ), the quaternion of exp(Θ) (eq. C12).
template <class Derived>
Quaternion<typename Derived::Scalar> quaternion_from_rotation_vector(
    const Eigen::MatrixBase<Derived>& theta) {
  using Scalar = typename Derived::Scalar;
  using std::cos;
  const Scalar half = detail::checked_angle(theta, "lie::quaternion_from_rotation_vector") / 2;
  // sin(θ/2)/θ = a1(θ/2)/2, a1 keeping full precision as θ → 0.
  const Vector3<Scalar> v = coefficients::a1(half) / 2 * theta;
  return Quaternion<Scalar>(cos(half), v(0), v(1), v(2));
}

/// The rotation vector of a unit quaternion, with angle in [0, π]: θ = 2 atan2(‖v‖, |w|)
/// (eq. C12). Below ‖v‖/|w| = 1e-4 the factor θ/‖v‖ = (2/w)·atan(r)/r is taken from its series
/// 1 − r²/3 + r⁴/5, exact to round-off there; above, atan2 has no cancellation.
template <class Scalar>
Vector3<Scalar> rotation_vector_from_quaternion(const Quaternion<Scalar>& q) {
  using std::atan2;
  const Scalar sign = (q.w() < 0) ? Scalar(-1) : Scalar(1);
  const Scalar w = sign * q.w();
  const Vector3<Scalar> v = sign * q.vec();
  const Scalar n = v.norm();
  Scalar factor;
  if (n < Scalar(1e-4) * w) {
    const Scalar r2 = (n / w) * (n / w);
    factor = Scalar(2) / w * (Scalar(1) - r2 / 3 + r2 * r2 / 5);
  } else {
    factor = 2 * atan2(n, w) / n;
  }
  return factor * v;
}

}  // namespace spar::lie
