// End-to-end dynamics: the slider-crank of 003 §5.1 in each iteration-matrix strategy (whole run
// and single steps), and the OpenMP speed-up of assembly on a 256-element beam.
#include <spar/spar.hpp>

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
  const auto execution = state.range(0) ? core::AssemblyExecution::parallel : core::AssemblyExecution::serial;
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection square = core::CrossSection::rectangle(0.01, 0.01, 0.3);
  for (auto _ : state) {
    state.PauseTiming();
    core::Model model;
    model.add_beam({.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 256, 3),
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
