// The parallel assembly inside real solves is bitwise the serial one: a pinned flexible pendulum
// of 240 cubic elements (past solvers::parallel_assembly_min_blocks, so `automatic` runs in parallel
// too) and a spherical joint, stepped with each execution; and one of 20 elements, which
// `automatic` evaluates serially or in parallel as it times them (solvers/src/execution_choice.hpp).
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/solvers/work_sharing.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "flexible_pendulum.hpp"

using namespace spar;

namespace {

struct Run {
  core::Configuration state;
  Eigen::VectorXd velocity, multipliers;
  long iterations = 0;
};

Run run(solvers::AssemblyExecution execution, int elements = 240, int steps = 8) {
  test::FlexiblePendulum p = test::flexible_pendulum(elements);
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints),
                                       {.time_step = 2.5e-4, .tolerance = 1e-20, .constraint_tolerance = 1e-12,
                                        .residual_tolerance = 1e-8, .assembly = execution});
  for (int n = 0; n < steps; ++n) integrator.step();
  return {p.model.state(), integrator.velocity(), integrator.multipliers(),
          integrator.counters().newton_iterations};
}

bool same_state(const core::Configuration& a, const core::Configuration& b) {
  if (a.block_count() != b.block_count()) return false;
  for (int k = 0; k < a.block_count(); ++k)
    if (a.position[k] != b.position[k] || a.rotation[k] != b.rotation[k]) return false;
  return true;
}

}  // namespace

TEST_CASE("parallel and automatic assembly step a 240-element pinned beam bitwise as serial does",
          "[solvers][openmp]") {
  // Each value of the iteration matrix and each residual entry is the same sum in the same order
  // in every execution (solvers::SparsePattern::assemble), so every Newton iterate is identical.
  if (solvers::WorkSharing::shared().thread_count() == 1) {
    WARN("one thread (OMP_NUM_THREADS or a 1-core machine): every execution is the serial one");
    return;
  }
  const Run serial = run(solvers::AssemblyExecution::serial);
  for (const solvers::AssemblyExecution execution :
       {solvers::AssemblyExecution::parallel, solvers::AssemblyExecution::automatic}) {
    CAPTURE(execution == solvers::AssemblyExecution::parallel ? "parallel" : "automatic");
    const Run other = run(execution);
    CHECK(same_state(other.state, serial.state));
    CHECK(other.velocity == serial.velocity);
    CHECK(other.multipliers == serial.multipliers);
    CHECK(other.iterations == serial.iterations);
  }
}

TEST_CASE("automatic assembly of a 20-element pendulum, serial and parallel as timed, steps bitwise as serial does",
          "[solvers][openmp]") {
  // 60 steps take 120 Newton iterations, each an evaluation with a matrix: the first round (nine
  // serial, nine parallel), the 32 evaluations of its choice, the second round and 52 more.
  if (solvers::WorkSharing::shared().thread_count() == 1) {
    WARN("one thread (OMP_NUM_THREADS or a 1-core machine): every execution is the serial one");
    return;
  }
  const Run serial = run(solvers::AssemblyExecution::serial, 20, 60);
  const Run automatic = run(solvers::AssemblyExecution::automatic, 20, 60);
  CHECK(serial.iterations >= 120);
  CHECK(same_state(automatic.state, serial.state));
  CHECK(automatic.velocity == serial.velocity);
  CHECK(automatic.multipliers == serial.multipliers);
  CHECK(automatic.iterations == serial.iterations);
}
