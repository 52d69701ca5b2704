#pragma once
/// \file
/// A study's run and what it records (docs/output.md, "Studies"). A driver declares what it
/// wants to see — scalars and vectors (a value with its unit and meaning), the energy balance,
/// the constraint residual and the Newton iterations, centerlines, rigid bodies' shapes, the
/// columns of a CSV, snapshots of the centerlines, profiles along beams (section forces and
/// moments: core::section_resultants), run metadata — and when; run() then steps the
/// integrator to the end time, drives the progress bar and writes the results file (HDF5 + XDMF
/// through output::ResultsWriter), the CSV and the snapshots, keeping every scalar's running
/// reductions for the JSON summary (output::JsonSummary). close() adds the solver's counters.
///
///     study::Recorder rec(integrator, {.folder = out, .name = "pendulum", .time_step = h});
///     const study::Scalar drift = rec.scalar({.name = "energy_drift", .unit = "1", .description = "(E - E0)/E0"},
///         [&](const study::State& s) { return (s.energies().total() - e0) / e0; });
///     rec.energy_balance();
///     rec.csv({"energy_drift", "kinetic_energy"});
///     rec.run(t_end);
///     rec.close();
///     output::JsonSummary().add("max_energy_drift", drift.max_abs()).print();

#include <spar/output/recording_summary.hpp>
#include <spar/output/results_writer.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/study/schedule.hpp>
#include <spar/study/state.hpp>
#include <spar/study/statistics.hpp>

#include <Eigen/Core>

#include <concepts>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace spar::study {

class Recorder;

/// A declared scalar: its value at the last evaluated step and its running reductions over the
/// evaluated steps (every step with Quantity::every_step, else the recorded ones; the start
/// included). Before any evaluation: NaN for last(), −∞/+∞ for max()/min(), 0 for max_abs().
class Scalar {
public:
  double last() const;
  double max() const;
  double min() const;
  double max_abs() const;
  /// The spread of its values at the steps from Quantity::spread_from on; none for fewer than two.
  std::optional<Spread> spread() const;

private:
  friend class Recorder;
  Scalar(const Recorder& recorder, int index) : recorder_(&recorder), index_(index) {}
  const Recorder* recorder_;
  int index_;
};

/// A declared vector: its value at the last evaluated step (NaN before).
class Vector {
public:
  Eigen::Vector3d last() const;

private:
  friend class Recorder;
  Vector(const Recorder& recorder, int index) : recorder_(&recorder), index_(index) {}
  const Recorder* recorder_;
  int index_;
};

/// The scalars of the energy balance (docs/dynamics.md D8).
struct EnergyBalance {
  Scalar kinetic, strain, gravity, external_work, physical_dissipation, numerical_dissipation, created;
};

struct RecorderOptions {
  std::string folder;      ///< where the files go (a driver's --out)
  std::string name;        ///< their stem: <name>.h5 (+ .xmf), <name>.csv; the progress bar's label
  double time_step = 0.0;  ///< h: the run's end is t_end − h/2, the schedules' tolerance h/2
  /// The states the results file and the CSV get (the CSV may have its own: csv()).
  Schedule schedule = Schedule::every_step();
  bool nodes = false;       ///< every block's position and rotation (ResultsLayout::node_count)
  bool velocities = false;  ///< the nodes' velocities and the shapes' vertex velocities
  /// λ, as many as the integrator has at the start (a constraint added later, an end stop's lock,
  /// is left out of the file).
  bool multipliers = false;
  /// Every centerline's reference arc length from its root (the sums of its sample's chords at the
  /// start: exact for straight beams) and its velocity, as point data ParaView colours by.
  bool centerline_fields = false;
  int csv_digits = 0;       ///< output::CsvFile's digits (0: the shortest text that reads back the same)
  /// close() prints one line on stdout: the steps, the time reached, the solver's work and the files.
  bool report = true;
  int flush_every = 100;    ///< output::ResultsWriter's block of steps
};

/// Snapshots of every centerline in one long CSV: a row per point, "t, line, [label,] x, y, z".
struct Snapshots {
  std::string file;    ///< in the folder, e.g. "sliding_beam_snapshots.csv"
  std::string header;  ///< e.g. "t,beam,x,y,z"
  Schedule schedule;
  int digits = 9;
  std::vector<double> labels;  ///< per centerline, a number written after its index (none: no column)
};

/// What Recorder::summary() starts the JSON summary with.
struct SummaryContents {
  bool counters = true;         ///< steps, newton_iterations, factorizations, cutbacks, wall_s
  bool energy_balance = false;  ///< external_work and numerical_dissipation at the end (J)
};

/// What run() does besides stepping and recording, after each step and before its recording.
struct RunHooks {
  std::function<void()> each_step;  ///< e.g. advance a reference solution, control a mesh
  std::function<bool()> stop_when;  ///< true: record this step as the last and stop
};

/// A root attribute of the results file (output::ResultsWriter::write_attribute).
using Attribute = std::pair<std::string, std::variant<double, long, std::string>>;

class Recorder {
public:
  /// Records `integrator`'s run. Declare everything, then run(); the files are made by run().
  /// spar::Error for an empty folder or name or a time step that is not positive.
  Recorder(solvers::GeneralizedAlpha& integrator, RecorderOptions options);
  /// Closes the files if close() was not called, reporting a failure on stderr.
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// A scalar; `value` takes a const State& (or nothing) and returns a double.
  template <class F>
  Scalar scalar(Quantity quantity, F&& value) {
    return add_scalar(std::move(quantity), evaluator<double>(std::forward<F>(value)));
  }
  /// A 3-vector (a probe of the results file), e.g. a point's position; `value` returns a 3-vector,
  /// or a 2-vector (a planar model's point, z = 0).
  template <class F>
  Vector vector(Quantity quantity, F&& value) {
    std::function<Eigen::Vector3d(const State&)> point;
    if constexpr (std::is_invocable_v<F&, const State&>)
      point = [f = std::forward<F>(value)](const State& s) { return as_point(f(s)); };
    else
      point = [f = std::forward<F>(value)](const State&) { return as_point(f()); };
    return add_vector(std::move(quantity), std::move(point));
  }
  /// kinetic_energy, strain_energy, gravity_potential, external_work, physical_dissipation,
  /// numerical_dissipation, created_energy (J; docs/dynamics.md D8–D8a).
  EnergyBalance energy_balance();
  /// The total energy E = kinetic + strain + gravity potential, "total_energy" in J unless
  /// `quantity` says otherwise.
  Scalar total_energy(Quantity quantity = {});
  /// Its drift (E − E(0)) / scale, E(0) the total energy at the start of run(): "energy_drift", "1",
  /// `quantity` giving its description (what the scale is).
  Scalar energy_drift(double scale, Quantity quantity);
  /// ‖Φ‖∞ after the step, "constraint_residual" in m unless `quantity` says otherwise.
  Scalar constraint_residual(Quantity quantity = {});
  /// The Newton iterations of the step, "newton_iterations", an integer, unless `quantity` says otherwise.
  Scalar newton_iterations(Quantity quantity = {});

  /// A centerline of `points` points, root to tip (`velocities` needed with centerline_fields).
  void centerline(int points, std::function<Eigen::MatrixXd(const State&)> positions,
                  std::function<Eigen::MatrixXd(const State&)> velocities = {});
  /// A centerline from a sampler with size() and positions(q), and velocities(q, v) if it has it
  /// (core::CenterlineSampler).
  template <class Sampler>
    requires requires(const Sampler& s, const core::Configuration& q) {
      { s.size() } -> std::convertible_to<int>;
      { s.positions(q) } -> std::convertible_to<Eigen::MatrixXd>;
    }
  void centerline(Sampler sampler) {
    auto shared = std::make_shared<const Sampler>(std::move(sampler));
    std::function<Eigen::MatrixXd(const State&)> velocities;
    if constexpr (requires(const core::Configuration& q, const Eigen::VectorXd& v) { shared->velocities(q, v); })
      velocities = [shared](const State& s) -> Eigen::MatrixXd { return shared->velocities(s.q, s.velocity); };
    centerline(shared->size(), [shared](const State& s) -> Eigen::MatrixXd { return shared->positions(s.q); },
               std::move(velocities));
  }
  /// A profile: a quantity along a line at `arc_length.size()` points of `components` values each,
  /// written to the results file as profiles/<name> (points × components) at its states, the
  /// points' reference arc lengths as the constant profiles/<name>_arc_length (m). `values`
  /// returns points × components, e.g. a beam's section moments:
  ///     const core::SectionPoints at = core::section_points(rod);
  ///     rec.profile({.name = "section_moment", .unit = "N m", .description = "..."}, at.arc_length, 3,
  ///                 [&](const study::State& s) { return core::section_resultants(rod, s.q).moment; });
  void profile(Quantity quantity, Eigen::VectorXd arc_length, int components,
               std::function<Eigen::MatrixXd(const State&)> values);
  /// A rigid body's shape in the XDMF sidecar (docs/output.md, "Rigid bodies").
  void shape(const output::RigidBodyShape& shape);

  /// The CSV <name>.csv: the time, then the columns of the named quantities in this order, at
  /// the file's states or at `schedule`'s.
  void csv(std::vector<std::string> columns);
  void csv(std::vector<std::string> columns, Schedule schedule);
  /// A CSV of the centerlines' points at `snapshots.schedule`.
  void snapshots(Snapshots snapshots);

  /// Root attributes of the results file (any time; "time_step" is written by itself).
  void attributes(const std::vector<Attribute>& attributes);
  /// The integrator's structure events after run(): their times as the dataset events/time (its
  /// description names `what` they are) and each as an attribute event_<k> holding
  /// `text(time, description)` (default: the description).
  void events(const std::string& what, const std::function<std::string(double, const std::string&)>& text = {});
  /// A constant dataset (output::ResultsWriter::write_constant), after run().
  void constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                const std::string& description);

  /// Makes the files (with the program's finished_options() as the results file's /options),
  /// records the start, then steps until t_end − h/2 or until hooks.stop_when,
  /// recording each step as scheduled. Call integrator.initialize() first.
  void run(double t_end, const RunHooks& hooks = {});
  /// Writes the counters (t_end, steps, newton_iterations, factorizations,
  /// substructured_factorizations, jtheta_updates, cutbacks) as attributes, and the energy alarm's
  /// energy_alarm_time (s), energy_alarm_created and energy_alarm_scale (J) if it went off
  /// (solvers::DynamicOptions::energy_alarm), closes the files and prints RecorderOptions::report's
  /// line.
  void close();

  /// A JSON summary holding `contents` (the counters, the integrator's wall time as wall_s; the
  /// final energy balance); the driver adds its figures and prints it.
  output::JsonSummary summary(SummaryContents contents = {}) const;
  /// Wall time of run()'s loop, s; states written to the results file.
  double wall_seconds() const { return wall_seconds_; }
  int states_written() const;

private:
  friend class Scalar;
  friend class Vector;
  struct Impl;

  /// A 3-vector as it is, a 2-vector padded with z = 0.
  template <class V>
  static Eigen::Vector3d as_point(const V& v) {
    if constexpr (std::decay_t<V>::RowsAtCompileTime == 2)
      return {v(0), v(1), 0.0};
    else
      return v;
  }
  template <class R, class F>
  static std::function<R(const State&)> evaluator(F&& f) {
    if constexpr (std::is_invocable_v<F&, const State&>)
      return [f = std::forward<F>(f)](const State& s) -> R { return f(s); };
    else
      return [f = std::forward<F>(f)](const State&) -> R { return f(); };
  }
  Scalar add_scalar(Quantity quantity, std::function<double(const State&)> value);
  Vector add_vector(Quantity quantity, std::function<Eigen::Vector3d(const State&)> value);

  std::unique_ptr<Impl> impl_;
  double wall_seconds_ = 0.0;
};

}  // namespace spar::study
