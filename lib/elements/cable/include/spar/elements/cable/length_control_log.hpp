#pragma once
/// \file
/// What a run's length-control events (SlidingCable::control_length) add up to: paper 000
/// Table 2's statistics of the merged elements' weights, eq. (42), and the event log as a table
/// for a results file (docs/rancf.md, "Sliding node and length control").

#include <spar/elements/cable/sliding_cable.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace spar::core {

/// 000 Table 2: the set of the merged elements' weights k_i (k0, k1, k2 of every event), its
/// extremes and its deviation from 1, σ = √(Σ (k_i − 1)² / n) (000 eq. (42)). With no event:
/// an empty set, max = min = 1 and σ = 0.
struct WeightStatistics {
  std::size_t count = 0;
  double max = 1.0, min = 1.0, sigma = 0.0;
};

WeightStatistics weight_statistics(const std::vector<LengthControlEvent>& events);

/// The event log, one row per event and 29 columns: the time (s); the split element; its weights
/// before (4); the two merged elements' weights before, next to the slider (4) and beyond (4); the
/// new far, near and merged weights (4 each); fallback to k = 1 (000 eq. (38), 1 or 0); bounded by
/// max_merge_weight (1 or 0); the merged element's miss |r̄(ū_H) − r_H| (m).
Eigen::MatrixXd length_control_log(const std::vector<LengthControlEvent>& events);

}  // namespace spar::core
