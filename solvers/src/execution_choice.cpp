#include "execution_choice.hpp"

#include <algorithm>

namespace spar::solvers::detail {

namespace {

/// The median of a round's times (the upper one of the middle two).
ExecutionChoice::Duration median(std::array<ExecutionChoice::Duration, ExecutionChoice::samples> times) {
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

}  // namespace

bool ExecutionChoice::parallel() const noexcept {
  if (position_ < 2 * run) return position_ >= run;
  return chosen_parallel_;
}

void ExecutionChoice::record(Duration elapsed) {
  if (position_ < 2 * run && position_ % run != 0) {
    auto& times = (position_ >= run) ? parallel_ : serial_;
    times[static_cast<std::size_t>(position_ % run - 1)] = elapsed;
  }
  ++position_;
  if (position_ == 2 * run) choose();
  if (position_ == 2 * run + kept_for_) {
    position_ = 0;
    kept_for_ = std::min(2 * kept_for_, longest_kept_for);
  }
}

void ExecutionChoice::choose() { chosen_parallel_ = median(parallel_) < median(serial_); }

}  // namespace spar::solvers::detail
