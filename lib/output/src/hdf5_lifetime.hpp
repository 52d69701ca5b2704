#pragma once
/// \file
/// HDF5's start and end in a process that writes results with spar (docs/output.md, "A full
/// disk").
///
/// HDF5 1.10 (Debian 12's) registers its own cleanup with atexit at its first call. Once a file's
/// data could not be written — a full disk, a file-size limit — that cleanup crashes at exit
/// (SIGSEGV in H5F__close_cb), whether or not the file has been closed since: a run that reported
/// the failure as a spar::Error and ended normally would still die of a segmentation fault. So
/// the library starts HDF5 itself, without HDF5's handler, and registers one of its own, which
/// ends HDF5 (H5close: every file still open is closed) unless an HDF5 call of the library has
/// failed — then HDF5 is left as it is, and the process ends without its cleanup (the data
/// flushed before the failure are on disk either way).

#include <hdf5.h>

#include <mutex>
#include <string>

namespace spar::output::detail {

/// How the library enters HDF5 on any thread: takes hdf5_mutex() (hdf5_lock.hpp), starts HDF5
/// at the first call (without HDF5's exit handler, with ours) and turns HDF5's printing of
/// errors off, as the failures become spar::Error (the setting is per thread in a thread-safe
/// HDF5). HDF5 calls follow while the lock is held. When code outside spar started HDF5 earlier,
/// HDF5's own handler is already registered and a failed write still crashes the exit.
std::unique_lock<std::mutex> hdf5_calls();

/// Records that an HDF5 call of the library failed: HDF5 is not ended at exit.
void note_hdf5_failure() noexcept;

/// The library's check of an HDF5 call: for a negative `status`, records the failure
/// (note_hdf5_failure) and throws spar::Error("HDF5 failed to " + what, where, fix).
void check_hdf5(herr_t status, const std::string& what, const std::string& where, const std::string& fix);

}  // namespace spar::output::detail
