#pragma once
/// \file
/// hat and vee: the isomorphism between R³ and so(3), the skew-symmetric 3×3 matrices
/// (docs/conventions.md, eq. C1): hat(v)·w = v × w.

#include <Eigen/Core>

namespace spar::lie {

template <class Scalar>
using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
template <class Scalar>
using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;

/// The skew-symmetric matrix of v, so that hat(v)·w = v × w (003 notation: Θ̃).
template <class Derived>
Matrix3<typename Derived::Scalar> hat(const Eigen::MatrixBase<Derived>& v) {
  using Scalar = typename Derived::Scalar;
  Matrix3<Scalar> S;
  S << Scalar(0), -v(2), v(1),  //
      v(2), Scalar(0), -v(0),   //
      -v(1), v(0), Scalar(0);
  return S;
}

/// The axial vector of the skew-symmetric part of S: vee(hat(v)) = v.
template <class Derived>
Vector3<typename Derived::Scalar> vee(const Eigen::MatrixBase<Derived>& S) {
  using Scalar = typename Derived::Scalar;
  return Vector3<Scalar>(S(2, 1) - S(1, 2), S(0, 2) - S(2, 0), S(1, 0) - S(0, 1)) / Scalar(2);
}

}  // namespace spar::lie
