#pragma once
/// \file
/// Which states of a run an output gets (docs/output.md, "Studies"): every step, every n-th step,
/// the first step at or past each multiple of an interval, the steps at given times, the last
/// step — or states interpolated between the steps at each multiple of an interval
/// (solvers::TimeSampler, docs/dynamics.md D10).

#include <vector>

namespace spar::study {

class Schedule {
public:
  /// The start and every step.
  static Schedule every_step() { return every_steps(1); }
  /// The start and every n-th step (n ≥ 1; steps counted as step() calls, a step cut back counts once).
  static Schedule every_steps(long n);
  /// The first step at or past each multiple k·Δt of `interval` (within half a step), the start included.
  static Schedule every_interval(double interval);
  /// The steps within half a step of `times`.
  static Schedule at_times(std::vector<double> times);
  /// States interpolated at each multiple k·Δt of `interval` (solvers::TimeSampler::every), not steps.
  static Schedule sampled_every(double interval);

  /// This schedule and the steps within half a step of `times`.
  Schedule and_at(std::vector<double> times) const;
  /// This schedule and the run's last step (the end time or a stop).
  Schedule and_last() const;

  bool sampled() const { return sampled_; }
  double interval() const { return interval_; }
  /// Whether the n-th step (0: the start) at time t, of a run of step h, is due; advances the
  /// interval's next time past t when it is. `last`: the run ends with this step.
  bool due(long n, double t, double h, bool last);

private:
  long every_ = 0;           ///< every n-th step, 0: none
  double interval_ = 0.0;    ///< the interval, 0: none
  double next_ = 0.0;        ///< the next multiple of the interval not yet recorded
  std::vector<double> times_;
  bool last_ = false;
  bool sampled_ = false;
};

}  // namespace spar::study
