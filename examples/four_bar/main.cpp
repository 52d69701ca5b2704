// four_bar — a spatial four-bar with two flexible steel rods and a rigid coupler, its crank driven
// at 10 rad/s, checked against the rigid four-bar (issue 14's worked example).
//
// Sample runs:
//   four_bar                                        (h = 1e-4 s, 1 s, ρ∞ = 0.9, 4 elements per rod)
//   four_bar --h 5e-4 --t-end 0.2
//   four_bar --initial-assembly off                 (start as given: from rest, inconsistent with the drive)
//   four_bar --elements 8 --out results/four_bar_8
//   four_bar --output-interval 1e-3                 (record every 1 ms, interpolated between steps)
//
// Description:
//   Ground pivots A = (0, 0, 0) and D = (0.4, 0, 0); the crank A → B (0.1 m) and the rocker
//   D → C (0.3 m) are steel rods of circular section, radius 5 mm (E = 210 GPa, ν = 0.3,
//   ρ = 7850 kg/m³), four cubic C² NURBS elements each; the coupler B → C (0.35 m) is a rigid
//   body of 0.5 kg. Revolute joints about Z join ground–crank, crank–coupler, coupler–rocker and
//   rocker–ground. The crank starts at 60° and its root section is driven at 10 rad/s about Z;
//   gravity 9.81 m/s² acts along −Y. The model is built at rest in the rigid four-bar's
//   configuration; the integrator's initial assembly (docs/dynamics.md D6a) gives the velocities
//   that the drive imposes. The run integrates 1 s (1.6 crank turns) with the Lie-group
//   generalized-α method and compares the rocker's angle (its chord D → tip) with the rigid
//   four-bar's closed-form angle at the same crank angle. The last line of stdout is a JSON
//   summary.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <centerline_fields.hpp>
#include <cli.hpp>
#include <run_counters.hpp>
#include <energy_balance.hpp>

#include "four_bar_model.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "four_bar: a flexible spatial four-bar driven at 10 rad/s");
  const double h = cli.number("--h", 1e-4, "time step [s]", examples::Range::positive());
  const double t_end = cli.number("--t-end", 1.0, "end time [s]", examples::Range::positive());
  const int elements = cli.elements("--elements", 4, "cubic NURBS elements per rod", 1, examples::memory_use::four_bar);
  const double rho_infinity = cli.number("--rho-inf", 0.9, "spectral radius at infinity", examples::Range::between(0, 1));
  const double tolerance = cli.number("--tolerance", 1e-16, "Newton: |[dq, h^2 beta dlambda]|^2 (squared, m and rad)",
                                        examples::newton_tolerances);
  const std::string assembly = cli.text("--initial-assembly", "on", "consistent initial assembly", {"on", "off"});
  const double stiffness_time = cli.number("--velocity-stiffness-time", 1.0,
                                           "initial velocities projected in the metric M + tau^2 K: tau [s] "
                                           "(0: the mass metric, an impulsive start)",
                                           examples::Range::between(0.0, 1e4));
  const double output_interval = cli.number("--output-interval", 0.0,
                                            "record every this many seconds, interpolated between steps "
                                            "(0: every step)", examples::Range{0.0, INFINITY, false, true});
  const std::string out = cli.output_folder("--out", "results/four_bar", "output folder");
  //    τ weighs the velocities of the initial assembly only. Its range: τ = 1 s already gives the
  //    rigid start to ~1/(τω)² (docs/dynamics.md D6a); the rocker's error over 0.01 s is the same to
  //    1e-10 from τ = 1 to 10⁴ s (4 and 64 elements per rod) and drifts above (2e-3 relative at 10¹⁰,
  //    10 times off at 10¹², where τ²K swamps M in double precision; τ² overflowed at 1e300).
  cli.applies_only_when("--velocity-stiffness-time", "--initial-assembly", {"on"});
  if (!cli.finish()) return 0;
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused
  examples::require_within_run(output_interval, "--output-interval", "the file would hold the state at t = 0 only",
                               t_end);

  // 2. Build the mechanism (examples/four_bar/four_bar_model.hpp): rods, coupler, joints, drive.
  examples::FourBar mechanism = examples::build_four_bar(elements);
  core::Model& model = mechanism.model;
  const core::GeometricallyExactBeam& crank = model.beam(mechanism.crank);
  const core::GeometricallyExactBeam& rocker = model.beam(mechanism.rocker);
  const examples::RigidFourBar& rigid = mechanism.rigid;

  // 3. The integrator; its first initialize() assembles the state and reports what it changed.
  solvers::GeneralizedAlpha integrator(model, std::move(mechanism.joints),
                                       {.time_step = h, .spectral_radius = rho_infinity, .tolerance = tolerance,
                                        .constraint_tolerance = 1e-12, .residual_tolerance = 1e-8,
                                        .initial_assembly = assembly == "on",
                                        .initial_velocity_stiffness_time = stiffness_time});
  integrator.initialize();
  const solvers::InitialAssembly& assembled = integrator.initial_assembly();
  // The ground pivots' joints (four_bar_model.hpp: A is constraint 0, D constraint 3; a = the
  // rod's root, b = the ground), for their reactions and coordinates.
  const auto& pivot_a = dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(0));
  const auto& pivot_d = dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(3));
  const core::Configuration initial_state = model.state();  // the reference geometry, for arc lengths

  // 4. Integrate and record.
  std::filesystem::create_directories(out);
  const int samples = 10 * elements + 1;
  const examples::RecordedCenterline crank_line(crank, samples, initial_state), rocker_line(rocker, samples, initial_state);
  core::ResultsWriter results(out + "/four_bar.h5",
                              {.node_count = model.block_count(),
                               .multiplier_count = integrator.multiplier_count(),
                               .scalars = examples::followed_by<core::ResultsQuantity>({
                                           {.name = "crank_angle", .unit = "rad",
                                            .description = "the driven crank angle theta(t) = 60 deg + 10 rad/s t"},
                                           {.name = "rocker_angle", .unit = "rad",
                                            .description = "the flexible rocker's angle: its chord D -> tip from +X"},
                                           {.name = "rigid_rocker_angle", .unit = "rad",
                                            .description = "the rigid four-bar's rocker angle at theta(t)"},
                                           {.name = "rocker_angle_error", .unit = "rad",
                                            .description = "rocker_angle - rigid_rocker_angle"},
                                           {.name = "rocker_joint_angle", .unit = "rad",
                                            .description = "pivot D's relative angle: the rocker's root section "
                                                           "turned about Z since t = 0"},
                                           {.name = "rocker_joint_rate", .unit = "rad/s",
                                            .description = "pivot D's relative rate about Z"},
                                           {.name = "constraint_residual", .unit = "m",
                                            .description = "largest constraint violation |Phi|_inf after the step "
                                                           "(point rows in m, axis rows dot products)"},
                                           {.name = "newton_iterations", .unit = "1",
                                            .description = "Newton iterations (linear solves) of the step (that holds the sample)",
                                            .integer = true}},
                                           examples::energy_balance_layout()),
                               .probes = {{.name = "crank_tip", .unit = "m", .description = "B, the crank's tip node"},
                                          {.name = "rocker_tip", .unit = "m", .description = "C, the rocker's tip node"},
                                          {.name = "coupler_center", .unit = "m",
                                           .description = "the coupler's centre of mass"},
                                          {.name = "pivot_a_force", .unit = "N",
                                           .description = "force of pivot A on the crank, in the joint's frame "
                                                          "(n1, n2, n) = (-Y, X, Z) carried by the ground (docs/joints.md 5)"},
                                          {.name = "pivot_a_moment", .unit = "N m",
                                           .description = "moment of pivot A on the crank about A, joint's frame "
                                                          "(its Z component: 0, frictionless)"},
                                          {.name = "pivot_d_force", .unit = "N",
                                           .description = "force of pivot D on the rocker, in the joint's frame"}},
                               .centerline_points = {samples, samples},
                               .centerline_fields = examples::centerline_field_layout(),
                               // The coupler drawn as a bar B → C (its body X) of 2 cm square section.
                               .rigid_bodies = {{.node = mechanism.coupler_node,
                                                 .kind = core::RigidBodyShape::Kind::box,
                                                 .size = {rigid.g.coupler, 0.02, 0.02}}}});
  results.write_attribute("example", "four_bar (issue 14)");
  results.write_attribute("time_step", h);
  results.write_attribute("initial_assembly", assembly);
  results.write_attribute("initial_position_change", assembled.largest_position_change);
  results.write_attribute("initial_velocity_correction", assembled.largest_velocity_change);
  std::ofstream csv(out + "/four_bar.csv");
  csv.precision(15);
  csv << "t,crank_angle,rocker_angle,rigid_rocker_angle,rocker_angle_error,constraint_residual,"
         "newton_iterations,kinetic_energy,strain_energy,gravity_potential,"
      << examples::energy_balance_csv_columns << '\n';
  double max_error = 0.0, max_residual = 0.0;
  // The largest rocker error and constraint residual over every step, whatever is recorded.
  auto check_step = [&]() {
    const double theta = rigid.crank_angle(integrator.time());
    max_error = std::max(max_error, std::abs(mechanism.rocker_angle(model.state()) - rigid.rocker_angle(theta)));
    max_residual = std::max(max_residual, integrator.constraint_residual());
  };
  // λ of constraint c within a multiplier vector (the constraints' equations one after another).
  auto joint_multipliers = [&](const Eigen::VectorXd& lambda, int c) {
    int first = 0;
    for (int i = 0; i < c; ++i) first += integrator.constraint(i).equation_count();
    return Eigen::VectorXd(lambda.segment(first, integrator.constraint(c).equation_count()));
  };
  // Records one sample: the state at the end of a step, or interpolated at an output time.
  auto record = [&](const solvers::Sample& sample) {
    const core::Configuration& q = sample.q;
    const double t = sample.time, theta = rigid.crank_angle(t);
    const double psi = mechanism.rocker_angle(q), psi_rigid = rigid.rocker_angle(theta), error = psi - psi_rigid;
    double residual = 0.0;
    for (int c = 0; c < integrator.constraint_count(); ++c) {
      Eigen::VectorXd phi(integrator.constraint(c).equation_count());
      integrator.constraint(c).value(q, t, phi);
      residual = std::max(residual, phi.lpNorm<Eigen::Infinity>());
    }
    const solvers::Energies& energy = sample.energies;
    const joints::Wrench at_a = pivot_a.reaction_in_frame(q, t, joint_multipliers(sample.multipliers, 0));
    const joints::Wrench at_d = pivot_d.reaction_in_frame(q, t, joint_multipliers(sample.multipliers, 3));
    const double joint_angle = pivot_d.relative_angle(q), joint_rate = pivot_d.relative_rate(q, sample.velocity);
    csv << t << ',' << theta << ',' << psi << ',' << psi_rigid << ',' << error << ',' << residual
        << ',' << integrator.last_step_iterations() << ',' << energy.kinetic << ',' << energy.strain << ','
        << energy.gravity;
    examples::write_energy_balance_csv(csv, energy);
    csv << '\n';
    results.append({.time = t, .configuration = &q, .velocity = &sample.velocity,
                    .multipliers = &sample.multipliers,
                    .scalars = examples::followed_by<double>(
                        {theta, psi, psi_rigid, error, joint_angle, joint_rate, residual,
                         static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {q.position[mechanism.crank_tip], q.position[mechanism.rocker_tip],
                               q.position[mechanism.coupler_node], at_a.force, at_a.moment, at_d.force},
                    .centerlines = {crank_line.positions(q), rocker_line.positions(q)},
                    .centerline_fields = {crank_line.fields(q, sample.velocity), rocker_line.fields(q, sample.velocity)}});
  };
  // Every step, or every output_interval through a solvers::TimeSampler.
  std::optional<solvers::TimeSampler> sampler;
  if (output_interval > 0.0) sampler = solvers::TimeSampler::every(output_interval);
  auto record_step = [&]() {
    check_step();
    if (sampler) {
      for (const solvers::Sample& sample : sampler->update(integrator)) record(sample);
    } else {
      record({.time = integrator.time(), .q = model.state(), .velocity = integrator.velocity(),
              .multipliers = integrator.multipliers(), .energies = integrator.energies()});
    }
  };
  record_step();
  core::ProgressBar progress(t_end, "four_bar");
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    record_step();
    progress.update(integrator.time(), integrator.counters().steps);
  }
  progress.finish();
  const solvers::DynamicCounters& counters = integrator.counters();
  examples::write_run_counters(results, integrator);
  results.close();

  // 5. Report.
  std::printf("four_bar, h = %g s, rho_inf = %g, %d elements per rod, t = %g s: %ld steps, %ld Newton "
              "iterations, %.3f s; initial assembly %s (positions moved %.2e, velocities changed %.3g), "
              "max rocker angle error %.3e rad against the rigid four-bar, max constraint residual %.2e\n",
              h, rho_infinity, elements, integrator.time(), counters.steps, counters.newton_iterations,
              counters.wall_seconds, assembly.c_str(), assembled.largest_position_change,
              assembled.largest_velocity_change, max_error, max_residual);
  examples::JsonSummary()
      .add("h", h).add("rho_inf", rho_infinity).add("elements", elements).add("t_end", integrator.time())
      .add("initial_assembly", assembly)
      .add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("factorizations", static_cast<int>(counters.factorizations))
      .add("cutbacks", static_cast<int>(counters.cutbacks))
      .add("wall_s", counters.wall_seconds)
      .add("max_rocker_angle_error", max_error)
      .add("initial_position_change", assembled.largest_position_change)
      .add("initial_velocity_correction", assembled.largest_velocity_change)
      .add("max_constraint_residual", max_residual)
      .add("external_work", integrator.energies().external_work)
      .add("numerical_dissipation", integrator.energies().numerical_dissipation)
      .print();
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
