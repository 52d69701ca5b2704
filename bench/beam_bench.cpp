// The geometrically exact beam: one element's force and stiffness for p = 1, 2, 3, and a full
// Newton statics solve of a 64-element cantilever (tip load P L²/EI = 10, 10 load steps).
#include <spar/spar.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace spar;

iga::NurbsCurve<3> straight(int elements, int degree) {
  return iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), elements, degree);
}

core::SectionStiffness steel_square() {
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  return core::SectionStiffness::from(steel, core::CrossSection::rectangle(0.01, 0.01, 0.3));
}

void beam_element(benchmark::State& state) {
  const int degree = static_cast<int>(state.range(0));
  const bool stiffness = state.range(1) != 0;
  core::Configuration q;
  const core::GeometricallyExactBeam beam({.centerline = straight(4, degree), .stiffness = steel_square()}, q);
  for (int k = 0; k < q.block_count(); ++k) {
    q.position[k].y() += 0.05 * k * k;
    q.rotation[k] = lie::exp(Eigen::Vector3d(0.1, 0.2 * k, 0.3 * k));
  }
  core::BeamElementResult result;
  const auto what = stiffness ? core::BeamEvaluation::force_and_stiffness : core::BeamEvaluation::force;
  for (auto _ : state) {
    core::evaluate_beam_element(beam, 1, q, what, result);
    benchmark::DoNotOptimize(result.internal_force.data());
  }
}
BENCHMARK(beam_element)->ArgsProduct({{1, 2, 3}, {0, 1}})->ArgNames({"p", "stiffness"});

void cantilever_newton_64_elements(benchmark::State& state) {
  for (auto _ : state) {
    core::Model model;
    const int b = core::add_beam(model, {.centerline = straight(64, 3), .stiffness = steel_square()});
    const int tip = core::beam(model, b).node(core::beam(model, b).control_point_count() - 1);
    model.fix(core::beam(model, b).node(0));
    const double EI = steel_square().bending_3;
    core::add_load(model, core::NodalForce{.node = tip, .force = Eigen::Vector3d(0, 10 * EI, 0)});
    const solvers::StaticReport report = solvers::solve_static(model, {.load_steps = 10});
    state.counters["newton_iterations"] = report.newton_iterations;
  }
}
BENCHMARK(cantilever_newton_64_elements)->Unit(benchmark::kMillisecond);

}  // namespace
