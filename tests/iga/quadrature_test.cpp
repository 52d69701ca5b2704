// Gauss–Legendre rules: exactness on monomials of degree ≤ 2n−1, symmetry and known values.
#include <spar/error.hpp>
#include <spar/iga/quadrature.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using spar::iga::gauss_legendre;

TEST_CASE("Gauss–Legendre rules integrate polynomials of degree 2n−1 exactly", "[iga]") {
  for (int n = 1; n <= 40; ++n) {
    const auto rule = gauss_legendre(n);
    REQUIRE(rule.points.size() == static_cast<std::size_t>(n));
    double worst = 0.0;
    for (int k = 0; k <= 2 * n - 1; ++k) {
      // The sum runs in long double so that the check measures the rule (its points and weights
      // rounded to double), not the summation.
      long double sum = 0.0L;
      for (int q = 0; q < n; ++q)
        sum += static_cast<long double>(rule.weights[q]) *
               std::pow(static_cast<long double>(rule.points[q]), k);
      const long double exact = k % 2 == 0 ? 2.0L / (k + 1) : 0.0L;
      worst = std::max(worst, static_cast<double>(std::fabs(sum - exact)));
    }
    INFO("n = " << n);
    CHECK(worst <= 1e-15);
    for (int q = 0; q < n; ++q) {
      CHECK(rule.points[q] == -rule.points[n - 1 - q]);
      CHECK(rule.weights[q] > 0.0);
      if (q > 0) CHECK(rule.points[q] > rule.points[q - 1]);
    }
  }
}

TEST_CASE("Gauss–Legendre rules agree with the closed forms for n ≤ 3", "[iga][validation]") {
  CHECK(gauss_legendre(1).points[0] == 0.0);
  CHECK(gauss_legendre(1).weights[0] == 2.0);
  CHECK(gauss_legendre(2).points[1] == Approx(1.0 / std::sqrt(3.0)).epsilon(1e-15));
  CHECK(gauss_legendre(3).points[2] == Approx(std::sqrt(0.6)).epsilon(1e-15));
  CHECK(gauss_legendre(3).weights[1] == Approx(8.0 / 9.0).epsilon(1e-15));
  CHECK_THROWS_WITH(gauss_legendre(0), Catch::Contains("1 to 64 points"));
}
