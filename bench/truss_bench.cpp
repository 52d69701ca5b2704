// The deployable truss unit of 003 §5.3 (examples/truss_deployment): one second of the cosine
// deployment (case 2, 4 elements per member, h = 5 ms: 200 steps, 1 216 unknowns) in each
// iteration-matrix strategy, and a single step mid-deployment. The whole 30 s runs per law are
// timed by scripts/truss_deployment.sh (docs/performance.md, "Truss deployment").
#include <spar/spar.hpp>

#include <benchmark/benchmark.h>

#include "truss_model.hpp"

namespace {

using namespace spar;

constexpr solvers::IterationMatrix strategies[] = {
    solvers::IterationMatrix::update, solvers::IterationMatrix::frozen, solvers::IterationMatrix::modified};

/// The example's integrator settings; `substructuring` off factorizes the whole matrix (D12).
solvers::DynamicOptions truss_options(solvers::IterationMatrix strategy, bool substructuring) {
  return {.time_step = 0.005, .spectral_radius = 0.9, .iteration_matrix = strategy, .tolerance = 1e-8,
          .constraint_tolerance = 1e-10, .residual_tolerance = 1e-8, .substructuring = substructuring};
}

struct Deployment {
  examples::TrussUnit unit;
  std::unique_ptr<solvers::GeneralizedAlpha> integrator;
  explicit Deployment(solvers::IterationMatrix strategy, bool substructuring = true) {
    examples::TrussParameters p;
    p.elements = 4;
    unit = examples::build_truss_unit(p);
    examples::add_deployment_drivers(unit, "cosine", 20.0);
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

}  // namespace
