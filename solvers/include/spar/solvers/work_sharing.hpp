#pragma once
/// \file
/// Work sharing that never waits for a thread that has not started: the loop over elements of an
/// assembly, split into chunks that the calling thread and sleeping helper threads take on
/// demand.
///
/// Why not an OpenMP parallel loop: its team ends at a barrier that every thread of the team must
/// reach, and its idle threads spin. With another process on one of two cores, a team thread
/// waits to be scheduled while the others spin at the barrier; runs of a cantilevered beam took
/// up to 12× the serial time that way, 70× with one barrier per assembly (docs/performance.md,
/// "Scaling"). Here the caller works through the chunks itself; a helper that wakes late finds
/// none left and sleeps again, and the caller waits only for chunks a helper has taken and is
/// running. Between jobs a helper watches for the next one for 50 µs (an assembly is two jobs in
/// a row), yielding its core to any other thread with work, then sleeps on a futex
/// (std::atomic::wait); the caller likewise watches for the helpers' last chunks for 50 µs before
/// it sleeps.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace spar::solvers {

/// Runs body(begin, end, thread) over consecutive chunks of [0, count): `thread` is 0 for the
/// calling thread and 1 … thread_count() − 1 for the helpers, so per-thread workspaces indexed by
/// it are never shared. Which thread runs which chunk depends on the machine's load; a result
/// that must be reproducible may depend on the chunk only, never on `thread`.
class WorkSharing {
public:
  using Body = std::function<void(int begin, int end, int thread)>;

  /// The process-wide instance with omp_get_max_threads() threads (OMP_NUM_THREADS) at first use.
  static WorkSharing& shared();

  /// A team of `threads` (≥ 1): the caller and threads − 1 helpers, started at once.
  explicit WorkSharing(int threads);
  ~WorkSharing();
  WorkSharing(const WorkSharing&) = delete;
  WorkSharing& operator=(const WorkSharing&) = delete;

  /// The caller plus the helpers.
  int thread_count() const noexcept { return static_cast<int>(helpers_.size()) + 1; }

  /// A chunk size for `count` indices of similar cost: four chunks per thread, so that a thread
  /// slowed by another process takes fewer, but at most `largest` indices, so that the wait for
  /// a helper descheduled in the middle of one is short.
  int chunk_for(int count, int largest) const noexcept {
    return std::clamp(count / (4 * thread_count()), 1, std::max(largest, 1));
  }

  /// Runs body over [0, count) in chunks of `chunk` indices (the last one shorter) and returns
  /// when every chunk has run. The caller runs them all itself (as thread 0) when there is only
  /// one chunk, when the team is busy with another caller's job, and for a few jobs after one in
  /// which it waited long for a helper (a helper that lost its core to another process in the
  /// middle of a chunk: the loaded machine, where sharing costs more than it saves). The first
  /// exception thrown by body is rethrown here once every running chunk has finished; chunks not
  /// yet started are then skipped.
  void for_each_chunk(int count, int chunk, const Body& body);

private:
  /// Claims a chunk of job `generation`: its index, or −1 when none is left or the job is over.
  /// The generation and the count of unclaimed chunks share one atomic word (chunks are taken
  /// from the last down), so a helper that wakes late can never take a chunk of a later job.
  int claim(std::uint32_t generation);
  void run_chunk(int index, int thread);
  void helper_loop(int thread);
  /// After a shared job: how long the caller ran chunks and then waited for the helpers decides
  /// how many of the next jobs it runs alone.
  void adapt(std::chrono::steady_clock::duration worked, std::chrono::steady_clock::duration waited);

  std::vector<std::thread> helpers_;
  std::atomic<bool> busy_{false};  ///< set while a caller runs a job on the team
  /// High 32 bits: the job's generation; low 32 bits: its number of unclaimed chunks.
  std::atomic<std::uint64_t> job_{0};
  std::atomic<std::uint32_t> generation_{0};  ///< what helpers wait on (futex)
  std::atomic<int> finished_{0};              ///< chunks of the current job run to the end
  std::atomic<bool> stop_{false};
  std::atomic<bool> failed_{false};
  // The current job; written by the caller before generation_ is published.
  const Body* body_ = nullptr;
  int count_ = 0, chunk_ = 1, chunks_ = 0;
  int inline_jobs_ = 0, backoff_ = 0;  ///< the caller's (under busy_): jobs to run alone
  std::mutex failure_mutex_;
  std::exception_ptr failure_;
};

}  // namespace spar::solvers
