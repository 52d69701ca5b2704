// flexible_pendulum — a slender steel rule pinned at one end, released from the horizontal at
// rest, swinging down under gravity; with ρ∞ = 1 the generalized-α method conserves its total
// energy to the integrator's accuracy.
//
// Sample runs:
//   flexible_pendulum                                   (h = 2.5e-4 s, 1 s, ρ∞ = 1, 8 elements)
//   flexible_pendulum --h 1e-3 --elements 4
//   flexible_pendulum --rho-inf 0.8 --out results/flexible_pendulum_rho08
//   flexible_pendulum --thickness 0.002                 (a stiffer rule: a quarter of the bending)
//
// Description:
//   A 1 m steel rule, 30 × 1 mm (E = 2.1e11 Pa, ν = 0.3, ρ = 7850 kg/m³; m = 0.236 kg,
//   EI = 0.525 N m² about its weak axis), lies along +X with its root at the origin, where a
//   spherical joint pins it to the ground; its flat side faces the fall, so it bends about its
//   weak axis. It is straight and at rest at t = 0; gravity (0, 0, −9.81) m/s² pulls it down, so
//   it swings in the XZ plane, reaches the vertical after about 0.47 s and bends on the way
//   (up to 2.8 % of its length away from its chord; first flexible pinned–free mode 3.7 Hz).
//   The rule is a geometrically exact beam on an open-uniform C² cubic NURBS mesh. The example
//   writes the tip trajectory, the rule's distance from its chord and the energies (kinetic,
//   strain, gravity potential, total) at every step. The energy drift is reported relative to
//   m g L / 2, the potential energy released between the horizontal and the vertical. The last
//   line of stdout is a JSON summary.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <centerline_fields.hpp>
#include <cli.hpp>
#include <run_counters.hpp>
#include <energy_balance.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

using namespace spar;

namespace {

/// A straight NURBS centerline from the origin along +X: open-uniform C^{p−1} knots, control
/// points at the Greville abscissae.
iga::NurbsCurve<3> straight_rod(double length, int elements, int degree) {
  const iga::KnotVector knots = iga::KnotVector::open_uniform(elements, degree, degree - 1);
  iga::NurbsCurve<3>::Points points = iga::NurbsCurve<3>::Points::Zero(3, knots.basis_count());
  const std::vector<double> greville = knots.greville();
  for (int i = 0; i < knots.basis_count(); ++i) points(0, i) = length * greville[i];
  return iga::NurbsCurve<3>(knots, points);
}

/// The rod's largest distance from its chord (root to tip) over 21 sample points, over L.
double chord_deflection(const core::GeometricallyExactBeam& rod, const core::Configuration& q, double length) {
  const Eigen::Vector3d root = rod.position_at(q, 0.0);
  const Eigen::Vector3d chord = (rod.position_at(q, 1.0) - root).normalized();
  double worst = 0.0;
  for (int i = 1; i < 20; ++i) {
    const Eigen::Vector3d r = rod.position_at(q, i / 20.0) - root;
    worst = std::max(worst, (r - r.dot(chord) * chord).norm());
  }
  return worst / length;
}

}  // namespace

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "flexible_pendulum: a pinned steel rule falling from the horizontal");
  const double h = cli.number("--h", 2.5e-4, "time step [s]", examples::Range::positive());
  const double t_end = cli.number("--t-end", 1.0, "end time [s]", examples::Range::positive());
  const double rho_infinity = cli.number("--rho-inf", 1.0, "spectral radius at infinity (1: no dissipation)",
                                          examples::Range::between(0, 1));
  const int elements = cli.elements("--elements", 8, "cubic NURBS elements", 1, examples::memory_use::flexible_pendulum);
  const double width = cli.number("--width", 0.03, "section width, out of the plane of the swing (Y) [m]",
                                    examples::Range::positive(0.5));
  const double thickness = cli.number("--thickness", 0.001, "section thickness, in the plane of the swing (Z) [m]",
                                        examples::Range::positive(0.5));
  const double tolerance = cli.number("--tolerance", 1e-20, "Newton: |[dq, h^2 beta dlambda]|^2",
                                        examples::newton_tolerances);
  const std::string out = cli.output_folder("--out", "results/flexible_pendulum", "output folder");
  if (!cli.finish()) return 0;
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused

  // 2. The rule: steel, flat rectangular section, pinned at the origin.
  const double length = 1.0;
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection section = core::CrossSection::rectangle(width, thickness, steel.poisson_ratio);
  core::Model model;
  const int rod_index = model.add_beam({.centerline = straight_rod(length, elements, 3),
                                        .stiffness = core::SectionStiffness::from(steel, section),
                                        .inertia = core::SectionInertia::from(steel, section)});
  const core::GeometricallyExactBeam& rod = model.beam(rod_index);
  const int root = rod.node(0);
  const Eigen::Vector3d gravity(0.0, 0.0, -9.81);
  model.set_gravity(gravity);
  const double mass = steel.density * width * thickness * length;
  const double energy_scale = 0.5 * mass * gravity.norm() * length;  // m g L / 2

  // 3. The pin: a spherical joint between the root control point (the rod's end, interpolated by
  //    the open knot vector) and the ground's origin.
  solvers::ConstraintList joints;
  joints.push_back(std::make_unique<joints::SphericalJoint>(
      joints::Attachment{.node = root, .offset = Eigen::Vector3d::Zero()},
      joints::Attachment{.node = -1, .offset = Eigen::Vector3d::Zero()}, model.state()));

  // 4. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(model, std::move(joints),
                                       {.time_step = h, .spectral_radius = rho_infinity, .tolerance = tolerance,
                                        .constraint_tolerance = 1e-12, .residual_tolerance = 1e-8});
  integrator.initialize();
  const core::Configuration initial_state = model.state();  // the reference geometry, for arc lengths
  const double initial_energy = integrator.energies().total();

  // 5. Integrate and record.
  const int samples = 10 * elements + 1;
  const examples::RecordedCenterline rod_line(rod, samples, initial_state);
  core::ResultsWriter results(out + "/flexible_pendulum.h5",
                              {.node_count = model.block_count(),
                               .multiplier_count = integrator.multiplier_count(),
                               .scalars = examples::followed_by<core::ResultsQuantity>({
                                           {.name = "total_energy", .unit = "J",
                                            .description = "kinetic + strain energy + gravity potential"},
                                           {.name = "energy_drift", .unit = "1",
                                            .description = "(E - E(0)) / (m g L / 2): total energy drift over the "
                                                           "energy released by the swing, a fraction"},
                                           {.name = "chord_deflection", .unit = "1",
                                            .description = "largest distance of the rule from its chord (21 points) "
                                                           "over its length L, a fraction (0.028 = 2.8 %)"},
                                           {.name = "constraint_residual", .unit = "m",
                                            .description = "largest violation |Phi|_inf of the pin after the step"},
                                           {.name = "newton_iterations", .unit = "1",
                                            .description = "Newton iterations (linear solves) of the step",
                                            .integer = true}},
                                           examples::energy_balance_layout()),
                               .probes = {{.name = "tip", .unit = "m",
                                           .description = "the rule's free end x(u = 1), inertial frame"}},
                               .centerline_points = {samples},
                               .centerline_fields = examples::centerline_field_layout()});
  results.write_attribute("example", "flexible_pendulum");
  results.write_attribute("time_step", h);
  results.write_attribute("rho_infinity", rho_infinity);
  std::ofstream csv(out + "/flexible_pendulum.csv");
  csv.precision(15);
  csv << "t,tip_x,tip_y,tip_z,chord_deflection,kinetic_energy,strain_energy,gravity_potential,"
         "total_energy,energy_drift,constraint_residual,newton_iterations,"
      << examples::energy_balance_csv_columns << '\n';
  double max_drift = 0.0, max_deflection = 0.0, max_residual = 0.0, drift = 0.0;
  auto record = [&]() {
    const core::Configuration& q = model.state();
    const Eigen::Vector3d tip = rod.position_at(q, 1.0);
    const solvers::Energies energy = integrator.energies();
    drift = (energy.total() - initial_energy) / energy_scale;
    const double deflection = chord_deflection(rod, q, length);
    const double residual = integrator.constraint_residual();
    max_drift = std::max(max_drift, std::abs(drift));
    max_deflection = std::max(max_deflection, deflection);
    max_residual = std::max(max_residual, residual);
    csv << integrator.time() << ',' << tip.x() << ',' << tip.y() << ',' << tip.z() << ',' << deflection << ','
        << energy.kinetic << ',' << energy.strain << ',' << energy.gravity << ',' << energy.total() << ','
        << drift << ',' << residual << ',' << integrator.last_step_iterations();
    examples::write_energy_balance_csv(csv, energy);
    csv << '\n';
    results.append({.time = integrator.time(), .configuration = &q, .velocity = &integrator.velocity(),
                    .multipliers = &integrator.multipliers(),
                    .scalars = examples::followed_by<double>(
                        {energy.total(), drift, deflection, residual,
                         static_cast<double>(integrator.last_step_iterations())},
                        examples::energy_balance_values(energy)),
                    .probes = {tip},
                    .centerlines = {rod_line.positions(q)},
                    .centerline_fields = {rod_line.fields(q, integrator.velocity())}});
  };
  record();
  core::ProgressBar progress(t_end, "flexible_pendulum");
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    record();
    progress.update(integrator.time(), integrator.counters().steps);
  }
  progress.finish();
  const solvers::DynamicCounters& counters = integrator.counters();
  examples::write_run_counters(results, integrator);
  results.close();

  // 6. Report.
  const Eigen::Vector3d tip = rod.position_at(model.state(), 1.0);
  std::printf("flexible_pendulum, h = %g s, rho_inf = %g, %d elements, t = %g s: %ld steps, %ld Newton "
              "iterations, %.3f s; tip (%.6f, %.6f, %.6f) m, max chord deflection %.2f %% of L, energy "
              "drift %.2e (max %.2e) of m g L/2 = %.4f J, max constraint residual %.2e m\n",
              h, rho_infinity, elements, integrator.time(), counters.steps, counters.newton_iterations,
              counters.wall_seconds, tip.x(), tip.y(), tip.z(), 100 * max_deflection, drift, max_drift,
              energy_scale, max_residual);
  examples::JsonSummary()
      .add("h", h).add("rho_inf", rho_infinity).add("elements", elements).add("t_end", integrator.time())
      .add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("factorizations", static_cast<int>(counters.factorizations))
      .add("cutbacks", static_cast<int>(counters.cutbacks))
      .add("wall_s", counters.wall_seconds)
      .add("tip_x", tip.x()).add("tip_y", tip.y()).add("tip_z", tip.z())
      .add("max_chord_deflection", max_deflection)
      .add("energy_scale", energy_scale).add("energy_drift", drift).add("max_energy_drift", max_drift)
      .add("max_constraint_residual", max_residual)
      .print();
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
