// The coefficient functions a1…a4, c1…c3, c6, b1…b3 keep full double precision everywhere in
// [0, π], in particular through their small-angle switch points (issue: relative error ≤ 1e-13
// at θ = 0, 1e-12, 1e-8, 1e-6, 1e-4, 1e-2, 0.5, 2, 3, π − 1e-6).
//
// The oracle is the long double instantiation of the same templates: 11 more bits of precision,
// and a series whose truncation error is below 1e-24, so its own error (≤ 1e-16 relative) is
// three orders below the tolerance. Independent checks: the exact values at θ = 0, and the series
// against the closed form at every switch point in long double.
#include <spar/lie/coefficients.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace coefficients = spar::lie::coefficients;

namespace {

struct Coefficient {
  std::string name;
  std::function<double(double)> in_double;
  std::function<long double(long double)> in_long_double;
  std::function<long double(long double)> series;
  std::function<long double(long double)> closed_form;
  double switch_point;
  long double value_at_zero;
};

#define SPAR_COEFFICIENT(name, switch_point, at_zero)                                     \
  Coefficient {                                                                           \
    #name, [](double t) { return coefficients::name(t); },                                \
        [](long double t) { return coefficients::name(t); },                              \
        [](long double t) { return coefficients::series::name(t); },                      \
        [](long double t) { return coefficients::closed_form::name(t); }, switch_point,   \
        at_zero                                                                           \
  }

std::vector<Coefficient> all_coefficients() {
  // Values at θ = 0 from the Taylor series: a1 = 1, a2 = 1/2, a3 = 1/6, a4 = 1/12 and
  // c = 2 d/dx a, b = 4 d²/dx² a with a1 = 1 − x/6 + x²/120, a2 = 1/2 − x/24 + x²/720,
  // a3 = 1/6 − x/120 + x²/5040, a4 = 1/12 + x/720 + ….
  return {
      SPAR_COEFFICIENT(a1, coefficients::a1_switch, 1.0L),
      SPAR_COEFFICIENT(a2, coefficients::a2_switch, 1.0L / 2),
      SPAR_COEFFICIENT(a3, coefficients::a3_switch, 1.0L / 6),
      SPAR_COEFFICIENT(a4, coefficients::a4_switch, 1.0L / 12),
      SPAR_COEFFICIENT(c1, coefficients::c_switch, -1.0L / 3),
      SPAR_COEFFICIENT(c2, coefficients::c_switch, -1.0L / 12),
      SPAR_COEFFICIENT(c3, coefficients::c_switch, -1.0L / 60),
      SPAR_COEFFICIENT(c6, coefficients::c6_switch, 1.0L / 360),
      SPAR_COEFFICIENT(b1, coefficients::b_switch, 1.0L / 15),
      SPAR_COEFFICIENT(b2, coefficients::b_switch, 1.0L / 90),
      SPAR_COEFFICIENT(b3, coefficients::b_switch, 1.0L / 630),
  };
}
#undef SPAR_COEFFICIENT

double relative_error(double value, long double reference) {
  return static_cast<double>(std::fabs((static_cast<long double>(value) - reference) / reference));
}

}  // namespace

TEST_CASE("coefficients are exact to 1e-13 at the issue's angles", "[lie][coefficients]") {
  const double pi = std::numbers::pi;
  const std::vector<double> angles = {0.0, 1e-12, 1e-8, 1e-6, 1e-4, 1e-2, 0.5, 2.0, 3.0, pi - 1e-6};
  for (const auto& f : all_coefficients()) {
    for (double theta : angles) {
      INFO(f.name << " at theta = " << theta);
      CHECK(relative_error(f.in_double(theta), f.in_long_double(theta)) <= 1e-13);
    }
  }
}

TEST_CASE("coefficients are exact to 1e-13 on a dense sweep of [1e-12, pi]", "[lie][coefficients]") {
  // 2000 log-spaced angles: no gap between switch points escapes.
  for (const auto& f : all_coefficients()) {
    double worst = 0.0, worst_theta = 0.0;
    for (int i = 0; i <= 2000; ++i) {
      const double theta = 1e-12 * std::pow(std::numbers::pi / 1e-12, i / 2000.0);
      const double error = relative_error(f.in_double(theta), f.in_long_double(theta));
      if (error > worst) worst = error, worst_theta = theta;
    }
    INFO(f.name << ": worst relative error " << worst << " at theta = " << worst_theta);
    CHECK(worst <= 1e-13);
  }
}

TEST_CASE("coefficients are exact on both sides of their switch point", "[lie][coefficients]") {
  for (const auto& f : all_coefficients()) {
    for (double factor : {1.0 - 1e-12, 1.0, 1.0 + 1e-12, 0.999, 1.001}) {
      const double theta = f.switch_point * factor;
      INFO(f.name << " at theta = " << theta);
      CHECK(relative_error(f.in_double(theta), f.in_long_double(theta)) <= 1e-13);
    }
  }
}

TEST_CASE("series and closed form agree at every switch point in long double",
          "[lie][coefficients]") {
  // Independent of the oracle: the two branches are different formulas. In long double the closed
  // form's cancellation at the switch costs at most ~1e3 ulps (5e-17); a wrong series coefficient
  // or too short a series would show as a much larger gap.
  for (const auto& f : all_coefficients()) {
    const long double theta = f.switch_point;
    const long double series = f.series(theta);
    const long double closed = f.closed_form(theta);
    INFO(f.name << ": series " << static_cast<double>(series) << ", closed form "
                << static_cast<double>(closed));
    CHECK(static_cast<double>(std::fabs((series - closed) / closed)) <= 1e-16);
  }
}

TEST_CASE("coefficients take their exact values at zero", "[lie][coefficients]") {
  for (const auto& f : all_coefficients()) {
    INFO(f.name);
    CHECK(relative_error(f.in_double(0.0), f.value_at_zero) <= 1e-16);
  }
}

TEST_CASE("derivative coefficients are (1/theta) d/dtheta of their parents", "[lie][coefficients]") {
  // c = D a with D = (1/θ) d/dθ, checked by a central difference in long double at angles in the
  // closed-form region (step 1e-6: truncation ~1e-12 relative, round-off ~1e-13).
  const long double h = 1e-6L;
  auto D = [h](auto f, long double theta) { return (f(theta + h) - f(theta - h)) / (2 * h * theta); };
  for (long double theta : {0.3L, 1.2L, 2.5L, 3.0L}) {
    INFO("theta = " << static_cast<double>(theta));
    auto close = [](long double a, long double b) {
      return std::fabs((a - b) / b) < 1e-9L;
    };
    CHECK(close(D([](long double t) { return coefficients::a1(t); }, theta), coefficients::c1(theta)));
    CHECK(close(D([](long double t) { return coefficients::a2(t); }, theta), coefficients::c2(theta)));
    CHECK(close(D([](long double t) { return coefficients::a3(t); }, theta), coefficients::c3(theta)));
    CHECK(close(D([](long double t) { return coefficients::a4(t); }, theta), coefficients::c6(theta)));
    CHECK(close(D([](long double t) { return coefficients::c1(t); }, theta), coefficients::b1(theta)));
    CHECK(close(D([](long double t) { return coefficients::c2(t); }, theta), coefficients::b2(theta)));
    CHECK(close(D([](long double t) { return coefficients::c3(t); }, theta), coefficients::b3(theta)));
  }
}
