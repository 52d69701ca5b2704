#pragma once
/// \file
/// A one-line progress bar for time integration on stderr: steps, simulated time, percent and
/// estimated time to completion. It draws only when stderr is a terminal, so logs and test
/// output stay clean.

#include <chrono>
#include <string>

namespace spar::output {

/// What one progress line shows.
struct ProgressSnapshot {
  std::string label;
  double t = 0;               ///< simulated time reached, s
  double t_start = 0;         ///< simulated time at the start, s
  double t_end = 0;           ///< simulated time at the end, s
  long steps = 0;             ///< steps taken
  double elapsed_s = 0;       ///< wall time since the start, s
};

/// The progress line, e.g.
/// `slider-crank [#########-----------]  45.0 %  t = 0.09 / 0.2 s  steps 900  ETA 0:12`.
/// The ETA extrapolates the wall time per simulated second so far; it reads `--:--` until time
/// has advanced, and the line ends `done in m:ss` once t reaches t_end.
std::string format_progress(const ProgressSnapshot& snapshot);

/// Draws format_progress() on stderr, in place (carriage return), at most about 10 times a
/// second; a no-op when stderr is not a terminal (isatty).
class ProgressBar {
public:
  ProgressBar(double t_end, std::string label, double t_start = 0);
  /// Ends the line (finish()) if it was drawn.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Records the state; redraws if 0.1 s have passed since the last draw.
  void update(double t, long steps);
  /// Draws the last state and ends the line; later calls do nothing.
  void finish();
  /// Whether this bar draws at all (stderr is a terminal).
  bool active() const { return active_; }

private:
  using Clock = std::chrono::steady_clock;
  void draw();

  bool active_;
  ProgressSnapshot snapshot_;
  Clock::time_point start_;
  Clock::time_point last_draw_;
  bool drawn_ = false;
};

}  // namespace spar::output
