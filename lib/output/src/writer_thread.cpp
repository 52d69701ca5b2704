#include "writer_thread.hpp"

#include <utility>

namespace spar::output::detail {

WriterThread::~WriterThread() { stop(); }

void WriterThread::start(Job first) {
  queue(std::move(first));
  thread_ = std::thread([this] { run(); });
}

std::uint64_t WriterThread::queue(Job job) {
  std::uint64_t number = 0;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    jobs_.push_back(std::move(job));
    number = ++queued_;
  }
  changed_.notify_all();
  return number;
}

void WriterThread::wait_for(std::uint64_t number) const {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this, number] { return finished_ >= number; });
}

void WriterThread::wait_idle() const {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return finished_ == queued_; });
}

std::exception_ptr WriterThread::take_failure() {
  const std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(failure_, nullptr);
}

void WriterThread::stop() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void WriterThread::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    changed_.wait(lock, [this] { return !jobs_.empty() || stopping_; });
    if (jobs_.empty()) return;
    const Job job = std::move(jobs_.front());
    jobs_.pop_front();
    if (!failed_) {
      lock.unlock();
      std::exception_ptr error;
      try {
        job();
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      failed_ = error != nullptr;
      failure_ = error;
    }
    ++finished_;
    changed_.notify_all();
  }
}

}  // namespace spar::output::detail
