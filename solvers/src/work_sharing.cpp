#include <spar/solvers/work_sharing.hpp>

#include <spar/error.hpp>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

namespace spar::solvers {

namespace {

constexpr std::uint64_t unclaimed_mask = 0xFFFFFFFFu;

std::uint64_t job_word(std::uint32_t generation, int unclaimed) {
  return (std::uint64_t{generation} << 32) | static_cast<std::uint32_t>(unclaimed);
}

/// Polls `done` for at most 50 µs: the time a thread watches for a job, or for the end of one,
/// before it sleeps on a futex (whose wake-up takes tens of µs on this machine). It yields between
/// polls, so that another thread with work on this core (the examples' results writer) runs
/// instead of waiting for the watch to end (the slider-crank's update run with its output at
/// h = 1e-4, medians of 8 in two rounds: 209 → 190 and 199 → 193 ms; docs/performance.md,
/// "Parallel assembly").
template <class Done>
void watch(const Done& done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
  while (!done() && std::chrono::steady_clock::now() < end) std::this_thread::yield();
}

}  // namespace

WorkSharing& WorkSharing::shared() {
  static WorkSharing team(omp_get_max_threads());
  return team;
}

WorkSharing::WorkSharing(int threads) {
  if (threads < 1)
    throw Error("a team of " + std::to_string(threads) + " threads", "solvers::WorkSharing",
                "give at least 1 thread (the caller)");
  helpers_.reserve(static_cast<std::size_t>(threads - 1));
  for (int thread = 1; thread < threads; ++thread)
    helpers_.emplace_back([this, thread] { helper_loop(thread); });
}

WorkSharing::~WorkSharing() {
  stop_.store(true);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& helper : helpers_) helper.join();
}

int WorkSharing::claim(std::uint32_t generation) {
  std::uint64_t word = job_.load(std::memory_order_acquire);
  for (;;) {
    const auto unclaimed = static_cast<int>(word & unclaimed_mask);
    if ((word >> 32) != generation || unclaimed == 0) return -1;
    if (job_.compare_exchange_weak(word, word - 1, std::memory_order_acq_rel,
                                   std::memory_order_acquire))
      return unclaimed - 1;
  }
}

void WorkSharing::run_chunk(int index, int thread) {
  // This chunk is claimed and not finished, so the caller is still waiting in this job: its
  // fields are this job's until finished_ counts the chunk.
  const int chunks = chunks_;
  if (!failed_.load(std::memory_order_relaxed)) {
    const int begin = index * chunk_;
    try {
      (*body_)(begin, std::min(count_, begin + chunk_), thread);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex_);
      if (!failure_) failure_ = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }
  if (finished_.fetch_add(1, std::memory_order_acq_rel) + 1 == chunks) finished_.notify_one();
}

void WorkSharing::helper_loop(int thread) {
  std::uint32_t seen = 0;
  for (;;) {
    // Jobs come in bursts (an assembly, then the factorization and the next assembly tens of µs
    // later): a helper that watches for the next job for a while before it sleeps joins it at
    // once instead of after a futex wake-up. The watch is bounded, so a loaded machine loses at
    // most that per job.
    watch([&] { return generation_.load(std::memory_order_acquire) != seen; });
    generation_.wait(seen, std::memory_order_acquire);
    if (stop_.load()) return;
    seen = generation_.load(std::memory_order_acquire);
    for (int index; (index = claim(seen)) >= 0;) run_chunk(index, thread);
  }
}

// On an idle machine the caller waits at most about one chunk (≤ 1/8 of the job with the
// assembly's chunks) at the end. Far longer means a helper lost its core in the middle of a chunk
// to another process; while that goes on, sharing costs more than it saves, so the next jobs run
// on the caller alone: 1, 2, 4, … 64 of them after consecutive late jobs, none after a good one.
void WorkSharing::adapt(std::chrono::steady_clock::duration worked,
                        std::chrono::steady_clock::duration waited) {
  if (waited > worked / 4 && waited > std::chrono::microseconds(50)) {
    backoff_ = std::min(2 * backoff_ + 1, 64);
    inline_jobs_ = backoff_;
  } else {
    backoff_ = 0;
  }
}

void WorkSharing::for_each_chunk(int count, int chunk, const Body& body) {
  if (chunk < 1)
    throw Error("chunk size " + std::to_string(chunk), "solvers::WorkSharing::for_each_chunk",
                "give chunks of at least 1 index");
  if (count <= 0) return;
  const auto run_inline = [&] {
    for (int begin = 0; begin < count; begin += chunk) body(begin, std::min(count, begin + chunk), 0);
  };
  // One chunk has nothing to share; a team busy with another job (another thread's, or the body
  // calling back in) is not shared.
  if (count <= chunk || helpers_.empty() || busy_.exchange(true, std::memory_order_acquire)) {
    run_inline();
    return;
  }
  struct Release {
    std::atomic<bool>& busy;
    ~Release() { busy.store(false, std::memory_order_release); }
  } release{busy_};
  if (inline_jobs_ > 0) {
    --inline_jobs_;
    run_inline();
    return;
  }

  body_ = &body;
  count_ = count;
  chunk_ = chunk;
  chunks_ = static_cast<int>((static_cast<long long>(count) + chunk - 1) / chunk);
  finished_.store(0, std::memory_order_relaxed);
  failed_.store(false, std::memory_order_relaxed);
  failure_ = nullptr;
  const std::uint32_t generation = generation_.load(std::memory_order_relaxed) + 1;
  job_.store(job_word(generation, chunks_), std::memory_order_release);
  generation_.store(generation, std::memory_order_release);
  generation_.notify_all();

  const auto start = std::chrono::steady_clock::now();
  for (int index; (index = claim(generation)) >= 0;) run_chunk(index, 0);
  const auto own_done = std::chrono::steady_clock::now();
  // Only chunks that a helper has claimed and is running are left to wait for. They usually end
  // within a chunk's time: the caller watches for that before it sleeps, since a futex wake-up
  // takes longer than a small job (the slider-crank's 17 blocks take ~60 µs).
  watch([&] { return finished_.load(std::memory_order_acquire) == chunks_; });
  for (int finished; (finished = finished_.load(std::memory_order_acquire)) != chunks_;)
    finished_.wait(finished, std::memory_order_acquire);
  adapt(own_done - start, std::chrono::steady_clock::now() - own_done);
  body_ = nullptr;
  if (failure_) std::rethrow_exception(failure_);
}

}  // namespace spar::solvers
