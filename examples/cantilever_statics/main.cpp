// cantilever_statics — a cantilever under a follower end moment (roll-up) or a dead tip load
// (large-deflection elastica), solved with the geometrically exact beam on NURBS and Newton
// statics in the Cardona–Géradin chart (003 §2–3; issue 4's validation example).
//
// Sample runs:
//   cantilever_statics                                   (roll-up into a full circle)
//   cantilever_statics --case rollup --load 3.14159265 --elements 16 --degree 3
//   cantilever_statics --case tip-load --load 10 --elements 32 --degree 2 --out results/tip
//
// Description:
//   A straight steel beam of length L along +X is clamped at the origin. Case `rollup` applies
//   a moment M = load · EI/L about the end section's material axis A₃ (a follower load); the
//   exact solution is an arc of radius L/load, a full circle for load = 2π. Case `tip-load`
//   applies a dead force P = load · EI/L² along +Y at the tip; the reference is the inextensible
//   Euler elastica, computed here by shooting (our beam also stretches and shears, which moves
//   the tip by O(EI/(EA L²)) ≈ 1e-5 L for the default section). The deformed centerline is
//   written to <out>/centerline.csv and <out>/cantilever_statics.h5 (docs/output.md); the last
//   line of stdout is a JSON summary.
#include <spar/spar.hpp>

#include <memory_use.hpp>

#include <cmath>
#include <numbers>

using namespace spar;

namespace {

/// The tip of the inextensible, unshearable Euler elastica under a dead tip force P along +Y:
/// EI θ″ = −P cos θ, θ(0) = 0, θ′(L) = 0, found by bisection on θ′(0) with RK4 (4000 steps).
/// A negative load bends the beam to −Y: the mirror image of the positive one.
Eigen::Vector2d elastica_tip(double load, double length) {
  if (load < 0.0) return elastica_tip(-load, length).cwiseProduct(Eigen::Vector2d(1.0, -1.0));
  const int steps = 4000;
  const double h = length / steps, p = load / (length * length);  // P/EI
  auto shoot = [&](double curvature0, Eigen::Vector2d& tip) {
    Eigen::Vector4d y(0.0, curvature0, 0.0, 0.0);  // θ, θ′, x, z
    auto f = [p](const Eigen::Vector4d& s) {
      return Eigen::Vector4d(s(1), -p * std::cos(s(0)), std::cos(s(0)), std::sin(s(0)));
    };
    for (int i = 0; i < steps; ++i) {
      const Eigen::Vector4d k1 = f(y), k2 = f(y + h / 2 * k1), k3 = f(y + h / 2 * k2), k4 = f(y + h * k3);
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    tip = Eigen::Vector2d(y(2), y(3));
    return y(1);  // θ′(L), zero at the solution
  };
  double lo = 0.0, hi = load / length;
  Eigen::Vector2d tip;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * (1 + hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    (shoot(mid, tip) > 0.0 ? hi : lo) = mid;
  }
  shoot(0.5 * (lo + hi), tip);
  return tip;
}

}  // namespace

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "cantilever_statics: roll-up and large-deflection cantilever (issue 4)");
  const std::string load_case = cli.text("--case", "rollup", "rollup | tip-load", {"rollup", "tip-load"});
  const double load = cli.number("--load", 2 * std::numbers::pi, "M L/EI (rollup) or P L^2/EI (tip-load)",
                                 study::Range::between(-100, 100));
  const int elements = cli.elements("--elements", 16, "number of NURBS elements", 1, examples::memory_use::cantilever_statics);
  const int degree = cli.integer("--degree", 3, "NURBS degree p (C^{p-1} continuity)", 1, iga::max_degree);
  const int load_steps = cli.integer("--steps", 10, "initial number of load steps", 1, 100000);
  const double length = cli.number("--length", 1.0, "beam length L [m]", study::Range::positive(1e3));
  const double width = cli.number("--width", 0.01, "side of the square steel section [m]", study::Range::positive(1));
  const std::string out = cli.output_folder("--out", "results/cantilever_statics", "output folder");
  if (!cli.finish()) return 0;
  study::require_slender_beam(length, "--length", width, "--width", width, "--width");  // before solving

  // 2. Build the beam: straight along +X (open-uniform C^{p-1} NURBS), steel square section.
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::SectionStiffness stiffness =
      core::SectionStiffness::from(steel, core::CrossSection::rectangle(width, width, 0.3));
  core::Model model;
  const int b = core::add_beam(
      model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0), elements, degree),
              .stiffness = stiffness});
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  const int root = beam.node(0), tip = beam.node(beam.control_point_count() - 1);

  // 3. Clamp the root and load the tip.
  model.fix(root);
  const double EI = stiffness.bending_3;
  if (load_case == "rollup")
    core::add_load(model, core::NodalMoment{.node = tip, .moment = Eigen::Vector3d(0, 0, load * EI / length),
                                     .frame = core::MomentFrame::material});
  else
    core::add_load(model, core::NodalForce{.node = tip, .force = Eigen::Vector3d(0, load * EI / (length * length), 0)});

  // 4. Solve.
  const core::Configuration undeformed_state = model.state();
  const solvers::StaticReport report = solvers::solve_static(model, {.load_steps = load_steps});
  study::warn_if_unstable(report);

  // 5. Compare with the analytical solution.
  const Eigen::Vector3d tip_position = model.state().position[tip] - model.state().position[root];
  Eigen::Vector3d reference;
  if (load_case == "rollup") {
    // An arc of radius L/load (κ = M/EI) through the angle load; the straight beam at load 0.
    const double radius = length / load;
    reference = load == 0.0 ? Eigen::Vector3d(length, 0.0, 0.0)
                            : Eigen::Vector3d(radius * std::sin(load), radius * (1 - std::cos(load)), 0.0);
  } else {
    const Eigen::Vector2d elastica = elastica_tip(load, length);
    reference = Eigen::Vector3d(elastica(0), elastica(1), 0.0);
  }
  const double error = (tip_position - reference).norm() / length;

  // 6. Write the deformed centerline (CSV and HDF5).
  const int samples = 10 * elements + 1;
  const Eigen::MatrixXd centerline = beam.sample_centerline(model.state(), samples);
  const Eigen::MatrixXd undeformed = beam.sample_centerline(undeformed_state, samples);
  output::CsvFile csv(out + "/centerline.csv", "u,x,y,z,x0,y0,z0", 6);
  for (int i = 0; i < samples; ++i)
    csv.row({static_cast<double>(i) / (samples - 1), centerline(i, 0), centerline(i, 1), centerline(i, 2),
             undeformed(i, 0), undeformed(i, 1), undeformed(i, 2)});
  csv.close();
  output::Hdf5File h5(out + "/cantilever_statics.h5");
  h5.write_attribute("case", load_case);
  h5.write_attribute("load", load);
  h5.write_options(cli.options());
  h5.write("centerline/deformed", centerline, "m",
           "deformed centerline at 10 points per element + 1, equally spaced in the knot parameter");
  h5.write("centerline/reference", undeformed, "m", "the same parameters on the reference (straight) centerline");
  Eigen::MatrixXd control_points(beam.control_point_count(), 3);
  for (int I = 0; I < beam.control_point_count(); ++I)
    control_points.row(I) = model.state().position[beam.node(I)].transpose();
  h5.write("control_points", control_points, "m", "deformed control points (the beam's nodes), root to tip");

  // 7. The summary.
  output::JsonSummary()
      .add("case", load_case).add("load", load).add("degree", degree).add("elements", elements).add("length", length)
      .add("tip_x", tip_position.x()).add("tip_y", tip_position.y()).add("tip_z", tip_position.z())
      .add("reference_tip_x", reference.x()).add("reference_tip_y", reference.y()).add("relative_tip_error", error)
      .add("load_steps", static_cast<int>(report.steps.size())).add("newton_iterations", report.newton_iterations)
      .add("wall_s", report.wall_seconds).add("unstable_directions", report.unstable_directions)
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
