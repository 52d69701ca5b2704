// heavy_top — the symmetric heavy top of Brüls, Cardona & Arnold (2012, §5.1), the standard check
// of a Lie-group integrator on a constrained rigid body.
//
// Sample runs:
//   heavy_top                                   (h = 2.5e-4 s, 1 s, rho_inf = 0.9)
//   heavy_top --h 1e-3 --t-end 0.5
//   heavy_top --rho-inf 1 --out results/heavy_top_rho1
//
// Description:
//   A rigid body of 15 kg with inertia diag(0.234375, 0.46875, 0.234375) kg m² about its centre
//   of mass turns about a fixed point: a spherical joint ties the body point X = (0, −1, 0) m from
//   the centre of mass (body frame) to the inertial origin, so the centre of mass sits 1 m from
//   the fixed point on the body's symmetry axis Y. At t = 0, R = I (the axis is horizontal, along
//   inertial Y), Ω = (0, 150, −4.61538) rad/s in the body frame and ẋ = R(Ω × X) so that the joint
//   holds at velocity level; gravity (0, 0, −9.81) m/s². The spar model has one node (the centre
//   of mass) on R³ × SO(3) and three Lagrange multipliers, integrated by the Lie-group
//   generalized-α method. Beside it, the example integrates the reduced equations (Euler's
//   equations about the fixed point in unit quaternions, reference.hpp) with classical RK4 and a
//   small step, and writes the rotation error ‖log(R_refᵀ R)‖ and the centre-of-mass error at
//   every step. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <cli.hpp>
#include <run_counters.hpp>
#include <energy_balance.hpp>

#include "reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "heavy_top: the heavy top of Bruls, Cardona & Arnold (2012)");
  const double h = cli.number("--h", 2.5e-4, "time step [s]", examples::Range::positive());
  const double t_end = cli.number("--t-end", 1.0, "end time [s]", examples::Range::positive());
  const double rho_infinity = cli.number("--rho-inf", 0.9, "spectral radius at infinity", examples::Range::between(0, 1));
  const double tolerance = cli.number("--tolerance", 1e-24, "Newton: |[dq, h^2 beta dlambda]|^2",
                                        examples::newton_tolerances);
  const double reference_step = cli.number("--reference-step", 1e-5, "largest RK4 step of the reference [s]",
                                            examples::Range::positive());
  const std::string out = cli.output_folder("--out", "results/heavy_top", "output folder");
  if (!cli.finish()) return 0;
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused
  examples::time_steps(reference_step, t_end, "--reference-step");  // and so for the RK4 reference

  // 2. The top (Brüls, Cardona & Arnold 2012, §5.1) and its initial state.
  const examples::heavy_top::TopParameters top = examples::heavy_top::classic_top();
  const Eigen::Vector3d omega0(0.0, 150.0, -4.61538);
  const Eigen::Vector3d x0 = top.center_of_mass;  // R(0) = I, fixed point at the origin
  const Eigen::Vector3d xdot0 = omega0.cross(top.center_of_mass);

  // 3. The model: one rigid body (node at the centre of mass) and gravity.
  core::Model model;
  const int body = model.rigid_body(model.add_rigid_body(
      {.center_of_mass = x0, .mass = top.mass, .inertia = top.inertia})).node;
  model.set_gravity(top.gravity);

  // 4. The fixed point: a spherical joint between the body point −X (from the centre of mass,
  //    body frame) and the ground's origin.
  solvers::ConstraintList joints;
  joints.push_back(std::make_unique<joints::SphericalJoint>(
      joints::Attachment{body, -top.center_of_mass}, joints::Attachment{-1, Eigen::Vector3d::Zero()},
      model.state()));

  // 5. The integrator, started with the top's velocity.
  solvers::GeneralizedAlpha integrator(
      model, std::move(joints),
      {.time_step = h, .spectral_radius = rho_infinity, .tolerance = tolerance,
       .constraint_tolerance = 1e-12, .residual_tolerance = 1e-10});
  integrator.set_velocity(body, xdot0, omega0);
  integrator.initialize();

  // 6. The reference, advanced in lockstep with RK4 sub-steps of at most --reference-step.
  const examples::heavy_top::TopReference reference(top);
  examples::heavy_top::TopState exact{.rotation = Eigen::Quaterniond::Identity(), .angular_velocity = omega0};
  const long substeps = std::max(1L, static_cast<long>(std::ceil(h / reference_step - 1e-9)));
  const double initial_energy = reference.energy(exact);

  // 7. Integrate and record.
  const double plate = std::sqrt(12.0 * top.inertia(0, 0) / top.mass);
  core::ResultsWriter results(out + "/heavy_top.h5",
                              {.node_count = model.block_count(),
                               .multiplier_count = integrator.multiplier_count(),
                               .scalars = examples::followed_by<core::ResultsQuantity>({
                                           {.name = "total_energy", .unit = "J",
                                            .description = "kinetic energy + gravity potential"},
                                           {.name = "rotation_error", .unit = "rad",
                                            .description = "|log(R_ref^T R)|: rotation error against the RK4 reference"},
                                           {.name = "position_error", .unit = "m",
                                            .description = "|x - x_ref|: centre-of-mass error against the RK4 reference"},
                                           {.name = "constraint_residual", .unit = "m",
                                            .description = "largest violation |Phi|_inf of the fixed point after the step"},
                                           {.name = "newton_iterations", .unit = "1",
                                            .description = "Newton iterations (linear solves) of the step",
                                            .integer = true}},
                                           examples::energy_balance_layout()),
                               .probes = {{.name = "reference_center_of_mass", .unit = "m",
                                           .description = "the centre of mass of the RK4 reference, inertial frame"}},
                               // The top drawn as a square plate of edge a at its centre of mass — a thin
                               // plate has I_X = I_Z = m a²/12, I_Y = m a²/6, the top's inertia for
                               // a = √(12 I_X/m) = 0.433 m (1 cm thick, to be seen) — on a stick from
                               // the fixed point (body −Y from the centre of mass) to it.
                               .rigid_bodies = {{.node = body, .kind = core::RigidBodyShape::Kind::box,
                                                 .size = {plate, 0.01, plate}},
                                                {.node = body, .kind = core::RigidBodyShape::Kind::box,
                                                 .size = {0.02, top.center_of_mass.norm(), 0.02},
                                                 .offset = -0.5 * top.center_of_mass}}});
  results.write_attribute("example", "heavy_top (Bruls, Cardona & Arnold 2012, section 5.1)");
  results.write_attribute("time_step", h);
  results.write_attribute("rho_infinity", rho_infinity);
  std::ofstream csv(out + "/heavy_top.csv");
  csv.precision(15);
  csv << "t,x,y,z,x_ref,y_ref,z_ref,omega_1,omega_2,omega_3,rotation_error,position_error,omega_error,"
         "kinetic_energy,gravity_potential,total_energy,energy_drift,constraint_residual,newton_iterations,"
      << examples::energy_balance_csv_columns << '\n';
  double max_rotation_error = 0.0, max_position_error = 0.0, max_drift = 0.0, max_residual = 0.0;
  double rotation_error = 0.0, position_error = 0.0, omega_error = 0.0, drift = 0.0;
  auto record = [&]() {
    const core::Configuration& q = model.state();
    const Eigen::Vector3d x_ref = reference.center_of_mass(exact);
    rotation_error = lie::log(exact.rotation_matrix().transpose() * q.rotation[body]).norm();
    position_error = (q.position[body] - x_ref).norm();
    const solvers::Energies energy = integrator.energies();
    drift = (energy.total() - initial_energy) / initial_energy;
    const double residual = integrator.constraint_residual();
    const Eigen::Vector3d omega = integrator.velocity().segment<3>(q.blocks[body].offset + 3);
    omega_error = (omega - exact.angular_velocity).norm();
    max_rotation_error = std::max(max_rotation_error, rotation_error);
    max_position_error = std::max(max_position_error, position_error);
    max_drift = std::max(max_drift, std::abs(drift));
    max_residual = std::max(max_residual, residual);
    const Eigen::Vector3d& x = q.position[body];
    csv << integrator.time() << ',' << x.x() << ',' << x.y() << ',' << x.z() << ',' << x_ref.x() << ','
        << x_ref.y() << ',' << x_ref.z() << ',' << omega.x() << ',' << omega.y() << ',' << omega.z() << ','
        << rotation_error << ',' << position_error << ',' << omega_error << ',' << energy.kinetic << ',' << energy.gravity << ','
        << energy.total() << ',' << drift << ',' << residual << ',' << integrator.last_step_iterations();
    examples::write_energy_balance_csv(csv, energy);
    csv << '\n';
    results.append({.time = integrator.time(), .configuration = &q, .velocity = &integrator.velocity(),
                    .multipliers = &integrator.multipliers(),
                    .scalars = examples::followed_by<double>(
                        {energy.total(), rotation_error, position_error, residual,
                         static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {x_ref}});
  };
  record();
  core::ProgressBar progress(t_end, "heavy_top");
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    reference.advance(exact, h, substeps);
    record();
    progress.update(integrator.time(), integrator.counters().steps);
  }
  progress.finish();
  const solvers::DynamicCounters& counters = integrator.counters();
  examples::write_run_counters(results, integrator);
  results.close();

  // 8. Report.
  std::printf("heavy_top, h = %g s, rho_inf = %g, t = %g s: %ld steps, %ld Newton iterations, %.3f s; "
              "rotation error %.3e rad, centre-of-mass error %.3e m (vs RK4, %ld sub-steps per step), "
              "energy drift %.2e (max %.2e), max constraint residual %.2e m\n",
              h, rho_infinity, integrator.time(), counters.steps, counters.newton_iterations,
              counters.wall_seconds, rotation_error, position_error, substeps, drift, max_drift, max_residual);
  examples::JsonSummary()
      .add("h", h).add("rho_inf", rho_infinity).add("t_end", integrator.time())
      .add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("factorizations", static_cast<int>(counters.factorizations))
      .add("cutbacks", static_cast<int>(counters.cutbacks))
      .add("wall_s", counters.wall_seconds)
      .add("rotation_error", rotation_error).add("position_error", position_error)
      .add("omega_error", omega_error)
      .add("max_rotation_error", max_rotation_error).add("max_position_error", max_position_error)
      .add("energy_drift", drift).add("max_energy_drift", max_drift)
      .add("max_constraint_residual", max_residual)
      .add("reference_substeps", static_cast<int>(substeps))
      .print();
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
