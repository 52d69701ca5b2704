#pragma once
/// \file
/// Rest-to-rest motion laws for the drivers (docs/joints.md §3): a coordinate moved by a given
/// change over [0, t_f] and held after, as a TimeFunction with its first two derivatives (the
/// drivers' Φ_t and acceleration terms need them). The four laws are paper 003's deployment laws,
/// §5.3 eqs. (54)–(57), where they turn the truss's bays from β₀ to β_f.

#include <spar/joints/time_function.hpp>

#include <array>
#include <string>

namespace spar::joints {

/// The laws' names, in 003's order.
inline constexpr std::array<const char*, 4> motion_laws = {"linear", "polynomial", "cycloid", "cosine"};

/// The shape g(τ) of a law on τ = t/t_f ∈ [0, 1], g(0) = 0, g(1) = 1, and its derivatives.
struct MotionLawShape {
  double g, dg, ddg;
};

/// g(τ) of law `name` (003 eqs. 54–57; β = β₀ + (β_f − β₀) g(t/t_f)):
///   linear      τ                                    (eq. 54, with the "+ β₀" the print lacks)
///   polynomial  6τ⁵ − 15τ⁴ + 10τ³                    (eq. 55)
///   cycloid     τ − sin(2πτ)/(2π)                    (eq. 56)
///   cosine      1/2 − (9/16) cos(πτ) + (1/16) cos(3πτ) (eq. 57)
/// Throws spar::Error for another name.
MotionLawShape motion_law_shape(const std::string& name, double tau);

/// change · g(t/t_f) for law `name` as a time function: the law on [0, t_f], `change` after t_f
/// (the motion holds; the linear law's rate drops to zero there, as 003's Figures 10–11 show) and
/// 0 before 0. The rates are the right derivatives at the ends: the linear law starts at
/// change/t_f at t = 0 (so that an initial assembly starts the driven body moving with it) and
/// stops at t_f. Throws spar::Error for an unknown name, here rather than at the first step.
TimeFunction motion_law(const std::string& name, double change, double t_f);

}  // namespace spar::joints
