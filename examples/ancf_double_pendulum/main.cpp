// ancf_double_pendulum — the spatial flexible double pendulum of paper 001 (Song, Chen & Chen
// 2021, §6, Figures 8–11, Table 2) with the 3D ANCF beam elements (issue 13).
//
// Sample runs:
//   ancf_double_pendulum                                   (24 coordinates, method II, mesh (2, 5), 3 s, h = 1e-4)
//   ancf_double_pendulum --force invariant --elements-oa 4 --elements-ab 6
//   ancf_double_pendulum --element 30 --t-end 0.5 --h 1e-3 --out results/ancf_double_pendulum_quick
//   ancf_double_pendulum --iteration-matrix update         (full Newton: 2.1 iterations a step, each refactorized)
//
// Description:
//   Link OA (0.5 m) and link AB (0.8 m), circular, diameter 0.02 m, E = 300 MPa, ν = 0,
//   ρ = 7200 kg/m³. Ball joints: O (OA's first node) to the ground at the origin, A (OA's last
//   node to AB's first node). The paper's Figure 8, which showed the initial configuration, is
//   lost; we choose a spatial one: OA along +X and AB along +Y, both horizontal, at rest, gravity
//   (0, 0, −9.81) m/s². The links fall, swing and twist out of any plane. Lie-group
//   generalized-α with ρ∞ = 0.9, index 3. Time histories (positions of A and B, energies,
//   constraint residual) go to <out>/ancf_double_pendulum.csv and .h5 (+ .xmf); the energy drift
//   is relative to m₁ g OA/2 + m₂ g (OA + AB/2) and includes the numerical dissipation of ρ∞. The
//   last stdout line is a JSON summary with the preprocessing and simulation times that the
//   paper's Table 2 lists (582.7 s to 1942.5 s there).
#include <spar/spar.hpp>

#include <ancf_options.hpp>
#include <memory_use.hpp>

#include <chrono>
#include <numbers>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "ancf_double_pendulum: paper 001's spatial double pendulum (Table 2)");
  const examples::AncfChoice ancf = examples::ancf_options(cli, false);
  const int elements_oa = cli.elements("--elements-oa", 2, "elements on link OA", 1, examples::memory_use::ancf_double_pendulum);
  const int elements_ab = cli.elements("--elements-ab", 5, "elements on link AB", 1, examples::memory_use::ancf_double_pendulum);
  //    The Newton tests and the refactorization of modified Newton: step 4.
  study::Integration run = study::integrator_options(
      cli, {.time_step = 1e-4, .iteration_matrix = solvers::IterationMatrix::modified, .tolerance = 1e-16,
            .constraint_tolerance = 1e-12, .residual_tolerance = 1e-8},
      {.end_time = 3.0, .iteration_matrix_option = "--iteration-matrix", .newton = study::NewtonOptions::tolerance});
  const double h = run.dynamics.time_step;
  run.dynamics.modified_newton_contraction =
      cli.number("--refactor-contraction", 0.02,
                 "modified Newton refactorizes when an increment exceeds this times the previous one",
                 study::Range::positive(1.0));
  const int record_every = cli.integer("--record-every", 10, "steps between HDF5 records", 1);
  const std::string out = cli.output_folder("--out", "results/ancf_double_pendulum", "output folder");
  cli.applies_only_when("--refactor-contraction", "--iteration-matrix", {"modified"});  // modified Newton's test
  if (!cli.finish()) return 0;
  study::require_memory(static_cast<double>(elements_oa) + elements_ab, examples::memory_use::ancf_double_pendulum,
                        "options --elements-oa, --elements-ab");  // the two links together

  // 2. The two links (001 §6), OA along +X from the origin, AB along +Y from A.
  const auto preprocessing_start = std::chrono::steady_clock::now();
  const double oa = 0.5, ab = 0.8, radius = 0.01;
  const core::Material material{.young_modulus = 300e6, .poisson_ratio = 0.0, .density = 7200};
  const Eigen::Vector3d gravity(0, 0, -9.81), A(oa, 0, 0);
  core::Model model;
  model.set_gravity(gravity);
  const auto section = core::SectionIntegrals::circle(radius);
  const core::AncfBeam link_oa = core::add_ancf_beam(
      model, {.end = A, .y_direction = Eigen::Vector3d::UnitY(), .elements = elements_oa, .kind = ancf.kind(),
              .method = ancf.method(), .material = material, .section = section});
  const core::AncfBeam link_ab = core::add_ancf_beam(
      model, {.start = A, .end = A + Eigen::Vector3d(0, ab, 0), .y_direction = -Eigen::Vector3d::UnitX(),
              .elements = elements_ab, .kind = ancf.kind(), .method = ancf.method(), .material = material, .section = section});

  // 3. Ball joints at O (ground) and A (between the links' end nodes).
  solvers::ConstraintList joints;
  joints.push_back(std::make_unique<joints::PointJoint>(
      core::ancf_node_point(model.state(), link_oa.nodes.front()), Eigen::Vector3d::Zero(), model.state()));
  joints.push_back(std::make_unique<joints::PointJoint>(
      core::ancf_node_point(model.state(), link_oa.nodes.back()),
      core::ancf_node_point(model.state(), link_ab.nodes.front()), model.state()));
  const double preprocessing =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - preprocessing_start).count();
  const double area = std::numbers::pi * radius * radius;
  const double energy_scale = material.density * area * gravity.norm() * (oa * oa / 2 + ab * (oa + ab / 2));

  // 4. The integrator, from rest. The motion is chaotic and Newton's error accumulates over 30 000
  // steps: the increment tolerance 1e-16 (last increment ≤ 1e-8) is the loosest power of 100
  // that leaves B at 3 s unchanged in its five digits for both elements; with 1e-14 the
  // 30-coordinate B moves (README, "Newton tolerances"). The residual test (1e-8 of the row's
  // terms) is then what stops most steps. Modified Newton keeps a factorization while the
  // increments shrink by at least 50× per iteration (--refactor-contraction 0.02; the library's
  // default 0.5 kept one for ~350 steps at a contraction of ~0.2–0.3 and took 7.9 iterations a
  // step): a refactorization costs about six iterations (README, "Newton tolerances").
  solvers::GeneralizedAlpha integrator(model, std::move(joints), run.dynamics);
  integrator.initialize();

  // 5. Record every --record-every steps: A, B, the energies and the drift; the summary's
  //    extremes at every step.
  study::Recorder rec(integrator, {.folder = out, .name = "ancf_double_pendulum", .time_step = h,
                                   .schedule = study::Schedule::every_steps(record_every), .csv_digits = 12});
  rec.attributes({{"example", "ancf_double_pendulum"}, {"element", ancf.element}, {"force", ancf.force}});
  const study::Scalar residual = rec.constraint_residual(
      {.description = "largest violation |Phi|_inf of the joints after the step", .every_step = true});
  const study::Scalar drift = rec.energy_drift(
      energy_scale, {.description = "(E - E(0)) / (the potential released by both links falling from the horizontal), "
                                    "a fraction",
                     .every_step = true});
  rec.total_energy();
  rec.energy_balance();
  rec.newton_iterations();
  const int samples_oa = 10 * elements_oa + 1, samples_ab = 10 * elements_ab + 1;
  rec.centerline(samples_oa, [&](const study::State& s) { return core::sample_ancf_centerline(s.q, link_oa, samples_oa); });
  rec.centerline(samples_ab, [&](const study::State& s) { return core::sample_ancf_centerline(s.q, link_ab, samples_ab); });
  rec.vector({.name = "A", .unit = "m", .description = "the joint A (end of OA), inertial frame", .csv = "A_x,A_y,A_z"},
             [&](const study::State& s) { return core::ancf_node_position(s.q, link_oa.nodes.back()); });
  rec.vector({.name = "B", .unit = "m", .description = "the free end B, inertial frame", .csv = "B_x,B_y,B_z"},
             [&](const study::State& s) { return core::ancf_node_position(s.q, link_ab.nodes.back()); });
  rec.csv({"A", "B", "kinetic_energy", "strain_energy", "gravity_potential", "total_energy", "energy_drift",
           "constraint_residual", "newton_iterations", "external_work", "numerical_dissipation"});
  rec.run(run.end_time);
  rec.close();

  // 6. The summary.
  const solvers::DynamicCounters& counters = integrator.counters();
  const Eigen::Vector3d b = core::ancf_node_position(model.state(), link_ab.nodes.back());
  output::JsonSummary summary;
  summary.add("element", ancf.element).add("force", ancf.force).add("elements_oa", elements_oa).add("elements_ab", elements_ab)
      .add("h", h).add("t_end", integrator.time()).add("iteration_matrix", run.strategy);
  if (run.strategy == "modified")  // only the options the run used
    summary.add("refactor_contraction", run.dynamics.modified_newton_contraction);
  summary.add("tolerance", run.dynamics.tolerance)
      .add("factorizations", counters.factorizations).add("steps", counters.steps)
      .add("newton_iterations", counters.newton_iterations)
      .add("max_constraint_residual", residual.max()).add("max_energy_drift", drift.max_abs())
      .add("B_x", b.x()).add("B_y", b.y()).add("B_z", b.z())
      .add("preprocessing_s", preprocessing).add("wall_s", counters.wall_seconds)
      .print();
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
