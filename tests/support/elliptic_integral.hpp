#pragma once
// The complete elliptic integral of the first kind, for the exact period of a pendulum released at
// a finite angle (the bead-on-a-wire and bead-on-a-rail tests).
#include <cmath>
#include <numbers>

namespace spar::test {

/// The arithmetic–geometric mean of a and b (quadratic convergence: 6 iterations reach round-off
/// for b/a ≥ 0.1).
inline double arithmetic_geometric_mean(double a, double b) {
  for (int i = 0; i < 20 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return 0.5 * (a + b);
}

/// The complete elliptic integral of the first kind K(k) = π / (2 AGM(1, √(1 − k²))).
inline double complete_elliptic_k(double k) {
  return std::numbers::pi / (2 * arithmetic_geometric_mean(1.0, std::sqrt(1 - k * k)));
}

}  // namespace spar::test
