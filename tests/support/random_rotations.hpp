#pragma once
// Seeded random rotation vectors for property tests: uniform axes, angles drawn from a mix of
// uniform [0, π] and clusters within 1e-10 of 0 and of π, where exp/log lose digits if careless.
#include <Eigen/Core>

#include <cmath>
#include <numbers>
#include <random>

namespace spar::test {

class RandomRotations {
public:
  explicit RandomRotations(unsigned seed) : engine_(seed) {}

  Eigen::Vector3d axis() {
    Eigen::Vector3d v;
    do {
      v = Eigen::Vector3d(normal_(engine_), normal_(engine_), normal_(engine_));
    } while (v.norm() < 1e-3);
    return v.normalized();
  }

  /// A rotation vector of angle in [0, π]; one in four near 0, one in four near π.
  Eigen::Vector3d rotation_vector() {
    const double u = uniform_(engine_);
    const int kind = static_cast<int>(engine_() % 4);
    double angle = std::numbers::pi * u;
    if (kind == 0) angle = 1e-10 * u;
    if (kind == 1) angle = std::numbers::pi - 1e-10 * u;
    return angle * axis();
  }

  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform_(engine_); }

private:
  std::mt19937_64 engine_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
};

}  // namespace spar::test
