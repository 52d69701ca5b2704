#pragma once
/// \file
/// The SO(3) logarithm (003 eq. 4; docs/conventions.md eq. C13), through the quaternion so that it
/// stays exact near θ = π, where the paper's acos((tr R − 1)/2) form loses half the digits.

#include <spar/error.hpp>
#include <spar/lie/quaternion.hpp>

#include <cmath>
#include <string>

namespace spar::lie {

/// Tolerance on ‖RᵀR − I‖ (Frobenius) above which log refuses a matrix as not a rotation.
inline constexpr double rotation_tolerance = 1e-9;

/// Throws spar::Error unless R is a finite proper rotation: ‖RᵀR − I‖_F ≤ 1e-9 and det R > 0.
template <class Derived>
void check_rotation(const Eigen::MatrixBase<Derived>& R, std::string_view where) {
  using Scalar = typename Derived::Scalar;
  if (!R.allFinite())
    throw Error("the matrix has a NaN or infinite entry", where,
                "check the state or the increment that produced it");
  const Scalar orthogonality = (R.transpose() * R - Matrix3<Scalar>::Identity()).norm();
  if (!(orthogonality <= Scalar(rotation_tolerance)))
    throw Error("the matrix is not orthogonal: |R^T R - I| = " +
                    significant(static_cast<double>(orthogonality)) + " > 1e-9",
                where, "pass a rotation matrix, or re-orthogonalize it first");
  if (!(R.determinant() > 0))
    throw Error("the matrix is a reflection (det R <= 0), not a rotation", where,
                "pass a proper rotation with det R = +1");
}

/// The rotation vector Θ with ‖Θ‖ ∈ [0, π] and exp(Θ) = R (eq. C13). At θ = π both ±Θ are
/// valid; the one whose largest-magnitude component is positive is returned.
/// Throws spar::Error for a matrix that is not a rotation (see check_rotation).
template <class Derived>
Vector3<typename Derived::Scalar> log(const Eigen::MatrixBase<Derived>& R) {
  check_rotation(R, "lie::log");
  return rotation_vector_from_quaternion(quaternion_from_rotation(R));
}

/// The relative rotation vector log(R_rᵀ R) of Crisfield–Jelenić interpolation (003 eq. 40):
/// R = R_r · exp(relative_rotation(R_r, R)).
template <class DerivedRr, class DerivedR>
Vector3<typename DerivedR::Scalar> relative_rotation(const Eigen::MatrixBase<DerivedRr>& R_r,
                                                     const Eigen::MatrixBase<DerivedR>& R) {
  return log(R_r.transpose() * R);
}

}  // namespace spar::lie
