#pragma once
// A lumped mass sliding on an ALE-RANCF / ALE-ANCF cable with length control (paper 000 §5–6:
// falling_beam, suspended_beam, semicircular_beam): the options the three share, the supports,
// and the run — integrate, control the lengths after each step (000 §5), release the mass at a
// free end (falling_beam), record the energies, the deformed length, the mass and the centreline,
// and report Table 1's time split, Table 2's weight statistics and the energy balance.
#include <spar/spar.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace spar::examples {

struct SlidingMassOptions {
  std::string example;  ///< the file stem of the outputs, e.g. "suspended_beam"
  std::string out;      ///< the output folder
  std::string kind;     ///< ale-rancf | ale-ancf
  int elements = 0;
  study::Integration run;  ///< h, t_end, ρ∞, the iteration matrix; Newton's increment at 1e-16, the residual at 1e-9
};

/// An example's defaults.
struct SlidingMassDefaults {
  std::string example;  ///< its name: the output folder is results/<example>
  int elements = 0;
  double t_end = 0.0;
  study::MemoryUse memory;  ///< what its run needs (examples/common/memory_use.hpp)
};

/// Reads --element, --elements (at most what the memory lets fit), --h, --t-end, --rho-inf,
/// --strategy and --out with the example's defaults.
inline SlidingMassOptions sliding_mass_options(study::CommandLine& cli, const SlidingMassDefaults& defaults) {
  SlidingMassOptions o{.example = defaults.example};
  o.kind = cli.text("--element", "ale-rancf", "ale-rancf or ale-ancf", {"ale-rancf", "ale-ancf"});
  o.elements = cli.elements("--elements", defaults.elements, "elements", 3, defaults.memory);
  o.run = study::integrator_options(
      cli, {.time_step = 1e-3, .spectral_radius = 1.0, .tolerance = 1e-16, .residual_tolerance = 1e-9},
      {.end_time = defaults.t_end});
  o.out = cli.output_folder("--out", "results/" + defaults.example, "output folder");
  return o;
}

struct SlidingMassRun {
  SlidingMassOptions options;
  core::CableSupports supports;
  /// The mass's initial speed along the straight cable at rest (m/s): ṙ = ẋ r_x, r_x = (1, 0).
  double slider_speed = 0.0;
  int per_element = 10;  ///< centreline samples per element
};

/// Under gravity 9.81 m/s² along −Y, with `run.supports` and `constraints`, integrates from rest
/// (but for the slider's speed) to t_end with `cable`'s length control after every step and, for a
/// cable with a reserved particle block, the mass's release at the free end (the run stops if it
/// slides back to the clamp instead); writes <example>.h5 (+ XDMF), <example>.csv and
/// <example>_shapes.csv (the centrelines just before and after each event) and prints the summary.
inline void run_sliding_mass(core::Model& model, core::SlidingCable<2>& cable, solvers::ConstraintList constraints,
                             const SlidingMassRun& run) {
  const SlidingMassOptions& o = run.options;
  const double h = o.run.dynamics.time_step, rho_infinity = o.run.dynamics.spectral_radius;
  model.set_gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  cable.fix_supports(model, run.supports);
  solvers::GeneralizedAlpha integrator(model, std::move(constraints), o.run.dynamics);
  if (run.slider_speed != 0.0) {
    integrator.set_velocity(cable.chain()[cable.slider()], Eigen::Vector4d(run.slider_speed, 0.0, 0.0, 0.0));
    integrator.set_velocity(cable.materials()[cable.slider()], Eigen::VectorXd::Constant(1, run.slider_speed));
  }
  integrator.initialize();
  const bool detachable = cable.particle() >= 0;
  const int points = o.elements * run.per_element + 1;
  study::Recorder rec(integrator, {.folder = o.out, .name = o.example, .time_step = h, .csv_digits = 12});
  rec.attributes({{"example", o.example}, {"element", o.kind}, {"rho_infinity", rho_infinity}, {"strategy", o.run.strategy}});
  //    The centreline at a constant number of points (after the mass leaves, the cable has one
  //    element less: its last point is repeated).
  rec.centerline(points, [&](const study::State& s) { return cable.sample_centerline(s.q, run.per_element, points); });
  rec.energy_balance();
  rec.total_energy();
  rec.scalar({.name = "beam_length", .unit = "m", .description = "the cable's current length (sum of element arc lengths)"},
             [&](const study::State& s) { return cable.deformed_length(s.q); });
  rec.scalar({.name = "slider_material_coordinate", .unit = "m",
              .description = "the sliding node's material coordinate (arc length from the left end)",
              .csv = "slider_material", .may_be_undefined = detachable},
             [&](const study::State& s) { return cable.slider_coordinate(s.q); });
  rec.newton_iterations();
  rec.vector({.name = detachable ? "mass" : "slider", .unit = "m", .description = "the sliding mass, inertial frame",
              .csv = detachable ? "mass_x,mass_y" : "slider_x,slider_y"},
             [&](const study::State& s) -> Eigen::Vector2d { return cable.mass_position(s.q); });
  std::vector<std::string> columns = {"kinetic_energy", "strain_energy", "gravity_potential", "total_energy",
                                      "beam_length", "slider_material", detachable ? "mass" : "slider"};
  if (detachable) {
    rec.vector({.name = "right_end", .unit = "m", .description = "the beam's free end", .csv = "right_end_x,right_end_y"},
               [&](const study::State& s) -> Eigen::Vector2d { return s.q.vector(cable.chain().back()).head<2>(); });
    columns.push_back("right_end");
  }
  rec.csv(columns);
  output::CsvFile shapes(o.out + "/" + o.example + "_shapes.csv", "event,phase,x,y", 12);
  const auto write_shape = [&](std::size_t event, int phase, const Eigen::MatrixXd& x) {
    for (Eigen::Index i = 0; i < x.rows(); ++i) shapes.row({static_cast<double>(event), double(phase), x(i, 0), x(i, 1)});
  };

  //    After each step: the energy account (drift, drift between events, jumps at the events and
  //    the release), the length control (000 Table 1's split: the event, the remap and the
  //    restart, timed), the release, and the controlled element lengths over L_std
  //    (SlidingCable::controlled_length_ratios) but before the first event (initial mesh).
  study::EnergyLedger energy(integrator);
  double min_ratio = 1e300, max_ratio = 0.0, control_seconds = 0.0, separation_time = -1.0, support_time = -1.0;
  std::vector<core::LengthControlEvent> events;
  const auto each_step = [&] {
    energy.after_step();
    const auto start = std::chrono::steady_clock::now();
    Eigen::MatrixXd P;
    const Eigen::MatrixXd before = cable.sample_centerline(model.state(), run.per_element);
    if (const std::optional<core::LengthControlEvent> event = cable.control_length(model, integrator.time(), P)) {
      write_shape(events.size(), 0, before);
      write_shape(events.size(), 1, cable.sample_centerline(model.state(), run.per_element));
      events.push_back(*event);
      energy.restart(P);
      std::printf("t = %.4f s: %s; merged weights (%.4f, %.4f, %.4f)%s\n", event->time, event->description.c_str(),
                  event->merged_weights(0), event->merged_weights(1), event->merged_weights(2),
                  event->merge_fallback ? " (fallback k = 1)" : event->merge_bounded ? " (bounded)" : "");
    }
    if (detachable && !cable.released()) {  // the element to an end shorter than SlidingCable::release_length
      const double rate = integrator.velocity()(model.state().blocks[cable.materials()[cable.slider()]].offset);
      const double min_length = cable.release_length(h, rate);
      if (cable.near_end(model.state(), 0, min_length)) {  // back at the clamp: a collision this model lacks
        support_time = integrator.time();
        std::printf("t = %.4f s: the mass reached the clamped end; the run stops\n", support_time);
        return;
      }
      if (cable.near_end(model.state(), static_cast<int>(cable.chain().size()) - 1, min_length)) {
        P.resize(0, 0);
        cable.release(model, P);
        cable.fix_supports(model, run.supports);
        separation_time = integrator.time();
        std::printf("t = %.4f s: the mass leaves the beam (energy change %.3e J)\n", separation_time,
                    energy.restart(P));
      }
    }
    control_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!events.empty() && !cable.released()) {
      const auto [shortest, longest] = cable.controlled_length_ratios(model.state());
      min_ratio = std::min(min_ratio, shortest);
      max_ratio = std::max(max_ratio, longest);
    }
  };
  rec.run(o.run.end_time, {.each_step = each_step, .stop_when = [&] { return support_time >= 0.0; }});
  if (!events.empty())
    rec.constant("length_control_events", core::length_control_log(events), "s, 1",
                 "one row per length-control event: time (s), the grown element, then the weights before and after "
                 "(docs/rancf.md, the columns in the example's README)");
  rec.close();
  shapes.close();

  const core::WeightStatistics weights = core::weight_statistics(events);
  const double wall = rec.wall_seconds();
  output::JsonSummary summary;
  summary.add("elements", o.elements).add("element_kind", o.kind).add("h", h).add("rho_inf", rho_infinity)
      .add("strategy", o.run.strategy).add("t_end", integrator.time())
      .add("length_control_events", static_cast<int>(events.size()))
      .add("min_element_length_ratio", events.empty() ? 0.0 : min_ratio)
      .add("max_element_length_ratio", events.empty() ? 0.0 : max_ratio)
      .add("max_energy_drift", energy.max_drift() / energy.max_kinetic())
      .add("max_drift_between_events", energy.max_drift_between_restarts() / energy.max_kinetic())
      .add("max_merge_energy_jump", energy.max_jump() / energy.max_kinetic())
      .add("weight_set_size", static_cast<int>(weights.count))
      .add("weight_max", weights.max).add("weight_min", weights.min).add("weight_sigma", weights.sigma);
  if (detachable)
    summary.add("separation_time", separation_time).add("support_reached_time", support_time);
  else
    summary.add("slider_material_coordinate", cable.slider_coordinate(model.state()));
  summary.add("steps", integrator.counters().steps).add("newton_iterations", integrator.counters().newton_iterations)
      .add("motion_time_s", wall - control_seconds).add("length_control_time_s", control_seconds).add("wall_s", wall)
      .print();
}

}  // namespace spar::examples
