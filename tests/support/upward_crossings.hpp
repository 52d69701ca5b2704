#pragma once
// The upward zero crossings of a sampled coordinate x(t), located inside each step by the cubic
// Hermite interpolant of (x, ẋ) at its ends (O(h⁴)), and the mean period between them: the period
// measurement of the pendulum-like tests (a bead on a wire, a bead on a rail).
#include <cstddef>
#include <vector>

namespace spar::test {

class UpwardCrossings {
public:
  /// One step of length h from (x_prev, v_prev) at t_prev to (x, v): records the time at which x
  /// passes 0 upwards inside it, if it does.
  void add_step(double t_prev, double h, double x_prev, double v_prev, double x, double v) {
    if (!(x_prev < 0.0 && x >= 0.0)) return;
    // Newton on the interpolant p(τ), τ ∈ [0, 1], from the linear guess.
    double tau = -x_prev / (x - x_prev);
    for (int i = 0; i < 20; ++i) {
      const double t2 = tau * tau, t3 = t2 * tau;
      const double p = (2 * t3 - 3 * t2 + 1) * x_prev + (t3 - 2 * t2 + tau) * h * v_prev +
                       (-2 * t3 + 3 * t2) * x + (t3 - t2) * h * v;
      const double dp = (6 * t2 - 6 * tau) * x_prev + (3 * t2 - 4 * tau + 1) * h * v_prev +
                        (-6 * t2 + 6 * tau) * x + (3 * t2 - 2 * tau) * h * v;
      tau -= p / dp;
    }
    times_.push_back(t_prev + tau * h);
  }

  std::size_t count() const { return times_.size(); }
  /// The mean time between the first and the last crossing (needs two).
  double period() const {
    return (times_.back() - times_.front()) / static_cast<double>(times_.size() - 1);
  }

private:
  std::vector<double> times_;
};

}  // namespace spar::test
