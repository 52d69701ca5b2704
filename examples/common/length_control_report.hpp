#pragma once
// The length control of the ALE-RANCF examples (000 §5, Table 2): the check after each step, the
// event log written to the results file and the statistics of the merged elements' weights.
#include <spar/spar.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <vector>

namespace spar::examples {

/// One length-control check after a step. On an event the centreline just before (phase 0) and
/// after (phase 1) goes to `shapes` (rows: event, phase, x, y), the integrator is remapped and
/// restarted from consistent accelerations (docs/rancf.md), and the event is logged and printed.
/// Returns the total energy after the event, or nothing when no event happened.
inline std::optional<double> control_length(core::SlidingCable<2>& cable, core::Model& model,
                                            solvers::GeneralizedAlpha& integrator, int per_element,
                                            std::ostream& shapes,
                                            std::vector<core::LengthControlEvent>& events) {
  Eigen::MatrixXd P;
  const Eigen::MatrixXd before = cable.sample_centerline(model.state(), per_element);
  const std::optional<core::LengthControlEvent> event = cable.control_length(model, integrator.time(), P);
  if (!event) return std::nullopt;
  const auto write_shape = [&](int phase, const Eigen::MatrixXd& points) {
    for (Eigen::Index i = 0; i < points.rows(); ++i)
      shapes << events.size() << ',' << phase << ',' << points(i, 0) << ',' << points(i, 1) << '\n';
  };
  write_shape(0, before);
  write_shape(1, cable.sample_centerline(model.state(), per_element));
  integrator.remap(P);
  integrator.initialize();
  events.push_back(*event);
  std::printf("t = %.4f s: %s; merged weights (%.4f, %.4f, %.4f)%s\n", event->time, event->description.c_str(),
              event->merged_weights(0), event->merged_weights(1), event->merged_weights(2),
              event->merge_fallback ? " (fallback k = 1)" : event->merge_bounded ? " (bounded)" : "");
  return integrator.energies().total();
}

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
/// far/near/merged weights, fallback (000 eq. (38)), bounded (max_merge_weight), miss (29 columns).
inline void write_length_control_log(core::ResultsWriter& results,
                                     const std::vector<core::LengthControlEvent>& events) {
  if (events.empty()) return;
  Eigen::MatrixXd log(static_cast<Eigen::Index>(events.size()), 29);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const core::LengthControlEvent& e = events[i];
    log.row(static_cast<Eigen::Index>(i)) << e.time, e.grown_element, e.grown_weights.transpose(),
        e.merged_near_weights.transpose(), e.merged_far_weights.transpose(), e.split_weights_far.transpose(),
        e.split_weights_near.transpose(), e.merged_weights.transpose(), e.merge_fallback ? 1.0 : 0.0,
        e.merge_bounded ? 1.0 : 0.0, e.merge_miss;
  }
  results.write_constant("length_control_events", log, "s, 1",
                         "one row per length-control event: time (s), the grown element, then the weights "
                         "before and after (docs/rancf.md, the columns in the example's README)");
}

}  // namespace spar::examples
