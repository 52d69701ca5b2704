// slider_crank — the high-speed flexible slider-crank of 003 §5.1 (Table 1, Figure 3, Table 2).
//
// Sample runs:
//   slider_crank                                          (h = 5e-4, frozen, 0.2 s)
//   slider_crank --h 1e-4 --strategy update               (recorded every 5e-4 s, every 5th step)
//   slider_crank --h 1e-4 --output-interval 0             (every step recorded)
//   slider_crank --strategy modified --out results/slider_crank_modified
//   slider_crank --tolerance 1e-16 --strategy frozen      (tight Newton tolerance)
//
// Description:
//   Rod I (the crank, 0.3 m) is pinned to the ground at the origin by a spherical joint; Rod II
//   (the coupler, 0.6 m) is joined to Rod I's tip and to a rigid slider of 0.1 kg by spherical
//   joints; the slider moves along the X axis (prismatic joint, rotation locked). Both rods are
//   steel, 0.03 × 0.03 m (E = 2.1e11 Pa, ν = 0.3, ρ = 7850 kg/m³), six cubic C² NURBS elements
//   each, straight along +X and at rest at t = 0. A constant moment M = 500 N·m about Z drives
//   Rod I; gravity 9.81 m/s² acts along −Y (our reading of the paper: in the plane of motion).
//   The run integrates 0.2 s with the Lie-group generalized-α method and writes Rod II's
//   deformation rate (distance of its midpoint from the chord's midpoint over its length) and
//   Rod I's angular speed, to compare with the paper's Figure 3 and its Table 2 of iteration
//   counts. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <centerline_fields.hpp>
#include <cli.hpp>
#include <csv_row.hpp>
#include <run_counters.hpp>
#include <energy_balance.hpp>
#include <newton_test.hpp>

#include "slider_crank_model.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

using namespace spar;

int main(int argc, char** argv) try {
  const auto started = std::chrono::steady_clock::now();  // the whole run, output included
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "slider_crank: the flexible slider-crank of 003 section 5.1");
  const double h = cli.number("--h", 5e-4, "time step [s]", examples::Range::positive());
  const double t_end = cli.number("--t-end", 0.2, "end time [s]", examples::Range::positive());
  const std::string strategy = cli.text("--strategy", "frozen", "iteration matrix: update | frozen | modified",
                                          {"update", "frozen", "modified"});
  const int elements = cli.elements("--elements", 6, "cubic NURBS elements per rod", 1, examples::memory_use::slider_crank);
  const double rho_infinity = cli.number("--rho-inf", 0.9, "spectral radius at infinity", examples::Range::between(0, 1));
  const examples::NewtonTest newton = examples::newton_test_options(cli);
  const int max_iterations = cli.integer("--max-iterations", 25, "Newton iterations before a step is cut back", 1, 1000);
  const std::string solver = cli.text("--solver", "klu", "sparse LU: klu | umfpack | eigen-lu",
                                        {"klu", "umfpack", "eigen-lu"});
  const double drive_rise_time = cli.number("--drive-rise-time", 0.0,
                                            "ramp the drive from 0 to M over this time [s] (0: the paper's step)",
                                            examples::Range::between(0, 1e3));
  const double output_interval =
      cli.number("--output-interval", 5e-4, "time between recorded states [s], a whole number of steps (0: every step)",
                 examples::Range::between(0, 1e3));
  const std::string out = cli.output_folder("--out", "results/slider_crank", "output folder");
  if (!cli.finish()) return 0;
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused

  // 2. Build the mechanism of 003 Table 1 (examples/slider_crank/slider_crank_model.hpp): the
  //    rods, the slider, the joints, the driving moment and gravity.
  examples::SliderCrank mechanism = examples::build_slider_crank(elements, drive_rise_time);
  core::Model& model = mechanism.model;
  const core::GeometricallyExactBeam& crank = model.beam(mechanism.crank);
  const core::GeometricallyExactBeam& coupler = model.beam(mechanism.coupler);
  const int crank_root = crank.node(0), crank_tip = crank.node(crank.control_point_count() - 1);
  const int slider = mechanism.slider_node;
  const examples::DeformationRate rod2_rate(coupler, examples::SliderCrank::coupler_length);

  // 3. Integrate.
  solvers::GeneralizedAlpha integrator(
      model, std::move(mechanism.joints),
      {.time_step = h, .spectral_radius = rho_infinity,
       .iteration_matrix = solvers::iteration_matrix_from_string(strategy),
       .tolerance = newton.tolerance, .constraint_tolerance = newton.constraint_tolerance,
       .residual_tolerance = newton.residual_tolerance, .max_iterations = max_iterations,
       .linear_solver = solvers::linear_solver_kind_from_string(solver)});
  integrator.initialize();
  const core::Configuration initial_state = model.state();  // the reference geometry, for arc lengths

  // The summary's extremes are taken at every step; the states are recorded every
  // `record_every` steps (the first and the last always).
  const long record_every = std::max(1L, std::lround(output_interval / h));
  const int samples = 10 * elements + 1;  // centerline points per rod in the results file
  const examples::RecordedCenterline crank_line(crank, samples, initial_state),
      coupler_line(coupler, samples, initial_state);
  core::ResultsWriter results(out + "/slider_crank.h5",
                              {.node_count = model.block_count(),
                               .multiplier_count = integrator.multiplier_count(),
                               .scalars = examples::followed_by<core::ResultsQuantity>({
                                           {.name = "rod2_deformation_rate", .unit = "1",
                                            .description = "Rod II's midpoint distance from its chord's midpoint "
                                                           "over its length, a fraction (0.05 = 5 %, 003 Fig. 3)"},
                                           {.name = "rod1_angular_speed", .unit = "rad/s",
                                            .description = "Rod I's angular speed about Z: the rotation rate of "
                                                           "its chord r = tip - root, (r x r')_z / |r|^2"},
                                           {.name = "slider_position", .unit = "m",
                                            .description = "the slider's x coordinate"},
                                           {.name = "constraint_residual", .unit = "m",
                                            .description = "largest constraint violation |Phi|_inf after the step "
                                                           "(position rows in m; the slider's rotation-lock rows "
                                                           "are dot products, about rad)"},
                                           {.name = "newton_iterations", .unit = "1",
                                            .description = "Newton iterations (linear solves) of the step",
                                            .integer = true}},
                                           examples::energy_balance_layout()),
                               .probes = {{.name = "rod2_midpoint", .unit = "m",
                                           .description = "Rod II's midpoint x(u = 1/2), inertial frame"},
                                          {.name = "rod1_tip", .unit = "m",
                                           .description = "Rod I's tip (its last node), inertial frame"}},
                               .centerline_points = {samples, samples},
                               .centerline_fields = examples::centerline_field_layout(),
                               // The slider drawn as the 2 cm cube its inertia m s²/6 stands for.
                               .rigid_bodies = {{.node = slider, .kind = core::RigidBodyShape::Kind::box,
                                                 .size = {0.02, 0.02, 0.02}}}});
  results.write_attribute("example", "slider_crank (003 section 5.1)");
  results.write_attribute("time_step", h);
  results.write_attribute("strategy", strategy);
  results.write_attribute("output_interval", static_cast<double>(record_every) * h);
  std::ofstream csv(out + "/slider_crank.csv");
  csv << "t,rod2_deformation_rate,rod1_angular_speed,slider_x,rod2_mid_x,rod2_mid_y,rod2_mid_z,"
         "constraint_residual,newton_iterations,kinetic_energy,strain_energy,gravity_potential,"
      << examples::energy_balance_csv_columns << '\n';
  double max_speed = 0.0, max_rate = 0.0, max_residual = 0.0;
  std::optional<double> slider_x_at_0_1;  // the slider at t = 0.1 s, to compare runs and engines
  auto observe = [&](bool last) {
    const core::Configuration& q = model.state();
    const double rate = rod2_rate(q);
    // Rod I's angular speed about Z: the rotation rate of its chord, (r × ṙ)_z / |r|² with
    // r = x_tip − x_root. (The root section's own angular velocity carries the high-frequency
    // local vibration that the concentrated moment excites in a section of tiny rotary inertia.)
    const Eigen::Vector3d chord = q.position[crank_tip] - q.position[crank_root];
    const Eigen::Vector3d chord_rate = integrator.velocity().segment<3>(q.blocks[crank_tip].offset) -
                                       integrator.velocity().segment<3>(q.blocks[crank_root].offset);
    const double speed = chord.cross(chord_rate).z() / chord.squaredNorm();
    const double residual = integrator.constraint_residual();
    if (std::abs(integrator.time() - 0.1) <= 0.5 * h) slider_x_at_0_1 = q.position[slider].x();
    max_speed = std::max(max_speed, std::abs(speed));
    max_rate = std::max(max_rate, rate);
    max_residual = std::max(max_residual, residual);
    if (!last && integrator.counters().steps % record_every != 0) return;
    const solvers::Energies energy = integrator.energies();
    const Eigen::Vector3d midpoint = rod2_rate.midpoint(q);
    examples::write_csv_row(csv, {integrator.time(), rate, speed, q.position[slider].x(), midpoint.x(), midpoint.y(),
                                  midpoint.z(), residual, static_cast<double>(integrator.last_step_iterations()),
                                  energy.kinetic, energy.strain, energy.gravity, energy.external_work,
                                  energy.numerical_dissipation});
    results.append({.time = integrator.time(), .configuration = &q, .velocity = &integrator.velocity(),
                    .multipliers = &integrator.multipliers(),
                    .scalars = examples::followed_by<double>(
                        {rate, speed, q.position[slider].x(), residual,
                         static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {midpoint, q.position[crank_tip]},
                    .centerlines = {crank_line.positions(q), coupler_line.positions(q)},
                    .centerline_fields = {crank_line.fields(q, integrator.velocity()),
                                          coupler_line.fields(q, integrator.velocity())}});
  };
  observe(false);
  core::ProgressBar progress(t_end, "slider_crank");
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    observe(integrator.time() >= t_end - 0.5 * h);
    progress.update(integrator.time(), integrator.counters().steps);
  }
  progress.finish();
  const solvers::DynamicCounters& counters = integrator.counters();
  examples::write_run_counters(results, integrator);
  const int recorded_states = results.steps_written();
  results.close();
  csv.close();
  const double total_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  // 4. Report.
  std::printf("slider_crank, h = %g s, %s: %ld steps, %ld Newton iterations, %ld J_theta updates, "
              "%ld factorizations, %.3f s; max Rod I speed %.1f rad/s, max Rod II deformation rate "
              "%.2f %%, max constraint residual %.2e m\n",
              h, strategy.c_str(), counters.steps, counters.newton_iterations,
              counters.jtheta_evaluations, counters.factorizations, counters.wall_seconds, max_speed,
              100 * max_rate, max_residual);
  examples::JsonSummary()
      .add("h", h).add("strategy", strategy).add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("jtheta_updates", static_cast<int>(counters.jtheta_evaluations))
      .add("factorizations", static_cast<int>(counters.factorizations))
      .add("cutbacks", static_cast<int>(counters.cutbacks))
      .add("wall_s", counters.wall_seconds).add("total_wall_s", total_wall)
      .add("recorded_states", recorded_states).add("max_rod1_speed", max_speed)
      .add("max_rod2_deformation_rate", max_rate).add("max_constraint_residual", max_residual)
      .add("slider_x_at_0_1", slider_x_at_0_1)
      .add("external_work", integrator.energies().external_work)
      .add("numerical_dissipation", integrator.energies().numerical_dissipation)
      .print();
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
