#pragma once
/// \file
/// Statistics of a recorded series for a study's summary, e.g. the residual vibration of a point
/// after a deployment: its deviation from its mean, RMS and peak.

#include <optional>
#include <vector>

namespace spar::study {

struct Spread {
  double mean = 0.0;
  double rms = 0.0;   ///< √(Σ (x − mean)² / n)
  double peak = 0.0;  ///< max |x − mean|
};

/// The spread of `values` about their mean; none for fewer than two values.
std::optional<Spread> spread(const std::vector<double>& values);

}  // namespace spar::study
