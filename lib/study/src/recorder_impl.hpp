#pragma once
// The state of a study::Recorder: what was declared, the schedules' channels and their files, and
// one evaluation of the quantities at a state (recorder.cpp: the declarations and the run;
// recorder_files.cpp: making and writing the files).
#include <spar/output/recording_csv.hpp>
#include <spar/output/results_writer.hpp>
#include <spar/solvers/time_sampler.hpp>
#include <spar/study/recorder.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace spar::study {

struct Recorder::Impl {
  struct ScalarEntry {
    Quantity quantity;
    std::function<double(const State&)> value;
    double last = std::numeric_limits<double>::quiet_NaN();
    double max = -std::numeric_limits<double>::infinity(), min = std::numeric_limits<double>::infinity();
    double max_abs = 0.0;
    std::vector<double> kept;  ///< the values from quantity.spread_from on
  };
  struct VectorEntry {
    Quantity quantity;
    std::function<Eigen::Vector3d(const State&)> value;
    Eigen::Vector3d last = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  };
  struct Line {
    int points = 0;
    std::function<Eigen::MatrixXd(const State&)> positions, velocities;
    Eigen::MatrixXd arc_length;  ///< from the root at the start, points × 1 (centerline_fields)
  };
  struct ProfileEntry {
    Quantity quantity;
    Eigen::VectorXd arc_length;
    int components = 0;
    std::function<Eigen::MatrixXd(const State&)> values;
  };
  struct CsvColumn {
    bool vector = false;
    int index = 0, component = 0;
  };
  /// A schedule and the outputs it feeds.
  struct Channel {
    Schedule schedule;
    bool file = false, csv = false;
    int snapshots = -1;  ///< index into snapshot_specs, or none
    std::optional<solvers::TimeSampler> sampler;  ///< for a sampled schedule, made by open()
  };
  /// The quantities at one state, each evaluated at most once; at a step they update the reductions.
  struct Evaluation {
    Impl& impl;
    const State& state;
    bool step;
    std::vector<std::optional<double>> scalars;
    std::vector<std::optional<Eigen::Vector3d>> vectors;
    std::optional<std::vector<Eigen::MatrixXd>> lines;

    Evaluation(Impl& impl, const State& state, bool step)
        : impl(impl), state(state), step(step), scalars(impl.scalars.size()), vectors(impl.vectors.size()) {}
    double scalar(std::size_t i) {
      if (!scalars[i]) {
        ScalarEntry& entry = impl.scalars[i];
        const double v = entry.value(state);
        scalars[i] = v;
        if (step) {
          entry.last = v;
          entry.max = std::max(entry.max, v);
          entry.min = std::min(entry.min, v);
          entry.max_abs = std::max(entry.max_abs, std::abs(v));
          if (state.time >= entry.quantity.spread_from - 0.5 * impl.options.time_step) entry.kept.push_back(v);
        }
      }
      return *scalars[i];
    }
    const Eigen::Vector3d& vector(std::size_t i) {
      if (!vectors[i]) {
        vectors[i] = impl.vectors[i].value(state);
        if (step) impl.vectors[i].last = *vectors[i];
      }
      return *vectors[i];
    }
    const std::vector<Eigen::MatrixXd>& centerlines() {
      if (!lines) {
        lines.emplace();
        for (const Line& line : impl.lines) lines->push_back(line.positions(state));
      }
      return *lines;
    }
  };

  Impl(solvers::GeneralizedAlpha& integrator, RecorderOptions options)
      : integrator(integrator), options(std::move(options)) {}

  std::string where() const { return "study::Recorder '" + options.name + "'"; }
  /// spar::Error once run() has made the files.
  void require_declaring(const char* what) const;
  void require_new_name(const std::string& name) const;

  /// Makes the results file, the CSV and the snapshots (recorder_files.cpp).
  void open();
  /// The CSV's header and csv_columns: the time, then each named quantity's cells.
  std::string resolve_csv();
  void write(const Attribute& attribute);
  void write_file(Evaluation& e);
  void write_csv(Evaluation& e);
  void write_snapshot(int k, Evaluation& e);
  void record(const Channel& channel, Evaluation& e);
  /// The state after step n (0: the start): each channel's due records, then the every_step quantities.
  void observe(long n, bool last);

  solvers::GeneralizedAlpha& integrator;
  RecorderOptions options;
  std::vector<ScalarEntry> scalars;
  std::vector<VectorEntry> vectors;
  std::vector<Line> lines;
  std::vector<ProfileEntry> profiles;
  std::vector<output::RigidBodyShape> shapes;
  std::vector<std::string> csv_names;
  std::vector<CsvColumn> csv_columns;
  std::vector<Snapshots> snapshot_specs;
  std::vector<Channel> channels;
  std::vector<Attribute> pending_attributes;
  std::optional<output::ResultsWriter> writer;
  std::optional<output::CsvFile> csv;
  std::vector<output::CsvFile> snapshot_files;
  int multiplier_count = 0;
  bool start_energy_needed = false;  ///< energy_drift() was declared
  double start_energy = 0.0;         ///< E(0) of energy_drift(), taken by open()
  bool closed = false;
};

}  // namespace spar::study
