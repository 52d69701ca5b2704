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
#include <spar/joints/joints.hpp>
#include <spar/spar.hpp>

#include <cli.hpp>
#include <energy_balance.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "ancf_pendulum: paper 001's flexible pendulum (Figures 3-7)");
  const std::string element = cli.text("--element", "24", "24 | 30 (ANCF coordinates per element) | gebt",
                                       {"24", "30", "gebt"});
  const std::string force = cli.text("--force", "gerstmayr", "invariant (method I) | gerstmayr (method II)",
                                     {"invariant", "gerstmayr"});
  const int elements = cli.elements("--elements", 8, "number of elements", 1, examples::memory_use::ancf_pendulum);
  const double h = cli.number("--h", 1e-3, "time step [s]", examples::Range::positive());
  const double t_end = cli.number("--t-end", 1.0, "end time [s]", examples::Range::positive());
  const double rho_infinity = cli.number("--rho-inf", 0.9, "spectral radius at infinity", examples::Range::between(0, 1));
  const std::string out = cli.output_folder("--out", "results/ancf_pendulum", "output folder");
  cli.applies_only_when("--force", "--element", {"24", "30"});  // the ANCF element's elastic forces
  if (!cli.finish()) return 0;
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused

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
  if (element == "gebt") {
    const core::CrossSection section = core::CrossSection::circle(2 * radius, material.poisson_ratio);
    rod_index = model.add_beam({.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0), elements, 3),
                                .stiffness = core::SectionStiffness::from(material, section),
                                .inertia = core::SectionInertia::from(material, section)});
    joints.push_back(std::make_unique<joints::SphericalJoint>(
        joints::Attachment{.node = model.beam(rod_index).node(0), .offset = Eigen::Vector3d::Zero()},
        joints::Attachment{.node = -1, .offset = Eigen::Vector3d::Zero()}, model.state()));
  } else {
    ancf = core::add_ancf_beam(
        model, {.end = Eigen::Vector3d(length, 0, 0), .elements = elements,
                .kind = element == "24" ? core::AncfElementKind::standard_24 : core::AncfElementKind::higher_order_30,
                .method = force == "invariant" ? core::AncfForceMethod::invariant : core::AncfForceMethod::gerstmayr,
                .material = material, .section = core::SectionIntegrals::circle(radius)});
    // 3. The pin: the root node's position held at the origin.
    joints.push_back(std::make_unique<joints::PointJoint>(core::ancf_node_point(model.state(), ancf.nodes[0]),
                                                                  Eigen::Vector3d::Zero(), model.state()));
  }
  const double preprocessing =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - preprocessing_start).count();
  const int tip = rod_index >= 0 ? model.beam(rod_index).node(model.beam(rod_index).control_point_count() - 1)
                                 : ancf.nodes.back();
  auto tip_position = [&](const core::Configuration& q) -> Eigen::Vector3d {
    return rod_index >= 0 ? q.position[tip] : core::ancf_node_position(q, tip);
  };
  const int samples = 10 * elements + 1;
  auto centerline = [&](const core::Configuration& q) {
    return rod_index >= 0 ? model.beam(rod_index).sample_centerline(q, samples) : core::sample_ancf_centerline(q, ancf, samples);
  };

  // 4. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(model, std::move(joints),
                                       {.time_step = h, .spectral_radius = rho_infinity, .tolerance = 1e-20,
                                        .constraint_tolerance = 1e-12, .residual_tolerance = 1e-8});
  integrator.initialize();
  const double initial_energy = integrator.energies().total();

  // 5. Integrate and record.
  core::ResultsWriter results(out + "/ancf_pendulum.h5",
                              {.node_count = 0, .velocities = false,
                               .scalars = examples::followed_by<core::ResultsQuantity>(
                                   {{.name = "total_energy", .unit = "J", .description = "kinetic + strain energy + gravity potential"},
                                    {.name = "energy_drift", .unit = "1",
                                     .description = "(E - E(0)) / (m g L / 2), a fraction"},
                                    {.name = "constraint_residual", .unit = "m",
                                     .description = "largest violation |Phi|_inf of the joints after the step"},
                                    {.name = "newton_iterations", .unit = "1",
                                     .description = "Newton iterations (linear solves) of the step", .integer = true}},
                                   examples::energy_balance_layout()),
                               .probes = {{.name = "tip", .unit = "m", .description = "the free end r(x = L), inertial frame"},
                                          {.name = "tip_velocity", .unit = "m/s", .description = "the free end's velocity"}},
                               .centerline_points = {samples}});
  results.write_attribute("example", "ancf_pendulum");
  results.write_attribute("element", element);
  if (element != "gebt") results.write_attribute("force", force);
  results.write_attribute("time_step", h);
  std::ofstream csv(out + "/ancf_pendulum.csv");
  csv.precision(15);
  csv << "t,tip_x,tip_y,tip_z,tip_vx,tip_vy,tip_vz,kinetic_energy,strain_energy,gravity_potential,total_energy,"
         "energy_drift,constraint_residual,newton_iterations," << examples::energy_balance_csv_columns << '\n';
  double max_drift = 0.0, max_residual = 0.0, drift = 0.0;
  auto record = [&]() {
    const core::Configuration& q = model.state();
    const Eigen::Vector3d r = tip_position(q);
    const Eigen::Vector3d v = integrator.velocity().segment<3>(q.blocks[tip].offset);
    const solvers::Energies energy = integrator.energies();
    drift = (energy.total() - initial_energy) / energy_scale;
    const double residual = integrator.constraint_residual();
    max_drift = std::max(max_drift, std::abs(drift));
    max_residual = std::max(max_residual, residual);
    csv << integrator.time() << ',' << r.x() << ',' << r.y() << ',' << r.z() << ',' << v.x() << ',' << v.y() << ','
        << v.z() << ',' << energy.kinetic << ',' << energy.strain << ',' << energy.gravity << ',' << energy.total()
        << ',' << drift << ',' << residual << ',' << integrator.last_step_iterations();
    examples::write_energy_balance_csv(csv, energy);
    csv << '\n';
    results.append({.time = integrator.time(),
                    .scalars = examples::followed_by<double>(
                        {energy.total(), drift, residual, static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {r, v},
                    .centerlines = {centerline(q)}});
  };
  record();
  core::ProgressBar progress(t_end, "ancf_pendulum");
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    record();
    progress.update(integrator.time(), integrator.counters().steps);
  }
  progress.finish();
  results.close();
  const solvers::DynamicCounters& counters = integrator.counters();

  // 6. Report.
  const Eigen::Vector3d r = tip_position(model.state());
  std::printf("ancf_pendulum, %s%s, %d elements, h = %g s, rho_inf = %g, t = %g s: %ld steps, %ld Newton "
              "iterations, %.3f s; tip (%.6f, %.6f, %.6f) m, energy drift %.2e (max %.2e) of m g L/2 = %.2f J, "
              "max constraint residual %.2e m\n",
              element.c_str(), element == "gebt" ? "" : (" (" + force + ")").c_str(), elements, h, rho_infinity,
              integrator.time(), counters.steps, counters.newton_iterations, counters.wall_seconds, r.x(), r.y(),
              r.z(), drift, max_drift, energy_scale, max_residual);
  examples::JsonSummary summary;
  summary.add("element", element);
  if (element != "gebt") summary.add("force", force);  // only the options the run used
  summary.add("elements", elements).add("h", h)
      .add("rho_inf", rho_infinity).add("t_end", integrator.time())
      .add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("tip_x", r.x()).add("tip_y", r.y()).add("tip_z", r.z())
      .add("max_energy_drift", max_drift).add("max_constraint_residual", max_residual)
      .add("preprocessing_s", preprocessing).add("wall_s", counters.wall_seconds)
      .print();
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
