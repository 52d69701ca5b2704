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

#include "reference.hpp"

#include <algorithm>
#include <cmath>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "heavy_top: the heavy top of Bruls, Cardona & Arnold (2012)");
  const study::Integration run = study::integrator_options(
      cli, {.time_step = 2.5e-4, .tolerance = 1e-24, .constraint_tolerance = 1e-12, .residual_tolerance = 1e-10},
      {.iteration_matrix_option = "", .newton = study::NewtonOptions::tolerance});
  const double h = run.dynamics.time_step, t_end = run.end_time, rho_infinity = run.dynamics.spectral_radius;
  const double reference_step = cli.number("--reference-step", 1e-5, "largest RK4 step of the reference [s]",
                                           study::Range::positive());
  const std::string out = cli.output_folder("--out", "results/heavy_top", "output folder");
  if (!cli.finish()) return 0;
  study::time_steps(reference_step, t_end, "--reference-step");  // a span the RK4 reference can take

  // 2. The top (Brüls, Cardona & Arnold 2012, §5.1) and its initial state.
  const examples::heavy_top::TopParameters top = examples::heavy_top::classic_top();
  const Eigen::Vector3d omega0(0.0, 150.0, -4.61538);
  const Eigen::Vector3d x0 = top.center_of_mass;  // R(0) = I, fixed point at the origin
  const Eigen::Vector3d xdot0 = omega0.cross(top.center_of_mass);

  // 3. The model: one rigid body (node at the centre of mass) and gravity.
  core::Model model;
  const int body = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = x0, .mass = top.mass, .inertia = top.inertia})).node;
  model.set_gravity(top.gravity);

  // 4. The fixed point: a spherical joint between the body point −X (from the centre of mass,
  //    body frame) and the ground's origin.
  solvers::ConstraintList joints;
  joints.push_back(std::make_unique<joints::SphericalJoint>(
      joints::Attachment{body, -top.center_of_mass}, joints::Attachment{-1, Eigen::Vector3d::Zero()}, model.state()));

  // 5. The integrator, started with the top's velocity.
  solvers::GeneralizedAlpha integrator(model, std::move(joints), run.dynamics);
  integrator.set_velocity(body, xdot0, omega0);
  integrator.initialize();

  // 6. The reference, advanced in lockstep with RK4 sub-steps of at most --reference-step.
  const examples::heavy_top::TopReference reference(top);
  examples::heavy_top::TopState exact{.rotation = Eigen::Quaterniond::Identity(), .angular_velocity = omega0};
  const long substeps = std::max(1L, static_cast<long>(std::ceil(h / reference_step - 1e-9)));
  const double initial_energy = reference.energy(exact);

  // 7. Record every step (docs/output.md, "heavy_top"): the errors against the reference, the
  //    energies, and the top drawn as a square plate of edge a at its centre of mass — a thin plate
  //    has I_X = I_Z = m a²/12, I_Y = m a²/6, the top's inertia for a = √(12 I_X/m) = 0.433 m (1 cm
  //    thick, to be seen) — on a stick from the fixed point (body −Y from the centre of mass) to it.
  study::Recorder rec(integrator, {.folder = out, .name = "heavy_top", .time_step = h, .nodes = true,
                                   .velocities = true, .multipliers = true, .csv_digits = 15});
  rec.attributes({{"example", "heavy_top (Bruls, Cardona & Arnold 2012, section 5.1)"},
                  {"rho_infinity", rho_infinity}});
  const double plate = std::sqrt(12.0 * top.inertia(0, 0) / top.mass);
  rec.shape({.node = body, .kind = output::RigidBodyShape::Kind::box, .size = {plate, 0.01, plate}});
  rec.shape({.node = body, .kind = output::RigidBodyShape::Kind::box,
             .size = {0.02, top.center_of_mass.norm(), 0.02}, .offset = -0.5 * top.center_of_mass});
  const auto omega = [&](const study::State& s) -> Eigen::Vector3d {
    return s.velocity.segment<3>(s.q.blocks[body].offset + 3);
  };
  rec.vector({.name = "position", .csv = "x,y,z", .file = false}, study::node_position(body));
  rec.vector({.name = "reference_center_of_mass", .unit = "m",
              .description = "the centre of mass of the RK4 reference, inertial frame", .csv = "x_ref,y_ref,z_ref"},
             [&] { return reference.center_of_mass(exact); });
  rec.vector({.name = "omega", .csv = "omega_1,omega_2,omega_3", .file = false}, omega);
  const study::Scalar rotation_error = rec.scalar(
      {.name = "rotation_error", .unit = "rad",
       .description = "|log(R_ref^T R)|: rotation error against the RK4 reference"},
      [&](const study::State& s) { return lie::log(exact.rotation_matrix().transpose() * s.q.rotation[body]).norm(); });
  const study::Scalar position_error = rec.scalar(
      {.name = "position_error", .unit = "m",
       .description = "|x - x_ref|: centre-of-mass error against the RK4 reference"},
      [&](const study::State& s) { return (s.q.position[body] - reference.center_of_mass(exact)).norm(); });
  const study::Scalar omega_error = rec.scalar({.name = "omega_error", .file = false}, [&](const study::State& s) {
    return (omega(s) - exact.angular_velocity).norm();
  });
  rec.total_energy({.description = "kinetic energy + gravity potential"});
  const study::Scalar drift = rec.scalar({.name = "energy_drift", .file = false}, [&](const study::State& s) {
    return (s.energies().total() - initial_energy) / initial_energy;
  });
  const study::Scalar residual =
      rec.constraint_residual({.description = "largest violation |Phi|_inf of the fixed point after the step"});
  rec.newton_iterations();
  rec.energy_balance();
  rec.csv({"position", "reference_center_of_mass", "omega", "rotation_error", "position_error", "omega_error",
           "kinetic_energy", "gravity_potential", "total_energy", "energy_drift", "constraint_residual",
           "newton_iterations", "external_work", "numerical_dissipation"});
  rec.run(t_end, {.each_step = [&] { reference.advance(exact, h, substeps); }});
  rec.close();

  // 8. The summary.
  rec.summary()
      .add("h", h).add("rho_inf", rho_infinity).add("t_end", integrator.time())
      .add("rotation_error", rotation_error.last()).add("position_error", position_error.last())
      .add("omega_error", omega_error.last())
      .add("max_rotation_error", rotation_error.max()).add("max_position_error", position_error.max())
      .add("energy_drift", drift.last()).add("max_energy_drift", drift.max_abs())
      .add("max_constraint_residual", residual.max()).add("reference_substeps", substeps)
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
