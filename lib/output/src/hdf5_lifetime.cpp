#include "hdf5_lifetime.hpp"

#include "hdf5_lock.hpp"

#include <spar/error.hpp>

#include <hdf5.h>

#include <atomic>
#include <cstdlib>
#include <mutex>

namespace spar::output::detail {

namespace {

std::atomic<bool> hdf5_failed{false};

/// The exit handler: HDF5's own cleanup, unless an HDF5 call of ours failed (hdf5_lifetime.hpp).
void end_hdf5() {
  if (hdf5_failed.load()) return;
  const std::lock_guard<std::mutex> hdf5(hdf5_mutex());
  H5close();
}

/// Starts HDF5 on the first call; later calls do nothing. Called with hdf5_mutex() held.
void start_hdf5() {
  static const bool started = [] {
    H5dont_atexit();  // before HDF5's first call, so that it registers no handler of its own
    H5open();
    std::atexit(end_hdf5);
    return true;
  }();
  static_cast<void>(started);
}

}  // namespace

void note_hdf5_failure() noexcept { hdf5_failed.store(true); }

void check_hdf5(herr_t status, const std::string& what, const std::string& where, const std::string& fix) {
  if (status >= 0) return;
  note_hdf5_failure();
  throw Error("HDF5 failed to " + what, where, fix);
}

std::unique_lock<std::mutex> hdf5_calls() {
  std::unique_lock<std::mutex> hdf5(hdf5_mutex());
  start_hdf5();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  return hdf5;
}

}  // namespace spar::output::detail
