#include "recorder_impl.hpp"

#include <spar/error.hpp>
#include <spar/output/progress_bar.hpp>

#include <chrono>
#include <cstdio>

namespace spar::study {

void Recorder::Impl::require_declaring(const char* what) const {
  if (writer) throw Error(std::string(what) + " declared after run()", where(), "declare every output before run()");
}

void Recorder::Impl::require_new_name(const std::string& name) const {
  const auto named = [&](const auto& entry) { return entry.quantity.name == name; };
  if (std::any_of(scalars.begin(), scalars.end(), named) || std::any_of(vectors.begin(), vectors.end(), named) ||
      std::any_of(profiles.begin(), profiles.end(), named))
    throw Error("the name '" + name + "' is declared twice", where(), "give each quantity its own name");
}

double Scalar::last() const { return recorder_->impl_->scalars[index_].last; }
double Scalar::max() const { return recorder_->impl_->scalars[index_].max; }
double Scalar::min() const { return recorder_->impl_->scalars[index_].min; }
double Scalar::max_abs() const { return recorder_->impl_->scalars[index_].max_abs; }
std::optional<Spread> Scalar::spread() const { return study::spread(recorder_->impl_->scalars[index_].kept); }
Eigen::Vector3d Vector::last() const { return recorder_->impl_->vectors[index_].last; }

Recorder::Recorder(solvers::GeneralizedAlpha& integrator, RecorderOptions options)
    : impl_(std::make_unique<Impl>(integrator, std::move(options))) {
  const RecorderOptions& o = impl_->options;
  if (o.folder.empty() || o.name.empty())
    throw Error("the folder or the name is empty", "study::Recorder", "give both: the files are <folder>/<name>.h5, ...");
  if (!(std::isfinite(o.time_step) && o.time_step > 0.0))
    throw Error("the time step " + significant(o.time_step) + " s is not a positive finite time", impl_->where(),
                "give RecorderOptions::time_step, the integrator's h");
  impl_->channels.push_back({.schedule = o.schedule, .file = true, .csv = true});
}

Recorder::~Recorder() {
  if (!impl_ || impl_->closed) return;
  try {
    close();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
  }
}

Scalar Recorder::add_scalar(Quantity quantity, std::function<double(const State&)> value) {
  impl_->require_declaring("a scalar");
  impl_->require_new_name(quantity.name);
  impl_->scalars.push_back({std::move(quantity), std::move(value)});
  return Scalar(*this, static_cast<int>(impl_->scalars.size()) - 1);
}

Vector Recorder::add_vector(Quantity quantity, std::function<Eigen::Vector3d(const State&)> value) {
  impl_->require_declaring("a vector");
  impl_->require_new_name(quantity.name);
  impl_->vectors.push_back({std::move(quantity), std::move(value)});
  return Vector(*this, static_cast<int>(impl_->vectors.size()) - 1);
}

EnergyBalance Recorder::energy_balance() {
  const auto energy = [&](std::string name, std::string description, double solvers::Energies::*member) {
    return scalar({.name = std::move(name), .unit = "J", .description = std::move(description)},
                  [member](const State& s) { return s.energies().*member; });
  };
  return {energy("kinetic_energy", "kinetic energy, 1/2 v^T M v", &solvers::Energies::kinetic),
          energy("strain_energy", "strain energy of the beams", &solvers::Energies::strain),
          energy("gravity_potential", "potential of gravity, -sum m g . x", &solvers::Energies::gravity),
          energy("external_work",
                 "work done since t = 0 by the external loads without a potential and by the drivers, trapezoidal "
                 "along the increments",
                 &solvers::Energies::external_work),
          energy("physical_dissipation",
                 "work of the elements' own dissipative forces since t = 0 (dampers, Kelvin-Voigt stresses), "
                 "trapezoidal along the increments; numerical_dissipation is what remains besides it",
                 &solvers::Energies::physical_dissipation),
          energy("numerical_dissipation",
                 "energy removed by the integrator since t = 0: external_work - (E - E(0)) - physical_dissipation, "
                 "E = kinetic + strain + gravity",
                 &solvers::Energies::numerical_dissipation),
          energy("created_energy",
                 "energy the integrator created since t = 0: E - E(0) + physical_dissipation - the work of the loads "
                 "and of the drivers (passive joints do none); the energy alarm watches it (docs/dynamics.md D8a)",
                 &solvers::Energies::created)};
}

namespace {

/// `given` with its empty name, unit and description taken from `defaults`.
Quantity with_defaults(Quantity given, Quantity defaults) {
  if (given.name.empty()) given.name = std::move(defaults.name);
  if (given.unit.empty()) given.unit = std::move(defaults.unit);
  if (given.description.empty()) given.description = std::move(defaults.description);
  return given;
}

}  // namespace

Scalar Recorder::total_energy(Quantity quantity) {
  return scalar(with_defaults(std::move(quantity), {.name = "total_energy", .unit = "J",
                                                    .description = "kinetic + strain energy + gravity potential"}),
                [](const State& s) { return s.energies().total(); });
}

Scalar Recorder::energy_drift(double scale, Quantity quantity) {
  impl_->start_energy_needed = true;
  return scalar(with_defaults(std::move(quantity), {.name = "energy_drift", .unit = "1"}),
                [this, scale](const State& s) { return (s.energies().total() - impl_->start_energy) / scale; });
}

Scalar Recorder::constraint_residual(Quantity quantity) {
  return scalar(with_defaults(std::move(quantity), {.name = "constraint_residual", .unit = "m",
                                                    .description = "largest constraint violation |Phi|_inf after the step"}),
                [](const State& s) { return s.constraint_residual(); });
}

Scalar Recorder::newton_iterations(Quantity quantity) {
  quantity.integer = true;
  return scalar(with_defaults(std::move(quantity), {.name = "newton_iterations", .unit = "1",
                                                    .description = "Newton iterations (linear solves) of the step"}),
                [](const State& s) { return static_cast<double>(s.integrator.last_step_iterations()); });
}

void Recorder::centerline(int points, std::function<Eigen::MatrixXd(const State&)> positions,
                          std::function<Eigen::MatrixXd(const State&)> velocities) {
  impl_->require_declaring("a centerline");
  impl_->lines.push_back({points, std::move(positions), std::move(velocities), {}});
}

void Recorder::profile(Quantity quantity, Eigen::VectorXd arc_length, int components,
                       std::function<Eigen::MatrixXd(const State&)> values) {
  impl_->require_declaring("a profile");
  impl_->require_new_name(quantity.name);
  if (arc_length.size() < 1 || components < 1 || !arc_length.allFinite())
    throw Error("the profile '" + quantity.name + "' has " + std::to_string(arc_length.size()) + " points of " +
                    std::to_string(components) + " components, or an arc length that is not finite",
                impl_->where(), "give one finite arc length per point and at least one component");
  impl_->profiles.push_back({std::move(quantity), std::move(arc_length), components, std::move(values)});
}

void Recorder::shape(const output::RigidBodyShape& shape) {
  impl_->require_declaring("a shape");
  impl_->shapes.push_back(shape);
}

void Recorder::csv(std::vector<std::string> columns) {
  impl_->require_declaring("the CSV");
  impl_->csv_names = std::move(columns);
}

void Recorder::csv(std::vector<std::string> columns, Schedule schedule) {
  csv(std::move(columns));
  impl_->channels.front().csv = false;
  impl_->channels.push_back({.schedule = std::move(schedule), .csv = true});
}

void Recorder::snapshots(Snapshots snapshots) {
  impl_->require_declaring("snapshots");
  impl_->channels.push_back({.schedule = snapshots.schedule, .snapshots = static_cast<int>(impl_->snapshot_specs.size())});
  impl_->snapshot_specs.push_back(std::move(snapshots));
}

void Recorder::attributes(const std::vector<Attribute>& attributes) {
  for (const Attribute& attribute : attributes) {
    if (impl_->writer)
      impl_->write(attribute);
    else
      impl_->pending_attributes.push_back(attribute);
  }
}

void Recorder::events(const std::string& what, const std::function<std::string(double, const std::string&)>& text) {
  const std::vector<std::pair<double, std::string>>& events = impl_->integrator.events();
  if (events.empty()) return;
  Eigen::VectorXd times(static_cast<Eigen::Index>(events.size()));
  for (std::size_t k = 0; k < events.size(); ++k) {
    times(static_cast<Eigen::Index>(k)) = events[k].first;
    attributes({{"event_" + std::to_string(k), text ? text(events[k].first, events[k].second) : events[k].second}});
  }
  constant("events/time", times, "s",
           "times of the structure events (" + what + "); attribute event_<k> describes event k");
}

void Recorder::constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                        const std::string& description) {
  if (!impl_->writer)
    throw Error("constant '" + name + "' before the results file exists", impl_->where(), "write constants after run()");
  impl_->writer->write_constant(name, data, unit, description);
}

void Recorder::run(double t_end, const RunHooks& hooks) {
  if (impl_->writer) throw Error("run() called twice", impl_->where(), "record one run per Recorder");
  impl_->open();
  solvers::GeneralizedAlpha& integrator = impl_->integrator;
  const double h = impl_->options.time_step;
  impl_->observe(0, false);
  output::ProgressBar progress(t_end, impl_->options.name);
  const auto start = std::chrono::steady_clock::now();
  for (long n = 1; integrator.time() < t_end - 0.5 * h; ++n) {
    integrator.step();
    if (hooks.each_step) hooks.each_step();
    const bool stop = hooks.stop_when && hooks.stop_when();
    impl_->observe(n, stop || integrator.time() >= t_end - 0.5 * h);
    progress.update(integrator.time(), integrator.counters().steps);
    if (stop) break;
  }
  wall_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
}

void Recorder::close() {
  if (impl_->closed) return;
  impl_->closed = true;
  if (!impl_->writer) impl_->open();
  const solvers::GeneralizedAlpha& integrator = impl_->integrator;
  const solvers::DynamicCounters& counters = integrator.counters();
  output::ResultsWriter& writer = *impl_->writer;
  writer.write_attribute("t_end", integrator.time());
  writer.write_attribute("steps", std::int64_t{counters.steps});
  writer.write_attribute("newton_iterations", std::int64_t{counters.newton_iterations});
  writer.write_attribute("factorizations", std::int64_t{counters.factorizations});
  writer.write_attribute("substructured_factorizations", std::int64_t{counters.substructured_factorizations});
  writer.write_attribute("jtheta_updates", std::int64_t{counters.jtheta_evaluations});
  writer.write_attribute("cutbacks", std::int64_t{counters.cutbacks});
  if (const std::optional<solvers::EnergyAlarm>& alarm = integrator.energy_alarm()) {
    writer.write_attribute("energy_alarm_time", alarm->time);
    writer.write_attribute("energy_alarm_created", alarm->created);
    writer.write_attribute("energy_alarm_scale", alarm->scale);
  }
  const int states = writer.steps_written();
  writer.close();
  if (impl_->csv) impl_->csv->close();
  for (output::CsvFile& file : impl_->snapshot_files) file.close();
  if (impl_->options.report)
    std::printf("%s: %ld steps to t = %g s, %ld Newton iterations, %ld factorizations, %.3f s; %d states in %s/%s.h5\n",
                impl_->options.name.c_str(), counters.steps, integrator.time(), counters.newton_iterations,
                counters.factorizations, counters.wall_seconds, states, impl_->options.folder.c_str(),
                impl_->options.name.c_str());
}

output::JsonSummary Recorder::summary(SummaryContents contents) const {
  const solvers::DynamicCounters& counters = impl_->integrator.counters();
  output::JsonSummary summary;
  if (contents.counters) {
    summary.add("steps", counters.steps).add("newton_iterations", counters.newton_iterations);
    summary.add("factorizations", counters.factorizations).add("cutbacks", counters.cutbacks);
    summary.add("wall_s", counters.wall_seconds);
  }
  if (contents.energy_balance) {
    const solvers::Energies energies = impl_->integrator.energies();
    summary.add("external_work", energies.external_work).add("numerical_dissipation", energies.numerical_dissipation);
  }
  return summary;
}

int Recorder::states_written() const { return impl_->writer ? impl_->writer->steps_written() : 0; }

}  // namespace spar::study
