#include <spar/error.hpp>
#include <spar/joints/motion_law.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace spar::joints {

MotionLawShape motion_law_shape(const std::string& name, double tau) {
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
  throw Error("unknown motion law '" + name + "'", "joints::motion_law_shape",
              "use linear, polynomial, cycloid or cosine (003 eqs. 54-57)");
}

TimeFunction motion_law(const std::string& name, double change, double t_f) {
  (void)motion_law_shape(name, 0.0);  // an unknown name fails here, not at the first step
  const auto tau = [t_f](double t) { return std::clamp(t / t_f, 0.0, 1.0); };
  const auto inside = [t_f](double t) { return t >= 0.0 && t < t_f; };
  return {.value = [=](double t) { return change * motion_law_shape(name, tau(t)).g; },
          .first_derivative = [=](double t) { return inside(t) ? change * motion_law_shape(name, tau(t)).dg / t_f : 0.0; },
          .second_derivative =
              [=](double t) { return inside(t) ? change * motion_law_shape(name, tau(t)).ddg / (t_f * t_f) : 0.0; }};
}

}  // namespace spar::joints
