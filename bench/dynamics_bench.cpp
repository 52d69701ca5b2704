// End-to-end dynamics: the slider-crank of 003 §5.1 in each iteration-matrix strategy (whole run
// and single steps), the limit a step cannot beat (one residual and one back-substitution), and
// the OpenMP speed-up of assembly on a 256-element beam.
#include <spar/spar.hpp>

// The solvers' private assembly, to time one residual evaluation by itself.
#include "system_assembly.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

#include "slider_crank_model.hpp"

namespace {

using namespace spar;

constexpr solvers::IterationMatrix strategies[] = {
    solvers::IterationMatrix::update, solvers::IterationMatrix::frozen, solvers::IterationMatrix::modified};

/// 003's convergence test (‖[Δq, h²βΔλ]‖² ≤ 1e-6, ‖Φ‖∞ ≤ 1e-10), as the example runs by default.
solvers::DynamicOptions paper_options(solvers::IterationMatrix strategy) {
  return {.time_step = 1e-4, .iteration_matrix = strategy, .residual_tolerance = INFINITY};
}

/// The whole 0.2 s run at h = 1e-4 (2000 steps).
void slider_crank_run(benchmark::State& state) {
  const solvers::IterationMatrix strategy = strategies[state.range(0)];
  for (auto _ : state) {
    examples::SliderCrank mechanism = examples::build_slider_crank(6);
    solvers::GeneralizedAlpha integrator(mechanism.model, std::move(mechanism.joints), paper_options(strategy));
    while (integrator.time() < 0.2 - 0.5e-4) integrator.step();
    state.counters["newton_iterations"] = static_cast<double>(integrator.counters().newton_iterations);
    state.counters["factorizations"] = static_cast<double>(integrator.counters().factorizations);
  }
  state.SetLabel(std::string(solvers::to_string(strategy)));
}
BENCHMARK(slider_crank_run)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

/// The limit of a step (issue 17): one evaluation of the residual [r; Φ] and one back-substitution
/// with a factorization kept from before, at the state of t = 0.1 s. A Newton step needs at least
/// that much; docs/performance.md gives every strategy's cost per step as a multiple of it.
/// Arg 0: both; 1: the residual alone; 2: the back-substitution alone.
void slider_crank_limit(benchmark::State& state) {
  // The state at t = 0.1 s, reached by the integrator, copied into a second, identical mechanism
  // whose joints this benchmark still owns.
  examples::SliderCrank running = examples::build_slider_crank(6);
  solvers::GeneralizedAlpha integrator(running.model, std::move(running.joints),
                                       paper_options(solvers::IterationMatrix::update));
  while (integrator.time() < 0.1 - 0.5e-4) integrator.step();
  examples::SliderCrank mechanism = examples::build_slider_crank(6);
  mechanism.model.state() = integrator.configuration();
  std::vector<joints::Constraint*> constraints;
  for (auto& joint : mechanism.joints) constraints.push_back(joint.get());
  solvers::detail::SystemAssembly assembly(mechanism.model, constraints, solvers::AssemblyExecution::serial);
  const Eigen::VectorXd velocity = integrator.velocity(), acceleration = integrator.acceleration();
  const Eigen::VectorXd lambda = integrator.multipliers();
  const Eigen::VectorXd increment = Eigen::VectorXd::Zero(assembly.dof_count());
  core::ElementInput in;
  in.q = &mechanism.model.state();
  in.velocity = &velocity;
  in.acceleration = &acceleration;
  in.time = integrator.time();
  in.gravity = mechanism.model.gravity();
  // The iteration matrix of h = 1e-4 and ρ∞ = 0.9, factorized once.
  const auto alpha = solvers::GeneralizedAlphaParameters::from_spectral_radius(0.9);
  const double h = 1e-4, beta_prime = (1 - alpha.alpha_m) / (h * h * alpha.beta * (1 - alpha.alpha_f));
  const solvers::detail::MatrixCoefficients c{.mass = 1.0, .damping = alpha.gamma / (h * alpha.beta) / beta_prime,
                                              .stiffness = 1.0 / beta_prime};
  assembly.evaluate(in, lambda, &c, solvers::detail::Chart::local_increment, increment, false);
  const auto solver = solvers::make_linear_solver(solvers::LinearSolverKind::klu);
  solver->analyze(assembly.pattern().matrix());
  solver->factorize(assembly.pattern().matrix());
  Eigen::VectorXd solution(assembly.size());
  const bool residual = state.range(0) != 2, solve = state.range(0) != 1;
  for (auto _ : state) {
    if (residual)
      assembly.evaluate(in, lambda, nullptr, solvers::detail::Chart::local_increment, increment, false);
    if (solve) {
      solution = -assembly.residual();
      solver->solve(solution);
    }
    benchmark::DoNotOptimize(solution.data());
  }
  state.SetLabel(residual && solve ? "residual + back-substitution" : residual ? "residual" : "back-substitution");
}
BENCHMARK(slider_crank_limit)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

/// One step at h = 1e-4 from t = 0.1 s (mid-run, the crank at speed).
void slider_crank_step(benchmark::State& state) {
  const solvers::IterationMatrix strategy = strategies[state.range(0)];
  examples::SliderCrank mechanism = examples::build_slider_crank(6);
  solvers::GeneralizedAlpha integrator(mechanism.model, std::move(mechanism.joints), paper_options(strategy));
  while (integrator.time() < 0.1) integrator.step();
  const long before = integrator.counters().newton_iterations;
  long steps = 0;
  for (auto _ : state) {
    integrator.step();
    ++steps;
  }
  state.counters["iterations_per_step"] =
      static_cast<double>(integrator.counters().newton_iterations - before) / static_cast<double>(steps);
  state.SetLabel(std::string(solvers::to_string(strategy)));
}
BENCHMARK(slider_crank_step)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

/// Ten steps of a free 256-element cubic beam (ρ∞ = 0.9, h = 1e-4), serial or parallel assembly.
void free_beam_256_elements(benchmark::State& state) {
  const auto execution = state.range(0) ? solvers::AssemblyExecution::parallel : solvers::AssemblyExecution::serial;
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection square = core::CrossSection::rectangle(0.01, 0.01, 0.3);
  for (auto _ : state) {
    state.PauseTiming();
    core::Model model;
    core::add_beam(model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 256, 3),
                    .stiffness = core::SectionStiffness::from(steel, square),
                    .inertia = core::SectionInertia::from(steel, square)});
    model.set_gravity(Eigen::Vector3d(0, -9.81, 0));
    solvers::GeneralizedAlpha integrator(model, {}, {.time_step = 1e-4, .assembly = execution});
    integrator.initialize();
    state.ResumeTiming();
    for (int i = 0; i < 10; ++i) integrator.step();
  }
  state.SetLabel(state.range(0) ? "parallel" : "serial");
}
BENCHMARK(free_beam_256_elements)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
