// suspended_beam — a beam pinned at both ends with a lumped mass sliding along it without
// friction under gravity, modelled with a sliding node on ALE-RANCF or ALE-ANCF elements and
// element length control (paper 000, Ding & Ouyang 2022, §6.2, Figures 13–14).
//
// Sample runs:
//   suspended_beam                                   (ALE-RANCF, 3 elements, h = 1e-3 s, 2 s)
//   suspended_beam --element ale-ancf
//   suspended_beam --elements 6 --h 5e-4 --out results/suspended_beam_6
//
// Description:
//   L = 1 m, circular section r = 0.01 m, ρ = 7200 kg/m³, E = 20 MPa, no damping (000 §6.1–6.2);
//   both ends pinned (positions fixed, slopes free); a 5 kg mass starts at rest 0.1 m from the
//   left end and slides towards the sag's bottom and beyond. The beam is straight at t = 0, so it
//   first falls and the mass slides as it sags. The sliding node carries the mass; the two
//   elements next to it are ALE, the others fixed length; when one of them passes 1.5 L_std a
//   node is inserted (exact) and the node beyond the other one deleted (merge: least-squares
//   weights for ALE-RANCF, unit weights for ALE-ANCF). After each event the integrator restarts
//   its accelerations. Written at every step: the energies, the deformed beam length, the slider's
//   material coordinate and position, and the centreline; at the end, the event log. ρ∞ = 1 by
//   default, so between events the total energy is conserved to the integrator's accuracy and the
//   jumps at the events are the merges'. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>

#include <cli.hpp>
#include <length_control_report.hpp>
#include <energy_balance.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "suspended_beam: a lumped mass sliding on a pinned-pinned beam (000 §6.2)");
  const std::string kind = cli.text("--element", "ale-rancf", "ale-rancf or ale-ancf", {"ale-rancf", "ale-ancf"});
  const int elements = cli.integer("--elements", 3, "elements", 3, examples::element_limit(examples::bytes_per_element));
  const double h = cli.number("--h", 1e-3, "time step [s]", examples::Range::positive());
  const double t_end = cli.number("--t-end", 2.0, "end time [s]", examples::Range::positive());
  const double rho_infinity = cli.number("--rho-inf", 1.0, "spectral radius at infinity (1: no dissipation)",
                                          examples::Range::between(0, 1));
  const std::string out = cli.output_folder("--out", "results/suspended_beam", "output folder");
  if (!cli.finish()) return 0;
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused

  // 2. The beam, the sliding mass and the supports.
  const double radius = 0.01, young = 20e6, density = 7200;
  const double area = std::numbers::pi * radius * radius, inertia = area * radius * radius / 4;
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = elements,
                                      .section = {.axial_stiffness = young * area,
                                                  .bending_stiffness = young * inertia,
                                                  .mass_per_length = density * area},
                                      .slider_position = 0.1, .slider_mass = 5.0,
                                      .rational = kind == "ale-rancf"});
  model.set_gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  std::vector<int> fixed = cable.fixed_dofs(model.state());
  for (int end : {cable.chain().front(), cable.chain().back()})
    for (int i = 0; i < 2; ++i) fixed.push_back(model.state().blocks[end].offset + i);
  std::sort(fixed.begin(), fixed.end());
  model.set_fixed_dofs(fixed);

  // 3. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = h, .spectral_radius = rho_infinity,
                                                   .tolerance = 1e-16, .residual_tolerance = 1e-9});
  integrator.initialize();

  // 4. Integrate, control the lengths, record.
  const int per_element = 10;
  core::ResultsWriter results(out + "/suspended_beam.h5",
                              {.node_count = 0, .velocities = false,
                               .scalars = examples::followed_by<core::ResultsQuantity>(
                                   {{.name = "total_energy", .unit = "J",
                                     .description = "kinetic + strain energy + gravity potential"},
                                    {.name = "beam_length", .unit = "m",
                                     .description = "the cable's current length (sum of element arc lengths)"},
                                    {.name = "slider_material_coordinate", .unit = "m",
                                     .description = "the sliding node's material coordinate (arc length from the left end)"},
                                    {.name = "newton_iterations", .unit = "1",
                                     .description = "Newton iterations (linear solves) of the step", .integer = true}},
                                   examples::energy_balance_layout()),
                               .probes = {{.name = "slider", .unit = "m", .description = "the sliding mass, inertial frame"}},
                               .centerline_points = {elements * per_element + 1}});
  results.write_attribute("example", "suspended_beam");
  results.write_attribute("element", kind);
  results.write_attribute("time_step", h);
  results.write_attribute("rho_infinity", rho_infinity);
  std::ofstream csv(out + "/suspended_beam.csv"), shapes(out + "/suspended_beam_shapes.csv");
  csv.precision(12);
  shapes.precision(12);
  csv << "t,kinetic_energy,strain_energy,gravity_potential,total_energy,beam_length,slider_material,"
         "slider_x,slider_y\n";
  shapes << "event,phase,x,y\n";  // centrelines just before (phase 0) and after (1) each event
  const double initial_energy = integrator.energies().total();
  double max_kinetic = 0.0, max_deviation = 0.0, max_jump = 0.0, segment_reference = initial_energy;
  double max_segment_drift = 0.0, min_ratio = 1e300, max_ratio = 0.0, control_seconds = 0.0;
  std::vector<core::LengthControlEvent> events;
  std::vector<double> deviations;
  const auto record = [&]() {
    const core::Configuration& q = model.state();
    const solvers::Energies energy = integrator.energies();
    const Eigen::Vector2d slider = q.vector(cable.chain()[cable.slider()]).head<2>();
    const double beam_length = cable.deformed_length(q), slider_material = q.vector(cable.materials()[cable.slider()])(0);
    csv << integrator.time() << ',' << energy.kinetic << ',' << energy.strain << ',' << energy.gravity << ','
        << energy.total() << ',' << beam_length << ',' << slider_material << ',' << slider.x() << ','
        << slider.y() << '\n';
    results.append({.time = integrator.time(),
                    .scalars = examples::followed_by<double>(
                        {energy.total(), beam_length, slider_material,
                         static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {Eigen::Vector3d(slider.x(), slider.y(), 0.0)},
                    .centerlines = {cable.sample_centerline(q, per_element)}});
  };
  record();
  const auto run_start = std::chrono::steady_clock::now();
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    const solvers::Energies energy = integrator.energies();
    max_kinetic = std::max(max_kinetic, energy.kinetic);
    deviations.push_back(energy.total() - initial_energy);
    max_segment_drift = std::max(max_segment_drift, std::fabs(energy.total() - segment_reference));
    // Length control, timed (000 Table 1's split: the event, the remap and the restart).
    const auto start = std::chrono::steady_clock::now();
    if (const std::optional<double> after =
            examples::control_length(cable, model, integrator, per_element, shapes, events)) {
      max_jump = std::max(max_jump, std::fabs(*after - energy.total()));
      segment_reference = *after;
    }
    control_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Element lengths over L_std, but for the two next to the slider while it is next to an end
    // element (no node left to delete on that side) and before the first event (initial mesh).
    const int s = cable.slider(), last = static_cast<int>(cable.chain().size()) - 1;
    if (!events.empty())
      for (int k = 0; k < elements; ++k) {
        if ((k == s - 1 || k == s) && (s - 1 == 0 || s + 1 == last)) continue;
        const double ratio = cable.element_length(model.state(), k) / cable.standard_length();
        min_ratio = std::min(min_ratio, ratio);
        max_ratio = std::max(max_ratio, ratio);
      }
    record();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
  for (double d : deviations) max_deviation = std::max(max_deviation, std::fabs(d));

  // 5. The event log and the weight statistics (000 Table 2: k_i of the merged elements).
  examples::write_length_control_log(results, events);
  results.close();
  const examples::WeightStatistics weights = examples::weight_statistics(events);

  // 6. Report.
  const solvers::DynamicCounters& counters = integrator.counters();
  const double slider_x = model.state().vector(cable.materials()[cable.slider()])(0);
  std::printf("suspended_beam, %s, %d elements, h = %g s, rho_inf = %g, t = %g s: %ld steps, %ld Newton "
              "iterations, %.3f s (length control %.4f s); %zu length-control events; slider at x = %.4f m; "
              "energy: max |E - E0| %.3e, max drift between events %.3e, largest jump %.3e of the largest "
              "kinetic energy %.4f J; merged weights: set %zu, max %.3f, min %.3f, sigma %.3f\n",
              kind.c_str(), elements, h, rho_infinity, integrator.time(), counters.steps,
              counters.newton_iterations, wall, control_seconds, events.size(), slider_x,
              max_deviation / max_kinetic, max_segment_drift / max_kinetic, max_jump / max_kinetic, max_kinetic,
              weights.count, weights.max, weights.min, weights.sigma);
  examples::JsonSummary()
      .add("elements", elements).add("element_kind", kind).add("h", h).add("rho_inf", rho_infinity)
      .add("t_end", integrator.time())
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
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
