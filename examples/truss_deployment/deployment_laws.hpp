#pragma once
// The deployment laws of 003 §5.3, eqs. (54)–(57): β(t) from β₀ to β_f in t_f, as time functions
// with their first two derivatives (the drivers' Φ_t and acceleration terms need them).
#include <spar/error.hpp>
#include <spar/joints/time_function.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace spar::examples {

/// The shape g(τ) of a law on τ = t/t_f ∈ [0, 1], g(0) = 0, g(1) = 1, and its derivatives.
struct LawShape {
  double g, dg, ddg;
};

/// g(τ) of law `name` (003 eqs. 54–57; β = β₀ + (β_f − β₀) g(t/t_f)):
///   linear      τ                                    (eq. 54, with the "+ β₀" the print lacks)
///   polynomial  6τ⁵ − 15τ⁴ + 10τ³                    (eq. 55)
///   cycloid     τ − sin(2πτ)/(2π)                    (eq. 56)
///   cosine      1/2 − (9/16) cos(πτ) + (1/16) cos(3πτ) (eq. 57)
inline LawShape law_shape(const std::string& name, double tau) {
  constexpr double pi = std::numbers::pi;
  if (name == "linear") return {tau, 1.0, 0.0};
  if (name == "polynomial")
    return {tau * tau * tau * (10.0 + tau * (-15.0 + 6.0 * tau)),
            30.0 * tau * tau * (1.0 + tau * (-2.0 + tau)), 60.0 * tau * (1.0 + tau * (-3.0 + 2.0 * tau))};
  if (name == "cycloid")
    return {tau - std::sin(2.0 * pi * tau) / (2.0 * pi), 1.0 - std::cos(2.0 * pi * tau),
            2.0 * pi * std::sin(2.0 * pi * tau)};
  if (name == "cosine")
    return {0.5 - 9.0 / 16.0 * std::cos(pi * tau) + 1.0 / 16.0 * std::cos(3.0 * pi * tau),
            9.0 * pi / 16.0 * std::sin(pi * tau) - 3.0 * pi / 16.0 * std::sin(3.0 * pi * tau),
            9.0 * pi * pi / 16.0 * (std::cos(pi * tau) - std::cos(3.0 * pi * tau))};
  throw Error("unknown deployment law '" + name + "'", "examples::law_shape",
              "use linear, polynomial, cycloid or cosine (003 eqs. 54-57)");
}

inline constexpr std::array<const char*, 4> deployment_laws = {"linear", "polynomial", "cycloid", "cosine"};

/// β(t) − β₀ for law `name` as a time function: the law on [0, t_f], β_f − β₀ after t_f (the
/// deployment holds; the linear law's rate drops to zero there, as 003's Figures 10–11 show) and 0
/// before 0.
inline joints::TimeFunction deployment_angle(const std::string& name, double beta0, double beta_f, double t_f) {
  (void)law_shape(name, 0.0);  // an unknown name fails here, not at the first step
  const double range = beta_f - beta0;
  const auto tau = [t_f](double t) { return std::clamp(t / t_f, 0.0, 1.0); };
  // The rates are the right derivatives at the ends: the linear law starts at (β_f − β₀)/t_f at
  // t = 0 (so that the initial assembly starts the unit moving with it) and stops at t_f.
  const auto inside = [t_f](double t) { return t >= 0.0 && t < t_f; };
  return {.value = [=](double t) { return range * law_shape(name, tau(t)).g; },
          .first_derivative = [=](double t) { return inside(t) ? range * law_shape(name, tau(t)).dg / t_f : 0.0; },
          .second_derivative =
              [=](double t) { return inside(t) ? range * law_shape(name, tau(t)).ddg / (t_f * t_f) : 0.0; }};
}

}  // namespace spar::examples
