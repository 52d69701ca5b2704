// truss_deployment — the deployable truss unit of 003 §5.3 (Table 4, eqs. 54–57, Figures 7–12):
// three square frames, eight cross-bars and eight diagonals of flexible tubes; the side diagonals
// slide along the frames' rods and lock when the unit is deployed.
//
// Sample runs:
//   truss_deployment --case 2 --law cosine          (003 case 2: 4 elements per member, h = 5 ms, 30 s)
//   truss_deployment --case 2 --law linear --elements 10    (003 Figure 9's convergence check)
//   truss_deployment --case 1                       (003 case 1: gravity 0.005 g along X, 1 element, h = 0.1 s)
//   scripts/truss_deployment.sh                     (case 2, the four laws, and the summary table)
//
// Description:
//   The geometry (003's Figure 7 is not in its text) is drawn and tabulated in README.md and
//   built by truss_model.hpp: frames 0, 1, 2 of side 2 m in planes X = const, two bays of four
//   4 m cross-bars hinged about Y folding as a Z, side diagonals of √20 m hinged at one frame and
//   sliding on the next frame's vertical rods, top and bottom diagonals hinged about Y. Frame 0 is
//   fixed; the unit starts folded at β = 5° and at rest.
//   Case 1: gravity 0.005 g along +X unfolds the unit; the run ends when all four sliders have
//   locked at their carriers' ends (003: "the calculation was terminated through a constraint of
//   ζ"). Case 2: no gravity; the four bar angles β_i follow one of the laws of eqs. (54)–(57) from
//   5° to 90° in t_f = 20 s; each driver hands over to its slider's lock when the slider reaches
//   the carrier's end (README, "Decisions"); the run goes on to 30 s, and the residual vibration
//   of D (the free frame's upper corner) after t_f is reported. Writes D's history (CSV), the
//   members' centerlines (HDF5 + XDMF for ParaView) and snapshots for the figures; the last line
//   of stdout is a JSON summary.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <cli.hpp>
#include <run_counters.hpp>
#include <energy_balance.hpp>
#include <newton_test.hpp>

#include "truss_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options; the defaults of h, t-end and elements are 003's for the chosen case.
  examples::CommandLine cli(argc, argv, "truss_deployment: the deployable truss unit of 003 section 5.3");
  const int load_case = cli.integer("--case", 2, "1: deployment under gravity 0.005 g along X; 2: driven by a law", 1, 2);
  const bool driven = load_case == 2;
  const std::string law = cli.text("--law", "cosine", "case 2: the deployment law (003 eqs. 54-57)",
                                   {"linear", "polynomial", "cycloid", "cosine"});
  const double t_f = cli.number("--t-f", 20.0, "case 2: deployment time of the law [s]", examples::Range::positive());
  const double h = cli.number("--h", driven ? 0.005 : 0.1, "time step [s] (003: 0.005 in case 2, 0.1 in case 1)",
                              examples::Range::positive());
  const double t_end = cli.number("--t-end", driven ? 30.0 : 100.0,
                                  "end time [s] (case 1 ends earlier, when the sliders have locked)",
                                  examples::Range::positive());
  examples::TrussParameters parameters;
  //    28 members per --elements (examples::memory_use::truss_deployment is per --elements).
  parameters.elements = cli.elements("--elements", driven ? 4 : 1,
                                     "quadratic NURBS elements per member (003: 1 in case 1, 4 in case 2)", 1,
                                     examples::memory_use::truss_deployment);
  const std::string strategy = cli.text("--strategy", "update", "iteration matrix", {"update", "frozen", "modified"});
  const std::string linear_solver = cli.text("--linear-solver", "klu", "sparse direct solver", {"klu", "umfpack", "eigen-lu"});
  const bool substructuring = cli.text("--substructuring", "on", "KLU by members where cheaper (docs/dynamics.md D12)", {"on", "off"}) == "on";
  const double rho_infinity = cli.number("--rho-inf", 0.9, "spectral radius at infinity", examples::Range::between(0, 1));
  //    003's test: the increment at 1e-6 (a squared norm) and Phi at 1e-10 m. Case 2 leaves the
  //    dynamic residual untested: with `update` the residual test at 1e-8 of its terms gives the
  //    same lock time and residual vibration to 4 digits for 1.16-1.33x the iterations. Case 1
  //    (h = 0.1 s) tests it: untested, the last lock comes 33 ms early (README, "Newton's test").
  const examples::NewtonTest newton = examples::newton_test_options(cli, driven ? INFINITY : 1e-8);
  const double output_interval = cli.number("--output-interval", driven ? 0.05 : 0.1,
                                            "time between the members' centerlines in the HDF5/XDMF file [s]",
                                            examples::Range::positive());
  const std::string out = cli.output_folder("--out", driven ? "results/truss_deployment/case2_" + law
                                                   : std::string("results/truss_deployment/case1"),
                                   "output folder");
  //    Case 1 has no law (gravity deploys the unit); substructuring is a way of using KLU.
  cli.applies_only_when("--law", "--case", {"2"});
  cli.applies_only_when("--t-f", "--case", {"2"});
  cli.applies_only_when("--substructuring", "--linear-solver", {"klu"});
  if (!cli.finish()) return 0;
  examples::time_steps(h, t_end);  // a span of no steps or of too many is refused
  if (driven)
    examples::require_within_run(t_f, "--t-f", "the law would not finish, and the unit would not deploy, by the end",
                                 t_end);
  examples::require_within_run(output_interval, "--output-interval",
                               "the file would hold the members' centerlines at t = 0 only", t_end);

  // 2. Build the folded unit of 003 Table 4 (truss_model.hpp), then the case's load: gravity
  //    along X, or the drivers of the law that hand over to the locks.
  examples::TrussUnit unit = examples::build_truss_unit(parameters);
  core::Model& model = unit.model;
  if (driven)
    examples::add_deployment_drivers(unit, law, t_f);
  else
    model.set_gravity(Eigen::Vector3d(0.005 * 9.81, 0.0, 0.0));

  // 3. The integrator, from rest at β₀. The linear law starts with a finite rate: the initial
  //    assembly projects the velocities onto it in the mass metric (an impulsive start,
  //    docs/dynamics.md D6a).
  solvers::GeneralizedAlpha integrator(
      model, std::move(unit.joints),
      {.time_step = h, .spectral_radius = rho_infinity,
       .iteration_matrix = solvers::iteration_matrix_from_string(strategy), .tolerance = newton.tolerance,
       .constraint_tolerance = newton.constraint_tolerance, .residual_tolerance = newton.residual_tolerance,
       .linear_solver = solvers::linear_solver_kind_from_string(linear_solver), .substructuring = substructuring});
  integrator.initialize();
  const core::Configuration& q = model.state();
  const auto zeta = [&](const examples::TrussSlider& s) { return s.joint->zeta(q); };
  //    β of a bay read off its slider: the side face's law of cosines (truss_model.hpp).
  const auto measured_angle = [&](const examples::TrussSlider& s) {
    const double a = parameters.frame_side, z = zeta(s);
    return examples::angle_from_slide(s.bay == 0 ? z : a - z, parameters);
  };

  // 4. Integrate, recording D and the sliders every step and the centerlines every output interval.
  std::filesystem::create_directories(out);
  const int samples = 4 * parameters.elements + 1;
  std::vector<core::CenterlineSampler> member_points;
  for (const examples::Member& m : unit.members) member_points.emplace_back(model.beam(m.beam), samples);
  std::vector<core::ResultsQuantity> scalars = {
      {.name = "constraint_residual", .unit = "m", .description = "largest constraint violation |Phi|_inf after the step"},
      {.name = "newton_iterations", .unit = "1", .description = "Newton iterations of the step", .integer = true}};
  for (const examples::TrussSlider& s : unit.sliders) {
    scalars.push_back({.name = "zeta_" + std::to_string(&s - unit.sliders.data()), .unit = "m",
                       .description = "coordinate of " + s.joint->name() + " on its carrier"});
    scalars.push_back({.name = "beta_" + std::to_string(&s - unit.sliders.data()), .unit = "rad",
                       .description = "bar angle of " + s.joint->name() + "'s face, from its slider"});
  }
  core::ResultsWriter results(
      out + "/truss_deployment.h5",
      {.node_count = model.block_count(), .velocities = false,
       .scalars = examples::followed_by(scalars, examples::energy_balance_layout()),
       .probes = {{.name = "D", .unit = "m", .description = "point D, the upper corner Y = 0 of frame 2"}},
       .centerline_points = std::vector<int>(unit.members.size(), samples)},
      10);
  results.write_attribute("example", "truss_deployment");
  results.write_attribute("case", load_case);
  results.write_attribute("law", driven ? law : std::string("gravity"));
  results.write_attribute("time_step", h);
  results.write_attribute("elements_per_member", parameters.elements);
  results.write_attribute("strategy", strategy);
  std::ofstream csv(out + "/truss_deployment.csv");
  csv.precision(12);
  csv << "t,d_x,d_y,d_z,zeta_0,zeta_1,zeta_2,zeta_3,beta_0,beta_1,beta_2,beta_3,kinetic_energy,strain_energy,"
      << examples::energy_balance_csv_columns << ",constraint_residual,newton_iterations\n";
  std::ofstream snapshots(out + "/truss_snapshots.csv");  // the folded, half-deployed, deployed and final shapes
  snapshots.precision(9);
  snapshots << "t,member,kind,x,y,z\n";
  const std::vector<double> snapshot_times =
      driven ? std::vector<double>{0.0, 0.5 * t_f, t_f, t_end} : std::vector<double>{0.0, t_end};
  double max_residual = 0.0, next_output = 0.0;
  const auto record = [&](bool last) {
    const solvers::Energies energy = integrator.energies();
    const double residual = integrator.constraint_residual(), t = integrator.time();
    max_residual = std::max(max_residual, residual);
    const Eigen::Vector3d d = q.position[unit.d_node];
    std::array<double, 4> zetas{}, betas{};
    for (std::size_t k = 0; k < unit.sliders.size(); ++k) {
      zetas[k] = zeta(unit.sliders[k]);
      betas[k] = measured_angle(unit.sliders[k]);
    }
    std::vector<double> row = {residual, static_cast<double>(integrator.last_step_iterations())};
    csv << t << ',' << d.x() << ',' << d.y() << ',' << d.z();
    for (const double z : zetas) csv << ',' << z;
    for (const double b : betas) csv << ',' << b;
    for (std::size_t k = 0; k < zetas.size(); ++k) row.insert(row.end(), {zetas[k], betas[k]});
    csv << ',' << energy.kinetic << ',' << energy.strain;
    examples::write_energy_balance_csv(csv, energy);
    csv << ',' << residual << ',' << integrator.last_step_iterations() << '\n';
    const bool snapshot = std::any_of(snapshot_times.begin(), snapshot_times.end(),
                                      [&](double ts) { return std::abs(t - ts) < 0.5 * h; });
    if (!(last || snapshot || t >= next_output - 0.5 * h)) return;
    std::vector<Eigen::MatrixXd> lines;
    for (const core::CenterlineSampler& points : member_points) lines.push_back(points.positions(q));
    if (last || snapshot) {
      for (std::size_t k = 0; k < lines.size(); ++k)
        for (Eigen::Index i = 0; i < lines[k].rows(); ++i)
          snapshots << t << ',' << k << ',' << static_cast<int>(unit.members[k].kind) << ',' << lines[k](i, 0)
                    << ',' << lines[k](i, 1) << ',' << lines[k](i, 2) << '\n';
      snapshots.flush();
    }
    results.append({.time = t, .configuration = &q,
                    .scalars = examples::followed_by(row, examples::energy_balance_values(energy)),
                    .probes = {d}, .centerlines = std::move(lines)});
    while (next_output <= t + 0.5 * h) next_output += output_interval;  // the next time not yet recorded
  };
  record(false);
  core::ProgressBar progress(t_end, "truss_deployment");
  const auto all_locked = [&] {
    return std::all_of(unit.sliders.begin(), unit.sliders.end(), [](const auto& s) { return s.joint->locked(); });
  };
  std::vector<double> d_z_after;  // D_z over t_f … t_end, case 2
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    const bool done = !driven && all_locked();
    record(done || integrator.time() >= t_end - 0.5 * h);
    if (driven && integrator.time() >= t_f - 0.5 * h) d_z_after.push_back(q.position[unit.d_node].z());
    progress.update(integrator.time(), integrator.counters().steps);
    if (done) break;
  }
  progress.finish();
  csv.flush();

  // 5. The summary: when the sliders locked, where D ended, and (case 2) D's residual vibration
  //    after the deployment: its Z deviation from its mean over t_f … t_end, RMS and peak.
  std::optional<double> lock_time;
  if (all_locked())
    lock_time = std::max_element(unit.sliders.begin(), unit.sliders.end(), [](const auto& a, const auto& b) {
                  return a.joint->lock_time() < b.joint->lock_time();
                })->joint->lock_time();
  std::optional<double> rms_z, peak_z;
  if (d_z_after.size() > 1) {
    double mean = 0.0;
    for (const double z : d_z_after) mean += z;
    mean /= static_cast<double>(d_z_after.size());
    double sum = 0.0, peak = 0.0;
    for (const double z : d_z_after) {
      sum += (z - mean) * (z - mean);
      peak = std::max(peak, std::abs(z - mean));
    }
    rms_z = std::sqrt(sum / static_cast<double>(d_z_after.size()));
    peak_z = peak;
  }
  const solvers::DynamicCounters& counters = integrator.counters();
  const auto& events = integrator.events();
  for (std::size_t k = 0; k < events.size(); ++k)
    results.write_attribute("event_" + std::to_string(k), std::to_string(events[k].first) + " s: " + events[k].second);
  if (lock_time) results.write_attribute("lock_time", *lock_time);
  examples::write_run_counters(results, integrator);
  results.close();
  const Eigen::Vector3d d = q.position[unit.d_node];
  std::printf("truss_deployment case %d (%s), %d elements per member, h = %g s, %s: sliders locked at",
              load_case, driven ? law.c_str() : "gravity 0.005 g", parameters.elements, h, strategy.c_str());
  for (const auto& s : unit.sliders)
    s.joint->locked() ? std::printf(" %.3f", s.joint->lock_time()) : std::printf(" (never)");
  std::printf(" s; D at (%.4f, %.4f, %.4f) m at t = %.3f s", d.x(), d.y(), d.z(), integrator.time());
  if (rms_z) std::printf("; D_z after t_f: RMS %.3e m, peak %.3e m", *rms_z, *peak_z);
  std::printf("; %ld steps, %ld Newton iterations, %ld factorizations, %.2f s; max constraint residual %.2e\n",
              counters.steps, counters.newton_iterations, counters.factorizations, counters.wall_seconds,
              max_residual);
  examples::JsonSummary()
      .add("case", load_case)
      .add("law", driven ? law : std::string("gravity"))
      .add("lock_time", lock_time)
      .add("d_x_final", d.x())
      .add("d_z_final", d.z())
      .add("rms_z_after_deployment", rms_z)
      .add("peak_z_after_deployment", peak_z)
      .add("max_constraint_residual", max_residual)
      .add("initial_velocity_correction", integrator.initial_assembly().largest_velocity_change)
      .add("h", h).add("elements", parameters.elements).add("strategy", strategy)
      .add("t_end", integrator.time())
      .add("steps", static_cast<int>(counters.steps))
      .add("newton_iterations", static_cast<int>(counters.newton_iterations))
      .add("factorizations", static_cast<int>(counters.factorizations))
      .add("substructured_factorizations", static_cast<int>(counters.substructured_factorizations))
      .add("cutbacks", static_cast<int>(counters.cutbacks))
      .add("wall_s", counters.wall_seconds)
      .print();
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
