// Micro benchmarks of the SO(3) kernels. Inputs vary per iteration so nothing is hoisted.
#include <spar/lie/lie.hpp>

#include <benchmark/benchmark.h>

namespace {

Eigen::Vector3d input(int i) { return Eigen::Vector3d(0.3 + 1e-9 * i, -0.8, 1.4); }

void exp(benchmark::State& state) {
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(spar::lie::exp(input(++i)));
}
BENCHMARK(exp);

void log(benchmark::State& state) {
  const Eigen::Matrix3d R = spar::lie::exp(input(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(R.data());
    benchmark::DoNotOptimize(spar::lie::log(R));
  }
}
BENCHMARK(log);

void tangent(benchmark::State& state) {
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(spar::lie::tangent(input(++i)));
}
BENCHMARK(tangent);

void tangent_inverse(benchmark::State& state) {
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(spar::lie::tangent_inverse(input(++i)));
}
BENCHMARK(tangent_inverse);

void exp_and_tangent(benchmark::State& state) {
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(spar::lie::exp_and_tangent(input(++i)));
}
BENCHMARK(exp_and_tangent);

void tangent_transpose_second_derivative(benchmark::State& state) {
  const Eigen::Vector3d a(1.0, 2.0, 3.0), b(-1.0, 0.5, 0.25);
  int i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(spar::lie::tangent_transpose_second_derivative(input(++i), a, b));
}
BENCHMARK(tangent_transpose_second_derivative);

}  // namespace
