#include <spar/study/schedule.hpp>

#include <spar/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace spar::study {

namespace {

void require_interval(double interval, const char* function) {
  if (!(std::isfinite(interval) && interval > 0.0))
    throw Error("the interval " + significant(interval) + " s is not a positive finite time",
                std::string("study::Schedule::") + function, "give a positive output interval");
}

}  // namespace

Schedule Schedule::every_steps(long n) {
  if (n < 1)
    throw Error("every " + std::to_string(n) + " steps: no step would be recorded", "study::Schedule::every_steps",
                "give n >= 1");
  Schedule s;
  s.every_ = n;
  return s;
}

Schedule Schedule::every_interval(double interval) {
  require_interval(interval, "every_interval");
  Schedule s;
  s.interval_ = interval;
  return s;
}

Schedule Schedule::at_times(std::vector<double> times) { return Schedule().and_at(std::move(times)); }

Schedule Schedule::sampled_every(double interval) {
  require_interval(interval, "sampled_every");
  Schedule s;
  s.interval_ = interval;
  s.sampled_ = true;
  return s;
}

Schedule Schedule::and_at(std::vector<double> times) const {
  Schedule s = *this;
  s.times_.insert(s.times_.end(), times.begin(), times.end());
  return s;
}

Schedule Schedule::and_last() const {
  Schedule s = *this;
  s.last_ = true;
  return s;
}

bool Schedule::due(long n, double t, double h, bool last) {
  const bool at_time = std::any_of(times_.begin(), times_.end(), [&](double time) { return std::abs(t - time) < 0.5 * h; });
  const bool due = (last_ && last) || at_time || (every_ > 0 && n % every_ == 0) ||
                   (interval_ > 0.0 && t >= next_ - 0.5 * h);
  if (due && interval_ > 0.0)
    while (next_ <= t + 0.5 * h) next_ += interval_;  // the next multiple not yet recorded
  return due;
}

}  // namespace spar::study
