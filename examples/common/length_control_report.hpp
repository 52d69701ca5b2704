#pragma once
// What the ALE-RANCF examples report of their length control (000 §5, Table 2): the event log
// written to the results file and the statistics of the merged elements' weights.
#include <spar/spar.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace spar::examples {

/// 000 Table 2: the set of merged-element weights k_i, its extremes and σ of eq. (42).
struct WeightStatistics {
  std::size_t count = 0;
  double max = 1.0, min = 1.0, sigma = 0.0;
};

inline WeightStatistics weight_statistics(const std::vector<core::LengthControlEvent>& events) {
  std::vector<double> weights;
  for (const core::LengthControlEvent& e : events)
    for (int j = 0; j < 3; ++j) weights.push_back(e.merged_weights(j));
  WeightStatistics statistics;
  statistics.count = weights.size();
  if (weights.empty()) return statistics;
  statistics.max = *std::max_element(weights.begin(), weights.end());
  statistics.min = *std::min_element(weights.begin(), weights.end());
  double sum = 0.0;
  for (double k : weights) sum += (k - 1) * (k - 1);
  statistics.sigma = std::sqrt(sum / static_cast<double>(weights.size()));  // 000 eq. (42)
  return statistics;
}

/// Writes the event log to the results file: one row per event — time, split element, its weights
/// before, the two merged elements' weights before (next to the slider, beyond), the new
/// far/near/merged weights, fallback, miss (28 columns).
inline void write_length_control_log(core::ResultsWriter& results,
                                     const std::vector<core::LengthControlEvent>& events) {
  if (events.empty()) return;
  Eigen::MatrixXd log(static_cast<Eigen::Index>(events.size()), 28);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const core::LengthControlEvent& e = events[i];
    log.row(static_cast<Eigen::Index>(i)) << e.time, e.grown_element, e.grown_weights.transpose(),
        e.merged_near_weights.transpose(), e.merged_far_weights.transpose(), e.split_weights_far.transpose(),
        e.split_weights_near.transpose(), e.merged_weights.transpose(), e.merge_fallback ? 1.0 : 0.0, e.merge_miss;
  }
  results.write_constant("length_control_events", log, "s, 1",
                         "one row per length-control event: time (s), the grown element, then the weights "
                         "before and after (docs/rancf.md, the columns in the example's README)");
}

}  // namespace spar::examples
