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

#include <memory_use.hpp>

#include "slider_crank_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

using namespace spar;

int main(int argc, char** argv) try {
  const auto started = std::chrono::steady_clock::now();  // the whole run, output included
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "slider_crank: the flexible slider-crank of 003 section 5.1");
  //    003's Newton test: the increment at 1e-6, Phi at 1e-10 m, the residual untested.
  study::Integration run = study::integrator_options(
      cli, {.time_step = 5e-4, .iteration_matrix = solvers::IterationMatrix::frozen, .residual_tolerance = INFINITY},
      {.end_time = 0.2, .newton = study::NewtonOptions::test_003});
  const double h = run.dynamics.time_step;
  const int elements = cli.elements("--elements", 6, "cubic NURBS elements per rod", 1, examples::memory_use::slider_crank);
  run.dynamics.max_iterations = cli.integer("--max-iterations", 25, "Newton iterations before a step is cut back", 1, 1000);
  run.dynamics.linear_solver = solvers::linear_solver_kind_from_string(
      cli.text("--solver", "klu", "sparse LU: klu | umfpack | eigen-lu", {"klu", "umfpack", "eigen-lu"}));
  const double drive_rise_time = cli.number("--drive-rise-time", 0.0,
                                            "ramp the drive from 0 to M over this time [s] (0: the paper's step)",
                                            study::Range::between(0, 1e3));
  const double output_interval =
      cli.number("--output-interval", 5e-4, "time between recorded states [s], a whole number of steps (0: every step)",
                 study::Range::between(0, 1e3));
  const std::string out = cli.output_folder("--out", "results/slider_crank", "output folder");
  if (!cli.finish()) return 0;

  // 2. Build the mechanism of 003 Table 1 (examples/slider_crank/slider_crank_model.hpp): the
  //    rods, the slider, the joints, the driving moment and gravity.
  examples::SliderCrank mechanism = examples::build_slider_crank(elements, drive_rise_time);
  core::Model& model = mechanism.model;
  const core::GeometricallyExactBeam& crank = core::beam(model, mechanism.crank);
  const core::GeometricallyExactBeam& coupler = core::beam(model, mechanism.coupler);
  const int crank_root = crank.node(0), crank_tip = crank.node(crank.control_point_count() - 1);
  const int slider = mechanism.slider_node;
  const examples::DeformationRate rod2_rate(coupler, examples::SliderCrank::coupler_length);

  // 3. The integrator.
  solvers::GeneralizedAlpha integrator(model, std::move(mechanism.joints), run.dynamics);
  integrator.initialize();

  // 4. Record (docs/output.md, "slider_crank") every `record_every` steps, the first and the last
  //    always; the summary's extremes are taken at every step.
  const long record_every = std::max(1L, std::lround(output_interval / h));
  study::Recorder rec(integrator, {.folder = out, .name = "slider_crank", .time_step = h,
                                   .schedule = study::Schedule::every_steps(record_every).and_last(), .nodes = true,
                                   .velocities = true, .multipliers = true, .centerline_fields = true});
  rec.attributes({{"example", "slider_crank (003 section 5.1)"}, {"strategy", run.strategy},
                  {"output_interval", static_cast<double>(record_every) * h}});
  for (const core::GeometricallyExactBeam* rod : {&crank, &coupler})
    rec.centerline(core::CenterlineSampler(*rod, 10 * elements + 1));
  //    The slider drawn as the 2 cm cube its inertia m s²/6 stands for.
  rec.shape({.node = slider, .kind = output::RigidBodyShape::Kind::box, .size = {0.02, 0.02, 0.02}});
  const study::Scalar rate = rec.scalar(
      {.name = "rod2_deformation_rate", .unit = "1",
       .description = "Rod II's midpoint distance from its chord's midpoint over its length, a fraction (0.05 = 5 %, 003 Fig. 3)",
       .every_step = true},
      [&](const study::State& s) { return rod2_rate(s.q); });
  //    Rod I's angular speed about Z: the rotation rate of its chord, (r × ṙ)_z / |r|² with
  //    r = x_tip − x_root. (The root section's own angular velocity carries the high-frequency
  //    local vibration that the concentrated moment excites in a section of tiny rotary inertia.)
  const study::Scalar speed = rec.scalar(
      {.name = "rod1_angular_speed", .unit = "rad/s",
       .description = "Rod I's angular speed about Z: the rotation rate of its chord r = tip - root, (r x r')_z / |r|^2",
       .every_step = true},
      [&](const study::State& s) {
        const Eigen::Vector3d chord = s.q.position[crank_tip] - s.q.position[crank_root];
        const Eigen::Vector3d chord_rate =
            s.velocity.segment<3>(s.q.blocks[crank_tip].offset) - s.velocity.segment<3>(s.q.blocks[crank_root].offset);
        return chord.cross(chord_rate).z() / chord.squaredNorm();
      });
  rec.scalar({.name = "slider_position", .unit = "m", .description = "the slider's x coordinate", .csv = "slider_x"},
             [&](const study::State& s) { return s.q.position[slider].x(); });
  rec.vector({.name = "rod2_midpoint", .unit = "m", .description = "Rod II's midpoint x(u = 1/2), inertial frame",
              .csv = "rod2_mid_x,rod2_mid_y,rod2_mid_z"},
             [&](const study::State& s) { return rod2_rate.midpoint(s.q); });
  rec.vector({.name = "rod1_tip", .unit = "m", .description = "Rod I's tip (its last node), inertial frame"},
             study::node_position(crank_tip));
  const study::Scalar residual = rec.constraint_residual(
      {.description = "largest constraint violation |Phi|_inf after the step (position rows in m; the slider's "
                      "rotation-lock rows are dot products, about rad)",
       .every_step = true});
  rec.newton_iterations();
  rec.energy_balance();
  rec.csv({"rod2_deformation_rate", "rod1_angular_speed", "slider_x", "rod2_midpoint", "constraint_residual",
           "newton_iterations", "kinetic_energy", "strain_energy", "gravity_potential", "external_work",
           "numerical_dissipation"});
  std::optional<double> slider_x_at_0_1;  // the slider at t = 0.1 s, to compare runs and engines
  rec.run(run.end_time, {.each_step = [&] {
                    if (std::abs(integrator.time() - 0.1) <= 0.5 * h) slider_x_at_0_1 = model.state().position[slider].x();
                  }});
  rec.close();
  const double total_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  // 5. The summary.
  rec.summary({.energy_balance = true})
      .add("h", h).add("strategy", run.strategy).add("jtheta_updates", integrator.counters().jtheta_evaluations)
      .add("total_wall_s", total_wall).add("recorded_states", rec.states_written())
      .add("max_rod1_speed", speed.max_abs()).add("max_rod2_deformation_rate", rate.max())
      .add("max_constraint_residual", residual.max()).add("slider_x_at_0_1", slider_x_at_0_1)
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
