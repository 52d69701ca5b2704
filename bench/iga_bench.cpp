// Micro benchmarks of the spline kernels (issue 3). Parameters vary per iteration so nothing is
// hoisted out of the loop.
#include <spar/iga/iga.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace spar::iga;

double parameter(int i) { return 0.3 + 1e-9 * (i & 1023); }

// B-spline basis values and derivatives up to order 3 (A2.3) at one parameter, for degree p.
void basis_derivatives_p(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const KnotVector U = KnotVector::open_uniform(10, p, p - 1);
  BasisTable N;
  int i = 0;
  for (auto _ : state) {
    const double u = parameter(++i);
    basis_derivatives(U, U.find_span(u), u, 3, N);
    benchmark::DoNotOptimize(N.data());
  }
}
BENCHMARK(basis_derivatives_p)->Arg(2)->Arg(3);

// The same with the NURBS quotient rule.
void rational_basis_derivatives_p(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const KnotVector U = KnotVector::open_uniform(10, p, p - 1);
  const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(U.basis_count(), 0.8, 1.2);
  BasisTable N;
  int i = 0;
  for (auto _ : state) {
    const double u = parameter(++i);
    rational_basis_derivatives(U, U.find_span(u), u, 3, weights, N);
    benchmark::DoNotOptimize(N.data());
  }
}
BENCHMARK(rational_basis_derivatives_p)->Arg(2)->Arg(3);

// A point of a cubic NURBS space curve with its first two derivatives.
void curve_point_two_derivatives(benchmark::State& state) {
  const KnotVector U = KnotVector::open_uniform(10, 3, 2);
  const NurbsCurve<3> curve(U, NurbsCurve<3>::Points::Random(3, U.basis_count()),
                            Eigen::VectorXd::LinSpaced(U.basis_count(), 0.8, 1.2));
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curve.derivatives(parameter(++i), 2));
}
BENCHMARK(curve_point_two_derivatives);

// One knot insertion (A5.1) on a 100-element cubic NURBS curve, operator matrix included.
void knot_insertion_100_elements(benchmark::State& state) {
  const KnotVector U = KnotVector::open_uniform(100, 3, 2);
  const NurbsCurve<3> curve(U, NurbsCurve<3>::Points::Random(3, U.basis_count()),
                            Eigen::VectorXd::LinSpaced(U.basis_count(), 0.8, 1.2));
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(insert_knot(curve, 0.5055 + 1e-9 * (++i & 1023)));
}
BENCHMARK(knot_insertion_100_elements);

// Gauss–Legendre rule of 8 points (element quadrature setup).
void gauss_legendre_8(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(gauss_legendre(8));
}
BENCHMARK(gauss_legendre_8);

}  // namespace
