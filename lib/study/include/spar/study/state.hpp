#pragma once
/// \file
/// What a study's quantities are evaluated at and how one is declared (docs/output.md,
/// "Studies"): a study::State is the end of a step (or the start of the run) or, for a schedule
/// sampled between steps, an interpolated output time (solvers::TimeSampler); a Quantity names a
/// value, its unit and its meaning, and where it goes.

#include <spar/core/configuration.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/time_sampler.hpp>

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <string>

namespace spar::study {

/// The state a quantity is evaluated at. Valid during the evaluation only.
class State {
public:
  /// The integrator's state now; its energies are asked for at the first energies() call.
  explicit State(const solvers::GeneralizedAlpha& integrator);
  /// An output time between steps (the integrator is the one that took the step holding it).
  State(const solvers::GeneralizedAlpha& integrator, const solvers::Sample& sample);

  double time;
  const core::Configuration& q;
  const Eigen::VectorXd& velocity;     ///< global tangent layout: ẋ inertial, Ω material per frame
  const Eigen::VectorXd& multipliers;  ///< λ, constraint by constraint
  const solvers::GeneralizedAlpha& integrator;

  /// The energy balance (docs/dynamics.md D8): the integrator's at a step, interpolated at a sample.
  const solvers::Energies& energies() const;
  /// λ of the integrator's constraint c (its equation_count() entries), e.g. for
  /// joints::RevoluteJoint::reaction_in_frame.
  Eigen::VectorXd multipliers_of(int c) const;
  /// ‖Φ(q, t)‖∞ over the integrator's constraints (at a step: integrator.constraint_residual()).
  double constraint_residual() const;

private:
  mutable std::optional<solvers::Energies> energies_;
};

/// The position of frame block `node`, as a function of the recorded state:
/// `rec.vector({.name = "tip", ...}, study::node_position(tip))`.
inline auto node_position(int node) {
  return [node](const State& s) -> Eigen::Vector3d { return s.q.position[node]; };
}

/// A value a study records: a scalar (Recorder::scalar) or a 3-vector (Recorder::vector).
struct Quantity {
  /// Its name: the results file's dataset (scalars/<name> or probes/<name>) and the name the CSV
  /// columns (Recorder::csv) refer to. Unique within a recorder; no '/'.
  std::string name;
  std::string unit;         ///< SI unit, e.g. "J", "m/s"; "1" for ratios and counts
  std::string description;  ///< what it is, e.g. "kinetic energy of the rods"
  /// Its CSV header: a scalar's column (default: `name`), a vector's columns comma-separated, one
  /// per component written (e.g. "tip_x,tip_y,tip_z", or "x,y" for the first two).
  std::string csv;
  bool integer = false;           ///< stored as 32-bit integers (counters); every value a whole number
  bool may_be_undefined = false;  ///< NaN marks a state where it is not defined (otherwise refused)
  /// Evaluated at every step, also where nothing is recorded, so that its running reductions
  /// (Scalar::max, …) cover every step; otherwise at the recorded steps only.
  bool every_step = false;
  /// Keep its values at the steps from this time on (within half a step) for Scalar::spread(), e.g.
  /// a point's residual vibration after a manoeuvre; +∞: none kept.
  double spread_from = std::numeric_limits<double>::infinity();
  bool file = true;  ///< written to the results file; false: the CSV and the summary only (no unit needed)
};

}  // namespace spar::study
