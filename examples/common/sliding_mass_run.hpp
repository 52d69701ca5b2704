#pragma once
// The run of a lumped mass sliding on a pinned–pinned cable with length control (paper 000 §6.2
// and §6.3: suspended_beam, semicircular_beam): integrate, control the lengths after each step,
// record the energies, the deformed length, the slider and the centreline, and report Table 1's
// time split, Table 2's weight statistics and the energy balance in a JSON summary.
#include <spar/spar.hpp>

#include <cli.hpp>
#include <energy_balance.hpp>
#include <sliding_mass_options.hpp>
#include <length_control_report.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace spar::examples {

struct SlidingMassRun {
  std::string example;  ///< the file stem of the outputs, e.g. "suspended_beam"
  std::string out;      ///< the output folder
  SlidingMassOptions options;
  int per_element = 10;  ///< centreline samples per element
};

/// Pins both ends of `cable` (positions fixed, slopes free) besides the dofs the cable fixes itself.
inline void pin_both_ends(const core::SlidingCable<2>& cable, core::Model& model) {
  std::vector<int> fixed = cable.fixed_dofs(model.state());
  for (int end : {cable.chain().front(), cable.chain().back()})
    for (int i = 0; i < 2; ++i) fixed.push_back(model.state().blocks[end].offset + i);
  std::sort(fixed.begin(), fixed.end());
  model.set_fixed_dofs(fixed);
}

/// Integrates `integrator` (initialized) to run.t_end with `cable`'s length control after every
/// step; writes <example>.h5 (+ XDMF), <example>.csv and <example>_shapes.csv (the centrelines
/// just before and after each event) to run.out, prints a summary line and the JSON summary.
inline void run_sliding_mass(core::SlidingCable<2>& cable, core::Model& model,
                             solvers::GeneralizedAlpha& integrator, const SlidingMassRun& run) {
  core::ResultsWriter results(run.out + "/" + run.example + ".h5",
                              {.node_count = 0, .velocities = false,
                               .scalars = followed_by<core::ResultsQuantity>(
                                   {{.name = "total_energy", .unit = "J",
                                     .description = "kinetic + strain energy + gravity potential"},
                                    {.name = "beam_length", .unit = "m",
                                     .description = "the cable's current length (sum of element arc lengths)"},
                                    {.name = "slider_material_coordinate", .unit = "m",
                                     .description = "the sliding node's material coordinate (arc length from the left end)"},
                                    {.name = "newton_iterations", .unit = "1",
                                     .description = "Newton iterations (linear solves) of the step", .integer = true}},
                                   energy_balance_layout()),
                               .probes = {{.name = "slider", .unit = "m", .description = "the sliding mass, inertial frame"}},
                               .centerline_points = {run.options.elements * run.per_element + 1}});
  write_attributes(results, run.example, run.options);
  std::ofstream csv(run.out + "/" + run.example + ".csv"), shapes(run.out + "/" + run.example + "_shapes.csv");
  csv.precision(12);
  shapes.precision(12);
  csv << "t,kinetic_energy,strain_energy,gravity_potential,total_energy,beam_length,slider_material,"
         "slider_x,slider_y\n";
  shapes << "event,phase,x,y\n";  // centrelines just before (phase 0) and after (1) each event
  const double initial_energy = integrator.energies().total();
  double max_kinetic = 0.0, max_deviation = 0.0, max_jump = 0.0, segment_reference = initial_energy;
  double max_segment_drift = 0.0, min_ratio = 1e300, max_ratio = 0.0, control_seconds = 0.0;
  std::vector<core::LengthControlEvent> events;
  const auto record = [&]() {
    const core::Configuration& q = model.state();
    const solvers::Energies energy = integrator.energies();
    const Eigen::Vector2d slider = q.vector(cable.chain()[cable.slider()]).head<2>();
    const double beam_length = cable.deformed_length(q), slider_material = q.vector(cable.materials()[cable.slider()])(0);
    csv << integrator.time() << ',' << energy.kinetic << ',' << energy.strain << ',' << energy.gravity << ','
        << energy.total() << ',' << beam_length << ',' << slider_material << ',' << slider.x() << ','
        << slider.y() << '\n';
    results.append({.time = integrator.time(),
                    .scalars = followed_by<double>({energy.total(), beam_length, slider_material,
                                                    static_cast<double>(integrator.last_step_iterations())},
                                                   energy_balance_values(energy)),
                    .probes = {Eigen::Vector3d(slider.x(), slider.y(), 0.0)},
                    .centerlines = {cable.sample_centerline(q, run.per_element)}});
  };
  record();
  const auto run_start = std::chrono::steady_clock::now();
  while (integrator.time() < run.options.t_end - 0.5 * run.options.h) {
    integrator.step();
    const solvers::Energies energy = integrator.energies();
    max_kinetic = std::max(max_kinetic, energy.kinetic);
    max_deviation = std::max(max_deviation, std::fabs(energy.total() - initial_energy));
    max_segment_drift = std::max(max_segment_drift, std::fabs(energy.total() - segment_reference));
    // Length control, timed (000 Table 1's split: the event, the remap and the restart).
    const auto start = std::chrono::steady_clock::now();
    if (const std::optional<double> after = control_length(cable, model, integrator, run.per_element, shapes, events)) {
      max_jump = std::max(max_jump, std::fabs(*after - energy.total()));
      segment_reference = *after;
    }
    control_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Element lengths over L_std, but for the two next to the slider while it is next to an end
    // element (no node left to delete on that side) and before the first event (initial mesh).
    const int s = cable.slider(), last = static_cast<int>(cable.chain().size()) - 1;
    if (!events.empty())
      for (int k = 0; k < run.options.elements; ++k) {
        if ((k == s - 1 || k == s) && (s - 1 == 0 || s + 1 == last)) continue;
        const double ratio = cable.element_length(model.state(), k) / cable.standard_length();
        min_ratio = std::min(min_ratio, ratio);
        max_ratio = std::max(max_ratio, ratio);
      }
    record();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();

  // The event log and the weight statistics (000 Table 2: k_i of the merged elements).
  write_length_control_log(results, events);
  results.close();
  const WeightStatistics weights = weight_statistics(events);

  const solvers::DynamicCounters& counters = integrator.counters();
  const double slider_x = model.state().vector(cable.materials()[cable.slider()])(0);
  std::printf("%s, %s, %d elements, h = %g s, rho_inf = %g, t = %g s: %ld steps, %ld Newton iterations, %.3f s "
              "(length control %.4f s); %zu length-control events; slider at x = %.4f m; energy: max |E - E0| "
              "%.3e, max drift between events %.3e, largest jump %.3e of the largest kinetic energy %.4f J; "
              "merged weights: set %zu, max %.3f, min %.3f, sigma %.3f\n",
              run.example.c_str(), run.options.kind.c_str(), run.options.elements, run.options.h, run.options.rho_infinity,
              integrator.time(), counters.steps, counters.newton_iterations, wall, control_seconds, events.size(),
              slider_x, max_deviation / max_kinetic, max_segment_drift / max_kinetic, max_jump / max_kinetic,
              max_kinetic, weights.count, weights.max, weights.min, weights.sigma);
  JsonSummary()
      .add("elements", run.options.elements).add("element_kind", run.options.kind).add("h", run.options.h)
      .add("rho_inf", run.options.rho_infinity).add("strategy", run.options.strategy).add("t_end", integrator.time())
      .add("length_control_events", static_cast<int>(events.size()))
      .add("min_element_length_ratio", events.empty() ? 0.0 : min_ratio)
      .add("max_element_length_ratio", events.empty() ? 0.0 : max_ratio)
      .add("max_energy_drift", max_deviation / max_kinetic)
      .add("max_drift_between_events", max_segment_drift / max_kinetic)
      .add("max_merge_energy_jump", max_jump / max_kinetic)
      .add("weight_set_size", static_cast<int>(weights.count))
      .add("weight_max", weights.max).add("weight_min", weights.min).add("weight_sigma", weights.sigma)
      .add("slider_material_coordinate", slider_x)
      .add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("motion_time_s", wall - control_seconds).add("length_control_time_s", control_seconds)
      .add("wall_s", wall)
      .print();
}

}  // namespace spar::examples
