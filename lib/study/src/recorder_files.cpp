#include "recorder_impl.hpp"

#include <spar/error.hpp>
#include <spar/study/command_line.hpp>

#include <sstream>
#include <type_traits>
#include <variant>

namespace spar::study {

namespace {

/// "a,b,c" → {"a", "b", "c"}; "" → {}.
std::vector<std::string> split_cells(const std::string& text) {
  std::vector<std::string> cells;
  std::stringstream stream(text);
  for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
  return cells;
}

output::ResultsQuantity file_quantity(const Quantity& q) {
  return {.name = q.name, .unit = q.unit, .description = q.description, .integer = q.integer,
          .may_be_undefined = q.may_be_undefined};
}

}  // namespace

std::string Recorder::Impl::resolve_csv() {
  std::string header = "t";
  for (const std::string& name : csv_names) {
    bool found = false;
    for (std::size_t i = 0; i < scalars.size() && !found; ++i) {
      const Quantity& q = scalars[i].quantity;
      if (q.name != name && q.csv != name) continue;
      header += "," + (q.csv.empty() ? q.name : q.csv);
      csv_columns.push_back({false, static_cast<int>(i), 0});
      found = true;
    }
    for (std::size_t i = 0; i < vectors.size() && !found; ++i) {
      if (vectors[i].quantity.name != name) continue;
      const std::vector<std::string> cells = split_cells(vectors[i].quantity.csv);
      if (cells.empty() || cells.size() > 3)
        throw Error("the vector '" + name + "' has " + std::to_string(cells.size()) + " CSV cells in Quantity::csv",
                    where(), "give one to three comma-separated column names, e.g. \"x,y,z\"");
      for (std::size_t k = 0; k < cells.size(); ++k) {
        header += "," + cells[k];
        csv_columns.push_back({true, static_cast<int>(i), static_cast<int>(k)});
      }
      found = true;
    }
    if (!found)
      throw Error("the CSV column '" + name + "' names no declared scalar or vector", where(),
                  "declare it with scalar() or vector(), or drop it from csv()");
  }
  return header;
}

void Recorder::Impl::open() {
  const core::Configuration& q = integrator.configuration();
  if (start_energy_needed) start_energy = integrator.energies().total();
  output::ResultsLayout layout{.node_count = options.nodes ? q.block_count() : 0,
                               .velocities = options.velocities,
                               .multiplier_count = options.multipliers ? integrator.multiplier_count() : 0,
                               .rigid_bodies = shapes};
  for (const ScalarEntry& s : scalars)
    if (s.quantity.file) layout.scalars.push_back(file_quantity(s.quantity));
  for (const VectorEntry& v : vectors)
    if (v.quantity.file) layout.probes.push_back(file_quantity(v.quantity));
  const State start(integrator);
  for (Line& line : lines) {
    layout.centerline_points.push_back(line.points);
    if (!options.centerline_fields) continue;
    if (!line.velocities)
      throw Error("a centerline without velocities, and centerline_fields asks for them", where(),
                  "give the centerline a sampler with velocities(q, v), or leave centerline_fields off");
    const Eigen::MatrixXd x0 = line.positions(start);
    line.arc_length = Eigen::MatrixXd::Zero(line.points, 1);
    for (int i = 1; i < line.points; ++i)
      line.arc_length(i, 0) = line.arc_length(i - 1, 0) + (x0.row(i) - x0.row(i - 1)).norm();
  }
  if (options.centerline_fields)
    layout.centerline_fields = {
        {.name = "arc_length", .unit = "m",
         .description = "arc length from the root on the reference centerline (sums of the sample's chords: "
                        "exact for straight beams)"},
        {.name = "velocity", .unit = "m/s", .description = "velocity of the centerline point, inertial frame",
         .components = 3}};
  for (const ProfileEntry& profile : profiles)
    layout.profiles.push_back({.quantity = file_quantity(profile.quantity),
                               .points = static_cast<int>(profile.arc_length.size()),
                               .components = profile.components});
  multiplier_count = layout.multiplier_count;
  std::string header;
  if (!csv_names.empty()) header = resolve_csv();  // refuses a bad column before any file is made
  writer.emplace(options.folder + "/" + options.name + ".h5", std::move(layout), options.flush_every);
  writer->write_attribute("time_step", options.time_step);
  if (!finished_options().empty()) writer->write_options(finished_options());
  for (const ProfileEntry& profile : profiles)
    writer->write_constant("profiles/" + profile.quantity.name + "_arc_length", profile.arc_length, "m",
                           "reference arc length of each point of profiles/" + profile.quantity.name +
                               " from the start of its line");
  for (const Attribute& attribute : pending_attributes) write(attribute);
  pending_attributes.clear();
  if (!csv_names.empty()) csv.emplace(options.folder + "/" + options.name + ".csv", header, options.csv_digits);
  for (const Snapshots& spec : snapshot_specs) {
    if (!spec.labels.empty() && spec.labels.size() != lines.size())
      throw Error(std::to_string(spec.labels.size()) + " snapshot labels for " + std::to_string(lines.size()) +
                      " centerlines", where() + ", " + spec.file, "give one label per centerline, or none");
    snapshot_files.emplace_back(options.folder + "/" + spec.file, spec.header, spec.digits);
  }
  for (Channel& channel : channels)
    if (channel.schedule.sampled()) channel.sampler = solvers::TimeSampler::every(channel.schedule.interval());
}

void Recorder::Impl::write(const Attribute& attribute) {
  std::visit([&](const auto& value) {
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, long>)
      writer->write_attribute(attribute.first, std::int64_t{value});
    else
      writer->write_attribute(attribute.first, value);
  }, attribute.second);
}

void Recorder::Impl::write_file(Evaluation& e) {
  output::ResultsStep step{.time = e.state.time};
  if (options.nodes) step.configuration = &e.state.q;
  if (options.nodes && options.velocities) step.velocity = &e.state.velocity;
  Eigen::VectorXd lambda;
  if (multiplier_count > 0) {
    lambda = e.state.multipliers.head(multiplier_count);
    step.multipliers = &lambda;
  }
  for (std::size_t i = 0; i < scalars.size(); ++i)
    if (scalars[i].quantity.file) step.scalars.push_back(e.scalar(i));
  for (std::size_t i = 0; i < vectors.size(); ++i)
    if (vectors[i].quantity.file) step.probes.push_back(e.vector(i));
  step.centerlines = e.centerlines();
  if (options.centerline_fields)
    for (const Line& line : lines) step.centerline_fields.push_back({line.arc_length, line.velocities(e.state)});
  for (const ProfileEntry& profile : profiles) step.profiles.push_back(profile.values(e.state));
  writer->append(step);
}

void Recorder::Impl::write_csv(Evaluation& e) {
  std::vector<double> row{e.state.time};
  for (const CsvColumn& c : csv_columns) row.push_back(c.vector ? e.vector(c.index)(c.component) : e.scalar(c.index));
  csv->row(row);
}

void Recorder::Impl::write_snapshot(int k, Evaluation& e) {
  const std::vector<double>& labels = snapshot_specs[k].labels;
  const std::vector<Eigen::MatrixXd>& points = e.centerlines();
  for (std::size_t line = 0; line < points.size(); ++line)
    for (Eigen::Index i = 0; i < points[line].rows(); ++i) {
      std::vector<double> row{e.state.time, static_cast<double>(line)};
      if (!labels.empty()) row.push_back(labels[line]);
      row.insert(row.end(), {points[line](i, 0), points[line](i, 1), points[line](i, 2)});
      snapshot_files[k].row(row);
    }
}

void Recorder::Impl::record(const Channel& channel, Evaluation& e) {
  if (channel.file) write_file(e);
  if (channel.csv && csv) write_csv(e);  // a CSV only if columns were declared
  if (channel.snapshots >= 0) write_snapshot(channel.snapshots, e);
}

void Recorder::Impl::observe(long n, bool last) {
  const State state(integrator);
  Evaluation e(*this, state, true);
  for (Channel& channel : channels) {
    if (channel.sampler) {
      for (const solvers::Sample& sample : channel.sampler->update(integrator)) {
        const State at(integrator, sample);
        Evaluation sampled(*this, at, false);
        record(channel, sampled);
      }
    } else if (channel.schedule.due(n, state.time, options.time_step, last)) {
      record(channel, e);
    }
  }
  for (std::size_t i = 0; i < scalars.size(); ++i)
    if (scalars[i].quantity.every_step) e.scalar(i);
  for (std::size_t i = 0; i < vectors.size(); ++i)
    if (vectors[i].quantity.every_step) e.vector(i);
}

}  // namespace spar::study
