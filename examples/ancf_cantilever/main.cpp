// ancf_cantilever — the static cantilever of paper 001 (Song, Chen & Chen 2021, §6, Table 1)
// with the fully parameterized 3D ANCF beam elements (issue 13): a tip force on a clamped
// circular aluminium beam, small deflection, against Euler–Bernoulli theory F L³/(3EI).
//
// Sample runs:
//   ancf_cantilever                                      (24 coordinates, method II, 8 elements)
//   ancf_cantilever --element 30 --force invariant --elements 16
//   ancf_cantilever --poisson 0 --elements 32 --out results/ancf_cantilever_nu0
//   ancf_cantilever --element gebt --elements 8          (the geometrically exact beam, for comparison)
//   ancf_cantilever --section paper                      (only A, I_y, I_z as in 001 eq. 47)
//   ancf_cantilever --element 30 --remedy uniaxial-bending (bending in uniaxial stress: no Poisson locking)
//
// Description:
//   L = 1 m along +X, circular section r = 0.01 m, E = 72 GPa, ν = 0.33 (option), ρ = 2700.
//   The root node's 12 coordinates are fixed (clamp: r, r_x, r_y, r_z), a dead force of 10 N
//   along −Y acts on the tip node's position. Theory: F L³/(3EI) = 5.8946 mm; the paper reports
//   4.1331 mm (method I), 4.1328 mm (method II) and 5.7921 mm (method III, the 30-coordinate
//   element). The fully parameterized element with ν ≠ 0 suffers Poisson locking: its transverse
//   gradients are constant across the section, so a bent fibre cannot contract laterally and
//   bending is stiffened by (1 − ν)/((1 + ν)(1 − 2ν)) ≈ 1.48 at ν = 0.33 (docs/ancf.md §6);
//   `--remedy uniaxial-bending` removes it. The deformed centerline goes to
//   <out>/centerline.csv and <out>/ancf_cantilever.h5 (+ .xmf); the last stdout line is a JSON
//   summary.
#include <spar/spar.hpp>

#include <ancf_options.hpp>
#include <memory_use.hpp>

#include <cmath>
#include <numbers>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "ancf_cantilever: paper 001's static cantilever (Table 1)");
  const examples::AncfChoice ancf_element = examples::ancf_options(cli, true);
  const std::string& element = ancf_element.element;
  const int elements = cli.elements("--elements", 8, "number of elements", 1, examples::memory_use::ancf_cantilever);
  const double poisson = cli.number("--poisson", 0.33, "Poisson's ratio", {-1, 0.5, true, true});
  const std::string section_kind = cli.text("--section", "exact", "exact (moments to order 4) | paper (A, I only)",
                                            {"exact", "paper"});
  const std::string remedy = cli.text("--remedy", "none", "Poisson locking remedy: none | uniaxial-bending",
                                      {"none", "uniaxial-bending"});
  const double tip_force = cli.number("--force-n", 10.0, "tip force along -Y [N], not 0", study::Range::between(-1e6, 1e6));
  const std::string out = cli.output_folder("--out", "results/ancf_cantilever", "output folder");
  //    The ANCF element's options mean nothing to the geometrically exact beam.
  for (const char* ancf_option : {"--section", "--remedy"})
    cli.applies_only_when(ancf_option, "--element", {"24", "30"});
  if (!cli.finish()) return 0;
  //    The example compares the deflection with F L³/(3EI): with no force there is none to compare.
  if (tip_force == 0.0)
    throw Error("--force-n 0 loads nothing: the deflection's ratio to Euler-Bernoulli's F L^3/(3EI) is 0/0",
                "option --force-n", "give a nonzero force, e.g. 10 (along -Y) or -10 (along +Y)");

  // 2. The beam of 001 §6.
  const double length = 1.0, radius = 0.01;
  const core::Material aluminium{.young_modulus = 72e9, .poisson_ratio = poisson, .density = 2700};
  const double EI = aluminium.young_modulus * std::numbers::pi * std::pow(radius, 4) / 4;
  const double theory = tip_force * std::pow(length, 3) / (3 * EI);
  core::Model model;
  int root = 0, tip = 0;
  core::AncfBeam ancf;
  const int gebt_index = [&] {
    if (element == "gebt") {
      const int b = core::add_beam(
          model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0), elements, 3),
                  .stiffness = core::SectionStiffness::from(aluminium, core::CrossSection::circle(2 * radius, poisson))});
      root = core::beam(model, b).node(0);
      tip = core::beam(model, b).node(core::beam(model, b).control_point_count() - 1);
      return b;
    }
    const auto section = core::SectionIntegrals::circle(radius);
    ancf = core::add_ancf_beam(
        model, {.end = Eigen::Vector3d(length, 0, 0), .elements = elements,
                .kind = ancf_element.kind(), .method = ancf_element.method(),
                .remedy = remedy == "none" ? core::AncfLockingRemedy::none : core::AncfLockingRemedy::uniaxial_bending,
                .material = aluminium,
                .section = section_kind == "exact" ? section : section.truncated_to_second_order()});
    root = ancf.nodes.front();
    tip = ancf.nodes.back();
    return -1;
  }();

  // 3. Clamp the root (all coordinates of its block) and load the tip along −Y.
  model.fix(root);
  const Eigen::Vector3d load(0, -tip_force, 0);
  if (gebt_index >= 0) core::add_load(model, core::NodalForce{.node = tip, .force = load});
  else core::add_ancf_nodal_force(model, tip, load);

  // 4. Solve (one load step suffices for this small deflection; Newton converges quadratically).
  const solvers::StaticReport report = solvers::solve_static(model, {.load_steps = 1});
  study::warn_if_unstable(report);

  // 5. The tip deflection, and its ratio to Euler-Bernoulli's: the tip's displacement along the
  //    force over F L³/(3EI), the same for a force along −Y (--force-n > 0) and its mirror image.
  const Eigen::Vector3d tip_position =
      gebt_index >= 0 ? model.state().position[tip] : core::ancf_node_position(model.state(), tip);
  const double deflection = (tip_position - Eigen::Vector3d(length, 0, 0)).norm();
  const double ratio = -tip_position.y() / theory;

  // 6. Write the deformed centerline (CSV and HDF5).
  const int samples = 10 * elements + 1;
  const Eigen::MatrixXd centerline = gebt_index >= 0 ? core::beam(model, gebt_index).sample_centerline(model.state(), samples)
                                                     : core::sample_ancf_centerline(model.state(), ancf, samples);
  output::CsvFile csv(out + "/centerline.csv", "s,x,y,z,euler_bernoulli_y", 6);
  for (int i = 0; i < samples; ++i) {
    const double s = length * i / (samples - 1);
    const double theory_y = -tip_force * s * s * (3 * length - s) / (6 * EI);
    csv.row({s, centerline(i, 0), centerline(i, 1), centerline(i, 2), theory_y});
  }
  csv.close();
  // One "step" of the results file (docs/output.md): the deformed centerline as an XDMF polyline.
  output::ResultsWriter results(out + "/ancf_cantilever.h5",
                              {.node_count = 0, .velocities = false,
                               .scalars = {{.name = "tip_deflection", .unit = "m",
                                            .description = "magnitude of the tip's displacement under the load"}},
                               .probes = {{.name = "tip", .unit = "m", .description = "the tip r(x = L), inertial frame"}},
                               .centerline_points = {samples}});
  results.write_attribute("example", "ancf_cantilever");
  results.write_attribute("element", element);
  if (gebt_index < 0) {
    results.write_attribute("force", ancf_element.force);
    results.write_attribute("remedy", remedy);
  }
  results.write_attribute("poisson_ratio", poisson);
  results.write_options(cli.options());
  results.append({.time = 1.0, .scalars = {deflection}, .probes = {tip_position}, .centerlines = {centerline}});
  results.close();

  // 7. The summary: only the options the run used (the ANCF element's for the ANCF element).
  output::JsonSummary summary;
  summary.add("element", element);
  if (gebt_index < 0) summary.add("force", ancf_element.force).add("section", section_kind).add("remedy", remedy);
  summary.add("elements", elements).add("poisson", poisson).add("tip_deflection", deflection).add("euler_bernoulli", theory)
      .add("ratio", ratio).add("newton_iterations", report.newton_iterations).add("wall_s", report.wall_seconds)
      .add("unstable_directions", report.unstable_directions)
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
