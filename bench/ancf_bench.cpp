// The ANCF beam elements (docs/ancf.md): one element's elastic force, and force with Jacobian, by
// method I (invariant tensors) and method II (Piola–Kirchhoff section resultants), for 24 and 30
// coordinates; and the preprocessing of each method's constant tables.
#include <spar/spar.hpp>

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace spar;

const core::Material material{.young_modulus = 300e6, .poisson_ratio = 0.0, .density = 7200};

template <int transverse>
void elastic_force(benchmark::State& state) {
  const auto method = state.range(0) == 1 ? core::AncfForceMethod::invariant : core::AncfForceMethod::gerstmayr;
  const bool jacobian = state.range(1) != 0;
  core::Model model;
  const core::AncfBeam beam = core::add_ancf_beam(
      model, {.end = Eigen::Vector3d(0.16, 0, 0), .kind = transverse == 2 ? core::AncfElementKind::standard_24
                                                                          : core::AncfElementKind::higher_order_30,
              .method = method, .material = material, .section = core::SectionIntegrals::circle(0.01)});
  const auto& element = dynamic_cast<const core::AncfBeamElement<transverse>&>(model.element(beam.elements[0]));
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  auto e = element.coordinates(model.state());
  for (int k = 0; k < e.size(); ++k) e(k) += u(gen);
  typename core::AncfBeamElement<transverse>::Vector Q;
  typename core::AncfBeamElement<transverse>::Matrix K;
  for (auto _ : state) {
    benchmark::DoNotOptimize(element.elastic_force(e, Q, jacobian ? &K : nullptr));
    benchmark::DoNotOptimize(K.data());
  }
}
BENCHMARK(elastic_force<2>)->ArgsProduct({{1, 2}, {0, 1}})->ArgNames({"method", "jacobian"});
BENCHMARK(elastic_force<3>)->ArgsProduct({{1, 2}, {0, 1}})->ArgNames({"method", "jacobian"});

template <int transverse>
void tables(benchmark::State& state) {
  const auto method = state.range(0) == 1 ? core::AncfForceMethod::invariant : core::AncfForceMethod::gerstmayr;
  for (auto _ : state) {
    const core::AncfElementTables<transverse> t(0.16, material, core::SectionIntegrals::circle(0.01), method);
    benchmark::DoNotOptimize(t.scalar_mass.data());
  }
}
BENCHMARK(tables<2>)->Arg(1)->Arg(2)->ArgName("method")->Unit(benchmark::kMicrosecond);
BENCHMARK(tables<3>)->Arg(1)->Arg(2)->ArgName("method")->Unit(benchmark::kMicrosecond);

}  // namespace
