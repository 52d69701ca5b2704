#include <spar/elements/cable/length_control_log.hpp>

#include <algorithm>
#include <cmath>

namespace spar::core {

WeightStatistics weight_statistics(const std::vector<LengthControlEvent>& events) {
  std::vector<double> weights;
  for (const LengthControlEvent& e : events)
    weights.insert(weights.end(), e.merged_weights.data(), e.merged_weights.data() + 3);  // k0, k1, k2
  if (weights.empty()) return {};
  double sum = 0.0;
  for (double k : weights) sum += (k - 1) * (k - 1);
  return {.count = weights.size(), .max = std::ranges::max(weights), .min = std::ranges::min(weights),
          .sigma = std::sqrt(sum / static_cast<double>(weights.size()))};  // 000 eq. (42)
}

Eigen::MatrixXd length_control_log(const std::vector<LengthControlEvent>& events) {
  Eigen::MatrixXd log(static_cast<Eigen::Index>(events.size()), 29);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const LengthControlEvent& e = events[i];
    log.row(static_cast<Eigen::Index>(i)) << e.time, e.grown_element, e.grown_weights.transpose(),
        e.merged_near_weights.transpose(), e.merged_far_weights.transpose(), e.split_weights_far.transpose(),
        e.split_weights_near.transpose(), e.merged_weights.transpose(), e.merge_fallback ? 1.0 : 0.0,
        e.merge_bounded ? 1.0 : 0.0, e.merge_miss;
  }
  return log;
}

}  // namespace spar::core
