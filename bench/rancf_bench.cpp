// One ALE-RANCF cable element evaluation (2D, 5 Gauss points), rational weights against unit
// weights (ALE-ANCF): residual only, and residual + stiffness + damping + mass (dual numbers).
// 000 §6.1 found its ALE-RANCF runs 1.6× slower than ALE-ANCF; here the kernel is the same code
// with the shape functions tabulated per element, so the two should cost the same.
#include <spar/spar.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace spar;

void ale_rancf_element(benchmark::State& state) {
  const bool rational = state.range(0) != 0;
  const bool jacobians = state.range(1) != 0;
  core::Configuration q;
  core::RancfCableParameters p;
  p.node_a = q.add_vector(Eigen::Vector4d(0.0, 0.0, 1.0, 0.05));
  p.node_b = q.add_vector(Eigen::Vector4d(0.2, 0.02, 0.98, 0.1));
  p.material_a = q.add_vector(Eigen::VectorXd::Constant(1, 0.3));
  p.material_b = q.add_vector(Eigen::VectorXd::Constant(1, 0.5));
  p.section = {.axial_stiffness = 6283.0, .bending_stiffness = 0.157, .mass_per_length = 2.26};
  if (rational) p.weights = Eigen::Vector4d(1.0, 0.93, 1.08, 1.0);
  const core::AleRancfCableElement<2> element(p);
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(q.dof_count(), 0.1, 1.0);
  const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(q.dof_count(), -1.0, 2.0);
  core::ElementInput in;
  in.q = &q;
  in.velocity = &v;
  in.acceleration = &a;
  in.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
  const core::ElementRequest request{.residual = true, .stiffness = jacobians, .damping = jacobians,
                                     .mass = jacobians, .energy = true};
  core::ElementOutput out;
  for (auto _ : state) {
    out.reset(q.dof_count(), request);
    element.evaluate(in, request, out);
    benchmark::DoNotOptimize(out.residual.data());
  }
}
BENCHMARK(ale_rancf_element)->ArgsProduct({{0, 1}, {0, 1}})->ArgNames({"rational", "jacobians"});

}  // namespace
