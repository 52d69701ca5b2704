// sliding_beam — the eccentric sliding beam of 003 §5.2 (Table 3, Figures 4–6; Sugiyama et al.
// 2003): a flexible beam carrying a tip mass slides down a flexible carrier beam.
//
// Sample runs:
//   sliding_beam                                   (16 + 2 quadratic elements, h = 1e-3 s, update)
//   sliding_beam --elements 32 --h 5e-4            (a convergence-study run)
//   sliding_beam --degree 3 --elements 64 --sliding-elements 8 --h 5e-4
//   sliding_beam --strategy frozen --out results/sliding_beam_frozen
//
// Description:
//   The carrier beam runs from A = (0, 3, 1) to B = (0, 0, 0) m and is held at both ends by
//   spherical joints to the ground. The sliding beam runs from A to M = (1, 3, 1) m; its end at A
//   slides along the carrier's centerline (a frictionless sliding joint, 003 §4: a point on the
//   carrier at the coordinate ζ, its rotation free), and a 1 kg point mass sits at M (a rigid
//   body joined to the sliding beam's tip by a spherical joint, so its own rotation carries no
//   load). Both beams: 0.01 × 0.01 m, E = 2e8 Pa, ν = 0.3, ρ = 800 kg/m³, quadratic C¹ NURBS
//   (003: 16 and 2 elements; `--degree 3` for cubic C² ones). Everything starts straight and at rest; gravity 9.81 m/s² along −Z
//   pulls the mass down and the slider down the carrier. The run stops when the slider reaches B
//   (an end stop at ζ = L locks the joint; 003: t = 1.306 s) and reports the arrival time,
//   which the integrator locates inside the step (DynamicOptions::locate_events). It writes the mass's trajectory
//   (003 Figure 6: X–Z and Y–Z), both beams' centerlines every 0.1 s (Figure 5) and the HDF5
//   time histories. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>

#include <memory_use.hpp>

#include "sliding_beam_model.hpp"

#include <optional>
#include <string>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "sliding_beam: the eccentric sliding beam of 003 section 5.2");
  const study::Integration run = study::integrator_options(
      cli, {.time_step = 1e-3, .tolerance = 1e-12, .constraint_tolerance = 1e-10, .residual_tolerance = 1e-8},
      {.end_time = 3.0, .end_time_help = "end time if the slider has not reached B by then [s]",
       .newton = study::NewtonOptions::tolerance});
  const double h = run.dynamics.time_step;
  const int elements = cli.elements("--elements", 16, "NURBS elements of the carrier beam", 1, examples::memory_use::sliding_beam);
  const int sliding_elements = cli.elements("--sliding-elements", 2, "NURBS elements of the sliding beam", 1,
                                            examples::memory_use::sliding_beam);
  const int degree = cli.integer("--degree", 2, "NURBS degree of both beams (003: 2)", 1, iga::max_degree);
  const std::string out = cli.output_folder("--out", "results/sliding_beam", "output folder");
  if (!cli.finish()) return 0;
  study::require_memory(static_cast<double>(elements) + sliding_elements, examples::memory_use::sliding_beam,
                        "options --elements, --sliding-elements");  // the two beams together

  // 2. Build the model of 003 Table 3 (examples/sliding_beam/sliding_beam_model.hpp): the two
  //    beams, the tip mass, gravity, the carrier's pins at A and B, the mass's pin at M and the
  //    sliding joint of the sliding beam's end along the carrier, locking at B.
  examples::SlidingBeam setup = examples::build_sliding_beam(elements, sliding_elements, degree);
  core::Model& model = setup.model;
  const core::GeometricallyExactBeam& carrier = core::beam(model, setup.carrier);
  const core::GeometricallyExactBeam& sliding = core::beam(model, setup.sliding);
  const int mass = setup.mass_node;
  const joints::SlidingJoint& slide = *setup.slide;
  const int zeta_block = slide.zeta_block();

  // 3. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(model, std::move(setup.joints), run.dynamics);
  integrator.initialize();

  // 4. Integrate until the slider locks at B, recording every step (docs/output.md), both beams'
  //    centerlines every 0.1 s (003 Figure 5).
  const int carrier_samples = 8 * elements + 1, sliding_samples = 16 * sliding_elements + 1;
  study::Recorder rec(integrator, {.folder = out, .name = "sliding_beam", .time_step = h, .nodes = true,
                                   .multipliers = true, .csv_digits = 12});
  rec.attributes({{"example", "sliding_beam"}, {"carrier_elements", elements}, {"strategy", run.strategy}});
  rec.centerline(carrier_samples, [&](const study::State& s) { return carrier.sample_centerline(s.q, carrier_samples); });
  rec.centerline(sliding_samples, [&](const study::State& s) { return sliding.sample_centerline(s.q, sliding_samples); });
  rec.snapshots({.file = "sliding_beam_snapshots.csv", .header = "t,beam,x,y,z",
                 .schedule = study::Schedule::every_interval(0.1)});
  rec.scalar({.name = "zeta", .unit = "m",
              .description = "the slider's coordinate on the carrier, from A (curve parameter scaled to the carrier's "
                             "reference length)"},
             [&](const study::State& s) { return s.q.values(s.q.blocks[zeta_block].offset); });
  rec.scalar({.name = "zeta_rate", .unit = "m/s", .description = "d zeta / dt"},
             [&](const study::State& s) { return s.velocity(s.q.blocks[zeta_block].offset); });
  const study::Vector mass_position = rec.vector(
      {.name = "mass", .unit = "m", .description = "the tip mass M, inertial frame", .csv = "mass_x,mass_y,mass_z"},
      study::node_position(mass));
  rec.vector({.name = "slider", .unit = "m", .description = "the sliding point on the carrier, inertial frame",
              .csv = "slider_x,slider_y,slider_z"},
             [&](const study::State& s) { return sliding.position_at(s.q, 0.0); });
  rec.energy_balance();
  const study::Scalar residual = rec.constraint_residual();
  rec.newton_iterations();
  rec.csv({"zeta", "zeta_rate", "mass", "slider", "kinetic_energy", "strain_energy", "gravity_potential",
           "numerical_dissipation", "constraint_residual", "newton_iterations"});
  //    The integrator locates the arrival inside the step (the slider within 1 µm past B,
  //    DynamicOptions::event_tolerance), locks the joint there and finishes the step.
  rec.run(run.end_time, {.stop_when = [&] { return slide.locked(); }});
  const std::optional<double> arrival_time = slide.locked() ? std::optional(slide.lock_time()) : std::nullopt;
  if (arrival_time) rec.attributes({{"arrival_time", *arrival_time}});
  rec.events("the slider entering carrier elements, the lock at B");
  rec.close();

  // 5. The summary.
  const Eigen::Vector3d mass_final = mass_position.last();
  rec.summary()
      .add("arrival_time", arrival_time)
      .add("h", h).add("elements", elements).add("sliding_elements", sliding_elements).add("degree", degree)
      .add("strategy", run.strategy).add("max_constraint_residual", residual.max())
      .add("mass_x", mass_final.x()).add("mass_y", mass_final.y()).add("mass_z", mass_final.z())
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
