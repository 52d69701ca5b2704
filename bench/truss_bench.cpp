// The deployable truss unit of 003 §5.3 (examples/truss_deployment): one second of the cosine
// deployment (case 2, 4 elements per member, h = 5 ms: 200 steps, 1 216 unknowns) in each
// iteration-matrix strategy, a single step mid-deployment, and the whole 30 s of each law in
// `update` and `frozen` (the issue's target: under 10 s each; docs/performance.md, "Truss
// deployment"). The whole runs take ~45 s: --benchmark_filter=truss_deployment_whole_run.
#include <spar/spar.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "truss_model.hpp"

namespace {

using namespace spar;

constexpr solvers::IterationMatrix strategies[] = {
    solvers::IterationMatrix::update, solvers::IterationMatrix::frozen, solvers::IterationMatrix::modified};

constexpr const char* laws[] = {"linear", "polynomial", "cycloid", "cosine"};

/// The example's integrator settings (003's Newton test); `substructuring` off factorizes the
/// whole matrix (D12).
solvers::DynamicOptions truss_options(solvers::IterationMatrix strategy, bool substructuring) {
  return {.time_step = 0.005, .spectral_radius = 0.9, .iteration_matrix = strategy, .tolerance = 1e-6,
          .constraint_tolerance = 1e-10, .residual_tolerance = INFINITY, .substructuring = substructuring};
}

struct Deployment {
  examples::TrussUnit unit;
  std::unique_ptr<solvers::GeneralizedAlpha> integrator;
  explicit Deployment(solvers::IterationMatrix strategy, bool substructuring = true,
                      const std::string& law = "cosine") {
    examples::TrussParameters p;
    p.elements = 4;
    unit = examples::build_truss_unit(p);
    examples::add_deployment_drivers(unit, law, 20.0);
    integrator = std::make_unique<solvers::GeneralizedAlpha>(unit.model, std::move(unit.joints),
                                                           truss_options(strategy, substructuring));
    integrator->initialize();
  }
};

/// Steps 0 … 1 s of the deployment, from the model's construction on; the second argument 0
/// factorizes the whole matrix, 1 by substructures (the default; `modified` never does, D12).
void truss_deployment_first_second(benchmark::State& state) {
  const solvers::IterationMatrix strategy = strategies[state.range(0)];
  const bool substructuring = state.range(1) != 0;
  bool substructured = false;
  for (auto _ : state) {
    Deployment run(strategy, substructuring);
    while (run.integrator->time() < 1.0 - 0.0025) run.integrator->step();
    state.counters["newton_iterations"] = static_cast<double>(run.integrator->counters().newton_iterations);
    state.counters["factorizations"] = static_cast<double>(run.integrator->counters().factorizations);
    substructured = run.integrator->counters().substructured_factorizations > 0;
  }
  state.SetLabel(std::string(solvers::to_string(strategy)) + (substructured ? ", substructured" : ", whole matrix"));
}
BENCHMARK(truss_deployment_first_second)
    ->Args({0, 0})->Args({0, 1})->Args({1, 0})->Args({1, 1})->Args({2, 1})
    ->Unit(benchmark::kMillisecond);

/// One step from t = 2 s on (β ≈ 7°, the cosine law accelerating).
void truss_deployment_step(benchmark::State& state) {
  const solvers::IterationMatrix strategy = strategies[state.range(0)];
  Deployment run(strategy);
  while (run.integrator->time() < 2.0) run.integrator->step();
  const long before = run.integrator->counters().newton_iterations;
  long steps = 0;
  for (auto _ : state) {
    run.integrator->step();
    ++steps;
  }
  state.counters["iterations_per_step"] =
      static_cast<double>(run.integrator->counters().newton_iterations - before) / static_cast<double>(steps);
  state.SetLabel(std::string(solvers::to_string(strategy)));
}
BENCHMARK(truss_deployment_step)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

/// Case 2 as the example runs it, 0 … 30 s (6 000 steps), for law range(0) (linear, polynomial,
/// cycloid, cosine) in strategy range(1) (update, frozen): one run per repetition, without the
/// example's output.
void truss_deployment_whole_run(benchmark::State& state) {
  const char* law = laws[state.range(0)];
  const solvers::IterationMatrix strategy = strategies[state.range(1)];
  for (auto _ : state) {
    Deployment run(strategy, true, law);
    while (run.integrator->time() < 30.0 - 0.0025) run.integrator->step();
    const solvers::DynamicCounters& c = run.integrator->counters();
    state.counters["steps"] = static_cast<double>(c.steps);
    state.counters["newton_iterations"] = static_cast<double>(c.newton_iterations);
    state.counters["factorizations"] = static_cast<double>(c.factorizations);
  }
  state.SetLabel(std::string(law) + ", " + std::string(solvers::to_string(strategy)));
}
BENCHMARK(truss_deployment_whole_run)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace
