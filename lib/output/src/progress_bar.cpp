#include <spar/output/progress_bar.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spar::output {

namespace {

constexpr int bar_width = 20;
constexpr auto redraw_interval = std::chrono::milliseconds(100);

/// `seconds` as h:mm:ss, or m:ss below an hour.
std::string format_duration(double seconds) {
  const long total = std::lround(std::max(seconds, 0.0));
  char text[32];
  if (total >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  return text;
}

}  // namespace

std::string format_progress(const ProgressSnapshot& s) {
  const double span = s.t_end - s.t_start;
  const double fraction = span > 0 ? std::clamp((s.t - s.t_start) / span, 0.0, 1.0) : 1.0;
  const int filled = static_cast<int>(fraction * bar_width);
  std::string tail;
  if (fraction >= 1.0)
    tail = "done in " + format_duration(s.elapsed_s);
  else if (fraction > 0)
    tail = "ETA " + format_duration(s.elapsed_s * (1 - fraction) / fraction);
  else
    tail = "ETA --:--";
  char text[160];
  std::snprintf(text, sizeof text, " [%s%s] %5.1f %%  t = %.4g / %.4g s  steps %ld  ", std::string(filled, '#').c_str(),
                std::string(bar_width - filled, '-').c_str(), 100 * fraction, s.t, s.t_end, s.steps);
  return s.label + text + tail;
}

ProgressBar::ProgressBar(double t_end, std::string label, double t_start)
    : active_(isatty(STDERR_FILENO) == 1),
      snapshot_{std::move(label), t_start, t_start, t_end, 0, 0},
      start_(Clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(double t, long steps) {
  if (!active_) return;
  snapshot_.t = t;
  snapshot_.steps = steps;
  const Clock::time_point now = Clock::now();
  if (drawn_ && now - last_draw_ < redraw_interval) return;
  last_draw_ = now;
  draw();
}

void ProgressBar::finish() {
  if (!active_) return;
  draw();
  std::fputc('\n', stderr);
  active_ = false;
}

void ProgressBar::draw() {
  snapshot_.elapsed_s = std::chrono::duration<double>(Clock::now() - start_).count();
  // \r returns to the line start, ESC[K clears what a longer previous line left behind.
  std::fprintf(stderr, "\r%s\x1b[K", format_progress(snapshot_).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace spar::output
