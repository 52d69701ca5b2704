#pragma once
/// \file
/// A scalar function of time with its first two derivatives, the input of the driving
/// constraints (docs/joints.md §3).

#include <functional>
#include <string_view>
#include <vector>

namespace spar::joints {

/// f(t), f′(t), f″(t). Any three callables may be given; the factories below build the common
/// ones. A driver checks at construction that all three are set.
struct TimeFunction {
  std::function<double(double)> value;
  std::function<double(double)> first_derivative;
  std::function<double(double)> second_derivative;

  /// f(t) = c.
  static TimeFunction constant(double c);
  /// f(t) = offset + rate·t.
  static TimeFunction linear(double rate, double offset = 0.0);
  /// f(t) = Σ_k coefficients[k] tᵏ (ascending powers; an empty list is f = 0), evaluated with
  /// Horner's rule together with its derivatives.
  static TimeFunction polynomial(std::vector<double> coefficients);
};

/// Raises spar::Error naming `where` when one of f, f′, f″ is empty.
void check_time_function(const TimeFunction& f, std::string_view where);

}  // namespace spar::joints
