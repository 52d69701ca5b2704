// slider_crank_steps STRATEGY STEPS — runs STEPS steps of the flexible slider-crank (003 §5.1, h =
// 1e-4, 003's Newton test) and prints the Newton iterations. A fixed workload for instruction
// counts, which a loaded machine does not change (docs/performance.md):
//   valgrind --tool=callgrind build/release/bench/slider_crank_steps update 300
#include <spar/spar.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "slider_crank_model.hpp"

int main(int argc, char** argv) try {
  using namespace spar;
  if (argc != 3) {
    std::fprintf(stderr, "usage: slider_crank_steps update|frozen|modified STEPS\n");
    return 2;
  }
  const solvers::IterationMatrix strategy = solvers::iteration_matrix_from_string(argv[1]);
  const int steps = std::atoi(argv[2]);
  examples::SliderCrank mechanism = examples::build_slider_crank(6);
  solvers::GeneralizedAlpha integrator(
      mechanism.model, std::move(mechanism.joints),
      {.time_step = 1e-4, .iteration_matrix = strategy, .residual_tolerance = INFINITY});
  for (int i = 0; i < steps; ++i) integrator.step();
  std::printf("%s: %d steps, %ld Newton iterations, %ld factorizations\n", argv[1], steps,
              integrator.counters().newton_iterations, integrator.counters().factorizations);
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
