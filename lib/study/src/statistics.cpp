#include <spar/study/statistics.hpp>

#include <algorithm>
#include <cmath>

namespace spar::study {

std::optional<Spread> spread(const std::vector<double>& values) {
  if (values.size() < 2) return std::nullopt;
  Spread s;
  for (const double x : values) s.mean += x;
  s.mean /= static_cast<double>(values.size());
  double sum = 0.0;
  for (const double x : values) {
    sum += (x - s.mean) * (x - s.mean);
    s.peak = std::max(s.peak, std::abs(x - s.mean));
  }
  s.rms = std::sqrt(sum / static_cast<double>(values.size()));
  return s;
}

}  // namespace spar::study
