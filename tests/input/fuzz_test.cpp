// Property fuzzing of the spline and model inputs (issue 15) with a seeded generator: the cases of
// fuzz/cases (the same ones the libFuzzer targets run on mutated bytes) draw mostly plausible
// inputs with rare hostile mutations and check that the public API ends each call in a spar::Error
// or in a result with its defining property (a refined curve is the same curve; a solved model has
// a finite state and finite energies). Deterministic: SPAR_FUZZ_SEED, SPAR_FUZZ_RUNS (spline runs;
// the model cases run a fiftieth of them) and SPAR_FUZZ_MODEL_RUNS change the seed and the lengths
// (docs/errors.md); the defaults keep the suite at about a second.
#include "model_case.hpp"
#include "spline_case.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>

using namespace spar;

namespace {

long environment_number(const char* name, long fallback) {
  const char* text = std::getenv(name);
  return text == nullptr ? fallback : std::strtol(text, nullptr, 10);
}

}  // namespace

TEST_CASE("fuzzed spline inputs end in a spar::Error or a finite, unchanged curve", "[fuzz]") {
  const auto seed = static_cast<unsigned>(environment_number("SPAR_FUZZ_SEED", 15));
  const long runs = environment_number("SPAR_FUZZ_RUNS", 20000);
  fuzz::SeededSource source(seed);
  long curves = 0, refinements = 0;
  for (long run = 0; run < runs; ++run) {
    fuzz::CaseLog log;
    const fuzz::SplineOutcome outcome = fuzz::spline_case(source, log);
    curves += outcome.curve;
    refinements += outcome.refined;
    if (!log.violations().empty()) FAIL_CHECK("seed " << seed << ", run " << run << "\n" << log.report());
  }
  // The mutations are rare enough that most runs reach the properties.
  CHECK(curves > runs / 2);
  CHECK(refinements > runs / 4);
}

TEST_CASE("fuzzed models end in a spar::Error or a finite solved state", "[fuzz]") {
  const auto seed = static_cast<unsigned>(environment_number("SPAR_FUZZ_SEED", 15));
  const long runs = environment_number("SPAR_FUZZ_MODEL_RUNS", environment_number("SPAR_FUZZ_RUNS", 20000) / 50);
  fuzz::SeededSource source(seed);
  long solved = 0;
  for (long run = 0; run < runs; ++run) {
    fuzz::CaseLog log;
    solved += fuzz::model_case(source, log).solved;
    if (!log.violations().empty()) FAIL_CHECK("seed " << seed << ", run " << run << "\n" << log.report());
  }
  CHECK(solved > runs / 4);
}
