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

#include <memory_use.hpp>

#include "four_bar_model.hpp"

#include <cmath>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "four_bar: a flexible spatial four-bar driven at 10 rad/s");
  study::Integration run = study::integrator_options(
      cli, {.time_step = 1e-4, .tolerance = 1e-16, .constraint_tolerance = 1e-12, .residual_tolerance = 1e-8},
      {.iteration_matrix_option = "", .newton = study::NewtonOptions::tolerance});
  const double h = run.dynamics.time_step, t_end = run.end_time, rho_infinity = run.dynamics.spectral_radius;
  const int elements = cli.elements("--elements", 4, "cubic NURBS elements per rod", 1, examples::memory_use::four_bar);
  const std::string assembly = cli.text("--initial-assembly", "on", "consistent initial assembly", {"on", "off"});
  run.dynamics.initial_assembly = assembly == "on";
  run.dynamics.initial_velocity_stiffness_time =
      cli.number("--velocity-stiffness-time", 1.0,
                 "initial velocities projected in the metric M + tau^2 K: tau [s] (0: the mass metric, an impulsive start)",
                 study::Range::between(0.0, 1e4));
  const double output_interval = cli.number("--output-interval", 0.0,
                                            "record every this many seconds, interpolated between steps "
                                            "(0: every step)", study::Range{0.0, INFINITY, false, true});
  const std::string out = cli.output_folder("--out", "results/four_bar", "output folder");
  //    τ weighs the velocities of the initial assembly only. Its range: τ = 1 s already gives the
  //    rigid start to ~1/(τω)² (docs/dynamics.md D6a); the rocker's error over 0.01 s is the same to
  //    1e-10 from τ = 1 to 10⁴ s (4 and 64 elements per rod) and drifts above (2e-3 relative at 10¹⁰,
  //    10 times off at 10¹², where τ²K swamps M in double precision; τ² overflowed at 1e300).
  cli.applies_only_when("--velocity-stiffness-time", "--initial-assembly", {"on"});
  if (!cli.finish()) return 0;
  study::require_within_run(output_interval, "--output-interval", "the file would hold the state at t = 0 only", t_end);

  // 2. Build the mechanism (examples/four_bar/four_bar_model.hpp): rods, coupler, joints, drive.
  examples::FourBar mechanism = examples::build_four_bar(elements);
  core::Model& model = mechanism.model;
  const core::GeometricallyExactBeam& crank = core::beam(model, mechanism.crank);
  const core::GeometricallyExactBeam& rocker = core::beam(model, mechanism.rocker);
  const examples::RigidFourBar& rigid = mechanism.rigid;

  // 3. The integrator; its first initialize() assembles the state and reports what it changed.
  solvers::GeneralizedAlpha integrator(model, std::move(mechanism.joints), run.dynamics);
  integrator.initialize();
  const solvers::InitialAssembly& assembled = integrator.initial_assembly();
  // The ground pivots' joints (four_bar_model.hpp: A is constraint 0, D constraint 3; a = the
  // rod's root, b = the ground), for their reactions and coordinates.
  const auto& pivot_a = dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(0));
  const auto& pivot_d = dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(3));

  // 4. Record every step, or every --output-interval interpolated between the steps
  //    (solvers::TimeSampler, docs/dynamics.md D10): the angles against the rigid four-bar, pivot
  //    D's coordinates, the pivots' reactions, the energies (docs/output.md, "four_bar").
  study::Recorder rec(integrator, {.folder = out, .name = "four_bar", .time_step = h,
                                   .schedule = output_interval > 0.0 ? study::Schedule::sampled_every(output_interval)
                                                                     : study::Schedule::every_step(),
                                   .nodes = true, .velocities = true, .multipliers = true, .centerline_fields = true,
                                   .csv_digits = 15});
  rec.attributes({{"example", "four_bar (issue 14)"}, {"initial_assembly", assembly},
                  {"initial_position_change", assembled.largest_position_change},
                  {"initial_velocity_correction", assembled.largest_velocity_change}});
  rec.centerline(core::CenterlineSampler(crank, 10 * elements + 1));
  rec.centerline(core::CenterlineSampler(rocker, 10 * elements + 1));
  //    The coupler drawn as a bar B → C (its body X) of 2 cm square section.
  rec.shape({.node = mechanism.coupler_node, .kind = output::RigidBodyShape::Kind::box, .size = {rigid.g.coupler, 0.02, 0.02}});
  const auto theta = [&](const study::State& s) { return rigid.crank_angle(s.time); };
  const auto error = [&](const study::State& s) { return mechanism.rocker_angle(s.q) - rigid.rocker_angle(theta(s)); };
  rec.scalar({.name = "crank_angle", .unit = "rad", .description = "the driven crank angle theta(t) = 60 deg + 10 rad/s t"},
             theta);
  rec.scalar({.name = "rocker_angle", .unit = "rad", .description = "the flexible rocker's angle: its chord D -> tip from +X"},
             [&](const study::State& s) { return mechanism.rocker_angle(s.q); });
  rec.scalar({.name = "rigid_rocker_angle", .unit = "rad", .description = "the rigid four-bar's rocker angle at theta(t)"},
             [&](const study::State& s) { return rigid.rocker_angle(theta(s)); });
  const study::Scalar rocker_error = rec.scalar(
      {.name = "rocker_angle_error", .unit = "rad", .description = "rocker_angle - rigid_rocker_angle", .every_step = true},
      error);
  rec.scalar({.name = "rocker_joint_angle", .unit = "rad",
              .description = "pivot D's relative angle: the rocker's root section turned about Z since t = 0"},
             [&](const study::State& s) { return pivot_d.relative_angle(s.q); });
  rec.scalar({.name = "rocker_joint_rate", .unit = "rad/s", .description = "pivot D's relative rate about Z"},
             [&](const study::State& s) { return pivot_d.relative_rate(s.q, s.velocity); });
  const study::Scalar residual = rec.constraint_residual(
      {.description = "largest constraint violation |Phi|_inf after the step (point rows in m, axis rows dot products)",
       .every_step = true});
  rec.newton_iterations({.description = "Newton iterations (linear solves) of the step (that holds the sample)"});
  rec.energy_balance();
  rec.vector({.name = "crank_tip", .unit = "m", .description = "B, the crank's tip node"},
             study::node_position(mechanism.crank_tip));
  rec.vector({.name = "rocker_tip", .unit = "m", .description = "C, the rocker's tip node"},
             study::node_position(mechanism.rocker_tip));
  rec.vector({.name = "coupler_center", .unit = "m", .description = "the coupler's centre of mass"},
             study::node_position(mechanism.coupler_node));
  //    A joint's reaction on its first body, in the joint's frame, from its multipliers (docs/joints.md §5).
  const auto at_a = [&](const study::State& s) { return pivot_a.reaction_in_frame(s.q, s.time, s.multipliers_of(0)); };
  rec.vector({.name = "pivot_a_force", .unit = "N",
              .description = "force of pivot A on the crank, in the joint's frame (n1, n2, n) = (-Y, X, Z) carried by "
                             "the ground (docs/joints.md 5)"},
             [&](const study::State& s) { return at_a(s).force; });
  rec.vector({.name = "pivot_a_moment", .unit = "N m",
              .description = "moment of pivot A on the crank about A, joint's frame (its Z component: 0, frictionless)"},
             [&](const study::State& s) { return at_a(s).moment; });
  rec.vector({.name = "pivot_d_force", .unit = "N", .description = "force of pivot D on the rocker, in the joint's frame"},
             [&](const study::State& s) { return pivot_d.reaction_in_frame(s.q, s.time, s.multipliers_of(3)).force; });
  rec.csv({"crank_angle", "rocker_angle", "rigid_rocker_angle", "rocker_angle_error", "constraint_residual",
           "newton_iterations", "kinetic_energy", "strain_energy", "gravity_potential", "external_work",
           "numerical_dissipation"});
  rec.run(t_end);
  rec.close();

  // 5. The summary.
  rec.summary({.energy_balance = true})
      .add("h", h).add("rho_inf", rho_infinity).add("elements", elements).add("t_end", integrator.time())
      .add("initial_assembly", assembly).add("max_rocker_angle_error", rocker_error.max_abs())
      .add("initial_position_change", assembled.largest_position_change)
      .add("initial_velocity_correction", assembled.largest_velocity_change)
      .add("max_constraint_residual", residual.max())
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
