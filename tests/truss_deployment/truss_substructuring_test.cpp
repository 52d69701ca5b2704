// The truss unit's iteration matrix factorized by members (docs/dynamics.md D12): KLU takes that
// way by itself on the unit of 003's case 2, and the run is the run of the whole matrix.
#include "truss_model.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace spar;

namespace {

struct Run {
  examples::TrussUnit unit;
  std::unique_ptr<solvers::GeneralizedAlpha> integrator;
};

/// Case 2 (cosine law, t_f = 20 s) with 003's four elements per member, 50 steps of 5 ms.
void run_case_2(Run& run, bool substructuring) {
  examples::TrussParameters p;
  p.elements = 4;
  run.unit = examples::build_truss_unit(p);
  examples::add_deployment_drivers(run.unit, "cosine", 20.0);
  run.integrator = std::make_unique<solvers::GeneralizedAlpha>(
      run.unit.model, std::move(run.unit.joints),
      solvers::DynamicOptions{.time_step = 0.005, .spectral_radius = 0.9, .tolerance = 1e-8,
                              .constraint_tolerance = 1e-10, .residual_tolerance = 1e-8,
                              .substructuring = substructuring});
  run.integrator->initialize();
  for (int step = 0; step < 50; ++step) run.integrator->step();
}

}  // namespace

TEST_CASE("truss substructuring: case 2 is factorized by members, with the whole matrix's iterates",
          "[truss][dynamics][substructuring]") {
  Run by_members, whole;
  run_case_2(by_members, true);
  run_case_2(whole, false);
  const solvers::DynamicCounters& c = by_members.integrator->counters();
  // 28 members of 6 nodes, 1 216 unknowns: 0.64 Mflop per factorization by members against 4.6 for
  // the whole matrix (COLAMD), so every factorization goes by members…
  CHECK(c.factorizations > 50);
  CHECK(c.substructured_factorizations == c.factorizations);
  CHECK(whole.integrator->counters().substructured_factorizations == 0);
  // …and the Newton sequence is the same: the solves are refined to a backward error of 1e-9
  // (GeneralizedAlpha's refinement target), so the states agree to far below the Newton tests,
  // not bitwise. The multipliers are compared as 003's test measures them, h²β λ in metres: at
  // 0.25 s of the cosine law they are 0.04 N at most, and the refinement's 1e-9 of the whole
  // system leaves them ~1e-6 of that apart (h²β·4e-8 N = 3e-13 m, measured).
  CHECK(c.newton_iterations == whole.integrator->counters().newton_iterations);
  const core::Configuration& q = by_members.unit.model.state();
  const core::Configuration& r = whole.unit.model.state();
  double position_difference = 0.0;
  for (int b = 0; b < q.block_count(); ++b)
    if (q.is_frame(b)) position_difference = std::max(position_difference, (q.position[b] - r.position[b]).norm());
  CHECK(position_difference <= 1e-12);
  const Eigen::VectorXd& lambda = by_members.integrator->multipliers();
  const double h2_beta = 0.005 * 0.005 * solvers::GeneralizedAlphaParameters::from_spectral_radius(0.9).beta;
  CHECK(h2_beta * (lambda - whole.integrator->multipliers()).lpNorm<Eigen::Infinity>() <= 1e-12);
  CHECK(by_members.integrator->constraint_residual() <= 1e-10);
}
