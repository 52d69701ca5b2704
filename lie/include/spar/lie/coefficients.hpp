#pragma once
/// \file
/// The scalar coefficient functions of the SO(3) exponential, its tangent operator and their
/// derivatives, as functions of the rotation angle θ = ‖Θ‖ (docs/conventions.md, eqs. C3–C8).
///
/// Every one of them is an even, entire (a4, c6: analytic for θ < 2π) function of θ whose closed
/// form loses digits to cancellation as θ → 0. Each therefore has exactly one switch point θₛ:
/// below it, a Taylor series in x = θ² with enough terms to be exact to round-off at θₛ (the
/// truncation error there is below 1e-24 relative, so the `long double` instantiation is an
/// oracle for the `double` one); above it, the closed form, whose cancellation at θₛ costs at most
/// a factor ~100 of round-off. tests/lie/coefficients_test.cpp proves both sides.
///
/// With the operator D = (1/θ) d/dθ = 2 d/dx, the derivative families are
///   c1 = D a1, c2 = D a2, c3 = D a3, c6 = D a4, b1 = D c1, b2 = D c2, b3 = D c3,
/// so that ∂a(‖Θ‖)/∂Θ = (D a) Θᵀ. The paper's c4 and c5 (003 eq. 27) are a2 and a3.

#include <array>
#include <cmath>

namespace spar::lie::coefficients {

namespace detail {

/// Taylor coefficients s_k (k = 0..N−1, in powers of x = θ²) of D^d applied to the series
/// Σ_j (−1)^j x^j / (2j + m)!, i.e. of sin-type functions: m = 1 gives sin θ/θ, m = 2 gives
/// (1 − cos θ)/θ², m = 3 gives (θ − sin θ)/θ³. D = 2 d/dx, so s_k = 2^d (k+1)…(k+d) t_{k+d}.
template <int N>
constexpr std::array<long double, N> sine_family_series(int m, int d) {
  std::array<long double, N> s{};
  for (int k = 0; k < N; ++k) {
    const int j = k + d;
    long double factorial = 1.0L;
    for (int i = 2; i <= 2 * j + m; ++i) factorial *= static_cast<long double>(i);
    long double c = ((j % 2 == 0) ? 1.0L : -1.0L) / factorial;
    for (int i = 1; i <= d; ++i) c *= static_cast<long double>(2 * (k + i));
    s[k] = c;
  }
  return s;
}

/// Taylor coefficients (in x = θ²) of D^d applied to a4(θ) = (1 − (θ/2)cot(θ/2))/θ²
/// = Σ_k (−1)^k B_{2k+2} x^k / (2k+2)!, with the Bernoulli numbers B_2 … B_30.
template <int N, int d>
constexpr std::array<long double, N> cotangent_family_series() {
  constexpr long double bernoulli[] = {
      1.0L / 6.0L,           -1.0L / 30.0L,        1.0L / 42.0L,          -1.0L / 30.0L,
      5.0L / 66.0L,          -691.0L / 2730.0L,    7.0L / 6.0L,           -3617.0L / 510.0L,
      43867.0L / 798.0L,     -174611.0L / 330.0L,  854513.0L / 138.0L,    -236364091.0L / 2730.0L,
      8553103.0L / 6.0L,     -23749461029.0L / 870.0L,
      8615841276005.0L / 14322.0L};  // B_2, B_4, …, B_30
  static_assert(N + d <= 15, "extend the Bernoulli table");
  std::array<long double, N> s{};
  for (int k = 0; k < N; ++k) {
    const int j = k + d;
    long double factorial = 1.0L;
    for (int i = 2; i <= 2 * j + 2; ++i) factorial *= static_cast<long double>(i);
    long double c = ((j % 2 == 0) ? 1.0L : -1.0L) * bernoulli[j] / factorial;
    for (int i = 1; i <= d; ++i) c *= static_cast<long double>(2 * (k + i));
    s[k] = c;
  }
  return s;
}

/// The table s rounded to Scalar.
template <class Scalar, std::size_t N>
constexpr std::array<Scalar, N> rounded(const std::array<long double, N>& s) {
  std::array<Scalar, N> r{};
  for (std::size_t k = 0; k < N; ++k) r[k] = static_cast<Scalar>(s[k]);
  return r;
}

/// A series table in the precision of Scalar, rounded once at compile time: rounded at every
/// call, each term cost an x87 load and store (~40 % of a beam Gauss point's Hessian terms).
/// Rounding to nearest either way, the values are the same bit for bit.
template <class Scalar, const auto& series>
inline constexpr auto in_precision = rounded<Scalar>(series);

/// Σ s_k x^k by Horner's rule, in the precision of Scalar.
template <class Scalar, std::size_t N>
Scalar horner(const std::array<Scalar, N>& s, Scalar x) {
  Scalar sum = s[N - 1];
  for (std::size_t k = N - 1; k-- > 0;) sum = sum * x + s[k];
  return sum;
}

/// The series `series` at x = θ², in the precision of Scalar.
template <class Scalar, const auto& series>
Scalar series_at(Scalar theta) {
  return horner(in_precision<Scalar, series>, theta * theta);
}

// Series tables. Lengths are chosen so that the truncation error at the switch point is below
// 1e-24 relative (checked by the tests, which compare with the closed form in long double).
inline constexpr auto a1_series = sine_family_series<8>(1, 0);
inline constexpr auto a2_series = sine_family_series<8>(2, 0);
inline constexpr auto a3_series = sine_family_series<10>(3, 0);
inline constexpr auto a4_series = cotangent_family_series<11, 0>();
inline constexpr auto c1_series = sine_family_series<14>(1, 1);
inline constexpr auto c2_series = sine_family_series<14>(2, 1);
inline constexpr auto c3_series = sine_family_series<14>(3, 1);
inline constexpr auto c6_series = cotangent_family_series<14, 1>();
inline constexpr auto b1_series = sine_family_series<20>(1, 2);
inline constexpr auto b2_series = sine_family_series<20>(2, 2);
inline constexpr auto b3_series = sine_family_series<20>(3, 2);

}  // namespace detail

/// Switch points θₛ: the series is used for θ < θₛ, the closed form for θ ≥ θₛ.
/// a1 and a2 have closed forms free of cancellation (a2 through the half angle), so their switch
/// only avoids 0/0; the others switch where the closed form's cancellation is still mild.
inline constexpr double a1_switch = 0.25;
inline constexpr double a2_switch = 0.25;
inline constexpr double a3_switch = 0.5;
inline constexpr double a4_switch = 0.5;
inline constexpr double c_switch = 1.0;   // c1, c2, c3
inline constexpr double c6_switch = 1.0;
inline constexpr double b_switch = 2.25;  // b1, b2, b3

/// The Taylor series of each coefficient in x = θ², exact to round-off for θ < θₛ.
namespace series {
template <class Scalar> Scalar a1(Scalar theta) { return detail::series_at<Scalar, detail::a1_series>(theta); }
template <class Scalar> Scalar a2(Scalar theta) { return detail::series_at<Scalar, detail::a2_series>(theta); }
template <class Scalar> Scalar a3(Scalar theta) { return detail::series_at<Scalar, detail::a3_series>(theta); }
template <class Scalar> Scalar a4(Scalar theta) { return detail::series_at<Scalar, detail::a4_series>(theta); }
template <class Scalar> Scalar c1(Scalar theta) { return detail::series_at<Scalar, detail::c1_series>(theta); }
template <class Scalar> Scalar c2(Scalar theta) { return detail::series_at<Scalar, detail::c2_series>(theta); }
template <class Scalar> Scalar c3(Scalar theta) { return detail::series_at<Scalar, detail::c3_series>(theta); }
template <class Scalar> Scalar c6(Scalar theta) { return detail::series_at<Scalar, detail::c6_series>(theta); }
template <class Scalar> Scalar b1(Scalar theta) { return detail::series_at<Scalar, detail::b1_series>(theta); }
template <class Scalar> Scalar b2(Scalar theta) { return detail::series_at<Scalar, detail::b2_series>(theta); }
template <class Scalar> Scalar b3(Scalar theta) { return detail::series_at<Scalar, detail::b3_series>(theta); }
}  // namespace series

/// The closed forms (003 eqs. 3, 11, 27), accurate for θ ≥ θₛ.
namespace closed_form {

/// a1(θ) = sin θ / θ (003 eq. 3).
template <class Scalar>
Scalar a1(Scalar theta) {
  using std::sin;
  return sin(theta) / theta;
}

/// a2(θ) = (1 − cos θ)/θ² (003 eq. 3), evaluated as ½ (sin(θ/2)/(θ/2))², free of cancellation.
template <class Scalar>
Scalar a2(Scalar theta) {
  using std::sin;
  const Scalar half_sinc = sin(theta / 2) / (theta / 2);
  return half_sinc * half_sinc / 2;
}

/// a3(θ) = (θ − sin θ)/θ³ (003 eq. 11).
template <class Scalar>
Scalar a3(Scalar theta) {
  using std::sin;
  return (theta - sin(theta)) / (theta * theta * theta);
}

/// a4(θ) = (1 − (θ/2) cot(θ/2))/θ² (003 eq. 11). Analytic for θ < 2π.
template <class Scalar>
Scalar a4(Scalar theta) {
  using std::cos;
  using std::sin;
  const Scalar half = theta / 2;
  return (Scalar(1) - half * cos(half) / sin(half)) / (theta * theta);
}

/// c1(θ) = (θ cos θ − sin θ)/θ³ (003 eq. 27).
template <class Scalar>
Scalar c1(Scalar theta) {
  using std::cos;
  using std::sin;
  return (theta * cos(theta) - sin(theta)) / (theta * theta * theta);
}

/// c2(θ) = (θ sin θ + 2 cos θ − 2)/θ⁴ (003 eq. 27).
template <class Scalar>
Scalar c2(Scalar theta) {
  using std::cos;
  using std::sin;
  const Scalar theta2 = theta * theta;
  return (theta * sin(theta) + 2 * cos(theta) - 2) / (theta2 * theta2);
}

/// c3(θ) = (3 sin θ − 2θ − θ cos θ)/θ⁵ (003 eq. 27).
template <class Scalar>
Scalar c3(Scalar theta) {
  using std::cos;
  using std::sin;
  const Scalar theta2 = theta * theta;
  return (3 * sin(theta) - 2 * theta - theta * cos(theta)) / (theta2 * theta2 * theta);
}

/// c6(θ) = a3(θ)/(4 sin²(θ/2)) − 2 a4(θ)/θ² (not in 003; conventions eq. C3). From a4 = (1 − g)/θ²
/// with g = (θ/2)cot(θ/2) and g′ = (sin θ − θ)/(4 sin²(θ/2)); written so that both terms are
/// accurate and only their difference cancels (a factor ~60 at the switch). It calls the closed
/// forms of a3 and a4, which are accurate for θ ≥ c6_switch > a3_switch, a4_switch.
template <class Scalar>
Scalar c6(Scalar theta) {
  using std::sin;
  const Scalar s = sin(theta / 2);
  return a3(theta) / (4 * s * s) - 2 * a4(theta) / (theta * theta);
}

/// b1(θ) = ((3 − θ²) sin θ − 3θ cos θ)/θ⁵ (003 eq. 27).
template <class Scalar>
Scalar b1(Scalar theta) {
  using std::cos;
  using std::sin;
  const Scalar theta2 = theta * theta;
  return ((3 - theta2) * sin(theta) - 3 * theta * cos(theta)) / (theta2 * theta2 * theta);
}

/// b2(θ) = ((θ² − 8) cos θ − 5θ sin θ + 8)/θ⁶ (003 eq. 27).
template <class Scalar>
Scalar b2(Scalar theta) {
  using std::cos;
  using std::sin;
  const Scalar theta2 = theta * theta;
  return ((theta2 - 8) * cos(theta) - 5 * theta * sin(theta) + 8) / (theta2 * theta2 * theta2);
}

/// b3(θ) = ((θ² − 15) sin θ + 7θ cos θ + 8θ)/θ⁷ (003 eq. 27).
template <class Scalar>
Scalar b3(Scalar theta) {
  using std::cos;
  using std::sin;
  const Scalar theta2 = theta * theta;
  return ((theta2 - 15) * sin(theta) + 7 * theta * cos(theta) + 8 * theta) /
         (theta2 * theta2 * theta2 * theta);
}

}  // namespace closed_form

// The coefficients: the series below the function's switch point, the closed form above.
// The meaning of each is in its closed_form:: counterpart and in docs/conventions.md eq. C3.
#define SPAR_LIE_SWITCHED_COEFFICIENT(name, switch_point)                                    \
  template <class Scalar>                                                                    \
  Scalar name(Scalar theta) {                                                                \
    return theta < Scalar(switch_point) ? series::name(theta) : closed_form::name(theta);   \
  }
SPAR_LIE_SWITCHED_COEFFICIENT(a1, a1_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(a2, a2_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(a3, a3_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(a4, a4_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(c1, c_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(c2, c_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(c3, c_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(c6, c6_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(b1, b_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(b2, b_switch)
SPAR_LIE_SWITCHED_COEFFICIENT(b3, b_switch)
#undef SPAR_LIE_SWITCHED_COEFFICIENT

}  // namespace spar::lie::coefficients
