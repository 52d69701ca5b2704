// WorkSharing: every index runs exactly once whatever the chunking, per-thread indices stay in
// range, a body's exception reaches the caller, and a body that calls back in or a job of one
// chunk runs inline.
#include <spar/solvers/work_sharing.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <stdexcept>
#include <vector>

using spar::solvers::WorkSharing;

TEST_CASE("for_each_chunk runs every index exactly once", "[core][work_sharing]") {
  const int threads = GENERATE(1, 2, 3);
  WorkSharing team(threads);
  CHECK(team.thread_count() == threads);
  for (const int count : {0, 1, 7, 64, 1000, 4097})
    for (const int chunk : {1, 3, 64, 5000}) {
      CAPTURE(threads, count, chunk);
      std::vector<std::atomic<int>> visits(static_cast<std::size_t>(count));
      std::atomic<bool> thread_in_range{true};
      team.for_each_chunk(count, chunk, [&](int begin, int end, int thread) {
        if (thread < 0 || thread >= threads || end - begin > chunk || begin % chunk != 0)
          thread_in_range = false;
        for (int i = begin; i < end; ++i) ++visits[static_cast<std::size_t>(i)];
      });
      CHECK(thread_in_range);
      int wrong = 0;
      for (const std::atomic<int>& v : visits) wrong += (v != 1);
      CHECK(wrong == 0);
    }
}

TEST_CASE("for_each_chunk rethrows a body's exception and stays usable", "[core][work_sharing]") {
  WorkSharing team(2);
  CHECK_THROWS_WITH(team.for_each_chunk(100, 1,
                                        [](int begin, int, int) {
                                          if (begin == 37) throw std::runtime_error("index 37 failed");
                                        }),
                    Catch::Contains("index 37 failed"));
  std::atomic<int> sum{0};
  team.for_each_chunk(100, 1, [&](int begin, int, int) { sum += begin; });
  CHECK(sum == 4950);
  CHECK_THROWS_AS(team.for_each_chunk(10, 0, [](int, int, int) {}), spar::Error);
  CHECK_THROWS_AS(WorkSharing(0), spar::Error);
}

TEST_CASE("a body that calls for_each_chunk again runs the inner loop on its own thread",
          "[core][work_sharing]") {
  WorkSharing team(2);
  std::atomic<int> inner{0};
  team.for_each_chunk(8, 1, [&](int, int, int) {
    team.for_each_chunk(10, 2, [&](int begin, int end, int thread) {
      if (thread == 0) inner += end - begin;  // inline: always thread 0
    });
  });
  CHECK(inner == 80);
}

TEST_CASE("a job of one chunk runs on the calling thread", "[core][work_sharing]") {
  // Nothing to share: the helpers are not woken, the body sees thread 0 with the whole range.
  WorkSharing team(2);
  for (const int count : {1, 5, 64}) {
    int calls = 0, first = -1, last = -1, thread_seen = -1;
    team.for_each_chunk(count, 64, [&](int begin, int end, int thread) {
      ++calls;
      first = begin;
      last = end;
      thread_seen = thread;
    });
    CAPTURE(count);
    CHECK(calls == 1);
    CHECK(first == 0);
    CHECK(last == count);
    CHECK(thread_seen == 0);
  }
}
