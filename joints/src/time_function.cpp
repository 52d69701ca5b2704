#include <spar/error.hpp>
#include <spar/joints/time_function.hpp>

#include <cstddef>
#include <memory>
#include <utility>

namespace spar::joints {

TimeFunction TimeFunction::constant(double c) {
  return {.value = [c](double) { return c; },
          .first_derivative = [](double) { return 0.0; },
          .second_derivative = [](double) { return 0.0; }};
}

TimeFunction TimeFunction::linear(double rate, double offset) {
  return {.value = [rate, offset](double t) { return offset + rate * t; },
          .first_derivative = [rate](double) { return rate; },
          .second_derivative = [](double) { return 0.0; }};
}

TimeFunction TimeFunction::polynomial(std::vector<double> coefficients) {
  // The three callables share one coefficient list; evaluation reads it and allocates nothing.
  const auto shared = std::make_shared<const std::vector<double>>(std::move(coefficients));
  // d-th derivative of Σ c_k tᵏ by Horner's rule on the coefficients c_k k!/(k−d)!.
  const auto derivative = [shared](int d, double t) {
    const std::vector<double>& c = *shared;
    double sum = 0.0;
    for (std::size_t k = c.size(); k-- > static_cast<std::size_t>(d);) {
      double factor = 1.0;
      for (int j = 0; j < d; ++j) factor *= static_cast<double>(k - static_cast<std::size_t>(j));
      sum = sum * t + factor * c[k];
    }
    return sum;
  };
  return {.value = [derivative](double t) { return derivative(0, t); },
          .first_derivative = [derivative](double t) { return derivative(1, t); },
          .second_derivative = [derivative](double t) { return derivative(2, t); }};
}

void check_time_function(const TimeFunction& f, std::string_view where) {
  if (!f.value || !f.first_derivative || !f.second_derivative)
    throw Error("the time function lacks its value, first or second derivative", where,
                "set all three callables, or build it with TimeFunction::constant, linear or "
                "polynomial");
}

}  // namespace spar::joints
