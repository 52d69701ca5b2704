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
//   writes the tip trajectory, the rule's distance from its chord, the energies (kinetic,
//   strain, gravity potential, total) and the section forces and moments at every step. The
//   energy drift is reported relative to m g L / 2, the potential energy released between the
//   horizontal and the vertical. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>

#include <memory_use.hpp>

#include <algorithm>

using namespace spar;

namespace {

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
  study::CommandLine cli(argc, argv, "flexible_pendulum: a pinned steel rule falling from the horizontal");
  const double h = cli.number("--h", 2.5e-4, "time step [s]", study::Range::positive());
  const double t_end = cli.number("--t-end", 1.0, "end time [s]", study::Range::positive());
  const double rho_infinity = cli.number("--rho-inf", 1.0, "spectral radius at infinity (1: no dissipation)",
                                         study::Range::between(0, 1));
  const int elements = cli.elements("--elements", 8, "cubic NURBS elements", 1, examples::memory_use::flexible_pendulum);
  const double width = cli.number("--width", 0.03, "section width, out of the plane of the swing (Y) [m]",
                                  study::Range::positive(0.5));
  const double thickness = cli.number("--thickness", 0.001, "section thickness, in the plane of the swing (Z) [m]",
                                      study::Range::positive(0.5));
  const double tolerance = cli.number("--tolerance", 1e-20, "Newton: |[dq, h^2 beta dlambda]|^2",
                                      study::newton_tolerances);
  const std::string out = cli.output_folder("--out", "results/flexible_pendulum", "output folder");
  if (!cli.finish()) return 0;
  study::time_steps(h, t_end);  // a span of no steps or of too many is refused

  // 2. The rule: steel, flat rectangular section, pinned at the origin.
  const double length = 1.0;
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection section = core::CrossSection::rectangle(width, thickness, steel.poisson_ratio);
  core::Model model;
  const int rod_index = core::add_beam(
      model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0), elements, 3),
              .stiffness = core::SectionStiffness::from(steel, section),
              .inertia = core::SectionInertia::from(steel, section)});
  const core::GeometricallyExactBeam& rod = core::beam(model, rod_index);
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

  // 5. Record every step (docs/output.md, "flexible_pendulum"): the tip, the rule's distance from
  //    its chord, the energies and the drift relative to m g L / 2, the section forces and moments.
  study::Recorder rec(integrator, {.folder = out, .name = "flexible_pendulum", .time_step = h, .nodes = true,
                                   .velocities = true, .multipliers = true, .centerline_fields = true,
                                   .csv_digits = 15});
  rec.attributes({{"example", "flexible_pendulum"}, {"rho_infinity", rho_infinity}});
  rec.centerline(core::CenterlineSampler(rod, 10 * elements + 1));
  const study::Vector tip =
      rec.vector({.name = "tip", .unit = "m", .description = "the rule's free end x(u = 1), inertial frame",
                  .csv = "tip_x,tip_y,tip_z"},
                 [&](const study::State& s) { return rod.position_at(s.q, 1.0); });
  const study::Scalar deflection = rec.scalar(
      {.name = "chord_deflection", .unit = "1",
       .description = "largest distance of the rule from its chord (21 points) over its length L, a fraction "
                      "(0.028 = 2.8 %)"},
      [&](const study::State& s) { return chord_deflection(rod, s.q, length); });
  rec.energy_balance();
  rec.total_energy();
  const study::Scalar drift = rec.energy_drift(
      energy_scale, {.description = "(E - E(0)) / (m g L / 2): total energy drift over the energy released by the "
                                    "swing, a fraction"});
  const study::Scalar residual =
      rec.constraint_residual({.description = "largest violation |Phi|_inf of the pin after the step"});
  rec.newton_iterations();
  //    The section forces and moments along the rule (docs/beam.md B16), inertial frame.
  const core::SectionPoints sections = core::section_points(rod);
  rec.profile({.name = "section_force", .unit = "N", .description = "R n at the Gauss points, inertial frame"},
              sections.arc_length, 3,
              [&](const study::State& s) { return core::section_resultants(rod, s.q, sections).force; });
  rec.profile({.name = "section_moment", .unit = "N m", .description = "R m at the Gauss points, inertial frame"},
              sections.arc_length, 3,
              [&](const study::State& s) { return core::section_resultants(rod, s.q, sections).moment; });
  rec.csv({"tip", "chord_deflection", "kinetic_energy", "strain_energy", "gravity_potential", "total_energy",
           "energy_drift", "constraint_residual", "newton_iterations", "external_work", "numerical_dissipation"});
  rec.run(t_end);
  rec.close();

  // 6. The summary.
  const Eigen::Vector3d end = tip.last();
  rec.summary()
      .add("h", h).add("rho_inf", rho_infinity).add("elements", elements).add("t_end", integrator.time())
      .add("tip_x", end.x()).add("tip_y", end.y()).add("tip_z", end.z())
      .add("max_chord_deflection", deflection.max())
      .add("energy_scale", energy_scale).add("energy_drift", drift.last()).add("max_energy_drift", drift.max_abs())
      .add("max_constraint_residual", residual.max())
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
