// The rest-to-rest motion laws of the drivers (<spar/joints/motion_law.hpp>; paper 003's deployment
// laws, §5.3 eqs. (54)-(57)): the change reached at t_f and held after, the derivatives against
// central differences, rest at both ends for the smooth laws, and an unknown name refused.
#include <spar/joints/motion_law.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

using namespace spar;

namespace {
constexpr double pi = std::numbers::pi;
}  // namespace

TEST_CASE("motion laws (003 eqs. 54-57): from beta0 to beta_f in t_f, derivatives by finite differences",
          "[joints]") {
  const double beta0 = 5 * pi / 180, beta_f = pi / 2, t_f = 20.0;
  for (const char* name : joints::motion_laws) {
    INFO(name);
    const joints::TimeFunction f = joints::motion_law(name, beta_f - beta0, t_f);
    CHECK(std::abs(f.value(0.0)) <= 1e-15);
    CHECK(std::abs(f.value(t_f) - (beta_f - beta0)) <= 1e-15);
    CHECK(std::abs(f.value(25.0) - (beta_f - beta0)) <= 1e-15);  // held after t_f
    CHECK(f.first_derivative(25.0) == 0.0);
    // Central differences, step 1e-4 s: truncation (1e-8 · f‴) and round-off (1e-16/1e-4) below 1e-9.
    for (const double t : {0.7, 5.0, 10.0, 13.3, 19.2}) {
      const double dt = 1e-4;
      CHECK(std::abs((f.value(t + dt) - f.value(t - dt)) / (2 * dt) - f.first_derivative(t)) <= 1e-9);
      CHECK(std::abs((f.first_derivative(t + dt) - f.first_derivative(t - dt)) / (2 * dt) - f.second_derivative(t)) <= 1e-9);
    }
    // The smooth laws start and end at rest; the linear one runs at (β_f − β₀)/t_f throughout.
    const double rate0 = f.first_derivative(0.0), rate_f = f.first_derivative(t_f - 1e-12);
    if (std::string(name) == "linear") {
      CHECK(std::abs(rate0 - (beta_f - beta0) / t_f) <= 1e-15);
    } else {
      CHECK(std::abs(rate0) <= 1e-9);
      CHECK(std::abs(rate_f) <= 1e-9);
    }
  }
  CHECK_THROWS_WITH(joints::motion_law("sine", beta_f - beta0, t_f), Catch::Contains("linear, polynomial, cycloid or cosine"));
}
