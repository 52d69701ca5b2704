// ancf_pendulum — the flexible pendulum of paper 001 (Song, Chen & Chen 2021, §6, Figures 3–7)
// with the 3D ANCF beam elements (issue 13), beside the geometrically exact beam model of the
// same pendulum (an independent model of the same physics).
//
// Sample runs:
//   ancf_pendulum                                        (24 coordinates, method II, 8 elements, 1 s)
//   ancf_pendulum --element 30 --force invariant --elements 4
//   ancf_pendulum --element gebt --elements 16            (the geometrically exact beam)
//   ancf_pendulum --h 5e-4 --t-end 2 --out results/ancf_pendulum_fine
//
// Description:
//   A 2 m steel-density rod (circular, r = 0.02 m, E = 0.72 GPa, ν = 0, ρ = 7200 kg/m³;
//   m = 18.1 kg, EI = 90.5 N m²) lies along +X with its root at the origin, pinned there by a
//   spherical joint on the root node's position. It is straight and at rest at t = 0 and falls
//   under gravity (0, 0, −9.81) m/s², bending strongly on the way. The ANCF root node keeps its
//   12 coordinates free (only r is held). Lie-group generalized-α (index 3). The tip position and
//   velocity, the energies and the constraint residual go to <out>/ancf_pendulum.csv and
//   <out>/ancf_pendulum.h5 (+ .xmf); the energy drift is relative to m g L/2 and, with ρ∞ < 1,
//   includes the integrator's numerical dissipation. The last stdout line is a JSON summary.
#include <spar/spar.hpp>

#include <ancf_options.hpp>
#include <memory_use.hpp>

#include <chrono>
#include <numbers>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "ancf_pendulum: paper 001's flexible pendulum (Figures 3-7)");
  const examples::AncfChoice ancf_element = examples::ancf_options(cli, true);
  const int elements = cli.elements("--elements", 8, "number of elements", 1, examples::memory_use::ancf_pendulum);
  const study::Integration run = study::integrator_options(
      cli, {.time_step = 1e-3, .tolerance = 1e-20, .constraint_tolerance = 1e-12, .residual_tolerance = 1e-8},
      {.iteration_matrix_option = ""});
  const double h = run.dynamics.time_step;
  const std::string out = cli.output_folder("--out", "results/ancf_pendulum", "output folder");
  if (!cli.finish()) return 0;

  // 2. The rod of 001 §6 along +X from the origin.
  const double length = 2.0, radius = 0.02;
  const core::Material material{.young_modulus = 0.72e9, .poisson_ratio = 0.0, .density = 7200};
  const Eigen::Vector3d gravity(0, 0, -9.81);
  const double mass = material.density * std::numbers::pi * radius * radius * length;
  const double energy_scale = 0.5 * mass * gravity.norm() * length;
  core::Model model;
  model.set_gravity(gravity);
  solvers::ConstraintList joints;
  const auto preprocessing_start = std::chrono::steady_clock::now();
  core::AncfBeam ancf;
  int rod_index = -1;
  if (ancf_element.gebt()) {
    const core::CrossSection section = core::CrossSection::circle(2 * radius, material.poisson_ratio);
    rod_index = core::add_beam(
        model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0), elements, 3),
                .stiffness = core::SectionStiffness::from(material, section),
                .inertia = core::SectionInertia::from(material, section)});
    joints.push_back(std::make_unique<joints::SphericalJoint>(
        joints::Attachment{.node = core::beam(model, rod_index).node(0), .offset = Eigen::Vector3d::Zero()},
        joints::Attachment{.node = -1, .offset = Eigen::Vector3d::Zero()}, model.state()));
  } else {
    ancf = core::add_ancf_beam(
        model, {.end = Eigen::Vector3d(length, 0, 0), .elements = elements,
                .kind = ancf_element.kind(), .method = ancf_element.method(),
                .material = material, .section = core::SectionIntegrals::circle(radius)});
    // 3. The pin: the root node's position held at the origin.
    joints.push_back(std::make_unique<joints::PointJoint>(core::ancf_node_point(model.state(), ancf.nodes[0]),
                                                          Eigen::Vector3d::Zero(), model.state()));
  }
  const double preprocessing =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - preprocessing_start).count();
  const int tip = rod_index >= 0 ? core::beam(model, rod_index).node(core::beam(model, rod_index).control_point_count() - 1)
                                 : ancf.nodes.back();
  auto tip_position = [&](const core::Configuration& q) -> Eigen::Vector3d {
    return rod_index >= 0 ? q.position[tip] : core::ancf_node_position(q, tip);
  };
  auto centerline = [&](const core::Configuration& q) {
    return rod_index >= 0 ? core::beam(model, rod_index).sample_centerline(q, 10 * elements + 1)
                          : core::sample_ancf_centerline(q, ancf, 10 * elements + 1);
  };

  // 4. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(model, std::move(joints), run.dynamics);
  integrator.initialize();

  // 5. Record every step: the tip, the energies and the drift relative to m g L/2.
  study::Recorder rec(integrator, {.folder = out, .name = "ancf_pendulum", .time_step = h, .csv_digits = 15});
  rec.attributes({{"example", "ancf_pendulum"}, {"element", ancf_element.element}});
  if (!ancf_element.gebt()) rec.attributes({{"force", ancf_element.force}});
  rec.centerline(10 * elements + 1, [&](const study::State& s) { return centerline(s.q); });
  const study::Vector tip_point = rec.vector(
      {.name = "tip", .unit = "m", .description = "the free end r(x = L), inertial frame", .csv = "tip_x,tip_y,tip_z"},
      [&](const study::State& s) { return tip_position(s.q); });
  rec.vector({.name = "tip_velocity", .unit = "m/s", .description = "the free end's velocity", .csv = "tip_vx,tip_vy,tip_vz"},
             [&](const study::State& s) -> Eigen::Vector3d { return s.velocity.segment<3>(s.q.blocks[tip].offset); });
  rec.energy_balance();
  rec.total_energy();
  const study::Scalar drift = rec.energy_drift(energy_scale, {.description = "(E - E(0)) / (m g L / 2), a fraction"});
  const study::Scalar residual =
      rec.constraint_residual({.description = "largest violation |Phi|_inf of the joints after the step"});
  rec.newton_iterations();
  rec.csv({"tip", "tip_velocity", "kinetic_energy", "strain_energy", "gravity_potential", "total_energy", "energy_drift",
           "constraint_residual", "newton_iterations", "external_work", "numerical_dissipation"});
  rec.run(run.end_time);
  rec.close();

  // 6. The summary.
  const solvers::DynamicCounters& counters = integrator.counters();
  const Eigen::Vector3d r = tip_point.last();
  output::JsonSummary summary;
  summary.add("element", ancf_element.element);
  if (!ancf_element.gebt()) summary.add("force", ancf_element.force);  // only the options the run used
  summary.add("elements", elements).add("h", h).add("rho_inf", run.dynamics.spectral_radius).add("t_end", integrator.time())
      .add("steps", counters.steps).add("newton_iterations", counters.newton_iterations)
      .add("tip_x", r.x()).add("tip_y", r.y()).add("tip_z", r.z())
      .add("max_energy_drift", drift.max_abs()).add("max_constraint_residual", residual.max())
      .add("preprocessing_s", preprocessing).add("wall_s", counters.wall_seconds)
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
