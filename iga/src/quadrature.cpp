#include <spar/error.hpp>
#include <spar/iga/quadrature.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace spar::iga {

namespace {

struct Legendre {
  long double value;
  long double derivative;
};

/// P_n(x) by the three-term recurrence (k+1) P_{k+1} = (2k+1) x P_k − k P_{k−1}, and
/// P_n′(x) = n (x P_n − P_{n−1}) / (x² − 1).
Legendre legendre(int n, long double x) {
  long double previous = 1.0L, current = x;
  for (int k = 1; k < n; ++k) {
    const long double next = ((2 * k + 1) * x * current - k * previous) / (k + 1);
    previous = current;
    current = next;
  }
  return {current, n * (x * current - previous) / (x * x - 1.0L)};
}

}  // namespace

GaussRule gauss_legendre(int n) {
  if (n < 1 || n > max_gauss_points)
    throw Error("a Gauss–Legendre rule has 1 to " + std::to_string(max_gauss_points) + " points, asked for " +
                    std::to_string(n),
                "iga::gauss_legendre", "ask for 1 ≤ n ≤ " + std::to_string(max_gauss_points) + " points");
  GaussRule rule{std::vector<double>(n), std::vector<double>(n)};
  // Roots come in ± pairs; compute the non-negative ones and mirror them.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    long double x = std::cos(std::numbers::pi_v<long double> * (i + 0.75L) / (n + 0.5L));
    Legendre p = legendre(n, x);
    for (int iteration = 0; iteration < 100; ++iteration) {
      const long double step = p.value / p.derivative;
      x -= step;
      p = legendre(n, x);
      if (std::fabs(step) <= 1e-18L) break;
    }
    const bool middle = (n % 2 == 1) && (i == n / 2);
    if (middle) x = 0.0L;
    const long double weight = 2.0L / ((1.0L - x * x) * p.derivative * p.derivative);
    rule.points[n - 1 - i] = static_cast<double>(x);
    rule.points[i] = static_cast<double>(-x);
    rule.weights[i] = rule.weights[n - 1 - i] = static_cast<double>(weight);
  }
  return rule;
}

}  // namespace spar::iga
