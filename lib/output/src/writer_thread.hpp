#pragma once
/// \file
/// The thread of a ResultsWriter's own (docs/output.md, "The writer thread"): it does the jobs
/// handed to it one at a time, in the order queued, while the run goes on. After a job fails it
/// keeps the error for the caller and skips every later job, so a writer that met an error makes
/// no more HDF5 calls.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace spar::output::detail {

class WriterThread {
public:
  using Job = std::function<void()>;

  WriterThread() = default;
  /// Stops the thread (stop()) if it runs.
  ~WriterThread();
  WriterThread(const WriterThread&) = delete;
  WriterThread& operator=(const WriterThread&) = delete;

  /// Starts the thread, with `first` as its first job.
  void start(Job first);
  /// Queues `job` after the jobs queued before it; returns its number for wait_for.
  std::uint64_t queue(Job job);
  /// Waits until job `number` is done or skipped (0: returns at once).
  void wait_for(std::uint64_t number) const;
  /// Waits until every job queued is done or skipped: the thread is then idle, and the caller
  /// sees everything the jobs wrote.
  void wait_idle() const;
  /// The error of the job that failed, if it has not been taken yet (else nullptr), without
  /// waiting for the job in hand.
  std::exception_ptr take_failure();
  /// Once every queued job is done or skipped, stops and joins the thread; nothing if it does
  /// not run.
  void stop();

private:
  void run();

  std::thread thread_;
  mutable std::mutex mutex_;                ///< guards the fields below
  mutable std::condition_variable changed_;  ///< signals a job queued, a job finished, a stop
  std::deque<Job> jobs_;                    ///< queued, not yet taken by the thread
  std::uint64_t queued_ = 0;                ///< jobs queued so far; job k (1, 2, …) is the k-th
  std::uint64_t finished_ = 0;              ///< jobs done or skipped so far, in order
  bool stopping_ = false;                   ///< the thread returns once `jobs_` is empty
  bool failed_ = false;                     ///< a job failed: the later ones are skipped
  std::exception_ptr failure_;              ///< the failed job's error, not yet taken
};

}  // namespace spar::output::detail
