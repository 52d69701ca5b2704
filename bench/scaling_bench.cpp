// Scaling with the element count (issue 17): a cantilevered cubic beam of 10, 100, 1 000 and
// 10 000 elements, 100 dynamic steps with the results written at every step, serial and parallel
// assembly. Reports the time per step and per element and Newton iteration; docs/performance.md,
// "Scaling", fits the exponent and lists the peak memory (scripts/scaling.sh). `assembly` times
// the assembly alone (every element's K, C, M into the sparse pattern), the part that runs in
// parallel.
//
//   build/release/bench/bench_scaling --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//   build/release/bench/bench_scaling --benchmark_filter='cantilever/elements:1000/'
#include <spar/spar.hpp>

#include <benchmark/benchmark.h>

#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace spar;

constexpr int steps = 100;

/// The steel rule of examples/flexible_pendulum (1 m, 30 × 1 mm), clamped at x = 0, sagging
/// under gravity from straight and at rest; h = 2.5e-4 s.
struct Cantilever {
  core::Model model;
  int beam = 0;

  explicit Cantilever(int elements) {
    const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
    const core::CrossSection section = core::CrossSection::rectangle(0.03, 0.001, steel.poisson_ratio);
    beam = core::add_beam(model,
        {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), elements, 3),
         .stiffness = core::SectionStiffness::from(steel, section),
         .inertia = core::SectionInertia::from(steel, section)});
    model.fix(core::beam(model, beam).node(0));
    model.set_gravity(Eigen::Vector3d(0.0, 0.0, -9.81));
  }
};

/// 100 steps with the results written at every step (nodes, velocities, energies and the
/// centerline sampled at 10 points per element, as the examples write them).
void cantilever(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  const bool parallel = state.range(1) != 0;
  const std::string path = "/tmp/spar_bench_scaling_" + std::to_string(getpid()) + ".h5";
  const int samples = 10 * elements + 1;
  long iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Cantilever cantilever(elements);
    solvers::GeneralizedAlpha integrator(
        cantilever.model, {},
        {.time_step = 2.5e-4,
         .assembly = parallel ? solvers::AssemblyExecution::parallel : solvers::AssemblyExecution::serial});
    integrator.initialize();
    output::ResultsWriter results(path, {.node_count = cantilever.model.block_count(),
                                       .scalars = {{.name = "total_energy", .unit = "J", .description = "E"}},
                                       .centerline_points = {samples}});
    // The centerline's basis once for the run, as the examples sample it (core::CenterlineSampler).
    const core::CenterlineSampler centerline(core::beam(cantilever.model, cantilever.beam), samples);
    const long before = integrator.counters().newton_iterations;
    state.ResumeTiming();
    for (int step = 0; step < steps; ++step) {
      integrator.step();
      const core::Configuration& q = cantilever.model.state();
      results.append({.time = integrator.time(), .configuration = &q, .velocity = &integrator.velocity(),
                      .scalars = {integrator.energies().total()},
                      .centerlines = {centerline.positions(q)}});
    }
    results.close();
    state.PauseTiming();
    iterations += integrator.counters().newton_iterations - before;
    state.ResumeTiming();
  }
  std::remove(path.c_str());
  const double runs = static_cast<double>(state.iterations());
  state.counters["ms_per_step"] = benchmark::Counter(runs * steps / 1e3, benchmark::Counter::kIsRate |
                                                                             benchmark::Counter::kInvert);
  state.counters["iterations_per_step"] = static_cast<double>(iterations) / (runs * steps);
  state.counters["us_per_element_iteration"] = benchmark::Counter(
      static_cast<double>(iterations) * elements / 1e6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(parallel ? "parallel" : "serial");
}
BENCHMARK(cantilever)
    ->ArgsProduct({{10, 100, 1000, 10000}, {0, 1}})
    ->ArgNames({"elements", "parallel"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// One assembly of c_K K + c_C C + c_M M of every element of the cantilever at rest (element
/// kernels, combination and scatter), as the integrator's Newton iteration runs it.
void assembly(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  const auto execution = state.range(1) ? solvers::AssemblyExecution::parallel : solvers::AssemblyExecution::serial;
  Cantilever cantilever(elements);
  const core::Model& model = cantilever.model;
  const core::Configuration& q = model.state();
  const Eigen::VectorXd velocity = Eigen::VectorXd::Zero(model.dof_count());
  const core::ElementInput in{.q = &q, .velocity = &velocity, .acceleration = &velocity,
                              .gravity = model.gravity()};
  const core::ElementRequest request{.stiffness = true, .damping = true, .mass = true};
  std::vector<solvers::PatternBlock> blocks;
  for (int e = 0; e < model.element_count(); ++e)
    blocks.push_back(solvers::PatternBlock::element(core::block_dofs(q, model.element(e).blocks())));
  solvers::SparsePattern pattern(model.dof_count(), blocks);
  std::vector<core::ElementOutput> outputs(static_cast<std::size_t>(model.element_count()));
  const solvers::BlockCompute compute = [&](int e, Eigen::MatrixXd& K) {
    core::ElementOutput& out = outputs[static_cast<std::size_t>(e)];
    out.reset(static_cast<int>(K.rows()), request);
    model.element(e).evaluate(in, request, out);
    K.noalias() = out.stiffness + 2e3 * out.damping + 4e6 * out.mass;
  };
  for (auto _ : state) {
    pattern.assemble(compute, execution);
    benchmark::DoNotOptimize(pattern.matrix().valuePtr());
  }
  state.counters["us_per_element"] = benchmark::Counter(
      static_cast<double>(elements) / 1e6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetLabel(state.range(1) ? "parallel" : "serial");
}
BENCHMARK(assembly)
    ->ArgsProduct({{10, 100, 200, 1000, 10000}, {0, 1}})
    ->ArgNames({"elements", "parallel"})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
