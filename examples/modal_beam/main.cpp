// modal_beam — natural frequencies and mode shapes of a steel beam pinned at both ends by two
// spherical joints, against the exact frequencies of the simply supported Timoshenko beam.
//
// Sample runs:
//   modal_beam                                   (1 m, 20 × 10 mm, 64 cubic elements, 12 modes)
//   modal_beam --elements 8                      (a coarse mesh: the higher modes drift upward)
//   modal_beam --height 0.05 --out results/modal_beam_deep   (a deep section: Timoshenko matters)
//
// Description:
//   A straight steel beam (E = 210 GPa, ν = 0.3, ρ = 7850 kg/m³) along X, its end control
//   points held at the ground by spherical joints, is linearized about its unstressed reference
//   (solvers::modal_analysis, docs/dynamics.md D11: constraints in null-space form). The modes are
//   the free rigid turn about the axis (ω = 0), bending in the two planes, torsion and axial
//   modes. Each bending mode is matched with the simply supported Timoshenko beam's frequency
//   (rotary inertia included, the section's shear coefficients). The example writes the
//   frequencies and the control points' displacements of every mode to CSV; the last line of
//   stdout is a JSON summary with the largest relative difference of the bending modes found.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <memory_use.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

using namespace spar;

namespace {

/// The k-th bending frequency of a simply supported Timoshenko beam with rotary inertia (the
/// lower root s = ω² of ρAρI s² − (ρI κGA α² + ρA EI α² + ρA κGA) s + κGA EI α⁴ = 0, α = kπ/L;
/// docs/dynamics.md D11).
double timoshenko_pinned(int k, double length, double EI, double kGA, double rhoA, double rhoI) {
  const double alpha = k * std::numbers::pi / length;
  const double a = rhoA * rhoI, b = rhoI * kGA * alpha * alpha + rhoA * EI * alpha * alpha + rhoA * kGA,
               c = kGA * EI * std::pow(alpha, 4);
  return std::sqrt(2 * c / (b + std::sqrt(b * b - 4 * a * c)));
}

}  // namespace

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "modal_beam: modes of a pinned-pinned steel beam against Timoshenko's");
  //    The ranges of the other examples (docs/errors.md): lengths up to 10³ m (--length 1e300 ended
  //    in "the matrix is not orthogonal"), section sides up to 1 m.
  const double length = cli.number("--length", 1.0, "beam length [m]", study::Range::positive(1e3));
  const double width = cli.number("--width", 0.02, "section width, along the section axis 2 (Y) [m]", study::Range::positive(1));
  const double height = cli.number("--height", 0.01, "section height, along the section axis 3 (Z) [m]", study::Range::positive(1));
  const int elements = cli.elements("--elements", 64, "cubic NURBS elements", 1, examples::memory_use::modal_beam);
  const int mode_count = cli.integer("--modes", 12, "lowest modes to compute", 1, 1000);
  const std::string out = cli.output_folder("--out", "results/modal_beam", "output folder");
  if (!cli.finish()) return 0;
  //    A slender beam in both planes: Timoshenko's frequencies are a beam's. The dense eigensolver
  //    loses digits as (L/t)²: the bending modes' largest relative error is 2.5e-6, 2.4e-4, 2.2e-3
  //    at L/t = 100, 10³, 3·10³ (64 elements, L = 10⁻³ to 10³ m) and 5-68 % at 10⁴, so at most 3·10³.
  const bool width_thinner = width <= height;
  study::require_slender_beam(length, "--length", std::min(width, height), width_thinner ? "--width" : "--height",
                              std::max(width, height), width_thinner ? "--height" : "--width", 3e3);

  // 2. The beam and its two pins.
  const core::Material steel{.young_modulus = 210e9, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection section = core::CrossSection::rectangle(width, height, steel.poisson_ratio);
  core::Model model;
  const int b = core::add_beam(
      model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0), elements, 3),
              .stiffness = core::SectionStiffness::from(steel, section), .inertia = core::SectionInertia::from(steel, section)});
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  const core::Configuration& q = model.state();
  joints::SphericalJoint left(joints::Attachment{beam.node(0)}, joints::Attachment{-1}, q);
  joints::SphericalJoint right(joints::Attachment{beam.node(beam.control_point_count() - 1)},
                               joints::Attachment{-1, Eigen::Vector3d(length, 0, 0)}, q);

  // 3. The modes.
  const solvers::Modes modes = solvers::modal_analysis(model, {&left, &right}, {.modes = mode_count});

  // 4. Match the bending modes with Timoshenko's (both planes, k = 1, 2, …) and report.
  const core::SectionStiffness& C = beam.stiffness();
  const core::SectionInertia& J = beam.inertia();
  output::CsvFile csv(out + "/modal_beam.csv", "mode,frequency_hz,timoshenko_hz,relative_difference", 15);
  std::printf("modal_beam: %g m, %g x %g mm, %d elements\n  mode   f [Hz]          Timoshenko [Hz]   relative difference\n",
              length, 1e3 * width, 1e3 * height, elements);
  double worst = 0.0;
  int matched = 0;
  const Eigen::VectorXd f = modes.frequencies();
  // A bending mode moves the control points across the beam more than along it; the rigid turn
  // and torsion barely move them (the centerline is the axis), axial modes move them along it.
  Eigen::VectorXd transverse(f.size()), axial(f.size());
  for (int i = 0; i < f.size(); ++i) {
    transverse(i) = axial(i) = 0.0;
    for (int cp = 0; cp < beam.control_point_count(); ++cp) {
      const Eigen::Vector3d d = modes.shapes.col(i).segment<3>(q.blocks[beam.node(cp)].offset);
      transverse(i) += d.y() * d.y() + d.z() * d.z();
      axial(i) += d.x() * d.x();
    }
  }
  // The beam's spin about the line through its pins is a rigid mode (f ≈ 0) whose control points,
  // on the axis, barely move: their round-off could pass for a transverse motion, so a mode far
  // below the first Timoshenko frequency is never a bending mode.
  const double fundamental_hz =
      std::min(timoshenko_pinned(1, length, C.bending_2, C.shear_3, J.mass_per_length, J.rotary(1, 1)),
               timoshenko_pinned(1, length, C.bending_3, C.shear_2, J.mass_per_length, J.rotary(2, 2))) /
      (2 * std::numbers::pi);
  for (int i = 0; i < f.size(); ++i) {
    const bool bending = transverse(i) > axial(i) && transverse(i) > 1e-6 * transverse.maxCoeff() &&
                         f(i) > 1e-3 * fundamental_hz;
    // The nearest Timoshenko bending frequency, either plane, k ≤ 20 (a bending mode's reference).
    double reference = NAN, best = INFINITY;
    for (int k = 1; k <= 20; ++k)
      for (const double omega : {timoshenko_pinned(k, length, C.bending_2, C.shear_3, J.mass_per_length, J.rotary(1, 1)),
                                 timoshenko_pinned(k, length, C.bending_3, C.shear_2, J.mass_per_length, J.rotary(2, 2))}) {
        const double hz = omega / (2 * std::numbers::pi);
        if (std::abs(hz - f(i)) < best) best = std::abs(hz - f(i)), reference = hz;
      }
    const double difference = best / reference;
    if (bending) {
      worst = std::max(worst, difference);
      ++matched;
    }
    if (bending)
      std::printf("  %4d   %-14.8g  %-16.8g  %.2e\n", i + 1, f(i), reference, difference);
    else
      std::printf("  %4d   %-14.8g  %-16s  (not a bending mode)\n", i + 1, f(i), "-");
    csv.row({i + 1.0, f(i), bending ? reference : NAN, bending ? difference : NAN});
  }
  // The control points' displacements of every mode (x, y, z per control point, mode by mode).
  output::CsvFile shapes(out + "/modal_beam_shapes.csv", "mode,control_point,x0,dx,dy,dz", 15);
  for (int i = 0; i < modes.shapes.cols(); ++i)
    for (int cp = 0; cp < beam.control_point_count(); ++cp) {
      const int node = beam.node(cp);
      const Eigen::Vector3d d = modes.shapes.col(i).segment<3>(q.blocks[node].offset);
      shapes.row({i + 1.0, static_cast<double>(cp), q.position[node].x(), d.x(), d.y(), d.z()});
    }
  csv.close();
  shapes.close();
  output::JsonSummary()
      .add("elements", elements).add("modes", static_cast<int>(f.size())).add("bending_modes_matched", matched)
      .add("max_relative_error", matched > 0 ? std::optional<double>(worst) : std::nullopt)
      .add("first_frequency_hz", f.size() > 1 ? std::optional<double>(f(1)) : std::nullopt)
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
