#include <spar/solvers/time_sampler.hpp>

#include <spar/error.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace spar::solvers {

namespace {

/// "0.001 s": the shortest text that reads back as `t`.
std::string format_seconds(double t) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, t);
  return std::string(text, result.ptr) + " s";
}

}  // namespace

TimeSampler::TimeSampler(double interval, std::vector<double> times)
    : interval_(interval), times_(std::move(times)) {}

TimeSampler TimeSampler::every(double interval) {
  if (!(interval > 0.0) || !std::isfinite(interval))
    throw Error("output interval " + std::to_string(interval) + " is not positive and finite",
                "solvers::TimeSampler::every", "give the time between samples in seconds, > 0");
  return TimeSampler(interval, {});
}

// Listed times must increase (issue 29): a list out of order was sorted silently, and a repeated
// time gave two samples at one time, which ResultsWriter::append refuses in the middle of the run.
TimeSampler::TimeSampler(std::vector<double> times) : TimeSampler(0.0, std::move(times)) {
  for (std::size_t k = 0; k < times_.size(); ++k) {
    const std::string entry = "output time " + std::to_string(k) + " (" + format_seconds(times_[k]) + ")";
    if (!std::isfinite(times_[k]))
      throw Error(entry + " is not finite", "solvers::TimeSampler", "give finite times in seconds");
    if (k > 0 && !(times_[k] > times_[k - 1]))
      throw Error(entry + " is not after output time " + std::to_string(k - 1) + " (" + format_seconds(times_[k - 1]) +
                      ")",
                  "solvers::TimeSampler", "list the output times in increasing order, each once");
  }
}

double TimeSampler::output_time(long k) const {
  if (interval_ > 0.0) return static_cast<double>(k) * interval_;
  return k < static_cast<long>(times_.size()) ? times_[k] : std::numeric_limits<double>::infinity();
}

const std::vector<Sample>& TimeSampler::update(const GeneralizedAlpha& integrator) {
  samples_.clear();
  const double t = integrator.time();
  // Times within round-off of a step count as on it (k · Δt_out against a sum of steps).
  const double slack = 1e-9 * std::max(std::abs(t), std::abs(t - t_previous_));
  if (!started_) {
    while (output_time(next_) < t - slack) ++next_;  // times before the start are not sampled
    started_ = true;
  }
  for (double time = output_time(next_); time <= t + slack; time = output_time(++next_))
    add_sample(std::min(time, t), integrator);
  t_previous_ = t;
  q_previous_ = integrator.configuration();
  v_previous_ = integrator.velocity();
  lambda_previous_ = integrator.multipliers();
  energies_previous_ = integrator.energies();
  return samples_;
}

void TimeSampler::add_sample(double time, const GeneralizedAlpha& integrator) {
  const core::Configuration& q1 = integrator.configuration();
  const Eigen::VectorXd& v1 = integrator.velocity();
  const Eigen::VectorXd& lambda1 = integrator.multipliers();
  const double h = integrator.time() - t_previous_;
  const Energies e1 = integrator.energies();
  Sample sample{.time = time, .q = q1, .velocity = v1, .multipliers = lambda1, .energies = e1};
  const bool same_layout = q_previous_.dof_count() == q1.dof_count() &&
                           q_previous_.block_count() == q1.block_count() && lambda_previous_.size() == lambda1.size();
  if (h > 0.0 && same_layout && time < integrator.time()) {
    const double s = (time - t_previous_) / h;
    const double h1 = s * s * (3 - 2 * s), h2 = s * (1 - s) * (1 - s), h3 = s * s * (s - 1);
    // D: the step's increment in the chart at q_n.
    const Eigen::VectorXd D = q1.increment_from(q_previous_);
    const Eigen::VectorXd delta = h1 * D + h * h2 * v_previous_ + h * h3 * v1;
    sample.q.assign_increment(q_previous_, delta);
    sample.velocity = (1 - s) * v_previous_ + s * v1;
    sample.multipliers = (1 - s) * lambda_previous_ + s * lambda1;
    const Energies& e0 = energies_previous_;
    auto mix = [s](double a, double b) { return (1 - s) * a + s * b; };
    sample.energies = {.kinetic = mix(e0.kinetic, e1.kinetic), .strain = mix(e0.strain, e1.strain),
                       .gravity = mix(e0.gravity, e1.gravity),
                       .external_work = mix(e0.external_work, e1.external_work),
                       .physical_dissipation = mix(e0.physical_dissipation, e1.physical_dissipation),
                       .numerical_dissipation = mix(e0.numerical_dissipation, e1.numerical_dissipation)};
  }
  samples_.push_back(std::move(sample));
}

}  // namespace spar::solvers
