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
#include <spar/joints/joints.hpp>

#include <cli.hpp>
#include <energy_balance.hpp>

#include "sliding_beam_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "sliding_beam: the eccentric sliding beam of 003 section 5.2");
  const double h = cli.number("--h", 1e-3, "time step [s]", examples::Range::positive());
  const double t_end = cli.number("--t-end", 3.0, "end time if the slider has not reached B by then [s]",
                                 examples::Range::positive());
  const int elements = cli.elements("--elements", 16, "NURBS elements of the carrier beam", 1, examples::memory_use::sliding_beam);
  const int sliding_elements = cli.elements("--sliding-elements", 2, "NURBS elements of the sliding beam", 1,
                                            examples::memory_use::sliding_beam);
  const int degree = cli.integer("--degree", 2, "NURBS degree of both beams (003: 2)", 1, iga::max_degree);
  const std::string strategy = cli.text("--strategy", "update", "iteration matrix: update | frozen | modified",
                                          {"update", "frozen", "modified"});
  const double rho_infinity = cli.number("--rho-inf", 0.9, "spectral radius at infinity", examples::Range::between(0, 1));
  const double tolerance = cli.number("--tolerance", 1e-12, "Newton: |[dq, h^2 beta dlambda]|^2",
                                        examples::newton_tolerances);
  const std::string out = cli.output_folder("--out", "results/sliding_beam", "output folder");
  if (!cli.finish()) return 0;
  examples::require_memory(static_cast<double>(elements) + sliding_elements, examples::memory_use::sliding_beam,
                           "options --elements, --sliding-elements");  // the two beams together
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused

  // 2. Build the model of 003 Table 3 (examples/sliding_beam/sliding_beam_model.hpp): the two
  //    beams, the tip mass, gravity, the carrier's pins at A and B, the mass's pin at M and the
  //    sliding joint of the sliding beam's end along the carrier, locking at B.
  examples::SlidingBeam setup = examples::build_sliding_beam(elements, sliding_elements, degree);
  core::Model& model = setup.model;
  const core::GeometricallyExactBeam& carrier = model.beam(setup.carrier);
  const core::GeometricallyExactBeam& sliding = model.beam(setup.sliding);
  const int mass = setup.mass_node;
  const joints::SlidingJoint& slide = *setup.slide;
  const int zeta_block = slide.zeta_block();

  // 3. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(
      model, std::move(setup.joints),
      {.time_step = h, .spectral_radius = rho_infinity,
       .iteration_matrix = solvers::iteration_matrix_from_string(strategy), .tolerance = tolerance,
       .constraint_tolerance = 1e-10, .residual_tolerance = 1e-8});
  integrator.initialize();
  const auto zeta = [&] { return model.state().vector(zeta_block)(0); };
  const auto zeta_rate = [&] { return integrator.velocity()(model.state().blocks[zeta_block].offset); };

  // 4. Integrate until the slider locks at B, recording every step.
  const int carrier_samples = 8 * elements + 1, sliding_samples = 16 * sliding_elements + 1;
  core::ResultsWriter results(out + "/sliding_beam.h5",
                              {.node_count = model.block_count(), .velocities = false,
                               .multiplier_count = integrator.multiplier_count(),
                               .scalars = examples::followed_by<core::ResultsQuantity>(
                                   {{.name = "zeta", .unit = "m",
                                     .description = "the slider's coordinate on the carrier, from A (curve parameter "
                                                    "scaled to the carrier's reference length)"},
                                    {.name = "zeta_rate", .unit = "m/s", .description = "d zeta / dt"},
                                    {.name = "constraint_residual", .unit = "m",
                                     .description = "largest constraint violation |Phi|_inf after the step"},
                                    {.name = "newton_iterations", .unit = "1",
                                     .description = "Newton iterations (linear solves) of the step", .integer = true}},
                                   examples::energy_balance_layout()),
                               .probes = {{.name = "mass", .unit = "m", .description = "the tip mass M, inertial frame"},
                                          {.name = "slider", .unit = "m",
                                           .description = "the sliding point on the carrier, inertial frame"}},
                               .centerline_points = {carrier_samples, sliding_samples}});
  results.write_attribute("example", "sliding_beam");
  results.write_attribute("time_step", h);
  results.write_attribute("carrier_elements", elements);
  results.write_attribute("strategy", strategy);
  std::ofstream csv(out + "/sliding_beam.csv");
  csv.precision(12);
  csv << "t,zeta,zeta_rate,mass_x,mass_y,mass_z,slider_x,slider_y,slider_z,kinetic_energy,strain_energy,"
         "gravity_potential,numerical_dissipation,constraint_residual,newton_iterations\n";
  std::ofstream snapshots(out + "/sliding_beam_snapshots.csv");
  snapshots.precision(9);
  snapshots << "t,beam,x,y,z\n";
  double max_residual = 0.0, next_snapshot = 0.0;
  //    The multipliers of the free slider (the lock adds a 13th at the last step, which the
  //    file's fixed layout leaves out).
  const int multiplier_count = integrator.multiplier_count();
  Eigen::VectorXd multipliers(multiplier_count);
  const auto record = [&] {
    const core::Configuration& q = model.state();
    const solvers::Energies energy = integrator.energies();
    const double residual = integrator.constraint_residual();
    max_residual = std::max(max_residual, residual);
    const Eigen::Vector3d mass_position = q.position[mass], slider_position = sliding.position_at(q, 0.0);
    const Eigen::MatrixXd carrier_line = carrier.sample_centerline(q, carrier_samples);
    const Eigen::MatrixXd sliding_line = sliding.sample_centerline(q, sliding_samples);
    csv << integrator.time() << ',' << zeta() << ',' << zeta_rate() << ',' << mass_position.x() << ','
        << mass_position.y() << ',' << mass_position.z() << ',' << slider_position.x() << ','
        << slider_position.y() << ',' << slider_position.z() << ',' << energy.kinetic << ',' << energy.strain
        << ',' << energy.gravity << ',' << energy.numerical_dissipation << ',' << residual << ','
        << integrator.last_step_iterations() << '\n';
    if (integrator.time() >= next_snapshot - 0.25 * h) {  // 003 Figure 5: every 0.1 s
      for (int k = 0; k < 2; ++k) {
        const Eigen::MatrixXd& line = k == 0 ? carrier_line : sliding_line;
        for (Eigen::Index i = 0; i < line.rows(); ++i)
          snapshots << integrator.time() << ',' << k << ',' << line(i, 0) << ',' << line(i, 1) << ','
                    << line(i, 2) << '\n';
      }
      next_snapshot += 0.1;
    }
    multipliers = integrator.multipliers().head(multiplier_count);
    results.append({.time = integrator.time(), .configuration = &q, .velocity = nullptr,
                    .multipliers = &multipliers,
                    .scalars = examples::followed_by<double>(
                        {zeta(), zeta_rate(), residual, static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {mass_position, slider_position},
                    .centerlines = {carrier_line, sliding_line}});
  };
  record();
  core::ProgressBar progress(t_end, "sliding_beam");
  std::optional<double> arrival_time;  // none when the run ends before the slider reaches B
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    if (slide.locked()) {
      // The integrator located the arrival inside the step (the slider within 1 µm past B,
      // DynamicOptions::event_tolerance), locked the joint there and finished the step.
      arrival_time = slide.lock_time();
      record();
      break;
    }
    record();
    progress.update(integrator.time(), integrator.counters().steps);
  }
  progress.finish();
  const solvers::DynamicCounters& counters = integrator.counters();
  if (arrival_time) results.write_attribute("arrival_time", *arrival_time);
  //    The structure events (the slider entering carrier elements, the lock at B): their times,
  //    and each description as an attribute event_<k>.
  const auto& events = integrator.events();
  Eigen::VectorXd event_times(static_cast<Eigen::Index>(events.size()));
  for (std::size_t k = 0; k < events.size(); ++k) {
    event_times(static_cast<Eigen::Index>(k)) = events[k].first;
    results.write_attribute("event_" + std::to_string(k), events[k].second);
  }
  if (!events.empty())
    results.write_constant("events/time", event_times, "s",
                           "times of the structure events (the slider entering carrier elements, the lock at "
                           "B); attribute event_<k> describes event k");
  results.close();

  // 5. Report.
  const Eigen::Vector3d mass_final = model.state().position[mass];
  const std::string arrival = arrival_time ? "reached B at t = " + std::to_string(*arrival_time) + " s"
                                           : "had not reached B at t = " + std::to_string(integrator.time()) + " s";
  std::printf("sliding_beam, %d + %d elements of degree %d, h = %g s, %s: the slider %s "
              "(003: 1.306 s); %ld steps, %ld Newton iterations, %ld factorizations, %ld pattern builds, "
              "%.2f s; mass at (%.4f, %.4f, %.4f) m; max constraint residual %.2e\n",
              elements, sliding_elements, degree, h, strategy.c_str(), arrival.c_str(), counters.steps,
              counters.newton_iterations, counters.factorizations, counters.pattern_builds,
              counters.wall_seconds, mass_final.x(), mass_final.y(), mass_final.z(), max_residual);
  examples::JsonSummary()
      .add("arrival_time", arrival_time)
      .add("h", h).add("elements", elements).add("sliding_elements", sliding_elements).add("degree", degree)
      .add("strategy", strategy)
      .add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("factorizations", static_cast<int>(counters.factorizations))
      .add("cutbacks", static_cast<int>(counters.cutbacks))
      .add("max_constraint_residual", max_residual)
      .add("mass_x", mass_final.x()).add("mass_y", mass_final.y()).add("mass_z", mass_final.z())
      .add("wall_s", counters.wall_seconds)
      .print();
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
