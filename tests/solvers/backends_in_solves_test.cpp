// UMFPACK, Eigen's SparseLU and the OpenMP assembly inside real solves: a static roll-up and a
// flexible pendulum's swing give the same states as KLU with serial assembly.
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>

#include <catch2/catch.hpp>

#include <numbers>
#include <utility>
#include <vector>

#include "cantilever.hpp"
#include "flexible_pendulum.hpp"

using namespace spar;

namespace {

struct Setup {
  solvers::LinearSolverKind kind;
  solvers::AssemblyExecution assembly;
};

const std::vector<Setup> setups{{solvers::LinearSolverKind::klu, solvers::AssemblyExecution::serial},
                                {solvers::LinearSolverKind::umfpack, solvers::AssemblyExecution::serial},
                                {solvers::LinearSolverKind::eigen_lu, solvers::AssemblyExecution::serial},
                                {solvers::LinearSolverKind::klu, solvers::AssemblyExecution::parallel},
                                {solvers::LinearSolverKind::umfpack, solvers::AssemblyExecution::parallel},
                                {solvers::LinearSolverKind::eigen_lu, solvers::AssemblyExecution::parallel}};

/// Largest distance between the node positions of two configurations.
double max_distance(const core::Configuration& a, const core::Configuration& b) {
  double worst = 0.0;
  for (int k = 0; k < a.block_count(); ++k) worst = std::max(worst, (a.position[k] - b.position[k]).norm());
  return worst;
}

}  // namespace

TEST_CASE("every linear solver and the parallel assembly give the same static and dynamic solutions",
          "[solvers][linear_solver]") {
  // The backends solve the same Newton systems to round-off (condition ≤ ~1e8 here, so ≤ 1e-8
  // relative per solve) and the assemblies differ only in summation order; each solve stops when
  // its last increment is ≤ 1e-10 m (statics) or ‖Δ‖² ≤ 1e-20 (dynamics, ‖Δ‖ ≤ 1e-10) after
  // quadratic convergence. The states therefore agree to the increment bound: 1e-9 m leaves a
  // margin of 10 (measured ≤ 7.3e-16 m: Newton converges far past its test).
  // Newton's path is the same too: a backend whose solutions were off by more than round-off
  // would still converge (the residual decides the answer) but in more iterations, so the
  // iteration counts must equal KLU's.
  std::vector<core::Configuration> statics, dynamics;
  std::vector<long> static_iterations, dynamic_iterations;
  for (const Setup& s : setups) {
    INFO("solver " << solvers::to_string(s.kind) << ", "
                   << (s.assembly == solvers::AssemblyExecution::parallel ? "parallel" : "serial") << " assembly");
    // Statics: a cantilever rolled into a half circle (M = π EI/L) in 4 load steps.
    auto c = test::make_cantilever(16, 3);
    core::add_load(c.model, core::NodalMoment{.node = c.tip, .moment = Eigen::Vector3d(0, 0, std::numbers::pi * 1e4),
                                       .frame = core::MomentFrame::material});
    const solvers::StaticReport report =
        solvers::solve_static(c.model, {.load_steps = 4, .linear_solver = s.kind, .assembly = s.assembly});
    CHECK(report.steps.size() == 4);
    statics.push_back(c.model.state());
    static_iterations.push_back(report.newton_iterations);
    // Dynamics: the pinned flexible pendulum (4 cubic elements) over 0.05 s at h = 1e-3.
    test::FlexiblePendulum p = test::flexible_pendulum(4);
    solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints),
                                         {.time_step = 1e-3, .tolerance = 1e-20, .constraint_tolerance = 1e-12,
                                          .residual_tolerance = 1e-8, .linear_solver = s.kind,
                                          .assembly = s.assembly});
    for (int n = 0; n < 50; ++n) integrator.step();
    CHECK(integrator.counters().cutbacks == 0);
    dynamics.push_back(p.model.state());
    dynamic_iterations.push_back(integrator.counters().newton_iterations);
  }
  for (std::size_t i = 1; i < setups.size(); ++i) {
    INFO("setup " << i << " (solver " << solvers::to_string(setups[i].kind) << "): statics differ by "
                  << max_distance(statics[i], statics[0]) << " m, dynamics by "
                  << max_distance(dynamics[i], dynamics[0]) << " m from KLU, serial");
    CHECK(max_distance(statics[i], statics[0]) <= 1e-9);
    CHECK(max_distance(dynamics[i], dynamics[0]) <= 1e-9);
    CHECK(static_iterations[i] == static_iterations[0]);
    CHECK(dynamic_iterations[i] == dynamic_iterations[0]);
  }
  // The half circle itself: the tip at (0, 2L/π) to the accuracy of 16 cubic elements (measured
  // 3.1e-6 m; 32 elements reach 1e-6, docs/validation.md).
  CHECK((statics[0].position.back() - Eigen::Vector3d(0, 2 / std::numbers::pi, 0)).norm() <= 1e-5);
}
