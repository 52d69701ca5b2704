// falling_beam — a cantilever falling under gravity with a lumped mass sliding along it without
// friction until it leaves the free end, modelled with a sliding node on ALE-RANCF or ALE-ANCF
// elements and element length control (paper 000, Ding & Ouyang 2022, §6.1, Figures 8–12,
// Tables 1–2).
//
// Sample runs:
//   falling_beam                                     (ALE-RANCF, 20 elements, h = 1e-3 s, 1 s)
//   falling_beam --element ale-ancf --elements 5
//   falling_beam --elements 40 --h 5e-4 --out results/falling_beam_40
//
// Description:
//   L = 1 m, circular section r = 0.01 m, ρ = 7200 kg/m³, E = 20 MPa, no damping; left end
//   clamped, right end free; a 0.8 kg mass starts 0.1 m from the left end, sliding at 0.4 m/s
//   along the beam, which is straight and at rest at t = 0. Gravity (0, −9.81) m/s². The sliding
//   node carries the mass; the two elements next to it are ALE, the others fixed length; when one
//   of them passes 1.5 L_std a node is inserted (exact) and the node beyond the other one deleted
//   (merge: least-squares weights for ALE-RANCF, unit weights for ALE-ANCF). When the element
//   between the mass and the free end is shorter than 0.05 L_std (or than four steps of its travel)
//   the mass leaves the beam and flies
//   on as a free particle (core::SlidingCable::release). After each event the integrator restarts
//   its accelerations. Written every step: the energies, the right end, the slider (or the free
//   mass), the centreline; at the end, the event log. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>

#include <cli.hpp>
#include <sliding_mass_options.hpp>
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
  examples::CommandLine cli(argc, argv, "falling_beam: a lumped mass sliding off a falling cantilever (000 §6.1)");
  const examples::SlidingMassOptions o = examples::sliding_mass_options(cli, 20, 1.0, examples::memory_use::falling_beam);
  const std::string out = cli.output_folder("--out", "results/falling_beam", "output folder");
  if (!cli.finish()) return 0;
  examples::time_steps(o.h, o.t_end);  // a span of no steps or of too many is refused

  // 2. The beam, the sliding mass (and the block it flies off in) and the clamp.
  const double radius = 0.01, young = 20e6, density = 7200;
  const double area = std::numbers::pi * radius * radius, inertia = area * radius * radius / 4;
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = o.elements,
                                      .section = {.axial_stiffness = young * area,
                                                  .bending_stiffness = young * inertia,
                                                  .mass_per_length = density * area},
                                      .slider_position = 0.1, .slider_mass = 0.8,
                                      .rational = o.kind == "ale-rancf", .detachable = true});
  model.set_gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  const auto set_fixed = [&]() {
    std::vector<int> fixed = cable.fixed_dofs(model.state());
    for (int i = 0; i < 4; ++i) fixed.push_back(model.state().blocks[cable.chain().front()].offset + i);
    std::sort(fixed.begin(), fixed.end());
    model.set_fixed_dofs(fixed);
  };
  set_fixed();

  // 3. The integrator; the mass slides at 0.4 m/s relative to the beam at rest (ṙ = ẋ r_x).
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = o.h, .spectral_radius = o.rho_infinity,
                                                   .iteration_matrix = solvers::iteration_matrix_from_string(o.strategy),
                                                   .tolerance = 1e-16, .residual_tolerance = 1e-9});
  integrator.set_velocity(cable.chain()[cable.slider()], Eigen::Vector4d(0.4, 0.0, 0.0, 0.0));
  integrator.set_velocity(cable.materials()[cable.slider()], Eigen::VectorXd::Constant(1, 0.4));
  integrator.initialize();
  double separation_time = -1.0, support_time = -1.0;

  // 4. Integrate, control the lengths, record.
  const int per_element = 10;
  core::ResultsWriter results(out + "/falling_beam.h5",
                              {.node_count = 0, .velocities = false,
                               .scalars = examples::followed_by<core::ResultsQuantity>(
                                   {{.name = "total_energy", .unit = "J",
                                     .description = "kinetic + strain energy + gravity potential"},
                                    {.name = "beam_length", .unit = "m",
                                     .description = "the cable's current length (sum of element arc lengths)"},
                                    {.name = "slider_material_coordinate", .unit = "m",
                                     .description = "the sliding node's material coordinate (arc length from the left end)",
                                     .may_be_undefined = true},
                                    {.name = "newton_iterations", .unit = "1",
                                     .description = "Newton iterations (linear solves) of the step", .integer = true}},
                                   examples::energy_balance_layout()),
                               .probes = {{.name = "mass", .unit = "m", .description = "the sliding mass, inertial frame"},
                                          {.name = "right_end", .unit = "m", .description = "the beam's free end"}},
                               .centerline_points = {o.elements * per_element + 1}});
  examples::write_attributes(results, "falling_beam", o);
  std::ofstream csv(out + "/falling_beam.csv"), shapes(out + "/falling_beam_shapes.csv");
  csv.precision(12);
  shapes.precision(12);
  csv << "t,kinetic_energy,strain_energy,gravity_potential,total_energy,beam_length,slider_material,"
         "mass_x,mass_y,right_end_x,right_end_y\n";
  shapes << "event,phase,x,y\n";  // centrelines just before (phase 0) and after (1) each event
  const double initial_energy = integrator.energies().total();
  double max_kinetic = 0.0, max_deviation = 0.0, max_jump = 0.0, segment_reference = initial_energy;
  double max_segment_drift = 0.0, min_ratio = 1e300, max_ratio = 0.0, control_seconds = 0.0;
  std::vector<core::LengthControlEvent> events;
  std::vector<double> deviations;
  // The centreline at a constant number of points (after the mass leaves, the cable has one
  // element less: its last point is repeated).
  const auto centerline = [&](const core::Configuration& q) {
    Eigen::MatrixXd points = cable.sample_centerline(q, per_element);
    const Eigen::Index rows = points.rows();
    points.conservativeResize(o.elements * per_element + 1, 3);
    for (Eigen::Index i = rows; i < points.rows(); ++i) points.row(i) = points.row(rows - 1);
    return points;
  };
  const auto record = [&]() {
    const core::Configuration& q = model.state();
    const solvers::Energies energy = integrator.energies();
    const Eigen::Vector2d slider = cable.released() ? Eigen::Vector2d(q.vector(cable.particle()))
                                                    : Eigen::Vector2d(q.vector(cable.chain()[cable.slider()]).head<2>());
    const Eigen::Vector2d end = q.vector(cable.chain().back()).head<2>();
    const double beam_length = cable.deformed_length(q);
    const double slider_material = cable.released() ? std::nan("") : q.vector(cable.materials()[cable.slider()])(0);
    csv << integrator.time() << ',' << energy.kinetic << ',' << energy.strain << ',' << energy.gravity << ','
        << energy.total() << ',' << beam_length << ',' << slider_material << ',' << slider.x() << ','
        << slider.y() << ',' << end.x() << ',' << end.y() << '\n';
    results.append({.time = integrator.time(),
                    .scalars = examples::followed_by<double>(
                        {energy.total(), beam_length, slider_material,
                         static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {Eigen::Vector3d(slider.x(), slider.y(), 0.0), Eigen::Vector3d(end.x(), end.y(), 0.0)},
                    .centerlines = {centerline(q)}});
  };
  record();
  const auto run_start = std::chrono::steady_clock::now();
  while (integrator.time() < o.t_end - 0.5 * o.h) {
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
    // Departure: the element to the free end is shorter than 0.1 L_std, or than four steps of
    // the slider's travel (SlidingCable::release_length).
    const double slider_rate =
        cable.released() ? 0.0 : integrator.velocity()(model.state().blocks[cable.materials()[cable.slider()]].offset);
    const double min_length = cable.release_length(o.h, slider_rate);
    if (!cable.released() && cable.near_end(model.state(), 0, min_length)) {
      // The mass has slid back to the clamp: a collision this model does not have. Stop here.
      support_time = integrator.time();
      std::printf("t = %.4f s: the mass reached the clamped end; the run stops\n", support_time);
      record();
      break;
    }
    if (!cable.released() && cable.near_end(model.state(), static_cast<int>(cable.chain().size()) - 1, min_length)) {
      const double before_release = integrator.energies().total();
      Eigen::MatrixXd P;
      cable.release(model, P);
      set_fixed();
      integrator.remap(P);
      integrator.initialize();
      separation_time = integrator.time();
      const double after = integrator.energies().total();
      max_jump = std::max(max_jump, std::fabs(after - before_release));
      segment_reference = after;
      std::printf("t = %.4f s: the mass leaves the beam (energy change %.3e J)\n", separation_time,
                  after - before_release);
    }
    control_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Element lengths over L_std, but for the two next to the slider while it is next to an end
    // element (no node left to delete on that side) and before the first event (initial mesh).
    const int s = cable.slider(), last = static_cast<int>(cable.chain().size()) - 1;
    if (!events.empty() && !cable.released())
      for (int k = 0; k < static_cast<int>(cable.chain().size()) - 1; ++k) {
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
  std::printf("falling_beam, %s, %d elements, h = %g s, rho_inf = %g, t = %g s: %ld steps, %ld Newton "
              "iterations, %.3f s (length control %.4f s); %zu length-control events; "
              "energy: max |E - E0| %.3e, max drift between events %.3e, largest jump %.3e of the largest "
              "kinetic energy %.4f J; merged weights: set %zu, max %.3f, min %.3f, sigma %.3f; the mass left at t = %.4f s\n",
              o.kind.c_str(), o.elements, o.h, o.rho_infinity, integrator.time(), counters.steps,
              counters.newton_iterations, wall, control_seconds, events.size(),
              max_deviation / max_kinetic, max_segment_drift / max_kinetic, max_jump / max_kinetic, max_kinetic,
              weights.count, weights.max, weights.min, weights.sigma, separation_time);
  examples::JsonSummary()
      .add("elements", o.elements).add("element_kind", o.kind).add("h", o.h).add("rho_inf", o.rho_infinity)
      .add("strategy", o.strategy)
      .add("t_end", integrator.time())
      .add("length_control_events", static_cast<int>(events.size()))
      .add("min_element_length_ratio", events.empty() ? 0.0 : min_ratio)
      .add("max_element_length_ratio", events.empty() ? 0.0 : max_ratio)
      .add("max_energy_drift", max_deviation / max_kinetic)
      .add("max_drift_between_events", max_segment_drift / max_kinetic)
      .add("max_merge_energy_jump", max_jump / max_kinetic)
      .add("weight_set_size", static_cast<int>(weights.count))
      .add("weight_max", weights.max).add("weight_min", weights.min).add("weight_sigma", weights.sigma)
      .add("separation_time", separation_time).add("support_reached_time", support_time)
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
