#pragma once
/// \file
/// The SO(3) exponential (Rodrigues' formula, 003 eqs. 2–3; docs/conventions.md eq. C2) and the
/// right-trivialized update R ← R·exp(Δφ) used by every solver.

#include <spar/error.hpp>
#include <spar/lie/coefficients.hpp>
#include <spar/lie/hat.hpp>

#include <cmath>
#include <string_view>

namespace spar::lie {

namespace detail {

/// ‖Θ‖, or a spar::Error naming `where` when Θ has a NaN or infinite entry.
template <class Derived>
typename Derived::Scalar checked_angle(const Eigen::MatrixBase<Derived>& theta,
                                       std::string_view where) {
  const auto angle = theta.norm();
  if (!std::isfinite(static_cast<double>(angle)))
    throw Error("the rotation vector has a NaN or infinite entry", where,
                "check the state or the increment that produced it");
  return angle;
}

}  // namespace detail

/// R = exp(Θ̃) = I + a1 Θ̃ + a2 Θ̃² (003 eq. 2), evaluated as I + a1 Θ̃ + a2 (ΘΘᵀ − θ² I).
/// Valid for every angle; exp(Θ) for θ > π equals exp of the equivalent vector of angle 2π − θ.
template <class Derived>
Matrix3<typename Derived::Scalar> exp(const Eigen::MatrixBase<Derived>& theta) {
  using Scalar = typename Derived::Scalar;
  const Scalar angle = detail::checked_angle(theta, "lie::exp");
  const Scalar alpha = coefficients::a1(angle);
  const Scalar beta = coefficients::a2(angle);
  Matrix3<Scalar> R = beta * theta * theta.transpose();
  R.diagonal().array() += Scalar(1) - beta * angle * angle;
  R += alpha * hat(theta);
  return R;
}

/// The local-frame (right-trivialized) update R·exp(Δφ) (docs/conventions.md eq. C9).
template <class DerivedR, class DerivedPhi>
Matrix3<typename DerivedR::Scalar> right_plus(const Eigen::MatrixBase<DerivedR>& R,
                                              const Eigen::MatrixBase<DerivedPhi>& delta_phi) {
  return R * exp(delta_phi);
}

}  // namespace spar::lie
