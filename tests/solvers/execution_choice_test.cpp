// ExecutionChoice (solvers/src/execution_choice.hpp): a round runs nine serial evaluations, then
// nine parallel ones, the first of each untimed; the kind with the smaller median of the eight
// timed ones runs until the next round, 32 evaluations after the first round, twice as many after
// each further one, at most 1024.
#include <catch2/catch.hpp>

#include <chrono>
#include <vector>

#include "execution_choice.hpp"

using spar::solvers::detail::ExecutionChoice;
using namespace std::chrono_literals;

namespace {

/// Runs one round, timing the serial evaluations `serial` and the parallel ones `parallel` (the
/// i-th timed one of each kind takes the i-th entry; the untimed ones take an hour), and returns
/// the kinds asked for, in order.
std::vector<bool> run_round(ExecutionChoice& choice, const std::vector<std::chrono::microseconds>& serial,
                            const std::vector<std::chrono::microseconds>& parallel) {
  std::vector<bool> asked;
  for (int i = 0; i < 2 * (ExecutionChoice::samples + 1); ++i) {
    const bool is_parallel = choice.parallel();
    asked.push_back(is_parallel);
    const int within = i % (ExecutionChoice::samples + 1);
    const auto& times = is_parallel ? parallel : serial;
    choice.record(within == 0 ? std::chrono::microseconds(1h) : times[static_cast<std::size_t>(within - 1)]);
  }
  return asked;
}

/// Records `count` evaluations of the chosen kind; true when every one was parallel.
bool all_parallel(ExecutionChoice& choice, int count) {
  bool all = true;
  for (int i = 0; i < count; ++i) {
    all = all && choice.parallel();
    choice.record(1us);
  }
  return all;
}

/// Records `count` evaluations of the chosen kind; true when every one was serial.
bool all_serial(ExecutionChoice& choice, int count) {
  bool all = true;
  for (int i = 0; i < count; ++i) {
    all = all && !choice.parallel();
    choice.record(1us);
  }
  return all;
}

const std::vector<std::chrono::microseconds> fast(8, 30us), slow(8, 50us);

}  // namespace

TEST_CASE("a round runs nine serial evaluations, then nine parallel ones", "[solvers][execution_choice]") {
  ExecutionChoice choice;
  const std::vector<bool> asked = run_round(choice, slow, fast);
  const std::vector<bool> expected = {false, false, false, false, false, false, false, false, false,
                                      true,  true,  true,  true,  true,  true,  true,  true,  true};
  CHECK(asked == expected);
}

TEST_CASE("the kind with the smaller median runs until the next round", "[solvers][execution_choice]") {
  SECTION("parallel faster") {
    ExecutionChoice choice;
    run_round(choice, slow, fast);
    CHECK(all_parallel(choice, ExecutionChoice::first_kept_for));
  }
  SECTION("serial faster") {
    ExecutionChoice choice;
    run_round(choice, fast, slow);
    CHECK(all_serial(choice, ExecutionChoice::first_kept_for));
  }
  SECTION("three slow outliers (a preempted helper) do not decide it") {
    ExecutionChoice choice;
    run_round(choice, slow, {30us, 900us, 30us, 30us, 900us, 30us, 900us, 30us});
    CHECK(all_parallel(choice, ExecutionChoice::first_kept_for));
  }
}

TEST_CASE("rounds come 32 evaluations after the first, then twice as far apart, at most 1024",
          "[solvers][execution_choice]") {
  ExecutionChoice choice;
  int kept_for = ExecutionChoice::first_kept_for;
  for (int round = 0; round < 8; ++round) {
    CAPTURE(round, kept_for);
    // Alternate the winner, so that each round's choice shows where the last one ended.
    const bool parallel_wins = round % 2 == 0;
    run_round(choice, parallel_wins ? slow : fast, parallel_wins ? fast : slow);
    CHECK((parallel_wins ? all_parallel(choice, kept_for) : all_serial(choice, kept_for)));
    CHECK_FALSE(choice.parallel());  // the next round's serial run
    kept_for = std::min(2 * kept_for, ExecutionChoice::longest_kept_for);
  }
  CHECK(kept_for == ExecutionChoice::longest_kept_for);
}
