#pragma once
/// \file
/// Output at chosen times, independent of the time step: every Δt_out or at a list of times,
/// interpolated between the integrator's steps (docs/dynamics.md D10).

#include <spar/core/configuration.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::solvers {

/// The state at one output time.
struct Sample {
  double time = 0.0;
  core::Configuration q;
  Eigen::VectorXd velocity;     ///< global tangent layout (ẋ inertial, Ω material)
  Eigen::VectorXd multipliers;  ///< λ, constraint by constraint
  Energies energies;            ///< the energy balance (interpolated linearly, like v)
};

/// Collects samples at output times as an integrator steps. Call update() once after
/// initialize() (whose initial assembly may move the state) and before the first step, then after
/// every step: it returns the samples whose times fall in (t_n, t_{n+1}] of the step just taken
/// (at the first call, those equal to the start time).
///
/// Between steps n and n + 1 (h = t_{n+1} − t_n, s = (t − t_n)/h), in the chart at q_n:
///   q(t) = q_n ⊕ Δ(s),  Δ(s) = H₁(s) D + h H₂(s) v_n + h H₃(s) v_{n+1}   (cubic Hermite),
/// D the step's increment (x_{n+1} − x_n, log(R_nᵀ R_{n+1}), p_{n+1} − p_n) and H the Hermite
/// basis (H₁ = 3s² − 2s³, H₂ = s − 2s² + s³, H₃ = s³ − s²). It reproduces q_n, q_{n+1} and the
/// end velocities (the end tangent up to the chart's T(D) = I + O(h)), so its error is O(h³) per
/// sample (exact for a motion of constant acceleration and a steady rotation), below the
/// method's O(h²). Velocities, multipliers and energies are interpolated linearly, O(h²) like the
/// method.
/// A step that changed the blocks (Model::replace_state, remap) has no common chart: its
/// samples are the end state.
class TimeSampler {
public:
  /// Every `interval` from t = 0: times k · interval, k = 0, 1, … (computed, not accumulated).
  /// spar::Error for an interval that is not positive and finite.
  static TimeSampler every(double interval);
  /// At the given times, in increasing order (spar::Error naming the first time that is not
  /// finite or not after the one before).
  explicit TimeSampler(std::vector<double> times);

  /// The samples of the step just taken (see the class comment); valid until the next call.
  const std::vector<Sample>& update(const GeneralizedAlpha& integrator);

private:
  TimeSampler(double interval, std::vector<double> times);
  /// The k-th output time (every: k · interval; list: times[k]); +∞ past the list's end.
  double output_time(long k) const;
  void add_sample(double time, const GeneralizedAlpha& integrator);

  double interval_ = 0.0;
  std::vector<double> times_;
  long next_ = 0;
  bool started_ = false;
  // The state at the previous update.
  double t_previous_ = 0.0;
  core::Configuration q_previous_;
  Eigen::VectorXd v_previous_, lambda_previous_;
  Energies energies_previous_;
  std::vector<Sample> samples_;
};

}  // namespace spar::solvers
