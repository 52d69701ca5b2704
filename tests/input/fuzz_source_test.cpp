// The fuzzing machinery of fuzz/cases (docs/errors.md, "Fuzzing"): how libFuzzer's bytes become
// decisions, what counts as a broken property, and that a case is a function of its input alone
// (libFuzzer replays a reported input and must see the same failure).
#include "fuzz_case.hpp"
#include "model_case.hpp"
#include "spline_case.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <vector>

using namespace spar;

TEST_CASE("ByteSource reads its decisions front to back and takes the low end when the bytes run out", "[input]") {
  const std::array<std::uint8_t, 9> bytes{12, 13, 200, 0x01, 0x02, 0x80, 0x00, 0x00, 0x00};
  fuzz::ByteSource source(bytes);
  CHECK(source.chance(0.05));            // 12 < 0.05 · 256 = 12.8
  CHECK_FALSE(source.chance(0.05));      // 13 ≥ 12.8
  CHECK(source.integer(-5, 5) == -5 + 200 % 11);  // a range of 11 needs one byte
  CHECK(source.integer(0, 999) == 0x0102 % 1000);  // a range of 1000 needs two
  CHECK(source.uniform(-1.0, 1.0) == 0.0);         // 0x80000000 / 2³² = 1/2 of the way
  CHECK(source.integer(7, 7) == 7);                // a single value reads no byte
  // The bytes are used up: no chance, the lowest integer, the low end of a range.
  CHECK_FALSE(source.chance(1.0));
  CHECK(source.integer(3, 9) == 3);
  CHECK(source.uniform(2.0, 4.0) == 2.0);
  CHECK(source.value(0.5) == 0.5);  // plausible values once the input is spent
}

TEST_CASE("a spar::Error is an accepted outcome; any other exception is a broken property", "[input]") {
  fuzz::CaseLog log;
  CHECK(fuzz::accepted([] {}, "a call that returns", log));
  CHECK_FALSE(fuzz::accepted([] { throw Error("bad input", "here", "fix it"); }, "a refusal", log));
  CHECK(log.violations().empty());
  CHECK_FALSE(fuzz::accepted([] { throw std::bad_alloc(); }, "an allocation", log));
  REQUIRE(log.violations().size() == 1);
  CHECK_THAT(log.violations()[0], Catch::Contains("an allocation threw a") && Catch::Contains("instead of a spar::Error"));
  log.check(false, "a curve moved");
  CHECK_THAT(log.report(), Catch::Contains("VIOLATED: a curve moved"));
}

TEST_CASE("a fuzz case is a function of its bytes, and the empty input is a plausible curve and model", "[input]") {
  const std::array<std::uint8_t, 24> bytes{3, 200, 17, 90, 1, 250, 64, 9, 33, 128, 7, 77,
                                           150, 2, 41, 99, 180, 5, 66, 210, 8, 120, 31, 240};
  for (const auto run_case : {+[](fuzz::FuzzSource& f, fuzz::CaseLog& log) { fuzz::spline_case(f, log); },
                              +[](fuzz::FuzzSource& f, fuzz::CaseLog& log) { fuzz::model_case(f, log); }}) {
    fuzz::CaseLog first, second;
    fuzz::ByteSource a(bytes), b(bytes);
    run_case(a, first);
    run_case(b, second);
    CHECK(first.report() == second.report());
    CHECK(first.violations().empty());
  }
  // libFuzzer starts from the empty input: it must reach the properties, not the first refusal.
  fuzz::CaseLog spline_log, model_log;
  fuzz::ByteSource empty_spline({}), empty_model({});
  CHECK(fuzz::spline_case(empty_spline, spline_log).curve);
  CHECK(fuzz::model_case(empty_model, model_log).built);
  CHECK(spline_log.violations().empty());
  CHECK(model_log.violations().empty());
}

TEST_CASE("the inputs libFuzzer found replay without a broken property", "[input]") {
  // fuzz/regressions: each input that broke a property, named <target>-<what it found>; replayed
  // through the case of its target, under the sanitizers too (the model input overflowed an int).
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SPAR_FUZZ_REGRESSIONS)) {
    std::ifstream file(entry.path(), std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    const std::string name = entry.path().filename().string();
    INFO(name);
    fuzz::ByteSource source(bytes);
    fuzz::CaseLog log;
    if (name.starts_with("spline-"))
      fuzz::spline_case(source, log);
    else if (name.starts_with("model-"))
      fuzz::model_case(source, log);
    else
      FAIL("a regression input must be named spline-… or model-…");
    CHECK(log.violations().empty());
    if (!log.violations().empty()) WARN(log.report());
    ++replayed;
  }
  CHECK(replayed >= 2);
}
