#include "output_fixtures.hpp"

#include <spar/output/progress_bar.hpp>

#include <catch2/catch.hpp>

#include <cstdio>
#include <fcntl.h>

using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::StartsWith;
using spar::output::format_progress;
using spar::output::ProgressSnapshot;

TEST_CASE("format_progress shows steps, time, percent and ETA", "[output]") {
  ProgressSnapshot snapshot{"slider-crank", 0.05, 0.0, 0.2, 500, 10.0};
  const std::string quarter = format_progress(snapshot);
  CHECK_THAT(quarter, StartsWith("slider-crank [#####---------------]  25.0 %"));
  CHECK_THAT(quarter, Contains("t = 0.05 / 0.2 s") && Contains("steps 500"));
  CHECK_THAT(quarter, EndsWith("ETA 0:30"));  // 10 s for a quarter: 30 s to go

  snapshot.t = 0.0;
  CHECK_THAT(format_progress(snapshot), EndsWith("ETA --:--"));
  snapshot.t = 0.2;
  snapshot.elapsed_s = 3725;
  CHECK_THAT(format_progress(snapshot), Contains("100.0 %") && EndsWith("done in 1:02:05"));
  snapshot.t_start = 0.1;  // a restarted run counts from its own start
  snapshot.t = 0.15;
  snapshot.elapsed_s = 20;
  CHECK_THAT(format_progress(snapshot), Contains(" 50.0 %") && EndsWith("ETA 0:20"));
}

TEST_CASE("ProgressBar writes nothing when stderr is not a terminal", "[output]") {
  const spar::test::ScratchFolder folder("progress");
  const std::string log = folder.file("stderr.txt");
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  const int redirected = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  REQUIRE(saved >= 0);
  REQUIRE(redirected >= 0);
  dup2(redirected, STDERR_FILENO);
  bool active = true;
  {
    spar::output::ProgressBar bar(1.0, "run");
    active = bar.active();
    bar.update(0.5, 10);
    bar.finish();
  }
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  close(redirected);
  CHECK_FALSE(active);
  CHECK(spar::test::read_text(log).empty());
}
