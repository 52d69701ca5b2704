#pragma once
/// \file
/// The choice between the serial and the parallel evaluation of a model's blocks, by timing both
/// (SystemAssembly, for solvers::AssemblyExecution::automatic below
/// solvers::parallel_assembly_min_blocks).

#include <array>
#include <chrono>

namespace spar::solvers::detail {

/// Below solvers::parallel_assembly_min_blocks neither evaluation wins for certain: the
/// slider-crank's 17 blocks assemble in 23 instead of 39 µs on two idle cores, and a second
/// process or thread on the other core can turn that round (docs/performance.md, "Parallel
/// assembly"). So a round times both: `samples` evaluations of each kind in a row, each run
/// after one untimed evaluation of its kind (which wakes the helper threads, and builds the
/// assembly's gather the first time), and the kind with the smaller median runs until the next
/// round: 32 evaluations after the first round, twice as many after each further one, at most
/// 1024 (a start-up that misleads the first round is mended soon, a long run is timed seldom).
/// In a row, because a parallel evaluation right after another finds the helpers awake, and one
/// after a serial one has to wake them. Serial and parallel give bitwise the same results
/// (tests/solvers/parallel_assembly_test.cpp), so the choice changes the time only.
class ExecutionChoice {
public:
  using Duration = std::chrono::steady_clock::duration;
  static constexpr int samples = 8;              ///< timed evaluations of each kind in a round
  static constexpr int first_kept_for = 32;      ///< evaluations between the first two rounds
  static constexpr int longest_kept_for = 1024;  ///< at most between two rounds

  /// Whether the next evaluation runs in parallel.
  bool parallel() const noexcept;
  /// Records the time of the evaluation that parallel() asked for, and moves on to the next.
  void record(Duration elapsed);

private:
  static constexpr int run = samples + 1;  ///< one untimed evaluation, then `samples` timed ones

  void choose();

  /// Position in the cycle: [0, run) the round's serial run, [run, 2·run) its parallel one,
  /// [2·run, 2·run + kept_for_) the chosen kind.
  int position_ = 0;
  int kept_for_ = first_kept_for;
  bool chosen_parallel_ = false;
  std::array<Duration, samples> serial_{}, parallel_{};
};

}  // namespace spar::solvers::detail
