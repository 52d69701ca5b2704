#pragma once
/// \file
/// The tangent operator T(Θ) of SO(3), its inverse, and their directional derivatives
/// (docs/conventions.md eqs. C4–C8).
///
/// T is the right-trivialized differential of exp (003 eq. 10):
///   exp(Θ + δ) = exp(Θ)·exp(T(Θ) δ) + O(δ²),   T = I − a2 Θ̃ + a3 Θ̃²,
/// so T is the "right Jacobian" J_r of the Lie-group literature; Tᵀ = T(−Θ) = J_l and
/// exp(Θ)·T(Θ) = T(Θ)ᵀ. The beam's curvature is κ = T(Θ)Θ′ (003 eq. 9).

#include <spar/error.hpp>
#include <spar/lie/coefficients.hpp>
#include <spar/lie/exp.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

#include <numbers>
#include <string>

namespace spar::lie {

namespace detail {

/// I + s·Θ̃ + c·Θ̃², evaluated as I + sΘ̃ + c(ΘΘᵀ − θ²I).
template <class Derived, class Scalar>
Matrix3<Scalar> identity_plus_hat_terms(const Eigen::MatrixBase<Derived>& theta, Scalar angle,
                                        Scalar s, Scalar c) {
  Matrix3<Scalar> M = c * theta * theta.transpose();
  M.diagonal().array() += Scalar(1) - c * angle * angle;
  M += s * hat(theta);
  return M;
}

/// ∂(Θ̃²a)/∂Θ = (Θ·a) I + Θ aᵀ − 2 a Θᵀ.
template <class Scalar>
Matrix3<Scalar> hat_squared_derivative(const Vector3<Scalar>& theta, const Vector3<Scalar>& a) {
  Matrix3<Scalar> M = theta * a.transpose() - 2 * a * theta.transpose();
  M.diagonal().array() += theta.dot(a);
  return M;
}

/// ∂/∂Θ [ (I − σ a2 Θ̃ + a3 Θ̃²) a ] for σ = +1 (T) and σ = −1 (Tᵀ), eq. C6:
///   −σ c2 (Θ̃a)Θᵀ + σ a2 ã + c3 (Θ̃²a)Θᵀ + a3 [(Θ·a)I + Θaᵀ − 2aΘᵀ],
/// from the coefficients k of T at Θ (k.a2, k.a3, k.c2, k.c3).
template <class Scalar, class Coefficients>
Matrix3<Scalar> tangent_family_derivative(const Vector3<Scalar>& theta, const Vector3<Scalar>& a,
                                          Scalar sigma, const Coefficients& k) {
  const Vector3<Scalar> theta_cross_a = theta.cross(a);
  const Vector3<Scalar> hat2_a = theta.cross(theta_cross_a);
  Matrix3<Scalar> D = (-sigma * k.c2 * theta_cross_a + k.c3 * hat2_a) * theta.transpose();
  D += sigma * k.a2 * hat(a);
  D += k.a3 * hat_squared_derivative(theta, a);
  return D;
}

/// ∂/∂Θ [ (∂/∂Θ[(I − σ a2 Θ̃ + a3 Θ̃²) a]) b ], eq. C7 (the paper's H of 003 eq. 26 for σ = −1,
/// a = M, b = Θ′).
template <class Scalar>
Matrix3<Scalar> tangent_family_second_derivative(const Vector3<Scalar>& theta,
                                                 const Vector3<Scalar>& a,
                                                 const Vector3<Scalar>& b, Scalar sigma) {
  using coefficients::a3;
  using coefficients::b2;
  using coefficients::b3;
  using coefficients::c2;
  using coefficients::c3;
  const Scalar angle = checked_angle(theta, "lie::tangent_second_derivative");
  const Scalar theta_b = theta.dot(b);
  const Scalar theta_a = theta.dot(a);
  const Vector3<Scalar> theta_cross_a = theta.cross(a);
  const Vector3<Scalar> hat2_a = theta.cross(theta_cross_a);
  const Scalar c2v = c2(angle);
  const Scalar c3v = c3(angle);
  // Terms proportional to (·)Θᵀ: derivatives of the coefficient functions.
  const Vector3<Scalar> row_theta =
      (-sigma * b2(angle) * theta_b) * theta_cross_a + (b3(angle) * theta_b) * hat2_a +
      sigma * c2v * a.cross(b) + c3v * (theta_a * b + a.dot(b) * theta - 2 * theta_b * a);
  Matrix3<Scalar> H = row_theta * theta.transpose();
  // Terms proportional to (·)bᵀ: derivatives of Θ·b.
  H += (-sigma * c2v * theta_cross_a + c3v * hat2_a) * b.transpose();
  // The rest: derivatives of Θ̃a and Θ̃²a at fixed coefficients.
  H += (sigma * c2v * theta_b) * hat(a);
  H += (c3v * theta_b) * hat_squared_derivative(theta, a);
  Matrix3<Scalar> last = b * a.transpose() - 2 * a * b.transpose();
  last.diagonal().array() += a.dot(b);
  H += a3(angle) * last;
  return H;
}

/// ∂/∂Θ [ (I + σ ½ Θ̃ + a4 Θ̃²) a ] for σ = +1 (T⁻¹) and σ = −1 (T⁻ᵀ), eq. C8:
///   −σ ½ ã + c6 (Θ̃²a)Θᵀ + a4 [(Θ·a)I + Θaᵀ − 2aΘᵀ].
template <class Scalar>
Matrix3<Scalar> tangent_inverse_family_derivative(const Vector3<Scalar>& theta,
                                                  const Vector3<Scalar>& a, Scalar sigma) {
  const Scalar angle = checked_angle(theta, "lie::tangent_inverse_derivative");
  const Vector3<Scalar> hat2_a = theta.cross(theta.cross(a));
  Matrix3<Scalar> D = coefficients::c6(angle) * hat2_a * theta.transpose();
  D -= (sigma / 2) * hat(a);
  D += coefficients::a4(angle) * hat_squared_derivative(theta, a);
  return D;
}

/// Throws unless θ < 2π, where T⁻¹ exists.
template <class Scalar>
void check_invertible_tangent(Scalar angle) {
  if (!(angle < Scalar(2 * std::numbers::pi)))
    throw Error("the tangent operator is singular at |theta| = 2 pi (here |theta| = " +
                    std::to_string(static_cast<double>(angle)) + ")",
                "lie::tangent_inverse",
                "use the equivalent rotation vector of angle below pi (lie::log(lie::exp(theta)))");
}

}  // namespace detail

/// The coefficients of exp(Θ), T(Θ) and T's first derivatives at one Θ (eqs. C3–C6): for a caller
/// that needs several of them at the same point — a beam's Gauss point takes exp, T, ∂(TΘ′)/∂Θ,
/// two ∂(Tᵀa)/∂Θ and a Hessian — each coefficient is a Taylor sum or a trigonometric expression,
/// worth computing once. The overloads below that take them give the same values as those that
/// do not, bit for bit.
template <class Scalar>
struct TangentCoefficients {
  Scalar angle, a1, a2, a3, c2, c3;
};

/// The coefficients of exp, T and T's first derivatives at Θ.
template <class Derived>
TangentCoefficients<typename Derived::Scalar> tangent_coefficients(const Eigen::MatrixBase<Derived>& theta) {
  const auto angle = detail::checked_angle(theta, "lie::tangent_coefficients");
  return {angle, coefficients::a1(angle), coefficients::a2(angle), coefficients::a3(angle),
          coefficients::c2(angle), coefficients::c3(angle)};
}

/// T(Θ) = I − a2 Θ̃ + a3 Θ̃² (003 eq. 10; eq. C4).
template <class Derived>
Matrix3<typename Derived::Scalar> tangent(const Eigen::MatrixBase<Derived>& theta) {
  const auto angle = detail::checked_angle(theta, "lie::tangent");
  return detail::identity_plus_hat_terms(theta, angle, -coefficients::a2(angle),
                                         coefficients::a3(angle));
}

/// T⁻¹(Θ) = I + ½ Θ̃ + a4 Θ̃² (003 eq. 11; eq. C5). Requires ‖Θ‖ < 2π.
template <class Derived>
Matrix3<typename Derived::Scalar> tangent_inverse(const Eigen::MatrixBase<Derived>& theta) {
  using Scalar = typename Derived::Scalar;
  const Scalar angle = detail::checked_angle(theta, "lie::tangent_inverse");
  detail::check_invertible_tangent(angle);
  return detail::identity_plus_hat_terms(theta, angle, Scalar(0.5), coefficients::a4(angle));
}

/// J = ∂(T(Θ) a)/∂Θ, so that T(Θ + δ)a = T(Θ)a + J δ + O(δ²) (eq. C6), with the coefficients k
/// of tangent_coefficients(Θ).
template <class DerivedT, class DerivedA>
Matrix3<typename DerivedT::Scalar> tangent_derivative(const Eigen::MatrixBase<DerivedT>& theta,
                                                      const Eigen::MatrixBase<DerivedA>& a,
                                                      const TangentCoefficients<typename DerivedT::Scalar>& k) {
  using Scalar = typename DerivedT::Scalar;
  return detail::tangent_family_derivative<Scalar>(theta, a, Scalar(1), k);
}

/// J = ∂(T(Θ) a)/∂Θ, so that T(Θ + δ)a = T(Θ)a + J δ + O(δ²) (eq. C6).
template <class DerivedT, class DerivedA>
Matrix3<typename DerivedT::Scalar> tangent_derivative(const Eigen::MatrixBase<DerivedT>& theta,
                                                      const Eigen::MatrixBase<DerivedA>& a) {
  return tangent_derivative(theta, a, tangent_coefficients(theta));
}

/// J = ∂(T(Θ)ᵀ a)/∂Θ (eq. C6; 003 eq. 28 writes it as Ξ(ΔTᵀa), with c4 = a2, c5 = a3), with the
/// coefficients k of tangent_coefficients(Θ).
template <class DerivedT, class DerivedA>
Matrix3<typename DerivedT::Scalar> tangent_transpose_derivative(
    const Eigen::MatrixBase<DerivedT>& theta, const Eigen::MatrixBase<DerivedA>& a,
    const TangentCoefficients<typename DerivedT::Scalar>& k) {
  using Scalar = typename DerivedT::Scalar;
  return detail::tangent_family_derivative<Scalar>(theta, a, Scalar(-1), k);
}

/// J = ∂(T(Θ)ᵀ a)/∂Θ (eq. C6; 003 eq. 28 writes it as Ξ(ΔTᵀa), with c4 = a2, c5 = a3).
template <class DerivedT, class DerivedA>
Matrix3<typename DerivedT::Scalar> tangent_transpose_derivative(
    const Eigen::MatrixBase<DerivedT>& theta, const Eigen::MatrixBase<DerivedA>& a) {
  return tangent_transpose_derivative(theta, a, tangent_coefficients(theta));
}

/// H = ∂/∂Θ [ tangent_derivative(Θ, a) · b ] (eq. C7): the derivative of T′a along Θ′ = b.
template <class DerivedT, class DerivedA, class DerivedB>
Matrix3<typename DerivedT::Scalar> tangent_second_derivative(
    const Eigen::MatrixBase<DerivedT>& theta, const Eigen::MatrixBase<DerivedA>& a,
    const Eigen::MatrixBase<DerivedB>& b) {
  using Scalar = typename DerivedT::Scalar;
  return detail::tangent_family_second_derivative<Scalar>(theta, a, b, Scalar(1));
}

/// H = ∂/∂Θ [ tangent_transpose_derivative(Θ, a) · b ] (eq. C7). With a = M and b = Θ′ this is
/// the H of 003 eq. (26); the paper prints its c5 term as "Θ′M I₃" where (Θ′ᵀM) I₃ is meant.
template <class DerivedT, class DerivedA, class DerivedB>
Matrix3<typename DerivedT::Scalar> tangent_transpose_second_derivative(
    const Eigen::MatrixBase<DerivedT>& theta, const Eigen::MatrixBase<DerivedA>& a,
    const Eigen::MatrixBase<DerivedB>& b) {
  using Scalar = typename DerivedT::Scalar;
  return detail::tangent_family_second_derivative<Scalar>(theta, a, b, Scalar(-1));
}

/// The gradient ∂(mᵀ T(Θ) b)/∂Θ = tangent_derivative(Θ, b)ᵀ m of the scalar mᵀT(Θ)b, without
/// forming the 3 × 3 derivative (eq. C6 contracted with m): with the coefficients of T,
///   [m·(−c2 Θ×b + c3 Θ×(Θ×b))] Θ + a2 (m × b) + a3 ((Θ·b) m + (Θ·m) b − 2 (m·b) Θ).
/// It is the force of the curvature energy mᵀκ, κ = T(Θ)Θ′, for b = Θ′.
/// With the coefficients k of tangent_coefficients(Θ).
template <class DerivedT, class DerivedM, class DerivedB>
Vector3<typename DerivedT::Scalar> tangent_gradient(const Eigen::MatrixBase<DerivedT>& theta_in,
                                                    const Eigen::MatrixBase<DerivedM>& m_in,
                                                    const Eigen::MatrixBase<DerivedB>& b_in,
                                                    const TangentCoefficients<typename DerivedT::Scalar>& k) {
  using Scalar = typename DerivedT::Scalar;
  const Vector3<Scalar> theta = theta_in, m = m_in, b = b_in;
  const Vector3<Scalar> theta_cross_b = theta.cross(b);
  const Scalar along_theta = m.dot(-k.c2 * theta_cross_b + k.c3 * theta.cross(theta_cross_b));
  return along_theta * theta + k.a2 * m.cross(b) +
         k.a3 * (theta.dot(b) * m + theta.dot(m) * b - 2 * m.dot(b) * theta);
}

template <class DerivedT, class DerivedM, class DerivedB>
Vector3<typename DerivedT::Scalar> tangent_gradient(const Eigen::MatrixBase<DerivedT>& theta,
                                                    const Eigen::MatrixBase<DerivedM>& m,
                                                    const Eigen::MatrixBase<DerivedB>& b) {
  return tangent_gradient(theta, m, b, tangent_coefficients(theta));
}

/// The Hessian ∂²(mᵀ T(Θ) b)/∂Θ² of the scalar mᵀT(Θ)b (symmetric; eq. C7b). With s = mᵀΘ̃²b,
/// p = b × m and q = ∂s/∂Θ = (b·Θ) m + (m·Θ) b − 2 (m·b) Θ:
///   (b3 s − b2 Θ·p) ΘΘᵀ − c2 (Θpᵀ + pΘᵀ + (Θ·p) I) + c3 (Θqᵀ + qΘᵀ + s I) + a3 (mbᵀ + bmᵀ − 2 (m·b) I).
/// It is the geometric stiffness of the curvature energy mᵀκ, κ = T(Θ)Θ′, for b = Θ′.
/// For the transpose, mᵀT(Θ)ᵀb = bᵀT(Θ)m: swap the arguments.
/// With the coefficients k of tangent_coefficients(Θ) (b2 and b3, which only this needs, are
/// computed here).
template <class DerivedT, class DerivedM, class DerivedB>
Matrix3<typename DerivedT::Scalar> tangent_hessian(const Eigen::MatrixBase<DerivedT>& theta_in,
                                                   const Eigen::MatrixBase<DerivedM>& m_in,
                                                   const Eigen::MatrixBase<DerivedB>& b_in,
                                                   const TangentCoefficients<typename DerivedT::Scalar>& k) {
  using Scalar = typename DerivedT::Scalar;
  const Vector3<Scalar> theta = theta_in, m = m_in, b = b_in;
  const Vector3<Scalar> p = b.cross(m);
  const Scalar m_dot_b = m.dot(b);
  const Scalar s = m.dot(theta) * b.dot(theta) - k.angle * k.angle * m_dot_b;
  const Vector3<Scalar> q = b.dot(theta) * m + m.dot(theta) * b - 2 * m_dot_b * theta;
  Matrix3<Scalar> H =
      (coefficients::b3(k.angle) * s - coefficients::b2(k.angle) * theta.dot(p)) * theta * theta.transpose();
  H -= k.c2 * (theta * p.transpose() + p * theta.transpose());
  H += k.c3 * (theta * q.transpose() + q * theta.transpose());
  H += k.a3 * (m * b.transpose() + b * m.transpose());
  H.diagonal().array() += k.c3 * s - k.c2 * theta.dot(p) - 2 * k.a3 * m_dot_b;
  return H;
}

template <class DerivedT, class DerivedM, class DerivedB>
Matrix3<typename DerivedT::Scalar> tangent_hessian(const Eigen::MatrixBase<DerivedT>& theta,
                                                   const Eigen::MatrixBase<DerivedM>& m,
                                                   const Eigen::MatrixBase<DerivedB>& b) {
  return tangent_hessian(theta, m, b, tangent_coefficients(theta));
}

/// J = ∂(T⁻¹(Θ) a)/∂Θ (eq. C8). Requires ‖Θ‖ < 2π.
template <class DerivedT, class DerivedA>
Matrix3<typename DerivedT::Scalar> tangent_inverse_derivative(
    const Eigen::MatrixBase<DerivedT>& theta, const Eigen::MatrixBase<DerivedA>& a) {
  using Scalar = typename DerivedT::Scalar;
  detail::check_invertible_tangent(detail::checked_angle(theta, "lie::tangent_inverse_derivative"));
  return detail::tangent_inverse_family_derivative<Scalar>(theta, a, Scalar(1));
}

/// J = ∂(T⁻ᵀ(Θ) a)/∂Θ (eq. C8). Requires ‖Θ‖ < 2π.
template <class DerivedT, class DerivedA>
Matrix3<typename DerivedT::Scalar> tangent_inverse_transpose_derivative(
    const Eigen::MatrixBase<DerivedT>& theta, const Eigen::MatrixBase<DerivedA>& a) {
  using Scalar = typename DerivedT::Scalar;
  detail::check_invertible_tangent(
      detail::checked_angle(theta, "lie::tangent_inverse_transpose_derivative"));
  return detail::tangent_inverse_family_derivative<Scalar>(theta, a, Scalar(-1));
}

/// exp(Θ) and T(Θ) together, sharing the angle and the coefficients a2.
template <class Scalar>
struct ExpAndTangent {
  Matrix3<Scalar> rotation;
  Matrix3<Scalar> tangent;
};

/// exp(Θ) and T(Θ) in one call (the pair every beam Gauss point needs), from the coefficients k of
/// tangent_coefficients(Θ).
template <class Derived>
ExpAndTangent<typename Derived::Scalar> exp_and_tangent(const Eigen::MatrixBase<Derived>& theta,
                                                        const TangentCoefficients<typename Derived::Scalar>& k) {
  using Scalar = typename Derived::Scalar;
  const Matrix3<Scalar> S = hat(theta);
  Matrix3<Scalar> outer = theta * theta.transpose();
  outer.diagonal().array() -= k.angle * k.angle;  // Θ̃² = ΘΘᵀ − θ²I
  ExpAndTangent<Scalar> result;
  result.rotation = k.a1 * S + k.a2 * outer;
  result.rotation.diagonal().array() += Scalar(1);
  result.tangent = k.a3 * outer - k.a2 * S;
  result.tangent.diagonal().array() += Scalar(1);
  return result;
}

/// exp(Θ) and T(Θ) in one call, sharing the angle and the coefficient a2.
template <class Derived>
ExpAndTangent<typename Derived::Scalar> exp_and_tangent(const Eigen::MatrixBase<Derived>& theta) {
  return exp_and_tangent(theta, tangent_coefficients(theta));
}

}  // namespace spar::lie
